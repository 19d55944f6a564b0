//! The inverter between the controller and the motor: the set of voltages it can apply (a
//! per-component box, the circle of linear modulation or the hexagon of a two-level inverter)
//! and, optionally, its switching: symmetric carrier-based PWM at the sampling rate.
//!
//! Voltages are in the stationary a–b frame of model (2), amplitude-invariant: a phase voltage of
//! peak V gives |u| = V. A two-level inverter on a DC link v_dc reaches the hexagon with vertices
//! at 2v_dc/3; the circle inscribed in it, |u| ≤ v_dc/√3, is its linear range. Only correctly
//! rounded operations are used (no `hypot`), so native and WASM runs stay bit-identical.

use crate::model::{self, Input, State};
use crate::params::Lumped;
use serde::{Deserialize, Serialize};

/// Shape of the set of voltages the inverter can apply.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Serialize, Deserialize)]
pub enum Shape {
    /// |u_a|, |u_b| ≤ vmax each: the paper's limit (its corners need a DC link of 2.37·vmax, 946 V for 400 V).
    Box,
    /// |u| ≤ v_dc/√3: the linear range of sine-triangle PWM with third-harmonic injection.
    Circle,
    /// The two-level inverter's hexagon: every phase-to-phase voltage within ±v_dc.
    Hex,
}

/// The inverter's voltage limit.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Limit {
    /// Its shape.
    pub shape: Shape,
    /// Per-component limit of the box (V).
    pub vmax: f64,
    /// DC-link voltage of the circle and the hexagon (V).
    pub vdc: f64,
}

const SQRT3: f64 = 1.732_050_807_568_877_2;

/// Phase voltages (v_a, v_b, v_c) of the a–b vector `u` (inverse amplitude-invariant Clarke).
fn phases(u: &Input) -> [f64; 3] {
    [
        u[0],
        -0.5 * u[0] + 0.5 * SQRT3 * u[1],
        -0.5 * u[0] - 0.5 * SQRT3 * u[1],
    ]
}

impl Limit {
    /// How far `u` reaches toward the circle's or the hexagon's boundary: 1 on it, above 1 outside
    /// (the factor `limit` scales `u` down by).
    fn reach(&self, u: &Input) -> f64 {
        match self.shape {
            Shape::Box => u[0].abs().max(u[1].abs()) / self.vmax,
            Shape::Circle => (u[0] * u[0] + u[1] * u[1]).sqrt() * SQRT3 / self.vdc,
            Shape::Hex => {
                let v = phases(u);
                (v[0].max(v[1]).max(v[2]) - v[0].min(v[1]).min(v[2])) / self.vdc
            }
        }
    }

    /// Whether the commanded `u` lies beyond the limit.
    pub fn exceeds(&self, u: &Input) -> bool {
        match self.shape {
            Shape::Box => u[0].abs() > self.vmax || u[1].abs() > self.vmax,
            _ => self.reach(u) > 1.0,
        }
    }

    /// The voltage the inverter applies for the command `u`. The box clamps each component (which
    /// turns the vector toward a corner); the circle and the hexagon scale `u` toward the origin
    /// onto their boundary, which keeps its direction.
    #[inline]
    pub fn apply(&self, u: &Input) -> Input {
        match self.shape {
            Shape::Box => u.map(|v| v.clamp(-self.vmax, self.vmax)),
            _ => {
                let reach = self.reach(u);
                if reach > 1.0 {
                    u.map(|v| v / reach)
                } else {
                    *u
                }
            }
        }
    }

    /// The largest value one voltage component can take (V), for the plots' limit lines: vmax for
    /// the box, v_dc/√3 for the circle, and the hexagon's vertex 2v_dc/3 (reached along the a
    /// axis only; elsewhere the hexagon is tighter).
    pub fn component_max(&self) -> f64 {
        match self.shape {
            Shape::Box => self.vmax,
            Shape::Circle => self.vdc / SQRT3,
            Shape::Hex => 2.0 * self.vdc / 3.0,
        }
    }

    /// The largest voltage magnitude the limit allows in every direction (V): the half-width of
    /// the box, or the radius of the circle (the hexagon's inscribed circle).
    pub fn radius(&self) -> f64 {
        match self.shape {
            Shape::Box => self.vmax,
            _ => self.vdc / SQRT3,
        }
    }
}

/// Duty cycles d_a, d_b, d_c in [0, 1] that make the average voltage `u` on a DC link `vdc`:
/// d = ½ + (v_phase + v_0)/v_dc with the min–max zero sequence v_0 = −(max + min)/2, which
/// centres the phase voltages and reaches the whole hexagon (equivalent to space-vector PWM).
pub fn duties(u: &Input, vdc: f64) -> [f64; 3] {
    let v = phases(u);
    let v0 = -0.5 * (v[0].max(v[1]).max(v[2]) + v[0].min(v[1]).min(v[2]));
    v.map(|p| (0.5 + (p + v0) / vdc).clamp(0.0, 1.0))
}

/// The a–b voltage of the leg states `on` (true: the leg is at +v_dc, false: at 0).
fn vector(on: [bool; 3], vdc: f64) -> Input {
    let s = on.map(|o| if o { vdc } else { 0.0 });
    [(2.0 * s[0] - s[1] - s[2]) / 3.0, (s[1] - s[2]) / SQRT3]
}

/// The switching pattern of one period of symmetric (centre-aligned) PWM for the duties `d`: up
/// to seven intervals of constant voltage, as (length, voltage). Each leg is on for d·ts in the
/// middle of the period, so the period starts and ends in the zero vector, where a drive samples
/// its currents (the carrier's peak), and the pattern is symmetric about ts/2.
pub fn pattern(d: &[f64; 3], vdc: f64, ts: f64) -> [(f64, Input); 7] {
    // Legs in the order they switch on: the largest duty first.
    let mut order = [0usize, 1, 2];
    order.sort_by(|&i, &j| d[j].total_cmp(&d[i]));
    let on_at = order.map(|i| 0.5 * ts * (1.0 - d[i]));
    let mut on = [false; 3];
    let mut out = [(0.0, [0.0; 2]); 7];
    let mut t = 0.0;
    // Rising half: before each leg switches on.
    for (n, &i) in order.iter().enumerate() {
        out[n] = (on_at[n] - t, vector(on, vdc));
        on[i] = true;
        t = on_at[n];
    }
    // The middle, all three switched legs on, until the shortest duty's leg turns off at ts − t.
    out[3] = (ts - 2.0 * t, vector(on, vdc));
    // Falling half: the mirror image.
    for n in 0..3 {
        on[order[2 - n]] = false;
        out[4 + n] = (out[2 - n].0, vector(on, vdc));
    }
    out
}

/// The plant over one PWM period of length `ts` whose average voltage is `u`: integrated with
/// `substeps` RK4 steps on each interval between the switching instants (no step straddles a
/// switch). Returns the state at the end of the period and the current ripple: the largest
/// distance of the current vector at a switching instant from the straight line between its
/// values at the period's ends (A).
pub fn advance(
    p: &Lumped,
    x: &State,
    u: &Input,
    vdc: f64,
    extra_load: f64,
    ts: f64,
    substeps: u32,
) -> (State, f64) {
    let intervals = pattern(&duties(u, vdc), vdc, ts);
    let mut at = [(0.0, [0.0; 2]); 8];
    let (mut x, mut t) = (*x, 0.0);
    at[0] = (0.0, [x[1], x[2]]);
    for (n, (length, v)) in intervals.iter().enumerate() {
        if *length > 0.0 {
            x = model::advance(p, &x, v, extra_load, *length, substeps);
        }
        t += length;
        at[n + 1] = (t, [x[1], x[2]]);
    }
    let (i0, i1) = (at[0].1, at[7].1);
    let ripple = at.iter().fold(0.0_f64, |worst, (t, i)| {
        let s = t / ts;
        let line = [i0[0] + s * (i1[0] - i0[0]), i0[1] + s * (i1[1] - i0[1])];
        let d = [i[0] - line[0], i[1] - line[1]];
        worst.max((d[0] * d[0] + d[1] * d[1]).sqrt())
    });
    (x, ripple)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_largest_component_is_what_the_limit_applies_to_a_large_a_axis_command() {
        for shape in [Shape::Box, Shape::Circle, Shape::Hex] {
            let limit = Limit {
                shape,
                vmax: 400.0,
                vdc: 540.0,
            };
            let applied = limit.apply(&[1e6, 0.0]);
            assert!(
                (applied[0] - limit.component_max()).abs() < 1e-9,
                "{shape:?}: {applied:?}"
            );
            // No direction gives a component beyond it.
            for k in 0..360 {
                let a = f64::from(k).to_radians();
                let u = limit.apply(&[1e6 * libm::cos(a), 1e6 * libm::sin(a)]);
                assert!(
                    u[0].abs().max(u[1].abs()) <= limit.component_max() + 1e-9,
                    "{shape:?} at {k}°"
                );
            }
        }
    }
    use crate::params::MotorParams;
    use crate::rng::Rng;

    fn random_u(rng: &mut Rng, scale: f64) -> Input {
        [
            scale * (2.0 * rng.uniform() - 1.0),
            scale * (2.0 * rng.uniform() - 1.0),
        ]
    }

    #[test]
    fn limits_keep_inside_and_keep_direction() {
        let mut rng = Rng::new(3);
        let vdc = 540.0;
        for shape in [Shape::Circle, Shape::Hex] {
            let limit = Limit {
                shape,
                vmax: 400.0,
                vdc,
            };
            for _ in 0..10_000 {
                let u = random_u(&mut rng, 800.0);
                let a = limit.apply(&u);
                // Inside, up to rounding.
                assert!(limit.reach(&a) <= 1.0 + 1e-15, "{shape:?} {u:?} → {a:?}");
                match shape {
                    Shape::Circle => assert!(a[0].hypot(a[1]) <= vdc / SQRT3 * (1.0 + 1e-15)),
                    _ => {
                        let v = phases(&a);
                        for i in 0..3 {
                            for j in 0..3 {
                                assert!(v[i] - v[j] <= vdc * (1.0 + 1e-15));
                            }
                        }
                    }
                }
                // Same direction: parallel and not reversed; unchanged when inside.
                assert!((a[0] * u[1] - a[1] * u[0]).abs() <= 1e-9 * u[0].hypot(u[1]).powi(2));
                assert!(a[0] * u[0] + a[1] * u[1] > 0.0);
                if !limit.exceeds(&u) {
                    assert_eq!(a, u);
                } else {
                    assert!((limit.reach(&a) - 1.0).abs() < 1e-12);
                }
            }
        }
        // The hexagon's vertices sit at 2v_dc/3 on the phase axes, its sides at v_dc/√3.
        let hex = Limit {
            shape: Shape::Hex,
            vmax: 0.0,
            vdc,
        };
        assert!((hex.reach(&[2.0 * vdc / 3.0, 0.0]) - 1.0).abs() < 1e-15);
        assert!((hex.reach(&[0.0, vdc / SQRT3]) - 1.0).abs() < 1e-15);
        // The box clamps per component, as before.
        let bx = Limit {
            shape: Shape::Box,
            vmax: 400.0,
            vdc,
        };
        assert_eq!(bx.apply(&[500.0, -100.0]), [400.0, -100.0]);
    }

    #[test]
    fn pattern_averages_to_the_command_and_is_symmetric() {
        let mut rng = Rng::new(5);
        let (vdc, ts) = (540.0, 50e-6);
        let hex = Limit {
            shape: Shape::Hex,
            vmax: 0.0,
            vdc,
        };
        for _ in 0..10_000 {
            let u = hex.apply(&random_u(&mut rng, 400.0));
            let p = pattern(&duties(&u, vdc), vdc, ts);
            let total: f64 = p.iter().map(|(l, _)| l).sum();
            assert!((total - ts).abs() < 1e-18, "{p:?}");
            assert!(p.iter().all(|(l, _)| *l >= 0.0));
            for c in 0..2 {
                let mean = p.iter().map(|(l, v)| l * v[c]).sum::<f64>() / ts;
                assert!((mean - u[c]).abs() < 1e-9 * vdc, "{u:?}: {mean}");
            }
            // Starts and ends in the zero vector; mirror-symmetric.
            assert_eq!(p[0].1, [0.0, 0.0]);
            for n in 0..3 {
                assert_eq!(p[n].0, p[6 - n].0);
                assert_eq!(p[n].1, p[6 - n].1);
            }
        }
    }

    /// Fine-step reference: `n` RK4 steps over the period, each with the exact average of the
    /// leg voltages over that step, read off the carrier comparison (leg on while the triangular
    /// carrier |1 − 2t/ts| is below its duty).
    fn brute_force(p: &Lumped, x: &State, u: &Input, vdc: f64, ts: f64, n: usize) -> State {
        let d = duties(u, vdc);
        let h = ts / n as f64;
        let mut x = *x;
        for k in 0..n {
            let (a, b) = (k as f64 * h, (k + 1) as f64 * h);
            // Share of [a, b] during which each leg is on: it is on over ts(1 ∓ d)/2.
            let share = d.map(|d| {
                let (on, off) = (0.5 * ts * (1.0 - d), 0.5 * ts * (1.0 + d));
                (b.min(off) - a.max(on)).max(0.0) / h
            });
            let s = share.map(|s| s * vdc);
            let v = [(2.0 * s[0] - s[1] - s[2]) / 3.0, (s[1] - s[2]) / SQRT3];
            x = model::rk4(p, &x, &v, 0.0, h);
        }
        x
    }

    #[test]
    fn switching_instant_integration_matches_a_fine_step_reference() {
        let p = MotorParams::PAPER.lumped().unwrap();
        let mut rng = Rng::new(11);
        let (vdc, ts) = (540.0, 50e-6);
        let hex = Limit {
            shape: Shape::Hex,
            vmax: 0.0,
            vdc,
        };
        for _ in 0..20 {
            let x = [
                300.0 * (rng.uniform() - 0.5),
                10.0 * (rng.uniform() - 0.5),
                10.0 * (rng.uniform() - 0.5),
                1.0 * (rng.uniform() - 0.5),
                1.0 * (rng.uniform() - 0.5),
            ];
            let u = hex.apply(&random_u(&mut rng, 400.0));
            let (exact, _) = advance(&p, &x, &u, vdc, 0.0, ts, 1);
            let reference = brute_force(&p, &x, &u, vdc, ts, 1000);
            // Relative to the change over the period (the part the integration computes).
            for i in 0..5 {
                let change = (reference[i] - x[i]).abs().max(1e-3);
                assert!(
                    (exact[i] - reference[i]).abs() < 1e-6 * change,
                    "x{} = {} vs {} (change {change})",
                    i + 1,
                    exact[i],
                    reference[i]
                );
            }
        }
    }

    #[test]
    fn sampled_currents_match_the_averaged_model_to_well_within_the_ripple() {
        let p = MotorParams::PAPER.lumped().unwrap();
        let mut rng = Rng::new(13);
        let (vdc, ts) = (540.0, 50e-6);
        let hex = Limit {
            shape: Shape::Hex,
            vmax: 0.0,
            vdc,
        };
        for _ in 0..200 {
            let x = [
                200.0 * (rng.uniform() - 0.5),
                8.0 * (rng.uniform() - 0.5),
                8.0 * (rng.uniform() - 0.5),
                1.0 * (rng.uniform() - 0.5),
                1.0 * (rng.uniform() - 0.5),
            ];
            let u = hex.apply(&random_u(&mut rng, 300.0));
            let (pwm, ripple) = advance(&p, &x, &u, vdc, 0.0, ts, 1);
            let averaged = model::advance(&p, &x, &u, 0.0, ts, 1);
            let gap = (pwm[1] - averaged[1]).hypot(pwm[2] - averaged[2]);
            // Symmetric PWM: the ripple's mean at the sampling instant is zero to first order;
            // what remains is second order in ts (resistive and speed coupling).
            assert!(
                gap < 0.02 * ripple.max(1e-3),
                "gap {gap} A, ripple {ripple} A"
            );
        }
    }
}
