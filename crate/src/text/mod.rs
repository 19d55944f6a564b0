//! The ground floor for text, used by every module above it: how the core writes numbers into
//! its messages and figures (`numbers`), how it quotes user input (`quote`), its one percent
//! codec (`percent`), its one CSV escaping rule (`csv`), and what it says to a person (`message`).

pub mod csv;
mod message;
mod numbers;
pub mod percent;
mod quote;

pub use message::{Arg, Message};
pub use numbers::{rounded, short, significant};
pub use quote::{escape_invisible, excerpt, is_invisible, EXCERPT_CHARS};
