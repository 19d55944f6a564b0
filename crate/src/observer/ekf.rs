//! Extended Kalman filter, eqs (10)–(20).

use crate::model::{self, Input, State};
use crate::params::Lumped;
use nalgebra::{Matrix2, Matrix5, SMatrix, Vector2, Vector5};
use serde::{Deserialize, Serialize};

/// How the EKF predicts x̂_{k|k−1} from x̂_{k−1|k−1} over one sample.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Serialize, Deserialize)]
#[serde(rename_all = "lowercase")]
pub enum Predictor {
    /// Forward Euler, eq (10) and A_k = I + Ts·A of eq (12): the paper's choice.
    Euler,
    /// Classical RK4 for the state and its exact Jacobian for the covariance (an improvement).
    Rk4,
}

/// Tuning of the EKF.
#[derive(Clone, Copy, Debug, PartialEq, Serialize, Deserialize)]
pub struct EkfConfig {
    /// Predictor discretisation.
    pub predictor: Predictor,
    /// Process noise Q = q·Ts·I (the paper uses q = 0.001).
    pub q: f64,
    /// Measurement noise standard deviation assumed in R = r_std²·I (A).
    pub r_std: f64,
}

/// Extended Kalman filter over model (2) with measured y = [i_sa, i_sb].
#[derive(Clone, Debug)]
pub struct Ekf {
    model: Lumped,
    ts: f64,
    predictor: Predictor,
    q: Matrix5<f64>,
    /// Measurement noise variance: R = r2·I (A²).
    r2: f64,
    x: Vector5<f64>,
    p: Matrix5<f64>,
    gain: SMatrix<f64, 5, 2>,
    innovation: Vector2<f64>,
    s: Matrix2<f64>,
}

fn to_matrix(a: &[[f64; 5]; 5]) -> Matrix5<f64> {
    Matrix5::from_fn(|i, j| a[i][j])
}

/// A symmetric matrix from a function evaluated on the upper triangle only.
#[inline]
fn symmetric_from_upper(f: impl Fn(usize, usize) -> f64) -> Matrix5<f64> {
    let mut m = Matrix5::zeros();
    for i in 0..5 {
        for j in i..5 {
            let v = f(i, j);
            m[(i, j)] = v;
            m[(j, i)] = v;
        }
    }
    m
}

fn to_state(v: &Vector5<f64>) -> State {
    [v[0], v[1], v[2], v[3], v[4]]
}

impl Ekf {
    /// A filter started at `x0_hat` with covariance P0 = diag(p0_std²) + Q.
    pub fn new(model: Lumped, ts: f64, config: &EkfConfig, x0_hat: State, p0_std: State) -> Ekf {
        let q = Matrix5::identity() * (config.q * ts);
        let p0 = Matrix5::from_diagonal(&Vector5::from_fn(|i, _| p0_std[i] * p0_std[i])) + q;
        Ekf {
            model,
            ts,
            predictor: config.predictor,
            q,
            r2: config.r_std * config.r_std,
            x: Vector5::from_column_slice(&x0_hat),
            p: p0,
            gain: SMatrix::zeros(),
            innovation: Vector2::zeros(),
            s: Matrix2::zeros(),
        }
    }

    /// Predict step, eqs (13)–(14), with the input u_{k−1} held over the sample.
    pub fn predict(&mut self, u: &Input) {
        let x = to_state(&self.x);
        let (x_next, phi) = match self.predictor {
            Predictor::Euler => {
                let dx = model::f(&self.model, &x, u, 0.0);
                let a = to_matrix(&model::jacobian(&self.model, &x));
                let mut xn = x;
                for i in 0..5 {
                    xn[i] += self.ts * dx[i];
                }
                (xn, Matrix5::identity() + a * self.ts)
            }
            Predictor::Rk4 => self.rk4_with_jacobian(&x, u),
        };
        self.x = Vector5::from_column_slice(&x_next);
        let p = &self.p;
        let n = Matrix5::from_fn(|i, j| (0..5).map(|k| phi[(i, k)] * p[(k, j)]).sum::<f64>());
        self.p = symmetric_from_upper(|i, j| {
            (0..5).map(|k| n[(i, k)] * phi[(j, k)]).sum::<f64>() + self.q[(i, j)]
        });
    }

    /// RK4 state transition and its exact Jacobian Φ = ∂x_{k|k−1}/∂x_{k−1|k−1} (chain rule).
    fn rk4_with_jacobian(&self, x: &State, u: &Input) -> (State, Matrix5<f64>) {
        let (m, h) = (&self.model, self.ts);
        let id = Matrix5::<f64>::identity();
        let stage = |base: &State, c: f64, k: &State| -> State {
            let mut s = *base;
            for i in 0..5 {
                s[i] += c * k[i];
            }
            s
        };
        let k1 = model::f(m, x, u, 0.0);
        let j1 = to_matrix(&model::jacobian(m, x));
        let x2 = stage(x, 0.5 * h, &k1);
        let k2 = model::f(m, &x2, u, 0.0);
        let j2 = to_matrix(&model::jacobian(m, &x2)) * (id + j1 * (0.5 * h));
        let x3 = stage(x, 0.5 * h, &k2);
        let k3 = model::f(m, &x3, u, 0.0);
        let j3 = to_matrix(&model::jacobian(m, &x3)) * (id + j2 * (0.5 * h));
        let x4 = stage(x, h, &k3);
        let k4 = model::f(m, &x4, u, 0.0);
        let j4 = to_matrix(&model::jacobian(m, &x4)) * (id + j3 * h);
        let mut xn = *x;
        for i in 0..5 {
            xn[i] += h / 6.0 * (k1[i] + 2.0 * k2[i] + 2.0 * k3[i] + k4[i]);
        }
        (xn, id + (j1 + j2 * 2.0 + j3 * 2.0 + j4) * (h / 6.0))
    }

    /// Update step, eqs (15)–(19), with the measured currents y_k.
    ///
    /// The covariance uses the Joseph form (I−KC)P(I−KC)ᵀ + KRKᵀ instead of (19): it is
    /// algebraically equal for the optimal K and keeps P symmetric positive semi-definite in
    /// floating point.
    pub fn update(&mut self, y: &[f64; 2]) {
        // C selects x2 and x3, so C·P·Cᵀ is the 2×2 block P[1..3, 1..3] and P·Cᵀ is P[:, 1..3].
        let p = self.p;
        let r2 = self.r2;
        self.innovation = Vector2::new(y[0] - self.x[1], y[1] - self.x[2]);
        self.s = Matrix2::new(p[(1, 1)] + r2, p[(1, 2)], p[(2, 1)], p[(2, 2)] + r2);
        let inv_det = 1.0 / self.s.determinant();
        let (i11, i12, i22) = (
            self.s[(1, 1)] * inv_det,
            -self.s[(0, 1)] * inv_det,
            self.s[(0, 0)] * inv_det,
        );
        let k = SMatrix::<f64, 5, 2>::from_fn(|i, c| {
            let (g0, g1) = (p[(i, 1)], p[(i, 2)]);
            if c == 0 {
                g0 * i11 + g1 * i12
            } else {
                g0 * i12 + g1 * i22
            }
        });
        self.gain = k;
        self.x += k * self.innovation;
        // Joseph form with C's structure: A = (I − KC)·P = P − K·(C·P), then
        // P⁺ = A·(I − KC)ᵀ + K·R·Kᵀ = A − (A·Cᵀ)·Kᵀ + r²·K·Kᵀ. Only the upper triangle is
        // computed, so P stays exactly symmetric.
        let a = Matrix5::from_fn(|i, j| p[(i, j)] - k[(i, 0)] * p[(1, j)] - k[(i, 1)] * p[(2, j)]);
        self.p = symmetric_from_upper(|i, j| {
            a[(i, j)] - a[(i, 1)] * k[(j, 0)] - a[(i, 2)] * k[(j, 1)]
                + r2 * (k[(i, 0)] * k[(j, 0)] + k[(i, 1)] * k[(j, 1)])
        });
    }

    /// Posterior estimate x̂_{k|k}.
    pub fn state(&self) -> State {
        to_state(&self.x)
    }

    /// Kalman gain K_k (5×2, row-major).
    pub fn gain(&self) -> [[f64; 2]; 5] {
        let k = &self.gain;
        std::array::from_fn(|i| [k[(i, 0)], k[(i, 1)]])
    }

    /// Posterior covariance P_{k|k}.
    pub fn covariance(&self) -> &Matrix5<f64> {
        &self.p
    }

    /// Innovation ỹ_k = y_k − C x̂_{k|k−1} of eq (15) (A).
    pub fn innovation(&self) -> [f64; 2] {
        [self.innovation[0], self.innovation[1]]
    }

    /// Innovation covariance S_k of eq (16) as [s11, s12, s22] (A²).
    pub fn innovation_cov(&self) -> [f64; 3] {
        [self.s[(0, 0)], self.s[(0, 1)], self.s[(1, 1)]]
    }

    /// Normalised innovation squared ỹᵀ S⁻¹ ỹ (χ² with 2 degrees of freedom when consistent).
    pub fn nis(&self) -> f64 {
        let [s11, s12, s22] = self.innovation_cov();
        let [e1, e2] = self.innovation();
        (s22 * e1 * e1 - 2.0 * s12 * e1 * e2 + s11 * e2 * e2) / (s11 * s22 - s12 * s12)
    }
}

/// Two-sided `confidence` interval of one sample's NIS when the filter is consistent: χ² with
/// 2 degrees of freedom, whose distribution function is 1 − exp(−x/2).
pub fn nis_band(confidence: f64) -> (f64, f64) {
    let tail = 0.5 * (1.0 - confidence);
    (-2.0 * libm::log(1.0 - tail), -2.0 * libm::log(tail))
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::params::MotorParams;

    /// Finite differences of the RK4 map with step 1e-6 on O(1) states: ~1e-8 relative error.
    const PHI_TOL: f64 = 1e-6;

    #[test]
    fn nis_band_is_the_chi_square_2_quantiles() {
        let (lo, hi) = nis_band(0.95);
        assert!(
            (lo - 0.050636).abs() < 1e-6 && (hi - 7.377759).abs() < 1e-6,
            "{lo} {hi}"
        );
    }

    #[test]
    fn rk4_transition_jacobian_matches_finite_differences() {
        let p = MotorParams::PAPER.lumped().unwrap();
        let cfg = EkfConfig {
            predictor: Predictor::Rk4,
            q: 0.001,
            r_std: 0.002,
        };
        let ekf = Ekf::new(p, 5e-5, &cfg, [0.0; 5], [0.0; 5]);
        let x = [30.0, 3.0, -2.0, 0.6, -0.4];
        let u = [120.0, -80.0];
        let (_, phi) = ekf.rk4_with_jacobian(&x, &u);
        for j in 0..5 {
            let h = 1e-6 * (1.0 + f64::abs(x[j]));
            let (mut xp, mut xm) = (x, x);
            xp[j] += h;
            xm[j] -= h;
            let (fp, _) = ekf.rk4_with_jacobian(&xp, &u);
            let (fm, _) = ekf.rk4_with_jacobian(&xm, &u);
            for i in 0..5 {
                let fd = (fp[i] - fm[i]) / (2.0 * h);
                assert!((fd - phi[(i, j)]).abs() < PHI_TOL * (1.0 + phi[(i, j)].abs()));
            }
        }
    }
}
