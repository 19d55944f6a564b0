//! Model-reference adaptive speed estimator in the manner of Schauder (1992), the paper's [7].
//!
//! Reference model (voltage model, no speed): (M/L_r)·dφ/dt = u_s − R_s·i_s − σ·di_s/dt.
//! Adjustable model (current model, with ω̂): dφ/dt = −α·φ + n_p·ω̂·Jφ + αM·i_s.
//! ω̂ = PI(φ̂_i × φ̂_v). The pure integration of the voltage model drifts with any offset, so both
//! model fluxes pass through the same high-pass s/(s + ω_c): the comparison stays consistent at every
//! frequency and initial-condition offsets decay. Discretised by forward Euler at the sample rate.

use crate::params::Lumped;

/// Corner of the high-pass applied to both model fluxes (rad/s): far below the electrical
/// frequencies of interest, fast enough to forget initial offsets within about 0.5 s.
const HIGH_PASS: f64 = 10.0;

/// Schauder MRAS state and tuning.
#[derive(Clone, Debug)]
pub struct Mras {
    ts: f64,
    /// R_s, σ = L_s − M²/L_r, L_r/M of the model.
    rs: f64,
    sigma: f64,
    lr_over_m: f64,
    model: Lumped,
    kp: f64,
    ki: f64,
    /// ∫(u − R_s·i) dt with leakage ω_c (V s).
    lambda: [f64; 2],
    /// Low-pass of the current, for the high-pass of the σ·i term.
    current_lp: [f64; 2],
    /// Current-model flux (Wb).
    flux: [f64; 2],
    /// Low-pass of the current-model flux.
    flux_lp: [f64; 2],
    integral: f64,
    speed: f64,
}

impl Mras {
    /// An estimator for the model's parameters with closed-loop bandwidth `bandwidth` (rad/s) at
    /// flux modulus² `psi_d`, started at speed `speed0`, current-model flux `flux0` and measured
    /// current `i0` (both high-passed fluxes start at zero).
    pub fn new(
        model: Lumped,
        rs: f64,
        sigma: f64,
        lr_over_m: f64,
        ts: f64,
        bandwidth: f64,
        psi_d: f64,
        speed0: f64,
        flux0: [f64; 2],
        i0: [f64; 2],
    ) -> Mras {
        // Linearised: ε ≈ n_p·|φ|²/(s + α)·(ω − ω̂). With PI(s) the characteristic polynomial is
        // s² + (α + k·Kp)s + k·Ki with k = n_p·|φ|²; place both poles at −bandwidth (ζ = 1).
        let k = model.a9 * psi_d;
        let kp = ((2.0 * bandwidth - model.a8) / k).max(0.0);
        let ki = bandwidth * bandwidth / k;
        Mras {
            ts,
            rs,
            sigma,
            lr_over_m,
            model,
            kp,
            ki,
            lambda: [0.0; 2],
            current_lp: i0,
            flux: flux0,
            flux_lp: flux0,
            integral: speed0 / ki,
            speed: speed0,
        }
    }

    /// Advances one sample with the measured current `i` and the applied voltage `u`; returns ω̂.
    pub fn update(&mut self, i: &[f64; 2], u: &[f64; 2]) -> f64 {
        let (h, wc, m) = (self.ts, HIGH_PASS, &self.model);
        let mut hp_flux = [0.0; 2];
        let mut v_flux = [0.0; 2];
        let [fa, fb] = self.flux;
        let w = m.a9 * self.speed;
        let d_flux = [
            -m.a8 * fa - w * fb + m.a10 * i[0],
            -m.a8 * fb + w * fa + m.a10 * i[1],
        ];
        for c in 0..2 {
            self.lambda[c] += h * (self.lr_over_m * (u[c] - self.rs * i[c]) - wc * self.lambda[c]);
            self.current_lp[c] += h * wc * (i[c] - self.current_lp[c]);
            v_flux[c] = self.lambda[c] - self.lr_over_m * self.sigma * (i[c] - self.current_lp[c]);
            self.flux[c] += h * d_flux[c];
            self.flux_lp[c] += h * wc * (self.flux[c] - self.flux_lp[c]);
            hp_flux[c] = self.flux[c] - self.flux_lp[c];
        }
        // The current-model flux lags the voltage-model flux when ω̂ < ω: φ̂_i × φ̂_v > 0.
        let error = hp_flux[0] * v_flux[1] - hp_flux[1] * v_flux[0];
        self.integral += h * error;
        self.speed = self.kp * error + self.ki * self.integral;
        self.speed
    }
}
