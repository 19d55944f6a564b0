//! The ground floor for text: how the core writes numbers into its messages and quotes user input
//! (one rule each, used by every module above), and its one percent codec.

pub mod percent;
