//! The challenge codec's text: a query's `key=value` pieces, percent coding, and each key's value
//! read and checked against the base scenario.

use super::judge::{criterion_ops, figure_info, figures};
use super::{
    builtin, Allow, Allowed, Challenge, ChallengeError, Criterion, Op, Variants, BUILTINS,
    CHALLENGE_VERSION, MAX_CHALLENGE_BYTES, MAX_CRITERIA, MAX_TITLE_CHARS, MAX_VARIANTS,
};
use crate::record::LOAD_RECOVERY;
use crate::scenario::{FieldInfo, Scenario, MAX_SEED};
use crate::text::percent::{self, Plus};
use crate::text::{excerpt, Message};
use std::collections::HashSet;

/// The query of `text`: a bare query string, or the part of a URL after `?` without `#…`.
pub(super) fn query_of(text: &str) -> &str {
    let text = text.trim();
    let text = text.split_once('#').map_or(text, |(q, _)| q);
    text.split_once('?').map_or(text, |(_, q)| q)
}

/// Decodes `%XX` escapes and `+` (a space); `key` names the value in the error.
pub(super) fn pct_decode(key: &str, value: &str) -> Result<String, ChallengeError> {
    percent::decode(value, Plus::Space).ok_or_else(|| {
        ChallengeError::malformed(
            Message::new("challenge-not-percent-encoded")
                .text("key", excerpt(key))
                .text("value", excerpt(value)),
        )
    })
}

/// Percent-encodes everything but the unreserved characters `A–Z a–z 0–9 - . _ ~`.
pub(super) fn pct_encode(text: &str) -> String {
    percent::encode(text, b"-._~")
}

/// A plain decimal number (the scenario codec's: no `inf`, `nan` or `+`), finite.
pub(super) fn number(text: &str) -> Option<f64> {
    crate::scenario::parse_number(text).filter(|v| v.is_finite())
}

/// The scenario field `key`, described on `base`.
pub(super) fn field_info(base: &Scenario, key: &str) -> Option<FieldInfo> {
    base.describe().into_iter().find(|f| f.key == key)
}

/// The position of scenario field `key` in the field table (the codec's order).
pub(super) fn field_order(base: &Scenario, key: &str) -> usize {
    base.describe()
        .iter()
        .position(|f| f.key == key)
        .unwrap_or(usize::MAX)
}

/// Refuses a challenge or submission text longer than [`MAX_CHALLENGE_BYTES`].
pub(super) fn check_length(text: &str) -> Result<(), ChallengeError> {
    if text.len() > MAX_CHALLENGE_BYTES {
        return Err(ChallengeError::malformed(
            Message::new("challenge-too-long")
                .count("bytes", text.len())
                .count("max", MAX_CHALLENGE_BYTES)
                .count("kib", MAX_CHALLENGE_BYTES / 1024),
        ));
    }
    Ok(())
}

/// The `key=value` pieces of a query, refusing pieces without `=`, duplicates and an
/// over-long text.
pub(super) fn pieces(text: &str) -> Result<Vec<(&str, &str)>, ChallengeError> {
    check_length(text)?;
    let mut seen = HashSet::new();
    let mut out = Vec::new();
    for piece in query_of(text).split('&').filter(|p| !p.is_empty()) {
        let (k, v) = piece
            .split_once('=')
            .ok_or_else(|| ChallengeError::malformed(not_key_value(piece)))?;
        if !seen.insert(k) {
            return Err(ChallengeError::malformed(given_twice(k)));
        }
        out.push((k, v));
    }
    Ok(out)
}

/// The refusal of a piece that is not `key=value`, as the scenario codec words it.
fn not_key_value(piece: &str) -> Message {
    Message::new("scenario-malformed").text("piece", excerpt(piece))
}

/// The refusal of a key given twice, as the scenario codec words it.
pub(super) fn given_twice(key: &str) -> Message {
    Message::new("scenario-duplicate-key").text("key", excerpt(key))
}

/// The key and value of one `key=value` piece of an override string; `what` says an error of
/// the override, naming it.
pub(super) fn key_value<'a>(
    piece: &'a str,
    what: &dyn Fn(Message) -> Message,
) -> Result<(&'a str, &'a str), ChallengeError> {
    piece
        .split_once('=')
        .ok_or_else(|| ChallengeError::malformed(what(not_key_value(piece))))
}

/// A scenario override string (`key=value&…`) applied to `s`, each field checked; `what` says
/// an error of the override, naming it.
pub(super) fn apply_overrides(
    s: &mut Scenario,
    text: &str,
    what: &dyn Fn(Message) -> Message,
) -> Result<(), ChallengeError> {
    for piece in text.split('&').filter(|p| !p.is_empty()) {
        let (k, v) = key_value(piece, what)?;
        s.set(k, v)
            .map_err(|e| ChallengeError::malformed(what(e.message())))?;
    }
    Ok(())
}

/// The built-in challenge named `name`, or the error naming the built-in ones.
pub(super) fn builtin_named(name: &str) -> Result<Challenge, ChallengeError> {
    let b = builtin(name).ok_or_else(|| {
        ChallengeError::malformed(
            Message::new("challenge-unknown")
                .text("name", excerpt(name))
                .text(
                    "names",
                    BUILTINS
                        .iter()
                        .map(|b| b.name)
                        .collect::<Vec<_>>()
                        .join(", "),
                ),
        )
    })?;
    Ok(b.challenge())
}

/// Parses the challenge part of `text` (or a built-in's name) and returns it with the raw
/// `try.*` pairs.
pub(super) fn parse_parts(
    text: &str,
) -> Result<(Challenge, Vec<(String, String)>), ChallengeError> {
    let trimmed = text.trim();
    if !trimmed.contains('=') {
        return Ok((builtin_named(trimmed)?, Vec::new()));
    }
    let pairs = pieces(text)?;
    let get = |key: &str| pairs.iter().find(|(k, _)| *k == key).map(|(_, v)| *v);
    if let Some(name) = get("challenge") {
        return builtin_with_tries(name, &pairs);
    }
    let version = get("c").ok_or_else(|| missing_version(query_of(text)))?;
    if version != CHALLENGE_VERSION.to_string() {
        return Err(ChallengeError::malformed(
            Message::new("challenge-unsupported-version")
                .text("value", excerpt(version))
                .count("version", CHALLENGE_VERSION),
        ));
    }
    // Unknown keys first, in the order written.
    for (k, _) in &pairs {
        let known = matches!(*k, "c" | "title" | "base" | "vary" | "robust")
            || ["allow.", "need.", "try."]
                .iter()
                .any(|p| k.strip_prefix(p).is_some_and(|rest| !rest.is_empty()));
        if !known {
            return Err(ChallengeError::malformed(
                Message::new("challenge-unknown-key")
                    .text("key", excerpt(k))
                    .text(
                        "fields",
                        "c, title, base, allow.FIELD, need.FIGURE, vary, robust, try.FIELD",
                    ),
            ));
        }
    }
    let title = pct_decode("title", get("title").unwrap_or(""))?;
    check_title(&title)?;
    let base_text = pct_decode(
        "base",
        get("base").ok_or_else(|| {
            ChallengeError::malformed(Message::new("challenge-missing").text("key", "base"))
        })?,
    )?;
    let mut draft = Draft::new(title, &base_text)?;
    let mut tries = Vec::new();
    for (k, v) in &pairs {
        if let Some(field) = k.strip_prefix("allow.") {
            draft.allow(field, v)?;
        } else if let Some(figure) = k.strip_prefix("need.") {
            draft.need(figure, v)?;
        } else if let Some(field) = k.strip_prefix("try.") {
            tries.push((field.to_string(), pct_decode(k, v)?));
        }
    }
    let challenge = draft
        .finish(get("vary"), get("robust"))
        .map_err(|(_, e)| e)?;
    Ok((challenge, tries))
}

/// A built-in challenge named by `challenge=NAME` with the student's `try.*` pairs; any other
/// field is refused, since a built-in's text is fixed.
fn builtin_with_tries(
    name: &str,
    pairs: &[(&str, &str)],
) -> Result<(Challenge, Vec<(String, String)>), ChallengeError> {
    let challenge = builtin_named(name)?;
    let mut tries = Vec::new();
    for (k, v) in pairs {
        if let Some(field) = k.strip_prefix("try.").filter(|f| !f.is_empty()) {
            tries.push((field.to_string(), pct_decode(k, v)?));
        } else if *k != "challenge" {
            return Err(ChallengeError::malformed(
                Message::new("challenge-builtin-extra")
                    .text("key", excerpt(k))
                    .text("name", excerpt(name)),
            ));
        }
    }
    Ok((challenge, tries))
}

/// The error for a challenge text without its `c` field, naming any stray characters written
/// before a `c=` that starts the text.
fn missing_version(query: &str) -> ChallengeError {
    let first = query.split('&').next().unwrap_or("");
    let stray = first
        .find("c=")
        .filter(|&at| at > 0)
        .map(|at| &first[..at])
        .filter(|s| !s.chars().any(char::is_alphanumeric));
    ChallengeError::malformed(match stray {
        Some(stray) => Message::new("challenge-stray")
            .text("stray", excerpt(stray))
            .count("count", stray.chars().count())
            .count("version", CHALLENGE_VERSION),
        None => Message::new("challenge-version-missing").count("version", CHALLENGE_VERSION),
    })
}

/// Refuses a title longer than [`MAX_TITLE_CHARS`].
pub(super) fn check_title(title: &str) -> Result<(), ChallengeError> {
    let chars = title.chars().count();
    if chars > MAX_TITLE_CHARS {
        return Err(ChallengeError::malformed(
            Message::new("challenge-title-too-long")
                .count("chars", chars)
                .count("max", MAX_TITLE_CHARS),
        ));
    }
    Ok(())
}

/// The part of a challenge an error is about, as the composer names it to the page.
#[derive(Clone, Debug, PartialEq)]
pub(super) enum Part {
    /// `title`.
    Title,
    /// `base`.
    Base,
    /// `allow.FIELD`.
    Allow(String),
    /// `need.FIGURE`.
    Need(String),
    /// The criteria as a whole: none, or too many.
    Criteria,
    /// `vary`.
    Vary,
    /// `robust`.
    Robust,
    /// The whole text (its length).
    Whole,
}

impl Part {
    /// The key: `title`, `base`, `allow.FIELD`, `need.FIGURE`, `need`, `vary`, `robust` or
    /// `challenge`.
    pub(super) fn key(&self) -> String {
        match self {
            Part::Title => "title".to_string(),
            Part::Base => "base".to_string(),
            Part::Allow(field) => format!("allow.{field}"),
            Part::Need(figure) => format!("need.{figure}"),
            Part::Criteria => "need".to_string(),
            Part::Vary => "vary".to_string(),
            Part::Robust => "robust".to_string(),
            Part::Whole => "challenge".to_string(),
        }
    }
}

/// A challenge read part by part: the base first, then the allowed fields and the criteria in
/// the order given, then the variants. The codec and the composer both build through it, so
/// each part is checked by one rule whichever way it comes.
pub(super) struct Draft {
    title: String,
    base: Scenario,
    allow: Vec<Allow>,
    need: Vec<Criterion>,
}

impl Draft {
    /// A draft on the base scenario `base` (its text, decoded); `title` already checked.
    pub(super) fn new(title: String, base: &str) -> Result<Draft, ChallengeError> {
        let base = Scenario::parse(base).map_err(|e| {
            ChallengeError::malformed(Message::new("challenge-bad-base").said("error", e.message()))
        })?;
        Ok(Draft {
            title,
            base,
            allow: Vec::new(),
            need: Vec::new(),
        })
    }

    /// `allow.FIELD=VALUE`, the value as the codec writes it.
    pub(super) fn allow(&mut self, field: &str, value: &str) -> Result<(), ChallengeError> {
        self.allow.push(parse_allow(&self.base, field, value)?);
        Ok(())
    }

    /// `need.FIGURE=OP`, the op as the codec writes it.
    pub(super) fn need(&mut self, figure: &str, value: &str) -> Result<(), ChallengeError> {
        self.need.push(parse_need(&self.base, figure, value)?);
        Ok(())
    }

    /// The challenge, with `vary` and `robust` as the codec writes them (the overrides of a list
    /// percent-encoded); an error comes with the part it is about.
    pub(super) fn finish(
        self,
        vary: Option<&str>,
        robust: Option<&str>,
    ) -> Result<Challenge, (Part, ChallengeError)> {
        let Draft {
            title,
            base,
            mut allow,
            need,
        } = self;
        sort_small(&mut allow, |a| field_order(&base, &a.field));
        if need.is_empty() {
            return Err((
                Part::Criteria,
                ChallengeError::malformed(Message::new("challenge-no-criteria")),
            ));
        }
        if need.len() > MAX_CRITERIA {
            return Err((
                Part::Criteria,
                ChallengeError::malformed(
                    Message::new("challenge-too-many-criteria")
                        .count("count", need.len())
                        .count("max", MAX_CRITERIA),
                ),
            ));
        }
        let vary = vary
            .map(|v| parse_vary(&base, v))
            .transpose()
            .map_err(|e| (Part::Vary, e))?;
        let robust = match robust {
            None => Vec::new(),
            Some(v) => parse_robust(&need, v).map_err(|e| (Part::Robust, e))?,
        };
        match (&vary, robust.is_empty()) {
            (Some(_), true) => {
                return Err((
                    Part::Vary,
                    ChallengeError::malformed(Message::new("challenge-vary-unused")),
                ))
            }
            (None, false) => {
                return Err((
                    Part::Robust,
                    ChallengeError::malformed(Message::new("challenge-robust-without-vary")),
                ))
            }
            _ => {}
        }
        Ok(Challenge {
            title,
            base: base.encode(),
            allow,
            need,
            vary,
            robust,
        })
    }
}

/// `allow.FIELD=VALUE`.
fn parse_allow(base: &Scenario, field: &str, value: &str) -> Result<Allow, ChallengeError> {
    let key = format!("allow.{field}");
    let info = field_info(base, field).ok_or_else(|| {
        ChallengeError::malformed(
            Message::new("challenge-allow-unknown-field")
                .text("key", excerpt(&key))
                .text("field", excerpt(field)),
        )
    })?;
    let allowed = if info.formula.is_some() {
        if value != "formula" {
            return Err(ChallengeError::malformed(
                Message::new("challenge-allow-formula")
                    .text("key", key.as_str())
                    .text("value", excerpt(value))
                    .text("field", field),
            ));
        }
        Allowed::Formula
    } else if info.options.is_empty() {
        let bad = || {
            ChallengeError::malformed(
                Message::new("challenge-allow-range")
                    .text("key", key.as_str())
                    .text("value", excerpt(value)),
            )
        };
        let (lo, hi) = value.split_once("..").ok_or_else(bad)?;
        let (lo, hi) = (number(lo).ok_or_else(bad)?, number(hi).ok_or_else(bad)?);
        if lo > hi {
            return Err(bad());
        }
        // Both ends must be values of the field.
        for end in [lo, hi] {
            base.clone().set(field, &format!("{end}")).map_err(|e| {
                ChallengeError::malformed(
                    Message::new("challenge-allow-refused")
                        .text("key", key.as_str())
                        .text("value", excerpt(value))
                        .said("error", e.message()),
                )
            })?;
        }
        Allowed::Range { lo, hi }
    } else {
        let mut options: Vec<String> = Vec::new();
        for o in value.split('|') {
            if !info.options.contains(&o) || options.iter().any(|x| x == o) {
                return Err(ChallengeError::malformed(
                    Message::new("challenge-allow-choice")
                        .text("key", key.as_str())
                        .text("value", excerpt(value))
                        .text("options", info.options.join("|")),
                ));
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
        return Err(ChallengeError::malformed(
            Message::new("challenge-need-unknown-figure")
                .text("key", excerpt(&key))
                .text("figure", excerpt(figure))
                .text(
                    "figures",
                    figures().map(|f| f.name).collect::<Vec<_>>().join(", "),
                ),
        ));
    }
    let op = if value == "band" {
        if !criterion_ops(figure).0.contains(&"band") {
            return Err(ChallengeError::malformed(
                Message::new("challenge-need-band").text("key", key.as_str()),
            ));
        }
        Op::Band
    } else {
        let bad = || {
            ChallengeError::malformed(
                Message::new("challenge-need-op")
                    .text("key", key.as_str())
                    .text("value", excerpt(value)),
            )
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
    if figure == LOAD_RECOVERY && base.load_step.step().is_none() {
        return Err(ChallengeError::malformed(
            Message::new("challenge-need-no-load-step").text("key", key.as_str()),
        ));
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
            ChallengeError::malformed(
                Message::new("challenge-vary-seeds")
                    .text("value", excerpt(value))
                    .count("max_seed", MAX_SEED)
                    .count("max", MAX_VARIANTS),
            )
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
        return Err(ChallengeError::malformed(
            Message::new("challenge-vary-too-many")
                .count("count", raw.len())
                .count("max", MAX_VARIANTS),
        ));
    }
    let mut overrides = Vec::new();
    for (i, r) in raw.iter().enumerate() {
        let text = pct_decode("vary", r)?;
        let what = |error: Message| {
            Message::new("challenge-vary-variant-refused")
                .count("number", i + 1)
                .said("error", error)
        };
        let mut pairs: Vec<(String, String)> = Vec::new();
        for piece in text.split('&').filter(|p| !p.is_empty()) {
            let (k, v) = key_value(piece, &what)?;
            if pairs.iter().any(|(x, _)| x == k) {
                return Err(ChallengeError::malformed(what(given_twice(k))));
            }
            pairs.push((k.to_string(), v.to_string()));
        }
        if pairs.is_empty() {
            return Err(ChallengeError::malformed(
                Message::new("challenge-vary-variant-empty").count("number", i + 1),
            ));
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
            return Err(ChallengeError::malformed(
                Message::new("challenge-robust-unknown")
                    .text("value", excerpt(value))
                    .text("figure", excerpt(f)),
            ));
        }
        out.push(f.to_string());
    }
    sort_small(&mut out, |f| need.iter().position(|c| &c.figure == f));
    Ok(out)
}

/// Sorts the few items of a challenge's lists by `key`, keeping equal keys in order: an insertion
/// sort, a few hundred bytes of WASM where the standard library's stable sort takes about ten
/// kilobytes for each type it sorts.
pub(super) fn sort_small<T, K: Ord>(items: &mut [T], key: impl Fn(&T) -> K) {
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
            .to_string()
            .contains("'title'"));
        assert!(pct_decode("title", "%FF").is_err());
        assert_eq!(pct_decode("t", "a+b").unwrap(), "a b");
        // As the scenario codec reads a formula: two hex digits or nothing.
        assert!(pct_decode("title", "%+1").is_err());
    }

    #[test]
    fn urls_give_their_query() {
        assert_eq!(query_of(" https://h/p/?c=1&x=2#frag "), "c=1&x=2");
        assert_eq!(query_of("c=1&x=2"), "c=1&x=2");
        assert_eq!(query_of("?c=1"), "c=1");
    }
}
