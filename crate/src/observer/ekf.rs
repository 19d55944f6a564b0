//! Extended Kalman filter, eqs (10)–(20), over the five states of model (2) and, optionally,
//! the two parameters Section 3.1 names for adaptation: the load a2 = T_L0/J and the rotor
//! resistance R_r, each a random-walk state (the paper's remedy, which it does not build).

use crate::model::{self, Input, State};
use crate::params::{Lumped, MotorParams};
use five::{euler5_predict, update5};
use nalgebra::{Matrix2, SMatrix, SVector, Vector2};
use serde::{Deserialize, Serialize};

mod five;

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
    /// Process noise Q = q·Ts·I (the paper uses q = 0.001): one number for states of mixed
    /// units, so its unit is each state's unit squared per second (A²/s for the currents,
    /// (rad/s)²/s for ω, Wb²/s for the fluxes).
    pub q: f64,
    /// Process noise added to the speed state alone: Q_ωω = q·Ts + q_speed·Ts ((rad/s)²/s).
    /// Without a load state it lets the speed estimate follow an unknown load, at the price of a
    /// noisier estimate.
    pub q_speed: f64,
    /// Measurement noise standard deviation assumed in R = r_std²·I (A).
    pub r_std: f64,
    /// Estimate the load a2 = T_L0/J as a random-walk state, started at the model's T0/J.
    pub load: bool,
    /// Random-walk intensity of the load torque: Q_a2 = q_load·Ts/J² ((N m)²/s).
    pub q_load: f64,
    /// Initial standard deviation of the load-torque estimate (N m).
    pub load_std: f64,
    /// Estimate the rotor resistance R_r as a random-walk state, started at the model's R_r.
    pub rr: bool,
    /// Random-walk intensity of the rotor resistance: Q_Rr = q_rr·Ts (Ω²/s).
    pub q_rr: f64,
    /// Initial standard deviation of the rotor-resistance estimate (Ω).
    pub rr_std: f64,
}

/// Where the lumped parameters depend on R_r: a5 = α·β, a7 = R_s/σ + α·β·M, a8 = α, a10 = α·M
/// with α = R_r/L_r and β = M/(σ·L_r) (the same expressions as [`MotorParams::lumped`]).
#[derive(Clone, Copy, Debug)]
struct RrTerms {
    lr: f64,
    m: f64,
    beta: f64,
    rs_over_sigma: f64,
}

impl RrTerms {
    fn of(p: &MotorParams) -> RrTerms {
        let sigma = p.sigma();
        RrTerms {
            lr: p.lr,
            m: p.m,
            beta: p.m / (sigma * p.lr),
            rs_over_sigma: p.rs / sigma,
        }
    }

    /// `model` with a5, a7, a8 and a10 at rotor resistance `rr`.
    fn apply(&self, model: &mut Lumped, rr: f64) {
        let alpha = rr / self.lr;
        model.a5 = alpha * self.beta;
        model.a7 = self.rs_over_sigma + alpha * self.beta * self.m;
        model.a8 = alpha;
        model.a10 = alpha * self.m;
    }
}

/// The EKF with `N` states: the five of model (2), then â2 (if estimated), then R̂_r (if
/// estimated). With N = 5 it is the paper's filter, operation for operation.
#[derive(Clone, Debug)]
pub struct Filter<const N: usize> {
    /// The model's lumped parameters (a2 and the R_r-dependent ones are replaced by the
    /// estimates where those are states).
    model: Lumped,
    rr_terms: RrTerms,
    /// Index of â2 in the state, if estimated.
    load_at: Option<usize>,
    /// Index of R̂_r in the state, if estimated.
    rr_at: Option<usize>,
    ts: f64,
    predictor: Predictor,
    q: SMatrix<f64, N, N>,
    /// Measurement noise variance: R = r2·I (A²).
    r2: f64,
    x: SVector<f64, N>,
    p: SMatrix<f64, N, N>,
    gain: SMatrix<f64, N, 2>,
    innovation: Vector2<f64>,
    s: Matrix2<f64>,
}

/// The paper's five-state EKF.
pub type Ekf = Filter<5>;

/// What the loop takes from the filter after one sample.
#[derive(Clone, Copy, Debug)]
pub struct Estimate {
    /// Posterior estimate x̂_{k|k} of the five states.
    pub x_hat: State,
    /// Kalman gain K_k of the five states.
    pub gain: [[f64; 2]; 5],
    /// â2, its variance and its gain row, when the load is estimated.
    pub load: Option<(f64, f64, [f64; 2])>,
    /// R̂_r and its variance, when the rotor resistance is estimated.
    pub rotor_resistance: Option<(f64, f64)>,
    /// The lumped parameters at the estimate, when any parameter is estimated.
    pub adapted_model: Option<Lumped>,
    /// Posterior speed variance P_11.
    pub p_omega: f64,
    /// Innovation ỹ_k (A).
    pub innovation: [f64; 2],
    /// Innovation covariance [s11, s12, s22] (A²).
    pub innovation_cov: [f64; 3],
}

impl Estimate {
    /// Normalised innovation squared ỹᵀ S⁻¹ ỹ (χ² with 2 degrees of freedom when consistent),
    /// computed when asked for: the loop needs it for the samples it records only.
    pub fn nis(&self) -> f64 {
        let ([e1, e2], [s11, s12, s22]) = (self.innovation, self.innovation_cov);
        (s22 * e1 * e1 - 2.0 * s12 * e1 * e2 + s11 * e2 * e2) / (s11 * s22 - s12 * s12)
    }
}

/// A symmetric matrix from a function evaluated on the upper triangle only.
#[inline]
fn symmetric_from_upper<const N: usize>(f: impl Fn(usize, usize) -> f64) -> SMatrix<f64, N, N> {
    let mut m = SMatrix::<f64, N, N>::zeros();
    for i in 0..N {
        for j in i..N {
            let v = f(i, j);
            m[(i, j)] = v;
            m[(j, i)] = v;
        }
    }
    m
}

fn five<const N: usize>(v: &SVector<f64, N>) -> State {
    [v[0], v[1], v[2], v[3], v[4]]
}

impl<const N: usize> Filter<N> {
    /// A filter started at `x0_hat` with covariance P0 = diag(p0_std²) + Q for the five states;
    /// the added states start at the model's values with the configured standard deviations.
    /// N must be 5 plus one for each parameter `config` estimates.
    pub fn new(
        params: &MotorParams,
        model: Lumped,
        ts: f64,
        config: &EkfConfig,
        x0_hat: State,
        p0_std: State,
    ) -> Filter<N> {
        let load_at = config.load.then_some(5);
        let rr_at = config.rr.then_some(5 + usize::from(config.load));
        assert_eq!(
            N,
            5 + usize::from(config.load) + usize::from(config.rr),
            "state size"
        );
        let mut q = SMatrix::<f64, N, N>::identity() * (config.q * ts);
        // q·Ts > 0, so adding 0·Ts leaves Q's bits as they were without the speed's own noise.
        q[(0, 0)] += config.q_speed * ts;
        let mut x = SVector::<f64, N>::zeros();
        let mut std = [0.0; N];
        for i in 0..5 {
            x[i] = x0_hat[i];
            std[i] = p0_std[i];
        }
        if let Some(i) = load_at {
            q[(i, i)] = config.q_load * ts / (params.j * params.j);
            x[i] = model.a2;
            std[i] = config.load_std / params.j;
        }
        if let Some(i) = rr_at {
            q[(i, i)] = config.q_rr * ts;
            x[i] = params.rr;
            std[i] = config.rr_std;
        }
        let p0 = SMatrix::<f64, N, N>::from_diagonal(&SVector::<f64, N>::from_fn(|i, _| {
            std[i] * std[i]
        })) + q;
        Filter {
            model,
            rr_terms: RrTerms::of(params),
            load_at,
            rr_at,
            ts,
            predictor: config.predictor,
            q,
            r2: config.r_std * config.r_std,
            x,
            p: p0,
            gain: SMatrix::zeros(),
            innovation: Vector2::zeros(),
            s: Matrix2::zeros(),
        }
    }

    /// The lumped parameters at the estimate `x`: the model's, with â2 and R̂_r where estimated.
    #[inline]
    fn lumped_at(&self, x: &SVector<f64, N>) -> Lumped {
        let mut p = self.model;
        if let Some(i) = self.load_at {
            p.a2 = x[i];
        }
        if let Some(i) = self.rr_at {
            self.rr_terms.apply(&mut p, x[i]);
        }
        p
    }

    /// `then` of the lumped parameters at `x`; the paper's filter passes its model unchanged
    /// (no copy in the 20 kHz loop).
    #[inline]
    fn at<R>(&self, x: &SVector<f64, N>, then: impl FnOnce(&Lumped) -> R) -> R {
        if N == 5 {
            then(&self.model)
        } else {
            then(&self.lumped_at(x))
        }
    }

    /// f of the augmented model: (2) for the five states, zero for the random-walk parameters.
    #[inline]
    fn f(&self, x: &SVector<f64, N>, u: &Input) -> State {
        self.at(x, |p| model::f(p, &five(x), u, 0.0))
    }

    /// Jacobian of the augmented model: (11), plus ∂f/∂a2 = −e1 and ∂f/∂R_r (model (2) is affine
    /// in R_r, so its column is exact).
    #[inline]
    fn jacobian(&self, x: &SVector<f64, N>) -> SMatrix<f64, N, N> {
        let a = self.at(x, |p| model::jacobian(p, &five(x)));
        let mut m =
            SMatrix::<f64, N, N>::from_fn(|i, j| if i < 5 && j < 5 { a[i][j] } else { 0.0 });
        if let Some(k) = self.load_at {
            m[(0, k)] = -1.0;
        }
        if let Some(k) = self.rr_at {
            let RrTerms {
                lr, m: mm, beta, ..
            } = self.rr_terms;
            let [_, x2, x3, x4, x5] = five(x);
            // d/dR_r of a5 = β/L_r, of a7 = β·M/L_r, of a8 = 1/L_r, of a10 = M/L_r.
            m[(1, k)] = beta / lr * x4 - beta * mm / lr * x2;
            m[(2, k)] = beta / lr * x5 - beta * mm / lr * x3;
            m[(3, k)] = -x4 / lr + mm / lr * x2;
            m[(4, k)] = -x5 / lr + mm / lr * x3;
        }
        m
    }

    /// Predict step, eqs (13)–(14), with the input u_{k−1} held over the sample, on nalgebra
    /// matrices. [`Filter::sample`] runs the paper's filter (N = 5, Euler) on plain arrays
    /// instead, with the same bits.
    pub fn predict(&mut self, u: &Input) {
        let (x_next, phi) = match self.predictor {
            Predictor::Euler => (
                self.euler_state(u),
                SMatrix::<f64, N, N>::identity() + self.jacobian(&self.x) * self.ts,
            ),
            Predictor::Rk4 => self.rk4_with_jacobian(&self.x, u),
        };
        self.x = x_next;
        let p = &self.p;
        let n = SMatrix::<f64, N, N>::from_fn(|i, j| {
            (0..N).map(|k| phi[(i, k)] * p[(k, j)]).sum::<f64>()
        });
        self.p = symmetric_from_upper(|i, j| {
            (0..N).map(|k| n[(i, k)] * phi[(j, k)]).sum::<f64>() + self.q[(i, j)]
        });
    }

    /// x and P of the five-state filter as plain arrays (P as columns, `p[5j + i]` = P_ij).
    fn plain5(&mut self) -> (&mut [f64; 5], &mut [f64; 25]) {
        (
            self.x.as_mut_slice().try_into().expect("five states"),
            self.p.as_mut_slice().try_into().expect("five states"),
        )
    }

    /// The five-state filter's sample on plain arrays: the Euler prediction (when `u` is given,
    /// the caller having checked the predictor) and the update, in one piece so that P passes from
    /// one to the other without a round trip through the filter.
    fn sample5(&mut self, u: Option<&Input>, y: &[f64; 2]) {
        let q: [f64; 5] = std::array::from_fn(|i| self.q[(i, i)]);
        let (m, ts, r2) = (self.model, self.ts, self.r2);
        let (x, p) = self.plain5();
        if let Some(u) = u {
            euler5_predict(&m, ts, &q, u, x, p);
        }
        let out = update5(r2, y, x, p);
        self.gain.as_mut_slice().copy_from_slice(&out.gain);
        self.innovation = Vector2::from(out.innovation);
        self.s.as_mut_slice().copy_from_slice(&out.s);
    }

    /// The five states one sample ahead, x̂_{k+1|k}, under the input `u` held over the sample, by
    /// this filter's own predictor (the state part of [`Filter::predict`]; P is left alone).
    pub fn predicted_state(&self, u: &Input) -> State {
        let x = match self.predictor {
            Predictor::Euler => self.euler_state(u),
            Predictor::Rk4 => self.rk4_with_jacobian(&self.x, u).0,
        };
        five(&x)
    }

    /// Euler step of the state, eq (13): x + Ts·f(x, u); the added parameters stay.
    fn euler_state(&self, u: &Input) -> SVector<f64, N> {
        let dx = self.f(&self.x, u);
        let mut xn = self.x;
        for i in 0..5 {
            xn[i] += self.ts * dx[i];
        }
        xn
    }

    /// RK4 state transition and its exact Jacobian Φ = ∂x_{k|k−1}/∂x_{k−1|k−1} (chain rule).
    fn rk4_with_jacobian(
        &self,
        x: &SVector<f64, N>,
        u: &Input,
    ) -> (SVector<f64, N>, SMatrix<f64, N, N>) {
        let h = self.ts;
        let id = SMatrix::<f64, N, N>::identity();
        // The parameters are constant over the step: only the five states move.
        let stage = |base: &SVector<f64, N>, c: f64, k: &State| -> SVector<f64, N> {
            let mut s = *base;
            for i in 0..5 {
                s[i] += c * k[i];
            }
            s
        };
        let k1 = self.f(x, u);
        let j1 = self.jacobian(x);
        let x2 = stage(x, 0.5 * h, &k1);
        let k2 = self.f(&x2, u);
        let j2 = self.jacobian(&x2) * (id + j1 * (0.5 * h));
        let x3 = stage(x, 0.5 * h, &k2);
        let k3 = self.f(&x3, u);
        let j3 = self.jacobian(&x3) * (id + j2 * (0.5 * h));
        let x4 = stage(x, h, &k3);
        let k4 = self.f(&x4, u);
        let j4 = self.jacobian(&x4) * (id + j3 * h);
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
        if N == 5 {
            self.sample5(None, y);
        } else {
            self.update_general(y);
        }
    }

    /// [`Filter::update`] for any N, on nalgebra matrices.
    fn update_general(&mut self, y: &[f64; 2]) {
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
        let k = SMatrix::<f64, N, 2>::from_fn(|i, c| {
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
        let a = SMatrix::<f64, N, N>::from_fn(|i, j| {
            p[(i, j)] - k[(i, 0)] * p[(1, j)] - k[(i, 1)] * p[(2, j)]
        });
        self.p = symmetric_from_upper(|i, j| {
            a[(i, j)] - a[(i, 1)] * k[(j, 0)] - a[(i, 2)] * k[(j, 1)]
                + r2 * (k[(i, 0)] * k[(j, 0)] + k[(i, 1)] * k[(j, 1)])
        });
    }

    /// One sample: predict with u_{k−1} (none before the first sample), update with y_k, and
    /// return what the loop uses of the posterior.
    #[inline]
    pub fn sample(&mut self, u: Option<&Input>, y: &[f64; 2]) -> Estimate {
        if N == 5 && self.predictor == Predictor::Euler {
            self.sample5(u, y);
        } else {
            if let Some(u) = u {
                self.predict(u);
            }
            self.update(y);
        }
        Estimate {
            x_hat: self.state(),
            gain: self.gain(),
            load: self.load(),
            rotor_resistance: self.rotor_resistance(),
            adapted_model: (N > 5).then(|| self.lumped()),
            p_omega: self.p[(0, 0)],
            innovation: self.innovation(),
            innovation_cov: self.innovation_cov(),
        }
    }

    /// Posterior estimate x̂_{k|k} of the five states.
    pub fn state(&self) -> State {
        five(&self.x)
    }

    /// Kalman gain K_k of the five states (5×2, row-major).
    pub fn gain(&self) -> [[f64; 2]; 5] {
        let k = &self.gain;
        std::array::from_fn(|i| [k[(i, 0)], k[(i, 1)]])
    }

    /// The lumped parameters at the posterior estimate (the model's when nothing is estimated).
    pub fn lumped(&self) -> Lumped {
        self.lumped_at(&self.x)
    }

    /// â2, its posterior variance and its gain row, when the load is estimated.
    pub fn load(&self) -> Option<(f64, f64, [f64; 2])> {
        self.load_at.map(|i| {
            (
                self.x[i],
                self.p[(i, i)],
                [self.gain[(i, 0)], self.gain[(i, 1)]],
            )
        })
    }

    /// R̂_r and its posterior variance, when the rotor resistance is estimated.
    pub fn rotor_resistance(&self) -> Option<(f64, f64)> {
        self.rr_at.map(|i| (self.x[i], self.p[(i, i)]))
    }

    /// Posterior covariance P_{k|k}.
    pub fn covariance(&self) -> &SMatrix<f64, N, N> {
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

    /// Finite differences of the RK4 map with step 1e-6 on O(1) states: ~1e-8 relative error.
    const PHI_TOL: f64 = 1e-6;

    fn config(load: bool, rr: bool) -> EkfConfig {
        EkfConfig {
            predictor: Predictor::Rk4,
            q: 0.001,
            q_speed: 0.0,
            r_std: 0.002,
            load,
            q_load: 1.0,
            load_std: 1.0,
            rr,
            q_rr: 0.01,
            rr_std: 0.5,
        }
    }

    fn filter<const N: usize>(load: bool, rr: bool) -> Filter<N> {
        let params = MotorParams::PAPER;
        Filter::new(
            &params,
            params.lumped().unwrap(),
            5e-5,
            &config(load, rr),
            [0.0; 5],
            [0.0; 5],
        )
    }

    #[test]
    fn nis_band_is_the_chi_square_2_quantiles() {
        let (lo, hi) = nis_band(0.95);
        assert!(
            (lo - 0.050636).abs() < 1e-6 && (hi - 7.377759).abs() < 1e-6,
            "{lo} {hi}"
        );
    }

    fn rk4_jacobian_matches_finite_differences<const N: usize>(
        ekf: &Filter<N>,
        x: SVector<f64, N>,
    ) {
        let u = [120.0, -80.0];
        let (_, phi) = ekf.rk4_with_jacobian(&x, &u);
        for j in 0..N {
            let h = 1e-6 * (1.0 + f64::abs(x[j]));
            let (mut xp, mut xm) = (x, x);
            xp[j] += h;
            xm[j] -= h;
            let (fp, _) = ekf.rk4_with_jacobian(&xp, &u);
            let (fm, _) = ekf.rk4_with_jacobian(&xm, &u);
            for i in 0..N {
                let fd = (fp[i] - fm[i]) / (2.0 * h);
                assert!(
                    (fd - phi[(i, j)]).abs() < PHI_TOL * (1.0 + phi[(i, j)].abs()),
                    "N = {N}: Φ[{i},{j}] = {} against {fd}",
                    phi[(i, j)]
                );
            }
        }
    }

    /// The delay compensation controls `predicted_state`: it must be the prior the next
    /// `predict` makes, bit for bit, whatever the predictor and the added states.
    #[test]
    fn predicted_state_is_the_next_prior() {
        let params = MotorParams::PAPER;
        let x0 = [30.0, 3.0, -2.0, 0.6, -0.4];
        let u = [120.0, -80.0];
        for predictor in [Predictor::Euler, Predictor::Rk4] {
            let cfg = |states| EkfConfig {
                predictor,
                ..config(states, states)
            };
            let lumped = params.lumped().unwrap();
            let mut plain: Filter<5> =
                Filter::new(&params, lumped, 5e-5, &cfg(false), x0, [0.1; 5]);
            let mut both: Filter<7> = Filter::new(&params, lumped, 5e-5, &cfg(true), x0, [0.1; 5]);
            let ahead = (plain.predicted_state(&u), both.predicted_state(&u));
            plain.predict(&u);
            both.predict(&u);
            assert_eq!(ahead, (plain.state(), both.state()), "{predictor:?}");
            // The prediction moves the state: a stale copy of x̂ would not pass.
            assert_ne!(ahead.0, x0);
        }
    }

    /// The five-state filter's plain-array steps (the fused sample, and `update` after the general
    /// prediction) against the general steps on nalgebra matrices: the same bits, sample after
    /// sample, and P exactly symmetric (which the plain prediction's Φ·P relies on).
    #[test]
    fn five_state_steps_match_the_general_steps() {
        let params = MotorParams::PAPER;
        let lumped = params.lumped().unwrap();
        let bits = |f: &Filter<5>| -> Vec<u64> {
            let (x, p, k) = (f.x.iter(), f.p.iter(), f.gain.iter());
            let rest = f.innovation.iter().chain(f.s.iter());
            x.chain(p)
                .chain(k)
                .chain(rest)
                .map(|v| v.to_bits())
                .collect()
        };
        for predictor in [Predictor::Euler, Predictor::Rk4] {
            let cfg = EkfConfig {
                predictor,
                q_speed: 50.0,
                ..config(false, false)
            };
            let x0 = [30.0, 3.0, -2.0, 0.6, -0.4];
            let new = || -> Filter<5> { Filter::new(&params, lumped, 5e-5, &cfg, x0, [3.0; 5]) };
            let (mut fused, mut split, mut general) = (new(), new(), new());
            let mut rng = crate::rng::Rng::new(7);
            for k in 0..4000 {
                let t = k as f64 * 5e-5;
                let u = [300.0 * (60.0 * t).cos(), 300.0 * (60.0 * t).sin()];
                let y = [
                    general.x[1] + 0.05 * rng.normal(),
                    general.x[2] + 0.05 * rng.normal(),
                ];
                let u = (k > 0).then_some(&u);
                fused.sample(u, &y);
                if let Some(u) = u {
                    split.predict(u);
                    general.predict(u);
                }
                split.update(&y);
                general.update_general(&y);
                assert_eq!(bits(&fused), bits(&general), "{predictor:?}, sample {k}");
                assert_eq!(bits(&split), bits(&general), "{predictor:?}, sample {k}");
            }
            let p = general.covariance();
            for i in 0..5 {
                for j in 0..5 {
                    assert_eq!(p[(i, j)].to_bits(), p[(j, i)].to_bits(), "P[{i},{j}]");
                }
            }
        }
    }

    #[test]
    fn rk4_transition_jacobian_matches_finite_differences() {
        let x = [30.0, 3.0, -2.0, 0.6, -0.4];
        rk4_jacobian_matches_finite_differences(&filter::<5>(false, false), SVector::from(x));
        let augmented = [30.0, 3.0, -2.0, 0.6, -0.4, 100.0, 5.5];
        rk4_jacobian_matches_finite_differences(&filter::<7>(true, true), SVector::from(augmented));
    }

    #[cfg(not(target_arch = "wasm32"))]
    use proptest::prelude::*;

    #[cfg(not(target_arch = "wasm32"))]
    proptest! {
        /// The analytic Jacobian of the augmented model (load and R_r states) against central
        /// differences of f at random states; f is affine in a2 and R_r and quadratic in the
        /// states, so central differences are exact up to rounding.
        #[test]
        fn augmented_jacobian_matches_central_differences(
            x in prop::array::uniform5(-50.0f64..50.0),
            a2 in -500.0f64..500.0,
            rr in 0.5f64..20.0,
        ) {
            let ekf = filter::<7>(true, true);
            let state = SVector::<f64, 7>::from([x[0], x[1], x[2], x[3], x[4], a2, rr]);
            let a = ekf.jacobian(&state);
            let u = [50.0, -30.0];
            for j in 0..7 {
                let h = 1e-4 * (1.0 + state[j].abs());
                let (mut xp, mut xm) = (state, state);
                xp[j] += h;
                xm[j] -= h;
                let (fp, fm) = (ekf.f(&xp, &u), ekf.f(&xm, &u));
                for i in 0..7 {
                    let fd = if i < 5 { (fp[i] - fm[i]) / (2.0 * h) } else { 0.0 };
                    let scale = 1.0 + a[(i, j)].abs() + fp.iter().map(|v| v.abs()).fold(0.0, f64::max) * 1e-9 / h;
                    prop_assert!((fd - a[(i, j)]).abs() < 1e-6 * scale, "A[{},{}] = {} against {}", i, j, a[(i, j)], fd);
                }
            }
        }
    }
}
