//! The compiled form: a formula as postfix operations on a stack, with its limits checked.

use super::{parse, BinOp, FormulaError, Function, Node, MAX_DEPTH, MAX_OPS, SIGNALS};
use crate::text::Message;

/// One operation of a program, on a stack of values: each binary operation also comes fused with
/// a signal or a number as its right operand (one dispatch where there would be two).
#[derive(Clone, Copy, Debug, PartialEq)]
pub(super) enum Op {
    Num(f64),
    Sig(u16),
    Neg,
    Add,
    Sub,
    Mul,
    Div,
    Pow,
    AddSig(u16),
    SubSig(u16),
    MulSig(u16),
    DivSig(u16),
    AddNum(f64),
    SubNum(f64),
    MulNum(f64),
    DivNum(f64),
    /// Pushes signal · signal (a `Sig` and the `MulSig` after it).
    SigMulSig(u16, u16),
    /// Pushes number · signal (a `Num` and the `MulSig` after it).
    NumMulSig(f64, u16),
    Call1(Function),
    Call2(Function),
}

impl Op {
    /// Whether it reads a signal.
    fn names_signal(self) -> bool {
        matches!(
            self,
            Op::Sig(_)
                | Op::AddSig(_)
                | Op::SubSig(_)
                | Op::MulSig(_)
                | Op::DivSig(_)
                | Op::SigMulSig(..)
                | Op::NumMulSig(..)
        )
    }

    /// What the operation costs, evaluated and with its rate (forward mode), in simple
    /// operations (one dispatch and one addition): each function at its costliest argument, as
    /// measured (`docs/figures.md`, the work of own laws). A sine or cosine of a huge argument
    /// reduces it by hundreds of bits of π; a power computes a logarithm and an exponential.
    fn work(self) -> (u64, u64) {
        match self {
            Op::Call1(Function::Sin | Function::Cos) => (64, 128),
            Op::Pow => (32, 64),
            Op::Call1(Function::Exp | Function::Ln | Function::Tanh)
            | Op::Call2(Function::Atan2) => (12, 16),
            Op::Call1(_) | Op::Call2(_) => (3, 4),
            Op::Div | Op::DivSig(_) | Op::DivNum(_) => (2, 4),
            _ => (1, 2),
        }
    }

    /// How the operation changes the stack's depth.
    fn depth_change(self) -> isize {
        match self {
            Op::Num(_) | Op::Sig(_) | Op::SigMulSig(..) | Op::NumMulSig(..) => 1,
            Op::Add | Op::Sub | Op::Mul | Op::Div | Op::Pow | Op::Call2(_) => -1,
            _ => 0,
        }
    }
}

fn compile(node: &Node, ops: &mut Vec<Op>) {
    match node {
        Node::Num(v, _) => ops.push(Op::Num(*v)),
        Node::Sig(i) => ops.push(Op::Sig(*i as u16)),
        Node::Neg(x) => {
            compile(x, ops);
            ops.push(Op::Neg);
        }
        Node::Paren(x) => compile(x, ops),
        Node::Bin(op, a, b) => {
            compile(a, ops);
            compile(b, ops);
            // The same operation on the same operands, with one dispatch fewer.
            let fused = match (op, ops.last()) {
                (BinOp::Add, Some(Op::Sig(i))) => Some(Op::AddSig(*i)),
                (BinOp::Sub, Some(Op::Sig(i))) => Some(Op::SubSig(*i)),
                (BinOp::Mul, Some(Op::Sig(i))) => Some(Op::MulSig(*i)),
                (BinOp::Div, Some(Op::Sig(i))) => Some(Op::DivSig(*i)),
                (BinOp::Add, Some(Op::Num(v))) => Some(Op::AddNum(*v)),
                (BinOp::Sub, Some(Op::Num(v))) => Some(Op::SubNum(*v)),
                (BinOp::Mul, Some(Op::Num(v))) => Some(Op::MulNum(*v)),
                (BinOp::Div, Some(Op::Num(v))) => Some(Op::DivNum(*v)),
                _ => None,
            };
            // A product of two leaves is pushed in one step.
            let fused = match (fused, ops.len().checked_sub(2).map(|k| ops[k])) {
                (Some(Op::MulSig(j)), Some(Op::Sig(i))) => {
                    ops.pop();
                    Some(Op::SigMulSig(i, j))
                }
                (Some(Op::MulSig(j)), Some(Op::Num(v))) => {
                    ops.pop();
                    Some(Op::NumMulSig(v, j))
                }
                (f, _) => f,
            };
            match fused {
                Some(f) => *ops.last_mut().expect("an operand") = f,
                None => ops.push(match op {
                    BinOp::Add => Op::Add,
                    BinOp::Sub => Op::Sub,
                    BinOp::Mul => Op::Mul,
                    BinOp::Div => Op::Div,
                    BinOp::Pow => Op::Pow,
                }),
            }
        }
        Node::Call(f, args) => {
            for a in args {
                compile(a, ops);
            }
            ops.push(if f.arity() == 1 {
                Op::Call1(*f)
            } else {
                Op::Call2(*f)
            });
        }
    }
}

/// A compiled formula: its operations in postfix order and the stack depth they need.
#[derive(Clone, Debug, PartialEq)]
pub struct Program {
    pub(super) ops: Vec<Op>,
    pub(super) depth: usize,
}

impl Program {
    /// Compiles a parsed formula; refuses one that costs more than [`MAX_OPS`] operations or needs
    /// a deeper stack than [`MAX_DEPTH`].
    pub fn new(node: &Node) -> Result<Program, FormulaError> {
        let mut ops = Vec::new();
        compile(node, &mut ops);
        if ops.len() > MAX_OPS {
            return Err(FormulaError::new(
                0,
                0,
                Message::new("formula-too-many-operations")
                    .count("operations", ops.len())
                    .count("max", MAX_OPS),
            ));
        }
        let (mut depth, mut deepest) = (0usize, 0usize);
        for op in &ops {
            depth = depth.wrapping_add_signed(op.depth_change());
            deepest = deepest.max(depth);
        }
        if deepest > MAX_DEPTH {
            return Err(FormulaError::new(
                0,
                0,
                Message::new("formula-too-deep")
                    .count("depth", deepest)
                    .count("max", MAX_DEPTH),
            ));
        }
        Ok(Program {
            ops,
            depth: deepest,
        })
    }

    /// Parses and compiles `text` as the law of step `step`.
    pub fn parse(text: &str, step: u8) -> Result<Program, FormulaError> {
        Program::new(&parse(text, step)?)
    }

    /// What one evaluation costs, in simple operations (see [`Op::work`]): the bound on a run's
    /// work counts it once a sample.
    pub fn work(&self) -> u64 {
        self.ops.iter().map(|op| op.work().0).sum()
    }

    /// What one evaluation of its rate ([`Program::eval_rate`]) costs, in simple operations.
    pub fn rate_work(&self) -> u64 {
        self.ops.iter().map(|op| op.work().1).sum()
    }

    /// The names it reads, each once, in the order of [`NAMES`](super::NAMES).
    pub fn names(&self) -> Vec<usize> {
        let mut used_pair = Vec::new();
        let mut used: Vec<usize> = self
            .ops
            .iter()
            .filter_map(|op| match op {
                Op::Sig(i) | Op::AddSig(i) | Op::SubSig(i) | Op::MulSig(i) | Op::DivSig(i) => {
                    Some(*i as usize)
                }
                Op::NumMulSig(_, j) => Some(*j as usize),
                Op::SigMulSig(i, j) => {
                    used_pair.push(*j as usize);
                    Some(*i as usize)
                }
                _ => None,
            })
            .collect();
        used.append(&mut used_pair);
        used.sort_unstable();
        used.dedup();
        used
    }
}

/// The value of `node` when it holds no signal.
pub(super) fn constant(node: &Node) -> Option<f64> {
    let mut ops = Vec::new();
    compile(node, &mut ops);
    let program = Program {
        ops,
        depth: MAX_DEPTH,
    };
    let none = [0.0; SIGNALS];
    (!program.ops.iter().any(|op| op.names_signal())).then(|| program.eval(&none))
}
