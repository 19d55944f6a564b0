//! The control-law language: a formula of the controller's signals, parsed once into a compact
//! program that is evaluated each sample without allocating.
//!
//! A formula uses numbers, the names in [`NAMES`], + − · / ^ (`*` or `·` for the product, `-` or
//! `−` for the minus), parentheses and the functions of [`FUNCTIONS`]. The unary minus binds
//! tighter than the product and looser than the power: `-k1s1*z1` is (−k1s1)·z1, `-x^2` is −(x²);
//! `^` groups to the right. Every function is the `libm` crate's (or IEEE-exact), so a formula
//! gives the same bits natively and in WebAssembly.
//!
//! One job per file: `names` (the signals a formula may read), `functions` (the functions it may
//! call), `error` (why a formula is refused), `tree` (the parsed formula and its terms), `lexer`
//! and `parser` (text to tree), `program` (the compiled form), `eval` (its value each sample),
//! `rate` (its time derivative, by forward mode) and `print` (the tree as plain text and as TeX).

mod error;
mod eval;
mod functions;
mod lexer;
mod names;
mod parser;
mod print;
mod program;
mod rate;
mod tree;

pub use error::FormulaError;
pub use functions::{Function, FUNCTIONS};
pub use names::{at, index, Name, NAMES, SIGNALS};
pub use parser::parse;
pub use print::{tex, text};
pub use program::Program;
pub use tree::{monomials, terms, BinOp, Node};

/// Longest formula accepted (characters): the paper's v4 written out takes 283.
pub const MAX_CHARS: usize = 2000;
/// Most operations a program may have: about two per name or number (the paper's v4 has 61).
pub const MAX_OPS: usize = 400;
/// Deepest stack a program may need; the evaluator's stack holds this many values.
pub const MAX_DEPTH: usize = 32;
/// Deepest nesting of parentheses, signs and powers the parser follows.
pub const MAX_NESTING: usize = 64;
