//! The window figures' sums and peaks, accumulated in row order, and what a traced run keeps of
//! every row for them as it goes ([`WindowTally`]), so that its figures need no replay of the
//! run: the same sums, in the same order, from the same values, bit for bit.

use super::row::{first_not, is_saturated, Row};
use crate::control::Reference;
use crate::inverter::Limit;
use crate::scenario::Scenario;

/// Settling band of the step response: 2 % of the step size.
pub(super) const SETTLING_BAND: f64 = 0.02;

/// Fraction of the recorded run, at its end, over which a final value's trend is fitted: its
/// last tenth, and the two tenths before it for the means its approach is read from.
pub(super) const TREND_SHARE: f64 = 0.1;

/// Tenths a final value's trend reads: three consecutive means are the fewest that tell an
/// approach (changes shrinking by a constant ratio) from a drift.
pub(super) const TREND_TENTHS: usize = 3;

/// Rows up to which a traced run keeps its window tally (about 50 s at 20 kHz, 40 MiB); a longer
/// run's figures replay its window instead.
const MAX_TALLY_ROWS: usize = 1 << 20;

/// Sums for a least-squares line through (t − t0, y) of several signals at once.
#[derive(Clone, Copy, Debug)]
pub(super) struct LineFit<const N: usize> {
    /// The time the line's t is measured from (s).
    pub(super) t0: f64,
    n: f64,
    st: f64,
    stt: f64,
    sy: [f64; N],
    syy: [f64; N],
    sty: [f64; N],
}

impl<const N: usize> LineFit<N> {
    pub(super) fn new(t0: f64) -> Self {
        LineFit {
            t0,
            n: 0.0,
            st: 0.0,
            stt: 0.0,
            sy: [0.0; N],
            syy: [0.0; N],
            sty: [0.0; N],
        }
    }

    pub(super) fn push(&mut self, t: f64, y: [f64; N]) {
        let dt = t - self.t0;
        self.n += 1.0;
        self.st += dt;
        self.stt += dt * dt;
        for k in 0..N {
            self.sy[k] += y[k];
            self.syy[k] += y[k] * y[k];
            self.sty[k] += dt * y[k];
        }
    }

    /// The slope of signal `k` (per second); None with fewer than two distinct times.
    pub(super) fn slope(&self, k: usize) -> Option<f64> {
        let d = self.n * self.stt - self.st * self.st;
        (self.n >= 2.0 && d > 0.0).then(|| (self.n * self.sty[k] - self.st * self.sy[k]) / d)
    }

    /// The standard deviation of signal `k` about its line (0 with fewer than three samples).
    pub(super) fn scatter(&self, k: usize, slope: f64) -> f64 {
        if self.n < 3.0 {
            return 0.0;
        }
        let syy = self.syy[k] - self.sy[k] * self.sy[k] / self.n;
        let sty = self.sty[k] - self.st * self.sy[k] / self.n;
        ((syy - slope * sty) / (self.n - 2.0)).max(0.0).sqrt()
    }

    /// The mean of signal `k` (NaN with no samples).
    pub(super) fn mean(&self, k: usize) -> f64 {
        self.sy[k] / self.n
    }
}

/// The final values' trend sums: one line fit per tenth of the recorded run over its last
/// [`TREND_TENTHS`] tenths, oldest first; the last is the trend's line, the others give their
/// means.
#[derive(Clone, Copy, Debug)]
pub(super) struct Tenths {
    /// The first row of each tenth.
    pub(super) from: [usize; TREND_TENTHS],
    pub(super) fits: [LineFit<3>; TREND_TENTHS],
}

impl Tenths {
    /// For a run of rows `0..len` at times `time(i)`.
    pub(super) fn new(len: usize, time: impl Fn(usize) -> f64) -> Tenths {
        let from = trend_starts(len, &time);
        Tenths {
            from,
            fits: from.map(|i| LineFit::new(time(i.min(len - 1)))),
        }
    }

    /// The first row the trend reads.
    pub(super) fn first(&self) -> usize {
        self.from[0]
    }

    /// Takes row `i` (rows in order; those before the first tenth are ignored).
    #[inline]
    pub(super) fn push(&mut self, i: usize, r: &Row) {
        if let Some(k) = (0..TREND_TENTHS).rev().find(|&k| i >= self.from[k]) {
            self.fits[k].push(r.t, [r.flux - r.flux_ref, r.omega_err, r.omega_est_err]);
        }
    }

    /// The line through the last tenth.
    pub(super) fn line(&self) -> &LineFit<3> {
        &self.fits[TREND_TENTHS - 1]
    }

    /// The means of signal `k` over the tenths, oldest first (NaN for a tenth with no rows).
    pub(super) fn means(&self, k: usize) -> [f64; TREND_TENTHS] {
        self.fits.map(|f| f.mean(k))
    }
}

/// What the window figures read of one row.
#[derive(Clone, Copy, Debug)]
pub(super) struct Summand {
    omega_err: f64,
    nis: f64,
    /// |i_s|² (A²).
    current_sq: f64,
    ripple: f64,
    reference: f64,
    saturated: bool,
}

impl Summand {
    /// Of `r`, under the inverter's `limit`.
    #[inline]
    pub(super) fn of(r: &Row, limit: &Limit) -> Summand {
        Summand {
            omega_err: r.omega_err,
            nis: r.nis,
            current_sq: r.i_sa * r.i_sa + r.i_sb * r.i_sb,
            ripple: r.i_ripple,
            reference: r.omega_ref,
            saturated: is_saturated(r, limit),
        }
    }
}

/// Sums and peaks of the window figures, accumulated in row order (sums start at −0, as
/// `Iterator::sum` does, so that they equal it bit for bit).
pub(super) struct Window {
    pub(super) n: usize,
    pub(super) tracking_sq: f64,
    pub(super) tracking_peak: f64,
    pub(super) saturated: usize,
    pub(super) nis: f64,
    pub(super) current_peak: f64,
    pub(super) current_sq: f64,
    pub(super) ripple_peak: f64,
    pub(super) ripple_sq: f64,
    pub(super) reference_peak: f64,
    /// The first row (counted in the window) of the last stretch of rows where ω did not follow
    /// ω_d ([`following`]), when the window ends in one.
    pub(super) astray_from: Option<usize>,
}

/// Share of |ω_d| that ω may differ from it by and still be following it ...
pub(super) const FOLLOW_SHARE: f64 = 0.05;

/// ... plus this margin (rad/s), so that a reference near zero is not held to noise.
pub(super) const FOLLOW_MARGIN: f64 = 1.0;

/// Whether a speed error `omega_err` follows the reference `reference`: within
/// [`FOLLOW_SHARE`]·|ω_d| + [`FOLLOW_MARGIN`].
#[inline]
pub(super) fn following(omega_err: f64, reference: f64) -> bool {
    omega_err.abs() <= FOLLOW_SHARE * reference.abs() + FOLLOW_MARGIN
}

impl Window {
    pub(super) fn new() -> Window {
        Window {
            n: 0,
            tracking_sq: -0.0,
            tracking_peak: f64::NEG_INFINITY,
            saturated: 0,
            nis: -0.0,
            current_peak: f64::NEG_INFINITY,
            current_sq: -0.0,
            ripple_peak: f64::NEG_INFINITY,
            ripple_sq: -0.0,
            reference_peak: 0.0,
            astray_from: None,
        }
    }

    /// Takes the next row of the window.
    #[inline]
    pub(super) fn push(&mut self, x: &Summand) {
        self.n += 1;
        self.tracking_sq += x.omega_err * x.omega_err;
        self.tracking_peak = self.tracking_peak.max(x.omega_err.abs());
        self.saturated += usize::from(x.saturated);
        self.nis += x.nis;
        self.current_peak = self.current_peak.max(x.current_sq.sqrt());
        self.current_sq += x.current_sq;
        self.ripple_peak = self.ripple_peak.max(x.ripple);
        self.reference_peak = self.reference_peak.max(x.reference.abs());
        self.ripple_sq += x.ripple * x.ripple;
        if following(x.omega_err, x.reference) {
            self.astray_from = None;
        } else if self.astray_from.is_none() {
            self.astray_from = Some(self.n - 1);
        }
    }
}

/// The settling of ω after the step of a step reference: its first row, target and 2 % band,
/// and the last time ω was outside the band, from the step on.
#[derive(Clone, Debug)]
pub(super) struct Settling {
    /// Step time (s) and its first row.
    pub(super) time: f64,
    pub(super) from: usize,
    target: f64,
    band: f64,
    /// The last time ω was outside the band, from the step on.
    pub(super) last_out: Option<f64>,
}

impl Settling {
    /// For a step reference sampled every `ts`, whose step time is first reached at row `from`.
    pub(super) fn step(
        reference: &Reference,
        ts: f64,
        from: impl FnOnce(f64) -> usize,
    ) -> Option<Settling> {
        let Reference::Step { size, time, .. } = *reference else {
            return None;
        };
        Some(Settling {
            time,
            from: from(time),
            target: reference.sample(time - ts).value + size,
            band: SETTLING_BAND * size.abs(),
            last_out: None,
        })
    }

    pub(super) fn outside(&self, r: &Row) -> bool {
        (r.omega - self.target).abs() > self.band
    }

    /// Takes row `i` (rows in order; those before the step are ignored).
    #[inline]
    pub(super) fn push(&mut self, i: usize, r: &Row) {
        if i >= self.from && self.outside(r) {
            self.last_out = Some(r.t);
        }
    }

    /// The settling time after the step and the step time (s).
    pub(super) fn result(&self) -> (f64, f64) {
        (self.last_out.map_or(0.0, |t| t - self.time), self.time)
    }
}

/// The first rows of the tenths the final values' trend reads in a run of rows `0..len` at times
/// `time(i)`: the last [`TREND_TENTHS`] tenths of the recorded run, oldest first.
fn trend_starts(len: usize, time: impl Fn(usize) -> f64) -> [usize; TREND_TENTHS] {
    let (first, last) = (time(0), time(len - 1));
    std::array::from_fn(|k| {
        let cut = last - (TREND_TENTHS - k) as f64 * TREND_SHARE * (last - first);
        first_not(len, |i| time(i) < cut)
    })
}

/// What the window figures read of every row of a traced run, kept as its rows come (row k at
/// time k·Ts), with the trend of the final values and the step's settling tallied over the rows
/// they will cover if the run reaches its last sample. A run that ends early, or one longer
/// than the rows a tally keeps, has its window replayed instead.
#[derive(Clone, Debug)]
pub struct WindowTally {
    limit: Limit,
    steps: usize,
    summands: Vec<Summand>,
    /// The trend's sums over the tenths as planned.
    trend: Tenths,
    settling: Option<Settling>,
}

impl WindowTally {
    /// For a traced run of `scenario` of `steps` samples; None when it is longer than a tally
    /// keeps.
    pub fn new(scenario: &Scenario, steps: usize) -> Option<WindowTally> {
        if steps == 0 || steps > MAX_TALLY_ROWS {
            return None;
        }
        let ts = scenario.ts;
        let time = |k: usize| k as f64 * ts;
        Some(WindowTally {
            limit: scenario.limit(),
            steps,
            summands: Vec::with_capacity(steps),
            trend: Tenths::new(steps, time),
            settling: Settling::step(&scenario.reference, ts, |t| {
                first_not(steps, |k| time(k) < t)
            }),
        })
    }

    /// Takes row `i`, the rows coming in order from 0.
    #[inline]
    pub fn push(&mut self, i: usize, r: &Row) {
        // Within the capacity reserved for the whole run: no allocation.
        self.summands.push(Summand::of(r, &self.limit));
        self.trend.push(i, r);
        if let Some(s) = &mut self.settling {
            s.push(i, r);
        }
    }

    /// The window sums over rows `start..len`, the trend and the step's last time outside its
    /// band, when the tally covers them: the run reached its last sample (`len` rows) and the
    /// trend lies inside the window.
    pub(super) fn window(&self, start: usize, len: usize) -> Option<(Window, Tenths, Option<f64>)> {
        if len != self.steps || self.summands.len() != len || self.trend.first() < start {
            return None;
        }
        let mut w = Window::new();
        for x in &self.summands[start..] {
            w.push(x);
        }
        Some((
            w,
            self.trend,
            self.settling.as_ref().and_then(|s| s.last_out),
        ))
    }

    /// Bytes it holds.
    pub fn bytes(&self) -> usize {
        self.summands.capacity() * std::mem::size_of::<Summand>()
    }
}
