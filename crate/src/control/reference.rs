//! Speed references with analytic first and second time derivatives.

use super::Points;
use serde::{Deserialize, Serialize};
use std::f64::consts::PI;

/// A speed reference ω_d(t) (rad/s).
// A table's points are kept inline (a few hundred bytes), not boxed: the reference stays `Copy` and
// a run reads its reference every sample without following a pointer.
#[allow(clippy::large_enum_variant)]
#[derive(Clone, Copy, Debug, PartialEq, Serialize, Deserialize)]
#[serde(tag = "kind", rename_all = "lowercase")]
pub enum Reference {
    /// ω_d = value.
    Constant {
        /// Level (rad/s).
        value: f64,
    },
    /// ω_d = offset + amp·sin(2π·freq·t).
    Sine {
        /// Amplitude (rad/s).
        amp: f64,
        /// Frequency (Hz).
        freq: f64,
        /// Constant added to the sine (rad/s).
        offset: f64,
    },
    /// A step of `size` at `time` through the critically damped filter ω_n²/(s + ω_n)².
    Step {
        /// Step size (rad/s).
        size: f64,
        /// Step time (s).
        time: f64,
        /// Filter natural frequency ω_n (rad/s).
        wn: f64,
    },
    /// Trapezoid: 0 until `start`, up at `slope` to `level`, hold for `hold`, down at `slope` to 0.
    Ramp {
        /// Time the ramp starts (s).
        start: f64,
        /// Plateau level (rad/s).
        level: f64,
        /// Magnitude of the up and down slopes (rad/s²).
        slope: f64,
        /// Plateau duration (s).
        hold: f64,
    },
    /// Reversal: 0 until `start`, up at `slope` to `level`, hold for `hold`, then down at `slope`
    /// through zero to −`level`, held to the end.
    Reversal {
        /// Time the run-up starts (s).
        start: f64,
        /// Speed reversed, |ω_d| before and after the reversal (rad/s).
        level: f64,
        /// Magnitude of the slopes (rad/s²).
        slope: f64,
        /// Time at `level` before the reversal (s).
        hold: f64,
    },
    /// Straight between the points of a table (t, ω_d), held before the first and after the last.
    Table {
        /// The points.
        points: Points,
    },
}

/// ω_d(t) and its first two derivatives.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct RefSample {
    /// ω_d (rad/s).
    pub value: f64,
    /// dω_d/dt (rad/s²).
    pub d1: f64,
    /// d²ω_d/dt² (rad/s³).
    pub d2: f64,
}

impl Reference {
    /// The reference's name in the scenario codec.
    pub fn kind(&self) -> &'static str {
        match self {
            Reference::Constant { .. } => "constant",
            Reference::Sine { .. } => "sine",
            Reference::Step { .. } => "step",
            Reference::Ramp { .. } => "ramp",
            Reference::Reversal { .. } => "reversal",
            Reference::Table { .. } => "table",
        }
    }

    /// Samples ω_d and its derivatives at time `t` (s). Corners of the ramp, the reversal and the
    /// table, and the step's start, carry Dirac impulses in their derivatives; those are left out.
    pub fn sample(&self, t: f64) -> RefSample {
        match *self {
            Reference::Constant { value } => RefSample {
                value,
                d1: 0.0,
                d2: 0.0,
            },
            Reference::Sine { amp, freq, offset } => {
                let w = 2.0 * PI * freq;
                let (s, c) = libm::sincos(w * t);
                RefSample {
                    value: offset + amp * s,
                    d1: amp * w * c,
                    d2: -amp * w * w * s,
                }
            }
            Reference::Step { size, time, wn } => {
                if t < time {
                    return RefSample::default();
                }
                // Unit step response of ω_n²/(s+ω_n)²: 1 − e^{−ω_n τ}(1 + ω_n τ).
                let tau = t - time;
                let e = libm::exp(-wn * tau);
                RefSample {
                    value: size * (1.0 - e * (1.0 + wn * tau)),
                    d1: size * wn * wn * tau * e,
                    d2: size * wn * wn * e * (1.0 - wn * tau),
                }
            }
            Reference::Ramp {
                start,
                level,
                slope,
                hold,
            } => trapezoid(t, start, level, slope, hold, 0.0),
            Reference::Reversal {
                start,
                level,
                slope,
                hold,
            } => trapezoid(t, start, level, slope, hold, -level),
            Reference::Table { ref points } => {
                let (value, d1) = points.sample(t);
                RefSample { value, d1, d2: 0.0 }
            }
        }
    }
}

/// 0 until `start`, up at `slope` to `level`, held for `hold`, then at `slope` to `end` (0 or
/// −`level`), held there: the ramp's and the reversal's trapezoid. Its corners' impulses in d2 are
/// left out.
fn trapezoid(t: f64, start: f64, level: f64, slope: f64, hold: f64, end: f64) -> RefSample {
    let rise = level.abs() / slope;
    let dir = level.signum() * slope;
    // The way down is one rise to 0 and, to −level, one more.
    let down = if end == 0.0 { 2.0 } else { 3.0 };
    let (t1, t2, t3) = (
        start + rise,
        start + rise + hold,
        start + down * rise + hold,
    );
    let (value, d1) = if t < start {
        (0.0, 0.0)
    } else if t < t1 {
        (dir * (t - start), dir)
    } else if t < t2 {
        (level, 0.0)
    } else if t < t3 {
        (level - dir * (t - t2), -dir)
    } else {
        (end, 0.0)
    };
    RefSample { value, d1, d2: 0.0 }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Central differences with h = 1e-7 s on these smooth signals: relative error ~1e-6.
    const DERIV_TOL: f64 = 1e-5;

    fn check_derivatives(r: Reference, times: &[f64]) {
        let h = 1e-7;
        for &t in times {
            let (p, m, c) = (r.sample(t + h), r.sample(t - h), r.sample(t));
            let d1 = (p.value - m.value) / (2.0 * h);
            let d2 = (p.d1 - m.d1) / (2.0 * h);
            assert!(
                (d1 - c.d1).abs() <= DERIV_TOL * (1.0 + c.d1.abs()),
                "{r:?} d1 at {t}"
            );
            assert!(
                (d2 - c.d2).abs() <= DERIV_TOL * (1.0 + c.d2.abs()),
                "{r:?} d2 at {t}"
            );
        }
    }

    #[test]
    fn derivatives_are_consistent() {
        check_derivatives(
            Reference::Sine {
                amp: 0.5,
                freq: 200.0,
                offset: 3.0,
            },
            &[0.0, 0.0013, 0.01],
        );
        let step = Reference::Step {
            size: 0.5,
            time: 0.05,
            wn: 2.0 * PI * 200.0,
        };
        check_derivatives(step, &[0.051, 0.0525, 0.06]);
        let ramp = Reference::Ramp {
            start: 0.05,
            level: 100.0,
            slope: 400.0,
            hold: 0.1,
        };
        check_derivatives(ramp, &[0.01, 0.1, 0.35, 0.5, 0.68]);
        let reversal = Reference::Reversal {
            start: 0.05,
            level: 100.0,
            slope: 400.0,
            hold: 0.1,
        };
        check_derivatives(reversal, &[0.01, 0.1, 0.35, 0.5, 0.68, 0.95]);
    }

    #[test]
    fn a_reversal_crosses_zero_at_its_slope_and_holds_the_opposite_speed() {
        let r = Reference::Reversal {
            start: 0.05,
            level: 100.0,
            slope: 400.0,
            hold: 0.1,
        };
        // Up by 0.3 s, held to 0.4 s, through zero at 0.65 s, at −100 rad/s from 0.9 s on.
        assert_eq!(r.sample(0.35).value, 100.0);
        assert!(r.sample(0.65).value.abs() < 1e-9);
        assert_eq!(r.sample(0.65).d1, -400.0);
        assert_eq!(r.sample(0.95).value, -100.0);
        assert_eq!(r.sample(5.0).value, -100.0);
    }

    #[test]
    fn paper_ramp_corners() {
        let ramp = Reference::Ramp {
            start: 0.05,
            level: 100.0,
            slope: 400.0,
            hold: 0.1,
        };
        assert_eq!(ramp.sample(0.3).value, 100.0);
        assert_eq!(ramp.sample(0.4).value, 100.0);
        assert!(ramp.sample(0.65).value.abs() < 1e-9);
        assert_eq!(ramp.sample(0.69).value, 0.0);
        // Filtered step reaches 98 % of its size 5.83/ω_n after the step.
        let wn = 2.0 * PI * 200.0;
        let step = Reference::Step {
            size: 1.0,
            time: 0.0,
            wn,
        };
        assert!((step.sample(5.8335 / wn).value - 0.98).abs() < 1e-4);
    }
}
