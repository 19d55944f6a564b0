//! Why a formula was refused: the place and the reason.

use crate::text::Message;
use std::fmt;

/// Why a formula was refused: where (the character, counted from 1) and why.
#[cfg_attr(
    target_arch = "wasm32",
    derive(tsify::Tsify),
    tsify(missing_as_null, hashmap_as_object)
)]
#[derive(Clone, Debug, PartialEq, serde::Serialize)]
pub struct FormulaError {
    /// The first character the problem concerns, counted from 1 (0: the formula as a whole).
    pub at: usize,
    /// How many characters it spans (at least 1 when `at` > 0).
    pub len: usize,
    /// The reason, a `formula-*` message of `core-law.ftl` (without the place).
    pub reason: Message,
}

impl FormulaError {
    pub(crate) fn new(at: usize, len: usize, reason: Message) -> FormulaError {
        FormulaError {
            at,
            len: len.max(1),
            reason,
        }
    }

    /// What the error says, with its place, as a message of `core-law.ftl`.
    pub fn message(&self) -> Message {
        if self.at == 0 {
            self.reason.clone()
        } else {
            Message::new("formula-at")
                .count("at", self.at)
                .said("reason", self.reason.clone())
        }
    }
}

impl fmt::Display for FormulaError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        self.message().fmt(f)
    }
}

impl std::error::Error for FormulaError {}
