//! A challenge from the parts a lecturer fills in (title, base, allowed fields, criteria,
//! variants), checked part by part by the codec's own rules, and a challenge taken apart into
//! those parts again. An error names the part it is about by its key, so that a form can mark it.

use super::codec::{check_length, check_title, given_twice, pct_encode, Draft, Part};
use super::{Allowed, Challenge, ChallengeError, Op, Variants};
use crate::text::{excerpt, Message};
use serde::{Deserialize, Serialize};
use std::collections::HashSet;
use std::fmt;

/// A number as a form holds it: text as typed, or a number.
#[cfg_attr(
    target_arch = "wasm32",
    derive(tsify::Tsify),
    tsify(missing_as_null, hashmap_as_object)
)]
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
#[serde(untagged)]
pub enum FormNumber {
    /// A number.
    Number(f64),
    /// Text, read as the codec reads a number.
    Text(String),
}

impl FormNumber {
    /// The codec text: a number as Rust writes it, text trimmed.
    fn text(&self) -> String {
        match self {
            FormNumber::Number(v) => format!("{v}"),
            FormNumber::Text(t) => t.trim().to_string(),
        }
    }
}

/// Several names, or several strings: a list, or one text with `|` between them.
#[cfg_attr(
    target_arch = "wasm32",
    derive(tsify::Tsify),
    tsify(missing_as_null, hashmap_as_object)
)]
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
#[serde(untagged)]
pub enum FormList {
    /// One string each.
    Items(Vec<String>),
    /// One text, `a|b|…`.
    Text(String),
}

impl FormList {
    /// The items, each trimmed.
    fn items(&self) -> Vec<String> {
        match self {
            FormList::Items(items) => items.iter().map(|i| i.trim().to_string()).collect(),
            FormList::Text(text) => text.split('|').map(|i| i.trim().to_string()).collect(),
        }
    }
}

/// One field the student may set: a range (`lo`, `hi`) or choices (`options`).
#[cfg_attr(
    target_arch = "wasm32",
    derive(tsify::Tsify),
    tsify(missing_as_null, hashmap_as_object)
)]
#[derive(Clone, Debug, Default, PartialEq, Serialize, Deserialize)]
#[serde(default)]
pub struct AllowPart {
    /// The scenario field, e.g. `k1`.
    pub field: String,
    /// Smallest value of a range.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub lo: Option<FormNumber>,
    /// Largest value of a range.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub hi: Option<FormNumber>,
    /// The names the student may choose from.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub options: Option<FormList>,
}

/// One criterion: a figure, how it is bounded (`max`, `min`, `abs` or `band`) and the bound
/// (none for `band`).
#[cfg_attr(
    target_arch = "wasm32",
    derive(tsify::Tsify),
    tsify(missing_as_null, hashmap_as_object)
)]
#[derive(Clone, Debug, Default, PartialEq, Serialize, Deserialize)]
#[serde(default)]
pub struct NeedPart {
    /// The figure, e.g. `settling_time`.
    pub figure: String,
    /// `max`, `min`, `abs` or `band`.
    pub op: String,
    /// The bound, in the figure's unit.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub bound: Option<FormNumber>,
}

/// The parts of a challenge as a lecturer fills them in. `vary` is `seeds:A..B`, override strings
/// (a list, or one text with `|` between them), or none (null, "" or an empty list).
#[cfg_attr(
    target_arch = "wasm32",
    derive(tsify::Tsify),
    tsify(missing_as_null, hashmap_as_object)
)]
#[derive(Clone, Debug, Default, PartialEq, Serialize, Deserialize)]
#[serde(default)]
pub struct ChallengeParts {
    /// Short title.
    pub title: String,
    /// The scenario every run starts from (a scenario string or a preset's name).
    pub base: String,
    /// The fields the student may set.
    pub allow: Vec<AllowPart>,
    /// The criteria, in order.
    pub need: Vec<NeedPart>,
    /// The robustness variants.
    pub vary: Option<FormList>,
    /// The figures of the criteria that must hold on every variant too.
    pub robust: Vec<String>,
}

/// Why parts make no challenge: the part's key (`title`, `base`, `allow.FIELD`, `need.FIGURE`,
/// `need` for the criteria as a whole, `vary`, `robust`, or `challenge` for the whole text's
/// length) and the codec's message.
#[cfg_attr(
    target_arch = "wasm32",
    derive(tsify::Tsify),
    tsify(missing_as_null, hashmap_as_object)
)]
#[derive(Clone, Debug, PartialEq, Serialize)]
pub struct ComposeError {
    /// The part's key.
    pub key: String,
    /// The message, naming the key or field as the codec does.
    pub message: Message,
}

impl fmt::Display for ComposeError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        self.message.fmt(f)
    }
}

impl std::error::Error for ComposeError {}

/// `error` about `part`.
fn at(part: &Part, error: ChallengeError) -> ComposeError {
    ComposeError {
        key: part.key(),
        message: error.message,
    }
}

/// The refusal of a key given twice, as the codec words it.
fn twice(part: &Part) -> ComposeError {
    let key = part.key();
    ComposeError {
        message: given_twice(&key),
        key,
    }
}

impl AllowPart {
    /// The codec's value: `LO..HI` or `a|b`.
    fn text(&self, part: &Part) -> Result<String, ComposeError> {
        let show = |t: &Option<FormNumber>| t.as_ref().map_or(String::new(), FormNumber::text);
        match &self.options {
            Some(_) if self.lo.is_some() || self.hi.is_some() => Err(ComposeError {
                key: part.key(),
                message: Message::new("challenge-compose-range-and-options")
                    .text("key", excerpt(&part.key())),
            }),
            Some(options) => Ok(options.items().join("|")),
            None => Ok(format!("{}..{}", show(&self.lo), show(&self.hi))),
        }
    }
}

impl NeedPart {
    /// The codec's value: `OP:BOUND`, or `band`.
    fn text(&self) -> String {
        let op = self.op.trim();
        if op == "band" {
            return op.to_string();
        }
        let bound = self.bound.as_ref().map_or(String::new(), FormNumber::text);
        format!("{op}:{bound}")
    }
}

/// The codec's `vary`: `seeds:A..B` as written, or the overrides percent-encoded and joined by
/// `|`; None for no variants.
fn vary_text(vary: &Option<FormList>) -> Option<String> {
    match vary {
        None => None,
        Some(FormList::Text(t)) if t.trim().is_empty() => None,
        Some(FormList::Items(items)) if items.is_empty() => None,
        Some(FormList::Text(t)) if t.trim().starts_with("seeds:") => Some(t.trim().to_string()),
        Some(list) => Some(
            list.items()
                .iter()
                .map(|o| pct_encode(o))
                .collect::<Vec<_>>()
                .join("|"),
        ),
    }
}

impl Challenge {
    /// The challenge the parts describe, each part checked by the codec's rule for its key (the
    /// values as a form holds them: trimmed, numbers as text or numbers); an error names the
    /// part. Its [`Challenge::encode`] is the canonical link, which [`Challenge::parse`] reads
    /// back to the same challenge.
    pub fn compose(parts: &ChallengeParts) -> Result<Challenge, ComposeError> {
        let title = parts.title.trim();
        check_title(title).map_err(|e| at(&Part::Title, e))?;
        let mut draft =
            Draft::new(title.to_string(), parts.base.trim()).map_err(|e| at(&Part::Base, e))?;
        let mut seen = HashSet::new();
        for a in &parts.allow {
            let field = a.field.trim();
            let part = Part::Allow(field.to_string());
            if !seen.insert(part.key()) {
                return Err(twice(&part));
            }
            draft
                .allow(field, &a.text(&part)?)
                .map_err(|e| at(&part, e))?;
        }
        for n in &parts.need {
            let figure = n.figure.trim();
            let part = Part::Need(figure.to_string());
            if !seen.insert(part.key()) {
                return Err(twice(&part));
            }
            draft.need(figure, &n.text()).map_err(|e| at(&part, e))?;
        }
        let robust: Vec<&str> = parts.robust.iter().map(|r| r.trim()).collect();
        let robust = (!robust.is_empty()).then(|| robust.join(","));
        let challenge = draft
            .finish(vary_text(&parts.vary).as_deref(), robust.as_deref())
            .map_err(|(part, e)| at(&part, e))?;
        check_length(&challenge.encode()).map_err(|e| at(&Part::Whole, e))?;
        Ok(challenge)
    }

    /// The challenge's parts, as [`Challenge::compose`] takes them: numbers as the codec writes
    /// them, choices and overrides as lists, seeds as `seeds:A..B`.
    pub fn parts(&self) -> ChallengeParts {
        let text = |v: f64| Some(FormNumber::Text(format!("{v}")));
        ChallengeParts {
            title: self.title.clone(),
            base: self.base.clone(),
            allow: self
                .allow
                .iter()
                .map(|a| match &a.allowed {
                    Allowed::Range { lo, hi } => AllowPart {
                        field: a.field.clone(),
                        lo: text(*lo),
                        hi: text(*hi),
                        options: None,
                    },
                    Allowed::Choice { options } => AllowPart {
                        field: a.field.clone(),
                        lo: None,
                        hi: None,
                        options: Some(FormList::Items(options.clone())),
                    },
                    Allowed::Formula => AllowPart {
                        field: a.field.clone(),
                        lo: None,
                        hi: None,
                        options: Some(FormList::Items(vec!["formula".to_string()])),
                    },
                })
                .collect(),
            need: self
                .need
                .iter()
                .map(|c| {
                    let (op, bound) = match c.op {
                        Op::Max(b) => ("max", text(b)),
                        Op::Min(b) => ("min", text(b)),
                        Op::Abs(b) => ("abs", text(b)),
                        Op::Band => ("band", None),
                    };
                    NeedPart {
                        figure: c.figure.clone(),
                        op: op.to_string(),
                        bound,
                    }
                })
                .collect(),
            vary: self.vary.as_ref().map(|v| match v {
                Variants::Seeds { first, last } => FormList::Text(format!("seeds:{first}..{last}")),
                Variants::List { overrides } => FormList::Items(overrides.clone()),
            }),
            robust: self.robust.clone(),
        }
    }
}
