//! The induction-motor model (2) in the stationary a–b frame: f(x, u), its Jacobian (11) and RK4.
//!
//! State x = [ω, i_sa, i_sb, φ_ra, φ_rb] (rad/s mechanical, A, A, Wb, Wb); input u = [u_sa, u_sb] (V).

use crate::params::Lumped;

/// Model state x = [x1..x5] = [ω, i_sa, i_sb, φ_ra, φ_rb].
pub type State = [f64; 5];
/// Stator voltage u = [u_sa, u_sb] (V).
pub type Input = [f64; 2];

/// Right-hand side f(x, u) = g(x) + B u of model (2); `extra_load` is an additional load torque
/// over J (rad/s²) that the model's T_L = T_0 + C_f ω does not contain.
#[inline]
pub fn f(p: &Lumped, x: &State, u: &Input, extra_load: f64) -> State {
    let [x1, x2, x3, x4, x5] = *x;
    [
        p.a1 * (x3 * x4 - x2 * x5) - p.a2 - p.a3 * x1 - extra_load,
        p.a5 * x4 + p.a6 * x1 * x5 - p.a7 * x2 + p.b * u[0],
        p.a5 * x5 - p.a6 * x1 * x4 - p.a7 * x3 + p.b * u[1],
        -p.a8 * x4 - p.a9 * x1 * x5 + p.a10 * x2,
        -p.a8 * x5 + p.a9 * x1 * x4 + p.a10 * x3,
    ]
}

/// Jacobian A = ∂f/∂x of eq (11), row-major.
#[inline]
pub fn jacobian(p: &Lumped, x: &State) -> [[f64; 5]; 5] {
    let [x1, x2, x3, x4, x5] = *x;
    [
        [-p.a3, -p.a1 * x5, p.a1 * x4, p.a1 * x3, -p.a1 * x2],
        [p.a6 * x5, -p.a7, 0.0, p.a5, p.a6 * x1],
        [-p.a6 * x4, 0.0, -p.a7, -p.a6 * x1, p.a5],
        [-p.a9 * x5, p.a10, 0.0, -p.a8, -p.a9 * x1],
        [p.a9 * x4, 0.0, p.a10, p.a9 * x1, -p.a8],
    ]
}

#[inline]
fn axpy(x: &State, h: f64, k: &State) -> State {
    [
        x[0] + h * k[0],
        x[1] + h * k[1],
        x[2] + h * k[2],
        x[3] + h * k[3],
        x[4] + h * k[4],
    ]
}

/// One classical RK4 step of length `h` with the input held constant.
// Always inlined: the 20 kHz loop calls it once a sample, and a call there costs the saving and
// reloading of the loop's live registers around it.
#[inline(always)]
pub fn rk4(p: &Lumped, x: &State, u: &Input, extra_load: f64, h: f64) -> State {
    let k1 = f(p, x, u, extra_load);
    let k2 = f(p, &axpy(x, 0.5 * h, &k1), u, extra_load);
    let k3 = f(p, &axpy(x, 0.5 * h, &k2), u, extra_load);
    let k4 = f(p, &axpy(x, h, &k3), u, extra_load);
    let mut out = *x;
    for i in 0..5 {
        out[i] += h / 6.0 * (k1[i] + 2.0 * k2[i] + 2.0 * k3[i] + k4[i]);
    }
    out
}

/// Integrates the plant over one sample `ts` with `substeps` RK4 steps (zero-order-hold input).
#[inline]
pub fn advance(p: &Lumped, x: &State, u: &Input, extra_load: f64, ts: f64, substeps: u32) -> State {
    let h = ts / f64::from(substeps);
    let mut x = *x;
    for _ in 0..substeps {
        x = rk4(p, &x, u, extra_load, h);
    }
    x
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::params::MotorParams;
    use crate::rng::Rng;

    /// Central differences with step 1e-6 on O(1) states leave ~1e-9 truncation and rounding error.
    const JACOBIAN_TOL: f64 = 1e-6;

    #[test]
    fn jacobian_matches_central_differences() {
        let p = MotorParams::PAPER.lumped().unwrap();
        let mut rng = Rng::new(7);
        for _ in 0..200 {
            let x: State = [
                200.0 * (rng.uniform() - 0.5),
                20.0 * (rng.uniform() - 0.5),
                20.0 * (rng.uniform() - 0.5),
                2.0 * (rng.uniform() - 0.5),
                2.0 * (rng.uniform() - 0.5),
            ];
            let u = [800.0 * (rng.uniform() - 0.5), 800.0 * (rng.uniform() - 0.5)];
            let a = jacobian(&p, &x);
            for j in 0..5 {
                let h = 1e-6 * (1.0 + x[j].abs());
                let mut xp = x;
                let mut xm = x;
                xp[j] += h;
                xm[j] -= h;
                let (fp, fm) = (f(&p, &xp, &u, 0.0), f(&p, &xm, &u, 0.0));
                for i in 0..5 {
                    let fd = (fp[i] - fm[i]) / (2.0 * h);
                    let scale = 1.0 + a[i][j].abs();
                    assert!(
                        (fd - a[i][j]).abs() < JACOBIAN_TOL * scale,
                        "A[{i}][{j}] = {} but finite difference gives {fd} at x = {x:?}",
                        a[i][j]
                    );
                }
            }
        }
    }

    #[test]
    fn rk4_is_fourth_order() {
        // Over a fixed interval, halving the substep must cut the error by about 2^4 = 16 (global error O(h^4)).
        let p = MotorParams::PAPER.lumped().unwrap();
        let x = [10.0, 2.0, -1.0, 0.5, 0.3];
        let u = [100.0, -50.0];
        let ts = 2e-4;
        let exact = advance(&p, &x, &u, 0.0, ts, 256);
        let e1 = (advance(&p, &x, &u, 0.0, ts, 1)[1] - exact[1]).abs();
        let e2 = (advance(&p, &x, &u, 0.0, ts, 2)[1] - exact[1]).abs();
        let ratio = e1 / e2;
        assert!((13.0..19.0).contains(&ratio), "error ratio {ratio}");
    }
}
