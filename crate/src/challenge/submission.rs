//! A student's answer: a challenge with the values they set, checked against what it allows, and
//! the scenarios its runs take.

use super::codec::{apply_overrides, number, parse_parts, sort_small};
use super::{Allowed, Challenge, ChallengeError};
use crate::quote::excerpt;
use crate::scenario::{short, Scenario};
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
