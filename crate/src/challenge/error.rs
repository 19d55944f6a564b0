//! Why a challenge or submission was refused.

use serde::Serialize;
use std::fmt;

/// What kind of refusal an error is: the grading table's status names it.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Serialize)]
#[serde(rename_all = "lowercase")]
pub enum ErrorKind {
    /// The text is not a well-formed challenge or submission.
    Malformed,
    /// Well-formed, but a field the student set is not allowed or out of its range.
    Refused,
    /// A submission whose challenge text differs from the one it is graded against.
    Another,
}

/// Why a challenge or submission was refused: a message naming the key or field, with user
/// text quoted through [`excerpt`](crate::text::excerpt).
#[derive(Clone, Debug, PartialEq)]
pub struct ChallengeError {
    /// The kind of refusal.
    pub kind: ErrorKind,
    /// The message.
    pub message: String,
}

impl ChallengeError {
    pub(super) fn malformed(message: impl Into<String>) -> Self {
        ChallengeError {
            kind: ErrorKind::Malformed,
            message: message.into(),
        }
    }
    pub(super) fn refused(message: impl Into<String>) -> Self {
        ChallengeError {
            kind: ErrorKind::Refused,
            message: message.into(),
        }
    }

    /// The status of a grading row: `malformed: …`, `refused: …` or `another challenge`.
    pub fn status(&self) -> String {
        match self.kind {
            ErrorKind::Malformed => format!("malformed: {}", self.message),
            ErrorKind::Refused => format!("refused: {}", self.message),
            ErrorKind::Another => "another challenge".to_string(),
        }
    }
}

impl fmt::Display for ChallengeError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(&self.message)
    }
}

impl std::error::Error for ChallengeError {}
