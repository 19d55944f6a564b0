//! The parsed formula: its tree, and the additive terms a verdict compares.

use super::Function;

/// A binary operator.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum BinOp {
    /// a + b.
    Add,
    /// a − b.
    Sub,
    /// a · b.
    Mul,
    /// a / b.
    Div,
    /// a ^ b.
    Pow,
}

/// A parsed formula's tree: what the TeX, the terms and the program are made from.
#[derive(Clone, Debug, PartialEq)]
pub enum Node {
    /// A number, with the text it was written as.
    Num(f64, String),
    /// A signal, by its index in [`NAMES`](super::NAMES).
    Sig(usize),
    /// −x.
    Neg(Box<Node>),
    /// x op y.
    Bin(BinOp, Box<Node>, Box<Node>),
    /// f(args).
    Call(Function, Vec<Node>),
    /// (x), kept so that the TeX shows the student's parentheses.
    Paren(Box<Node>),
}

/// The additive terms of `node` with their signs: x − (y + z) gives [+x, −y, −z]; a negated or
/// parenthesised sum is opened. What the verdict tries one by one when a law differs.
pub fn terms(node: &Node) -> Vec<(f64, &Node)> {
    fn walk<'a>(node: &'a Node, sign: f64, out: &mut Vec<(f64, &'a Node)>) {
        match node {
            Node::Bin(BinOp::Add, a, b) => {
                walk(a, sign, out);
                walk(b, sign, out);
            }
            Node::Bin(BinOp::Sub, a, b) => {
                walk(a, sign, out);
                walk(b, -sign, out);
            }
            Node::Neg(x) => walk(x, -sign, out),
            Node::Paren(x) => walk(x, sign, out),
            _ => out.push((sign, node)),
        }
    }
    let mut out = Vec::new();
    walk(node, 1.0, &mut out);
    out
}

/// `node` multiplied out into signed products (a sum inside a product or a quotient's numerator
/// distributed): 2·(a + b)·c gives [+2·a·c, +2·b·c]. The parts a verdict tries when no whole
/// term of [`terms`] explains a difference.
pub fn monomials(node: &Node) -> Vec<(f64, Node)> {
    match node {
        Node::Bin(BinOp::Add | BinOp::Sub, ..) | Node::Paren(_) | Node::Neg(_) => terms(node)
            .into_iter()
            .flat_map(|(sign, t)| {
                let parts = match t {
                    Node::Bin(BinOp::Mul | BinOp::Div, ..) => monomials(t),
                    _ => vec![(1.0, t.clone())],
                };
                parts.into_iter().map(move |(s, p)| (sign * s, p))
            })
            .collect(),
        Node::Bin(op @ (BinOp::Mul | BinOp::Div), a, b) => {
            let right = match op {
                BinOp::Mul => monomials(b),
                _ => vec![(1.0, (**b).clone())],
            };
            let mut out = Vec::new();
            for (sa, pa) in monomials(a) {
                for (sb, pb) in &right {
                    let part = match op {
                        BinOp::Mul => product(pa.clone(), pb.clone()),
                        _ => Node::Bin(*op, Box::new(pa.clone()), Box::new(pb.clone())),
                    };
                    out.push((sa * sb, part));
                }
            }
            out
        }
        _ => vec![(1.0, node.clone())],
    }
}

/// a · b with b's factors appended one by one, so that a product prints without parentheses.
fn product(a: Node, b: Node) -> Node {
    match b {
        Node::Bin(BinOp::Mul, b1, b2) => product(product(a, *b1), *b2),
        b => Node::Bin(BinOp::Mul, Box::new(a), Box::new(b)),
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::control::formula::{parse, tex, text};

    #[test]
    fn terms_open_sums_and_keep_their_signs() {
        let node = parse("a - (b1 + c) + -(d - e*f)", 4);
        assert!(node.is_err(), "b1 is not a name");
        let node = parse("x2 - (x3 + z1) + -(z3 - a1*a3)", 4).unwrap();
        let t: Vec<(f64, String)> = terms(&node).iter().map(|(s, n)| (*s, tex(n))).collect();
        assert_eq!(
            t,
            [
                (1.0, "x_2".into()),
                (-1.0, "x_3".into()),
                (-1.0, "z_1".into()),
                (-1.0, "z_3".into()),
                (1.0, r"a_1 \cdot a_3".into()),
            ]
        );
    }

    #[test]
    fn monomials_multiply_sums_out() {
        let node = parse("-2*(x4h*si4 - x5h*si5)*dx4h + k3*(-k3*z3 + z4)/b", 4).unwrap();
        let m: Vec<(f64, String)> = monomials(&node)
            .iter()
            .map(|(s, n)| (*s, text(n)))
            .collect();
        assert_eq!(
            m,
            [
                (-1.0, "2·x4h·si4·dx4h".into()),
                (1.0, "2·x5h·si5·dx4h".into()),
                (-1.0, "k3·k3·z3/b".into()),
                (1.0, "k3·z4/b".into()),
            ]
        );
    }
}
