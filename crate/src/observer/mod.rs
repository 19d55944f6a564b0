//! State observers. The controller sees an observer only through the general form (4):
//! the posterior estimate x̂, the gain L = K/Ts of eq (20) and the current residual.

mod ekf;
mod mras;

pub use ekf::{nis_band, Ekf, EkfConfig, Estimate, Filter, Predictor};
pub use mras::Mras;
