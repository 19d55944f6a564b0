//! The load-recovery time of a run: how long its speed takes to come back to the reference after
//! the scenario's load step. A challenge's criterion may name it beside the figures of
//! [`super::report`]; the report itself does not give it.

use super::figures::{fig, FigureInfo};
use super::samples::Samples;
use crate::scenario::Scenario;

/// The load-recovery time's name: seconds from `load.time` until |ω − ω_d| stays within
/// [`recovery_band`] to the end of the run. 0 when it never leaves the band after the step;
/// infinite ("not recovered") when it is outside the band at the last sample. The same rule as
/// the lessons' `recovery(run, from, band)` in `tests/claims.mjs`: the time of the first sample
/// after the last one outside the band, less `load.time`.
pub const LOAD_RECOVERY: &str = "load_recovery_time";

/// [`LOAD_RECOVERY`], in words.
pub static LOAD_RECOVERY_INFO: FigureInfo = fig!("load_recovery_time", "s");

/// The band of [`LOAD_RECOVERY`] (rad/s): 1 % of |ω_d| at the load step or 0.5 rad/s, whichever
/// is larger (0.5 rad/s at the load presets' 50 rad/s, as the lessons read it).
pub fn recovery_band(reference_at_step: f64) -> f64 {
    (0.01 * reference_at_step.abs()).max(0.5)
}

/// [`LOAD_RECOVERY`] of the rows `rows` recorded from scenario `s` (s); None when the scenario
/// has no load step (`load.torque` = 0, or a load table instead) or the rows end before it.
pub fn load_recovery(s: &Scenario, rows: &dyn Samples) -> Option<f64> {
    let (from, _) = s.load_step.step()?;
    let len = rows.count();
    let start = (0..len).find(|&i| rows.time(i) >= from)?;
    let band = recovery_band(rows.row(start).omega_ref);
    let mut last_out = None;
    rows.visit(start, len, &mut |i, r| {
        if r.omega_err.abs() > band || !r.omega_err.is_finite() {
            last_out = Some(i);
        }
        true
    });
    Some(match last_out {
        None => 0.0,
        Some(i) if i + 1 >= len => f64::INFINITY,
        Some(i) => rows.time(i + 1) - from,
    })
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::record::samples::testing::{trace, TS};
    use crate::scenario::preset;

    /// A load step at 3 ms on a 50 rad/s reference: band 0.5 rad/s.
    fn load_at_3_ms() -> Scenario {
        let mut s = preset("load-step").unwrap();
        s.load_step.time = 3.0 * TS;
        s
    }

    #[test]
    fn recovery_is_the_first_sample_after_the_last_one_outside_the_band() {
        let s = load_at_3_ms();
        let errors = [0.0, 0.0, 0.0, -0.2, -2.0, -0.9, 0.4, -0.6, 0.3, 0.1, 0.0];
        let rows = trace(errors.len(), |k, r| {
            r.omega_ref = 50.0;
            r.omega_err = errors[k];
        });
        // The last sample outside ±0.5 is at 7 ms: recovered at 8 ms, 5 ms after the step.
        let t = load_recovery(&s, &rows).unwrap();
        assert!((t - 5.0 * TS).abs() < 1e-15, "{t}");
        // Never outside: 0; outside at the last sample: not recovered.
        let calm = trace(6, |_, r| r.omega_ref = 50.0);
        assert_eq!(load_recovery(&s, &calm), Some(0.0));
        let late = trace(6, |k, r| {
            r.omega_ref = 50.0;
            r.omega_err = if k == 5 { 1.0 } else { 0.0 };
        });
        assert_eq!(load_recovery(&s, &late), Some(f64::INFINITY));
        // A NaN error is outside the band.
        let nan = trace(6, |k, r| {
            r.omega_ref = 50.0;
            r.omega_err = if k == 4 { f64::NAN } else { 0.0 };
        });
        let t = load_recovery(&s, &nan).unwrap();
        assert!((t - 2.0 * TS).abs() < 1e-15, "{t}");
    }

    #[test]
    fn no_load_step_or_rows_ending_before_it_give_no_recovery() {
        let rows = trace(3, |_, r| r.omega_ref = 50.0);
        assert_eq!(load_recovery(&load_at_3_ms(), &rows), None);
        let mut none = load_at_3_ms();
        none.load_step.torque = 0.0;
        assert_eq!(load_recovery(&none, &trace(10, |_, _| ())), None);
    }

    #[test]
    fn the_band_is_one_percent_of_the_reference_or_half_a_rad_per_second() {
        assert_eq!(recovery_band(50.0), 0.5);
        assert_eq!(recovery_band(-200.0), 2.0);
        assert_eq!(recovery_band(0.0), 0.5);
    }
}
