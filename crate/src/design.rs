//! The design a motor gets from its data (`design=derived`): the flux target, the voltage limit,
//! the base speed where the field weakens, the start state, the gains k1–k4 and the EKF's
//! covariances, each by a rule stated with its reason. The presets keep the design the paper
//! states (`design=paper`); docs/model-and-paper.md gives the rule in words.

use crate::params::MotorParams;
use crate::text::Message;
use std::f64::consts::PI;

/// What the rule starts from: the model's motor, its rating and the sampling.
#[derive(Clone, Copy, Debug)]
pub struct Inputs {
    /// The motor the controller and observer assume.
    pub model: MotorParams,
    /// Amplitude of the rated phase current (A).
    pub i_rated: f64,
    /// Rated line-to-line voltage (V rms).
    pub voltage: f64,
    /// Rated frequency (Hz).
    pub frequency: f64,
    /// Sampling period (s).
    pub ts: f64,
    /// Standard deviation of the current sensor's noise (A).
    pub noise: f64,
}

/// The derived design, and the quantities it is derived through.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Derived {
    /// Amplitude of the rated phase voltage, V·√2/√3 (V): the radius of the voltage limit.
    pub v_phase: f64,
    /// DC-link voltage of the circle limit, √2·V (the rectified line voltage) (V).
    pub vdc: f64,
    /// Rotor flux amplitude at rated voltage and frequency with no load (Wb), capped so that the
    /// magnetising current leaves half the rated current's square for torque.
    pub flux: f64,
    /// ψ_d = flux² (Wb²).
    pub psi_d: f64,
    /// Magnetising current flux/M (A).
    pub i_d: f64,
    /// Torque current at rated current, √(i_rated² − i_d²) (A).
    pub i_q: f64,
    /// Torque at rated current and flux, (3/2)·n_p·(M/L_r)·flux·i_q (N m).
    pub torque: f64,
    /// Rated acceleration, torque/J (rad/s²).
    pub accel: f64,
    /// Leakage inductance σ = L_s − M²/L_r (H).
    pub sigma: f64,
    /// Base speed (mechanical, rad/s): the speed up to which rated flux and rated torque current
    /// need at most [`VOLTAGE_SHARE`] of the voltage limit in steady state.
    pub base: f64,
    /// The gains k1–k4 (1/s).
    pub gains: [f64; 4],
    /// Which bound set the gains: the sampling rate (`false`) or the voltage (`true`).
    pub gains_by_voltage: bool,
    /// EKF process noise q (state unit²/s) and its speed addition q_speed ((rad/s)²/s).
    pub q: f64,
    /// Added process noise of the speed ((rad/s)²/s).
    pub q_speed: f64,
    /// Standard deviation of the measurement noise assumed (A).
    pub r_std: f64,
    /// Random-walk intensity of the load torque ((N m)²/s).
    pub q_load: f64,
    /// Initial standard deviation of the load torque (N m).
    pub load_std: f64,
}

/// Share of the voltage limit that steady operation may use at base speed: the rest is the
/// headroom the current loops need to move the current.
pub const VOLTAGE_SHARE: f64 = 0.9;
/// k·Ts at most: each loop's error may fall by at most 6 % a sample, the paper's own 1200/s at
/// 20 kHz, so the discrete loop stays close to the continuous design.
pub const K_TS: f64 = 0.06;
/// Share of the voltage limit a rated-current error may ask for: the voltage σ·k·i_rated the
/// torque loop applies to close an error of the rated current at rate k.
pub const VOLTAGE_FOR_GAIN: f64 = 0.25;
/// Ratio of the speed loop's rate k1 to the current loops' rate.
pub const SPEED_RATIO: f64 = 0.25;
/// EKF process noise q ((state unit)²/s). The model is the motor's own equations with its own
/// values and the RK4 predictor integrates them as the plant does, so nothing is left for Q to
/// cover: q is a floor that keeps P, and so the gain, from vanishing. With the paper's 1e-3,
/// Q·Ts inflates the innovation covariance of these motors and their mean NIS falls to 1.4–1.9,
/// below its band, which is the measurement that set 1e-9 (docs/model-and-paper.md).
pub const EKF_Q: f64 = 1e-9;
/// Time (s) in which the load torque's random walk moves by the rated torque: q_load =
/// torque²/LOAD_TIME.
pub const LOAD_TIME: f64 = 0.1;
/// Largest current during a transient, as a multiple of the rated current, that a drive rated
/// for the motor carries: the 150 % for a minute of IEC 61800-2's heavy duty.
pub const OVERLOAD: f64 = 1.5;

/// Why no design follows from the data.
#[derive(Clone, Debug, PartialEq)]
pub enum DesignError {
    /// The rated voltage cannot hold rated flux and rated torque current even at rest.
    NoVoltage {
        /// Voltage needed at rest (V).
        needed: f64,
        /// Voltage the limit leaves for steady operation (V).
        available: f64,
    },
}

impl DesignError {
    /// What it says, as a message of `core-scenario.ftl`.
    pub fn message(&self) -> Message {
        match self {
            DesignError::NoVoltage { needed, available } => Message::new("design-no-voltage")
                .fixed("needed", *needed, 1)
                .fixed("available", *available, 1),
        }
    }
}

/// The design the rule gives for `inputs`.
pub fn derive(inputs: &Inputs) -> Result<Derived, DesignError> {
    let p = &inputs.model;
    let v_phase = inputs.voltage * 2f64.sqrt() / 3f64.sqrt();
    let vdc = inputs.voltage * 2f64.sqrt();
    let we = 2.0 * PI * inputs.frequency;
    // No load: the rotor branch carries nothing, the stator current is V/|R_s + jω L_s| and the
    // rotor flux M times it.
    let no_load = p.m * v_phase / (p.rs * p.rs + we * we * p.ls * p.ls).sqrt();
    let flux = no_load.min(p.m * inputs.i_rated / 2f64.sqrt());
    let i_d = flux / p.m;
    let i_q = (inputs.i_rated * inputs.i_rated - i_d * i_d).sqrt();
    let torque = 1.5 * p.np * p.m / p.lr * flux * i_q;
    let sigma = p.sigma();
    // Steady state in the flux frame: v_d = R_s i_d − ω_e σ i_q, v_q = R_s i_q + ω_e L_s i_d,
    // with ω_e = n_p ω + (R_r/L_r)·M i_q/flux. |v| = share·V at base speed.
    let available = VOLTAGE_SHARE * v_phase;
    let a = sigma * sigma * i_q * i_q + p.ls * p.ls * i_d * i_d;
    let b = 2.0 * p.rs * i_d * i_q * (p.ls - sigma);
    let c = p.rs * p.rs * (i_d * i_d + i_q * i_q) - available * available;
    let slip = p.rr / p.lr * p.m * i_q / flux;
    let we_base = (-b + (b * b - 4.0 * a * c).sqrt()) / (2.0 * a);
    let base = (we_base - slip) / p.np;
    if !(c < 0.0 && base > 0.0) {
        // At rest the stator frequency is the slip's.
        let (vd, vq) = (
            p.rs * i_d - slip * sigma * i_q,
            p.rs * i_q + slip * p.ls * i_d,
        );
        return Err(DesignError::NoVoltage {
            needed: vd.hypot(vq),
            available,
        });
    }
    let by_ts = K_TS / inputs.ts;
    let by_voltage = VOLTAGE_FOR_GAIN * v_phase / (sigma * inputs.i_rated);
    let k = by_ts.min(by_voltage);
    let gains = [SPEED_RATIO * k, k, k, k];
    let r_std = if inputs.noise > 0.0 {
        inputs.noise
    } else {
        1e-3 * inputs.i_rated
    };
    Ok(Derived {
        v_phase,
        vdc,
        flux,
        psi_d: flux * flux,
        i_d,
        i_q,
        torque,
        accel: torque / p.j,
        sigma,
        base,
        gains,
        gains_by_voltage: by_voltage < by_ts,
        q: EKF_Q,
        q_speed: 0.0,
        r_std,
        q_load: torque * torque / LOAD_TIME,
        load_std: torque / 4.0,
    })
}

/// One value of the derived design, for `imlab design` and the page.
#[cfg_attr(
    target_arch = "wasm32",
    derive(tsify::Tsify),
    tsify(missing_as_null, hashmap_as_object)
)]
#[derive(Clone, Debug, serde::Serialize)]
pub struct Line {
    /// The scenario field it sets, or the quantity's name when it sets none.
    pub key: &'static str,
    /// Its value.
    pub value: f64,
    /// Its unit.
    pub unit: &'static str,
    /// The rule that gives it, with its reason (`design-rule-*` of `core-analysis.ftl`).
    pub rule: Message,
}

impl Derived {
    /// Each value with the rule behind it, in the order the rule derives them.
    pub fn lines(&self, inputs: &Inputs) -> Vec<Line> {
        let line = |key, value, unit, rule| Line {
            key,
            value,
            unit,
            rule,
        };
        let uncapped = self.flux < inputs.model.m * inputs.i_rated / 2f64.sqrt() * (1.0 - 1e-12);
        vec![
            line(
                "vdc",
                self.vdc,
                "V",
                Message::new("design-rule-vdc").real("voltage", inputs.voltage),
            ),
            line(
                "flux",
                self.flux,
                "Wb",
                Message::new(if uncapped {
                    "design-rule-flux"
                } else {
                    "design-rule-flux-capped"
                })
                .real("voltage", inputs.voltage)
                .real("frequency", inputs.frequency),
            ),
            line("psi_d", self.psi_d, "Wb²", Message::new("design-rule-psi")),
            line("i_d", self.i_d, "A", Message::new("design-rule-id")),
            line(
                "i_q",
                self.i_q,
                "A",
                Message::new("design-rule-iq").fixed("i_rated", inputs.i_rated, 3),
            ),
            line(
                "torque",
                self.torque,
                "N m",
                Message::new("design-rule-torque"),
            ),
            line(
                "accel",
                self.accel,
                "rad/s²",
                Message::new("design-rule-accel"),
            ),
            line(
                "fw.base",
                self.base,
                "rad/s",
                Message::new("design-rule-base").count("share", (VOLTAGE_SHARE * 100.0) as i64),
            ),
            line(
                "k2",
                self.gains[1],
                "1/s",
                Message::new(if self.gains_by_voltage {
                    "design-rule-gain-voltage"
                } else {
                    "design-rule-gain-ts"
                })
                .real("kts", K_TS)
                .count("share", (VOLTAGE_FOR_GAIN * 100.0) as i64)
                .fixed("sigma", self.sigma, 4),
            ),
            line(
                "k1",
                self.gains[0],
                "1/s",
                Message::new("design-rule-k1").real("ratio", SPEED_RATIO),
            ),
            line(
                "ekf.q",
                self.q,
                "(state unit)²/s",
                Message::new("design-rule-q"),
            ),
            line(
                "ekf.r_std",
                self.r_std,
                "A",
                Message::new(if inputs.noise > 0.0 {
                    "design-rule-r"
                } else {
                    "design-rule-r-none"
                }),
            ),
            line(
                "ekf.q_load",
                self.q_load,
                "N² m²/s",
                Message::new("design-rule-q-load").real("time", LOAD_TIME),
            ),
            line(
                "ekf.load_std",
                self.load_std,
                "N m",
                Message::new("design-rule-load-std"),
            ),
        ]
    }
}

/// `v` to three significant digits, as a link writes it.
fn three(v: f64) -> f64 {
    let scale = 10f64.powi(2 - v.abs().log10().floor() as i32);
    (v * scale).round() / scale
}

/// The runs that check a derived design, each scenario `s` (which has `design=derived`) with
/// its reference and load set: the preset's step; a ramp to 1.5× base speed at half the rated
/// acceleration (the torque at rated current falls as base/ω above base speed), through field
/// weakening; a reversal from base speed through zero to −base at the rated acceleration; and a
/// step of the rated torque, less the scenario's own load T_0 + C_f·ω at 50 rad/s, at 50 rad/s
/// with the load an EKF state. Values are written to three significant digits; each link is the
/// codec's.
pub fn checks(
    s: &crate::scenario::Scenario,
    d: &Derived,
) -> Result<[(&'static str, String); 4], crate::scenario::ScenarioError> {
    let (base_speed, accel) = (three(d.base), three(d.accel));
    let level = three(1.5 * d.base);
    let slope = three(0.5 * d.accel);
    let start = 0.05;
    // Each run lasts to 0.3 s past its reference's last change, in tenths of a second.
    let tenths = |end: f64| (((end + 0.3) * 10.0).ceil() / 10.0).to_string();
    let own_load = s.plant.t0 + s.plant.cf * 50.0;
    let with = |fields: &[(&str, String)]| {
        let mut run = s.clone();
        for (key, value) in fields {
            run.set(key, value)?;
        }
        Ok::<_, crate::scenario::ScenarioError>(run.encode())
    };
    let n = |v: f64| v.to_string();
    Ok([
        ("step", s.encode()),
        (
            "ramp",
            with(&[
                ("ref", "ramp".into()),
                ("ramp.start", n(start)),
                ("ramp.level", n(level)),
                ("ramp.slope", n(slope)),
                ("ramp.hold", n(0.3)),
                ("duration", tenths(start + 2.0 * level / slope + 0.3)),
            ])?,
        ),
        (
            "reversal",
            with(&[
                ("ref", "reversal".into()),
                ("rev.start", n(start)),
                ("rev.level", n(base_speed)),
                ("rev.slope", n(accel)),
                ("rev.hold", n(0.2)),
                ("duration", tenths(start + 3.0 * base_speed / accel + 0.2)),
            ])?,
        ),
        (
            "load",
            with(&[
                ("ref", "constant".into()),
                ("ref.value", n(50.0)),
                ("load.time", n(0.3)),
                ("load.torque", n(three(d.torque - own_load))),
                ("ekf.load", n(1.0)),
                ("duration", n(0.6)),
            ])?,
        ),
    ])
}
