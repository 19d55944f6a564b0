//! Motor parameters in SI units and the paper's lumped parameters a1..a10, b (Section 2.1).

use crate::text::Message;
use serde::{Deserialize, Serialize};
use std::fmt;

/// Physical parameters of the induction motor and its load (SI units).
#[derive(Clone, Copy, Debug, PartialEq, Serialize, Deserialize)]
pub struct MotorParams {
    /// Stator resistance R_s (Ω).
    pub rs: f64,
    /// Rotor resistance R_r (Ω).
    pub rr: f64,
    /// Mutual inductance M (H).
    pub m: f64,
    /// Stator inductance L_s (H).
    pub ls: f64,
    /// Rotor inductance L_r (H).
    pub lr: f64,
    /// Rotor inertia J (kg m²).
    pub j: f64,
    /// Number of pole pairs n_p.
    pub np: f64,
    /// Constant load torque T_0 (N m).
    pub t0: f64,
    /// Viscous friction coefficient C_f (N m s/rad).
    pub cf: f64,
}

impl MotorParams {
    /// The motor of the paper's Section 5 (from Khalil et al. 2009).
    pub const PAPER: MotorParams = MotorParams {
        rs: 2.3,
        rr: 4.95,
        m: 0.523,
        ls: 0.538,
        lr: 0.5396,
        j: 0.02,
        np: 2.0,
        t0: 0.5,
        cf: 0.001,
    };

    /// Leakage factor σ = L_s − M²/L_r (H).
    pub fn sigma(&self) -> f64 {
        self.ls - self.m * self.m / self.lr
    }

    /// Lumped parameters a1..a10 and b of model (2), after checking that they are physical.
    pub fn lumped(&self) -> Result<Lumped, ParamError> {
        for (name, value) in [
            ("rs", self.rs),
            ("rr", self.rr),
            ("m", self.m),
            ("ls", self.ls),
            ("lr", self.lr),
            ("j", self.j),
            ("np", self.np),
        ] {
            if !(value.is_finite() && value > 0.0) {
                return Err(ParamError::NotPositive { name, value });
            }
        }
        for (name, value) in [("t0", self.t0), ("cf", self.cf)] {
            if !(value.is_finite() && value >= 0.0) {
                return Err(ParamError::Negative { name, value });
            }
        }
        let sigma = self.sigma();
        if sigma <= 0.0 {
            return Err(ParamError::SigmaNotPositive {
                sigma,
                m: self.m,
                ls: self.ls,
                lr: self.lr,
            });
        }
        let alpha = self.rr / self.lr;
        let beta = self.m / (sigma * self.lr);
        let gamma = self.rs / sigma + alpha * beta * self.m;
        let mu = 1.5 * self.np * self.m / (self.j * self.lr);
        Ok(Lumped {
            a1: mu,
            a2: self.t0 / self.j,
            a3: self.cf / self.j,
            a5: alpha * beta,
            a6: self.np * beta,
            a7: gamma,
            a8: alpha,
            a9: self.np,
            a10: alpha * self.m,
            b: 1.0 / sigma,
            j: self.j,
        })
    }
}

/// The lumped parameters of model (2); the paper has no a4.
#[cfg_attr(
    target_arch = "wasm32",
    derive(tsify::Tsify),
    tsify(missing_as_null, hashmap_as_object)
)]
#[derive(Clone, Copy, Debug, PartialEq, Serialize)]
pub struct Lumped {
    /// a1 = μ = 3 n_p M / (2 J L_r) (torque constant over inertia, 1/(kg m²)): a1·(x3·x4 − x2·x5)
    /// is torque/J in rad/s², not a torque.
    pub a1: f64,
    /// a2 = T_0 / J (rad/s²).
    pub a2: f64,
    /// a3 = C_f / J (1/s).
    pub a3: f64,
    /// a5 = α β.
    pub a5: f64,
    /// a6 = n_p β.
    pub a6: f64,
    /// a7 = γ = R_s/σ + α β M (1/s).
    pub a7: f64,
    /// a8 = α = R_r / L_r (1/s).
    pub a8: f64,
    /// a9 = n_p.
    pub a9: f64,
    /// a10 = α M (Ω).
    pub a10: f64,
    /// b = 1/σ (1/H).
    pub b: f64,
    /// Rotor inertia J (kg m²), kept to turn an extra load torque into a deceleration.
    pub j: f64,
}

/// Why a set of motor parameters is not physical.
#[derive(Clone, Debug, PartialEq)]
pub enum ParamError {
    /// A parameter that must be strictly positive is not.
    NotPositive {
        /// Parameter name.
        name: &'static str,
        /// Offending value.
        value: f64,
    },
    /// A parameter that must be non-negative is not.
    Negative {
        /// Parameter name.
        name: &'static str,
        /// Offending value.
        value: f64,
    },
    /// The leakage factor σ = L_s − M²/L_r is not positive (M² ≥ L_s L_r).
    SigmaNotPositive {
        /// σ (H).
        sigma: f64,
        /// M (H).
        m: f64,
        /// L_s (H).
        ls: f64,
        /// L_r (H).
        lr: f64,
    },
}

impl ParamError {
    /// What the error says, as a message of `core-scenario.ftl`.
    pub fn message(&self) -> Message {
        match self {
            ParamError::NotPositive { name, value } => Message::new("param-not-positive")
                .text("name", *name)
                .real("value", *value),
            ParamError::Negative { name, value } => Message::new("param-negative")
                .text("name", *name)
                .real("value", *value),
            ParamError::SigmaNotPositive { sigma, m, ls, lr } => Message::new("param-sigma")
                .fixed("sigma", *sigma, 6)
                .real("m", *m)
                .real("ls", *ls)
                .real("lr", *lr),
        }
    }
}

impl fmt::Display for ParamError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        self.message().fmt(f)
    }
}

impl std::error::Error for ParamError {}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn paper_lumped_values() {
        let l = MotorParams::PAPER.lumped().unwrap();
        let sigma = 0.538 - 0.523 * 0.523 / 0.5396;
        assert!((l.b - 1.0 / sigma).abs() < 1e-12);
        assert!((l.a2 - 25.0).abs() < 1e-12); // 0.5 N m / 0.02 kg m²
        assert!((l.a3 - 0.05).abs() < 1e-12);
        assert!((l.a8 - 4.95 / 0.5396).abs() < 1e-12);
        // γ two ways (Section 2.1): (M² Rr + Lr² Rs)/(σ Lr²) = Rs/σ + αβM.
        let p = MotorParams::PAPER;
        let gamma = (p.m * p.m * p.rr + p.lr * p.lr * p.rs) / (sigma * p.lr * p.lr);
        assert!((l.a7 - gamma).abs() < 1e-9 * gamma);
    }

    #[test]
    fn rejects_unphysical() {
        let mut p = MotorParams::PAPER;
        p.m = 0.6; // M² > Ls Lr
        assert!(matches!(
            p.lumped(),
            Err(ParamError::SigmaNotPositive { .. })
        ));
        let mut p = MotorParams::PAPER;
        p.rr = 0.0;
        assert_eq!(
            p.lumped(),
            Err(ParamError::NotPositive {
                name: "rr",
                value: 0.0
            })
        );
    }
}
