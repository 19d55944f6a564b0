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
//! followed by `&try.FIELD=VALUE` for the fields set (see [`Submission`]). Only the core writes
//! these texts: [`Challenge::compose`] from a lecturer's parts, [`Challenge::submit`] from a
//! student's values, and [`Challenge::from_link`] opens any of them. [`Challenge::search_designs`]
//! lists the designs a check tries before a challenge is set, to tell whether any passes.

mod brief;
mod builtin;
mod codec;
mod compose;
mod error;
pub mod grade;
mod judge;
mod search;
mod submission;

pub use crate::record::LOAD_RECOVERY;
pub use brief::{Brief, Paragraph};
pub use builtin::{builtin, Builtin, BUILTINS};
pub use compose::{AllowPart, ChallengeParts, ComposeError, FormList, FormNumber, NeedPart};
pub use error::{ChallengeError, ErrorKind};
#[cfg(all(target_arch = "wasm32", feature = "tools"))]
pub(crate) use judge::bound_text;
pub use judge::{
    criterion_ops, figure_info, figures, judge, measure, CriterionVerdict, Measure, Measures,
    NotFinite, Verdict,
};
pub use search::{Design, MAX_SEARCH_DESIGNS, MOST_SEARCH_POINTS, SEARCH_POINTS};
pub use submission::Submission;

use crate::scenario::Scenario;
use crate::text::{excerpt, Message};
use codec::{check_length, parse_parts, pct_encode, query_of};
use serde::Serialize;

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
    /// Any formula the field takes: a step's own law (`law.v1`..`law.v4`).
    Formula,
}

impl Allowed {
    /// The codec text: `LO..HI`, `a|b` or `formula`.
    pub fn text(&self) -> String {
        match self {
            Allowed::Range { lo, hi } => format!("{lo}..{hi}"),
            Allowed::Choice { options } => options.join("|"),
            Allowed::Formula => "formula".to_string(),
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

impl Challenge {
    /// Parses a challenge: its text (bare or in a URL) or the name of a built-in one.
    pub fn parse(text: &str) -> Result<Challenge, ChallengeError> {
        let (challenge, tries) = parse_parts(text)?;
        if let Some((k, _)) = tries.first() {
            return Err(ChallengeError::malformed(
                Message::new("challenge-is-submission").text("key", excerpt(k)),
            ));
        }
        Ok(challenge)
    }

    /// Opens the challenge of any link the address bar may hold: a challenge link, a submission
    /// link (its `try.*` parts are left out unread), `challenge=NAME` for a built-in one, or a
    /// built-in's name; each bare or in a URL. The challenge is read by [`Challenge::parse`].
    pub fn from_link(text: &str) -> Result<Challenge, ChallengeError> {
        check_length(text)?;
        let kept: Vec<&str> = query_of(text)
            .split('&')
            .filter(|p| !p.is_empty() && !p.starts_with("try."))
            .collect();
        Challenge::parse(&kept.join("&"))
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
                message: Message::new("challenge-another"),
            });
        }
        Submission::check(challenge, &tries)
    }

    /// Whether criterion `figure` must hold on every variant.
    pub fn is_robust(&self, figure: &str) -> bool {
        self.robust.iter().any(|r| r == figure)
    }

    /// A short code of the canonical text ([`Challenge::encode`]) to tell challenges apart at a
    /// glance: the top 40 bits of its 64-bit FNV-1a hash in Crockford's base 32 (digits and
    /// capitals but I, L, O and U), two groups of four, e.g. `7KQ2-M9XD`. Two challenges with
    /// the same code are the same challenge but for a chance of about one in a million million.
    pub fn fingerprint(&self) -> String {
        const ALPHABET: &[u8; 32] = b"0123456789ABCDEFGHJKMNPQRSTVWXYZ";
        let hash = fnv1a(self.encode().as_bytes());
        let mut out = String::with_capacity(9);
        for i in 0..8 {
            if i == 4 {
                out.push('-');
            }
            let digit = (hash >> (59 - 5 * i)) & 31;
            out.push(char::from(ALPHABET[digit as usize]));
        }
        out
    }

    /// The name of the built-in challenge this one passes for while it differs from it: its
    /// title is the built-in's title or name (compared trimmed, in any case) but its canonical
    /// text is not the built-in's. None for a built-in itself and for any other title.
    pub fn edited_builtin(&self) -> Option<&'static str> {
        let claimed = self.title.trim().to_lowercase();
        let text = self.encode();
        BUILTINS
            .iter()
            .find(|b| {
                let title = b.challenge().title.to_lowercase();
                (claimed == title || claimed == b.name) && text != b.text
            })
            .map(|b| b.name)
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

/// The 64-bit FNV-1a hash of `bytes`: stable across platforms and releases.
pub(crate) fn fnv1a(bytes: &[u8]) -> u64 {
    bytes.iter().fold(0xcbf2_9ce4_8422_2325_u64, |h, &b| {
        (h ^ u64::from(b)).wrapping_mul(0x0000_0100_0000_01b3)
    })
}
