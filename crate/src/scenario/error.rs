//! Why a scenario string or value was refused, in words that name the field.

use super::{CODEC_VERSION, MAX_SCENARIO_BYTES, PRESETS};
use crate::params::ParamError;
use crate::text::{excerpt, short};
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
    /// A run that would need more steps or memory than allowed.
    TooLarge {
        /// What was too large and the limit.
        what: String,
    },
}

impl fmt::Display for ScenarioError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        use ScenarioError::*;
        let q = |text: &str| excerpt(text);
        match self {
            Missing { key } => write!(
                f,
                "field '{key}' is missing (a scenario starts with v={CODEC_VERSION}&preset=NAME)"
            ),
            UnsupportedVersion { value } => write!(
                f,
                "field 'v' = '{}': unsupported codec version, allowed: {CODEC_VERSION}",
                q(value)
            ),
            UnknownPreset { name } => write!(
                f,
                "field 'preset' = '{}': unknown preset, allowed: {}",
                q(name),
                PRESETS
                    .iter()
                    .map(|p| p.name)
                    .collect::<Vec<_>>()
                    .join(", ")
            ),
            UnknownKey { key } => write!(
                f,
                "field '{}' is not a scenario field (the settings form and `imlab describe` list them)",
                q(key)
            ),
            DuplicateKey { key } => write!(f, "field '{}' is given more than once", q(key)),
            Malformed { piece } => write!(f, "'{}' is not of the form key=value", q(piece)),
            BadValue {
                key,
                value,
                expected,
            } => write!(
                f,
                "field '{key}' = '{}': not valid, expected {expected}",
                q(value)
            ),
            OutOfRange {
                key,
                value,
                allowed,
            } => write!(
                f,
                "field '{key}' = {}: out of range, allowed {allowed}",
                short(*value)
            ),
            NotApplicable { key, reference } => write!(
                f,
                "field '{key}' does not apply to the reference '{reference}' (set ref= first)"
            ),
            Physics { which, error } => write!(f, "{which} parameters: {error}"),
            BadFormula { key, error } => write!(f, "field '{key}': {error}"),
            TooLong { bytes } => write!(
                f,
                "the scenario is {bytes} bytes long, more than the {MAX_SCENARIO_BYTES} bytes \
                 ({} KiB) allowed",
                MAX_SCENARIO_BYTES / 1024
            ),
            TooLarge { what } => write!(f, "{what}"),
        }
    }
}

impl ScenarioError {
    /// The field at fault, where one is: the key a page marks (`k1`, `law.v2`).
    pub fn key(&self) -> Option<&str> {
        use ScenarioError::*;
        match self {
            Missing { key } | BadFormula { key, .. } => Some(key),
            UnknownKey { key }
            | DuplicateKey { key }
            | BadValue { key, .. }
            | OutOfRange { key, .. }
            | NotApplicable { key, .. } => Some(key),
            UnsupportedVersion { .. } => Some("v"),
            UnknownPreset { .. } => Some("preset"),
            Malformed { .. } | Physics { .. } | TooLong { .. } | TooLarge { .. } => None,
        }
    }
}

impl std::error::Error for ScenarioError {}
