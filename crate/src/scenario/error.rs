//! Why a scenario string or value was refused, in words that name the field.

use super::{CODEC_VERSION, MAX_SCENARIO_BYTES, PRESETS};
use crate::params::ParamError;
use crate::text::{excerpt, Message};
use std::fmt;

/// Why a scenario string or value was refused. Every variant names the field (or the piece of
/// the string); input quoted in the message is shown through [`excerpt`].
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
        expected: Message,
    },
    /// A value outside the field's allowed range.
    OutOfRange {
        /// The field.
        key: String,
        /// The value given.
        value: f64,
        /// The allowed range, e.g. "0 < k1 ≤ 1000000 (1/s)".
        allowed: Message,
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
    /// A step's law that is not a formula of the language.
    BadFormula {
        /// The field (`law.v1`..`law.v4`).
        key: &'static str,
        /// Where and why.
        error: crate::control::formula::FormulaError,
    },
    /// A scenario string longer than [`MAX_SCENARIO_BYTES`].
    TooLong {
        /// Its length (bytes).
        bytes: usize,
    },
    /// A field that cannot be used with another setting of the scenario.
    Refused {
        /// The field.
        key: &'static str,
        /// Why.
        why: Message,
    },
    /// No design follows from the motor's data (`design=derived`).
    Design {
        /// Why.
        error: crate::design::DesignError,
    },
    /// A run that would need more steps or memory than allowed.
    TooLarge {
        /// What was too large and the limit.
        what: Message,
    },
}

impl ScenarioError {
    /// What the error says, as a message of `core-scenario.ftl`.
    pub fn message(&self) -> Message {
        use ScenarioError::*;
        let q = |text: &str| excerpt(text);
        match self {
            Missing { key } => Message::new("scenario-missing")
                .text("key", *key)
                .count("version", CODEC_VERSION),
            UnsupportedVersion { value } => Message::new("scenario-unsupported-version")
                .text("value", q(value))
                .count("version", CODEC_VERSION),
            UnknownPreset { name } => Message::new("scenario-unknown-preset")
                .text("name", q(name))
                .text(
                    "presets",
                    PRESETS
                        .iter()
                        .map(|p| p.name)
                        .collect::<Vec<_>>()
                        .join(", "),
                ),
            UnknownKey { key } => Message::new("scenario-unknown-key").text("key", q(key)),
            DuplicateKey { key } => Message::new("scenario-duplicate-key").text("key", q(key)),
            Malformed { piece } => Message::new("scenario-malformed").text("piece", q(piece)),
            BadValue {
                key,
                value,
                expected,
            } => Message::new("scenario-bad-value")
                .text("key", key.as_str())
                .text("value", q(value))
                .said("expected", expected.clone()),
            OutOfRange {
                key,
                value,
                allowed,
            } => Message::new("scenario-out-of-range")
                .text("key", key.as_str())
                .short("value", *value)
                .said("allowed", allowed.clone()),
            NotApplicable { key, reference } => Message::new("scenario-not-applicable")
                .text("key", key.as_str())
                .text("reference", *reference),
            Physics { which, error } => Message::new("scenario-physics")
                .text("which", *which)
                .said("error", error.message()),
            Refused { key, why } => Message::new("scenario-refused")
                .text("key", *key)
                .said("why", why.clone()),
            Design { error } => Message::new("scenario-design").said("why", error.message()),
            BadFormula { key, error } => Message::new("scenario-bad-formula")
                .text("key", *key)
                .said("error", error.message()),
            TooLong { bytes } => Message::new("scenario-too-long")
                .count("bytes", *bytes)
                .count("max", MAX_SCENARIO_BYTES)
                .count("kib", MAX_SCENARIO_BYTES / 1024),
            TooLarge { what } => what.clone(),
        }
    }
}

impl fmt::Display for ScenarioError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        self.message().fmt(f)
    }
}

impl ScenarioError {
    /// The field at fault, where one is: the key a page marks (`k1`, `law.v2`).
    pub fn key(&self) -> Option<&str> {
        use ScenarioError::*;
        match self {
            Missing { key } | BadFormula { key, .. } | Refused { key, .. } => Some(key),
            UnknownKey { key }
            | DuplicateKey { key }
            | BadValue { key, .. }
            | OutOfRange { key, .. }
            | NotApplicable { key, .. } => Some(key),
            UnsupportedVersion { .. } => Some("v"),
            UnknownPreset { .. } => Some("preset"),
            Design { .. } => Some("design"),
            Malformed { .. } | Physics { .. } | TooLong { .. } | TooLarge { .. } => None,
        }
    }
}

impl std::error::Error for ScenarioError {}
