//! The parser: tokens to a tree, refusing what the language or the step does not allow.

use super::lexer::{tokens, Token};
use super::program::{constant, Program};
use super::{index, BinOp, FormulaError, Node, FUNCTIONS, MAX_CHARS, MAX_NESTING, NAMES};
use crate::text::Message;

/// The parser: precedence climbing over the tokens, refusing names the step may not use.
struct Parser<'a> {
    tokens: &'a [(Token, usize, usize)],
    pos: usize,
    /// Where the formula ends (one past its last character), for errors at its end.
    end: usize,
    step: u8,
    /// How deep in parentheses, signs and powers the parser is.
    nesting: usize,
    /// The first division by a constant zero, reported once the formula's size and depth pass.
    zero_division: Option<FormulaError>,
}

impl Parser<'_> {
    fn peek(&self) -> Option<&(Token, usize, usize)> {
        self.tokens.get(self.pos)
    }

    fn at_op(&self, op: char) -> bool {
        matches!(self.peek(), Some((Token::Op(c), _, _)) if *c == op)
    }

    fn here(&self) -> (usize, usize) {
        self.peek().map_or((self.end, 1), |t| (t.1, t.2))
    }

    fn expr(&mut self) -> Result<Node, FormulaError> {
        let mut left = self.term()?;
        while self.at_op('+') || self.at_op('-') {
            let op = if self.at_op('+') {
                BinOp::Add
            } else {
                BinOp::Sub
            };
            self.pos += 1;
            let right = self.term()?;
            left = Node::Bin(op, Box::new(left), Box::new(right));
        }
        Ok(left)
    }

    fn term(&mut self) -> Result<Node, FormulaError> {
        let mut left = self.unary()?;
        while self.at_op('*') || self.at_op('/') {
            let op = if self.at_op('*') {
                BinOp::Mul
            } else {
                BinOp::Div
            };
            let (at, _) = self.here();
            self.pos += 1;
            let right = self.unary()?;
            if op == BinOp::Div && constant(&right) == Some(0.0) && self.zero_division.is_none() {
                self.zero_division = Some(FormulaError::new(
                    at,
                    1,
                    Message::new("formula-division-by-zero"),
                ));
            }
            left = Node::Bin(op, Box::new(left), Box::new(right));
        }
        Ok(left)
    }

    fn unary(&mut self) -> Result<Node, FormulaError> {
        self.nesting += 1;
        let node = self.unary_inner();
        self.nesting -= 1;
        node
    }

    fn unary_inner(&mut self) -> Result<Node, FormulaError> {
        if self.nesting > MAX_NESTING {
            let (at, len) = self.here();
            return Err(FormulaError::new(
                at,
                len,
                Message::new("formula-nests-too-deep").count("max", MAX_NESTING),
            ));
        }
        if self.at_op('-') {
            self.pos += 1;
            return Ok(Node::Neg(Box::new(self.unary()?)));
        }
        if self.at_op('+') {
            self.pos += 1;
            return self.unary();
        }
        self.power()
    }

    fn power(&mut self) -> Result<Node, FormulaError> {
        let base = self.primary()?;
        if self.at_op('^') {
            self.pos += 1;
            let exponent = self.unary()?;
            return Ok(Node::Bin(BinOp::Pow, Box::new(base), Box::new(exponent)));
        }
        Ok(base)
    }

    fn primary(&mut self) -> Result<Node, FormulaError> {
        let Some((token, at, len)) = self.peek().cloned() else {
            return Err(FormulaError::new(
                self.end,
                1,
                Message::new("formula-ends-early"),
            ));
        };
        self.pos += 1;
        match token {
            Token::Num(v, written) => Ok(Node::Num(v, written)),
            Token::Op('(') => {
                let inner = self.expr()?;
                if !self.at_op(')') {
                    let (here, n) = self.here();
                    return Err(if self.peek().is_none() {
                        FormulaError::new(at, 1, Message::new("formula-never-closed"))
                    } else {
                        FormulaError::new(here, n, Message::new("formula-expected-close"))
                    });
                }
                self.pos += 1;
                Ok(Node::Paren(Box::new(inner)))
            }
            Token::Ident(id) if self.at_op('(') => self.call(&id, at, len),
            Token::Ident(id) => self.signal(&id, at, len),
            Token::Op(c) => Err(FormulaError::new(
                at,
                1,
                Message::new("formula-misplaced-operator").text("op", c.to_string()),
            )),
        }
    }

    fn call(&mut self, id: &str, at: usize, len: usize) -> Result<Node, FormulaError> {
        let Some(&(_, f, arity, _)) = FUNCTIONS.iter().find(|f| f.0 == id) else {
            let known: Vec<&str> = FUNCTIONS.iter().map(|f| f.0).collect();
            return Err(FormulaError::new(
                at,
                len,
                Message::new("formula-no-function")
                    .text("name", id)
                    .text("functions", known.join(", ")),
            ));
        };
        self.pos += 1; // '('
        let mut args = vec![self.expr()?];
        while self.at_op(',') {
            self.pos += 1;
            args.push(self.expr()?);
        }
        if !self.at_op(')') {
            let (here, n) = self.here();
            return Err(FormulaError::new(
                here,
                n,
                Message::new("formula-expected-argument-end").text("name", id),
            ));
        }
        self.pos += 1;
        if args.len() != arity {
            return Err(FormulaError::new(
                at,
                len,
                Message::new("formula-arguments")
                    .text("name", id)
                    .count("arity", arity)
                    .count("given", args.len()),
            ));
        }
        Ok(Node::Call(f, args))
    }

    fn signal(&mut self, id: &str, at: usize, len: usize) -> Result<Node, FormulaError> {
        match index(id) {
            Some(i) if NAMES[i].from_step <= self.step => Ok(Node::Sig(i)),
            Some(i) => Err(FormulaError::new(
                at,
                len,
                Message::new("formula-later-name")
                    .text("name", id)
                    .count("step", self.step)
                    .count("from", NAMES[i].from_step - 1),
            )),
            None if FUNCTIONS.iter().any(|f| f.0 == id) => Err(FormulaError::new(
                at,
                len,
                Message::new("formula-is-function").text("name", id),
            )),
            None => Err(FormulaError::new(
                at,
                len,
                Message::new(unmeasured(id).unwrap_or("formula-unknown-name")).text("name", id),
            )),
        }
    }
}

/// Why a name of the true state or of an unmeasured error is not in the language, as the id of
/// its message: a sensorless controller has only the measured currents and its own estimates.
fn unmeasured(id: &str) -> Option<&'static str> {
    Some(match id {
        "x1" => "formula-true-speed",
        "x4" | "x5" => "formula-true-flux",
        "xt1" | "xt4" | "xt5" => "formula-unmeasured-error",
        _ => return None,
    })
}

/// Parses `text` as the law of step `step` (1–4).
pub fn parse(text: &str, step: u8) -> Result<Node, FormulaError> {
    let length = text.chars().count();
    if length > MAX_CHARS {
        return Err(FormulaError::new(
            0,
            0,
            Message::new("formula-too-long")
                .count("length", length)
                .count("max", MAX_CHARS),
        ));
    }
    let tokens = tokens(text)?;
    if tokens.is_empty() {
        return Err(FormulaError::new(0, 0, Message::new("formula-empty")));
    }
    let mut parser = Parser {
        tokens: &tokens,
        pos: 0,
        end: length + 1,
        step,
        nesting: 0,
        zero_division: None,
    };
    let node = parser.expr()?;
    if let Some((token, at, len)) = parser.peek() {
        let what = Message::new(match token {
            Token::Op(')') => "formula-unopened",
            _ => "formula-expected-operator",
        });
        return Err(FormulaError::new(*at, *len, what));
    }
    match parser.zero_division {
        // A formula too long or too deep is refused for that first: it is what to change.
        Some(e) => Err(Program::new(&node).err().unwrap_or(e)),
        None => Ok(node),
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn bad_formulas_are_refused_at_their_place_with_the_reason() {
        let cases: &[(&str, u8, usize, &str)] = &[
            ("", 1, 0, "empty"),
            ("1 +", 1, 4, "ends where"),
            ("(1 + 2", 1, 1, "never closed"),
            ("1 + 2)", 1, 6, "no '('"),
            ("2 x1h", 1, 3, "expected an operator"),
            ("foo + 1", 1, 1, "unknown name 'foo'"),
            ("x1 + 1", 1, 1, "'x1' is the true speed"),
            (
                "2*xt4",
                1,
                3,
                "'xt4' is an estimation error of an unmeasured state",
            ),
            ("z2 + 1", 1, 1, "not known in step 1"),
            ("1 + z4", 3, 5, "not known in step 3"),
            ("sqrt(1, 2)", 1, 1, "takes 1 argument"),
            ("sqr(2)", 1, 1, "no function 'sqr'"),
            ("sqrt + 1", 1, 1, "is a function"),
            ("1 / 0", 1, 3, "division by zero"),
            ("x1h/(2 - 2)", 1, 4, "division by zero"),
            ("1 $ 2", 1, 3, "not part of the language"),
            ("1e999", 1, 1, "too large"),
            ("* 2", 1, 1, "where a number"),
        ];
        for (text, step, at, needle) in cases {
            let e = parse(text, *step).expect_err(text);
            assert_eq!(e.at, *at, "{text}: {e}");
            assert!(e.reason.to_string().contains(needle), "{text}: {e}");
        }
        let long = "x1h + ".repeat(400) + "1";
        assert!(parse(&long, 1)
            .unwrap_err()
            .to_string()
            .contains("characters"));
        let costly = "x1h*x1h*x1h + ".repeat(140) + "1";
        assert!(Program::parse(&costly, 1)
            .unwrap_err()
            .to_string()
            .contains("operations"));
        let deep = "(".repeat(40) + "1" + &")".repeat(40);
        // Parentheses alone push nothing; a chain of powers does.
        assert!(Program::parse(&deep, 1).is_ok());
        let deep = "2^".repeat(40) + "1";
        assert!(Program::parse(&deep, 1)
            .unwrap_err()
            .to_string()
            .contains("deep"));
        // The parser follows at most MAX_NESTING levels: deeper input is refused, not recursed.
        let nested = "(".repeat(900) + "1" + &")".repeat(900);
        let e = parse(&nested, 1).unwrap_err();
        assert!(
            e.reason.to_string().contains("nests deeper") && e.at == MAX_NESTING + 1,
            "{e}"
        );
    }

    #[test]
    fn a_formula_too_deep_is_refused_for_its_depth_before_a_division_by_zero() {
        // Too deep for the evaluator's stack, with a division by zero inside.
        let deep = "2^".repeat(40) + "(x1h/0)";
        let e = Program::parse(&deep, 1).unwrap_err();
        assert!(e.reason.to_string().contains("values deep"), "{e}");
        assert_eq!(parse(&deep, 1).unwrap_err(), e);
        // Nested past what the parser follows, after a division by zero.
        let nested = "1/0 + ".to_string() + &"-".repeat(900) + "1";
        let e = parse(&nested, 1).unwrap_err();
        assert!(e.reason.to_string().contains("nests deeper"), "{e}");
        // Shallow, the division by zero is the reason, at its place.
        let e = parse("x1h + 1/(2 - 2)", 1).unwrap_err();
        assert_eq!(
            (e.at, e.reason.to_string()),
            (8, "division by zero".to_string())
        );
    }
}
