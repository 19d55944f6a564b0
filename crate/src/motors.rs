//! The motors `motor=` chooses for the plant and the model together: the paper's, and three
//! others of different sizes by their published equivalent-circuit values, each with its source
//! (docs/model-and-paper.md lists them). A motor whose source gives no rated current gets one
//! estimated from its equivalent circuit, and says so.

use crate::params::MotorParams;
use std::f64::consts::PI;

/// How a motor's rated current is known.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Rating {
    /// The amplitude |i_s| of the rated phase current that the scenarios give the motor (A).
    Given(f64),
    /// The rated phase current its source publishes (A rms).
    Published(f64),
    /// None published: estimated from the equivalent circuit (see [`Motor::rated_current`]).
    Estimated,
}

/// A motor of the library.
#[derive(Clone, Copy, Debug)]
pub struct Motor {
    /// Its name in `motor=`.
    pub name: &'static str,
    /// Its T-equivalent circuit and inertia (SI). The load (T_0, C_f) is the scenario's, not the
    /// motor's, and is not taken from here.
    pub params: MotorParams,
    /// Rated mechanical power (W).
    pub power: f64,
    /// Rated line-to-line voltage (V rms).
    pub voltage: f64,
    /// Rated frequency (Hz).
    pub frequency: f64,
    /// How its rated current is known.
    pub rating: Rating,
}

/// The equivalent circuit and inertia of a library motor, with no load of its own.
const fn circuit(rs: f64, rr: f64, m: f64, ls: f64, lr: f64, j: f64) -> MotorParams {
    MotorParams {
        rs,
        rr,
        m,
        ls,
        lr,
        j,
        np: 2.0,
        t0: 0.0,
        cf: 0.0,
    }
}

/// The library, the paper's motor first (the presets' own).
pub const MOTORS: &[Motor] = &[
    Motor {
        name: "paper",
        params: MotorParams::PAPER,
        power: f64::NAN,
        voltage: crate::scenario::RATED_V,
        frequency: crate::scenario::RATED_F,
        rating: Rating::Given(crate::scenario::I_RATED),
    },
    // Inverse-Γ values R_s 3.7 Ω, R_R 2.1 Ω, L_σ 0.021 H, L_M 0.224 H: in the T form, the rotor
    // leakage is zero (L_r = M = L_M, L_s = L_σ + L_M).
    Motor {
        name: "2.2kw",
        params: circuit(3.7, 2.1, 0.224, 0.245, 0.224, 0.015),
        power: 2200.0,
        voltage: 400.0,
        frequency: 50.0,
        rating: Rating::Published(5.0),
    },
    Motor {
        name: "3.7kw",
        params: circuit(1.405, 1.395, 0.1722, 0.178039, 0.178039, 0.0131),
        power: 3730.0,
        voltage: 400.0,
        frequency: 50.0,
        rating: Rating::Estimated,
    },
    Motor {
        name: "15kw",
        params: circuit(0.2147, 0.2205, 0.06419, 0.065181, 0.065181, 0.102),
        power: 14920.0,
        voltage: 400.0,
        frequency: 50.0,
        rating: Rating::Estimated,
    },
];

/// The library's names, in its order (`motor=`'s options).
pub const MOTOR_NAMES: &[&str] = &["paper", "2.2kw", "3.7kw", "15kw"];

/// The library motor `name`.
pub fn motor(name: &str) -> Option<&'static Motor> {
    MOTORS.iter().find(|m| m.name == name)
}

impl Motor {
    /// Where its values come from (for the CLI and the files the tools write: the run's module
    /// carries no English).
    #[cfg(feature = "english")]
    pub fn source(&self) -> &'static str {
        match self.name {
            "paper" => {
                "the paper's Section 5, from Khalil et al. (2009); the presets' rating, and 400 V, \
                 50 Hz assumed (the paper gives no nameplate)"
            }
            "2.2kw" => {
                "motulator (Aalto University), its 2.2-kW induction machine examples: 400 V, \
                 5 A, 50 Hz, 2.2 kW, inverse-Γ parameters and J"
            }
            "3.7kw" => {
                "MATLAB's preset IM5HP400V50Hz (5 hp, 400 V, 50 Hz, 4 poles), as the Modelica \
                 Buildings library's record IM_5HP_400V_50Hz gives it"
            }
            "15kw" => {
                "MATLAB's preset IM20HP400V50Hz (20 hp, 400 V, 50 Hz, 4 poles), as the Modelica \
                 Buildings library's record IM_20HP_400V_50Hz gives it"
            }
            _ => unreachable!("every motor of the library has its source"),
        }
    }

    /// The amplitude |i_s| of its rated phase current (A), and whether it is an estimate. With
    /// none published: the stator current of its steady-state T-equivalent circuit at its rated
    /// voltage and frequency, at the slip where its mechanical power 3·|I_r|²·R_r·(1 − s)/s is
    /// its rated power (on the stable side of the peak), losses in iron and friction left out.
    pub fn rated_current(&self) -> (f64, bool) {
        match self.rating {
            Rating::Given(amplitude) => (amplitude, false),
            Rating::Published(rms) => (rms * 2f64.sqrt(), false),
            Rating::Estimated => (self.steady_state_current() * 2f64.sqrt(), true),
        }
    }

    /// The rms stator current at rated voltage, frequency and power (see [`rated_current`]).
    ///
    /// [`rated_current`]: Motor::rated_current
    fn steady_state_current(&self) -> f64 {
        let p = &self.params;
        let w = 2.0 * PI * self.frequency;
        let v = self.voltage / 3f64.sqrt();
        // Complex numbers as (re, im).
        let mul = |a: (f64, f64), b: (f64, f64)| (a.0 * b.0 - a.1 * b.1, a.0 * b.1 + a.1 * b.0);
        let div = |a: (f64, f64), b: (f64, f64)| {
            let d = b.0 * b.0 + b.1 * b.1;
            ((a.0 * b.0 + a.1 * b.1) / d, (a.1 * b.0 - a.0 * b.1) / d)
        };
        let add = |a: (f64, f64), b: (f64, f64)| (a.0 + b.0, a.1 + b.1);
        let abs = |a: (f64, f64)| (a.0 * a.0 + a.1 * a.1).sqrt();
        // Stator current and mechanical power at slip s.
        let at = |s: f64| {
            let zs = (p.rs, w * (p.ls - p.m));
            let zm = (0.0, w * p.m);
            let zr = (p.rr / s, w * (p.lr - p.m));
            let parallel = div(mul(zm, zr), add(zm, zr));
            let i = div((v, 0.0), add(zs, parallel));
            let ir = abs(div(mul(i, zm), add(zm, zr)));
            (abs(i), 3.0 * ir * ir * p.rr * (1.0 - s) / s)
        };
        // The slip of peak power on a logarithmic grid from 1e-6 to 1 (each point 1.2 % above the
        // one before), then bisection below it.
        let mut peak = (0.0, 1e-6);
        let mut s = 1e-6;
        while s < 1.0 {
            let power = at(s).1;
            if power > peak.0 {
                peak = (power, s);
            }
            s *= 1.012;
        }
        let (mut lo, mut hi) = (1e-9, peak.1);
        for _ in 0..200 {
            let mid = 0.5 * (lo + hi);
            if at(mid).1 < self.power {
                lo = mid;
            } else {
                hi = mid;
            }
        }
        at(hi).0
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_estimate_is_close_to_the_rating_published_for_the_motor_that_has_one() {
        // The 2.2 kW motor publishes 5 A rms: its circuit's estimate, without iron and friction
        // losses, is within 5 % of it.
        let m = motor("2.2kw").unwrap();
        let estimate = m.steady_state_current();
        assert!((estimate / 5.0 - 1.0).abs() < 0.05, "{estimate}");
        for m in MOTORS {
            let (amplitude, estimated) = m.rated_current();
            assert!(amplitude.is_finite() && amplitude > 0.0, "{}", m.name);
            assert_eq!(estimated, m.rating == Rating::Estimated, "{}", m.name);
            assert!(m.params.lumped().is_ok(), "{}", m.name);
            assert!(!m.source().is_empty(), "{}", m.name);
        }
    }

    #[test]
    fn the_options_name_the_library() {
        let names: Vec<&str> = MOTORS.iter().map(|m| m.name).collect();
        assert_eq!(names, MOTOR_NAMES);
    }

    #[test]
    fn larger_motors_draw_more_current() {
        let amps: Vec<f64> = ["2.2kw", "3.7kw", "15kw"]
            .map(|n| motor(n).unwrap().rated_current().0)
            .to_vec();
        assert!(amps.windows(2).all(|w| w[0] < w[1]), "{amps:?}");
    }
}
