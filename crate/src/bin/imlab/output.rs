//! How a subcommand ends and writes: its stop, stdout's errors and stderr's messages.

use std::fmt;
use std::io::{self, ErrorKind, Write};

/// Why a subcommand stopped before the end.
pub(crate) enum Stop {
    /// The reader of stdout went away (`imlab … | head`): it has what it wanted.
    Closed,
    /// A failure, reported as `imlab: <message>`.
    Failed(String),
}

impl From<String> for Stop {
    /// A failure with this message.
    fn from(message: String) -> Self {
        Stop::Failed(message)
    }
}

/// Writes `text` to stderr; a closed stderr is no reason to stop or to panic.
pub(crate) fn to_stderr(text: fmt::Arguments) {
    let _ = io::stderr().write_fmt(text);
}

/// An error writing to stdout as a [`Stop`]: a closed pipe is the reader's choice, not a failure.
pub(crate) fn stdout_stop(error: io::Error) -> Stop {
    if error.kind() == ErrorKind::BrokenPipe {
        Stop::Closed
    } else {
        Stop::Failed(format!("stdout: {error}"))
    }
}
