//! Figures of a run: the end of the start-up transient and what tracking, saturation, the EKF's
//! consistency and the final errors look like after it, each with its unit and its window.
//!
//! Everything here reads the recorded trace; `imlab metrics` prints the list and the page shows it
//! as given.

use super::row::Row;
use super::samples::Samples;
use super::transient::{transient, Transient};
use super::warnings::{mean_nis_band, warnings_of, Astray, Warning, WarningKind};
use super::window::{Settling, Summand, Tenths, Window, TREND_TENTHS};
#[cfg(test)]
use crate::control::Reference;
use crate::scenario::Scenario;
use crate::text::Message;
use serde::Serialize;

/// One figure of a run.
#[cfg_attr(
    target_arch = "wasm32",
    derive(tsify::Tsify),
    tsify(missing_as_null, hashmap_as_object)
)]
#[derive(Clone, Debug, Serialize)]
pub struct Figure {
    /// Machine name, used by `imlab metrics` and the tests, e.g. "tracking_rms".
    pub name: &'static str,
    /// Short human label with symbols, e.g. "RMS of ω − ω_d" (`figure-NAME`).
    pub label: Message,
    /// The value, in `unit`.
    pub value: f64,
    /// Unit of `value` ("" for fractions and ratios).
    pub unit: &'static str,
    /// The part of the run it covers, e.g. "t ≥ 4.2 ms" or "last sample, t = 99.95 ms".
    pub window: Message,
    /// For a value read at the last sample: whether it had settled by then.
    pub trend: Option<Trend>,
}

/// How a value read at the last sample was still moving, from its samples over the last three
/// tenths of the recorded run (all after the start-up transient, which ends by half-way): a
/// least-squares line through the last tenth, and the means of the three tenths.
///
/// It is still changing ("changing") when the line shows a trend (it changes over the tenth by
/// more than twice the samples' scatter about it) and either
///
/// - the line changes by more than `tolerance` over the tenth, or
/// - the three means approach a value that is more than `tolerance` away: an exponential
///   approach with time constant τ shrinks each tenth's change by the same ratio q = e^(−tenth/τ),
///   so means changing by d₁ then d₂ with 0 < q = d₂/d₁ < 1 still have d₂·q/(1 − q) to go after
///   the last tenth (Aitken's Δ² extrapolation). An approach has its rate times its time
///   constant still to go, and one slower than the window after the transient cannot be told
///   from a drift, so the change still to come is taken as at most |rate| × that window.
///
/// Changes that reverse or do not shrink trace no approach, and only the line is read. A value
/// that is not changing is "fluctuating" when four times the samples' scatter about the line
/// is more than `tolerance` (its last sample does not stand for it), "drifting" when the EKF estimates the
/// load or R_r as a random walk (which the final values follow without end), and "settled"
/// otherwise. On a run that ran away no value is final: its state is "ran away".
#[cfg_attr(
    target_arch = "wasm32",
    derive(tsify::Tsify),
    tsify(missing_as_null, hashmap_as_object)
)]
#[derive(Clone, Copy, Debug, PartialEq, Serialize)]
pub struct Trend {
    /// Slope of the line through the last tenth (the figure's unit per second).
    pub rate: f64,
    /// Length of the last tenth of the recorded run, the line's span (s).
    pub over: f64,
    /// The most the value may still change for it to count as settled, and four times the most
    /// its samples may scatter about the line (the figure's unit): the larger of a fixed
    /// tolerance and 2 % of the value.
    pub tolerance: f64,
    /// Standard deviation of the samples about the line (the figure's unit).
    pub scatter: f64,
    /// What the approach traced by the three tenths' means still has to go after them, at most
    /// |rate| × the window after the transient (the figure's unit); None when their changes
    /// reverse or do not shrink.
    pub to_go: Option<f64>,
    /// Whether it had settled, and if not how (see [`Trend`]).
    pub state: TrendState,
    /// state == [`TrendState::Settled`].
    pub settled: bool,
    /// Whether it counts as settled by the last tenth alone: its line changes over the tenth by
    /// at most `tolerance` or twice the scatter, and the scatter is at most `tolerance`. This is
    /// the rule a version-1 challenge's brief states ("a value still changing over the last
    /// tenth of the run fails"), so a challenge judges by it.
    pub settled_in_last_tenth: bool,
}

/// How a value read at the last sample was still moving (see [`Trend`]); the page and the JSON
/// see it as "settled", "changing", "drifting", "fluctuating" or "ran away".
#[cfg_attr(
    target_arch = "wasm32",
    derive(tsify::Tsify),
    tsify(missing_as_null, hashmap_as_object)
)]
#[derive(Clone, Copy, Debug, PartialEq, Eq, Serialize)]
#[serde(rename_all = "lowercase")]
pub enum TrendState {
    /// Not changing, its samples' scatter within a quarter of its tolerance, and not tied to a
    /// random-walk estimate.
    Settled,
    /// Not changing over the last tenths, but tied to an estimate the EKF holds as a random walk
    /// (the load or R_r as a state): such an estimate wanders without end, and the value with it,
    /// so no stretch of the run tells where it ends (a run four times longer ends elsewhere).
    Drifting,
    /// Its line, or the approach its tenths trace, still moves it by more than its tolerance.
    Changing,
    /// Not changing, but four times its samples' scatter about the line exceeds its tolerance:
    /// its last sample does not stand for it.
    Fluctuating,
    /// The run ran away, so no value of it is final.
    #[serde(rename = "ran away")]
    RanAway,
}

/// A final speed error has settled when it still changes by at most this, or by at most
/// [`TREND_RELATIVE`] of its value if that is larger (rad/s): 0.01 rad/s is below what any
/// lesson reads, and a 200 Hz ripple of the presets' size fits a line of nearly zero slope over
/// whole periods.
const SPEED_TREND_TOL: f64 = 0.01;

/// A final flux error has settled when it still changes by at most this, or by at most
/// [`TREND_RELATIVE`] of its value if that is larger (Wb): 0.1 % of the presets' 1 Wb.
const FLUX_TREND_TOL: f64 = 1e-3;

/// Relative part of a final value's tolerance: a 2 % change of the value itself.
const TREND_RELATIVE: f64 = 0.02;

/// A final value is a single sample: it stands for the value only while this many times the
/// samples' scatter σ about their line fits its tolerance. Two such samples (this run's last,
/// and a run four times longer's) differ by noise alone with a scatter of √2·σ, at most 0.35 of
/// the tolerance: by more than the tolerance less than once in two hundred draws.
const FINAL_SCATTER: f64 = 4.0;

/// A change within twice the samples' scatter about the line cannot be told from the ripple of
/// a periodic reference or from noise: it is not called a trend.
const TREND_SCATTER: f64 = 2.0;

/// A figure's machine name, its words and its unit: one entry for each figure [`report`] gives.
#[cfg_attr(
    target_arch = "wasm32",
    derive(tsify::Tsify),
    tsify(missing_as_null, hashmap_as_object)
)]
#[derive(Clone, Debug, Serialize)]
pub struct FigureInfo {
    /// Machine name, as `imlab metrics` prints it.
    pub name: &'static str,
    /// In words, as `imlab metrics` and the page label it (`figure-NAME` of `core-run.ftl`).
    pub label: Message,
    /// Unit ("" for ratios).
    pub unit: &'static str,
}

/// The figure `name` in `unit`, labelled by its message `figure-NAME`.
macro_rules! fig {
    ($name:literal, $unit:literal) => {
        $crate::record::FigureInfo {
            name: $name,
            label: $crate::text::Message::new(concat!("figure-", $name)),
            unit: $unit,
        }
    };
}
pub(super) use fig;

/// Every figure [`report`] can give, in its order.
pub const FIGURE_INFO: &[FigureInfo] = &[
    fig!("transient_end", "s"),
    fig!("tracking_rms", "rad/s"),
    fig!("tracking_peak", "rad/s"),
    fig!("settling_time", "s"),
    fig!("saturated_share", ""),
    fig!("mean_nis", ""),
    fig!("mean_nis_low", ""),
    fig!("mean_nis_high", ""),
    fig!("current_peak", "A"),
    fig!("current_rms", "A"),
    fig!("current_rated", "A"),
    fig!("ripple_peak", "A"),
    fig!("ripple_rms", "A"),
    fig!("flux_error_final", "Wb"),
    fig!("speed_error_final", "rad/s"),
    fig!("speed_estimate_error_final", "rad/s"),
    fig!("law_residual", ""),
];

/// The entry of the figure named `name`, if [`report`] gives one.
pub fn figure_info(name: &str) -> Option<&'static FigureInfo> {
    FIGURE_INFO.iter().find(|f| f.name == name)
}

/// The transient and the figures of a run, computed together (the figures start at the end of
/// the transient): see [`report`].
#[cfg_attr(
    target_arch = "wasm32",
    derive(tsify::Tsify),
    tsify(missing_as_null, hashmap_as_object)
)]
#[derive(Clone, Debug, Serialize)]
pub struct Report {
    /// See [`transient`].
    pub transient: Transient,
    /// The figures after it (see [`Figure`]).
    pub figures: Option<Vec<Figure>>,
    /// Figures the run had not reached by its end, each in place of its value (see
    /// [`Unreached`]).
    pub unreached: Vec<Unreached>,
    /// What the figures must not be read without, in words (see [`Warning`]).
    pub warnings: Vec<Warning>,
    /// The peak and the RMS stator current as multiples of the rated current (none before any
    /// sample).
    pub peak_to_rated: Option<f64>,
    /// See [`Report::peak_to_rated`].
    pub rms_to_rated: Option<f64>,
    /// Whether the mean NIS lies within its 95 % band (none before any sample).
    pub nis_inside: Option<bool>,
}

/// A figure the run had not reached by its last sample: a step's settling time while ω is still
/// outside the band. It has no value, so none is given: the words stand in its place.
#[cfg_attr(
    target_arch = "wasm32",
    derive(tsify::Tsify),
    tsify(missing_as_null, hashmap_as_object)
)]
#[derive(Clone, Debug, PartialEq, Serialize)]
pub struct Unreached {
    /// The figure's machine name, e.g. "settling_time"; `imlab metrics` prints `NAME_reached,0,`.
    pub name: &'static str,
    /// The figure's label.
    pub label: Message,
    /// Where it stands among the report's figures: before the figure at this index, or after
    /// the last when it equals their count.
    pub index: usize,
    /// The part of the run it covers, e.g. "from the step at 50 ms".
    pub window: Message,
    /// The time of the last sample, by which it was not reached (s).
    pub end: f64,
    /// In words, e.g. "not settled by the end of the run (t = 99.95 ms)".
    pub text: Message,
}

/// The transient and the figures of the rows `rows` recorded from scenario `s`, computed together:
/// [`transient`], then the figures over the rows recorded so far, in this order:
/// `transient_end`, `tracking_rms`, `tracking_peak`, `settling_time` (step references only),
/// `saturated_share`, `mean_nis`, `mean_nis_low`, `mean_nis_high`, `current_peak`,
/// `current_rms`, `current_rated` (peak and RMS of |i_s| against the rating), `ripple_peak` and
/// `ripple_rms` (with PWM only), `flux_error_final`, `speed_error_final`,
/// `speed_estimate_error_final`. The window figures cover W = [transient end, last recorded
/// sample]. A figure whose value is not finite is left out; None when nothing is recorded.
/// A finished traced run is replayed once, for the window after the transient (and, for a step
/// reference, from the step if that is earlier); what the transient reads from every row it
/// tallied as it ran.
pub fn report(s: &Scenario, rows: &dyn Samples) -> Report {
    let (end, start) = transient(s, rows);
    let len = rows.count();
    if len == 0 {
        return Report {
            transient: end,
            figures: None,
            unreached: Vec::new(),
            warnings: Vec::new(),
            peak_to_rated: None,
            rms_to_rated: None,
            nis_inside: None,
        };
    }
    let last = rows.row(len - 1);
    // The step's settling, for a step reference whose step the run reached; it has a settling
    // time when ω ends inside the band.
    let step =
        Settling::step(&s.reference, s.ts, |t| rows.first_at(t)).filter(|st| last.t >= st.time);
    let unsettled_step = step
        .as_ref()
        .filter(|st| st.outside(&last))
        .map(|st| st.time);
    let mut settling = step.filter(|st| !st.outside(&last));
    let (w, tenths) = window_of(s, rows, start, len, &mut settling);
    let n = w.n as f64;
    let band = mean_nis_band(w.n);
    let astray = w.astray_from.map(|k| Astray {
        since: rows.time(start + k),
        from_window_start: k == 0,
        share: (w.n - k) as f64 / n,
    });
    let warnings = warnings_of(&last, w.reference_peak, w.nis / n, band, astray);
    let judge = TrendJudge {
        tenths: &tenths,
        over: last.t - tenths.line().t0,
        window: last.t - end.t,
        ran_away: warnings.iter().any(|w| w.kind == WarningKind::Runaway),
        // With a perfect observer the controller does not use the filter's estimates.
        random_walk: (s.ekf.load || s.ekf.rr) && !s.perfect,
    };
    let mut out = Figures(Vec::new());
    out.push_window(s, &w, end.t, settling, band);
    out.push_final(&last, &judge);
    let Figures(out) = out;
    let mut unreached = Vec::new();
    if let Some(time) = unsettled_step {
        unreached.push(unreached_figure(
            "settling_time",
            &out,
            Message::new("window-from-step").time("time", time),
            last.t,
            Message::new("unreached-not-settled").time("time", last.t),
        ));
    }
    let mean_nis = w.nis / n;
    Report {
        transient: end,
        figures: Some(out),
        unreached,
        warnings,
        peak_to_rated: Some(w.current_peak / s.i_rated),
        rms_to_rated: Some((w.current_sq / n).sqrt() / s.i_rated),
        nis_inside: Some(mean_nis >= band.0 && mean_nis <= band.1),
    }
}

/// The sums over the window from row `start` to `len` of the rows recorded from `s`, and the
/// last tenths' fits, with `settling` (the step's, if any) brought up to date: from the tally
/// kept as the run went when there is one, else from one pass over the window (from the step
/// on for a step reference that comes earlier).
fn window_of(
    s: &Scenario,
    rows: &dyn Samples,
    start: usize,
    len: usize,
    settling: &mut Option<Settling>,
) -> (Window, Tenths) {
    let tallied = rows.window_tally().and_then(|t| t.window(start, len));
    if let Some((w, tenths, last_out)) = tallied {
        if let Some(st) = settling {
            st.last_out = last_out;
        }
        return (w, tenths);
    }
    let limit = s.limit();
    let first = settling.as_ref().map_or(start, |st| st.from.min(start));
    // The final values' trend over the last tenths (inside the window, which starts at most
    // half-way).
    let mut tenths = Tenths::new(len, |i| rows.time(i));
    let mut w = Window::new();
    rows.visit(first, len, &mut |i, r| {
        if let Some(st) = settling.as_mut() {
            st.push(i, r);
        }
        if i < start {
            return true;
        }
        tenths.push(i, r);
        w.push(&Summand::of(r, &limit));
        true
    });
    (w, tenths)
}

/// What the trend of a value read at the last sample is judged from (see [`Trend`]).
struct TrendJudge<'a> {
    /// The last tenths' line fits and means.
    tenths: &'a Tenths,
    /// Span of the last tenth's line, to the last sample (s).
    over: f64,
    /// The window after the transient, to the last sample (s).
    window: f64,
    /// Whether the run ran away: no value of it is final.
    ran_away: bool,
    /// Whether the EKF holds the load or R_r as a random walk the controller follows.
    random_walk: bool,
}

impl TrendJudge<'_> {
    /// The trend of the final value `value` fitted as the tenths' signal `k`, with the fixed
    /// tolerance `tol`; None when the line has no finite slope.
    fn trend(&self, k: usize, value: f64, tol: f64) -> Option<Trend> {
        let line = self.tenths.line();
        let over = self.over;
        let rate = line.slope(k)?;
        let tolerance = tol.max(TREND_RELATIVE * value.abs());
        let scatter = line.scatter(k, rate);
        let change = (rate * over).abs();
        let visible = change > TREND_SCATTER * scatter;
        let to_go = approach(self.tenths.means(k)).map(|r| r.min((rate * self.window).abs()));
        let moves_in_tenth = visible && change > tolerance;
        let fluctuating = scatter > tolerance;
        // The last sample stands for the value only if four times its scatter fits the
        // tolerance: else the last sample of a run four times longer may end elsewhere by the
        // noise alone.
        let scattered = FINAL_SCATTER * scatter > tolerance;
        let state = if self.ran_away {
            TrendState::RanAway
        } else if moves_in_tenth || visible && to_go.is_some_and(|r| r > tolerance) {
            TrendState::Changing
        } else if scattered {
            TrendState::Fluctuating
        } else if self.random_walk {
            TrendState::Drifting
        } else {
            TrendState::Settled
        };
        rate.is_finite().then_some(Trend {
            rate,
            over,
            tolerance,
            scatter,
            to_go,
            state,
            settled: state == TrendState::Settled,
            settled_in_last_tenth: !(moves_in_tenth || fluctuating),
        })
    }
}

/// A report's figures as they are added, in [`FIGURE_INFO`]'s order.
struct Figures(Vec<Figure>);

impl Figures {
    /// Adds the figure `name` with `value` over `window` and, for a final value, its `trend`;
    /// a value that is not finite is left out.
    fn push(&mut self, name: &'static str, value: f64, window: &Message, trend: Option<Trend>) {
        let info = figure_info(name).expect("a figure of the table");
        if value.is_finite() {
            self.0.push(Figure {
                name,
                label: info.label.clone(),
                value,
                unit: info.unit,
                window: window.clone(),
                trend,
            });
        }
    }

    /// Adds the start-up's end `end` (s) and the figures over the window `w` after it of a run
    /// of `s`: tracking, the step's `settling` (if settled), saturation, the mean NIS with its
    /// `band`, currents and, with PWM, the ripple.
    fn push_window(
        &mut self,
        s: &Scenario,
        w: &Window,
        end: f64,
        settling: Option<Settling>,
        band: (f64, f64),
    ) {
        let n = w.n as f64;
        let in_w = Message::new("window-after-transient").time("time", end);
        let (low, high) = band;
        self.push(
            "transient_end",
            end,
            &Message::new("window-start-up").time("time", end),
            None,
        );
        self.push("tracking_rms", (w.tracking_sq / n).sqrt(), &in_w, None);
        self.push("tracking_peak", w.tracking_peak, &in_w, None);
        if let Some((value, time)) = settling.map(|st| st.result()) {
            self.push(
                "settling_time",
                value,
                &Message::new("window-from-step").time("time", time),
                None,
            );
        }
        self.push("saturated_share", w.saturated as f64 / n, &in_w, None);
        self.push("mean_nis", w.nis / n, &in_w, None);
        self.push("mean_nis_low", low, &in_w, None);
        self.push("mean_nis_high", high, &in_w, None);
        self.push("current_peak", w.current_peak, &in_w, None);
        self.push("current_rms", (w.current_sq / n).sqrt(), &in_w, None);
        self.push(
            "current_rated",
            s.i_rated,
            &Message::new("window-rating"),
            None,
        );
        if s.drive.pwm {
            self.push("ripple_peak", w.ripple_peak, &in_w, None);
            self.push("ripple_rms", (w.ripple_sq / n).sqrt(), &in_w, None);
        }
    }

    /// Adds the final errors read at the last row `last`, each with its trend from `judge`.
    fn push_final(&mut self, last: &Row, judge: &TrendJudge) {
        let at_last = Message::new("window-last-sample").time("time", last.t);
        let flux_final = last.flux - last.flux_ref;
        let flux_trend = judge.trend(0, flux_final, FLUX_TREND_TOL);
        let speed_trend = judge.trend(1, last.omega_err, SPEED_TREND_TOL);
        let estimate_trend = judge.trend(2, last.omega_est_err, SPEED_TREND_TOL);
        self.push("flux_error_final", flux_final, &at_last, flux_trend);
        self.push("speed_error_final", last.omega_err, &at_last, speed_trend);
        self.push(
            "speed_estimate_error_final",
            last.omega_est_err,
            &at_last,
            estimate_trend,
        );
    }
}

/// The figure `name`, not reached by the run's end at `end`, placed among `figures` where
/// [`FIGURE_INFO`] orders it.
fn unreached_figure(
    name: &str,
    figures: &[Figure],
    window: Message,
    end: f64,
    text: Message,
) -> Unreached {
    let rank = |name: &str| FIGURE_INFO.iter().position(|f| f.name == name);
    let info = figure_info(name).expect("a figure of the table");
    Unreached {
        name: info.name,
        label: info.label.clone(),
        index: figures
            .iter()
            .position(|f| rank(f.name) > rank(name))
            .unwrap_or(figures.len()),
        window,
        end,
        text,
    }
}

/// What an exponential approach traced by consecutive means `m` still has to go after the last
/// of them (the figure's unit): each change of an approach with time constant τ is the one
/// before times q = e^(−span/τ), so changes d₁ then d₂ with 0 < q = d₂/d₁ < 1 leave
/// d₂·q/(1 − q) to come (Aitken's Δ² extrapolation). None when the changes reverse or do not
/// shrink, or a mean is missing.
fn approach(m: [f64; TREND_TENTHS]) -> Option<f64> {
    let (d1, d2) = (m[1] - m[0], m[2] - m[1]);
    let q = d2 / d1;
    (q > 0.0 && q < 1.0).then(|| (d2 * q / (1.0 - q)).abs())
}

/// The 2 % settling time of the true speed after a step reference, and the step time (s):
/// the last recorded time after the step with |ω − (ω_d before the step + size)| above 2 % of
/// |size|, minus the step time; 0 when ω never leaves the band. None for other references, when
/// the recording stops before the step, or when ω is still outside the band at the last sample
/// (not settled: the settling time is unknown).
#[cfg(test)]
fn settling_time(reference: &Reference, ts: f64, rows: &dyn Samples) -> Option<(f64, f64)> {
    let len = rows.count();
    let last = rows.row(len.checked_sub(1)?);
    let mut settling = Settling::step(reference, ts, |t| rows.first_at(t))
        .filter(|st| last.t >= st.time && !st.outside(&last))?;
    rows.visit(settling.from, len, &mut |i, r| {
        settling.push(i, r);
        true
    });
    Some(settling.result())
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::record::samples::testing::{trace, TS};
    use crate::record::warnings::Z_975;
    use crate::scenario::preset;

    fn value(figures: &[Figure], name: &str) -> Option<f64> {
        figures.iter().find(|f| f.name == name).map(|f| f.value)
    }

    #[test]
    fn every_figure_is_labelled_by_its_name() {
        let all = FIGURE_INFO
            .iter()
            .chain([&crate::record::LOAD_RECOVERY_INFO]);
        for f in all {
            assert_eq!(f.label.id, format!("figure-{}", f.name));
            // A message the English lacks panics here.
            assert!(!f.label.to_string().is_empty(), "{}", f.name);
        }
        assert_eq!(
            crate::record::LOAD_RECOVERY_INFO.name,
            crate::record::LOAD_RECOVERY
        );
        assert_eq!(
            figure_info("tracking_rms").unwrap().label.to_string(),
            "RMS of ω − ω_d"
        );
    }

    #[test]
    fn mean_nis_band_matches_the_normal_limit_and_chi_square_tables() {
        // Large N: N·mean ~ χ²(2N) is nearly normal, mean 2 and sd 2/√N. The skew of χ² shifts
        // both ends by (2/3)(z² − 1)/N, 0.5 % of the half-width at N = 10 000.
        let n = 10_000;
        let (low, high) = mean_nis_band(n);
        let half = Z_975 * 2.0 / (n as f64).sqrt();
        assert!(((2.0 - low) / half - 1.0).abs() < 0.01, "low {low}");
        assert!(((high - 2.0) / half - 1.0).abs() < 0.01, "high {high}");
        // N = 50: χ²(100) has the tabulated 2.5 % and 97.5 % quantiles 74.2219 and 129.5612;
        // Wilson–Hilferty is within 0.01 of them at 100 degrees of freedom.
        let (low, high) = mean_nis_band(50);
        assert!((50.0 * low - 74.2219).abs() < 0.01, "{}", 50.0 * low);
        assert!((50.0 * high - 129.5612).abs() < 0.01, "{}", 50.0 * high);
    }

    #[test]
    fn an_approach_has_what_its_geometric_changes_still_sum_to() {
        // A few roundings of numbers near 4, whose spacing is 8.9e-16.
        const ROUNDING: f64 = 1e-14;
        // Means 3 + q^k: each change half the one before; 3 + q² is q² = 0.25 from the limit.
        let q: f64 = 0.5;
        let to_go = approach([3.0 + 1.0, 3.0 + q, 3.0 + q * q]).unwrap();
        assert!((to_go - q * q).abs() < ROUNDING, "{to_go}");
        // Falling towards the limit from above or rising from below: the same distance.
        let to_go = approach([3.0 - 1.0, 3.0 - q, 3.0 - q * q]).unwrap();
        assert!((to_go - q * q).abs() < ROUNDING, "{to_go}");
        // Changes that reverse, keep their size, grow, or a tenth with no samples: no approach.
        assert_eq!(approach([0.0, 1.0, 0.5]), None);
        assert_eq!(approach([0.0, 1.0, 2.0]), None);
        assert_eq!(approach([0.0, 1.0, 3.0]), None);
        assert_eq!(approach([1.0, 1.0, 1.0]), None);
        assert_eq!(approach([f64::NAN, 1.0, 1.5]), None);
    }

    #[test]
    fn settling_time_is_the_last_exit_from_the_2_percent_band() {
        let step = Reference::Step {
            size: 2.0,
            time: 0.003,
            wn: 1000.0,
        };
        // Band 0.04 about 2: the sample at 7 ms (2.05) is the last one outside.
        let speeds = [0.0, 0.0, 0.0, 0.5, 1.5, 1.97, 2.03, 2.05, 1.99, 2.01, 2.0];
        let rows = trace(speeds.len(), |k, r| r.omega = speeds[k]);
        let (settling, time) = settling_time(&step, TS, &rows).unwrap();
        assert_eq!(time, 0.003);
        assert!((settling - 0.004).abs() < 1e-15, "{settling}");
        // Never outside after the step: 0.
        let rows = trace(6, |k, r| r.omega = if k >= 3 { 2.0 } else { 0.0 });
        assert_eq!(settling_time(&step, TS, &rows), Some((0.0, 0.003)));
        // A negative step: the band is 2 % of |size|.
        let down = Reference::Step {
            size: -2.0,
            time: 0.003,
            wn: 1000.0,
        };
        let rows = trace(speeds.len(), |k, r| r.omega = -speeds[k]);
        assert!((settling_time(&down, TS, &rows).unwrap().0 - 0.004).abs() < 1e-15);
        // Still outside at the end, stopped before the step, or no step at all: no figure.
        let rows = trace(8, |k, r| r.omega = speeds[k]);
        assert_eq!(settling_time(&step, TS, &rows), None);
        let rows = trace(3, |_, _| ());
        assert_eq!(settling_time(&step, TS, &rows), None);
        let constant = Reference::Constant { value: 2.0 };
        let rows = trace(speeds.len(), |k, r| r.omega = speeds[k]);
        assert_eq!(settling_time(&constant, TS, &rows), None);
    }

    #[test]
    fn window_figures_cover_only_the_samples_after_the_transient() {
        let mut s = preset("ramp").unwrap();
        s.ts = TS;
        s.voltage_limit = 100.0;
        // Transient ends at 7 ms: the estimates count as converged with the first full 2 ms
        // window (mean NIS 2, its later level), and the controller's start-up, 5/1200 s, follows,
        // rounded up to a sample. Before it, wild values that must not count; after it,
        // ω − ω_d = ±0.3, one sample in four at the limit, NIS 1 or 3, currents (3, 4).
        let rows = trace(20, |k, r| {
            r.innov_band_a = 0.004;
            r.nis = if k % 2 == 0 { 1.0 } else { 3.0 };
            if k < 7 {
                r.omega_err = 100.0;
                r.u_a_cmd = 1e3;
                r.i_sa = 1e3;
                return;
            }
            r.omega_err = if k % 2 == 0 { 0.3 } else { -0.3 };
            r.u_b_cmd = if k % 4 == 0 { -101.0 } else { 99.0 };
            (r.i_sa, r.i_sb) = (3.0, if k == 7 { -4.0 } else { 0.0 });
            r.omega_est_err = 0.25;
            r.flux = 0.7;
            r.flux_ref = 0.5;
        });
        let f = report(&s, &rows).figures.unwrap();
        let names: Vec<&str> = f.iter().map(|f| f.name).collect();
        assert_eq!(
            names,
            [
                "transient_end",
                "tracking_rms",
                "tracking_peak",
                "saturated_share",
                "mean_nis",
                "mean_nis_low",
                "mean_nis_high",
                "current_peak",
                "current_rms",
                "current_rated",
                "flux_error_final",
                "speed_error_final",
                "speed_estimate_error_final"
            ]
        );
        assert_eq!(value(&f, "transient_end"), Some(rows[7].t));
        assert!((value(&f, "tracking_rms").unwrap() - 0.3).abs() < 1e-15);
        assert_eq!(value(&f, "tracking_peak"), Some(0.3));
        // Samples 7..20: 8, 12 and 16 are beyond the limit, 3 of 13.
        assert_eq!(value(&f, "saturated_share"), Some(3.0 / 13.0));
        // 6 samples (even k) of NIS 1 and 7 (odd k) of NIS 3.
        assert!((value(&f, "mean_nis").unwrap() - 27.0 / 13.0).abs() < 1e-15);
        assert_eq!(value(&f, "mean_nis_low"), Some(mean_nis_band(13).0));
        assert_eq!(value(&f, "current_peak"), Some(5.0));
        // |i_s|² is 9 on 12 samples and 25 on one.
        assert!((value(&f, "current_rms").unwrap() - (133.0f64 / 13.0).sqrt()).abs() < 1e-15);
        assert_eq!(value(&f, "current_rated"), Some(s.i_rated));
        assert!((value(&f, "flux_error_final").unwrap() - 0.2).abs() < 1e-15);
        assert_eq!(value(&f, "speed_error_final"), Some(-0.3));
        assert_eq!(value(&f, "speed_estimate_error_final"), Some(0.25));
        let window = |name| {
            f.iter()
                .find(|f| f.name == name)
                .unwrap()
                .window
                .to_string()
        };
        assert_eq!(window("tracking_rms"), "t ≥ 7 ms");
        assert_eq!(window("speed_error_final"), "last sample, t = 19 ms");
        // A value that is not finite is left out rather than shown as NaN.
        let mut bad = rows.clone();
        bad[10].nis = f64::INFINITY;
        let f = report(&s, &bad).figures.unwrap();
        assert_eq!(value(&f, "mean_nis"), None);
        assert!(value(&f, "mean_nis_high").is_some());
        assert!(f.iter().all(|f| f.value.is_finite()));
        // Nothing recorded: no figures.
        assert!(report(&s, &Vec::new()).figures.is_none());
    }
}
