//! A motor's equivalent circuit from its nameplate and the two standard tests a lab runs: the
//! no-load test and the locked-rotor test of IEEE Std 112, with the DC measurement of the stator
//! resistance. The locked-rotor reactance is split between stator and rotor by the motor's NEMA
//! design letter, as IEEE Std 112 tabulates it (docs/model-and-paper.md names the method). The
//! rotor branch is left out of the no-load circuit (the rotor turns at synchronous speed), and
//! the locked-rotor circuit is solved with its magnetising branch; iron and friction losses are
//! not in IM Lab's model, so the no-load power serves only to take the resistive part out of the
//! no-load impedance.

mod entry;

pub use entry::{identify, Entry, EntryError, Identified};

use crate::params::MotorParams;
use crate::text::Message;
use nalgebra::Complex;
use std::f64::consts::PI;

/// One steady reading of a test.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Reading {
    /// Line-to-line voltage (V rms).
    pub voltage: f64,
    /// Line current (A rms).
    pub current: f64,
    /// Input power of the three phases (W).
    pub power: f64,
    /// Supply frequency (Hz).
    pub frequency: f64,
}

/// The NEMA design letter of the rotor, which sets how the locked-rotor leakage reactance splits
/// between stator and rotor.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Nema {
    /// Design A (and a wound rotor): half each.
    A,
    /// Design B: 40 % stator, 60 % rotor.
    B,
    /// Design C: 30 % stator, 70 % rotor.
    C,
    /// Design D: half each.
    D,
}

impl Nema {
    /// The stator's share of the locked-rotor leakage reactance.
    pub fn stator_share(self) -> f64 {
        match self {
            Nema::A | Nema::D => 0.5,
            Nema::B => 0.4,
            Nema::C => 0.3,
        }
    }
}

/// What the lab measured.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Tests {
    /// Stator resistance per phase from the DC test (Ω), the phase's share of the line-to-line
    /// resistance of a star connection.
    pub rs: f64,
    /// The no-load test at rated voltage and frequency.
    pub no_load: Reading,
    /// The locked-rotor test, at reduced voltage, at rated or reduced frequency.
    pub locked: Reading,
    /// The rotor's NEMA design letter.
    pub nema: Nema,
    /// Rated frequency (Hz), at which the reactances are taken.
    pub frequency: f64,
}

/// Why the tests give no circuit.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum IdentifyError {
    /// A reading that must be positive is not (its name).
    NotPositive(&'static str),
    /// The test's power is more than its voltage and current can carry: R > |Z| (its name).
    PowerTooHigh(&'static str),
    /// The locked-rotor resistance is no more than the stator's: no rotor resistance is left.
    NoRotorResistance {
        /// Locked-rotor resistance per phase (Ω).
        locked: f64,
        /// DC stator resistance (Ω).
        rs: f64,
    },
    /// The no-load reactance is no more than the stator's leakage: no magnetising reactance is left.
    NoMagnetising,
}

impl IdentifyError {
    /// What it says, as a message of `core-analysis.ftl`.
    pub fn message(&self) -> Message {
        match *self {
            IdentifyError::NotPositive(what) => {
                Message::new("identify-not-positive").text("what", what)
            }
            IdentifyError::PowerTooHigh(test) => {
                Message::new("identify-power-too-high").text("test", test)
            }
            IdentifyError::NoRotorResistance { locked, rs } => {
                Message::new("identify-no-rotor-resistance")
                    .short("locked", locked)
                    .short("rs", rs)
            }
            IdentifyError::NoMagnetising => Message::new("identify-no-magnetising"),
        }
    }
}

impl std::fmt::Display for IdentifyError {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        self.message().fmt(f)
    }
}

impl std::error::Error for IdentifyError {}

/// Per-phase resistance and reactance of a star-connected reading (Ω), the reactance taken to
/// frequency `to` (Hz).
fn per_phase(r: &Reading, name: &'static str, to: f64) -> Result<(f64, f64), IdentifyError> {
    for (what, v) in [
        ("voltage", r.voltage),
        ("current", r.current),
        ("frequency", r.frequency),
    ] {
        if !(v.is_finite() && v > 0.0) {
            return Err(IdentifyError::NotPositive(what));
        }
    }
    if !(r.power.is_finite() && r.power >= 0.0) {
        return Err(IdentifyError::NotPositive("power"));
    }
    let z = r.voltage / 3f64.sqrt() / r.current;
    let resistance = r.power / (3.0 * r.current * r.current);
    if resistance > z {
        return Err(IdentifyError::PowerTooHigh(name));
    }
    Ok((
        resistance,
        (z * z - resistance * resistance).sqrt() * to / r.frequency,
    ))
}

/// The T-equivalent circuit the tests give, with inertia `j` and `np` pole pairs (which no test
/// here measures), and no load of its own.
pub fn circuit(t: &Tests, j: f64, np: f64) -> Result<MotorParams, IdentifyError> {
    if !(t.rs.is_finite() && t.rs > 0.0) {
        return Err(IdentifyError::NotPositive("rs"));
    }
    let w = 2.0 * PI * t.frequency;
    // Both tests' reactances at the locked-rotor test's frequency, where its circuit is solved.
    let f_locked = t.locked.frequency;
    let (r_locked, x_locked) = per_phase(&t.locked, "locked", f_locked)?;
    let (_, x_no_load) = per_phase(&t.no_load, "no-load", f_locked)?;
    // The locked rotor's impedance is rs + j·x1 + (j·xm ∥ (R2 + j·x2)), with x2 = x1·(1 − k)/k
    // and xm = x_no_load − x1 (the no-load circuit, the rotor branch open). For a guess of x1,
    // the rotor branch is 1/(1/(Z − rs − j·x1) − 1/(j·xm)); its reactance gives the next x1. The
    // circuit is solved exactly, where the textbook form of the method takes R2 small against
    // x2 + xm, which at a quarter of the rated frequency is off by per cents.
    if r_locked <= t.rs {
        return Err(IdentifyError::NoRotorResistance {
            locked: r_locked,
            rs: t.rs,
        });
    }
    let k = t.nema.stator_share();
    let z = Complex::new(r_locked, x_locked);
    let branch = |x1: f64| -> Result<Complex<f64>, IdentifyError> {
        let xm = x_no_load - x1;
        if xm <= 0.0 {
            return Err(IdentifyError::NoMagnetising);
        }
        let rest = z - Complex::new(t.rs, x1);
        Ok((rest.inv() - Complex::new(0.0, xm).inv()).inv())
    };
    // x1 where the rotor branch's reactance is x1·(1 − k)/k: bisection between no stator
    // leakage and all of the locked rotor's reactance.
    let gap = |x1: f64| branch(x1).map(|b| b.im - x1 * (1.0 - k) / k);
    let (mut lo, mut hi) = (0.0, x_locked.min(x_no_load) * (1.0 - 1e-12));
    if gap(lo)? * gap(hi)? > 0.0 {
        return Err(IdentifyError::NoMagnetising);
    }
    for _ in 0..200 {
        let mid = 0.5 * (lo + hi);
        if gap(mid)? * gap(lo)? > 0.0 {
            lo = mid;
        } else {
            hi = mid;
        }
    }
    let x1 = 0.5 * (lo + hi);
    let rotor = branch(x1)?;
    let (rr, x2, xm) = (rotor.re, rotor.im, x_no_load - x1);
    if rr.is_nan() || rr <= 0.0 {
        return Err(IdentifyError::NoRotorResistance {
            locked: r_locked,
            rs: t.rs,
        });
    }
    // Back to the rated frequency.
    let to_rated = t.frequency / f_locked;
    let (x1, x2, xm) = (x1 * to_rated, x2 * to_rated, xm * to_rated);
    Ok(MotorParams {
        rs: t.rs,
        rr,
        m: xm / w,
        ls: (xm + x1) / w,
        lr: (xm + x2) / w,
        j,
        np,
        t0: 0.0,
        cf: 0.0,
    })
}

/// A 2.2 kW, 4-pole, 400 V, 50 Hz, 5 A machine of a drives researcher (values of that class, not
/// a catalogue's): the motor the method and the derived design are checked on, read in a simulated
/// lab by [`readings`].
pub const MACHINE: MotorParams = MotorParams {
    rs: 3.7,
    rr: 2.5,
    m: 0.235,
    ls: 0.246,
    lr: 0.246,
    j: 0.015,
    np: 2.0,
    t0: 0.0,
    cf: 0.0,
};

/// [`MACHINE`]'s rating: line voltage (V rms), frequency (Hz) and current (A rms).
pub const MACHINE_RATING: (f64, f64, f64) = (400.0, 50.0, 5.0);

/// The readings the two tests give on motor `p` (its steady-state T circuit, with no iron or
/// friction loss): at no load, at voltage `v0` (V rms, line to line) and frequency `f0`, the rotor
/// turning at synchronous speed; locked, at `v_locked` and `f_locked`. A simulated lab: what the
/// method is checked against.
pub fn readings(
    p: &MotorParams,
    (v0, f0): (f64, f64),
    (v_locked, f_locked): (f64, f64),
) -> (Reading, Reading) {
    let read = |v: f64, f: f64, locked: bool| {
        let w = 2.0 * PI * f;
        let j = Complex::new(0.0, 1.0);
        let stator = Complex::new(p.rs, 0.0) + j * w * (p.ls - p.m);
        let magnetising = j * w * p.m;
        let z = if locked {
            let rotor = Complex::new(p.rr, 0.0) + j * w * (p.lr - p.m);
            stator + magnetising * rotor / (magnetising + rotor)
        } else {
            stator + magnetising
        };
        let current = v / 3f64.sqrt() / z.norm();
        Reading {
            voltage: v,
            current,
            power: 3.0 * current * current * z.re,
            frequency: f,
        }
    };
    (read(v0, f0, false), read(v_locked, f_locked, true))
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_method_recovers_the_circuit_it_was_read_from() {
        // Locked at a quarter of the rated voltage and frequency, as the standard advises.
        let (no_load, locked) = readings(&MACHINE, (400.0, 50.0), (100.0, 12.5));
        let tests = Tests {
            rs: MACHINE.rs,
            no_load,
            locked,
            nema: Nema::A,
            frequency: 50.0,
        };
        let c = circuit(&tests, MACHINE.j, MACHINE.np).unwrap();
        // Solved exactly, the circuit comes back to rounding.
        assert_eq!(c.rs, MACHINE.rs);
        for (name, got, true_value, within) in [
            ("rr", c.rr, MACHINE.rr, 1e-9),
            ("m", c.m, MACHINE.m, 1e-9),
            ("ls", c.ls, MACHINE.ls, 1e-9),
            ("lr", c.lr, MACHINE.lr, 1e-9),
        ] {
            assert!(
                (got / true_value - 1.0).abs() < within,
                "{name}: {got} against {true_value}"
            );
        }
    }

    #[test]
    fn impossible_readings_are_refused_with_the_reason() {
        let (no_load, locked) = readings(&MACHINE, (400.0, 50.0), (100.0, 12.5));
        let tests = Tests {
            rs: MACHINE.rs,
            no_load,
            locked,
            nema: Nema::B,
            frequency: 50.0,
        };
        let too_much = Tests { rs: 100.0, ..tests };
        assert!(matches!(
            circuit(&too_much, 0.015, 2.0),
            Err(IdentifyError::NoRotorResistance { .. })
        ));
        let hot = Tests {
            locked: Reading {
                power: 1e6,
                ..locked
            },
            ..tests
        };
        assert_eq!(
            circuit(&hot, 0.015, 2.0),
            Err(IdentifyError::PowerTooHigh("locked"))
        );
    }
}
