//! Theorem 4.6: the Lyapunov function V = ½ Σ z_i² and its bound (59).

use crate::control::Gains;
use serde::Serialize;

/// The bound (59): V(t) ≤ exp(−λt)·V(0) + ε/λ·(1 − exp(−λt)), with λ = 2·min(k_i).
#[cfg_attr(
    target_arch = "wasm32",
    derive(tsify::Tsify),
    tsify(missing_as_null, hashmap_as_object)
)]
#[derive(Clone, Copy, Debug, PartialEq, Serialize)]
pub struct LyapunovBound {
    /// V(0).
    pub v0: f64,
    /// λ = 2·min(k1, k2, k3, k4) (1/s).
    pub lambda: f64,
    /// ε = ε2 + ε4 with the robust terms on; 0 without them (then d̃ must vanish for (59) to hold).
    pub eps: f64,
}

impl LyapunovBound {
    /// The bound for `gains` starting from V(0) = `v0`.
    pub fn new(gains: &Gains, v0: f64) -> LyapunovBound {
        let k_min = gains.k1.min(gains.k2).min(gains.k3).min(gains.k4);
        LyapunovBound {
            v0,
            lambda: 2.0 * k_min,
            eps: if gains.robust {
                gains.eps2 + gains.eps4
            } else {
                0.0
            },
        }
    }

    /// The bound at time `t` (s).
    pub fn at(&self, t: f64) -> f64 {
        let e = libm::exp(-self.lambda * t);
        e * self.v0 + self.eps / self.lambda * (1.0 - e)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn bound_starts_at_v0_and_settles_at_eps_over_lambda() {
        let mut g = Gains {
            k1: 1200.0,
            k2: 900.0,
            k3: 1500.0,
            k4: 2000.0,
            robust: true,
            eps2: 3.0,
            h2: 1.0,
            eps4: 1.5,
            h4: 1.0,
        };
        let b = LyapunovBound::new(&g, 10.0);
        assert_eq!(b.lambda, 1800.0);
        assert_eq!(b.at(0.0), 10.0);
        assert!((b.at(1.0) - 4.5 / 1800.0).abs() < 1e-15);
        g.robust = false;
        assert_eq!(LyapunovBound::new(&g, 10.0).at(1.0), 0.0);
    }
}
