//! One scenario type holding every setting, the presets, and the compact query-string codec
//! shared by the CLI, the browser URL and the tests.
//!
//! A scenario string is `v=1&preset=NAME` followed by only the fields that differ from the
//! preset, e.g. `v=1&preset=step&step.size=0.3&noise=0.004`. Numbers are written in Rust's
//! shortest round-trip form, so decode(encode(s)) == s bit for bit.

mod error;
mod fields;
mod load;
mod origin;
mod presets;
mod validate;

pub use error::ScenarioError;
pub use load::LoadStep;
pub use origin::{DesignKind, Start, DESIGN_SET};

pub(crate) use fields::parse_number;
pub use fields::{FieldInfo, MAX_DURATION, MAX_SEED};
pub use presets::{preset, Preset, I_RATED, PRESETS, RATED_F, RATED_V};
pub use validate::{MAX_LAW_WORK, MAX_STEPS, MAX_WORK};

use crate::control::{Gains, IfocTuning, Reference};
use crate::inverter::{Limit, Shape};
use crate::observer::EkfConfig;
use crate::params::MotorParams;
use fields::{field, fields, idle_because};
use presets::default_reference;
use serde::{Deserialize, Serialize};
use std::collections::HashMap;

/// Version of the query-string codec.
pub const CODEC_VERSION: u32 = 1;
/// Longest scenario string accepted (bytes): every field written out at full precision takes
/// about 2 KiB, so 16 KiB leaves room without letting a pasted megabyte block the parser.
pub const MAX_SCENARIO_BYTES: usize = 16 * 1024;
/// What a real drive adds between the controller and the motor, all off by default (the paper's
/// idealised loop: u_k applied at t_k, ±vmax per component, ideal averaged voltages).
#[derive(Clone, Copy, Debug, PartialEq, Serialize, Deserialize)]
pub struct Drive {
    /// Computation delay: u_k, computed from the sample at t_k, is applied over
    /// [t_{k+1}, t_{k+2}), as on a DSP drive that updates its PWM once per period.
    pub delay: bool,
    /// Delay compensation (with `delay` and the backstepping controller): the controller acts on
    /// the one-step prediction x̂_{k+1|k} made with the voltage already committed, and on the
    /// reference at t_{k+1}.
    pub delay_comp: bool,
    /// Shape of the voltage limit.
    pub vlimit: Shape,
    /// DC-link voltage of the `circle` and `hex` limits and of PWM (V).
    pub vdc: f64,
    /// Two-level inverter with symmetric carrier-based PWM at the sampling rate, in place of the
    /// ideal averaged voltage (needs the `circle` or `hex` limit).
    pub pwm: bool,
}

/// Which controller drives the motor.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Serialize, Deserialize)]
#[serde(rename_all = "lowercase")]
pub enum ControllerKind {
    /// The paper's four-step backstepping controller with the EKF.
    Backstepping,
    /// Classical baseline: sensorless IFOC with a Schauder MRAS speed estimate.
    Ifoc,
}

/// Every setting of one simulation run.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub struct Scenario {
    /// Name of the preset this scenario starts from.
    pub preset: String,
    /// The library motor (`crate::motors`) the plant and the model were set from, before any of
    /// their values was changed on either side.
    pub motor: String,
    /// Speed reference ω_d(t).
    pub reference: Reference,
    /// Where the controller's and observer's settings come from.
    #[serde(default)]
    pub design: DesignKind,
    /// Flux target ψ_d for φ_ra² + φ_rb² (Wb²), below base speed with field weakening.
    pub psi_d: f64,
    /// Field weakening: the flux target falls as (base/ω_d)² above base speed (see
    /// [`crate::control::flux_target`]).
    #[serde(default)]
    pub fw: bool,
    /// Base speed of the field weakening (rad/s).
    #[serde(default = "default_fw_base")]
    pub fw_base: f64,
    /// The state the motor starts from.
    #[serde(default)]
    pub start: Start,
    /// Parameters of the simulated motor.
    pub plant: MotorParams,
    /// Parameters the observer and controller assume.
    pub model: MotorParams,
    /// Which controller drives the motor.
    pub controller: ControllerKind,
    /// Backstepping gains.
    pub gains: Gains,
    /// Tuning of the IFOC baseline.
    pub ifoc: IfocTuning,
    /// EKF tuning.
    pub ekf: EkfConfig,
    /// Relative initial estimation error: x̂(0) = (1 − e)·x(0), P0 = diag((e·x(0))²) + Q.
    pub init_error: f64,
    /// Standard deviation of the current-measurement noise (A).
    pub noise: f64,
    /// Seed of the measurement-noise generator.
    pub seed: u64,
    /// Per-component stator-voltage limit (V).
    pub voltage_limit: f64,
    /// Simulated time (s).
    pub duration: f64,
    /// Control and sampling period Ts (s).
    pub ts: f64,
    /// RK4 substeps of the plant per sample.
    pub substeps: u32,
    /// Unknown load-torque step.
    pub load_step: LoadStep,
    /// Teaching switch: the controller gets the true state and L = 0.
    pub perfect: bool,
    /// Delay, voltage limit and PWM of the drive.
    pub drive: Drive,
    /// Rated stator current of the motor: the amplitude of its rated phase current, which is
    /// |i_s| at rated load in the amplitude-invariant a–b frame (A).
    pub i_rated: f64,
    /// Rated line-to-line voltage (V rms), which the derived design reads.
    #[serde(default = "default_rated_v")]
    pub rated_v: f64,
    /// Rated frequency (Hz), which the derived design reads.
    #[serde(default = "default_rated_f")]
    pub rated_f: f64,
    /// The backstepping steps' own laws, v1..v4 as formulas (None: the paper's law), see
    /// [`crate::control::law`].
    #[serde(default)]
    pub law: [Option<String>; 4],
}

fn default_fw_base() -> f64 {
    presets::FW_BASE
}

fn default_rated_v() -> f64 {
    presets::RATED_V
}

fn default_rated_f() -> f64 {
    presets::RATED_F
}

impl Scenario {
    /// Parses a scenario string: a bare preset name, or `v=1&preset=NAME&key=value...`.
    pub fn parse(text: &str) -> Result<Scenario, ScenarioError> {
        Scenario::parse_with(text, false).map(|(s, _)| s)
    }

    /// Parses like [`Scenario::parse`] but keeps going past bad fields: returns the scenario with
    /// every acceptable field applied and the errors of the fields left out. Fails only when there
    /// is no scenario to start from (bad `v` or `preset`) or the result is not physical.
    pub fn parse_lenient(text: &str) -> Result<(Scenario, Vec<ScenarioError>), ScenarioError> {
        match Scenario::parse(text) {
            Ok(s) => Ok((s, Vec::new())),
            Err(_) => Scenario::parse_with(text, true),
        }
    }

    /// The one parser: strictly, the first problem is the answer; leniently, a problem with one
    /// piece or field is noted and that piece is skipped. Linear in the length of `text`: pieces
    /// are looked up by hashing, and the text is refused at once past [`MAX_SCENARIO_BYTES`].
    fn parse_with(
        text: &str,
        lenient: bool,
    ) -> Result<(Scenario, Vec<ScenarioError>), ScenarioError> {
        if text.len() > MAX_SCENARIO_BYTES {
            return Err(ScenarioError::TooLong { bytes: text.len() });
        }
        let text = text.trim().trim_start_matches('?');
        if !text.contains('=') {
            let s = preset(text).ok_or_else(|| ScenarioError::UnknownPreset {
                name: text.to_string(),
            })?;
            return Ok((s, Vec::new()));
        }
        let mut errors = Vec::new();
        let mut note = |e: ScenarioError| {
            if lenient {
                errors.push(e);
                Ok(())
            } else {
                Err(e)
            }
        };
        let mut pairs: HashMap<&str, &str> = HashMap::new();
        for piece in text.split('&').filter(|p| !p.is_empty()) {
            match piece.split_once('=') {
                Some((k, _)) if pairs.contains_key(k) => {
                    note(ScenarioError::DuplicateKey { key: k.to_string() })?
                }
                Some((k, v)) => {
                    pairs.insert(k, v);
                }
                None => note(ScenarioError::Malformed {
                    piece: piece.to_string(),
                })?,
            }
        }
        let version = *pairs.get("v").ok_or(ScenarioError::Missing { key: "v" })?;
        if version != CODEC_VERSION.to_string() {
            return Err(ScenarioError::UnsupportedVersion {
                value: version.to_string(),
            });
        }
        let name = *pairs
            .get("preset")
            .ok_or(ScenarioError::Missing { key: "preset" })?;
        let mut s = preset(name).ok_or_else(|| ScenarioError::UnknownPreset {
            name: name.to_string(),
        })?;
        // Unknown keys in the order they were written, so the first one is the one reported.
        let mut unknown = std::collections::HashSet::new();
        for piece in text.split('&') {
            if let Some((k, _)) = piece.split_once('=') {
                if !matches!(k, "v" | "preset") && field(k).is_none() && unknown.insert(k) {
                    note(ScenarioError::UnknownKey { key: k.to_string() })?;
                }
            }
        }
        // Apply in field order so `ref=` (which resets the reference parameters) comes first.
        // Strictly, cross-field checks wait for the whole scenario (so no order of fields matters);
        // leniently, each field must leave a valid scenario, so a bad one can be singled out.
        let mut given = std::collections::HashSet::new();
        for field in fields() {
            if let Some(value) = pairs.get(field.key) {
                if !lenient {
                    field.set(&mut s, value)?;
                    given.insert(field.key);
                    continue;
                }
                let mut trial = s.clone();
                match field.set(&mut trial, value).and_then(|()| trial.validate()) {
                    Ok(()) => {
                        s = trial;
                        given.insert(field.key);
                    }
                    Err(e) => note(e)?,
                }
            }
        }
        // The derived design, from the motor, rating and sampling the link ends with, for every
        // setting of the design the link does not give.
        if s.design == DesignKind::Derived {
            let derived = s
                .derived()
                .map_err(|error| ScenarioError::Design { error })?;
            origin::apply_design(&mut s, &derived, &|key| given.contains(key));
        }
        s.validate()?;
        Ok((s, errors))
    }

    /// The compact scenario string: version, preset, then only the fields that differ from it.
    pub fn encode(&self) -> String {
        let mut out = format!("v={CODEC_VERSION}&preset={}", self.preset);
        for (key, value) in self.changes() {
            out.push('&');
            out.push_str(key);
            out.push('=');
            out.push_str(&value);
        }
        out
    }

    /// The keys of the fields that differ from the preset, in the codec's order: what this
    /// scenario changes of it.
    pub fn changed_keys(&self) -> Vec<&'static str> {
        self.changes().into_iter().map(|(key, _)| key).collect()
    }

    /// Why field `key` has no effect in this scenario: the settings that leave it idle, as the
    /// codec writes them (`controller=ifoc`); None when it acts.
    pub fn idle_because(&self, key: &str) -> Option<String> {
        idle_because(key, self)
    }

    /// The fields this scenario changes of its preset that have no effect in it, each said with
    /// the settings that leave it idle (`field-idle`: "perfect has no effect with
    /// controller=ifoc"): a setting the run would silently ignore.
    pub fn idle_settings(&self) -> Vec<crate::text::Message> {
        self.changed_keys()
            .into_iter()
            .filter_map(|key| {
                idle_because(key, self).map(|because| {
                    crate::text::Message::new("field-idle")
                        .text("key", key)
                        .text("because", because)
                })
            })
            .collect()
    }

    /// The fields that differ from the preset, with their codec text, in the codec's order.
    fn changes(&self) -> Vec<(&'static str, String)> {
        let original = preset(&self.preset).expect("a scenario's preset exists");
        // After `ref=` switches kind, the reference parameters differ from that kind's defaults.
        let mut base = original.clone();
        if base.reference.kind() != self.reference.kind() {
            base.reference = default_reference(self.reference.kind()).expect("known kind");
        }
        // After `motor=`, the plant, the model and the rating differ from that motor's values.
        if base.motor != self.motor {
            origin::set_motor(&mut base, &self.motor);
        }
        // With the derived design, its settings differ from the preset's: they are read against
        // the design this scenario's motor, rating and sampling give.
        if self.design == DesignKind::Derived {
            if let Ok(derived) = self.derived() {
                origin::apply_design(&mut base, &derived, &|_| false);
            }
        }
        fields()
            .iter()
            .filter_map(|field| {
                let switch = matches!(field.key, "ref" | "motor" | "design");
                let theirs = field.get(if switch { &original } else { &base });
                field
                    .get(self)
                    .filter(|m| Some(m) != theirs.as_ref())
                    .map(|mine| (field.key, mine))
            })
            .collect()
    }

    /// Sets one field from its codec text, then checks the whole scenario.
    pub fn set(&mut self, key: &str, value: &str) -> Result<(), ScenarioError> {
        let field = field(key).ok_or_else(|| ScenarioError::UnknownKey {
            key: key.to_string(),
        })?;
        field.set(self, value)?;
        self.validate()
    }

    /// The inverter's voltage limit.
    pub fn limit(&self) -> Limit {
        Limit {
            shape: self.drive.vlimit,
            vmax: self.voltage_limit,
            vdc: self.drive.vdc,
        }
    }

    /// The fields whose values differ from `other`, as "key: other's value → this value (unit)".
    pub fn differences(&self, other: &Scenario) -> Vec<String> {
        let mut out = Vec::new();
        if self.preset != other.preset {
            out.push(format!("preset: {} → {}", other.preset, self.preset));
        }
        for f in fields() {
            let (mine, theirs) = (f.get(self), f.get(other));
            if mine != theirs {
                let show = |v: Option<String>| v.unwrap_or_else(|| "–".to_string());
                let unit = if f.unit.is_empty() {
                    String::new()
                } else {
                    format!(" {}", f.unit)
                };
                out.push(format!(
                    "{}: {} → {}{unit}",
                    f.key,
                    show(theirs),
                    show(mine)
                ));
            }
        }
        out
    }

    /// Every field with its value, for `describe` and the UI.
    pub fn describe(&self) -> Vec<FieldInfo> {
        fields().iter().map(|f| f.info(self)).collect()
    }
}

/// The scenario text of `preset` with each of `fields` set to its value as written (a form's
/// control), every part percent-encoded: a form's scenario is then read by the codec's own rules,
/// with their messages, and never written by the page.
pub fn compose(preset: &str, fields: &[(String, String)]) -> String {
    use crate::text::percent::encode;
    let mut out = format!("v={CODEC_VERSION}&preset={}", encode(preset, b"-._~"));
    for (key, value) in fields {
        out += &format!("&{}={}", encode(key, b"-._~"), encode(value, b"-._~"));
    }
    out
}

#[cfg(test)]
mod tests {
    #[test]
    fn a_forms_fields_compose_to_the_scenario_the_codec_reads() {
        let field = |k: &str, v: &str| (k.to_string(), v.to_string());
        // A value keeps its `+`, its spaces and its `=`: the law read back is the law typed.
        let law = "-si1 + dwd + a3*wd + a2 - k1s1*z1";
        let s = Scenario::parse(&super::compose(
            "step",
            &[field("k1", "600"), field("law.v1", law)],
        ))
        .unwrap();
        assert_eq!(s.gains.k1, 600.0);
        assert_eq!(s.law[0].as_deref(), Some(law));
        // A `&` inside a value stays in that value: the refusal names its field, not a piece.
        let e = Scenario::parse(&super::compose("step", &[field("law.v1", "z1 & 1")])).unwrap_err();
        assert_eq!(e.key(), Some("law.v1"), "{e}");
        let s = Scenario::parse(&super::compose("step", &[field("k1", "600")])).unwrap();
        assert_eq!(s.encode(), "v=1&preset=step&k1=600");
    }

    use super::*;

    #[test]
    fn the_changed_keys_are_those_the_codec_writes_in_its_order() {
        let s = Scenario::parse("v=1&preset=step&duration=1&k1=600").unwrap();
        assert_eq!(s.changed_keys(), ["k1", "duration"]);
        assert_eq!(s.encode(), "v=1&preset=step&k1=600&duration=1");
        assert!(preset("step").unwrap().changed_keys().is_empty());
    }

    #[test]
    fn every_preset_round_trips_and_encodes_to_its_name() {
        for p in PRESETS {
            let s = preset(p.name).unwrap();
            s.validate().unwrap();
            let text = s.encode();
            assert_eq!(text, format!("v=1&preset={}", p.name));
            assert_eq!(Scenario::parse(&text).unwrap(), s);
            assert_eq!(Scenario::parse(p.name).unwrap(), s);
        }
    }

    #[test]
    fn a_motor_sets_the_plant_the_model_and_the_rating_and_its_values_can_still_change() {
        let m = crate::motors::motor("2.2kw").unwrap();
        let s = Scenario::parse("v=1&preset=step&motor=2.2kw").unwrap();
        let step = preset("step").unwrap();
        for side in [&s.plant, &s.model] {
            // The motor's circuit and inertia; the scenario's load.
            assert_eq!(
                (side.rs, side.rr, side.m),
                (m.params.rs, m.params.rr, m.params.m)
            );
            assert_eq!(
                (side.ls, side.lr, side.j),
                (m.params.ls, m.params.lr, m.params.j)
            );
            assert_eq!((side.t0, side.cf), (step.plant.t0, step.plant.cf));
        }
        assert_eq!(s.i_rated, 5.0 * 2f64.sqrt());
        assert_eq!(s.encode(), "v=1&preset=step&motor=2.2kw");
        assert_eq!(s.changed_keys(), ["motor"]);
        // A value changed after it, in either order in the link, is written after it.
        for link in [
            "v=1&preset=step&motor=2.2kw&plant.rr=2.5&i_rated=7",
            "v=1&preset=step&i_rated=7&plant.rr=2.5&motor=2.2kw",
        ] {
            let t = Scenario::parse(link).unwrap();
            assert_eq!((t.plant.rr, t.model.rr, t.i_rated), (2.5, 2.1, 7.0));
            let written = t.encode();
            assert_eq!(
                written,
                "v=1&preset=step&motor=2.2kw&plant.rr=2.5&i_rated=7"
            );
            assert_eq!(Scenario::parse(&written).unwrap(), t);
        }
        // The paper's motor is the presets' own: choosing it changes nothing.
        let paper = Scenario::parse("v=1&preset=step&motor=paper").unwrap();
        assert_eq!(paper, step);
        assert_eq!(paper.encode(), "v=1&preset=step");
        // What a form must leave out when it changes the motor: every field the motor sets.
        let big = Scenario::parse("v=1&preset=step&motor=15kw").unwrap();
        let resets = big
            .describe()
            .into_iter()
            .find(|f| f.key == "motor")
            .unwrap()
            .resets;
        for (before, after) in step.describe().iter().zip(big.describe()) {
            if before.value != after.value && before.key != "motor" {
                assert!(resets.contains(&before.key), "{}", before.key);
            }
        }
        let e = Scenario::parse("v=1&preset=step&motor=7kw").unwrap_err();
        assert_eq!(e.key(), Some("motor"), "{e}");
    }

    #[test]
    fn only_fields_that_act_are_marked_so() {
        let acting = |text: &str, key: &str| {
            let s = Scenario::parse(text).unwrap();
            s.describe().iter().find(|f| f.key == key).unwrap().acts
        };
        assert!(!acting("v=1&preset=step", "ifoc.bw_i"));
        for key in [
            "k1",
            "k4",
            "robust",
            "perfect",
            "eps2",
            "law.v1",
            "delay.comp",
        ] {
            assert!(!acting("v=1&preset=ifoc-step", key), "{key}");
            assert!(acting("v=1&preset=step&robust=1&delay=1", key), "{key}");
        }
        assert!(acting("v=1&preset=ifoc-step", "ifoc.bw_i"));
        assert!(!acting("v=1&preset=step&robust=0", "eps2"));
        assert!(acting("v=1&preset=step&robust=1", "h4"));
        assert!(acting("v=1&preset=step", "k1"));
    }

    #[test]
    fn the_documented_example_round_trips() {
        let s = Scenario::parse("v=1&preset=step&step.size=0.3&noise=0.004").unwrap();
        assert_eq!(s.noise, 0.004);
        assert!(matches!(s.reference, Reference::Step { size, .. } if size == 0.3));
        assert_eq!(s.encode(), "v=1&preset=step&step.size=0.3&noise=0.004");
    }

    #[test]
    fn rejects_malformed_input_with_the_field_named() {
        let cases: &[(&str, &str)] = &[
            ("v=1&preset=step&k1=-5", "'k1'"),
            ("v=1&preset=step&k1=abc", "'k1'"),
            ("v=1&preset=step&k1=inf", "'k1'"),
            ("v=1&preset=step&k1=NaN", "'k1'"),
            ("v=1&preset=step&k1=", "'k1'"),
            ("v=1&preset=step&k1=1&k1=2", "'k1'"),
            ("v=1&preset=step&kk=1", "'kk'"),
            ("v=2&preset=step", "'v'"),
            ("preset=step", "'v'"),
            ("v=1&k1=5", "'preset'"),
            ("v=1&preset=nope", "'preset'"),
            ("v=1&preset=step&sine.amp=1", "'sine.amp'"),
            ("v=1&preset=step&ekf=rk5", "'ekf'"),
            ("v=1&preset=step&seed=1.5", "'seed'"),
            ("v=1&preset=step&plant.m=0.6", "plant"),
            ("v=1&preset=step&duration=20&ts=1e-6", "duration"),
            ("v=1&preset=step&garbage", "'garbage'"),
            ("v=1&preset=step&ekf.r_std=1e-200", "'ekf.r_std'"),
            ("v=1&preset=step&model.j=1e-155", "'model.j'"),
            ("v=1&preset=step&plant.lr=1e-300", "'plant.lr'"),
        ];
        for (text, needle) in cases {
            let err = Scenario::parse(text).expect_err(text).to_string();
            assert!(err.contains(needle), "{text}: {err}");
        }
        // Out of range names the allowed range with its unit.
        let err = Scenario::parse("v=1&preset=step&k1=-5")
            .unwrap_err()
            .to_string();
        assert!(err.contains("0 < k1 ≤ 1000000 (1/s)"), "{err}");
    }

    #[test]
    fn differences_name_each_changed_field() {
        let a = Scenario::parse("v=1&preset=step").unwrap();
        let b = Scenario::parse("v=1&preset=step&k1=1500&noise=0").unwrap();
        assert_eq!(
            b.differences(&a),
            vec!["k1: 1200 → 1500 1/s", "noise: 0.002 → 0 A"]
        );
        assert!(a.differences(&a).is_empty());
    }

    #[test]
    fn lenient_parse_keeps_the_good_fields_and_names_the_bad_ones() {
        let (s, errors) =
            Scenario::parse_lenient("v=1&preset=step&k1=-5&k2=1500&bogus=1&noise=0").unwrap();
        assert_eq!(s.encode(), "v=1&preset=step&k2=1500&noise=0");
        let text: Vec<String> = errors.iter().map(|e| e.to_string()).collect();
        assert_eq!(text.len(), 2, "{text:?}");
        assert!(
            text.iter().any(|t| t.contains("'k1'")) && text.iter().any(|t| t.contains("'bogus'"))
        );
        assert!(Scenario::parse_lenient("v=1&preset=nope&k1=5").is_err());
        assert_eq!(
            Scenario::parse_lenient("step").unwrap(),
            (preset("step").unwrap(), vec![])
        );
    }

    #[test]
    fn switching_reference_kind_round_trips() {
        let s = Scenario::parse("v=1&preset=step&ref=sine&sine.freq=50").unwrap();
        assert_eq!(
            s.reference,
            Reference::Sine {
                amp: 0.5,
                freq: 50.0,
                offset: 0.0,
            }
        );
        assert_eq!(s.encode(), "v=1&preset=step&ref=sine&sine.freq=50");
        assert_eq!(Scenario::parse(&s.encode()).unwrap(), s);
    }

    #[test]
    fn long_input_is_refused_at_once_with_the_cap() {
        let text = format!("v=1&preset=step&{}", "k1=1&".repeat(4000));
        let err = Scenario::parse(&text).unwrap_err().to_string();
        assert!(err.contains("16384 bytes (16 KiB) allowed"), "{err}");
        assert!(Scenario::parse_lenient(&text).is_err());
        // Just under the cap is parsed (and the duplicate named).
        let text = format!("v=1&preset=step&{}", "k1=1&".repeat(3000));
        assert!(text.len() < MAX_SCENARIO_BYTES);
        let err = Scenario::parse(&text).unwrap_err().to_string();
        assert!(err.contains("'k1' is given more than once"), "{err}");
    }

    #[test]
    fn echoed_input_is_escaped_and_cut() {
        let value = format!("1\n\u{1b}[31m{}", "9".repeat(500));
        let err = Scenario::parse(&format!("v=1&preset=step&k1={value}"))
            .unwrap_err()
            .to_string();
        assert!(!err.chars().any(char::is_control), "{err:?}");
        assert!(err.contains("1\\n\\u{1b}[31m999"), "{err}");
        assert!(err.contains("(507 characters)"), "{err}");
        assert!(err.chars().count() < 200, "{err}");
        // A right-to-left override in a key would reverse the rest of the message as shown.
        let err = Scenario::parse("v=1&preset=step&k\u{202e}1=5")
            .unwrap_err()
            .to_string();
        assert!(err.contains("field 'k\\u{202e}1'"), "{err}");
        assert!(!err.chars().any(crate::text::is_invisible), "{err:?}");
    }
}

/// Property tests of the codec (native only: proptest does not build for wasm32).
#[cfg(all(test, not(target_arch = "wasm32")))]
mod properties {
    use super::*;
    use proptest::prelude::*;

    /// A value in the range of the field described by `f`, as the codec writes it.
    fn value_in(f: &FieldInfo) -> BoxedStrategy<String> {
        if f.points.is_some() {
            // Two points, the second a value in the field's range.
            return (f.min.max(-1e3)..=f.max.min(1e3))
                .prop_map(|v| format!("0:0,0.1:{v}"))
                .boxed();
        }
        if !f.options.is_empty() {
            return proptest::sample::select(f.options)
                .prop_map(str::to_string)
                .boxed();
        }
        let (lo, hi, integer, open) = (f.min.max(-1e3), f.max.min(1e3), f.integer, f.min_open);
        (0.0..=1.0f64)
            .prop_map(move |u| {
                let mut v = lo + (hi - lo) * u;
                if integer {
                    v = v.round();
                }
                if open && v <= lo {
                    v = hi;
                }
                format!("{v}")
            })
            .boxed()
    }

    /// A scenario string: a preset and a few of its fields set to values in their ranges.
    fn scenario_text() -> impl Strategy<Value = String> {
        let fields = preset("step").unwrap().describe();
        (
            proptest::sample::select(PRESETS.iter().map(|p| p.name).collect::<Vec<_>>()),
            proptest::sample::subsequence(fields, 0..8),
        )
            .prop_flat_map(|(name, chosen)| {
                let values: Vec<_> = chosen.iter().map(value_in).collect();
                let keys: Vec<&str> = chosen.iter().map(|f| f.key).collect();
                values.prop_map(move |vals| {
                    let mut text = format!("v=1&preset={name}");
                    for (k, v) in keys.iter().zip(vals) {
                        text.push_str(&format!("&{k}={v}"));
                    }
                    text
                })
            })
    }

    /// Whether an error message names what it refuses: a field, the malformed piece, the preset,
    /// a parameter set or the length of the string.
    fn names_something(message: &str) -> bool {
        message.contains("field '")
            || message.contains("is not of the form key=value")
            || message.contains("parameters:")
            || message.contains("duration")
            || message.contains("bytes long")
    }

    /// A piece of a key/value soup: a field key or junk, `=` or not, a number or junk.
    fn soup_piece() -> impl Strategy<Value = String> {
        let keys: Vec<&'static str> = preset("step")
            .unwrap()
            .describe()
            .iter()
            .map(|f| f.key)
            .collect();
        (
            prop_oneof![
                proptest::sample::select(keys).prop_map(str::to_string),
                Just("v".to_string()),
                Just("preset".to_string()),
                "[a-z.]{0,6}",
                any::<String>(),
            ],
            prop_oneof![Just("="), Just(""), Just("==")],
            prop_oneof![
                any::<f64>().prop_map(|v| format!("{v}")),
                Just("1".to_string()),
                Just("step".to_string()),
                any::<String>(),
            ],
        )
            .prop_map(|(k, eq, v)| format!("{k}{eq}{v}"))
    }

    proptest! {
        // About half of the random scenarios set a reference parameter of another kind or are
        // unphysical, and are skipped; proptest still fails if more than 5 in 6 are.
        #![proptest_config(ProptestConfig { cases: 2000, max_global_rejects: 10_000, ..ProptestConfig::default() })]

        #[test]
        fn valid_scenarios_round_trip(text in scenario_text()) {
            // Values are in their fields' ranges, but a combination may still be unphysical (or
            // set a reference parameter of another kind); proptest fails if too many are.
            let parsed = Scenario::parse(&text);
            prop_assume!(parsed.is_ok());
            let parsed = parsed.unwrap();
            let encoded = parsed.encode();
            let again = Scenario::parse(&encoded).unwrap();
            prop_assert_eq!(&again, &parsed, "{} -> {}", text, encoded);
            prop_assert_eq!(again.encode(), encoded);
        }

        #[test]
        fn arbitrary_bytes_never_panic_and_errors_name_something(bytes in proptest::collection::vec(any::<u8>(), 0..200)) {
            let text = String::from_utf8_lossy(&bytes);
            if let Err(e) = Scenario::parse(&text) {
                let m = e.to_string();
                prop_assert!(names_something(&m) || m.contains("unknown preset"), "{}", m);
                prop_assert!(!m.chars().any(crate::text::is_invisible), "{:?}", m);
            }
        }

        #[test]
        fn key_value_soups_never_panic_and_errors_name_something(
            pieces in proptest::collection::vec(soup_piece(), 0..12),
            preset_index in 0..PRESETS.len(),
        ) {
            let text = format!("v=1&preset={}&{}", PRESETS[preset_index].name, pieces.join("&"));
            match Scenario::parse_lenient(&text) {
                Ok((s, errors)) => {
                    s.validate().unwrap();
                    for e in errors {
                        prop_assert!(names_something(&e.to_string()), "{}", e);
                    }
                }
                Err(e) => prop_assert!(names_something(&e.to_string()), "{}", e),
            }
        }
    }
}
