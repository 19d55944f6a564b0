//! One scenario type holding every setting, the presets, and the compact query-string codec
//! shared by the CLI, the browser URL and the tests.
//!
//! A scenario string is `v=1&preset=NAME` followed by only the fields that differ from the
//! preset, e.g. `v=1&preset=step&step.size=0.3&noise=0.004`. Numbers are written in Rust's
//! shortest round-trip form, so decode(encode(s)) == s bit for bit.

use crate::control::{Gains, IfocTuning, Reference};
use crate::observer::{EkfConfig, Predictor};
use crate::params::{MotorParams, ParamError};
use serde::{Deserialize, Serialize};
use std::f64::consts::PI;
use std::fmt;

/// Version of the query-string codec.
pub const CODEC_VERSION: u32 = 1;

/// An extra load torque applied from a given time on, unknown to the controller and observer.
#[derive(Clone, Copy, Debug, PartialEq, Serialize, Deserialize)]
pub struct LoadStep {
    /// Time the step is applied (s).
    pub time: f64,
    /// Extra load torque (N m); 0 means no step.
    pub torque: f64,
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
    /// Speed reference ω_d(t).
    pub reference: Reference,
    /// Flux target ψ_d for φ_ra² + φ_rb² (Wb²).
    pub psi_d: f64,
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
}

/// A named scenario with a one-line description.
pub struct Preset {
    /// Name used in `preset=`.
    pub name: &'static str,
    /// One line saying what it shows.
    pub description: &'static str,
}

/// All presets, in display order.
pub const PRESETS: &[Preset] = &[
    Preset { name: "sine200", description: "Paper Fig 2: track 0.5 sin(2π·200 t) rad/s with the EKF" },
    Preset { name: "step", description: "Paper Fig 3: 0 → 0.5 rad/s step at 50 ms through a 200 Hz critically damped filter" },
    Preset { name: "ramp", description: "Paper Fig 4: trapezoid to 100 rad/s at ±400 rad/s², hold, and back" },
    Preset { name: "sine200-1rad", description: "1 rad/s at 200 Hz: the 400 V limit saturates and tracking suffers" },
    Preset { name: "sine200-rk4", description: "Fig 2 with an RK4 EKF predictor instead of the paper's Euler" },
    Preset { name: "rr-mismatch", description: "Hold 50 rad/s with the motor's rotor resistance 10 % above the model's: a biased speed estimate" },
    Preset { name: "load-step", description: "Hold 50 rad/s; an unknown 2 N m load step at 0.15 s that the 5-state EKF cannot see" },
    Preset { name: "decay", description: "Perfect observer, no noise, ω_d ≡ 0: the errors decay at the designed 1200/s" },
    Preset { name: "ifoc-step", description: "Classical baseline: sensorless IFOC with an MRAS, step to 40 rad/s (MRAS is blind near zero speed)" },
    Preset { name: "high-gain", description: "Gains 3000/s (2.5× the paper): the Euler EKF's prediction errors through the gains saturate the 400 V limit" },
];

fn paper_base(name: &str, reference: Reference, duration: f64) -> Scenario {
    Scenario {
        preset: name.to_string(),
        reference,
        psi_d: 0.5,
        plant: MotorParams::PAPER,
        model: MotorParams::PAPER,
        controller: ControllerKind::Backstepping,
        ifoc: IfocTuning {
            current_bw: 1000.0,
            speed_bw: 10.0,
            mras_bw: 50.0,
            current_limit: 20.0,
        },
        gains: Gains {
            k1: 1200.0,
            k2: 1200.0,
            k3: 1200.0,
            k4: 1200.0,
            robust: false,
            eps2: 1.0,
            h2: 0.0,
            eps4: 1.0,
            h4: 0.0,
        },
        ekf: EkfConfig {
            predictor: Predictor::Euler,
            q: 0.001,
            r_std: 0.002,
        },
        init_error: 0.1,
        noise: 0.002,
        seed: 1,
        voltage_limit: 400.0,
        duration,
        ts: 50e-6,
        substeps: 1,
        load_step: LoadStep {
            time: 0.0,
            torque: 0.0,
        },
        perfect: false,
    }
}

const SINE200: Reference = Reference::Sine {
    amp: 0.5,
    freq: 200.0,
    offset: 0.0,
};
const STEP: Reference = Reference::Step {
    size: 0.5,
    time: 0.05,
    wn: 2.0 * PI * 200.0,
};

/// The preset called `name`, if there is one.
pub fn preset(name: &str) -> Option<Scenario> {
    let s = match name {
        "sine200" => paper_base(name, SINE200, 0.25),
        "step" => paper_base(name, STEP, 0.10),
        "ramp" => paper_base(
            name,
            Reference::Ramp {
                start: 0.05,
                level: 100.0,
                slope: 400.0,
                hold: 0.10,
            },
            0.70,
        ),
        "sine200-1rad" => paper_base(
            name,
            Reference::Sine {
                amp: 1.0,
                freq: 200.0,
                offset: 0.0,
            },
            0.25,
        ),
        "sine200-rk4" => {
            let mut s = paper_base(name, SINE200, 0.25);
            s.ekf.predictor = Predictor::Rk4;
            s
        }
        "rr-mismatch" => {
            let mut s = paper_base(name, Reference::Constant { value: 50.0 }, 0.30);
            s.plant.rr *= 1.1;
            s
        }
        "load-step" => {
            let mut s = paper_base(name, Reference::Constant { value: 50.0 }, 0.30);
            s.load_step = LoadStep {
                time: 0.15,
                torque: 2.0,
            };
            s
        }
        "decay" => {
            let mut s = paper_base(name, Reference::Constant { value: 0.0 }, 0.02);
            s.perfect = true;
            s.noise = 0.0;
            s
        }
        "ifoc-step" => {
            let mut s = paper_base(
                name,
                Reference::Step {
                    size: 40.0,
                    time: 0.05,
                    wn: 2.0 * PI * 200.0,
                },
                0.6,
            );
            s.controller = ControllerKind::Ifoc;
            s
        }
        "high-gain" => {
            let mut s = paper_base(name, STEP, 0.10);
            s.gains.k1 = 3000.0;
            s.gains.k2 = 3000.0;
            s.gains.k3 = 3000.0;
            s.gains.k4 = 3000.0;
            s
        }
        _ => return None,
    };
    Some(s)
}

/// Default parameters of each reference kind, used when `ref=` switches kind.
fn default_reference(kind: &str) -> Option<Reference> {
    Some(match kind {
        "constant" => Reference::Constant { value: 0.0 },
        "sine" => SINE200,
        "step" => STEP,
        "ramp" => Reference::Ramp {
            start: 0.05,
            level: 100.0,
            slope: 400.0,
            hold: 0.10,
        },
        _ => return None,
    })
}

/// Longest excerpt of user input quoted in a message (characters).
pub const EXCERPT_CHARS: usize = 40;

/// `text` as quoted in a message: control and other invisible characters written as escapes
/// (`\n`, `\u{7f}`), cut to [`EXCERPT_CHARS`] characters with the full length noted.
pub fn excerpt(text: &str) -> String {
    let count = text.chars().count();
    let mut out: String = text
        .chars()
        .take(EXCERPT_CHARS)
        .flat_map(|c| {
            if c.is_control() || c == '\u{200b}' || c == '\u{feff}' {
                c.escape_default().collect::<Vec<_>>()
            } else {
                vec![c]
            }
        })
        .collect();
    if count > EXCERPT_CHARS {
        out.push_str(&format!("… ({count} characters)"));
    }
    out
}

/// Why a scenario string or value was refused. Every variant names the field.
#[derive(Clone, Debug, PartialEq)]
pub enum ScenarioError {
    /// A required field (`v` or `preset`) is absent.
    Missing {
        /// The field.
        key: &'static str,
    },
    /// `v` names a codec version this build does not read.
    UnsupportedVersion {
        /// The value given.
        value: String,
    },
    /// `preset` names no preset.
    UnknownPreset {
        /// The value given.
        name: String,
    },
    /// A `key=value` pair whose key is not a field.
    UnknownKey {
        /// The key given.
        key: String,
    },
    /// A field given twice.
    DuplicateKey {
        /// The field.
        key: String,
    },
    /// A piece of the string that is not `key=value`.
    Malformed {
        /// The piece.
        piece: String,
    },
    /// A value that does not parse as the field's type.
    BadValue {
        /// The field.
        key: String,
        /// The value given.
        value: String,
        /// What the field takes.
        expected: String,
    },
    /// A value outside the field's allowed range.
    OutOfRange {
        /// The field.
        key: String,
        /// The value given.
        value: f64,
        /// The allowed range, e.g. "0 < k1 ≤ 1000000 (1/s)".
        allowed: String,
    },
    /// A reference parameter that does not belong to the scenario's reference kind.
    NotApplicable {
        /// The field.
        key: String,
        /// The scenario's reference kind.
        reference: &'static str,
    },
    /// Motor parameters that are not physical.
    Physics {
        /// `plant` or `model`.
        which: &'static str,
        /// The reason.
        error: ParamError,
    },
    /// A run that would need more steps or memory than allowed.
    TooLarge {
        /// What was too large and the limit.
        what: String,
    },
}

impl fmt::Display for ScenarioError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        use ScenarioError::*;
        match self {
            Missing { key } => write!(
                f,
                "field '{key}' is missing (a scenario starts with v={CODEC_VERSION}&preset=NAME)"
            ),
            UnsupportedVersion { value } => {
                write!(
                    f,
                    "field 'v' = '{value}': unsupported codec version, allowed: {CODEC_VERSION}"
                )
            }
            UnknownPreset { name } => write!(
                f,
                "field 'preset' = '{name}': unknown preset, allowed: {}",
                PRESETS
                    .iter()
                    .map(|p| p.name)
                    .collect::<Vec<_>>()
                    .join(", ")
            ),
            UnknownKey { key } => write!(
                f,
                "field '{key}' is not a scenario field (the settings form and `imlab describe` list them)"
            ),
            DuplicateKey { key } => write!(f, "field '{key}' is given more than once"),
            Malformed { piece } => write!(f, "'{piece}' is not of the form key=value"),
            BadValue {
                key,
                value,
                expected,
            } => {
                write!(
                    f,
                    "field '{key}' = '{value}': not valid, expected {expected}"
                )
            }
            OutOfRange {
                key,
                value,
                allowed,
            } => {
                write!(
                    f,
                    "field '{key}' = {value}: out of range, allowed {allowed}"
                )
            }
            NotApplicable { key, reference } => write!(
                f,
                "field '{key}' does not apply to the reference '{reference}' (set ref= first)"
            ),
            Physics { which, error } => write!(f, "{which} parameters: {error}"),
            TooLarge { what } => write!(f, "{what}"),
        }
    }
}

impl std::error::Error for ScenarioError {}

/// How a field's value is read and written.
#[derive(Clone, Copy)]
enum Access {
    Number {
        get: fn(&Scenario) -> Option<f64>,
        set: fn(&mut Scenario, f64) -> bool,
    },
    Choice {
        options: &'static [&'static str],
        get: fn(&Scenario) -> &'static str,
        set: fn(&mut Scenario, &str),
    },
}

/// One field of the codec: its key, unit, allowed range and meaning.
#[derive(Clone, Copy)]
pub struct Field {
    /// Key in the query string.
    pub key: &'static str,
    /// Settings group shown in the UI.
    pub group: &'static str,
    /// Unit (SI) or "" for dimensionless.
    pub unit: &'static str,
    /// Smallest allowed value.
    pub min: f64,
    /// Whether `min` itself is excluded.
    pub min_open: bool,
    /// Largest allowed value.
    pub max: f64,
    /// Whether only whole numbers are allowed.
    pub integer: bool,
    /// One line saying what the field is.
    pub doc: &'static str,
    access: Access,
}

/// A field as data, for the UI and `describe`.
#[derive(Clone, Debug, Serialize)]
pub struct FieldInfo {
    /// Key in the query string.
    pub key: &'static str,
    /// Settings group.
    pub group: &'static str,
    /// Unit.
    pub unit: &'static str,
    /// Smallest allowed value (numbers only).
    pub min: f64,
    /// Whether `min` is excluded.
    pub min_open: bool,
    /// Largest allowed value.
    pub max: f64,
    /// Whole numbers only.
    pub integer: bool,
    /// Allowed names for choice fields; empty for numbers.
    pub options: &'static [&'static str],
    /// Meaning.
    pub doc: &'static str,
    /// Current value as written in the codec, or None when it does not apply.
    pub value: Option<String>,
    /// Whether the field acts on this scenario (the page shows only those): the IFOC tuning only
    /// with the IFOC controller, ε and h only with the robust terms on.
    pub acts: bool,
}

/// Whether field `key` changes anything in scenario `s`.
fn acts(key: &str, s: &Scenario) -> bool {
    if key.starts_with("ifoc.") {
        s.controller == ControllerKind::Ifoc
    } else if matches!(key, "eps2" | "h2" | "eps4" | "h4") {
        s.gains.robust
    } else {
        true
    }
}

macro_rules! num {
    ($key:literal, $group:literal, $unit:literal, $min:expr, $open:expr, $max:expr, $int:expr, $doc:literal, |$s:ident| $place:expr) => {
        Field {
            key: $key,
            group: $group,
            unit: $unit,
            min: $min,
            min_open: $open,
            max: $max,
            integer: $int,
            doc: $doc,
            access: Access::Number {
                get: |$s: &Scenario| Some($place as f64),
                set: |$s: &mut Scenario, v: f64| {
                    $place = v as _;
                    true
                },
            },
        }
    };
}

macro_rules! bool_field {
    ($key:literal, $group:literal, $doc:literal, |$s:ident| $place:expr) => {
        Field {
            key: $key,
            group: $group,
            unit: "",
            min: 0.0,
            min_open: false,
            max: 1.0,
            integer: true,
            doc: $doc,
            access: Access::Number {
                get: |$s: &Scenario| Some(if $place { 1.0 } else { 0.0 }),
                set: |$s: &mut Scenario, v: f64| {
                    $place = v == 1.0;
                    true
                },
            },
        }
    };
}

macro_rules! ref_num {
    ($key:literal, $unit:literal, $min:expr, $open:expr, $max:expr, $doc:literal, $variant:ident . $field:ident) => {
        Field {
            key: $key,
            group: "reference",
            unit: $unit,
            min: $min,
            min_open: $open,
            max: $max,
            integer: false,
            doc: $doc,
            access: Access::Number {
                get: |s: &Scenario| match s.reference {
                    Reference::$variant { $field, .. } => Some($field),
                    _ => None,
                },
                set: |s: &mut Scenario, v: f64| match &mut s.reference {
                    Reference::$variant { $field, .. } => {
                        *$field = v;
                        true
                    }
                    _ => false,
                },
            },
        }
    };
}

macro_rules! motor {
    ($which:ident, $group:literal, $rs:literal, $rr:literal, $m:literal, $ls:literal, $lr:literal, $j:literal, $np:literal, $t0:literal, $cf:literal) => {
        [
            num!(
                $rs,
                $group,
                "Ω",
                0.0,
                true,
                1000.0,
                false,
                "stator resistance Rs",
                |s| s.$which.rs
            ),
            num!(
                $rr,
                $group,
                "Ω",
                0.0,
                true,
                1000.0,
                false,
                "rotor resistance Rr",
                |s| s.$which.rr
            ),
            num!(
                $m,
                $group,
                "H",
                0.0,
                true,
                100.0,
                false,
                "mutual inductance M",
                |s| s.$which.m
            ),
            num!(
                $ls,
                $group,
                "H",
                0.0,
                true,
                100.0,
                false,
                "stator inductance Ls",
                |s| s.$which.ls
            ),
            num!(
                $lr,
                $group,
                "H",
                0.0,
                true,
                100.0,
                false,
                "rotor inductance Lr",
                |s| s.$which.lr
            ),
            num!(
                $j,
                $group,
                "kg m²",
                0.0,
                true,
                1e4,
                false,
                "rotor inertia J",
                |s| s.$which.j
            ),
            num!(
                $np,
                $group,
                "",
                1.0,
                false,
                50.0,
                true,
                "pole pairs np",
                |s| s.$which.np
            ),
            num!(
                $t0,
                $group,
                "N m",
                0.0,
                false,
                1e4,
                false,
                "constant load torque T0",
                |s| s.$which.t0
            ),
            num!(
                $cf,
                $group,
                "N m s",
                0.0,
                false,
                1e3,
                false,
                "viscous friction Cf",
                |s| s.$which.cf
            ),
        ]
    };
}

/// Largest integer a JavaScript number holds exactly (2^53 − 1), the bound for seeds.
const MAX_SEED: f64 = 9_007_199_254_740_991.0;

/// Every field of the codec, in the order the encoder writes them.
pub fn fields() -> &'static [Field] {
    static FIELDS: std::sync::OnceLock<Vec<Field>> = std::sync::OnceLock::new();
    FIELDS.get_or_init(|| {
        let mut v = vec![
            Field {
                key: "ref",
                group: "reference",
                unit: "",
                min: 0.0,
                min_open: false,
                max: 0.0,
                integer: false,
                doc: "speed reference kind",
                access: Access::Choice {
                    options: &["constant", "sine", "step", "ramp"],
                    get: |s| s.reference.kind(),
                    set: |s, name| {
                        // Keep the parameters when the kind does not change.
                        if s.reference.kind() != name {
                            s.reference = default_reference(name).expect("checked option");
                        }
                    },
                },
            },
            ref_num!(
                "ref.value",
                "rad/s",
                -1000.0,
                false,
                1000.0,
                "constant speed",
                Constant.value
            ),
            ref_num!(
                "sine.amp",
                "rad/s",
                0.0,
                false,
                1000.0,
                "sine amplitude",
                Sine.amp
            ),
            ref_num!(
                "sine.freq",
                "Hz",
                0.0,
                false,
                5000.0,
                "sine frequency",
                Sine.freq
            ),
            ref_num!(
                "sine.offset",
                "rad/s",
                -1000.0,
                false,
                1000.0,
                "constant added to the sine",
                Sine.offset
            ),
            ref_num!(
                "step.size",
                "rad/s",
                -1000.0,
                false,
                1000.0,
                "step size",
                Step.size
            ),
            ref_num!("step.time", "s", 0.0, false, 10.0, "step time", Step.time),
            ref_num!(
                "step.wn",
                "rad/s",
                0.0,
                true,
                1e5,
                "step filter natural frequency ωn",
                Step.wn
            ),
            ref_num!(
                "ramp.start",
                "s",
                0.0,
                false,
                10.0,
                "ramp start time",
                Ramp.start
            ),
            ref_num!(
                "ramp.level",
                "rad/s",
                -1000.0,
                false,
                1000.0,
                "ramp plateau level",
                Ramp.level
            ),
            ref_num!(
                "ramp.slope",
                "rad/s²",
                0.0,
                true,
                1e6,
                "ramp slope magnitude",
                Ramp.slope
            ),
            ref_num!(
                "ramp.hold",
                "s",
                0.0,
                false,
                10.0,
                "ramp plateau duration",
                Ramp.hold
            ),
            num!(
                "psi_d",
                "reference",
                "Wb²",
                0.0,
                true,
                4.0,
                false,
                "flux target for φa² + φb²",
                |s| s.psi_d
            ),
            num!(
                "k1",
                "gains",
                "1/s",
                0.0,
                true,
                1e6,
                false,
                "speed-error rate k1",
                |s| s.gains.k1
            ),
            num!(
                "k2",
                "gains",
                "1/s",
                0.0,
                true,
                1e6,
                false,
                "torque-error rate k2 = a7 + a8 + k2s1",
                |s| s.gains.k2
            ),
            num!(
                "k3",
                "gains",
                "1/s",
                0.0,
                true,
                1e6,
                false,
                "flux-error rate k3",
                |s| s.gains.k3
            ),
            num!(
                "k4",
                "gains",
                "1/s",
                0.0,
                true,
                1e6,
                false,
                "flux-derivative-error rate k4",
                |s| s.gains.k4
            ),
            bool_field!(
                "robust",
                "gains",
                "apply robust terms (38) and (53) (0/1)",
                |s| s.gains.robust
            ),
            num!(
                "eps2",
                "gains",
                "",
                0.0,
                true,
                1e6,
                false,
                "ε2 of (38)",
                |s| s.gains.eps2
            ),
            num!(
                "h2",
                "gains",
                "",
                0.0,
                false,
                1e9,
                false,
                "h2 of (38): bound on |d̃2|",
                |s| s.gains.h2
            ),
            num!(
                "eps4",
                "gains",
                "",
                0.0,
                true,
                1e6,
                false,
                "ε4 of (53)",
                |s| s.gains.eps4
            ),
            num!(
                "h4",
                "gains",
                "",
                0.0,
                false,
                1e9,
                false,
                "h4 of (53): bound on |d̃4|",
                |s| s.gains.h4
            ),
            Field {
                key: "controller",
                group: "controller",
                unit: "",
                min: 0.0,
                min_open: false,
                max: 0.0,
                integer: false,
                doc: "backstepping (paper) or ifoc (classical sensorless FOC baseline)",
                access: Access::Choice {
                    options: &["backstepping", "ifoc"],
                    get: |s| match s.controller {
                        ControllerKind::Backstepping => "backstepping",
                        ControllerKind::Ifoc => "ifoc",
                    },
                    set: |s, name| {
                        s.controller = if name == "ifoc" {
                            ControllerKind::Ifoc
                        } else {
                            ControllerKind::Backstepping
                        }
                    },
                },
            },
            num!(
                "ifoc.bw_i",
                "controller",
                "Hz",
                0.0,
                true,
                5000.0,
                false,
                "IFOC current-loop bandwidth",
                |s| s.ifoc.current_bw
            ),
            num!(
                "ifoc.bw_w",
                "controller",
                "Hz",
                0.0,
                true,
                1000.0,
                false,
                "IFOC speed-loop bandwidth",
                |s| s.ifoc.speed_bw
            ),
            num!(
                "ifoc.bw_mras",
                "controller",
                "Hz",
                0.0,
                true,
                5000.0,
                false,
                "IFOC MRAS speed-estimator bandwidth",
                |s| s.ifoc.mras_bw
            ),
            num!(
                "ifoc.i_max",
                "controller",
                "A",
                0.0,
                true,
                1000.0,
                false,
                "IFOC q-current limit",
                |s| s.ifoc.current_limit
            ),
            Field {
                key: "ekf",
                group: "observer",
                unit: "",
                min: 0.0,
                min_open: false,
                max: 0.0,
                integer: false,
                doc: "EKF predictor: euler (paper) or rk4",
                access: Access::Choice {
                    options: &["euler", "rk4"],
                    get: |s| match s.ekf.predictor {
                        Predictor::Euler => "euler",
                        Predictor::Rk4 => "rk4",
                    },
                    set: |s, name| {
                        s.ekf.predictor = if name == "rk4" {
                            Predictor::Rk4
                        } else {
                            Predictor::Euler
                        }
                    },
                },
            },
            num!(
                "ekf.q",
                "observer",
                "1/s",
                0.0,
                true,
                1e6,
                false,
                "process noise Q = q·Ts·I",
                |s| s.ekf.q
            ),
            num!(
                "ekf.r_std",
                "observer",
                "A",
                0.0,
                true,
                10.0,
                false,
                "assumed current noise, R = r_std²·I",
                |s| s.ekf.r_std
            ),
            num!(
                "init_err",
                "observer",
                "",
                0.0,
                false,
                1.0,
                false,
                "initial relative estimation error",
                |s| s.init_error
            ),
            bool_field!(
                "perfect",
                "observer",
                "perfect observer: controller gets the true state (0/1)",
                |s| s.perfect
            ),
            num!(
                "noise",
                "noise",
                "A",
                0.0,
                false,
                10.0,
                false,
                "current-measurement noise std",
                |s| s.noise
            ),
            num!(
                "seed",
                "noise",
                "",
                0.0,
                false,
                MAX_SEED,
                true,
                "noise seed",
                |s| s.seed
            ),
        ];
        v.extend(motor!(
            plant, "plant", "plant.rs", "plant.rr", "plant.m", "plant.ls", "plant.lr", "plant.j",
            "plant.np", "plant.t0", "plant.cf"
        ));
        v.extend(motor!(
            model, "model", "model.rs", "model.rr", "model.m", "model.ls", "model.lr", "model.j",
            "model.np", "model.t0", "model.cf"
        ));
        v.extend([
            num!(
                "load.time",
                "load",
                "s",
                0.0,
                false,
                10.0,
                false,
                "time of the unknown load step",
                |s| s.load_step.time
            ),
            num!(
                "load.torque",
                "load",
                "N m",
                -1e4,
                false,
                1e4,
                false,
                "size of the unknown load step",
                |s| s.load_step.torque
            ),
            num!(
                "vmax",
                "limits",
                "V",
                0.0,
                true,
                1e5,
                false,
                "voltage limit per component",
                |s| s.voltage_limit
            ),
            num!(
                "duration",
                "limits",
                "s",
                0.0,
                true,
                MAX_DURATION,
                false,
                "simulated time",
                |s| s.duration
            ),
            num!(
                "ts",
                "limits",
                "s",
                1e-7,
                false,
                1e-2,
                false,
                "sampling period Ts",
                |s| s.ts
            ),
            num!(
                "substeps",
                "limits",
                "",
                1.0,
                false,
                1000.0,
                true,
                "plant RK4 substeps per sample",
                |s| s.substeps
            ),
        ]);
        v
    })
}

/// Longest simulated time accepted (s).
pub const MAX_DURATION: f64 = 20.0;
/// Most samples one run may take.
pub const MAX_STEPS: usize = 2_000_000;

impl Field {
    fn allowed(&self) -> String {
        match self.access {
            Access::Choice { options, .. } => options.join(" | "),
            Access::Number { .. } => {
                let lo = if self.min_open { "<" } else { "≤" };
                let unit = if self.unit.is_empty() {
                    String::new()
                } else {
                    format!(" ({})", self.unit)
                };
                let int = if self.integer { ", whole number" } else { "" };
                format!("{} {lo} {} ≤ {}{unit}{int}", self.min, self.key, self.max)
            }
        }
    }

    fn check(&self, value: f64) -> Result<(), ScenarioError> {
        let below = if self.min_open {
            value <= self.min
        } else {
            value < self.min
        };
        if !value.is_finite() || below || value > self.max || (self.integer && value.fract() != 0.0)
        {
            return Err(ScenarioError::OutOfRange {
                key: self.key.to_string(),
                value,
                allowed: self.allowed(),
            });
        }
        Ok(())
    }

    /// The field's value in `s` as written in the codec, or None when it does not apply.
    pub fn get(&self, s: &Scenario) -> Option<String> {
        match self.access {
            Access::Number { get, .. } => get(s).map(|v| format!("{v}")),
            Access::Choice { get, .. } => Some(get(s).to_string()),
        }
    }

    fn set(&self, s: &mut Scenario, value: &str) -> Result<(), ScenarioError> {
        match self.access {
            Access::Choice { options, set, .. } => {
                if !options.contains(&value) {
                    return Err(ScenarioError::BadValue {
                        key: self.key.to_string(),
                        value: value.to_string(),
                        expected: format!("one of {}", options.join(", ")),
                    });
                }
                set(s, value);
                Ok(())
            }
            Access::Number { set, .. } => {
                let v: f64 = parse_number(value).ok_or_else(|| ScenarioError::BadValue {
                    key: self.key.to_string(),
                    value: value.to_string(),
                    expected: "a decimal number".to_string(),
                })?;
                self.check(v)?;
                if !set(s, v) {
                    return Err(ScenarioError::NotApplicable {
                        key: self.key.to_string(),
                        reference: s.reference.kind(),
                    });
                }
                Ok(())
            }
        }
    }

    /// This field as data, with its value in `s`.
    pub fn info(&self, s: &Scenario) -> FieldInfo {
        FieldInfo {
            key: self.key,
            group: self.group,
            unit: self.unit,
            min: self.min,
            min_open: self.min_open,
            max: self.max,
            integer: self.integer,
            options: match self.access {
                Access::Choice { options, .. } => options,
                Access::Number { .. } => &[],
            },
            doc: self.doc,
            value: self.get(s),
            acts: acts(self.key, s),
        }
    }
}

/// Parses a plain decimal number; refuses Rust's extras ("inf", "nan", "+") that a URL should not carry.
fn parse_number(text: &str) -> Option<f64> {
    let ok = !text.is_empty()
        && text
            .bytes()
            .all(|c| c.is_ascii_digit() || matches!(c, b'.' | b'-' | b'e' | b'E'))
        && text.bytes().any(|c| c.is_ascii_digit());
    if ok {
        text.parse().ok()
    } else {
        None
    }
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
    /// piece or field is noted and that piece is skipped.
    fn parse_with(
        text: &str,
        lenient: bool,
    ) -> Result<(Scenario, Vec<ScenarioError>), ScenarioError> {
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
        let mut pairs: Vec<(&str, &str)> = Vec::new();
        for piece in text.split('&').filter(|p| !p.is_empty()) {
            match piece.split_once('=') {
                Some((k, _)) if pairs.iter().any(|(seen, _)| *seen == k) => {
                    note(ScenarioError::DuplicateKey { key: k.to_string() })?
                }
                Some(pair) => pairs.push(pair),
                None => note(ScenarioError::Malformed {
                    piece: piece.to_string(),
                })?,
            }
        }
        let lookup = |key: &str| pairs.iter().find(|(k, _)| *k == key).map(|(_, v)| *v);
        let version = lookup("v").ok_or(ScenarioError::Missing { key: "v" })?;
        if version != CODEC_VERSION.to_string() {
            return Err(ScenarioError::UnsupportedVersion {
                value: version.to_string(),
            });
        }
        let name = lookup("preset").ok_or(ScenarioError::Missing { key: "preset" })?;
        let mut s = preset(name).ok_or_else(|| ScenarioError::UnknownPreset {
            name: name.to_string(),
        })?;
        for (k, _) in &pairs {
            if !matches!(*k, "v" | "preset") && !fields().iter().any(|f| f.key == *k) {
                note(ScenarioError::UnknownKey { key: k.to_string() })?;
            }
        }
        // Apply in field order so `ref=` (which resets the reference parameters) comes first.
        // Strictly, cross-field checks wait for the whole scenario (so no order of fields matters);
        // leniently, each field must leave a valid scenario, so a bad one can be singled out.
        for field in fields() {
            if let Some(value) = lookup(field.key) {
                if !lenient {
                    field.set(&mut s, value)?;
                    continue;
                }
                let mut trial = s.clone();
                match field.set(&mut trial, value).and_then(|()| trial.validate()) {
                    Ok(()) => s = trial,
                    Err(e) => note(e)?,
                }
            }
        }
        s.validate()?;
        Ok((s, errors))
    }

    /// The compact scenario string: version, preset, then only the fields that differ from it.
    pub fn encode(&self) -> String {
        let original = preset(&self.preset).expect("a scenario's preset exists");
        // After `ref=` switches kind, the reference parameters differ from that kind's defaults.
        let mut base = original.clone();
        if base.reference.kind() != self.reference.kind() {
            base.reference = default_reference(self.reference.kind()).expect("known kind");
        }
        let mut out = format!("v={CODEC_VERSION}&preset={}", self.preset);
        for field in fields() {
            let theirs = field.get(if field.key == "ref" { &original } else { &base });
            if let Some(mine) = field.get(self).filter(|m| Some(m) != theirs.as_ref()) {
                out.push('&');
                out.push_str(field.key);
                out.push('=');
                out.push_str(&mine);
            }
        }
        out
    }

    /// Sets one field from its codec text, then checks the whole scenario.
    pub fn set(&mut self, key: &str, value: &str) -> Result<(), ScenarioError> {
        let field =
            fields()
                .iter()
                .find(|f| f.key == key)
                .ok_or_else(|| ScenarioError::UnknownKey {
                    key: key.to_string(),
                })?;
        field.set(self, value)?;
        self.validate()
    }

    /// Checks every field's range and the physics of both parameter sets.
    pub fn validate(&self) -> Result<(), ScenarioError> {
        if preset(&self.preset).is_none() {
            return Err(ScenarioError::UnknownPreset {
                name: self.preset.clone(),
            });
        }
        for field in fields() {
            if let Access::Number { get, .. } = field.access {
                if let Some(v) = get(self) {
                    field.check(v)?;
                }
            }
        }
        for (which, p) in [("plant", &self.plant), ("model", &self.model)] {
            p.lumped()
                .map_err(|error| ScenarioError::Physics { which, error })?;
        }
        let steps = self.steps();
        if steps > MAX_STEPS {
            return Err(ScenarioError::TooLarge {
                what: format!(
                    "duration/ts = {} s / {} s = {steps} samples is more than the {MAX_STEPS} allowed; \
                     shorten 'duration' or raise 'ts'",
                    self.duration, self.ts
                ),
            });
        }
        if steps == 0 {
            return Err(ScenarioError::TooLarge {
                what: format!(
                    "duration {} s is shorter than one sample ts = {} s",
                    self.duration, self.ts
                ),
            });
        }
        Ok(())
    }

    /// Number of samples simulated: round(duration / ts).
    pub fn steps(&self) -> usize {
        let n = (self.duration / self.ts).round();
        if n > MAX_STEPS as f64 * 2.0 {
            usize::MAX
        } else {
            n as usize
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

#[cfg(test)]
mod tests {
    use super::*;
    use crate::rng::Rng;

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
    fn only_fields_that_act_are_marked_so() {
        let acting = |text: &str, key: &str| {
            let s = Scenario::parse(text).unwrap();
            s.describe().iter().find(|f| f.key == key).unwrap().acts
        };
        assert!(!acting("v=1&preset=step", "ifoc.bw_i"));
        assert!(acting("v=1&preset=ifoc-step", "ifoc.bw_i"));
        assert!(!acting("v=1&preset=step&robust=0", "eps2"));
        assert!(acting("v=1&preset=step&robust=1", "h4"));
        assert!(acting("v=1&preset=step", "k1"));
    }

    #[test]
    fn example_from_the_issue() {
        let s = Scenario::parse("v=1&preset=step&step.size=0.3&noise=0.004").unwrap();
        assert_eq!(s.noise, 0.004);
        assert!(matches!(s.reference, Reference::Step { size, .. } if size == 0.3));
        assert_eq!(s.encode(), "v=1&preset=step&step.size=0.3&noise=0.004");
    }

    fn random_value(f: &Field, rng: &mut Rng) -> String {
        match f.access {
            Access::Choice { options, .. } => {
                options[(rng.next_u64() % options.len() as u64) as usize].to_string()
            }
            Access::Number { .. } => {
                let (lo, hi) = (f.min.max(-1e3), f.max.min(1e3));
                let mut v = lo + (hi - lo) * rng.uniform();
                if f.integer {
                    v = v.round().clamp(f.min, f.max);
                }
                if f.min_open && v <= f.min {
                    v = hi;
                }
                format!("{v}")
            }
        }
    }

    #[test]
    fn random_valid_scenarios_round_trip() {
        let mut rng = Rng::new(99);
        let mut accepted = 0;
        for _ in 0..2000 {
            let name = PRESETS[(rng.next_u64() % PRESETS.len() as u64) as usize].name;
            let mut text = format!("v=1&preset={name}");
            let mut s = preset(name).unwrap();
            for f in fields() {
                if rng.uniform() < 0.3 {
                    let value = random_value(f, &mut rng);
                    // Only keep values the field accepts in this state; the rest is the reject test's job.
                    let mut trial = s.clone();
                    if f.set(&mut trial, &value).is_ok() {
                        s = trial;
                        text.push_str(&format!("&{}={value}", f.key));
                    }
                }
            }
            let Ok(parsed) = Scenario::parse(&text) else {
                continue;
            };
            accepted += 1;
            let encoded = parsed.encode();
            let again = Scenario::parse(&encoded).unwrap();
            assert_eq!(again, parsed, "{text} -> {encoded}");
            assert_eq!(again.encode(), encoded);
        }
        assert!(
            accepted > 200,
            "only {accepted} random scenarios were valid"
        );
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
    fn fuzzed_strings_never_panic_and_errors_name_something() {
        let mut rng = Rng::new(5);
        let alphabet = b"v=1&preset=stepk.0123456789-eE.sinamprf";
        for _ in 0..20_000 {
            let len = (rng.next_u64() % 40) as usize;
            let text: String = (0..len)
                .map(|_| alphabet[(rng.next_u64() % alphabet.len() as u64) as usize] as char)
                .collect();
            if let Err(e) = Scenario::parse(&text) {
                assert!(!e.to_string().is_empty());
            }
        }
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
    fn cross_field_checks_wait_for_the_whole_scenario() {
        // plant.m = 0.6 alone makes σ < 0; with plant.ls = 1 as well it is physical.
        let s = Scenario::parse("v=1&preset=step&plant.m=0.6&plant.ls=1").unwrap();
        assert!(s.plant.sigma() > 0.0);
        assert_eq!(
            Scenario::parse_lenient("v=1&preset=step&plant.m=0.6&plant.ls=1")
                .unwrap()
                .1,
            vec![]
        );
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
}
