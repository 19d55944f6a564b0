//! The presets: the paper's figures and the scenarios the lessons use, each a [`Scenario`].

use super::{ControllerKind, DesignKind, Drive, LoadStep, Scenario, Start};
use crate::control::{Gains, IfocTuning, Points, Reference};
use crate::inverter::Shape;
use crate::observer::{EkfConfig, Predictor};
use crate::params::MotorParams;
use crate::text::Message;
use std::f64::consts::PI;

/// A named scenario with a one-line description.
pub struct Preset {
    /// Name used in `preset=`.
    pub name: &'static str,
    /// One line saying what it shows (`preset-NAME` of `core-run.ftl`).
    pub description: Message,
}

/// The preset `name`, described by its message `preset-NAME`.
macro_rules! described {
    ($name:literal) => {
        Preset {
            name: $name,
            description: Message::new(concat!("preset-", $name)),
        }
    };
}

/// All presets, in display order.
pub const PRESETS: &[Preset] = &[
    described!("sine200"),
    described!("step"),
    described!("ramp"),
    described!("sine200-1rad"),
    described!("sine200-rk4"),
    described!("rr-mismatch"),
    described!("load-step"),
    described!("decay"),
    described!("ifoc-step"),
    described!("load-step-est"),
    described!("rr-mismatch-est"),
    described!("sine200-drive"),
    described!("high-gain"),
];

// Tuning of the added EKF states (Section 3.1's remedies), justified in docs/model-and-paper.md.
/// Random-walk intensity of the load torque ((N m)²/s): on `load-step-est` the speed stays within
/// 0.2 rad/s of 50 rad/s through the 2 N m step, and the estimate's 2σ band is ±0.35 N m.
const LOAD_Q: f64 = 10.0;
/// Initial standard deviation of the load torque (N m): of the order of the rated load.
const LOAD_STD: f64 = 2.0;
/// Random-walk intensity of the rotor resistance (Ω²/s): R_r drifts with temperature over
/// minutes; 0.1 Ω²/s lets the estimate move 0.3 Ω in a second and keeps its band at ±0.17 Ω.
const RR_Q: f64 = 0.1;
/// Initial standard deviation of the rotor resistance (Ω): 10 % of the paper's 4.95 Ω.
const RR_STD: f64 = 0.5;

/// Rated current of the paper's motor, as the amplitude |i_s| of its rated phase current (A);
/// the paper gives no rating. At ψ_d = 0.5 Wb² the magnetising current is |φ_r|/M = 1.35 A, and
/// the torque per q-current is (3/2)·n_p·(M/L_r)·|φ_r| = 2.06 N m/A. A 4-pole motor of these
/// parameters is of the 1.1–1.5 kW class, whose rated torque at about
/// 1430 rpm is 7.3–10 N m: i_q = 3.6–4.9 A and |i_s| = 3.8–5.1 A. 4 A (2.8 A rms per phase)
/// gives 7.7 N m; at the model's slip for that current (25.5 rad/s electrical, 8.1 % at 50 Hz,
/// 1378 rpm) that is 1.12 kW, at the low end of that class.
pub const I_RATED: f64 = 4.0;
/// Rated voltage (V rms, line to line) and frequency (Hz) the derived design reads for the
/// paper's motor, which has no nameplate: the 400 V of its voltage limit, at 50 Hz, the class
/// its rating above is drawn from.
pub const RATED_V: f64 = 400.0;
/// See [`RATED_V`].
pub const RATED_F: f64 = 50.0;
/// Base speed the field-weakening setting shows while it is off (rad/s): the paper's motor's
/// synchronous speed at 50 Hz.
pub const FW_BASE: f64 = 50.0 * std::f64::consts::PI;

fn paper_base(name: &str, reference: Reference, duration: f64) -> Scenario {
    Scenario {
        preset: name.to_string(),
        motor: "paper".to_string(),
        reference,
        psi_d: 0.5,
        plant: MotorParams::PAPER,
        model: MotorParams::PAPER,
        controller: ControllerKind::Backstepping,
        ifoc: IfocTuning {
            current_bw: 1000.0,
            speed_bw: 10.0,
            mras_bw: 50.0,
            current_limit: 20.0,
            ff: false,
        },
        gains: Gains {
            k1: 1200.0,
            k2: 1200.0,
            k3: 1200.0,
            k4: 1200.0,
            robust: false,
            eps2: 1.0,
            h2: 0.0,
            eps4: 1.0,
            h4: 0.0,
        },
        ekf: EkfConfig {
            predictor: Predictor::Euler,
            q: 0.001,
            q_speed: 0.0,
            r_std: 0.002,
            load: false,
            q_load: LOAD_Q,
            load_std: LOAD_STD,
            rr: false,
            q_rr: RR_Q,
            rr_std: RR_STD,
        },
        init_error: 0.1,
        noise: 0.002,
        seed: 1,
        voltage_limit: 400.0,
        duration,
        ts: 50e-6,
        substeps: 1,
        load_step: LoadStep {
            time: 0.0,
            torque: 0.0,
            table: Points::EMPTY,
        },
        perfect: false,
        drive: Drive {
            delay: false,
            delay_comp: false,
            vlimit: Shape::Box,
            vdc: 540.0,
            pwm: false,
        },
        i_rated: I_RATED,
        rated_v: RATED_V,
        rated_f: RATED_F,
        design: DesignKind::Paper,
        fw: false,
        fw_base: FW_BASE,
        start: Start::Paper,
        law: Default::default(),
    }
}

const SINE200: Reference = Reference::Sine {
    amp: 0.5,
    freq: 200.0,
    offset: 0.0,
};
const STEP: Reference = Reference::Step {
    size: 0.5,
    time: 0.05,
    wn: 2.0 * PI * 200.0,
};

/// The preset called `name`, if there is one.
pub fn preset(name: &str) -> Option<Scenario> {
    let s = match name {
        "sine200" => paper_base(name, SINE200, 0.25),
        "step" => paper_base(name, STEP, 0.10),
        "ramp" => paper_base(
            name,
            Reference::Ramp {
                start: 0.05,
                level: 100.0,
                slope: 400.0,
                hold: 0.10,
            },
            0.70,
        ),
        "sine200-1rad" => paper_base(
            name,
            Reference::Sine {
                amp: 1.0,
                freq: 200.0,
                offset: 0.0,
            },
            0.25,
        ),
        "sine200-rk4" => {
            let mut s = paper_base(name, SINE200, 0.25);
            s.ekf.predictor = Predictor::Rk4;
            s
        }
        "rr-mismatch" => {
            let mut s = paper_base(name, Reference::Constant { value: 50.0 }, 0.30);
            s.plant.rr *= 1.1;
            s
        }
        "load-step" => {
            let mut s = paper_base(name, Reference::Constant { value: 50.0 }, 0.30);
            s.load_step = LoadStep {
                time: 0.15,
                torque: 2.0,
                table: Points::EMPTY,
            };
            s
        }
        "decay" => {
            let mut s = paper_base(name, Reference::Constant { value: 0.0 }, 0.02);
            s.perfect = true;
            s.noise = 0.0;
            s
        }
        "ifoc-step" => {
            let mut s = paper_base(
                name,
                Reference::Step {
                    size: 40.0,
                    time: 0.05,
                    wn: 2.0 * PI * 200.0,
                },
                0.6,
            );
            s.controller = ControllerKind::Ifoc;
            s
        }
        // The remedies of Section 3.1. The RK4 predictor: with the paper's Euler one and its Q the
        // added states take up its prediction error (at 0.3 s the load state leaves the speed
        // 2.9 rad/s low, and R̂_r is 4.7 % low). Q = 1e-5·Ts·I: the simulated motor has no process
        // noise, and the paper's 1e-3 makes the filter conservative.
        "load-step-est" | "rr-mismatch-est" => {
            let mut s = preset(name.trim_end_matches("-est"))?;
            s.preset = name.to_string();
            s.ekf.predictor = Predictor::Rk4;
            s.ekf.q = 1e-5;
            s.ekf.load = name == "load-step-est";
            s.ekf.rr = name == "rr-mismatch-est";
            s
        }
        // The real-drive question: what a 400 V-class drive adds (540 V DC link, an update of the
        // PWM once per period); `delay.comp=1` adds the compensation.
        "sine200-drive" => {
            let mut s = paper_base(name, SINE200, 0.25);
            s.drive = Drive {
                delay: true,
                delay_comp: false,
                vlimit: Shape::Hex,
                vdc: 540.0,
                pwm: true,
            };
            s
        }
        "high-gain" => {
            let mut s = paper_base(name, STEP, 0.10);
            s.gains.k1 = 3000.0;
            s.gains.k2 = 3000.0;
            s.gains.k3 = 3000.0;
            s.gains.k4 = 3000.0;
            s
        }
        _ => return None,
    };
    Some(s)
}

/// Default parameters of each reference kind, used when `ref=` switches kind.
pub(super) fn default_reference(kind: &str) -> Option<Reference> {
    Some(match kind {
        "constant" => Reference::Constant { value: 0.0 },
        "sine" => SINE200,
        "step" => STEP,
        "ramp" => Reference::Ramp {
            start: 0.05,
            level: 100.0,
            slope: 400.0,
            hold: 0.10,
        },
        "reversal" => Reference::Reversal {
            start: 0.05,
            level: 100.0,
            slope: 400.0,
            hold: 0.10,
        },
        // The ramp's trapezoid as a table, to edit from.
        "table" => Reference::Table {
            points: Points::new(&[(0.05, 0.0), (0.3, 100.0), (0.4, 100.0), (0.65, 0.0)])
                .expect("rising times"),
        },
        _ => return None,
    })
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn every_preset_says_what_it_shows() {
        for p in PRESETS {
            assert!(preset(p.name).is_some(), "{}", p.name);
            assert_eq!(p.description.id, format!("preset-{}", p.name));
            // A message the English lacks panics here.
            assert!(!p.description.to_string().is_empty(), "{}", p.name);
        }
        assert_eq!(
            PRESETS[1].description.to_string(),
            "Paper Fig 3: 0 → 0.5 rad/s step at 50 ms through a 200 Hz critically damped filter"
        );
    }
}
