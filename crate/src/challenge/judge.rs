//! Measuring a run for a challenge and judging the criteria on the measures of its runs.
//!
//! [`measure`] reads a finished [`Simulation`] through its public API: the figures of
//! [`crate::record::report`] and the load-recovery time ([`crate::record::load_recovery`]).
//! [`judge`] needs only the measures, so runs can be measured wherever they ran (a worker each,
//! in the page).

use super::{Challenge, Op};
use crate::record::{
    load_recovery, FigureInfo, WarningKind, FIGURE_INFO, LOAD_RECOVERY, LOAD_RECOVERY_INFO,
};
use crate::sim::Simulation;
use crate::text::{Arg, Message};
use serde::{Deserialize, Serialize};

/// The report's figures a criterion may not name: the ends of the NIS band (a criterion asks
/// for the band with `band`) and the rating itself.
const NOT_CRITERIA: [&str; 3] = ["mean_nis_low", "mean_nis_high", "current_rated"];

/// The figures criteria may name: those of [`crate::record::report`] (its table, with its labels
/// and units) but the band's ends and the rating, then [`LOAD_RECOVERY`].
pub fn figures() -> impl Iterator<Item = &'static FigureInfo> {
    FIGURE_INFO
        .iter()
        .filter(|f| !NOT_CRITERIA.contains(&f.name))
        .chain(std::iter::once(&LOAD_RECOVERY_INFO))
}

/// The bounds a criterion on figure `name` may take, in the order a composer offers them, and
/// the one it starts with: the mean NIS inside its band (the only figure with one); a final
/// value, which may end on either side of zero, by its size; any other figure from above.
pub fn criterion_ops(name: &str) -> (&'static [&'static str], &'static str) {
    const FINALS: [&str; 3] = [
        "speed_error_final",
        "flux_error_final",
        "speed_estimate_error_final",
    ];
    if name == "mean_nis" {
        (&["band", "max", "min"], "band")
    } else if FINALS.contains(&name) {
        (&["max", "min", "abs"], "abs")
    } else {
        (&["max", "min", "abs"], "max")
    }
}

/// The figure named `name`, if criteria may name it.
pub fn figure_info(name: &str) -> Option<&'static FigureInfo> {
    figures().find(|f| f.name == name)
}

/// `message` with the number `value` in `unit` as its argument `name`: the number alone when
/// the unit is empty (a ratio), else the number and its unit (`0.004 s`).
pub(crate) fn quantity(message: Message, name: &'static str, value: f64, unit: &str) -> Message {
    if unit.is_empty() {
        message.real(name, value)
    } else {
        let q = Message::new("challenge-quantity")
            .real("value", value)
            .text("unit", unit);
        message.said(name, q)
    }
}

/// One measured value of a run.
#[cfg_attr(
    target_arch = "wasm32",
    derive(tsify::Tsify),
    tsify(missing_as_null, hashmap_as_object)
)]
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub struct Measure {
    /// Figure name.
    pub name: String,
    /// Value in `unit`; may be infinite (a load never recovered from).
    pub value: f64,
    /// Unit.
    pub unit: String,
    /// For a value read at the last sample: whether it had settled by the rule of the
    /// challenge's brief, over the last tenth of the run (see
    /// [`crate::record::Trend::settled_in_last_tenth`]).
    pub settled: Option<bool>,
}

/// What [`measure`] read from one run.
#[cfg_attr(
    target_arch = "wasm32",
    derive(tsify::Tsify),
    tsify(missing_as_null, hashmap_as_object)
)]
#[derive(Clone, Debug, Default, PartialEq, Serialize, Deserialize)]
pub struct Measures {
    /// The figures (those the report could compute), then the load recovery time when the
    /// scenario has a load step.
    pub figures: Vec<Measure>,
    /// The figures the run gives no number for, each with why.
    #[serde(default)]
    pub not_finite: Vec<NotFinite>,
    /// Why the run does not count, if it does not: the simulation failed, or it ran away. The
    /// core's message; or, for measures that crossed the page on their way to the judge, the
    /// text the page said it as.
    #[cfg_attr(target_arch = "wasm32", tsify(type = "Message | string | null"))]
    pub failure: Option<Arg>,
}

/// A figure a run gives no number for, because it is not finite, and why.
#[cfg_attr(
    target_arch = "wasm32",
    derive(tsify::Tsify),
    tsify(missing_as_null, hashmap_as_object)
)]
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub struct NotFinite {
    /// Figure name.
    pub name: String,
    /// Why it is not a number (a message, or the page's text of it, as `failure`).
    #[cfg_attr(target_arch = "wasm32", tsify(type = "Message | string"))]
    pub cause: Arg,
}

impl Measures {
    /// The measure named `name`.
    pub fn get(&self, name: &str) -> Option<&Measure> {
        self.figures.iter().find(|m| m.name == name)
    }
}

/// The measures of a finished run: every figure of its report (the `*_final` ones with whether
/// they settled over the last tenth, as the brief states), and [`LOAD_RECOVERY`] when its
/// scenario has a load step.
pub fn measure(sim: &Simulation) -> Measures {
    let r = sim.report();
    let mut figures: Vec<Measure> = r
        .figures
        .iter()
        .flatten()
        .map(|f| Measure {
            name: f.name.to_string(),
            value: f.value,
            unit: f.unit.to_string(),
            settled: f.trend.map(|t| t.settled_in_last_tenth),
        })
        .collect();
    if let Some(value) = load_recovery(sim.scenario(), sim) {
        figures.push(Measure {
            name: LOAD_RECOVERY.to_string(),
            value,
            unit: LOAD_RECOVERY_INFO.unit.to_string(),
            settled: None,
        });
    }
    let failure = if let Some(e) = sim.failure() {
        Some(e.message().into())
    } else if !sim.is_finished() {
        Some(Message::new("challenge-run-unfinished").into())
    } else {
        r.warnings
            .iter()
            .find(|w| w.kind == WarningKind::Runaway)
            .map(|w| w.text.clone().into())
    };
    let not_finite = r
        .warnings
        .iter()
        .filter_map(|w| {
            w.figure.map(|name| NotFinite {
                name: name.to_string(),
                cause: w.text.clone().into(),
            })
        })
        .collect();
    Measures {
        figures,
        not_finite,
        failure,
    }
}

/// The verdict on one criterion.
#[cfg_attr(
    target_arch = "wasm32",
    derive(tsify::Tsify),
    tsify(missing_as_null, hashmap_as_object)
)]
#[derive(Clone, Debug, PartialEq, Serialize)]
pub struct CriterionVerdict {
    /// Figure name.
    pub figure: String,
    /// The figure in words.
    pub label: Message,
    /// The bound in words, e.g. "≤ 0.004 s" or "inside its 95 % band".
    pub bound: Message,
    /// The value judged (the worst over the runs of a robust criterion); None when a run did
    /// not measure it.
    pub value: Option<f64>,
    /// Unit of `value`.
    pub unit: String,
    /// The run the value comes from: "nominal" or a variant's overrides.
    pub run: String,
    /// Whether the criterion holds.
    pub pass: bool,
    /// Why it fails (None when it holds): "above the bound", "still changing", …
    pub reason: Option<Message>,
    /// False when the value judged was still changing at the end of its run.
    pub settled: bool,
}

/// The verdict on a submission.
#[cfg_attr(
    target_arch = "wasm32",
    derive(tsify::Tsify),
    tsify(missing_as_null, hashmap_as_object, rename = "ChallengeVerdict")
)]
#[derive(Clone, Debug, PartialEq, Serialize)]
pub struct Verdict {
    /// One verdict per criterion, in the challenge's order.
    pub criteria: Vec<CriterionVerdict>,
    /// Whether every criterion holds.
    pub pass: bool,
}

/// How one run meets one criterion: its value, whether it holds, why not, and how far it is
/// from holding (for picking the worst run; failures without a value are the worst).
struct Check {
    value: Option<f64>,
    pass: bool,
    reason: Option<Message>,
    badness: f64,
    settled: bool,
}

fn check(op: &Op, figure: &str, m: &Measures) -> Check {
    let fail = |reason: Message| Check {
        value: None,
        pass: false,
        reason: Some(reason),
        badness: f64::INFINITY,
        settled: true,
    };
    if let Some(f) = &m.failure {
        return fail(Message::new("challenge-reason-run-failed").arg("failure", f.clone()));
    }
    if let Some(n) = m.not_finite.iter().find(|n| n.name == figure) {
        return fail(Message::new("challenge-reason-not-finite").arg("cause", n.cause.clone()));
    }
    let Some(x) = m.get(figure) else {
        return fail(Message::new(if figure == LOAD_RECOVERY {
            "challenge-reason-before-load-step"
        } else {
            "challenge-reason-not-measured"
        }));
    };
    let v = x.value;
    let (pass, badness, side) = match *op {
        Op::Max(b) => (v <= b, v - b, "challenge-reason-above-bound"),
        Op::Min(b) => (v >= b, b - v, "challenge-reason-below-bound"),
        Op::Abs(b) => (v.abs() <= b, v.abs() - b, "challenge-reason-beyond-bound"),
        Op::Band => {
            let (Some(lo), Some(hi)) = (m.get("mean_nis_low"), m.get("mean_nis_high")) else {
                return fail(Message::new("challenge-reason-no-band"));
            };
            let (lo, hi) = (lo.value, hi.value);
            let side = if v < lo {
                "challenge-reason-below-band"
            } else {
                "challenge-reason-above-band"
            };
            ((lo..=hi).contains(&v), (lo - v).max(v - hi), side)
        }
    };
    let mut out = Check {
        value: Some(v),
        pass,
        reason: (!pass).then(|| Message::new(side)),
        badness,
        settled: true,
    };
    if v.is_infinite() && figure == LOAD_RECOVERY {
        out.reason = Some(Message::new("challenge-reason-not-recovered"));
    }
    // A final value that is still moving is not a final value.
    if x.settled == Some(false) {
        out.pass = false;
        out.reason = Some(Message::new("challenge-reason-still-changing"));
        out.badness = f64::INFINITY;
        out.settled = false;
    }
    out
}

/// The bound of `op` in words, with `unit`: "≤ 0.004 s".
pub(crate) fn bound_text(op: &Op, unit: &str) -> Message {
    match *op {
        Op::Max(b) => quantity(Message::new("challenge-bound-max"), "bound", b, unit),
        Op::Min(b) => quantity(Message::new("challenge-bound-min"), "bound", b, unit),
        Op::Abs(b) => quantity(Message::new("challenge-bound-abs"), "bound", b, unit),
        Op::Band => Message::new("challenge-bound-band"),
    }
}

/// Judges `challenge` on the measures of its runs: `runs[0]` the nominal run, then one per
/// variant in order. A robust criterion reports its worst run; the others the nominal run.
pub fn judge(challenge: &Challenge, runs: &[Measures]) -> Result<Verdict, Message> {
    let labels = challenge.run_labels();
    if runs.len() != labels.len() {
        return Err(Message::new("challenge-judge-runs")
            .count("runs", labels.len())
            .count("variants", labels.len() - 1)
            .count("measured", runs.len()));
    }
    let mut criteria = Vec::new();
    for c in &challenge.need {
        let info = super::judge::figure_info(&c.figure).expect("checked when parsed");
        let count = if challenge.is_robust(&c.figure) {
            runs.len()
        } else {
            1
        };
        let mut worst: Option<(usize, Check)> = None;
        for (i, m) in runs.iter().enumerate().take(count) {
            let k = check(&c.op, &c.figure, m);
            let worse = match &worst {
                None => true,
                Some((_, w)) => (w.pass && !k.pass) || (w.pass == k.pass && k.badness > w.badness),
            };
            if worse {
                worst = Some((i, k));
            }
        }
        let (i, k) = worst.expect("at least the nominal run");
        let unit = runs[i]
            .get(&c.figure)
            .map_or(info.unit.to_string(), |m| m.unit.clone());
        criteria.push(CriterionVerdict {
            figure: c.figure.clone(),
            label: figure_info(&c.figure)
                .expect("checked when parsed")
                .label
                .clone(),
            bound: bound_text(&c.op, info.unit),
            value: k.value,
            unit,
            run: labels[i].clone(),
            pass: k.pass,
            reason: k.reason,
            settled: k.settled,
        });
    }
    let pass = criteria.iter().all(|c| c.pass);
    Ok(Verdict { criteria, pass })
}
