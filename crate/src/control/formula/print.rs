//! The printers: a parsed formula as plain text (for verdicts) and as TeX (for the page).

use super::{BinOp, Function, Node, NAMES};

/// `node` as plain text, with the names and a centred dot for the product: how a verdict quotes
/// a term.
pub fn text(node: &Node) -> String {
    fn wrap(node: &Node, least: u8) -> String {
        if precedence(node) < least {
            format!("({})", text(node))
        } else {
            text(node)
        }
    }
    match node {
        Node::Num(_, written) => written.clone(),
        Node::Sig(i) => NAMES[*i].name.to_string(),
        Node::Neg(x) => format!("−{}", wrap(x, 3)),
        Node::Paren(x) => format!("({})", text(x)),
        Node::Bin(BinOp::Add, a, b) => format!("{} + {}", text(a), text(b)),
        Node::Bin(BinOp::Sub, a, b) => format!("{} − {}", text(a), wrap(b, 2)),
        Node::Bin(BinOp::Mul, a, b) => format!("{}·{}", wrap(a, 2), wrap(b, 3)),
        Node::Bin(BinOp::Div, a, b) => format!("{}/{}", wrap(a, 2), wrap(b, 3)),
        Node::Bin(BinOp::Pow, a, b) => format!("{}^{}", wrap(a, 5), wrap(b, 4)),
        Node::Call(f, args) => format!(
            "{}({})",
            f.name(),
            args.iter().map(text).collect::<Vec<_>>().join(", ")
        ),
    }
}

/// Operator precedence for the TeX: 1 sum, 2 product, 3 unary minus, 4 power, 5 atom.
fn precedence(node: &Node) -> u8 {
    match node {
        Node::Bin(BinOp::Add | BinOp::Sub, ..) => 1,
        Node::Bin(BinOp::Mul | BinOp::Div, ..) => 2,
        Node::Neg(_) => 3,
        Node::Bin(BinOp::Pow, ..) => 4,
        _ => 5,
    }
}

/// `node` in TeX, as KaTeX typesets it: the names as the walkthrough writes them, products with
/// a centred dot, quotients as fractions and the formula's own parentheses kept.
pub fn tex(node: &Node) -> String {
    fn wrap(node: &Node, least: u8) -> String {
        if precedence(node) < least {
            format!(r"\left({}\right)", tex(node))
        } else {
            tex(node)
        }
    }
    match node {
        Node::Num(_, written) => match written.split_once(['e', 'E']) {
            Some((m, e)) => format!(r"{m}\cdot 10^{{{}}}", e.trim_start_matches('+')),
            None => written.clone(),
        },
        Node::Sig(i) => NAMES[*i].tex.to_string(),
        Node::Neg(x) => format!("-{}", wrap(x, 3)),
        Node::Paren(x) => format!(r"\left({}\right)", tex(x)),
        Node::Bin(BinOp::Add, a, b) => format!("{} + {}", tex(a), tex(b)),
        Node::Bin(BinOp::Sub, a, b) => format!("{} - {}", tex(a), wrap(b, 2)),
        Node::Bin(BinOp::Mul, a, b) => format!(r"{} \cdot {}", wrap(a, 2), wrap(b, 3)),
        Node::Bin(BinOp::Div, a, b) => format!(r"\frac{{{}}}{{{}}}", tex(a), tex(b)),
        Node::Bin(BinOp::Pow, a, b) => format!("{{{}}}^{{{}}}", wrap(a, 5), tex(b)),
        Node::Call(Function::Sqrt, args) => format!(r"\sqrt{{{}}}", tex(&args[0])),
        Node::Call(Function::Abs, args) => format!(r"\left|{}\right|", tex(&args[0])),
        Node::Call(f, args) => format!(
            r"\operatorname{{{}}}\left({}\right)",
            f.name(),
            args.iter().map(tex).collect::<Vec<_>>().join(", ")
        ),
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::control::formula::parse;

    #[test]
    fn tex_writes_the_names_and_the_structure() {
        let t = |s: &str| tex(&parse(s, 4).unwrap());
        assert_eq!(t("-k1s1*z1"), r"-k_{1s1} \cdot z_1");
        assert_eq!(
            t("x1h/(2*a3)"),
            r"\frac{\hat{x}_1}{\left(2 \cdot a_3\right)}"
        );
        assert_eq!(t("a1 - (x2 - x3)"), r"a_1 - \left(x_2 - x_3\right)");
        assert_eq!(t("sqrt(x4h^2)"), r"\sqrt{{\hat{x}_4}^{2}}");
        assert_eq!(
            t("sat(z1, 1e3)"),
            r"\operatorname{sat}\left(z_1, 1\cdot 10^{3}\right)"
        );
        assert_eq!(t("-(x2 + x3)"), r"-\left(x_2 + x_3\right)");
    }
}
