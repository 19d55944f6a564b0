//! The field table of the codec, written once: each field's key, group, unit, allowed values
//! and place in [`Scenario`]; its meaning is its message `field-KEY` of `core-run.ftl`.

use super::origin::{resets, set_design, set_motor};
use super::presets::default_reference;
use super::{ControllerKind, DesignKind, Scenario, ScenarioError, Start};
use crate::control::{Points, PointsError, Reference, MAX_POINTS};
use crate::inverter::Shape;
use crate::motors::{motor, MOTOR_NAMES};
use crate::observer::Predictor;
use crate::text::percent::{self, Plus};
use crate::text::Message;
use serde::Serialize;

/// Largest seed: the largest integer a JavaScript number holds exactly (2^53 − 1), so that the
/// page reads every seed as the CLI does.
pub const MAX_SEED: u64 = (1 << 53) - 1;

/// Longest simulated time accepted (s).
pub const MAX_DURATION: f64 = 20.0;

/// How a field's value is read and written.
#[derive(Clone, Copy)]
pub(super) enum Access {
    Number {
        get: fn(&Scenario) -> Option<f64>,
        set: fn(&mut Scenario, f64) -> bool,
    },
    Choice {
        options: &'static [&'static str],
        get: fn(&Scenario) -> &'static str,
        set: fn(&mut Scenario, &str),
    },
    /// The law of backstepping step `step` (1–4): a formula, percent-encoded in the codec.
    Formula { step: u8 },
    /// A table of points `t:value,...` (a reference or a load torque); its range bounds the values,
    /// `slope` the change per second between points, and `empty` says whether no points is a value.
    Table {
        get: fn(&Scenario) -> Option<Points>,
        set: fn(&mut Scenario, Points) -> bool,
        slope: f64,
        empty: bool,
    },
}

/// The values a number field takes.
#[derive(Clone, Copy)]
struct Range {
    min: f64,
    min_open: bool,
    max: f64,
    integer: bool,
}

/// min ≤ value ≤ max.
const fn closed(min: f64, max: f64) -> Range {
    Range {
        min,
        min_open: false,
        max,
        integer: false,
    }
}

/// min < value ≤ max.
const fn above(min: f64, max: f64) -> Range {
    Range {
        min,
        min_open: true,
        max,
        integer: false,
    }
}

/// Whole numbers from min to max.
const fn whole(min: f64, max: f64) -> Range {
    Range {
        min,
        min_open: false,
        max,
        integer: true,
    }
}

/// One field of the codec: its key, unit, allowed range and the id of its meaning.
#[derive(Clone, Copy)]
pub(super) struct Field {
    pub(super) key: &'static str,
    group: &'static str,
    pub(super) unit: &'static str,
    range: Range,
    /// The message of its meaning, `field-KEY` (a dot of the key written as a hyphen).
    doc: &'static str,
    pub(super) access: Access,
}

/// A field as data, for the UI and `describe`.
#[cfg_attr(
    target_arch = "wasm32",
    derive(tsify::Tsify),
    tsify(missing_as_null, hashmap_as_object)
)]
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
    /// For a field that holds a formula, a step's own law: the step (1–4); its value is then the
    /// formula's text, not its codec text.
    pub formula: Option<u8>,
    /// For a table of points (`t:value,...`), the most points it holds; `min` and `max` bound its
    /// values, and its times run from 0 to the longest run.
    pub points: Option<u8>,
    /// Meaning (`field-KEY` of `core-run.ftl`).
    pub doc: Message,
    /// Current value as written in the codec, or None when it does not apply.
    pub value: Option<String>,
    /// Whether the field acts on this scenario (the page shows only those): the IFOC tuning only
    /// with the IFOC controller, ε and h only with the robust terms on, `vmax` only with the box
    /// limit, `vdc` only with the circle or hex limit or PWM, `delay.comp` only with the delay and
    /// the backstepping controller.
    pub acts: bool,
    /// The fields a new value of this one sets afresh (`ref=` the new kind's parameters, `motor=`
    /// the plant's and the model's circuit and the rating): a form that changes this field leaves
    /// those out, or their old values would undo it or not apply.
    pub resets: &'static [&'static str],
}

/// Why field `key` changes nothing in scenario `s`: the settings that leave it idle, as the codec
/// writes them (`controller=ifoc`); None when it acts. The IFOC tuning acts only with the IFOC
/// controller; the backstepping gains, its robust terms, its own laws and the perfect observer (which
/// only the backstepping controller reads) only with the backstepping controller; ε and h only
/// with the robust terms on; the EKF's load and R_r tuning only with those states on; `vmax` only
/// with the box limit; `vdc` only with the circle or hex limit or PWM; `delay.comp` only with the
/// delay and the backstepping controller; the load step only without a load table.
pub(super) fn idle_because(key: &str, s: &Scenario) -> Option<String> {
    let ifoc = s.controller == ControllerKind::Ifoc;
    let backstepping_only =
        matches!(key, "k1" | "k2" | "k3" | "k4" | "robust" | "perfect") || key.starts_with("law.");
    let reason = |idle: bool, why: &str| idle.then(|| why.to_string());
    if key.starts_with("ifoc.") {
        reason(!ifoc, "controller=backstepping")
    } else if backstepping_only {
        reason(ifoc, "controller=ifoc")
    } else if matches!(key, "eps2" | "h2" | "eps4" | "h4") {
        reason(ifoc, "controller=ifoc").or(reason(!s.gains.robust, "robust=0"))
    } else if matches!(key, "ekf.q_load" | "ekf.load_std") {
        reason(!s.ekf.load, "ekf.load=0")
    } else if matches!(key, "ekf.q_rr" | "ekf.rr_std") {
        reason(!s.ekf.rr, "ekf.rr=0")
    } else if key == "vmax" {
        (s.drive.vlimit != Shape::Box).then(|| {
            let vlimit = field("vlimit").and_then(|f| f.get(s)).unwrap_or_default();
            format!("vlimit={vlimit}")
        })
    } else if key == "vdc" {
        reason(
            s.drive.vlimit == Shape::Box && !s.drive.pwm,
            "vlimit=box, pwm=0",
        )
    } else if key == "fw" {
        reason(ifoc, "controller=ifoc")
    } else if key == "fw.base" {
        reason(ifoc, "controller=ifoc").or(reason(!s.fw, "fw=0"))
    } else if matches!(key, "rated.v" | "rated.f") {
        reason(s.design == DesignKind::Paper, "design=paper")
    } else if key == "delay.comp" {
        reason(ifoc, "controller=ifoc").or(reason(!s.drive.delay, "delay=0"))
    } else if matches!(key, "load.time" | "load.torque") {
        (!s.load_step.table.is_empty()).then(|| "load.table".to_string())
    } else {
        None
    }
}

/// A number stored at `s.<path>` (any numeric type).
macro_rules! at {
    ($($path:ident).+) => {
        Access::Number {
            get: |s| Some(s.$($path).+ as f64),
            set: |s, v| {
                s.$($path).+ = v as _;
                true
            },
        }
    };
}

/// A 0/1 switch stored as a bool at `s.<path>`.
macro_rules! flag {
    ($($path:ident).+) => {
        Access::Number {
            get: |s| Some(if s.$($path).+ { 1.0 } else { 0.0 }),
            set: |s, v| {
                s.$($path).+ = v == 1.0;
                true
            },
        }
    };
}

/// Parameter `field` of the reference kind `Variant`; absent under the other kinds.
macro_rules! reference {
    ($variant:ident . $field:ident) => {
        Access::Number {
            get: |s| match s.reference {
                Reference::$variant { $field, .. } => Some($field),
                _ => None,
            },
            set: |s, v| match &mut s.reference {
                Reference::$variant { $field, .. } => {
                    *$field = v;
                    true
                }
                _ => false,
            },
        }
    };
}

/// The nine parameters of one motor (`plant` or `model`). The lower bounds keep the lumped
/// parameters (a1 = np·M/(J·Lr), 1/σ, ...) finite: a value that is numerically zero is refused.
macro_rules! motor {
    ($which:ident) => {
        [
            number(
                concat!(stringify!($which), ".rs"),
                stringify!($which),
                "Ω",
                closed(1e-6, 1000.0),
                at!($which.rs),
            ),
            number(
                concat!(stringify!($which), ".rr"),
                stringify!($which),
                "Ω",
                closed(1e-6, 1000.0),
                at!($which.rr),
            ),
            number(
                concat!(stringify!($which), ".m"),
                stringify!($which),
                "H",
                closed(1e-6, 100.0),
                at!($which.m),
            ),
            number(
                concat!(stringify!($which), ".ls"),
                stringify!($which),
                "H",
                closed(1e-6, 100.0),
                at!($which.ls),
            ),
            number(
                concat!(stringify!($which), ".lr"),
                stringify!($which),
                "H",
                closed(1e-6, 100.0),
                at!($which.lr),
            ),
            number(
                concat!(stringify!($which), ".j"),
                stringify!($which),
                "kg m²",
                closed(1e-6, 1e4),
                at!($which.j),
            ),
            number(
                concat!(stringify!($which), ".np"),
                stringify!($which),
                "",
                whole(1.0, 50.0),
                at!($which.np),
            ),
            number(
                concat!(stringify!($which), ".t0"),
                stringify!($which),
                "N m",
                closed(0.0, 1e4),
                at!($which.t0),
            ),
            number(
                concat!(stringify!($which), ".cf"),
                stringify!($which),
                "N m s",
                closed(0.0, 1e3),
                at!($which.cf),
            ),
        ]
    };
}

const fn number(
    key: &'static str,
    group: &'static str,
    unit: &'static str,
    range: Range,
    access: Access,
) -> Field {
    Field {
        key,
        group,
        unit,
        range,
        doc: "",
        access,
    }
}

const fn choice(key: &'static str, group: &'static str, access: Access) -> Field {
    Field {
        key,
        group,
        unit: "",
        range: closed(0.0, 0.0),
        doc: "",
        access,
    }
}

const fn law(key: &'static str, unit: &'static str, step: u8) -> Field {
    Field {
        key,
        group: "law",
        unit,
        range: closed(0.0, 0.0),
        doc: "",
        access: Access::Formula { step },
    }
}

/// A formula as the codec writes it: every byte but the letters, digits and `-._~*()`
/// percent-encoded (so `+`, `&`, `=` and spaces survive any query string).
pub(crate) fn encode_formula(text: &str) -> String {
    percent::encode(text, b"-._~*()")
}

/// A formula's text from its codec text: `%XX` decoded, everything else kept (a `+` is a plus,
/// not a space); None unless the bytes decoded are UTF-8.
pub(crate) fn decode_formula(text: &str) -> Option<String> {
    percent::decode(text, Plus::Plus)
}

fn set_reference(s: &mut Scenario, name: &str) {
    // Keep the parameters when the kind does not change.
    if s.reference.kind() != name {
        s.reference = default_reference(name).expect("checked option");
    }
}

/// Every field of the codec, in the order the encoder writes them (`ref` first: it resets the
/// reference parameters).
#[rustfmt::skip]
fn table() -> Vec<Field> {
    let mut v = vec![
        choice("design", "gains", Access::Choice {
            options: &["paper", "derived"],
            get: |s| match s.design { DesignKind::Paper => "paper", DesignKind::Derived => "derived" },
            set: set_design,
        }),
        choice("ref", "reference", Access::Choice {
            options: &["constant", "sine", "step", "ramp", "reversal", "table"], get: |s| s.reference.kind(), set: set_reference,
        }),
        number("ref.value", "reference", "rad/s", closed(-1000.0, 1000.0), reference!(Constant.value)),
        number("sine.amp", "reference", "rad/s", closed(0.0, 1000.0), reference!(Sine.amp)),
        number("sine.freq", "reference", "Hz", closed(0.0, 5000.0), reference!(Sine.freq)),
        number("sine.offset", "reference", "rad/s", closed(-1000.0, 1000.0), reference!(Sine.offset)),
        number("step.size", "reference", "rad/s", closed(-1000.0, 1000.0), reference!(Step.size)),
        number("step.time", "reference", "s", closed(0.0, 10.0), reference!(Step.time)),
        number("step.wn", "reference", "rad/s", above(0.0, 1e5), reference!(Step.wn)),
        number("ramp.start", "reference", "s", closed(0.0, 10.0), reference!(Ramp.start)),
        number("ramp.level", "reference", "rad/s", closed(-1000.0, 1000.0), reference!(Ramp.level)),
        number("ramp.slope", "reference", "rad/s²", above(0.0, 1e6), reference!(Ramp.slope)),
        number("ramp.hold", "reference", "s", closed(0.0, 10.0), reference!(Ramp.hold)),
        number("rev.start", "reference", "s", closed(0.0, 10.0), reference!(Reversal.start)),
        number("rev.level", "reference", "rad/s", closed(-1000.0, 1000.0), reference!(Reversal.level)),
        number("rev.slope", "reference", "rad/s²", above(0.0, 1e6), reference!(Reversal.slope)),
        number("rev.hold", "reference", "s", closed(0.0, 10.0), reference!(Reversal.hold)),
        // A reference table's slopes are bounded as the ramp's are; it needs a point.
        number("ref.table", "reference", "rad/s", closed(-1000.0, 1000.0), Access::Table {
            get: |s| match s.reference { Reference::Table { points } => Some(points), _ => None },
            set: |s, p| match &mut s.reference { Reference::Table { points } => { *points = p; true } _ => false },
            slope: 1e6,
            empty: false,
        }),
        number("psi_d", "reference", "Wb²", above(0.0, 4.0), at!(psi_d)),
        number("fw", "reference", "", whole(0.0, 1.0), flag!(fw)),
        number("fw.base", "reference", "rad/s", above(0.0, 1e4), at!(fw_base)),
        number("k1", "gains", "1/s", above(0.0, 1e6), at!(gains.k1)),
        number("k2", "gains", "1/s", above(0.0, 1e6), at!(gains.k2)),
        number("k3", "gains", "1/s", above(0.0, 1e6), at!(gains.k3)),
        number("k4", "gains", "1/s", above(0.0, 1e6), at!(gains.k4)),
        number("robust", "gains", "", whole(0.0, 1.0), flag!(gains.robust)),
        number("eps2", "gains", "rad²/s⁵", above(0.0, 1e6), at!(gains.eps2)),
        number("h2", "gains", "rad/s³", closed(0.0, 1e9), at!(gains.h2)),
        number("eps4", "gains", "Wb⁴/s³", above(0.0, 1e6), at!(gains.eps4)),
        number("h4", "gains", "Wb²/s²", closed(0.0, 1e9), at!(gains.h4)),
        law("law.v1", "rad/s²", 1),
        law("law.v2", "rad/s³", 2),
        law("law.v3", "Wb²/s", 3),
        law("law.v4", "Wb²/s²", 4),
        choice("controller", "controller", Access::Choice {
            options: &["backstepping", "ifoc"],
            get: |s| match s.controller { ControllerKind::Backstepping => "backstepping", ControllerKind::Ifoc => "ifoc" },
            set: |s, name| s.controller = if name == "ifoc" { ControllerKind::Ifoc } else { ControllerKind::Backstepping },
        }),
        number("ifoc.bw_i", "controller", "Hz", above(0.0, 5000.0), at!(ifoc.current_bw)),
        number("ifoc.bw_w", "controller", "Hz", above(0.0, 1000.0), at!(ifoc.speed_bw)),
        number("ifoc.bw_mras", "controller", "Hz", above(0.0, 5000.0), at!(ifoc.mras_bw)),
        number("ifoc.i_max", "controller", "A", above(0.0, 1000.0), at!(ifoc.current_limit)),
        number("ifoc.ff", "controller", "", whole(0.0, 1.0), flag!(ifoc.ff)),
        choice("ekf", "observer", Access::Choice {
            options: &["euler", "rk4"],
            get: |s| match s.ekf.predictor { Predictor::Euler => "euler", Predictor::Rk4 => "rk4" },
            set: |s, name| s.ekf.predictor = if name == "rk4" { Predictor::Rk4 } else { Predictor::Euler },
        }),
        number("ekf.q", "observer", "(state unit)²/s", above(0.0, 1e6), at!(ekf.q)),
        number("ekf.q_speed", "observer", "(rad/s)²/s", closed(0.0, 1e10), at!(ekf.q_speed)),
        // R = r_std²·I must stay a positive number: below 1 µA it is numerically zero for the
        // innovation covariance S = HPHᵀ + R once P has converged.
        number("ekf.r_std", "observer", "A", closed(1e-6, 10.0), at!(ekf.r_std)),
        number("ekf.load", "observer", "", whole(0.0, 1.0), flag!(ekf.load)),
        number("ekf.q_load", "observer", "N² m²/s", above(0.0, 1e8), at!(ekf.q_load)),
        number("ekf.load_std", "observer", "N m", above(0.0, 1e4), at!(ekf.load_std)),
        number("ekf.rr", "observer", "", whole(0.0, 1.0), flag!(ekf.rr)),
        number("ekf.q_rr", "observer", "Ω²/s", above(0.0, 1e6), at!(ekf.q_rr)),
        number("ekf.rr_std", "observer", "Ω", above(0.0, 1000.0), at!(ekf.rr_std)),
        number("init_err", "observer", "", closed(0.0, 1.0), at!(init_error)),
        choice("start", "observer", Access::Choice {
            options: &["paper", "magnetized"],
            get: |s| match s.start { Start::Paper => "paper", Start::Magnetized => "magnetized" },
            set: |s, name| s.start = if name == "magnetized" { Start::Magnetized } else { Start::Paper },
        }),
        number("perfect", "observer", "", whole(0.0, 1.0), flag!(perfect)),
        number("noise", "noise", "A", closed(0.0, 10.0), at!(noise)),
        number("seed", "noise", "", whole(0.0, MAX_SEED as f64), at!(seed)),
    ];
    v.push(choice("motor", "plant", Access::Choice {
        options: MOTOR_NAMES, get: |s| motor(&s.motor).map_or("paper", |m| m.name), set: set_motor,
    }));
    v.extend(motor!(plant));
    v.extend(motor!(model));
    v.extend([
        number("load.time", "load", "s", closed(0.0, 10.0), at!(load_step.time)),
        number("load.torque", "load", "N m", closed(-1e4, 1e4), at!(load_step.torque)),
        // An empty load table leaves the load step; the plant takes any change of load.
        number("load.table", "load", "N m", closed(-1e4, 1e4), Access::Table {
            get: |s| Some(s.load_step.table),
            set: |s, p| { s.load_step.table = p; true },
            slope: f64::INFINITY,
            empty: true,
        }),
        number("vmax", "limits", "V", above(0.0, 1e5), at!(voltage_limit)),
        number("duration", "limits", "s", above(0.0, MAX_DURATION), at!(duration)),
        number("ts", "limits", "s", closed(1e-7, 1e-2), at!(ts)),
        number("substeps", "limits", "", whole(1.0, 1000.0), at!(substeps)),
        number("i_rated", "limits", "A", above(0.0, 1e4), at!(i_rated)),
        number("rated.v", "limits", "V", above(0.0, 1e5), at!(rated_v)),
        number("rated.f", "limits", "Hz", above(0.0, 1e4), at!(rated_f)),
        number("delay", "drive", "", whole(0.0, 1.0), flag!(drive.delay)),
        number("delay.comp", "drive", "", whole(0.0, 1.0), flag!(drive.delay_comp)),
        choice("vlimit", "drive", Access::Choice {
            options: &["box", "circle", "hex"],
            get: |s| match s.drive.vlimit { Shape::Box => "box", Shape::Circle => "circle", Shape::Hex => "hex" },
            set: |s, name| s.drive.vlimit = match name { "circle" => Shape::Circle, "hex" => Shape::Hex, _ => Shape::Box },
        }),
        number("vdc", "drive", "V", above(0.0, 1e5), at!(drive.vdc)),
        number("pwm", "drive", "", whole(0.0, 1.0), flag!(drive.pwm)),
    ]);
    // The id of each field's meaning, made once for the table's life.
    for f in &mut v {
        f.doc = Box::leak(format!("field-{}", f.key.replace('.', "-")).into_boxed_str());
    }
    v
}

/// Every field of the codec, in the order the encoder writes them.
pub(super) fn fields() -> &'static [Field] {
    static FIELDS: std::sync::OnceLock<Vec<Field>> = std::sync::OnceLock::new();
    FIELDS.get_or_init(table)
}

/// The field called `key`, found by hashing (parsing stays linear in the number of pieces).
pub(super) fn field(key: &str) -> Option<&'static Field> {
    static INDEX: std::sync::OnceLock<std::collections::HashMap<&'static str, usize>> =
        std::sync::OnceLock::new();
    let index = INDEX.get_or_init(|| {
        fields()
            .iter()
            .enumerate()
            .map(|(i, f)| (f.key, i))
            .collect()
    });
    index.get(key).map(|&i| &fields()[i])
}

impl Field {
    fn allowed(&self) -> Message {
        match self.access {
            Access::Choice { options, .. } => {
                Message::new("scenario-allowed-choice").text("options", options.join(" | "))
            }
            Access::Formula { step } => {
                Message::new("scenario-allowed-formula").count("step", step)
            }
            Access::Table { .. } => Message::new("scenario-allowed-table")
                .count("max", MAX_POINTS)
                .real("duration", MAX_DURATION)
                .said("values", self.value_range()),
            Access::Number { .. } => self.value_range(),
        }
    }

    /// The range of its numbers (of a table, its values), with the unit and whether whole.
    fn value_range(&self) -> Message {
        let Range {
            min,
            min_open,
            max,
            integer,
        } = self.range;
        let range = Message::new("scenario-allowed-range")
            .real("min", min)
            .text("below", if min_open { "<" } else { "≤" })
            .text("key", self.key)
            .real("max", max);
        let range = if self.unit.is_empty() {
            range
        } else {
            Message::new("scenario-allowed-unit")
                .said("range", range)
                .text("unit", self.unit)
        };
        if integer {
            Message::new("scenario-allowed-whole").said("range", range)
        } else {
            range
        }
    }

    /// Whether table `p` fits the field: a point at least where the field needs one, its times
    /// from 0 to the longest run, its values in the field's range, its slopes within the field's.
    pub(super) fn check_points(&self, p: &Points) -> Result<(), ScenarioError> {
        let Access::Table { slope, empty, .. } = self.access else {
            return Ok(());
        };
        let bad = |expected: Message| ScenarioError::BadValue {
            key: self.key.to_string(),
            value: p.encode(),
            expected,
        };
        if p.is_empty() && !empty {
            return Err(bad(Message::new("scenario-expected-table")));
        }
        let pairs: Vec<(f64, f64)> = p.pairs().collect();
        for w in pairs.windows(2) {
            let rate = (w[1].1 - w[0].1) / (w[1].0 - w[0].0);
            if rate.abs() > slope {
                return Err(bad(Message::new("scenario-expected-table-slope")
                    .real("max", slope)
                    .text("unit", self.unit)
                    .short("before", w[0].0)
                    .short("after", w[1].0)));
            }
        }
        for (t, v) in p.pairs() {
            if !(0.0..=MAX_DURATION).contains(&t) {
                return Err(ScenarioError::BadValue {
                    key: self.key.to_string(),
                    value: p.encode(),
                    expected: Message::new("scenario-expected-table-time")
                        .short("t", t)
                        .real("max", MAX_DURATION),
                });
            }
            self.check(v)?;
        }
        Ok(())
    }

    /// Whether `value` is in the field's range.
    pub(super) fn check(&self, value: f64) -> Result<(), ScenarioError> {
        let Range {
            min,
            min_open,
            max,
            integer,
        } = self.range;
        let below = if min_open { value <= min } else { value < min };
        if !value.is_finite() || below || value > max || (integer && value.fract() != 0.0) {
            return Err(ScenarioError::OutOfRange {
                key: self.key.to_string(),
                value,
                allowed: self.allowed(),
            });
        }
        Ok(())
    }

    /// The field's value in `s` as written in the codec, or None when it does not apply.
    pub(super) fn get(&self, s: &Scenario) -> Option<String> {
        match self.access {
            Access::Number { get, .. } => get(s).map(|v| format!("{v}")),
            Access::Choice { get, .. } => Some(get(s).to_string()),
            Access::Formula { step } => Some(encode_formula(
                s.law[step as usize - 1].as_deref().unwrap_or(""),
            )),
            Access::Table { get, .. } => get(s).map(|p| p.encode()),
        }
    }

    /// Sets the field in `s` from its codec text, checking the field's own range.
    pub(super) fn set(&self, s: &mut Scenario, value: &str) -> Result<(), ScenarioError> {
        match self.access {
            Access::Formula { step } => {
                let text = decode_formula(value).ok_or_else(|| ScenarioError::BadValue {
                    key: self.key.to_string(),
                    value: value.to_string(),
                    expected: Message::new("scenario-expected-formula"),
                })?;
                if text.trim().is_empty() {
                    s.law[step as usize - 1] = None;
                    return Ok(());
                }
                crate::control::formula::Program::parse(&text, step).map_err(|error| {
                    ScenarioError::BadFormula {
                        key: self.key,
                        error,
                    }
                })?;
                s.law[step as usize - 1] = Some(text);
                Ok(())
            }
            Access::Table { set, .. } => {
                let bad = |expected: Message| ScenarioError::BadValue {
                    key: self.key.to_string(),
                    value: value.to_string(),
                    expected,
                };
                // A page or a mail client may have escaped the `:` and `,`.
                let text = percent::decode(value, Plus::Plus)
                    .ok_or_else(|| bad(Message::new("scenario-expected-table")))?;
                let points = Points::parse(&text).map_err(|e| {
                    bad(match e {
                        PointsError::Syntax => Message::new("scenario-expected-table"),
                        PointsError::TooMany { count } => {
                            Message::new("scenario-expected-table-length")
                                .count("count", count)
                                .count("max", MAX_POINTS)
                        }
                        PointsError::NotRising { before, after } => {
                            Message::new("scenario-expected-table-rising")
                                .short("before", before)
                                .short("after", after)
                        }
                    })
                })?;
                self.check_points(&points)?;
                if !set(s, points) {
                    return Err(ScenarioError::NotApplicable {
                        key: self.key.to_string(),
                        reference: s.reference.kind(),
                    });
                }
                Ok(())
            }
            Access::Choice { options, set, .. } => {
                if !options.contains(&value) {
                    return Err(ScenarioError::BadValue {
                        key: self.key.to_string(),
                        value: value.to_string(),
                        expected: Message::new("scenario-expected-one-of")
                            .text("options", options.join(", ")),
                    });
                }
                set(s, value);
                Ok(())
            }
            Access::Number { set, .. } => {
                let v: f64 = parse_number(value).ok_or_else(|| ScenarioError::BadValue {
                    key: self.key.to_string(),
                    value: value.to_string(),
                    expected: Message::new("scenario-expected-number"),
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
    pub(super) fn info(&self, s: &Scenario) -> FieldInfo {
        let Range {
            min,
            min_open,
            max,
            integer,
        } = self.range;
        FieldInfo {
            key: self.key,
            group: self.group,
            unit: self.unit,
            min,
            min_open,
            max,
            integer,
            options: match self.access {
                Access::Choice { options, .. } => options,
                Access::Number { .. } | Access::Formula { .. } | Access::Table { .. } => &[],
            },
            formula: match self.access {
                Access::Formula { step } => Some(step),
                _ => None,
            },
            points: match self.access {
                Access::Table { .. } => Some(MAX_POINTS as u8),
                _ => None,
            },
            doc: Message::new(self.doc),
            value: match self.access {
                Access::Formula { step } => {
                    Some(s.law[step as usize - 1].clone().unwrap_or_default())
                }
                _ => self.get(s),
            },
            acts: idle_because(self.key, s).is_none(),
            resets: resets(self.key, s),
        }
    }
}

/// Parses a plain decimal number; refuses Rust's extras ("inf", "nan", "+") that a URL should not carry.
pub(crate) fn parse_number(text: &str) -> Option<f64> {
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

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn every_field_says_what_it_means_and_the_models_parameters_read_as_the_plants() {
        let s = super::super::preset("step").unwrap();
        for f in fields() {
            let info = f.info(&s);
            assert_eq!(info.doc.id, format!("field-{}", f.key.replace('.', "-")));
            // A message the English lacks panics here.
            assert!(!info.doc.to_string().is_empty(), "{}", f.key);
            if let Some(parameter) = f.key.strip_prefix("model.") {
                let plant = field(&format!("plant.{parameter}")).unwrap().info(&s);
                assert_eq!(info.doc.to_string(), plant.doc.to_string());
            }
        }
        assert_eq!(
            field("k1").unwrap().info(&s).doc.to_string(),
            "speed-error rate k1"
        );
    }
}
