//! Why a formula was refused: the place and the reason.

use std::fmt;

/// Why a formula was refused: where (the character, counted from 1) and why.
#[cfg_attr(
    target_arch = "wasm32",
    derive(tsify::Tsify),
    tsify(missing_as_null, hashmap_as_object)
)]
#[derive(Clone, Debug, PartialEq, Eq, serde::Serialize)]
pub struct FormulaError {
    /// The first character the problem concerns, counted from 1 (0: the formula as a whole).
    pub at: usize,
    /// How many characters it spans (at least 1 when `at` > 0).
    pub len: usize,
    /// The reason.
    pub reason: String,
}

impl FormulaError {
    pub(crate) fn new(at: usize, len: usize, reason: impl Into<String>) -> FormulaError {
        FormulaError {
            at,
            len: len.max(1),
            reason: reason.into(),
        }
    }
}

impl fmt::Display for FormulaError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        if self.at == 0 {
            write!(f, "{}", self.reason)
        } else {
            write!(f, "at character {}: {}", self.at, self.reason)
        }
    }
}

impl std::error::Error for FormulaError {}
