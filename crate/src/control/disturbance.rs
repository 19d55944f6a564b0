//! The unknown terms d̃2 of step 2 (33) and d̃4 of step 4 (47), evaluated from the simulated
//! truth: what the motor's actual ż2 and ż4 hold beyond the terms the controller knows. With an
//! exact model they are the paper's closed forms, linear in x̃1, x̃4, x̃5; a model that differs from
//! the motor, or an unknown load, adds its own terms, which the closed forms do not have.
//!
//! The evaluation is in continuous time at one sample, as the theorem is: the observer's rates
//! are (4) with the gain L held constant, the motor's are (2) with its own parameters, and the
//! currents are the motor's true ones (measurement noise lies outside the theorem).

use super::{Backstepping, ControlError, ControlInput, RefSample};
use crate::model::{self, Input, State};
use crate::params::Lumped;

/// One sample of a run, as the evaluation needs it.
pub struct Sample<'a> {
    /// The motor's parameters (the plant).
    pub plant: &'a Lumped,
    /// The true state x.
    pub x: State,
    /// The observer's posterior estimate x̂.
    pub x_hat: State,
    /// The voltage applied to the motor (V).
    pub u: Input,
    /// The observer gain L = K_k/Ts (1/s).
    pub l: [[f64; 2]; 5],
    /// An unknown load over the inertia (rad/s²), which the model lacks.
    pub extra_load: f64,
    /// The speed reference and its derivatives.
    pub speed_ref: RefSample,
    /// The flux target ψ_d (Wb²) and its time derivatives.
    pub psi_d: RefSample,
}

/// The rates of the observer (4): the model with the estimates, the measured currents `y` in the
/// torque term, and the injections si_i = l_i1·x̃2 + l_i2·x̃3.
fn observer_rate(p: &Lumped, x_hat: &State, y: [f64; 2], u: &Input, si: &[f64; 5]) -> State {
    let [x1h, x2h, x3h, x4h, x5h] = *x_hat;
    let [x2, x3] = y;
    [
        p.a1 * (x3 * x4h - x2 * x5h) - p.a2 - p.a3 * x1h + si[0],
        p.a5 * x4h + p.a6 * x1h * x5h - p.a7 * x2h + p.b * u[0] + si[1],
        p.a5 * x5h - p.a6 * x1h * x4h - p.a7 * x3h + p.b * u[1] + si[2],
        -p.a8 * x4h - p.a9 * x1h * x5h + p.a10 * x2h + si[3],
        -p.a8 * x5h + p.a9 * x1h * x4h + p.a10 * x3h + si[4],
    ]
}

/// [d̃2, d̃4] at `s` for `controller` (its model and gains): the actual ż2 and ż4, from the motor's
/// and the observer's rates, less v2 + ψ2 − (a7 + a8)·z2 and v4 + ψ4, with v2, v4 those of the
/// applied voltage and ψ2, ψ4 the controller's own. Errs where the controller does (no flux).
pub fn disturbances(controller: &Backstepping, s: &Sample) -> Result<[f64; 2], ControlError> {
    let p = controller.model();
    let g = controller.gains();
    let [x1h, _, _, x4h, x5h] = s.x_hat;
    let y = [s.x[1], s.x[2]];
    let residual = [y[0] - s.x_hat[1], y[1] - s.x_hat[2]];
    let terms = controller.control(&ControlInput {
        x_hat: s.x_hat,
        y,
        l: s.l,
        residual,
        speed_ref: s.speed_ref,
        psi_d: s.psi_d,
    })?;
    let [_, z2, z3, z4] = terms.z;
    let si: [f64; 5] = std::array::from_fn(|i| s.l[i][0] * residual[0] + s.l[i][1] * residual[1]);

    // The motor's rates, its own parameters and the unknown load; the observer's, (4).
    let dx = model::f(s.plant, &s.x, &s.u, s.extra_load);
    let dxh = observer_rate(p, &s.x_hat, y, &s.u, &si);
    // The residuals' actual rates, and the injections' (L held constant).
    let de = [dx[1] - dxh[1], dx[2] - dxh[2]];
    let dsi: [f64; 5] = std::array::from_fn(|i| s.l[i][0] * de[0] + s.l[i][1] * de[1]);

    // Step 2: z2 = a1(x3·x̂4 − x2·x̂5) − v1, v1 = −si1 + ω̇_d + a3·ω_d + â2 − k1s1·z1.
    let k1s1 = g.k1 - p.a3;
    let dz1 = dxh[0] - s.speed_ref.d1;
    let dv1 = -dsi[0] + s.speed_ref.d2 + p.a3 * s.speed_ref.d1 - k1s1 * dz1;
    let dz2 = p.a1 * (dx[2] * x4h + y[1] * dxh[3] - dx[1] * x5h - y[0] * dxh[4]) - dv1;
    let v2 = p.b * p.a1 * (x4h * s.u[1] - x5h * s.u[0]);
    let d2 = dz2 - (v2 + terms.psi2 - (p.a7 + p.a8) * z2);

    // Step 4: z4 = ż3 + k3·z3 with ż3 = 2(x̂4·x̂̇4 + x̂5·x̂̇5) − ψ̇_d, so ż4 = z̈3 + k3·ż3 (a
    // constant target subtracts 0.0, which leaves every bit).
    let dz3 = 2.0 * (x4h * dxh[3] + x5h * dxh[4]) - s.psi_d.d1;
    let ddx4h = -p.a8 * dxh[3] - p.a9 * (dxh[0] * x5h + x1h * dxh[4]) + p.a10 * dxh[1] + dsi[3];
    let ddx5h = -p.a8 * dxh[4] + p.a9 * (dxh[0] * x4h + x1h * dxh[3]) + p.a10 * dxh[2] + dsi[4];
    let ddz3 = 2.0 * (dxh[3] * dxh[3] + x4h * ddx4h + dxh[4] * dxh[4] + x5h * ddx5h) - s.psi_d.d2;
    let dz4 = ddz3 + g.k3 * dz3;
    let v4 = 2.0 * p.a10 * p.b * (x4h * s.u[0] + x5h * s.u[1]);
    let d4 = dz4 - (v4 + terms.psi4);
    debug_assert!((z4 - (dz3 + g.k3 * z3)).abs() <= 1e-6 * (1.0 + z4.abs()));
    Ok([d2, d4])
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::control::Gains;
    use crate::params::MotorParams;
    use crate::rng::Rng;

    /// The paper's closed forms (33) and (47) of d̃2 and d̃4, for an exact model.
    fn closed_forms(p: &Lumped, x: &State, x_hat: &State, l: &[[f64; 2]; 5]) -> [f64; 2] {
        let e: State = std::array::from_fn(|i| x[i] - x_hat[i]);
        let [x1, _, _, x4, x5] = *x;
        let [x1h, _, _, x4h, x5h] = *x_hat;
        let d2 = p.a1 * p.a5 * (e[4] * x4h - e[3] * x5h)
            - p.a1 * p.a6 * x1 * (e[3] * x4h + e[4] * x5h)
            - p.a1 * p.a6 * e[0] * (x4h * x4h + x5h * x5h)
            + (l[0][0] * p.a5 - l[0][1] * p.a6 * x1h) * e[3]
            + (l[0][1] * p.a5 + l[0][0] * p.a6 * x1h) * e[4]
            + (l[0][0] * p.a6 * x5 - l[0][1] * p.a6 * x4) * e[0];
        let d4 = (2.0 * p.a5 * l[3][0] * x4h - 2.0 * p.a6 * l[3][1] * x4h * x1h
            + 2.0 * p.a5 * l[4][0] * x5h
            - 2.0 * p.a6 * l[4][1] * x5h * x1h)
            * e[3]
            + (2.0 * l[3][0] * p.a6 * x1h * x4h
                + 2.0 * l[4][0] * p.a6 * x1h * x5h
                + 2.0 * l[3][1] * p.a5 * x4h
                + 2.0 * l[4][1] * p.a5 * x5h)
                * e[4]
            + 2.0 * (l[3][0] * x4h + l[4][0] * x5h) * p.a6 * e[0] * x5
            - 2.0 * (l[3][1] * x4h + l[4][1] * x5h) * p.a6 * e[0] * x4;
        [d2, d4]
    }

    fn gains() -> Gains {
        Gains {
            k1: 1200.0,
            k2: 1200.0,
            k3: 1200.0,
            k4: 1200.0,
            robust: false,
            eps2: 1.0,
            h2: 0.0,
            eps4: 1.0,
            h4: 0.0,
        }
    }

    /// A random state near an operating point, its estimate off by up to `err`, a gain, a
    /// voltage and a reference.
    struct Draw {
        x: State,
        x_hat: State,
        l: [[f64; 2]; 5],
        u: Input,
        r: RefSample,
    }

    fn random(rng: &mut Rng, err: f64) -> Draw {
        let mut u = |lo: f64, hi: f64| lo + (hi - lo) * (0.5 + 0.2 * rng.normal()).clamp(0.0, 1.0);
        let x = [
            u(-50.0, 50.0),
            u(-5.0, 5.0),
            u(-5.0, 5.0),
            u(-0.8, 0.8),
            u(-0.8, 0.8),
        ];
        let x_hat = x.map(|v| v * (1.0 + u(-err, err)) + u(-err, err) * 0.1);
        let l = std::array::from_fn(|_| [u(-3000.0, 3000.0), u(-3000.0, 3000.0)]);
        let input = [u(-300.0, 300.0), u(-300.0, 300.0)];
        let r = RefSample {
            value: u(-20.0, 20.0),
            d1: u(-100.0, 100.0),
            d2: u(-1000.0, 1000.0),
        };
        Draw {
            x,
            x_hat,
            l,
            u: input,
            r,
        }
    }

    /// [d̃2, d̃4] of the paper's controller (the paper's motor as its model) at `d`, for the motor
    /// `plant` under the unknown load `extra_load`.
    fn evaluate(plant: &Lumped, d: &Draw, extra_load: f64) -> [f64; 2] {
        let controller = Backstepping::new(MotorParams::PAPER.lumped().unwrap(), gains());
        let sample = Sample {
            plant,
            x: d.x,
            x_hat: d.x_hat,
            u: d.u,
            l: d.l,
            extra_load,
            speed_ref: d.r,
            psi_d: RefSample {
                value: 0.5,
                d1: 0.0,
                d2: 0.0,
            },
        };
        disturbances(&controller, &sample).unwrap()
    }

    /// With an exact model, the evaluation from the rates is the paper's closed forms: the
    /// derivation of ψ2, ψ4 and of (33), (47) holds term by term.
    #[test]
    fn exact_model_gives_the_closed_forms() {
        let p = MotorParams::PAPER.lumped().unwrap();
        let mut rng = Rng::new(7);
        for _ in 0..200 {
            let d = random(&mut rng, 0.1);
            let got = evaluate(&p, &d, 0.0);
            let want = closed_forms(&p, &d.x, &d.x_hat, &d.l);
            for i in 0..2 {
                let scale = 1.0 + want[i].abs();
                assert!(
                    (got[i] - want[i]).abs() <= 1e-9 * scale,
                    "d̃{}: {} against the closed form {}",
                    2 * i + 2,
                    got[i],
                    want[i]
                );
            }
        }
    }

    /// With a perfect estimate and an exact model nothing is unknown: both are zero.
    #[test]
    fn perfect_estimate_and_exact_model_give_zero() {
        let p = MotorParams::PAPER.lumped().unwrap();
        let [d2, d4] = evaluate(&p, &random(&mut Rng::new(3), 0.0), 0.0);
        assert!(d2.abs() < 1e-6 && d4.abs() < 1e-6, "{d2} {d4}");
    }

    /// An unknown load changes the motor's speed, not its currents nor the estimate: with a
    /// perfect estimate it enters neither at that instant; it reaches d̃2 and d̃4 later, through
    /// the speed error x̃1 it builds.
    #[test]
    fn an_unknown_load_enters_neither_with_a_perfect_estimate() {
        let p = MotorParams::PAPER.lumped().unwrap();
        let [d2, d4] = evaluate(&p, &random(&mut Rng::new(5), 0.0), 25.0);
        assert!(d2.abs() < 1e-6 && d4.abs() < 1e-6, "{d2} {d4}");
    }

    /// A motor whose R_r differs from the model's gives both a d̃ of its own, though the
    /// estimate is perfect: the closed forms, which assume an exact model, miss it.
    #[test]
    fn a_model_error_gives_a_disturbance_with_a_perfect_estimate() {
        let p = MotorParams::PAPER.lumped().unwrap();
        let plant = MotorParams {
            rr: 1.1 * MotorParams::PAPER.rr,
            ..MotorParams::PAPER
        }
        .lumped()
        .unwrap();
        let d = random(&mut Rng::new(11), 0.0);
        let [d2, d4] = evaluate(&plant, &d, 0.0);
        assert!(d2.abs() > 1.0 && d4.abs() > 1e-3, "{d2} {d4}");
        assert_eq!(closed_forms(&p, &d.x, &d.x, &d.l), [0.0, 0.0]);
    }
}
