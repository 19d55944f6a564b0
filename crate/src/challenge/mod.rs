//! Design challenges: a lecturer's task in a link, a student's answer as the same link with the
//! fields they set, and the verdict of re-running it.
//!
//! A challenge is a query string, versioned like a scenario:
//!
//! ```text
//! c=1&title=Fast%20step&base=v%3D1%26preset%3Dstep&allow.k1=300..3000&allow.ekf=euler|rk4
//!    &need.settling_time=max:0.004&need.current_peak=max:4&need.mean_nis=band
//!    &vary=seed%3D2|seed%3D3&robust=current_peak
//! ```
//!
//! - `title`: short text; `base`: the scenario every run starts from.
//! - `allow.FIELD=LO..HI` (numbers, closed range) or `allow.FIELD=a|b` (choices): what the student
//!   may set.
//! - `need.FIGURE=OP`, in the order written: `max:B` (value ≤ B), `min:B` (≥ B), `abs:B`
//!   (|value| ≤ B), `band` (mean NIS inside its 95 % band). The figures are those of
//!   [`crate::record::report`] and [`crate::record::LOAD_RECOVERY`].
//! - `vary`: robustness variants, `|`-separated override strings (applied after the student's
//!   fields), or `seeds:A..B`; `robust`: the criteria that must also hold on every variant.
//!
//! [`Challenge::encode`] writes the keys in a fixed order (allowed fields in the scenario's field
//! order, criteria as written), so one challenge has one text. A submission is that text
//! followed by `&try.FIELD=VALUE` for the fields set (see [`Submission`]).

mod brief;
mod builtin;
mod judge;

pub use crate::record::LOAD_RECOVERY;
pub use builtin::{builtin, Builtin, BUILTINS};
pub use judge::{
    figure_info, figures, judge, measure, CriterionVerdict, Measure, Measures, Verdict,
};

use crate::quote::excerpt;
use crate::scenario::{short, FieldInfo, Scenario, MAX_SEED};
use serde::Serialize;
use std::collections::HashSet;
use std::fmt;

/// Version of the challenge codec.
pub const CHALLENGE_VERSION: u32 = 1;
/// Longest challenge or submission text accepted (bytes), as for scenario strings.
pub const MAX_CHALLENGE_BYTES: usize = 16 * 1024;
/// Longest title (characters).
pub const MAX_TITLE_CHARS: usize = 120;
/// Most robustness variants.
pub const MAX_VARIANTS: usize = 20;
/// Most criteria.
pub const MAX_CRITERIA: usize = 20;

/// What kind of refusal an error is: the grading table's status names it.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Serialize)]
#[serde(rename_all = "lowercase")]
pub enum ErrorKind {
    /// The text is not a well-formed challenge or submission.
    Malformed,
    /// Well-formed, but a field the student set is not allowed or out of its range.
    Refused,
    /// A submission whose challenge text differs from the one it is graded against.
    Another,
}

/// Why a challenge or submission was refused: a message naming the key or field, with user
/// text quoted through [`excerpt`].
#[derive(Clone, Debug, PartialEq)]
pub struct ChallengeError {
    /// The kind of refusal.
    pub kind: ErrorKind,
    /// The message.
    pub message: String,
}

impl ChallengeError {
    fn malformed(message: impl Into<String>) -> Self {
        ChallengeError {
            kind: ErrorKind::Malformed,
            message: message.into(),
        }
    }
    fn refused(message: impl Into<String>) -> Self {
        ChallengeError {
            kind: ErrorKind::Refused,
            message: message.into(),
        }
    }

    /// The status of a grading row: `malformed: …`, `refused: …` or `another challenge`.
    pub fn status(&self) -> String {
        match self.kind {
            ErrorKind::Malformed => format!("malformed: {}", self.message),
            ErrorKind::Refused => format!("refused: {}", self.message),
            ErrorKind::Another => "another challenge".to_string(),
        }
    }
}

impl fmt::Display for ChallengeError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(&self.message)
    }
}

impl std::error::Error for ChallengeError {}

/// What a student may set a field to.
#[derive(Clone, Debug, PartialEq, Serialize)]
#[serde(tag = "kind", rename_all = "lowercase")]
pub enum Allowed {
    /// A number from `lo` to `hi`, both included.
    Range {
        /// Smallest value.
        lo: f64,
        /// Largest value.
        hi: f64,
    },
    /// One of these names.
    Choice {
        /// The names, as written.
        options: Vec<String>,
    },
}

impl Allowed {
    /// The codec text: `LO..HI` or `a|b`.
    pub fn text(&self) -> String {
        match self {
            Allowed::Range { lo, hi } => format!("{lo}..{hi}"),
            Allowed::Choice { options } => options.join("|"),
        }
    }
}

/// One field the student may set.
#[derive(Clone, Debug, PartialEq, Serialize)]
pub struct Allow {
    /// The scenario field.
    pub field: String,
    /// Its allowed values.
    pub allowed: Allowed,
}

/// How a criterion bounds its figure.
#[derive(Clone, Copy, Debug, PartialEq, Serialize)]
#[serde(tag = "op", content = "bound", rename_all = "lowercase")]
pub enum Op {
    /// value ≤ bound.
    Max(f64),
    /// value ≥ bound.
    Min(f64),
    /// |value| ≤ bound.
    Abs(f64),
    /// mean_nis_low ≤ value ≤ mean_nis_high (the mean NIS only).
    Band,
}

impl Op {
    /// The codec text: `max:B`, `min:B`, `abs:B` or `band`.
    pub fn text(&self) -> String {
        match self {
            Op::Max(b) => format!("max:{b}"),
            Op::Min(b) => format!("min:{b}"),
            Op::Abs(b) => format!("abs:{b}"),
            Op::Band => "band".to_string(),
        }
    }
}

/// One criterion: a figure and its bound.
#[derive(Clone, Debug, PartialEq, Serialize)]
pub struct Criterion {
    /// The figure's name, e.g. `settling_time`.
    pub figure: String,
    /// The bound.
    pub op: Op,
}

/// The robustness variants of a challenge.
#[derive(Clone, Debug, PartialEq, Serialize)]
#[serde(tag = "kind", rename_all = "lowercase")]
pub enum Variants {
    /// The seeds `first..=last`, each a variant.
    Seeds {
        /// First seed.
        first: u64,
        /// Last seed.
        last: u64,
    },
    /// Override strings (`key=value&…`, canonical: in the scenario's field order).
    List {
        /// The overrides, decoded.
        overrides: Vec<String>,
    },
}

impl Variants {
    /// Each variant's override string, e.g. `seed=2` or `model.j=0.016`.
    pub fn overrides(&self) -> Vec<String> {
        match self {
            Variants::Seeds { first, last } => {
                (*first..=*last).map(|s| format!("seed={s}")).collect()
            }
            Variants::List { overrides } => overrides.clone(),
        }
    }
}

/// A design task: the scenario to start from, what may change and the criteria.
#[derive(Clone, Debug, PartialEq, Serialize)]
pub struct Challenge {
    /// Short title.
    pub title: String,
    /// The scenario every run starts from (canonical scenario string).
    pub base: String,
    /// The fields the student may set, in the scenario's field order.
    pub allow: Vec<Allow>,
    /// The criteria, in the order written.
    pub need: Vec<Criterion>,
    /// Robustness variants, if any.
    pub vary: Option<Variants>,
    /// The figures of the criteria that must hold on every variant too, in criterion order.
    pub robust: Vec<String>,
}

/// A challenge with the values a student set.
#[derive(Clone, Debug, PartialEq, Serialize)]
pub struct Submission {
    /// The challenge answered.
    pub challenge: Challenge,
    /// The fields set and their values (canonical codec text), in the challenge's allow order.
    pub tries: Vec<(String, String)>,
}

/// The query of `text`: a bare query string, or the part of a URL after `?` without `#…`.
fn query_of(text: &str) -> &str {
    let text = text.trim();
    let text = text.split_once('#').map_or(text, |(q, _)| q);
    text.split_once('?').map_or(text, |(_, q)| q)
}

/// Decodes `%XX` escapes and `+` (a space); `key` names the value in the error.
fn pct_decode(key: &str, value: &str) -> Result<String, ChallengeError> {
    let bad = || {
        ChallengeError::malformed(format!(
            "field '{}' = '{}': not valid percent-encoded UTF-8",
            excerpt(key),
            excerpt(value)
        ))
    };
    let bytes = value.as_bytes();
    let mut out = Vec::with_capacity(bytes.len());
    let mut i = 0;
    while i < bytes.len() {
        match bytes[i] {
            b'%' => {
                let hex = value.get(i + 1..i + 3).ok_or_else(bad)?;
                out.push(u8::from_str_radix(hex, 16).map_err(|_| bad())?);
                i += 3;
            }
            b'+' => {
                out.push(b' ');
                i += 1;
            }
            b => {
                out.push(b);
                i += 1;
            }
        }
    }
    String::from_utf8(out).map_err(|_| bad())
}

/// Percent-encodes everything but the unreserved characters `A–Z a–z 0–9 - . _ ~`.
fn pct_encode(text: &str) -> String {
    let mut out = String::with_capacity(text.len());
    for b in text.bytes() {
        if b.is_ascii_alphanumeric() || matches!(b, b'-' | b'.' | b'_' | b'~') {
            out.push(char::from(b));
        } else {
            out.push_str(&format!("%{b:02X}"));
        }
    }
    out
}

/// A plain decimal number (the scenario codec's: no `inf`, `nan` or `+`), finite.
fn number(text: &str) -> Option<f64> {
    crate::scenario::parse_number(text).filter(|v| v.is_finite())
}

/// The scenario field `key`, described on `base`.
fn field_info(base: &Scenario, key: &str) -> Option<FieldInfo> {
    base.describe().into_iter().find(|f| f.key == key)
}

/// The position of scenario field `key` in the field table (the codec's order).
fn field_order(base: &Scenario, key: &str) -> usize {
    base.describe()
        .iter()
        .position(|f| f.key == key)
        .unwrap_or(usize::MAX)
}

/// The `key=value` pieces of a query, refusing pieces without `=`, duplicates and an
/// over-long text.
fn pieces(text: &str) -> Result<Vec<(&str, &str)>, ChallengeError> {
    if text.len() > MAX_CHALLENGE_BYTES {
        return Err(ChallengeError::malformed(format!(
            "the challenge is {} bytes long, more than the {MAX_CHALLENGE_BYTES} bytes ({} KiB) allowed",
            text.len(),
            MAX_CHALLENGE_BYTES / 1024
        )));
    }
    let mut seen = HashSet::new();
    let mut out = Vec::new();
    for piece in query_of(text).split('&').filter(|p| !p.is_empty()) {
        let (k, v) = piece.split_once('=').ok_or_else(|| {
            ChallengeError::malformed(format!("'{}' is not of the form key=value", excerpt(piece)))
        })?;
        if !seen.insert(k) {
            return Err(ChallengeError::malformed(format!(
                "field '{}' is given more than once",
                excerpt(k)
            )));
        }
        out.push((k, v));
    }
    Ok(out)
}

/// The key and value of one `key=value` piece of an override string; `what` names the override
/// in the error.
fn key_value<'a>(piece: &'a str, what: &str) -> Result<(&'a str, &'a str), ChallengeError> {
    piece.split_once('=').ok_or_else(|| {
        ChallengeError::malformed(format!(
            "{what}: '{}' is not of the form key=value",
            excerpt(piece)
        ))
    })
}

/// A scenario override string (`key=value&…`) applied to `s`, each field checked; `what`
/// names the override in errors.
fn apply_overrides(s: &mut Scenario, text: &str, what: &str) -> Result<(), ChallengeError> {
    for piece in text.split('&').filter(|p| !p.is_empty()) {
        let (k, v) = key_value(piece, what)?;
        s.set(k, v)
            .map_err(|e| ChallengeError::malformed(format!("{what}: {e}")))?;
    }
    Ok(())
}

impl Challenge {
    /// Parses a challenge: its text (bare or in a URL) or the name of a built-in one.
    pub fn parse(text: &str) -> Result<Challenge, ChallengeError> {
        let (challenge, tries) = parse_parts(text)?;
        if let Some((k, _)) = tries.first() {
            return Err(ChallengeError::malformed(format!(
                "field 'try.{}': this is a submission, not a challenge (grade it against its challenge)",
                excerpt(k)
            )));
        }
        Ok(challenge)
    }

    /// The canonical text: `c`, `title`, `base`, `allow.*` (field order), `need.*` (as
    /// written), `vary`, `robust`.
    pub fn encode(&self) -> String {
        let mut out = format!(
            "c={CHALLENGE_VERSION}&title={}&base={}",
            pct_encode(&self.title),
            pct_encode(&self.base)
        );
        for a in &self.allow {
            out.push_str(&format!("&allow.{}={}", a.field, a.allowed.text()));
        }
        for c in &self.need {
            out.push_str(&format!("&need.{}={}", c.figure, c.op.text()));
        }
        match &self.vary {
            Some(Variants::Seeds { first, last }) => {
                out.push_str(&format!("&vary=seeds:{first}..{last}"))
            }
            Some(Variants::List { overrides }) => {
                let list: Vec<String> = overrides.iter().map(|o| pct_encode(o)).collect();
                out.push_str(&format!("&vary={}", list.join("|")));
            }
            None => {}
        }
        if !self.robust.is_empty() {
            out.push_str(&format!("&robust={}", self.robust.join(",")));
        }
        out
    }

    /// The base scenario.
    pub fn base_scenario(&self) -> Scenario {
        Scenario::parse(&self.base).expect("a challenge's base was checked when it was parsed")
    }

    /// Reads a submission of this challenge: refuses one whose challenge text is another
    /// ([`ErrorKind::Another`]) before looking at its fields.
    pub fn submission(&self, text: &str) -> Result<Submission, ChallengeError> {
        let (challenge, tries) = parse_parts(text)?;
        if challenge != *self {
            return Err(ChallengeError {
                kind: ErrorKind::Another,
                message: "the submission belongs to another challenge (its challenge text differs)"
                    .to_string(),
            });
        }
        Submission::check(challenge, &tries)
    }

    /// Whether criterion `figure` must hold on every variant.
    pub fn is_robust(&self, figure: &str) -> bool {
        self.robust.iter().any(|r| r == figure)
    }

    /// Labels of the runs: `nominal`, then each variant's overrides.
    pub fn run_labels(&self) -> Vec<String> {
        let mut out = vec!["nominal".to_string()];
        if let Some(v) = &self.vary {
            out.extend(v.overrides());
        }
        out
    }
}

impl Submission {
    /// Parses a submission (bare or in a URL) against its own challenge text.
    pub fn parse(text: &str) -> Result<Submission, ChallengeError> {
        let (challenge, tries) = parse_parts(text)?;
        Submission::check(challenge, &tries)
    }

    /// The tries checked against the challenge: allowed, well-formed, in range.
    fn check(
        challenge: Challenge,
        tries: &[(String, String)],
    ) -> Result<Submission, ChallengeError> {
        let base = challenge.base_scenario();
        let mut out = Vec::new();
        for (field, value) in tries {
            let allow = challenge
                .allow
                .iter()
                .find(|a| &a.field == field)
                .ok_or_else(|| {
                    ChallengeError::refused(format!("field '{}' is not allowed", excerpt(field)))
                })?;
            let text = match &allow.allowed {
                Allowed::Range { lo, hi } => {
                    let v = number(value).ok_or_else(|| {
                        ChallengeError::malformed(format!(
                            "field 'try.{field}' = '{}': not a number",
                            excerpt(value)
                        ))
                    })?;
                    if v < *lo || v > *hi {
                        return Err(ChallengeError::refused(format!(
                            "{field}={} is outside {lo}..{hi}",
                            short(v)
                        )));
                    }
                    format!("{v}")
                }
                Allowed::Choice { options } => {
                    if !options.iter().any(|o| o == value) {
                        return Err(ChallengeError::refused(format!(
                            "{field}={} is not one of {}",
                            excerpt(value),
                            options.join("|")
                        )));
                    }
                    value.clone()
                }
            };
            // The field's own rules (whole numbers, say) on the base.
            base.clone()
                .set(field, &text)
                .map_err(|e| ChallengeError::refused(e.to_string()))?;
            out.push((field.clone(), text));
        }
        let order = |f: &str| challenge.allow.iter().position(|a| a.field == f);
        sort_small(&mut out, |(f, _)| order(f));
        Ok(Submission {
            challenge,
            tries: out,
        })
    }

    /// The canonical text: the challenge's, then `try.FIELD=VALUE` in allow order.
    pub fn encode(&self) -> String {
        let mut out = self.challenge.encode();
        for (f, v) in &self.tries {
            out.push_str(&format!("&try.{f}={v}"));
        }
        out
    }

    /// The scenarios to run: the nominal one (base + tries) first, then each variant
    /// (nominal + the variant's overrides).
    pub fn scenarios(&self) -> Result<Vec<Scenario>, ChallengeError> {
        let mut nominal = self.challenge.base_scenario();
        for (f, v) in &self.tries {
            nominal
                .set(f, v)
                .map_err(|e| ChallengeError::refused(e.to_string()))?;
        }
        let mut out = vec![nominal.clone()];
        if let Some(vary) = &self.challenge.vary {
            for o in vary.overrides() {
                let mut s = nominal.clone();
                apply_overrides(&mut s, &o, &format!("variant '{}'", excerpt(&o)))
                    .map_err(|e| ChallengeError::refused(e.message))?;
                out.push(s);
            }
        }
        Ok(out)
    }
}

/// Parses the challenge part of `text` (or a built-in's name) and returns it with the raw
/// `try.*` pairs.
fn parse_parts(text: &str) -> Result<(Challenge, Vec<(String, String)>), ChallengeError> {
    let trimmed = text.trim();
    if !trimmed.contains('=') {
        let b = builtin(trimmed).ok_or_else(|| {
            ChallengeError::malformed(format!(
                "'{}' is neither a challenge link nor a built-in challenge ({})",
                excerpt(trimmed),
                BUILTINS
                    .iter()
                    .map(|b| b.name)
                    .collect::<Vec<_>>()
                    .join(", ")
            ))
        })?;
        return Ok((b.challenge(), Vec::new()));
    }
    let pairs = pieces(text)?;
    let get = |key: &str| pairs.iter().find(|(k, _)| *k == key).map(|(_, v)| *v);
    let version = get("c").ok_or_else(|| {
        ChallengeError::malformed(format!(
            "field 'c' is missing (a challenge starts with c={CHALLENGE_VERSION})"
        ))
    })?;
    if version != CHALLENGE_VERSION.to_string() {
        return Err(ChallengeError::malformed(format!(
            "field 'c' = '{}': unsupported challenge version, allowed: {CHALLENGE_VERSION}",
            excerpt(version)
        )));
    }
    // Unknown keys first, in the order written.
    for (k, _) in &pairs {
        let known = matches!(*k, "c" | "title" | "base" | "vary" | "robust")
            || ["allow.", "need.", "try."]
                .iter()
                .any(|p| k.strip_prefix(p).is_some_and(|rest| !rest.is_empty()));
        if !known {
            return Err(ChallengeError::malformed(format!(
                "field '{}' is not a challenge field (c, title, base, allow.FIELD, need.FIGURE, vary, robust, try.FIELD)",
                excerpt(k)
            )));
        }
    }
    let title = pct_decode("title", get("title").unwrap_or(""))?;
    if title.chars().count() > MAX_TITLE_CHARS {
        return Err(ChallengeError::malformed(format!(
            "field 'title' is {} characters long, more than the {MAX_TITLE_CHARS} allowed",
            title.chars().count()
        )));
    }
    let base_text = pct_decode(
        "base",
        get("base").ok_or_else(|| ChallengeError::malformed("field 'base' is missing"))?,
    )?;
    let base = Scenario::parse(&base_text)
        .map_err(|e| ChallengeError::malformed(format!("field 'base': {e}")))?;
    let mut allow = Vec::new();
    let mut need = Vec::new();
    let mut tries = Vec::new();
    for (k, v) in &pairs {
        if let Some(field) = k.strip_prefix("allow.") {
            allow.push(parse_allow(&base, field, v)?);
        } else if let Some(figure) = k.strip_prefix("need.") {
            need.push(parse_need(&base, figure, v)?);
        } else if let Some(field) = k.strip_prefix("try.") {
            tries.push((field.to_string(), pct_decode(k, v)?));
        }
    }
    sort_small(&mut allow, |a| field_order(&base, &a.field));
    if need.is_empty() {
        return Err(ChallengeError::malformed(
            "no criteria: add at least one need.FIGURE=OP",
        ));
    }
    if need.len() > MAX_CRITERIA {
        return Err(ChallengeError::malformed(format!(
            "{} criteria, more than the {MAX_CRITERIA} allowed",
            need.len()
        )));
    }
    let vary = get("vary").map(|v| parse_vary(&base, v)).transpose()?;
    let robust = match get("robust") {
        None => Vec::new(),
        Some(v) => parse_robust(&need, v)?,
    };
    match (&vary, robust.is_empty()) {
        (Some(_), true) => {
            return Err(ChallengeError::malformed(
                "field 'vary': no criterion uses the variants (name them in robust=)",
            ))
        }
        (None, false) => {
            return Err(ChallengeError::malformed(
                "field 'robust': there are no variants (add vary=)",
            ))
        }
        _ => {}
    }
    let challenge = Challenge {
        title,
        base: base.encode(),
        allow,
        need,
        vary,
        robust,
    };
    Ok((challenge, tries))
}

/// `allow.FIELD=VALUE`.
fn parse_allow(base: &Scenario, field: &str, value: &str) -> Result<Allow, ChallengeError> {
    let key = format!("allow.{field}");
    let info = field_info(base, field).ok_or_else(|| {
        ChallengeError::malformed(format!(
            "field '{}': '{}' is not a scenario field",
            excerpt(&key),
            excerpt(field)
        ))
    })?;
    let allowed = if info.options.is_empty() {
        let bad = || {
            ChallengeError::malformed(format!(
                "field '{key}' = '{}': expected LO..HI, two numbers with LO ≤ HI",
                excerpt(value)
            ))
        };
        let (lo, hi) = value.split_once("..").ok_or_else(bad)?;
        let (lo, hi) = (number(lo).ok_or_else(bad)?, number(hi).ok_or_else(bad)?);
        if lo > hi {
            return Err(bad());
        }
        // Both ends must be values of the field.
        for end in [lo, hi] {
            base.clone().set(field, &format!("{end}")).map_err(|e| {
                ChallengeError::malformed(format!("field '{key}' = '{}': {e}", excerpt(value)))
            })?;
        }
        Allowed::Range { lo, hi }
    } else {
        let mut options: Vec<String> = Vec::new();
        for o in value.split('|') {
            if !info.options.contains(&o) || options.iter().any(|x| x == o) {
                return Err(ChallengeError::malformed(format!(
                    "field '{key}' = '{}': expected distinct names from {}, separated by |",
                    excerpt(value),
                    info.options.join("|")
                )));
            }
            options.push(o.to_string());
        }
        // Canonical: in the field's own order.
        sort_small(&mut options, |o| info.options.iter().position(|x| x == o));
        Allowed::Choice { options }
    };
    Ok(Allow {
        field: field.to_string(),
        allowed,
    })
}

/// `need.FIGURE=OP`.
fn parse_need(base: &Scenario, figure: &str, value: &str) -> Result<Criterion, ChallengeError> {
    let key = format!("need.{figure}");
    if figure_info(figure).is_none() {
        return Err(ChallengeError::malformed(format!(
            "field '{}': '{}' is not a figure ({})",
            excerpt(&key),
            excerpt(figure),
            figures().map(|f| f.name).collect::<Vec<_>>().join(", ")
        )));
    }
    let op = if value == "band" {
        if figure != "mean_nis" {
            return Err(ChallengeError::malformed(format!(
                "field '{key}' = 'band': only mean_nis has a band"
            )));
        }
        Op::Band
    } else {
        let bad = || {
            ChallengeError::malformed(format!(
                "field '{key}' = '{}': expected max:B, min:B, abs:B or band",
                excerpt(value)
            ))
        };
        let (op, bound) = value.split_once(':').ok_or_else(bad)?;
        let b = number(bound).ok_or_else(bad)?;
        match op {
            "max" => Op::Max(b),
            "min" => Op::Min(b),
            "abs" if b >= 0.0 => Op::Abs(b),
            _ => return Err(bad()),
        }
    };
    if figure == LOAD_RECOVERY && base.load_step.torque == 0.0 {
        return Err(ChallengeError::malformed(format!(
            "field '{key}': the base has no load step (load.torque = 0)"
        )));
    }
    Ok(Criterion {
        figure: figure.to_string(),
        op,
    })
}

/// `vary=seeds:A..B` or `vary=OVERRIDES|OVERRIDES…`.
fn parse_vary(base: &Scenario, value: &str) -> Result<Variants, ChallengeError> {
    if let Some(range) = value.strip_prefix("seeds:") {
        let bad = || {
            ChallengeError::malformed(format!(
                "field 'vary' = '{}': expected seeds:A..B, whole numbers with A ≤ B ≤ {MAX_SEED} and at most {MAX_VARIANTS} seeds",
                excerpt(value)
            ))
        };
        let (a, b) = range.split_once("..").ok_or_else(bad)?;
        let (first, last) = (
            a.parse::<u64>().map_err(|_| bad())?,
            b.parse::<u64>().map_err(|_| bad())?,
        );
        if first > last || last > MAX_SEED || last - first >= MAX_VARIANTS as u64 {
            return Err(bad());
        }
        return Ok(Variants::Seeds { first, last });
    }
    let raw: Vec<&str> = value.split('|').collect();
    if raw.len() > MAX_VARIANTS {
        return Err(ChallengeError::malformed(format!(
            "field 'vary': {} variants, more than the {MAX_VARIANTS} allowed",
            raw.len()
        )));
    }
    let mut overrides = Vec::new();
    for (i, r) in raw.iter().enumerate() {
        let text = pct_decode("vary", r)?;
        let what = format!("field 'vary', variant {}", i + 1);
        let mut pairs: Vec<(String, String)> = Vec::new();
        for piece in text.split('&').filter(|p| !p.is_empty()) {
            let (k, v) = key_value(piece, &what)?;
            if pairs.iter().any(|(x, _)| x == k) {
                return Err(ChallengeError::malformed(format!(
                    "{what}: field '{}' is given more than once",
                    excerpt(k)
                )));
            }
            pairs.push((k.to_string(), v.to_string()));
        }
        if pairs.is_empty() {
            return Err(ChallengeError::malformed(format!("{what} is empty")));
        }
        sort_small(&mut pairs, |(k, _)| field_order(base, k));
        let canonical = pairs
            .iter()
            .map(|(k, v)| format!("{k}={v}"))
            .collect::<Vec<_>>()
            .join("&");
        apply_overrides(&mut base.clone(), &canonical, &what)?;
        overrides.push(canonical);
    }
    Ok(Variants::List { overrides })
}

/// `robust=FIGURE,FIGURE…`: figures of criteria, in criterion order.
fn parse_robust(need: &[Criterion], value: &str) -> Result<Vec<String>, ChallengeError> {
    let mut out: Vec<String> = Vec::new();
    for f in value.split(',') {
        if !need.iter().any(|c| c.figure == f) || out.iter().any(|x| x == f) {
            return Err(ChallengeError::malformed(format!(
                "field 'robust' = '{}': '{}' is not the figure of a criterion (or is named twice)",
                excerpt(value),
                excerpt(f)
            )));
        }
        out.push(f.to_string());
    }
    sort_small(&mut out, |f| need.iter().position(|c| &c.figure == f));
    Ok(out)
}

/// Sorts the few items of a challenge's lists by `key`, keeping equal keys in order: an insertion
/// sort, a few hundred bytes of WASM where the standard library's stable sort takes about ten
/// kilobytes for each type it sorts.
fn sort_small<T, K: Ord>(items: &mut [T], key: impl Fn(&T) -> K) {
    for i in 1..items.len() {
        let mut j = i;
        while j > 0 && key(&items[j - 1]) > key(&items[j]) {
            items.swap(j - 1, j);
            j -= 1;
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn percent_coding_round_trips() {
        let text = "v=1&preset=step&k1=2000 ü|%";
        assert_eq!(pct_decode("x", &pct_encode(text)).unwrap(), text);
        assert!(pct_decode("title", "%ZZ")
            .unwrap_err()
            .message
            .contains("'title'"));
        assert!(pct_decode("title", "%FF").is_err());
        assert_eq!(pct_decode("t", "a+b").unwrap(), "a b");
    }

    #[test]
    fn urls_give_their_query() {
        assert_eq!(query_of(" https://h/p/?c=1&x=2#frag "), "c=1&x=2");
        assert_eq!(query_of("c=1&x=2"), "c=1&x=2");
        assert_eq!(query_of("?c=1"), "c=1");
    }
}
