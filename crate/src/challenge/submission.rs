//! A student's answer: a challenge with the values they set, checked against what it allows, and
//! the scenarios its runs take.

use super::codec::{apply_overrides, number, parse_parts, pct_encode, sort_small};
use super::{Allowed, Challenge, ChallengeError};
use crate::scenario::Scenario;
use crate::text::{excerpt, short, Message};
use serde::Serialize;

/// A challenge with the values a student set.
#[derive(Clone, Debug, PartialEq, Serialize)]
pub struct Submission {
    /// The challenge answered.
    pub challenge: Challenge,
    /// The fields set and their values (canonical codec text), in the challenge's allow order.
    pub tries: Vec<(String, String)>,
}

impl Submission {
    /// Parses a submission (bare or in a URL) against its own challenge text.
    pub fn parse(text: &str) -> Result<Submission, ChallengeError> {
        let (challenge, tries) = parse_parts(text)?;
        Submission::check(challenge, &tries)
    }

    /// The tries checked against the challenge: allowed, well-formed, in range.
    pub(super) fn check(
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
                .ok_or_else(|| ChallengeError::refused(not_allowed(field)))?;
            let text = match &allow.allowed {
                Allowed::Range { lo, hi } => {
                    let v = number(value).ok_or_else(|| {
                        ChallengeError::malformed(
                            Message::new("challenge-try-not-number")
                                .text("field", field.as_str())
                                .text("value", excerpt(value)),
                        )
                    })?;
                    if v < *lo || v > *hi {
                        return Err(ChallengeError::refused(
                            Message::new("challenge-try-outside")
                                .text("setting", format!("{field}={}", short(v)))
                                .text("range", format!("{lo}..{hi}")),
                        ));
                    }
                    format!("{v}")
                }
                Allowed::Choice { options } => {
                    if !options.iter().any(|o| o == value) {
                        return Err(ChallengeError::refused(
                            Message::new("challenge-try-not-option")
                                .text("setting", format!("{field}={}", excerpt(value)))
                                .text("options", options.join("|")),
                        ));
                    }
                    value.clone()
                }
                // Any formula the field takes: the field's own check below parses it.
                Allowed::Formula => value.clone(),
            };
            // The field's own rules (whole numbers, say) on the base.
            base.clone()
                .set(field, &text)
                .map_err(|e| ChallengeError::refused(e.message()))?;
            out.push((field.clone(), text));
        }
        let order = |f: &str| challenge.allow.iter().position(|a| a.field == f);
        sort_small(&mut out, |(f, _)| order(f));
        Ok(Submission {
            challenge,
            tries: out,
        })
    }

    /// The canonical text: the challenge's, then `try.FIELD=VALUE` in allow order, each value
    /// percent-encoded as the codec encodes text.
    pub fn encode(&self) -> String {
        let mut out = self.challenge.encode();
        for (f, v) in &self.tries {
            out.push_str(&format!("&try.{f}={}", pct_encode(v)));
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
                .map_err(|e| ChallengeError::refused(e.message()))?;
        }
        let mut out = vec![nominal.clone()];
        if let Some(vary) = &self.challenge.vary {
            for o in vary.overrides() {
                let mut s = nominal.clone();
                let what = |error: Message| {
                    Message::new("challenge-variant-refused")
                        .text("overrides", excerpt(&o))
                        .said("error", error)
                };
                apply_overrides(&mut s, &o, &what)
                    .map_err(|e| ChallengeError::refused(e.message))?;
                out.push(s);
            }
        }
        Ok(out)
    }
}

impl Challenge {
    /// The submission of a student's values, `tries` as [field, value] pairs in any order (the
    /// values as typed): the canonical submission link, read back by [`Challenge::submission`]
    /// as the codec reads any link, so a field not allowed, a value out of range or a field
    /// given twice is refused with the same message.
    pub fn submit(&self, tries: &[(String, String)]) -> Result<Submission, ChallengeError> {
        let mut text = self.encode();
        for (field, value) in tries {
            // Only an allowed field's name goes into the text as it is: the allowed fields are
            // scenario keys, which need no encoding.
            if !self.allow.iter().any(|a| &a.field == field) {
                return Err(ChallengeError::refused(not_allowed(field)));
            }
            text.push_str(&format!("&try.{field}={}", pct_encode(value)));
        }
        self.submission(&text)
    }
}

/// The refusal of a field the challenge does not allow.
fn not_allowed(field: &str) -> Message {
    Message::new("challenge-try-not-allowed").text("field", excerpt(field))
}
