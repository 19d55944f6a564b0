//! IM Lab core: speed-sensorless induction-motor control after Zhang, Wang, Bortoff et al. (2015),
//! "Integrated design of speed sensorless control algorithms for induction motors".
//!
//! Data flows one way: [`params`] → [`model`] (plant) → [`observer`] (EKF) → [`control`]
//! (four backstepping steps) → [`inverter`] (voltage limit, PWM) → [`record`] (what a run keeps,
//! and the figures read from it) → [`sim`] (the 20 kHz loop, advanced in chunks). [`scenario`] holds every
//! setting and the query-string codec shared by the CLI, the browser and the tests; [`analysis`]
//! runs many simulations (frequency responses, seed sweeps, model-error maps over model errors
//! and seeds, measurement tables); [`text`], the ground floor, is how every message writes a
//! number and quotes user input, and the one percent codec.

pub mod analysis;
pub mod challenge;
pub mod control;
pub mod design;
pub mod identify;
pub mod inverter;
pub mod model;
pub mod motors;
pub mod observer;
pub mod params;
pub mod record;
pub mod rng;
pub mod scenario;
pub mod sim;
pub mod text;

#[cfg(target_arch = "wasm32")]
pub mod wasm;
