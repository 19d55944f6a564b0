//! Classical baseline: speed-sensorless indirect field-oriented control (IFOC) with a Schauder
//! MRAS speed estimate, PI speed loop and PI current loops in the rotor-flux frame.
//!
//! Tuning follows stated textbook rules (e.g. Harnefors, *Control of Variable-Speed Drives*;
//! Leonhard, *Control of Electrical Drives*):
//! - current loops by internal-model control: the plant seen by i_d, i_q is 1/(σs + R') with
//!   R' = R_s + (M/L_r)²R_r; Kp = α_c·σ, Ki = α_c·R' gives a first-order loop of bandwidth α_c,
//!   with the back-EMF and cross-coupling fed forward;
//! - speed loop: torque T = (3/2)n_p(M/L_r)ψ_r·i_q, plant K_t/(Js); Kp = α_ω·J/K_t and
//!   Ki = Kp·α_ω/4 (a PI zero a factor 4 below the crossover), with α_ω ≤ α_c/10;
//! - flux: i_d* = ψ_r*/M with ψ_r* = ψ_d^½; slip ω_sl = (R_r/L_r)·M·i_q*/ψ_r*; the angle integrates
//!   n_p·ω̂ + ω_sl;
//! - MRAS: both poles of its linearised loop at −α_m (see `observer::Mras`), with α_ω ≤ α_m/5 so
//!   the speed loop sees the estimate as fast.
//!
//! - torque feedforward (`ifoc.ff`, off by default): i_q* gains (J·ω̇_d + T0 + C_f·ω_d)/K_t, the
//!   torque the reference needs with the model's friction, as the backstepping's v1 feeds ω̇_d
//!   forward. The speed PI then only corrects what the model does not predict.
//!
//! Defaults: α_c/2π = 1 kHz (1/20 of the sampling rate), α_m/2π = 50 Hz, α_ω/2π = 10 Hz. Faster
//! MRAS and speed loops oscillate here: the high-pass that keeps the voltage model from drifting
//! (corner 10 rad/s) slows the estimator's low-frequency response.

use crate::control::RefSample;
use crate::observer::Mras;
use crate::params::MotorParams;
use serde::{Deserialize, Serialize};

/// Bandwidths of the IFOC loops and its current limit.
#[derive(Clone, Copy, Debug, PartialEq, Serialize, Deserialize)]
pub struct IfocTuning {
    /// Current-loop bandwidth α_c/2π (Hz).
    pub current_bw: f64,
    /// Speed-loop bandwidth α_ω/2π (Hz).
    pub speed_bw: f64,
    /// MRAS bandwidth α_m/2π (Hz).
    pub mras_bw: f64,
    /// Limit on the q-axis current command (A).
    pub current_limit: f64,
    /// Torque feedforward: the q-current for J·ω̇_d + T0 + Cf·ω_d added to the speed PI's.
    pub ff: bool,
}

/// IFOC controller state.
#[derive(Clone, Debug)]
pub struct Ifoc {
    ts: f64,
    sigma: f64,
    lr: f64,
    m: f64,
    alpha: f64,
    np: f64,
    psi_ref: f64,
    kp_i: f64,
    ki_i: f64,
    kp_w: f64,
    ki_w: f64,
    i_max: f64,
    /// J, T0 and Cf over the torque constant, when the torque is fed forward.
    ff: Option<[f64; 3]>,
    mras: Mras,
    theta: f64,
    speed_integral: f64,
    current_integral: [f64; 2],
    speed_hat: f64,
}

const TWO_PI: f64 = 2.0 * std::f64::consts::PI;

impl Ifoc {
    /// A controller for the motor `model` (what the drive assumes) at sample time `ts`, with flux
    /// target ψ_d, started from speed `speed0`, flux `flux0` and measured current `i0`.
    pub fn new(
        model: &MotorParams,
        tuning: &IfocTuning,
        ts: f64,
        psi_d: f64,
        speed0: f64,
        flux0: [f64; 2],
        i0: [f64; 2],
    ) -> Ifoc {
        let lumped = model.lumped().expect("validated model");
        let sigma = model.sigma();
        let r_transient = model.rs + (model.m / model.lr) * (model.m / model.lr) * model.rr;
        let alpha_c = TWO_PI * tuning.current_bw;
        let alpha_w = TWO_PI * tuning.speed_bw;
        let psi_ref = psi_d.sqrt();
        let torque_constant = 1.5 * model.np * model.m / model.lr * psi_ref;
        let kp_w = alpha_w * model.j / torque_constant;
        let lr_over_m = model.lr / model.m;
        Ifoc {
            ts,
            sigma,
            lr: model.lr,
            m: model.m,
            alpha: model.rr / model.lr,
            np: model.np,
            psi_ref,
            kp_i: alpha_c * sigma,
            ki_i: alpha_c * r_transient,
            kp_w,
            ki_w: kp_w * alpha_w / 4.0,
            i_max: tuning.current_limit,
            ff: tuning
                .ff
                .then(|| [model.j, model.t0, model.cf].map(|v| v / torque_constant)),
            mras: Mras::new(
                lumped,
                model.rs,
                sigma,
                lr_over_m,
                ts,
                TWO_PI * tuning.mras_bw,
                psi_d,
                speed0,
                flux0,
                i0,
            ),
            theta: libm::atan2(flux0[1], flux0[0]),
            speed_integral: 0.0,
            current_integral: [0.0; 2],
            speed_hat: speed0,
        }
    }

    /// The voltage command for measured currents `i`, the voltage `u_prev` applied over the last
    /// sample and the speed reference. `limit` is the per-component voltage limit, used for
    /// anti-windup.
    pub fn control(
        &mut self,
        i: &[f64; 2],
        u_prev: &[f64; 2],
        speed_ref: &RefSample,
        limit: f64,
    ) -> [f64; 2] {
        self.speed_hat = self.mras.update(i, u_prev);
        // Speed PI with the integrator frozen while the current command is limited.
        let e_w = speed_ref.value - self.speed_hat;
        let mut iq_free = self.kp_w * e_w + self.ki_w * self.speed_integral;
        // The q-current for the torque J·ω̇_d + T0 + Cf·ω_d that the reference itself needs.
        if let Some([j, t0, cf]) = self.ff {
            iq_free += j * speed_ref.d1 + t0 + cf * speed_ref.value;
        }
        let iq_ref = iq_free.clamp(-self.i_max, self.i_max);
        if iq_free == iq_ref {
            self.speed_integral += self.ts * e_w;
        }
        let id_ref = self.psi_ref / self.m;
        let slip = self.alpha * self.m * iq_ref / self.psi_ref;
        let w_e = self.np * self.speed_hat + slip;
        let (s, c) = libm::sincos(self.theta);
        let id = c * i[0] + s * i[1];
        let iq = -s * i[0] + c * i[1];
        // Current PI in the rotor-flux frame with decoupling and back-EMF feedforward.
        let e = [id_ref - id, iq_ref - iq];
        let ff = [
            -w_e * self.sigma * iq,
            w_e * self.sigma * id + w_e * self.m / self.lr * self.psi_ref,
        ];
        let mut u_dq = [0.0; 2];
        for k in 0..2 {
            let free = self.kp_i * e[k] + self.ki_i * self.current_integral[k] + ff[k];
            u_dq[k] = free;
            // Anti-windup: integrate only while the voltage stays inside the limit. It acts per
            // dq component against the per-component limit, not on the voltage vector against the
            // drive's limit shape (circle or hexagon): a simplification of the baseline, listed
            // with the departures from textbook practice in docs/model-and-paper.md.
            if free.abs() < limit {
                self.current_integral[k] += self.ts * e[k];
            }
        }
        self.theta += self.ts * w_e;
        [c * u_dq[0] - s * u_dq[1], s * u_dq[0] + c * u_dq[1]]
    }

    /// The MRAS speed estimate used by the speed loop (rad/s).
    pub fn speed_estimate(&self) -> f64 {
        self.speed_hat
    }
}
