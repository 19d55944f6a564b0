//! What a run tallies as its rows come, so that reading its figures needs no replay of the whole
//! run: where V(t) leaves the bound (59), and what the start-up transient reads from every row.

use super::row::{first_not, is_saturated, Row};
use crate::control::{Gains, LyapunovBound};
use crate::inverter::Limit;
use serde::Serialize;

/// Rows between checkpoints of a [`super::Trace`], and of the intervals the tallies keep: a replay starts
/// at most this many samples before the first row it is asked for (about 0.1 s at 20 kHz, under a
/// millisecond of computing).
pub const CHECKPOINT_EVERY: usize = 2048;

/// Relative margin before V counts as outside the bound: rounding in V and the bound.
const BOUND_TOL: f64 = 1e-9;

/// How a run's V(t) compares with the bound (59).
#[cfg_attr(
    target_arch = "wasm32",
    derive(tsify::Tsify),
    tsify(missing_as_null, hashmap_as_object)
)]
#[derive(Clone, Copy, Debug, Serialize)]
pub struct Stability {
    /// The bound.
    pub bound: LyapunovBound,
    /// Recorded samples.
    pub samples: usize,
    /// Samples where V is above the bound.
    pub outside: usize,
    /// Of those, samples where a commanded voltage exceeded the limit.
    pub outside_saturated: usize,
    /// Samples where a commanded voltage exceeded the limit.
    pub saturated: usize,
    /// First time V is above the bound (s).
    pub first_outside: Option<f64>,
    /// Most likely reason V leaves the bound.
    pub cause: StabilityCause,
}

/// Why V(t) most likely leaves the bound (59); the page and the JSON see it as "none",
/// "saturation", "sampling", "estimation_errors" or "eps_or_sampling".
#[cfg_attr(
    target_arch = "wasm32",
    derive(tsify::Tsify),
    tsify(missing_as_null, hashmap_as_object)
)]
#[derive(Clone, Copy, Debug, PartialEq, Eq, Serialize)]
#[serde(rename_all = "snake_case")]
pub enum StabilityCause {
    /// V stays under the bound.
    None,
    /// Most samples above the bound had the voltage limit active.
    Saturation,
    /// The observer is perfect (d̃ = 0): only the sampled loop departs from the continuous design.
    Sampling,
    /// ε = 0 with the robust terms off: nothing bounds the estimation errors' terms.
    EstimationErrors,
    /// The robust terms' ε, or the sampling.
    EpsOrSampling,
}

/// Where V(t) leaves the bound (59), counted row by row from the first (whose V is V(0)).
#[derive(Clone, Debug)]
pub struct StabilityTally {
    gains: Gains,
    limit: Limit,
    bound: Option<LyapunovBound>,
    samples: usize,
    outside: usize,
    outside_saturated: usize,
    saturated: usize,
    first_outside: Option<f64>,
}

impl StabilityTally {
    /// A tally of rows of a run with these gains and this voltage limit.
    pub fn new(gains: Gains, limit: Limit) -> StabilityTally {
        StabilityTally {
            gains,
            limit,
            bound: None,
            samples: 0,
            outside: 0,
            outside_saturated: 0,
            saturated: 0,
            first_outside: None,
        }
    }

    /// Counts the next row.
    #[inline]
    pub fn push(&mut self, r: &Row) {
        let gains = &self.gains;
        let bound = *self
            .bound
            .get_or_insert_with(|| LyapunovBound::new(gains, r.lyapunov));
        let at_limit = is_saturated(r, &self.limit);
        self.samples += 1;
        self.saturated += usize::from(at_limit);
        if r.lyapunov > bound.at(r.t) * (1.0 + BOUND_TOL) + f64::MIN_POSITIVE {
            self.outside += 1;
            self.outside_saturated += usize::from(at_limit);
            self.first_outside.get_or_insert(r.t);
        }
    }

    /// The report of the rows counted; None before the first.
    pub fn finish(&self, perfect: bool) -> Option<Stability> {
        let bound = self.bound?;
        let outside = self.outside;
        // Most likely reason: saturation when most samples above the bound had the limit active;
        // the sampled loop when the observer is perfect (d̃ = 0); otherwise the unbounded
        // estimation errors when ε = 0; otherwise ε or the sampling.
        let cause = if outside == 0 {
            StabilityCause::None
        } else if 2 * self.outside_saturated > outside {
            StabilityCause::Saturation
        } else if perfect {
            StabilityCause::Sampling
        } else if bound.eps == 0.0 {
            StabilityCause::EstimationErrors
        } else {
            StabilityCause::EpsOrSampling
        };
        Some(Stability {
            bound,
            samples: self.samples,
            outside,
            outside_saturated: self.outside_saturated,
            saturated: self.saturated,
            first_outside: self.first_outside,
            cause,
        })
    }
}

/// What the transient ([`super::transient`]) reads from every row, gathered by a traced run as its rows come: per
/// interval of [`CHECKPOINT_EVERY`] rows the least and the greatest innovation band, the sums
/// of the NIS and of the squared flux and speed estimation errors over the second half of the run
/// as planned, and of the squared speed estimation error over its second quarter (each from −0,
/// in row order, as the transient sums it). A run that ends early has another second half; the transient then
/// reads the rows again.
#[derive(Clone, Debug)]
pub struct TransientTally {
    /// The least and the greatest innovation band of each interval.
    pub band: Vec<(f64, f64)>,
    /// The first row of the second half of the run as planned.
    pub half_index: usize,
    /// The sum of the NIS from that row on.
    pub late_sum: f64,
    /// The sum of the squared rotor-flux estimation error |φ_r − φ̂_r|² from that row on (Wb²).
    pub late_flux_sum: f64,
    /// The sum of the squared speed estimation error (ω̂ − ω)² from that row on ((rad/s)²).
    pub late_speed_sum: f64,
    /// The first row of the second quarter of the run as planned.
    pub quarter_index: usize,
    /// The sum of the squared speed estimation error over the second quarter ((rad/s)²).
    pub mid_speed_sum: f64,
}

/// The squared distance |φ_r − φ̂_r|² of row `r`'s rotor-flux estimate from the true flux (Wb²).
#[inline]
pub fn flux_err_sq(r: &Row) -> f64 {
    let (a, b) = (r.phi_ra - r.phi_ra_hat, r.phi_rb - r.phi_rb_hat);
    a * a + b * b
}

impl TransientTally {
    /// For a run of `steps` samples of `ts` (row k at time k·ts).
    pub fn new(steps: usize, ts: f64) -> TransientTally {
        let last = steps.saturating_sub(1);
        // `transient`'s half of a run whose rows are 0..steps, at times k·ts.
        let half = 0.0 + 0.5 * (last as f64 * ts - 0.0);
        let quarter = 0.0 + 0.25 * (last as f64 * ts - 0.0);
        TransientTally {
            band: Vec::with_capacity(steps.div_ceil(CHECKPOINT_EVERY)),
            half_index: first_not(steps, |k| (k as f64 * ts) < half).min(last),
            late_sum: -0.0,
            late_flux_sum: -0.0,
            late_speed_sum: -0.0,
            quarter_index: first_not(steps, |k| (k as f64 * ts) < quarter).min(last),
            mid_speed_sum: -0.0,
        }
    }

    /// Takes row `i`, the rows coming in order from 0.
    #[inline]
    pub fn push(&mut self, i: usize, r: &Row) {
        let band = r.innov_band_a;
        if i % CHECKPOINT_EVERY == 0 {
            self.band.push((band, band));
        } else if let Some((lo, hi)) = self.band.last_mut() {
            *lo = if band < *lo { band } else { *lo };
            *hi = if band > *hi { band } else { *hi };
        }
        if i >= self.half_index {
            self.late_sum += r.nis;
            self.late_flux_sum += flux_err_sq(r);
            self.late_speed_sum += r.omega_est_err * r.omega_est_err;
        } else if i >= self.quarter_index {
            self.mid_speed_sum += r.omega_est_err * r.omega_est_err;
        }
    }

    /// Bytes it holds.
    pub fn bytes(&self) -> usize {
        self.band.capacity() * std::mem::size_of::<(f64, f64)>()
    }
}
