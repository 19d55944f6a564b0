//! Why a challenge or submission was refused.

use crate::text::Message;
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

/// Why a challenge or submission was refused: a message of `core-challenge.ftl` naming the key
/// or field, with user text quoted through [`excerpt`](crate::text::excerpt).
#[derive(Clone, Debug, PartialEq)]
pub struct ChallengeError {
    /// The kind of refusal.
    pub kind: ErrorKind,
    /// The message.
    pub message: Message,
}

impl ChallengeError {
    pub(super) fn malformed(message: Message) -> Self {
        ChallengeError {
            kind: ErrorKind::Malformed,
            message,
        }
    }
    pub(super) fn refused(message: Message) -> Self {
        ChallengeError {
            kind: ErrorKind::Refused,
            message,
        }
    }

    /// The status of a grading row: `malformed: …`, `refused: …` or `another challenge`.
    pub fn status(&self) -> Message {
        match self.kind {
            ErrorKind::Malformed => {
                Message::new("grade-row-malformed").said("reason", self.message.clone())
            }
            ErrorKind::Refused => {
                Message::new("grade-row-refused").said("reason", self.message.clone())
            }
            ErrorKind::Another => Message::new("grade-row-another"),
        }
    }
}

impl fmt::Display for ChallengeError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        self.message.fmt(f)
    }
}

impl std::error::Error for ChallengeError {}
