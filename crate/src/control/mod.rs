//! Speed and flux references, the four-step backstepping controller of Section 4 and the
//! Lyapunov bound of Theorem 4.6.

mod backstepping;
mod ifoc;
mod reference;
mod stability;

pub use backstepping::{Adapted, Backstepping, ControlError, ControlInput, Gains, Terms};
pub use ifoc::{Ifoc, IfocTuning};
pub use reference::{RefSample, Reference};
pub use stability::LyapunovBound;
