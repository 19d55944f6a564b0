//! The closed-loop frequency response: runs of sinusoidal speed references, the fit of their
//! fundamentals, the check that each run settled, and the bandwidth and phase read off the points.

use crate::control::Reference;
use crate::record::Row;
use crate::scenario::{Scenario, ScenarioError};
use crate::sim::{mib, trace_bytes, Simulation, MAX_TRACE_BYTES};
use crate::text::{csv, short, Arg, Message};
use serde::{Deserialize, Serialize};
use std::f64::consts::PI;

/// How one frequency is measured.
#[derive(Clone, Copy, Debug, PartialEq, Serialize)]
pub struct SweepSettings {
    /// Amplitude of the sinusoidal speed reference (rad/s).
    pub amp: f64,
    /// Length of each run (s); the fit uses the whole periods in its second half, and the
    /// settling check the last whole periods of the run.
    pub duration: f64,
    /// Operating speed the sine rides on (rad/s).
    pub offset: f64,
}

impl Default for SweepSettings {
    fn default() -> Self {
        // 0.02 rad/s keeps the voltages inside 400 V up to 1 kHz on the paper's motor.
        SweepSettings {
            amp: 0.02,
            duration: 0.2,
            offset: 0.0,
        }
    }
}

/// The measured response at one frequency.
#[cfg_attr(
    target_arch = "wasm32",
    derive(tsify::Tsify),
    tsify(missing_as_null, hashmap_as_object)
)]
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub struct SweepPoint {
    /// Reference frequency (Hz).
    pub freq: f64,
    /// |ω| / |ω_d| of the fundamentals.
    pub gain: f64,
    /// The same gain in decibels, 20·log10(gain).
    pub gain_db: f64,
    /// Phase of ω relative to ω_d (degrees, in (−270, 90]).
    pub phase: f64,
    /// |ω̂| / |ω_d| (the speed estimate the controller used).
    pub gain_hat: f64,
    /// Phase of ω̂ relative to ω_d (degrees).
    pub phase_hat: f64,
    /// Fraction of samples whose commanded voltage exceeded the limit.
    pub saturated: f64,
    /// Largest stator-current magnitude |i_s| = √(i_sa² + i_sb²) of the motor over the fit
    /// window (A): the current the point needs.
    pub peak_current: f64,
    /// The scenario's rated current, the |i_s| to compare [`SweepPoint::peak_current`] with (A).
    pub rated_current: f64,
    /// Why the run stopped early, if it did (the other figures are then NaN).
    pub failure: Option<String>,
    /// Change of |ω|/|ω_d| from the first to the second half of the settling check (dB).
    pub gain_change_db: f64,
    /// Change of the phase of ω over the same halves (degrees, in [−180, 180]).
    pub phase_change: f64,
    /// Why the run is not taken to have reached a periodic steady state, if it is not; such a
    /// point is never used for the bandwidth or the phase at 200 Hz. The core's message; or, for
    /// a point that crossed the page on its way to the summary or the CSV, the text the page
    /// said it as.
    #[cfg_attr(target_arch = "wasm32", tsify(type = "Message | string | null"))]
    pub unsettled: Option<Arg>,
}

/// Largest half-to-half change of the gain of ω (dB) and of its phase (degrees) of a settled
/// point: a 5 % change of the response, twice the largest that noise and slow drift give in runs
/// that settle (0.19 dB, 1.2°), and half the least of IFOC runs too short to settle (0.84 dB).
/// A run of fewer than four whole periods compares its last period with the one before, which
/// holds the start-up: such a point is flagged even on a loop that settles in milliseconds (the
/// lowest point of the default sweep, 10 Hz in 0.2 s runs, by about 5°). That is the check
/// working: the run cannot show a periodic steady state.
pub const SETTLED_GAIN_DB: f64 = 0.4;
/// See [`SETTLED_GAIN_DB`] (degrees).
pub const SETTLED_PHASE_DEG: f64 = 3.0;

/// How far the amplitude fitted from ω_d itself over the fit window may be from the amplitude set
/// (relative). The fit of an exact sine is within rounding of it (1e-12 relative at the default
/// 0.02 rad/s, up to the Nyquist frequency); only an amplitude lost to rounding misses it: one
/// whose square underflows (below about 1e-154 rad/s) or that vanishes against the offset in
/// offset + amp·sin(·). Such an amplitude would give an infinite or meaningless gain.
pub const SWEEP_AMP_TOL: f64 = 0.01;

/// `count` log-spaced frequencies from `lo` to `hi` (Hz), after checking the request.
pub fn checked_grid(lo: f64, hi: f64, count: usize) -> Result<Vec<f64>, String> {
    if !(lo.is_finite() && hi.is_finite() && lo > 0.0 && hi >= lo && (1..=200).contains(&count)) {
        return Err(format!(
            "frequency grid {}:{}:{count}: expected 0 < lo ≤ hi (Hz) and 1 to 200 points",
            short(lo),
            short(hi)
        ));
    }
    Ok(log_grid(lo, hi, count))
}

/// `count` frequencies from `lo` to `hi` (Hz), logarithmically spaced.
pub fn log_grid(lo: f64, hi: f64, count: usize) -> Vec<f64> {
    if count == 1 {
        return vec![lo];
    }
    let (a, b) = (libm::log(lo), libm::log(hi));
    (0..count)
        .map(|i| libm::exp(a + (b - a) * i as f64 / (count - 1) as f64))
        .collect()
}

/// Amplitude and phase (radians) of the component at `w` (rad/s) of a sampled signal, by least
/// squares: x ≈ a·sin(wt) + b·cos(wt) + c. The constant is fitted too, because a window of whole
/// periods rarely holds a whole number of samples, so an offset would leak into a and b.
fn fundamental(rows: &[Row], w: f64, signal: impl Fn(&Row) -> f64) -> (f64, f64) {
    fit(rows.iter().map(|r| (r.t, signal(r))), w)
}

/// [`fundamental`] of the samples (t, x).
fn fit(samples: impl Iterator<Item = (f64, f64)>, w: f64) -> (f64, f64) {
    // Normal equations G·[a, b, c] = h with basis (sin, cos, 1).
    let mut g = [[0.0; 3]; 3];
    let mut h = [0.0; 3];
    for (t, x) in samples {
        let (s, c) = libm::sincos(w * t);
        let basis = [s, c, 1.0];
        for i in 0..3 {
            h[i] += basis[i] * x;
            for j in 0..3 {
                g[i][j] += basis[i] * basis[j];
            }
        }
    }
    // Cramer's rule on the 3×3 system.
    let det3 = |m: &[[f64; 3]; 3]| {
        m[0][0] * (m[1][1] * m[2][2] - m[1][2] * m[2][1])
            - m[0][1] * (m[1][0] * m[2][2] - m[1][2] * m[2][0])
            + m[0][2] * (m[1][0] * m[2][1] - m[1][1] * m[2][0])
    };
    let d = det3(&g);
    let solve = |k: usize| {
        let mut m = g;
        for i in 0..3 {
            m[i][k] = h[i];
        }
        det3(&m) / d
    };
    let (a, b) = (solve(0), solve(1));
    ((a * a + b * b).sqrt(), libm::atan2(b, a))
}

/// Wraps a phase difference (radians) to degrees in (−270, 90]: small leads stay small, and lags
/// up to 270° stay continuous.
fn lag_degrees(phase: f64) -> f64 {
    let mut d = phase * 180.0 / PI;
    while d > 90.0 {
        d -= 360.0;
    }
    while d <= -270.0 {
        d += 360.0;
    }
    d
}

/// Gain and phase (radians) of the fundamental of `signal` relative to that of ω_d.
fn response(rows: &[Row], w: f64, signal: impl Fn(&Row) -> f64) -> (f64, f64) {
    // The offset is constant and orthogonal to the fundamental over whole periods.
    let (ref_amp, ref_phase) = fundamental(rows, w, |r| r.omega_ref);
    let (amp, phase) = fundamental(rows, w, signal);
    (amp / ref_amp, phase - ref_phase)
}

/// Runs `base` with the reference amp·sin(2π·freq·t), fits the fundamentals of ω and ω̂ over the
/// whole periods in the second half of the run, and checks that ω has settled: its fundamental
/// over the last k whole periods must match the one over the k before them, with k half the
/// periods of the fit window but at least one (the check then reaches into the first half).
pub fn sweep_point(
    base: &Scenario,
    freq: f64,
    settings: &SweepSettings,
) -> Result<SweepPoint, ScenarioError> {
    let run = SineRun::new(base, freq, settings)?;
    run.check_reference(settings)?;
    // The fit reads every row of the run: they must fit in memory.
    let bytes = trace_bytes(&run.s, 1);
    if bytes > MAX_TRACE_BYTES {
        return Err(ScenarioError::TooLarge {
            what: Message::new("sweep-run-too-large")
                .count("samples", run.s.steps())
                .fixed("mib", mib(bytes), 1)
                .count("max", MAX_TRACE_BYTES >> 20),
        });
    }
    let mut sim = Simulation::new(&run.s, 1)?;
    let failure = sim.run().err().map(|e| e.to_string());
    let rows = sim.recorder().rows();
    let window = &rows[run.at(rows, run.window_start)..];
    if failure.is_some() || window.is_empty() {
        return Ok(failed_point(freq, run.s.i_rated, failure));
    }
    run.measure(rows, settings)
}

/// One sweep point's run: the scenario with the sine reference, and where its fit window and
/// the halves of its settling check fall.
struct SineRun {
    /// The base scenario with the sine reference and the sweep's run length.
    s: Scenario,
    /// Reference frequency (Hz).
    freq: f64,
    /// Whole periods in the fit window.
    periods: f64,
    /// One period of the sine (s).
    period: f64,
    /// Its angular frequency (rad/s).
    w: f64,
    /// Start of the fit window: the whole periods that end the run's second half (s).
    window_start: f64,
}

impl SineRun {
    /// The run of `base` with the sine of `freq` and `settings`, refused when the scenario is
    /// not valid, the amplitude not positive, the frequency not below Nyquist, or the fit window
    /// shorter than one period.
    fn new(base: &Scenario, freq: f64, settings: &SweepSettings) -> Result<SineRun, ScenarioError> {
        let mut s = base.clone();
        s.reference = Reference::Sine {
            amp: settings.amp,
            freq,
            offset: settings.offset,
        };
        s.duration = settings.duration;
        // The sine's fields carry the codec's ranges, so a bad frequency or offset is named.
        s.validate()?;
        if settings.amp <= 0.0 {
            return Err(ScenarioError::OutOfRange {
                key: "sine.amp".to_string(),
                value: settings.amp,
                allowed: Message::new("sweep-allowed-amp"),
            });
        }
        if freq >= 0.5 / s.ts {
            return Err(ScenarioError::OutOfRange {
                key: "freq".to_string(),
                value: freq,
                allowed: Message::new("sweep-allowed-nyquist").real("nyquist", 0.5 / s.ts),
            });
        }
        let half = settings.duration / 2.0;
        let periods = (half * freq).floor();
        if periods < 1.0 {
            return Err(ScenarioError::OutOfRange {
                key: "freq".to_string(),
                value: freq,
                allowed: Message::new("sweep-allowed-period")
                    .real("least", 1.0 / half)
                    .real("duration", settings.duration),
            });
        }
        let period = 1.0 / freq;
        Ok(SineRun {
            s,
            freq,
            periods,
            period,
            w: 2.0 * PI * freq,
            window_start: settings.duration - periods * period,
        })
    }

    /// Whether a row at time t belongs to the run's part from time `start` on (the row times are
    /// the loop's k·Ts).
    fn from(&self, start: f64) -> impl Fn(f64) -> bool {
        let ts = self.s.ts;
        move |t: f64| t >= start - 0.5 * ts
    }

    /// The index of the first of `rows` at or after time `t`.
    fn at(&self, rows: &[Row], t: f64) -> usize {
        let inside = self.from(t);
        rows.partition_point(|r| !inside(r.t))
    }

    /// Refuses, by name, an amplitude the fit cannot resolve: ω_d over the fit window is known
    /// before the run, so it is fitted here rather than measured as an infinite gain.
    fn check_reference(&self, settings: &SweepSettings) -> Result<(), ScenarioError> {
        let s = &self.s;
        let in_window = self.from(self.window_start);
        let (reference_amp, _) = fit(
            (0..s.steps())
                .map(|k| k as f64 * s.ts)
                .filter(|&t| in_window(t))
                .map(|t| (t, s.reference.sample(t).value)),
            self.w,
        );
        let resolved = (reference_amp - settings.amp).abs() <= SWEEP_AMP_TOL * settings.amp;
        // A NaN fit is not resolved either.
        if !resolved {
            return Err(unmeasurable(
                settings,
                Message::new("sweep-unresolved")
                    .short("found", reference_amp)
                    .real("tolerance", SWEEP_AMP_TOL * 100.0)
                    .short("offset", settings.offset),
            ));
        }
        Ok(())
    }

    /// The point measured from the `rows` of a run that did not fail and recorded its fit
    /// window: the fundamentals' gains and phases, the settling check, the share of saturated
    /// samples and the peak current; refused when the response is too small for the fit.
    fn measure(&self, rows: &[Row], settings: &SweepSettings) -> Result<SweepPoint, ScenarioError> {
        let (freq, w, period) = (self.freq, self.w, self.period);
        let window = &rows[self.at(rows, self.window_start)..];
        let k = (self.periods / 2.0).floor().max(1.0);
        let halves = [
            &rows[self.at(rows, settings.duration - 2.0 * k * period)
                ..self.at(rows, settings.duration - k * period)],
            &rows[self.at(rows, settings.duration - k * period)..],
        ];
        let (gain, phase) = response(window, w, |r| r.omega);
        let (gain_hat, phase_hat) = response(window, w, |r| r.omega_used);
        // ω only: at high frequencies the fundamental of the IFOC's MRAS estimate is buried in
        // its noise, so its halves differ by up to 5 dB and 30° even in runs where ω has long
        // settled.
        let [(g1, p1), (g2, p2)] = halves.map(|h| response(h, w, |r| r.omega));
        let gain_change_db = 20.0 * libm::log10(g2 / g1);
        let phase_change = libm::remainder((p2 - p1) * 180.0 / PI, 360.0);
        let gain_db = 20.0 * libm::log10(gain);
        // A response too small for the fit (its square underflows) reads as a gain of 0 or ∞.
        let figures = [
            ("gain_db", gain_db),
            ("gain_hat", gain_hat),
            ("phase", phase),
            ("phase_hat", phase_hat),
            ("gain_change_db", gain_change_db),
            ("phase_change", phase_change),
        ];
        if let Some((name, value)) = figures.iter().find(|(_, v)| !v.is_finite()) {
            return Err(unmeasurable(
                settings,
                Message::new("sweep-too-small")
                    .short("freq", freq)
                    .text("name", *name)
                    .real("value", *value),
            ));
        }
        let settled =
            gain_change_db.abs() <= SETTLED_GAIN_DB && phase_change.abs() <= SETTLED_PHASE_DEG;
        // The scenario's own limit: the box, the circle or the hexagon.
        let limit = self.s.limit();
        let saturated = rows
            .iter()
            .filter(|r| limit.exceeds(&[r.u_a_cmd, r.u_b_cmd]))
            .count() as f64
            / rows.len() as f64;
        // The largest |i_s|² first: √ is monotonic, so its root is the largest |i_s|.
        let peak_current = window
            .iter()
            .map(|r| r.i_sa * r.i_sa + r.i_sb * r.i_sb)
            .fold(0.0, f64::max)
            .sqrt();
        Ok(SweepPoint {
            freq,
            gain,
            gain_db,
            phase: lag_degrees(phase),
            gain_hat,
            phase_hat: lag_degrees(phase_hat),
            saturated,
            peak_current,
            rated_current: self.s.i_rated,
            failure: None,
            gain_change_db,
            phase_change,
            unsettled: (!settled).then(|| {
                Message::new("sweep-not-settled")
                    .count("periods", (2.0 * k) as i64)
                    .fixed("gain", gain_change_db, 2)
                    .fixed("phase", phase_change, 1)
                    .real("gain-bound", SETTLED_GAIN_DB)
                    .real("phase-bound", SETTLED_PHASE_DEG)
                    .into()
            }),
        })
    }
}

/// The point at `freq` of a run that failed (`failure`) or recorded nothing in its fit window:
/// every figure NaN but the rated current `rated_current`.
fn failed_point(freq: f64, rated_current: f64, failure: Option<String>) -> SweepPoint {
    SweepPoint {
        freq,
        gain: f64::NAN,
        gain_db: f64::NAN,
        phase: f64::NAN,
        gain_hat: f64::NAN,
        phase_hat: f64::NAN,
        saturated: f64::NAN,
        peak_current: f64::NAN,
        rated_current,
        failure: failure.or(Some("nothing recorded in the fit window".to_string())),
        gain_change_db: f64::NAN,
        phase_change: f64::NAN,
        unsettled: None,
    }
}

/// The error for a sweep amplitude that cannot be measured, with the reason.
fn unmeasurable(settings: &SweepSettings, reason: Message) -> ScenarioError {
    ScenarioError::OutOfRange {
        key: "sine.amp".to_string(),
        value: settings.amp,
        allowed: Message::new("sweep-allowed-measurable").said("reason", reason),
    }
}

/// The sweep as CSV: one line per frequency, then a `#` line with the summary. `settled` is
/// false for a failed run too; `peak_current_a` is the largest |i_s| over the fit window (A).
pub fn sweep_csv(points: &[SweepPoint]) -> String {
    let mut out = String::from(
        "freq_hz,gain,gain_db,phase_deg,gain_hat,phase_hat_deg,saturated,failure,\
         settled,gain_change_db,phase_change_deg,peak_current_a\n",
    );
    for p in points {
        let failure = csv::field(p.failure.as_deref().unwrap_or(""));
        out += &format!(
            "{},{},{},{},{},{},{},{failure},{},{},{},{}\n",
            p.freq,
            p.gain,
            p.gain_db,
            p.phase,
            p.gain_hat,
            p.phase_hat,
            p.saturated,
            p.failure.is_none() && p.unsettled.is_none(),
            p.gain_change_db,
            p.phase_change,
            p.peak_current
        );
    }
    let s = summarise(points);
    let show = |v: Option<f64>| v.map_or("none".to_string(), |v| v.to_string());
    let bandwidth = if s.bandwidth_unsettled {
        "unsettled".to_string()
    } else if s.below_grid {
        "below_lowest_frequency".to_string()
    } else {
        show(s.bandwidth)
    };
    out += &format!(
        "# bandwidth_hz={} phase_at_200hz_deg={} unsettled={}\n",
        bandwidth,
        show(s.phase_at_200),
        s.unsettled
    );
    out
}

/// Figures read off a measured frequency response; none rests on a point that had not settled.
#[cfg_attr(
    target_arch = "wasm32",
    derive(tsify::Tsify),
    tsify(missing_as_null, hashmap_as_object)
)]
#[derive(Clone, Debug, PartialEq, Serialize)]
pub struct SweepSummary {
    /// First frequency where the gain falls below 1/√2, interpolated in log frequency (Hz).
    pub bandwidth: Option<f64>,
    /// The gain is already below 1/√2 at the lowest frequency measured.
    pub below_grid: bool,
    /// The bandwidth reading rests on an unsettled point, so none is given.
    pub bandwidth_unsettled: bool,
    /// Phase of ω at 200 Hz, interpolated in log frequency between settled points (degrees).
    pub phase_at_200: Option<f64>,
    /// Completed points that had not settled.
    pub unsettled: usize,
    /// Points whose run failed.
    pub failed: usize,
    /// The largest share of saturated samples over the points that ran (none when none ran).
    pub worst_saturation: Option<f64>,
    /// The largest |i_s| over the points that ran (A).
    pub peak_current: Option<f64>,
    /// The scenario's rated current (A).
    pub rated_current: Option<f64>,
    /// The frequencies (Hz) of the points whose |i_s| went above the rating.
    pub over_rating: Vec<f64>,
}

fn interpolate_log(f0: f64, f1: f64, y0: f64, y1: f64, target: f64) -> f64 {
    let u = (target - y0) / (y1 - y0);
    libm::exp(libm::log(f0) + u * (libm::log(f1) - libm::log(f0)))
}

/// The −3 dB bandwidth and the phase at 200 Hz of sweep points. The first fall below 1/√2 is
/// sought over every completed point; the reading rests on the two points it lies between (the
/// lowest point if the gain starts below, the highest if it never falls) and is withheld if one of
/// them has not settled. The phase is interpolated between settled points only.
pub fn summarise(points: &[SweepPoint]) -> SweepSummary {
    let cutoff = std::f64::consts::FRAC_1_SQRT_2;
    let ran: Vec<&SweepPoint> = points.iter().filter(|p| p.failure.is_none()).collect();
    let largest = |f: fn(&SweepPoint) -> f64| ran.iter().map(|p| f(p)).reduce(f64::max);
    let worst_saturation = largest(|p| p.saturated);
    let peak_current = largest(|p| p.peak_current);
    let rated_current = ran.first().map(|p| p.rated_current);
    let over_rating = ran
        .iter()
        .filter(|p| p.peak_current > p.rated_current)
        .map(|p| p.freq)
        .collect();
    let failed = points.len() - ran.len();
    // Only completed points, in increasing frequency, one per frequency.
    let mut points: Vec<&SweepPoint> = points
        .iter()
        .filter(|p| p.gain.is_finite() && p.phase.is_finite())
        .collect();
    points.sort_by(|a, b| a.freq.total_cmp(&b.freq));
    points.dedup_by(|a, b| a.freq == b.freq);
    let settled = |p: &SweepPoint| p.unsettled.is_none();
    let fall = points.iter().position(|p| p.gain < cutoff);
    let rests_on = match fall {
        Some(i) => &points[i.saturating_sub(1)..=i],
        None => &points[points.len().saturating_sub(1)..],
    };
    let bandwidth_unsettled = !rests_on.iter().all(|p| settled(p));
    let (bandwidth, below_grid) = match fall {
        _ if bandwidth_unsettled => (None, false),
        Some(0) => (None, true),
        Some(i) => {
            let (p, q) = (points[i - 1], points[i]);
            (
                Some(interpolate_log(p.freq, q.freq, p.gain, q.gain, cutoff)),
                false,
            )
        }
        None => (None, false),
    };
    let unsettled = points.iter().filter(|p| !settled(p)).count();
    points.retain(|p| settled(p));
    let phase_at_200 = points
        .windows(2)
        .find(|w| w[0].freq <= 200.0 && w[1].freq >= 200.0)
        .map(|w| {
            let u = (libm::log(200.0) - libm::log(w[0].freq))
                / (libm::log(w[1].freq) - libm::log(w[0].freq));
            w[0].phase + u * (w[1].phase - w[0].phase)
        });
    SweepSummary {
        bandwidth,
        below_grid,
        bandwidth_unsettled,
        phase_at_200,
        unsettled,
        failed,
        worst_saturation,
        peak_current,
        rated_current,
        over_rating,
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::record::Row;

    #[test]
    fn fundamental_ignores_a_large_offset_on_a_window_of_whole_periods_but_not_whole_samples() {
        // 183 Hz at 20 kHz: a period is 109.3 samples, so the window never holds whole samples.
        let (w, ts) = (2.0 * PI * 183.0, 5e-5);
        let rows: Vec<Row> = (0..(9.0 / 183.0 / ts) as usize)
            .map(|k| {
                let t = k as f64 * ts;
                Row {
                    t,
                    omega: 40.0 + 0.05 * libm::sin(w * t - 1.2),
                    ..Row::default()
                }
            })
            .collect();
        let (amp, phase) = fundamental(&rows, w, |r| r.omega);
        assert!(
            (amp - 0.05).abs() < 1e-6 && (phase + 1.2).abs() < 1e-5,
            "{amp} {phase}"
        );
    }

    #[test]
    fn summary_sorts_skips_failed_points_and_flags_a_response_below_the_grid() {
        let c = std::f64::consts::FRAC_1_SQRT_2;
        let mut failed = point(300.0, f64::NAN, f64::NAN);
        failed.failure = Some("diverged".to_string());
        let s = summarise(&[
            point(400.0, c - 0.3, -90.0),
            failed,
            point(100.0, c + 0.1, -30.0),
            point(100.0, c + 0.1, -30.0),
        ]);
        assert!(s.bandwidth.is_some() && !s.below_grid);
        assert!(s.phase_at_200.unwrap().is_finite());
        let low = summarise(&[point(10.0, 0.5, -60.0), point(20.0, 0.3, -80.0)]);
        assert!(low.below_grid && low.bandwidth.is_none());
        assert!(
            sweep_csv(&[point(10.0, 0.5, -60.0)]).contains("bandwidth_hz=below_lowest_frequency")
        );
    }

    #[test]
    fn a_run_too_long_to_keep_its_rows_is_refused_naming_the_sweeps_own_settings() {
        let s = Scenario::parse("v=1&preset=step&ts=0.00001").unwrap();
        let settings = SweepSettings {
            duration: 20.0,
            ..SweepSettings::default()
        };
        let e = sweep_point(&s, 100.0, &settings).unwrap_err().to_string();
        assert!(
            e.contains("each sweep run keeps its 2000000 samples")
                && e.ends_with("shorten the sweep's run length or raise 'ts'")
                && !e.contains("every"),
            "{e}"
        );
    }

    #[test]
    fn frequencies_at_or_above_nyquist_are_refused() {
        // Ts = 100 µs: the Nyquist frequency is 5 kHz, inside the codec's range for sine.freq.
        let s = Scenario::parse("v=1&preset=step&ts=0.0001").unwrap();
        let err = sweep_point(&s, 5000.0, &SweepSettings::default())
            .unwrap_err()
            .to_string();
        assert!(err.contains("Nyquist"), "{err}");
    }

    #[test]
    fn fundamental_recovers_a_known_sinusoid_over_whole_periods() {
        let (w, ts) = (2.0 * PI * 37.0, 5e-5);
        let rows: Vec<Row> = (0..(4.0 / 37.0 / ts) as usize)
            .map(|k| {
                let t = k as f64 * ts;
                Row {
                    t,
                    omega: 3.0 + 0.7 * libm::sin(w * t + 0.4) + 0.1 * libm::sin(3.0 * w * t),
                    ..Row::default()
                }
            })
            .collect();
        let (amp, phase) = fundamental(&rows, w, |r| r.omega);
        assert!(
            (amp - 0.7).abs() < 1e-3 && (phase - 0.4).abs() < 1e-3,
            "{amp} {phase}"
        );
    }

    fn point(freq: f64, gain: f64, phase: f64) -> SweepPoint {
        SweepPoint {
            freq,
            gain,
            gain_db: 20.0 * libm::log10(gain),
            phase,
            gain_hat: gain,
            phase_hat: phase,
            saturated: 0.0,
            peak_current: 1.0,
            rated_current: 5.0,
            failure: None,
            gain_change_db: 0.0,
            phase_change: 0.0,
            unsettled: None,
        }
    }

    fn unsettled(freq: f64, gain: f64, phase: f64) -> SweepPoint {
        SweepPoint {
            unsettled: Some(Arg::Text("not settled".to_string())),
            ..point(freq, gain, phase)
        }
    }

    #[test]
    fn summary_gives_no_reading_that_rests_on_an_unsettled_point() {
        let c = std::f64::consts::FRAC_1_SQRT_2;
        let (above, below) = (c + 0.1, c - 0.3);
        // The gain falls between a settled and an unsettled point, either way round.
        for pts in [
            [point(100.0, above, -30.0), unsettled(400.0, below, -90.0)],
            [unsettled(100.0, above, -30.0), point(400.0, below, -90.0)],
        ] {
            let s = summarise(&pts);
            assert!(s.bandwidth_unsettled && s.bandwidth.is_none() && !s.below_grid);
            assert_eq!((s.unsettled, s.phase_at_200), (1, None));
            assert!(sweep_csv(&pts)
                .ends_with("# bandwidth_hz=unsettled phase_at_200hz_deg=none unsettled=1\n"));
        }
        // Below at the lowest point, or never below up to the highest: that point decides.
        assert!(
            summarise(&[unsettled(10.0, 0.5, -60.0), point(20.0, 0.3, -80.0)]).bandwidth_unsettled
        );
        assert!(summarise(&[point(10.0, 1.0, 0.0), unsettled(20.0, 0.9, 0.0)]).bandwidth_unsettled);
        // Unsettled points away from the fall do not stop the reading.
        let s = summarise(&[
            unsettled(50.0, 1.0, 0.0),
            point(100.0, above, -30.0),
            point(400.0, below, -90.0),
            unsettled(800.0, 0.1, -180.0),
        ]);
        assert!(s.bandwidth.is_some() && !s.bandwidth_unsettled && s.unsettled == 2);
        // The phase at 200 Hz is interpolated between the settled points around an unsettled one.
        let s = summarise(&[
            point(100.0, 1.0, -30.0),
            unsettled(200.0, 1.0, 0.0),
            point(400.0, 1.0, -90.0),
        ]);
        assert!(s.bandwidth.is_none() && !s.bandwidth_unsettled);
        assert!((s.phase_at_200.unwrap() + 60.0).abs() < 1e-9);
    }

    #[test]
    fn summary_interpolates_bandwidth_and_phase_in_log_frequency() {
        let c = std::f64::consts::FRAC_1_SQRT_2;
        // Gain crosses 1/√2 a quarter of the way (in the gain) from 100 to 400 Hz.
        let pts = [point(100.0, c + 0.1, -30.0), point(400.0, c - 0.3, -90.0)];
        let s = summarise(&pts);
        let expected = libm::exp(libm::log(100.0) + 0.25 * (libm::log(400.0) - libm::log(100.0)));
        assert!((s.bandwidth.unwrap() - expected).abs() < 1e-9);
        assert!(
            (s.phase_at_200.unwrap() + 60.0).abs() < 1e-9,
            "halfway in log f"
        );
        assert_eq!(
            summarise(&[point(10.0, 1.0, 0.0), point(20.0, 0.9, 0.0)]).bandwidth,
            None
        );
    }
}
