//! The challenge bindings: a challenge parsed once, its description, submissions, the measures of
//! a run and the verdict on them.

use super::{from_js, js_error, read_js, to_js, to_js_list};
use crate::challenge::{Brief, ErrorKind};
use crate::scenario::Scenario;
use crate::text::Message;
use serde::Serialize;
use tsify::Ts;
use wasm_bindgen::prelude::*;

/// A design challenge, parsed once: its description, the scenarios a submission runs and the
/// verdict on their measures. The page runs each scenario in a worker (`new Simulation(text)`,
/// stepped to the end), measures it there with [`challenge_measure`] and judges the measures
/// here, so only small JSON crosses between workers.
#[wasm_bindgen]
pub struct Challenge {
    inner: crate::challenge::Challenge,
}

/// What kind of values an allowed field takes; the page sees "range" or "choice".
#[cfg_attr(
    target_arch = "wasm32",
    derive(tsify::Tsify),
    tsify(missing_as_null, hashmap_as_object)
)]
#[derive(Clone, Copy, Serialize)]
#[serde(rename_all = "lowercase")]
enum AllowKind {
    /// A number from `lo` to `hi`.
    Range,
    /// One of `options`.
    Choice,
    /// A formula: a step's own law.
    Formula,
}

/// An allowed field as the page shows it.
#[cfg_attr(
    target_arch = "wasm32",
    derive(tsify::Tsify),
    tsify(missing_as_null, hashmap_as_object)
)]
#[derive(Serialize)]
pub struct AllowView {
    field: String,
    kind: AllowKind,
    lo: Option<f64>,
    hi: Option<f64>,
    options: Vec<String>,
    unit: &'static str,
    doc: crate::text::Message,
    /// The base scenario's value, as the codec writes it.
    value: Option<String>,
}

/// How a criterion bounds its figure; the page sees "max", "min", "abs" or "band".
#[cfg_attr(
    target_arch = "wasm32",
    derive(tsify::Tsify),
    tsify(missing_as_null, hashmap_as_object)
)]
#[derive(Clone, Copy, Serialize)]
#[serde(rename_all = "lowercase")]
enum OpKind {
    /// value ≤ bound.
    Max,
    /// value ≥ bound.
    Min,
    /// |value| ≤ bound.
    Abs,
    /// Inside the mean NIS's 95 % band (no bound).
    Band,
}

/// A criterion as the page shows it.
#[cfg_attr(
    target_arch = "wasm32",
    derive(tsify::Tsify),
    tsify(missing_as_null, hashmap_as_object)
)]
#[derive(Serialize)]
pub struct NeedView {
    figure: String,
    label: crate::text::Message,
    unit: &'static str,
    op: OpKind,
    bound: Option<f64>,
    /// The bound in words, as a verdict gives it ("≤ 0.004 s").
    bound_text: Message,
    /// Whether it must hold on every variant too.
    robust: bool,
}

#[cfg_attr(
    target_arch = "wasm32",
    derive(tsify::Tsify),
    tsify(missing_as_null, hashmap_as_object)
)]
#[derive(Serialize)]
pub struct ChallengeView {
    /// The title as the page shows it: its invisible characters escaped, as in every message.
    title: String,
    base: String,
    encoded: String,
    allow: Vec<AllowView>,
    need: Vec<NeedView>,
    /// Each variant's override string (`seed=2`, `model.j=0.016`).
    variants: Vec<String>,
    /// The task in words, with the title (see [`crate::challenge::Challenge::brief`]).
    brief: Brief,
    /// The brief without its title (see [`crate::challenge::Challenge::task`]).
    task: Brief,
    /// [`crate::challenge::Challenge::fingerprint`]: `7KQ2-M9XD`.
    fingerprint: String,
    /// The built-in this challenge passes for while it differs from it
    /// ([`crate::challenge::Challenge::edited_builtin`]), or null.
    edited_from: Option<&'static str>,
}

/// Whether a submission link can be graded, or why not; the page sees "ok", "malformed",
/// "refused" or "another".
#[cfg_attr(
    target_arch = "wasm32",
    derive(tsify::Tsify),
    tsify(missing_as_null, hashmap_as_object)
)]
#[derive(Clone, Copy, Serialize)]
#[serde(rename_all = "lowercase")]
enum SubmissionKind {
    /// It can run.
    Ok,
    /// See [`ErrorKind::Malformed`].
    Malformed,
    /// See [`ErrorKind::Refused`].
    Refused,
    /// See [`ErrorKind::Another`].
    Another,
}

impl From<ErrorKind> for SubmissionKind {
    fn from(kind: ErrorKind) -> Self {
        match kind {
            ErrorKind::Malformed => SubmissionKind::Malformed,
            ErrorKind::Refused => SubmissionKind::Refused,
            ErrorKind::Another => SubmissionKind::Another,
        }
    }
}

/// What a submission link gives: its status and, when it can run, the scenarios to run.
#[cfg_attr(
    target_arch = "wasm32",
    derive(tsify::Tsify),
    tsify(missing_as_null, hashmap_as_object)
)]
#[derive(Serialize)]
pub struct SubmissionView {
    kind: SubmissionKind,
    /// "ok", or the grading status: "malformed: …", "refused: …", "another challenge".
    status: Message,
    /// The error's message (null when ok).
    message: Option<Message>,
    /// The canonical submission link ("" unless ok).
    encoded: String,
    /// The fields set, [field, value] in allow order.
    tries: Vec<(String, String)>,
    /// Scenario strings: the nominal run first, then one per variant (empty unless ok).
    scenarios: Vec<String>,
}

#[wasm_bindgen]
impl Challenge {
    /// Parses a challenge link (bare query, or a URL whose query it is) or a built-in's name;
    /// throws the message naming the offending key or field.
    #[wasm_bindgen(constructor)]
    pub fn new(text: &str) -> Result<Challenge, JsValue> {
        let inner = crate::challenge::Challenge::parse(text).map_err(js_error)?;
        Ok(Challenge { inner })
    }

    /// Opens the challenge of any link the address bar may hold: a challenge link (`c=1&…`), a
    /// submission link (its `&try.FIELD=VALUE` parts are left out unread), `challenge=NAME` or a
    /// built-in's name, each a bare query or a URL (`?` before it and `#…` after it are
    /// ignored); throws the message naming the offending key or field.
    pub fn from_link(text: &str) -> Result<Challenge, JsValue> {
        let inner = crate::challenge::Challenge::from_link(text).map_err(js_error)?;
        Ok(Challenge { inner })
    }

    /// The challenge's parts, as [`challenge_compose`] takes them: `{title, base, allow: [{field,
    /// lo, hi} | {field, options: [name]}], need: [{figure, op, bound}], vary, robust: [figure]}`
    /// with numbers as the codec writes them (strings), `bound` left out for `band`, and `vary`
    /// `"seeds:A..B"`, an array of override strings, or null.
    pub fn parts(&self) -> Result<Ts<crate::challenge::ChallengeParts>, JsValue> {
        to_js(&self.inner.parts())
    }

    /// The canonical challenge link (query string).
    pub fn encode(&self) -> String {
        self.inner.encode()
    }

    /// `{title, base, encoded, allow: [{field, kind, lo, hi, options, unit, doc, value}],
    /// need: [{figure, label, unit, op, bound, bound_text, robust}], variants: [string], brief,
    /// task, fingerprint, edited_from}`: `label` and `bound_text` messages, `brief` and `task`
    /// the task in words (paragraphs of messages), `fingerprint` a short code of the canonical
    /// link to compare at a glance (`7KQ2-M9XD`), `edited_from` the name of the built-in whose
    /// title (or name) the challenge carries while its link differs from the built-in's, else
    /// null.
    pub fn describe(&self) -> Result<Ts<ChallengeView>, JsValue> {
        use crate::challenge::{figure_info, Allowed, Op};
        let c = &self.inner;
        let fields = c.base_scenario().describe();
        let allow = c
            .allow
            .iter()
            .map(|a| {
                let f = fields.iter().find(|f| f.key == a.field).expect("checked");
                let (kind, lo, hi, options) = match &a.allowed {
                    Allowed::Range { lo, hi } => {
                        (AllowKind::Range, Some(*lo), Some(*hi), Vec::new())
                    }
                    Allowed::Choice { options } => (AllowKind::Choice, None, None, options.clone()),
                    Allowed::Formula => (AllowKind::Formula, None, None, Vec::new()),
                };
                AllowView {
                    field: a.field.clone(),
                    kind,
                    lo,
                    hi,
                    options,
                    unit: f.unit,
                    doc: f.doc.clone(),
                    value: f.value.clone(),
                }
            })
            .collect();
        let need = c
            .need
            .iter()
            .map(|n| {
                let f = figure_info(&n.figure).expect("checked");
                let (op, bound) = match n.op {
                    Op::Max(b) => (OpKind::Max, Some(b)),
                    Op::Min(b) => (OpKind::Min, Some(b)),
                    Op::Abs(b) => (OpKind::Abs, Some(b)),
                    Op::Band => (OpKind::Band, None),
                };
                NeedView {
                    figure: n.figure.clone(),
                    label: f.label.clone(),
                    unit: f.unit,
                    op,
                    bound,
                    bound_text: crate::challenge::bound_text(&n.op, f.unit),
                    robust: c.is_robust(&n.figure),
                }
            })
            .collect();
        to_js(&ChallengeView {
            title: crate::text::escape_invisible(&c.title),
            base: c.base.clone(),
            encoded: c.encode(),
            allow,
            need,
            variants: c.run_labels().into_iter().skip(1).collect(),
            brief: c.brief(),
            task: c.task(),
            fingerprint: c.fingerprint(),
            edited_from: c.edited_builtin(),
        })
    }

    /// A submission link of this challenge (bare query or URL): never throws; returns
    /// `{kind, status, message, encoded, tries, scenarios}` (see the fields' docs).
    pub fn submission(&self, text: &str) -> Result<Ts<SubmissionView>, JsValue> {
        to_js(&submission_view(self.inner.submission(text)))
    }

    /// The submission of the student's settings, as [`Challenge::submission`] reads its
    /// canonical link (see [`Challenge::submit`]): `tries` is an array of [field, value] pairs
    /// (strings, any order); never throws for pairs of strings; returns `{kind, status, message,
    /// encoded, tries, scenarios}`, `encoded` the canonical submission link when `kind` is "ok".
    pub fn submission_of(
        &self,
        #[wasm_bindgen(unchecked_param_type = "[string, string][]")] tries: JsValue,
    ) -> Result<Ts<SubmissionView>, JsValue> {
        let tries: Vec<(String, String)> = read_js(tries)?;
        to_js(&submission_view(self.inner.submit(&tries)))
    }

    /// The designs a check of the challenge tries, at most `max` (and at most 10 000): an array
    /// of designs, each an array of [field, value] pairs (strings: the fields set, in allow order,
    /// each value as the codec writes it), for [`Challenge::submission_of`]. The base comes first
    /// (an empty array), then the designs that change the fewest fields, coarsest first; the full
    /// grid when it fits (see [`crate::challenge::Challenge::search_designs`] for the rule).
    #[wasm_bindgen(unchecked_return_type = "[string, string][][]")]
    pub fn search_designs(&self, max: u32) -> Result<JsValue, JsValue> {
        super::raw_js(&self.inner.search_designs(max as usize))
    }

    /// Judges the measures of the runs (`runs[0]` the nominal run, then one per variant, each
    /// what [`challenge_measure`] returned): `{criteria: [{figure, label, bound, value, unit, run,
    /// pass, reason}], pass}` (`label`, `bound` and `reason` messages, `reason` null when the
    /// criterion holds); throws the message when the count of runs is wrong.
    pub fn judge(
        &self,
        #[wasm_bindgen(unchecked_param_type = "Measures[]")] runs: JsValue,
    ) -> Result<Ts<crate::challenge::Verdict>, JsValue> {
        let runs: Vec<crate::challenge::Measures> = read_js(runs)?;
        let verdict = crate::challenge::judge(&self.inner, &runs).map_err(js_error)?;
        to_js(&verdict)
    }
}

/// What a submission read gives the page: its status and, when it can run, its scenarios.
fn submission_view(
    read: Result<crate::challenge::Submission, crate::challenge::ChallengeError>,
) -> SubmissionView {
    match read.and_then(|s| s.scenarios().map(|runs| (s, runs))) {
        Ok((s, runs)) => SubmissionView {
            kind: SubmissionKind::Ok,
            status: Message::new("grade-row-ok"),
            message: None,
            encoded: s.encode(),
            tries: s.tries.clone(),
            scenarios: runs.iter().map(Scenario::encode).collect(),
        },
        Err(e) => SubmissionView {
            kind: e.kind.into(),
            status: e.status(),
            message: Some(e.message.clone()),
            encoded: String::new(),
            tries: Vec::new(),
            scenarios: Vec::new(),
        },
    }
}

#[cfg_attr(
    target_arch = "wasm32",
    derive(tsify::Tsify),
    tsify(missing_as_null, hashmap_as_object)
)]
#[derive(Serialize)]
pub struct BuiltinView {
    name: &'static str,
    summary: &'static str,
    text: &'static str,
    solution: &'static str,
}

/// The built-in challenges: `[{name, summary, text, solution}]` (`text` the canonical link;
/// `solution` a passing `field=value&…`).
#[wasm_bindgen]
pub fn challenge_builtins() -> Result<Vec<Ts<BuiltinView>>, JsValue> {
    let list: Vec<BuiltinView> = crate::challenge::BUILTINS
        .iter()
        .map(|b| BuiltinView {
            name: b.name,
            summary: b.summary,
            text: b.text,
            solution: b.solution,
        })
        .collect();
    to_js_list(&list)
}

/// A figure a challenge's criterion may name, with the bounds it may take.
#[cfg_attr(
    target_arch = "wasm32",
    derive(tsify::Tsify),
    tsify(missing_as_null, hashmap_as_object)
)]
#[derive(Serialize)]
pub struct CriterionFigure {
    name: &'static str,
    label: crate::text::Message,
    unit: &'static str,
    /// The bounds (`max`, `min`, `abs`, `band`) in the order a composer offers them.
    ops: &'static [&'static str],
    /// The bound a composer starts with.
    op: &'static str,
}

/// The figures a challenge's criteria may name, each with the bounds it may take.
#[wasm_bindgen]
pub fn challenge_figures() -> Result<Vec<Ts<CriterionFigure>>, JsValue> {
    let figures: Vec<_> = crate::challenge::figures()
        .map(|f| {
            let (ops, op) = crate::challenge::criterion_ops(f.name);
            CriterionFigure {
                name: f.name,
                label: f.label.clone(),
                unit: f.unit,
                ops,
                op,
            }
        })
        .collect();
    to_js_list(&figures)
}

/// What [`challenge_compose`] gives: the link and the task in words, or the part at fault.
#[cfg_attr(
    target_arch = "wasm32",
    derive(tsify::Tsify),
    tsify(missing_as_null, hashmap_as_object)
)]
#[derive(Serialize)]
pub struct Composed {
    /// The canonical challenge link (query string), or null.
    encoded: Option<String>,
    /// The task in words (paragraphs of messages), or null.
    brief: Option<Brief>,
    /// `{key, message}` when the parts make no challenge, else null.
    error: Option<crate::challenge::ComposeError>,
}

/// A challenge from the composer's parts, encoded and checked by the codec's rules part by
/// part. `parts` is
///
/// ```text
/// {title: string, base: string (a scenario string),
///  allow: [{field, lo, hi} (a range; numbers or their text) | {field, options} (choices:
///          an array of names, or one string "a|b")],
///  need: [{figure, op: "max" | "min" | "abs" | "band", bound (number or text; none for band)}],
///  vary: "seeds:A..B" | "OVERRIDES|OVERRIDES…" | [override strings] | "" | null,
///  robust: [figure]}
/// ```
///
/// (missing members are empty; text is trimmed). Never throws for parts of that shape: returns
/// `{encoded, brief, error: null}`, or `{encoded: null, brief: null, error: {key, message}}`
/// where `key` names the part at fault: `title`, `base`, `allow.FIELD`, `need.FIGURE`, `need`
/// (no criterion, or too many), `vary`, `robust`, or `challenge` (the whole link too long), and
/// `message` is the core's message.
#[wasm_bindgen]
pub fn challenge_compose(
    parts: Ts<crate::challenge::ChallengeParts>,
) -> Result<Ts<Composed>, JsValue> {
    let parts = from_js(&parts)?;
    let view = match crate::challenge::Challenge::compose(&parts) {
        Ok(c) => Composed {
            encoded: Some(c.encode()),
            brief: Some(c.brief()),
            error: None,
        },
        Err(e) => Composed {
            encoded: None,
            brief: None,
            error: Some(e),
        },
    };
    to_js(&view)
}
