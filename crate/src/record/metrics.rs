//! Summary figures of a run for comparing variants (sweeps, seed runs, the predictor
//! comparison): RMS errors, mean NIS and saturation over the window after the transient.

use super::row::{first_not, is_saturated};
use super::samples::Samples;
use super::transient::transient;
use crate::scenario::Scenario;
use serde::Serialize;

/// Summary figures of a run, for comparing variants. A figure [`super::report`] gives too has
/// the report's name here.
#[cfg_attr(
    target_arch = "wasm32",
    derive(tsify::Tsify),
    tsify(missing_as_null, hashmap_as_object)
)]
#[derive(Clone, Copy, Debug, Serialize)]
pub struct Metrics {
    /// The end of the start-up transient (s), where the window the figures cover starts: the
    /// window of the run's figures ([`super::report`]), so that a figure has one value wherever
    /// it is shown.
    pub transient_end: f64,
    /// RMS of ω − ω_d (rad/s).
    pub tracking_rms: f64,
    /// Largest |ω − ω_d| (rad/s).
    pub tracking_peak: f64,
    /// RMS of the speed-estimate error ω − ω̂ (rad/s).
    pub speed_estimate_error_rms: f64,
    /// RMS of the flux-estimate error |φ| − |φ̂| (Wb).
    pub flux_estimate_error_rms: f64,
    /// Mean NIS (2 for a consistent filter).
    pub mean_nis: f64,
    /// Share of samples with a commanded voltage beyond the limit.
    pub saturated_share: f64,
}

/// RMS errors, mean NIS and saturation of the rows `rows` recorded from scenario `s` after the
/// start-up transient (see [`Metrics::transient_end`]); None when nothing is recorded.
pub fn metrics(s: &Scenario, rows: &dyn Samples) -> Option<Metrics> {
    let len = rows.count();
    if len == 0 {
        return None;
    }
    let start = transient(s, rows).0.t;
    let from = first_not(len, |i| rows.time(i) < start);
    let n = (len - from) as f64;
    let limit = s.limit();
    // Sums in row order, as `Iterator::sum` adds.
    let mut sums = [-0.0; 4];
    let (mut max, mut saturated) = (0.0f64, 0usize);
    rows.visit(from, len, &mut |_, r| {
        sums[0] += r.omega_err * r.omega_err;
        sums[1] += r.omega_est_err * r.omega_est_err;
        sums[2] += r.flux_est_err * r.flux_est_err;
        sums[3] += r.nis;
        max = max.max(r.omega_err.abs());
        saturated += usize::from(is_saturated(r, &limit));
        true
    });
    Some(Metrics {
        transient_end: rows.time(from),
        tracking_rms: (sums[0] / n).sqrt(),
        tracking_peak: max,
        speed_estimate_error_rms: (sums[1] / n).sqrt(),
        flux_estimate_error_rms: (sums[2] / n).sqrt(),
        mean_nis: sums[3] / n,
        saturated_share: saturated as f64 / n,
    })
}
