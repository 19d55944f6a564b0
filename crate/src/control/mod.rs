//! Speed and flux references, the four-step backstepping controller of Section 4, its unknown
//! terms d̃2 and d̃4 evaluated from the simulated truth, the Lyapunov bound of Theorem 4.6, and the
//! laws a student writes for its steps.

/// The index of signal `name` in the signal vector, found when compiled.
macro_rules! sig {
    ($name:literal) => {{
        const I: usize = $crate::control::formula::at($name);
        I
    }};
}

mod backstepping;
mod chain;
mod disturbance;
mod flux;
pub mod formula;
mod ifoc;
pub mod law;
mod points;
mod reference;
mod stability;

pub use backstepping::{
    Adapted, Backstepping, ControlError, ControlInput, Custom, Gains, Gathered, Paper, Signals,
    Terms,
};
pub use disturbance::{disturbances, Sample};
pub use flux::flux_target;
pub use ifoc::{Ifoc, IfocTuning};
pub use points::{Points, PointsError, MAX_POINTS};
pub use reference::{RefSample, Reference};
pub use stability::LyapunovBound;
