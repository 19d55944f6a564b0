//! Speed and flux references, the four-step backstepping controller of Section 4, its unknown
//! terms d̃2 and d̃4 evaluated from the simulated truth, and the Lyapunov bound of Theorem 4.6.

mod backstepping;
mod disturbance;
mod ifoc;
mod reference;
mod stability;

pub use backstepping::{Adapted, Backstepping, ControlError, ControlInput, Gains, Terms};
pub use disturbance::{disturbances, Sample};
pub use ifoc::{Ifoc, IfocTuning};
pub use reference::{RefSample, Reference};
pub use stability::LyapunovBound;
