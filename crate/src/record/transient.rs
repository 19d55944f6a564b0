//! The end of a run's start-up transient: where the controller's and the observer's start-up are
//! over, so that the figures after it describe the run and not its start.

use super::samples::Samples;
use super::tally::{flux_err_sq, TransientTally, CHECKPOINT_EVERY};
use crate::control::Reference;
use crate::scenario::{ControllerKind, Scenario};
use crate::text::Message;
use serde::Serialize;
use std::f64::consts::PI;

/// Time constants of the slowest designed rate after which the controller's start-up is over:
/// e^−5 < 1 % of the initial error remains.
const CONTROLLER_TIME_CONSTANTS: f64 = 5.0;

/// The innovation band counts as settled within this fraction of its value at the last sample.
const BAND_SETTLED: f64 = 0.10;

/// Window of the moving mean NIS that tells when the EKF's estimates have converged (s).
const NIS_WINDOW: f64 = 2e-3;

/// The estimates count as converged once the moving mean NIS stays within this factor of the
/// mean NIS over the second half of the run.
const NIS_SETTLED: f64 = 2.0;

/// How long the 2 ms mean NIS must stay within [`NIS_SETTLED`] times its later level for the
/// estimates to count as converged (s): over seeds 1–30, shorter stretches within come and go
/// while the estimates still converge, and the strip's peak current would read that start-up.
const NIS_HOLD: f64 = 5e-3;

/// The flux estimate's start-up is over once its 2 ms RMS error stays within this multiple of its
/// RMS over the second half: over seeds 1–30, the Euler EKF's 200 Hz runs keep an RMS error near
/// 0.023 Wb, and their start-up's windows reach 0.04 Wb.
const FLUX_SETTLED: f64 = 1.5;

/// Window of the moving RMS speed estimation error (s): a whole period of the 200 Hz references,
/// whose error swings within each.
const SPEED_WINDOW: f64 = 5e-3;

/// The speed estimate's start-up is over once its 5 ms RMS error stays within this multiple of
/// its RMS over the second quarter or the second half of the run, whichever is less (a load step
/// in the second half raises the error there). Over seeds 1–30 of the presets, the start-up's
/// current then ends before the transient does, where the NIS and the flux estimate cannot tell
/// (the Euler EKF's 200 Hz runs and the 50 rad/s runs whose speed starts 10 % off).
const SPEED_SETTLED: f64 = 2.0;

/// Where the start-up transient ends, and why there.
#[cfg_attr(
    target_arch = "wasm32",
    derive(tsify::Tsify),
    tsify(missing_as_null, hashmap_as_object)
)]
#[derive(Clone, Debug, PartialEq, Serialize)]
pub struct Transient {
    /// End of the transient (s): a recorded sample time.
    pub t: f64,
    /// One line naming the controller's and the observer's start-up times (`transient-reason`
    /// of `core-run.ftl`).
    pub reason: Message,
}

/// The end of the start-up transient of a run: the first recorded sample time at or after the
/// controller's start-up (b), counted from the end of the observer's, the latest of (a), (c), (d)
/// and (e): the controller acts on the estimates, so its own start-up begins once they hold.
///
/// - (a) the observer's start-up: the first recorded time from which the EKF innovation band
///   `innov_band_a` (2·S_aa^½) stays within 10 % of its value at the last recorded sample (P0
///   starts it near 0.4 A; on the presets it settles to about 4 mA within 0.5–1.4 ms), and
/// - (b) the controller's start-up: five time constants of its slowest designed rate,
///   5/min(k1, k2, k3, k4) for backstepping (4.17 ms at the paper's 1200/s), or
///   5/(2π·current_bw) for the IFOC baseline (its current loops), and
/// - (c) the EKF's estimates: the end of the first full 2 ms window whose mean NIS is within
///   twice the mean NIS of the second half of the run and stays so, window after window, for
///   5 ms (the estimates start 10 % off and take about 10 ms to converge; until then the NIS is
///   far above its later level, and a lucky window or two below it do not end the start-up); the
///   first window within when none stays so for 5 ms; left out when no window in the first half
///   gets there (a noise-free run, whose NIS decays towards zero), and
/// - (d) the estimates' start-up error: the end of the first full 2 ms window whose RMS rotor-flux
///   estimation error |φ_r − φ̂_r| is within 1.5 times its RMS over the second half and stays so
///   for 5 ms (the estimates start 10 % off; where the EKF's NIS cannot tell, as the Euler
///   filter's on a 200 Hz sine, whose NIS stays far above its band, the controller still draws
///   the start-up's current until then); left out when no stretch of the first half gets there
///   (a noise-free run, whose error decays towards zero), and
/// - (e) the speed estimate's start-up error: the end of the first full 5 ms window whose RMS
///   speed estimation error |ω̂ − ω| is within twice its RMS over the second quarter or the
///   second half of the run, whichever is less, and stays so for 5 ms; left out as (d) is, and
///   when the lesser of those levels is 0 (a perfect observer's error is 0 throughout),
///
/// clamped to at most half the recorded run, so that a window of samples always remains after
/// it, and to the scenario's first event after the controller's own start-up (the reference's
/// step, the start of its ramp or reversal or a corner of its table, a change of the load): what follows an event is the drive's response to it, not its
/// start, even when a model error keeps the estimates from converging (`first_event`). With nothing recorded yet, t = 0. Also returns the index of its first row in `rows`.
pub fn transient(s: &Scenario, rows: &dyn Samples) -> (Transient, usize) {
    let len = rows.count();
    if len == 0 {
        return (
            Transient {
                t: 0.0,
                reason: Message::new("transient-nothing-recorded"),
            },
            0,
        );
    }
    let first_t = rows.time(0);
    let half = first_t + 0.5 * (rows.time(len - 1) - first_t);
    let levels = Levels::of(rows);
    let t_observer = rows.time(levels.observer);
    let (t_controller, controller) = controller_start_up(s);
    let (estimates, flux, speed) = converged(rows, &levels);
    let t_of = |t: Option<f64>| t.unwrap_or(first_t);
    let later = t_controller
        + t_observer
            .max(t_of(estimates))
            .max(t_of(flux))
            .max(t_of(speed));
    let event = first_event(s, t_controller).filter(|&e| e < later.min(half));
    let target = event.unwrap_or(later).min(half);
    // The rows are in time order and the last one is at or after `half`.
    let index = rows.first_at(target).min(len - 1);
    // A criterion's time, or the words for one never met.
    let at = |reason: Message, name, t: Option<f64>| match t {
        Some(t) => reason.time(name, t),
        None => reason.said(name, Message::new("transient-never")),
    };
    let mut reason = Message::new("transient-reason")
        .said("controller", controller)
        .time("observer", t_observer);
    reason = at(reason, "estimates", estimates);
    reason = at(reason, "flux", flux);
    reason = at(reason, "speed", speed);
    let reason = if let Some(e) = event {
        reason.text("end", "event").time("at", e)
    } else if later > half {
        reason.text("end", "half").time("at", half)
    } else {
        reason.text("end", "none")
    };
    (
        Transient {
            t: rows.time(index),
            reason,
        },
        index,
    )
}

/// (b) The controller's own start-up: its duration (s) and the words that name it.
fn controller_start_up(s: &Scenario) -> (f64, Message) {
    match s.controller {
        ControllerKind::Backstepping => {
            let g = &s.gains;
            let k = g.k1.min(g.k2).min(g.k3).min(g.k4);
            let t = CONTROLLER_TIME_CONSTANTS / k;
            let words = Message::new("transient-backstepping")
                .real("k", k)
                .time("time", t);
            (t, words)
        }
        ControllerKind::Ifoc => {
            let bw = s.ifoc.current_bw;
            let t = CONTROLLER_TIME_CONSTANTS / (2.0 * PI * bw);
            let words = Message::new("transient-ifoc")
                .real("bw", bw)
                .time("time", t);
            (t, words)
        }
    }
}

/// What the start-up's criteria compare against: (a)'s first settled row, and the later levels
/// of the NIS (c), the flux estimation error (d) and the speed estimation error (e).
struct Levels {
    /// The first row from which the innovation band stays settled (a).
    observer: usize,
    /// The first row of the second half.
    half_index: usize,
    /// Mean NIS over the second half.
    nis: f64,
    /// Mean squared flux estimation error over the second half (Wb²).
    flux: f64,
    /// Mean squared speed estimation error over the second quarter or half, the lesser.
    speed: f64,
}

impl Levels {
    /// One pass over the rows, or a traced run's tally when its quarters are the ones it summed.
    fn of(rows: &dyn Samples) -> Levels {
        let len = rows.count();
        let (first_t, last) = (rows.time(0), rows.row(len - 1));
        let half_index = rows
            .first_at(first_t + 0.5 * (last.t - first_t))
            .min(len - 1);
        let quarter_index = rows
            .first_at(first_t + 0.25 * (last.t - first_t))
            .min(half_index);
        // (a) The last row outside the band settles nothing; the one after it starts the settled
        // run. A NaN band counts as not settled.
        let settled =
            |band: f64| (band - last.innov_band_a).abs() <= BAND_SETTLED * last.innov_band_a;
        let (mut unsettled, mut nis, mut flux) = (None, -0.0, -0.0);
        let (mut late_speed, mut mid_speed) = (-0.0, -0.0);
        let tally = rows.tally().filter(|t| {
            t.half_index == half_index
                && t.quarter_index == quarter_index
                && t.band.len() == len.div_ceil(CHECKPOINT_EVERY)
        });
        match tally {
            Some(tally) => {
                unsettled = last_unsettled(tally, rows, len, &settled);
                nis = tally.late_sum;
                flux = tally.late_flux_sum;
                late_speed = tally.late_speed_sum;
                mid_speed = tally.mid_speed_sum;
            }
            None => rows.visit(0, len, &mut |i, r| {
                if !settled(r.innov_band_a) {
                    unsettled = Some(i);
                }
                if i >= half_index {
                    nis += r.nis;
                    flux += flux_err_sq(r);
                    late_speed += r.omega_est_err * r.omega_est_err;
                } else if i >= quarter_index {
                    mid_speed += r.omega_est_err * r.omega_est_err;
                }
                true
            }),
        }
        let late = (len - half_index) as f64;
        let late_speed = late_speed / late;
        Levels {
            observer: unsettled.map_or(0, |i| (i + 1).min(len - 1)),
            half_index,
            nis: nis / late,
            flux: flux / late,
            speed: if half_index > quarter_index {
                late_speed.min(mid_speed / (half_index - quarter_index) as f64)
            } else {
                late_speed
            },
        }
    }
}

/// A moving window's mean of one signal over the first half, and the first stretch of full
/// windows whose mean stays within a bound for [`NIS_HOLD`].
struct Held {
    /// The window's span (s).
    span: f64,
    /// The bound on the window's mean.
    bound: f64,
    /// The window's (t, value), and their sum.
    window: std::collections::VecDeque<(f64, f64)>,
    sum: f64,
    /// Whether a row has left the window: only full windows count.
    full: bool,
    /// The end of the first window within of the current stretch within.
    streak: Option<f64>,
    /// The end of the first window within at all.
    first_within: Option<f64>,
    /// Where the first stretch held for [`NIS_HOLD`] began.
    held: Option<f64>,
}

impl Held {
    fn new(span: f64, bound: f64) -> Held {
        Held {
            span,
            bound,
            window: std::collections::VecDeque::new(),
            sum: 0.0,
            full: false,
            streak: None,
            first_within: None,
            held: None,
        }
    }

    /// Takes the row at `t` with `value`, the rows coming in time order.
    fn push(&mut self, t: f64, value: f64) {
        if self.held.is_some() {
            return;
        }
        self.sum += value;
        self.window.push_back((t, value));
        while let Some(&(t0, v0)) = self.window.front() {
            if t - t0 < self.span {
                break;
            }
            self.sum -= v0;
            self.window.pop_front();
            self.full = true;
        }
        if !self.full {
            return;
        }
        if self.sum / self.window.len() as f64 <= self.bound {
            self.first_within = self.first_within.or(Some(t));
            let since = *self.streak.get_or_insert(t);
            if t - since >= NIS_HOLD {
                self.held = Some(since);
            }
        } else {
            self.streak = None;
        }
    }
}

/// (c), (d) and (e): where the estimates' NIS, the flux estimate and the speed estimate hold at
/// their later levels, each `None` where none does in the first half. The NIS falls back to its
/// first window within when no stretch of the first half stays within for [`NIS_HOLD`]; a
/// perfect observer's speed error is 0 throughout, so (e) has nothing to tell.
fn converged(rows: &dyn Samples, levels: &Levels) -> (Option<f64>, Option<f64>, Option<f64>) {
    let mut nis = Held::new(NIS_WINDOW, NIS_SETTLED * levels.nis);
    let mut flux = Held::new(NIS_WINDOW, FLUX_SETTLED * FLUX_SETTLED * levels.flux);
    let mut speed = (levels.speed > 0.0)
        .then(|| Held::new(SPEED_WINDOW, SPEED_SETTLED * SPEED_SETTLED * levels.speed));
    rows.visit(0, levels.half_index, &mut |_, r| {
        nis.push(r.t, r.nis);
        flux.push(r.t, flux_err_sq(r));
        if let Some(speed) = speed.as_mut() {
            speed.push(r.t, r.omega_est_err * r.omega_est_err);
        }
        let speed_done = speed.as_ref().is_none_or(|s| s.held.is_some());
        !(nis.held.is_some() && flux.held.is_some() && speed_done)
    });
    (
        nis.held.or(nis.first_within),
        flux.held,
        speed.and_then(|s| s.held),
    )
}

/// The time of the first change the scenario makes to the drive after `after` (s): the
/// reference's step, the start of its ramp or reversal or a corner of its table, or when the
/// extra load first acts (none for a constant or sine reference and no load after it).
fn first_event(s: &Scenario, after: f64) -> Option<f64> {
    let reference = match s.reference {
        Reference::Step { size, time, .. } if size != 0.0 => Some(time),
        Reference::Ramp {
            start,
            level,
            slope,
            ..
        }
        | Reference::Reversal {
            start,
            level,
            slope,
            ..
        } if level != 0.0 && slope > 0.0 => Some(start),
        // A table's first corner after `after` from which the reference moves.
        Reference::Table { points } => points.first_change_after(after),
        _ => None,
    };
    let load = s.load_step.change_after(after);
    [reference, load]
        .into_iter()
        .flatten()
        .filter(|&t| t > after)
        .reduce(f64::min)
}

/// The last of rows `0..len` whose band is not `settled`. The rows whose band is settled
/// form an interval of values (`settled` compares |band − final| with a bound, and rounding
/// is monotonic), so an interval of rows whose least and greatest band are settled is settled
/// throughout; only the last interval that is not is read again.
fn last_unsettled(
    tally: &TransientTally,
    rows: &dyn Samples,
    len: usize,
    settled: &dyn Fn(f64) -> bool,
) -> Option<usize> {
    let b = tally
        .band
        .iter()
        .rposition(|&(lo, hi)| !(settled(lo) && settled(hi)))?;
    let mut last = None;
    rows.visit(
        b * CHECKPOINT_EVERY,
        len.min((b + 1) * CHECKPOINT_EVERY),
        &mut |i, r| {
            if !settled(r.innov_band_a) {
                last = Some(i);
            }
            true
        },
    );
    last
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::record::samples::testing::{trace, TS};
    use crate::record::Row;
    use crate::scenario::preset;

    /// A band that starts at 0.4 A and settles to 4 mA at sample `settled`.
    fn band(k: usize, settled: usize) -> f64 {
        if k < settled {
            0.4
        } else {
            0.004
        }
    }

    /// Rows with a tally, as a traced run gives them.
    struct Tallied(Vec<Row>, TransientTally);

    impl Samples for Tallied {
        fn count(&self) -> usize {
            self.0.count()
        }
        fn time(&self, i: usize) -> f64 {
            self.0.time(i)
        }
        fn visit(&self, start: usize, end: usize, f: &mut dyn FnMut(usize, &Row) -> bool) {
            self.0.visit(start, end, f);
        }
        fn tally(&self) -> Option<&TransientTally> {
            Some(&self.1)
        }
    }

    fn tallied(rows: &[Row], steps: usize) -> Tallied {
        let mut tally = TransientTally::new(steps, TS);
        for (i, r) in rows.iter().enumerate() {
            tally.push(i, r);
        }
        Tallied(rows.to_vec(), tally)
    }

    #[test]
    fn a_tally_gives_the_transient_the_rows_give() {
        let s = preset("step").unwrap();
        // Odd, so that a run one row short has the same second half (the tally is used then too).
        let n = 3 * CHECKPOINT_EVERY + 17;
        assert_eq!(n % 2, 1);
        // The final band is 0.01: 0.01099 and 0.00901 are within 10 % of it, 0.0111, 0.0089 and
        // 0.5 are not. Unsettled rows up to `until` (in the first, second, third or last
        // interval, or none), among settled ones; the NIS decays from 42, so where the estimates
        // count as converged depends on its mean over the second half.
        for until in [40, 2100, 5000, n - 3, 0] {
            let rows = trace(n, |k, r| {
                let off = k < until && k % 7 != 3;
                r.innov_band_a = if k == n - 1 {
                    0.01
                } else if off {
                    [0.0111, 0.0089, 0.5][k % 3]
                } else {
                    [0.01, 0.01099, 0.00901][k % 3]
                };
                r.nis = 2.0 + (k % 13) as f64 * 0.25 + 40.0 * (-(k as f64) / 200.0).exp();
            });
            for len in [n, n - 1, n - 1000] {
                let rows = &rows[..len];
                let with = tallied(rows, n);
                let last = rows[len - 1].t;
                let used = with.1.half_index == rows.to_vec().first_at(0.5 * last).min(len - 1);
                // The tally is used for the whole run and for one a row short, not for one that
                // ended 1,000 rows early.
                assert_eq!(used, len != n - 1000, "until {until}, {len} rows");
                let (expect, got) = (transient(&s, &rows.to_vec()), transient(&s, &with));
                assert_eq!(got.1, expect.1, "until {until}, {len} rows");
                assert_eq!(got.0.t, expect.0.t);
                assert_eq!(got.0.reason, expect.0.reason);
            }
        }
    }

    #[test]
    fn transient_ends_at_the_later_of_controller_and_observer_start_up() {
        let mut s = preset("step").unwrap();
        s.ts = TS;
        s.gains.k1 = 1000.0; // 5/1000 s = 5 ms: the slowest of 1000, 1200, 1200, 1200
                             // Observer settled at 2 ms, then the controller's 5 ms.
        let rows = trace(100, |k, r| r.innov_band_a = band(k, 2));
        let (t, i) = transient(&s, &rows);
        assert_eq!((t.t, i), (rows[7].t, 7));
        assert!(
            t.reason.to_string().contains("(1/1000 s) = 5 ms"),
            "{}",
            t.reason
        );
        assert!(
            t.reason.to_string().contains("of its final value): 2 ms"),
            "{}",
            t.reason
        );
        // Within 10 % counts as settled; 11 % off at 19 ms does not: 20 ms, then 5 ms.
        let rows = trace(100, |k, r| {
            r.innov_band_a = match k {
                19 => 0.00444,
                30 => 0.0043,
                _ => band(k, 2),
            }
        });
        assert_eq!(transient(&s, &rows).1, 25);
        // IFOC: 2 ms, then 5/(2π·100 Hz) = 7.96 ms, so the first sample at or after 9.96 ms.
        s.controller = ControllerKind::Ifoc;
        s.ifoc.current_bw = 100.0;
        let rows = trace(100, |k, r| r.innov_band_a = band(k, 2));
        let (t, _) = transient(&s, &rows);
        assert_eq!(t.t, rows[10].t);
        assert!(
            t.reason.to_string().contains("IFOC current loops"),
            "{}",
            t.reason
        );
        // A run of 10 samples (0–9 ms) is clamped to its half, 4.5 ms: first sample 5 ms.
        let rows = trace(10, |k, r| r.innov_band_a = band(k, 2));
        let (t, i) = transient(&s, &rows);
        assert_eq!(i, 5);
        assert!(
            t.reason.to_string().contains("clamped to half"),
            "{}",
            t.reason
        );
        // One sample: the window is that sample.
        assert_eq!(transient(&s, &rows[..1].to_vec()).1, 0);
        // The estimates: NIS 50 until 30 ms, then 2. The first full 2 ms window with a mean
        // within 2 × 2 is [30, 31] ms (mean 2); whether 31 − 29 ms counts as a whole window is
        // up to rounding, so 31 or 32 ms; the IFOC's 7.96 ms follow.
        let rows = trace(100, |k, r| {
            r.innov_band_a = band(k, 2);
            r.nis = if k < 30 { 50.0 } else { 2.0 };
        });
        let (t, i) = transient(&s, &rows);
        assert!((39..=40).contains(&i), "{}", t.reason);
        let converged = format!("level in the second half, for 5 ms): {} ms", i - 8);
        assert!(t.reason.to_string().contains(&converged), "{}", t.reason);
        // A noise-free run whose NIS decays to zero: the estimates' part is not used.
        let rows = trace(100, |k, r| {
            r.innov_band_a = band(k, 2);
            r.nis = 100.0 * 0.5f64.powi(k as i32);
        });
        assert!(transient(&s, &rows)
            .0
            .reason
            .to_string()
            .contains("not used"));
    }

    #[test]
    fn the_speed_estimate_ends_a_start_up_the_nis_cannot_see() {
        let mut s = preset("step").unwrap();
        s.ts = TS;
        // NIS and flux at their later level from the start; the speed estimate 1 rad/s off until
        // 20 ms, then 0.1: the first window of 5 samples within 2 × 0.1 ends at 24 ms, and holds.
        let rows = trace(200, |k, r| {
            r.innov_band_a = band(k, 2);
            r.nis = 2.0;
            r.omega_est_err = if k < 20 { 1.0 } else { 0.1 };
        });
        let (t, i) = transient(&s, &rows);
        // 24 ms, then 5/1200 s: the first sample at or after 28.17 ms.
        assert_eq!(i, 29, "{}", t.reason);
        assert!(t
            .reason
            .to_string()
            .contains("(5 ms windows, for 5 ms): 24 ms"));
        // A load step in the second half raises the error there; the second quarter's level
        // still ends the start-up at the same time.
        let rows = trace(200, |k, r| {
            r.innov_band_a = band(k, 2);
            r.nis = 2.0;
            r.omega_est_err = if k < 20 {
                1.0
            } else if k < 100 {
                0.1
            } else {
                3.0
            };
        });
        assert_eq!(transient(&s, &rows).1, 29);
        // A perfect observer: no speed error, nothing added.
        let rows = trace(200, |k, r| {
            r.innov_band_a = band(k, 2);
            r.nis = 2.0;
        });
        let (t, _) = transient(&s, &rows);
        assert!(
            t.reason.to_string().contains(
                "twice its later RMS error (5 ms windows, for 5 ms): never in the first half"
            ),
            "{}",
            t.reason
        );
    }

    #[test]
    fn the_start_up_ends_at_the_latest_with_the_scenarios_first_event() {
        // The step preset's step at 50 ms: NIS far above its later level until 80 ms, so the
        // estimates would count as converged at 80 ms; the step cuts it.
        let mut s = preset("step").unwrap();
        s.ts = TS;
        let rows = trace(300, |k, r| {
            r.innov_band_a = band(k, 2);
            r.nis = if k < 80 { 50.0 } else { 2.0 };
        });
        let (t, i) = transient(&s, &rows);
        assert_eq!(i, 50, "{}", t.reason);
        assert!(t
            .reason
            .to_string()
            .contains("cut at the scenario's first event, at 50 ms"));
        // An event before the controller's own start-up does not cut it, and a later one still
        // does.
        if let Reference::Step { ref mut time, .. } = s.reference {
            *time = 0.002;
        }
        // (the estimates converge at 81 ms, then 5/1200 s: 86 ms).
        assert_eq!(transient(&s, &rows).1, 86);
        s.load_step.time = 0.07;
        s.load_step.torque = 2.0;
        assert_eq!(transient(&s, &rows).1, 70);
        s.load_step.torque = 0.0;
        // The load step counts too; a step of size 0 does not.
        if let Reference::Step { ref mut size, .. } = s.reference {
            *size = 0.0;
        }
        s.load_step.time = 0.06;
        s.load_step.torque = 2.0;
        assert_eq!(transient(&s, &rows).1, 60);
    }
}
