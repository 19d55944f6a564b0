//! Speed and flux references, and the four-step backstepping controller of Section 4.

mod backstepping;
mod reference;

pub use backstepping::{Backstepping, ControlError, ControlInput, Gains, Terms};
pub use reference::{RefSample, Reference};
