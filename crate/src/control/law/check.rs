//! The verdict on a step's law: its designed dynamics checked at drawn states and parameter
//! values, and what a wrong law misses.

use super::mistakes::mistakes;
use super::{step_values, Laws, DESIGNED, OUTPUTS, PAPER};
use crate::control::backstepping::{Adapted, Backstepping, ControlError, ControlInput, Gains};
use crate::control::chain;
use crate::control::formula::{self, FormulaError, Node, Program, SIGNALS};
use crate::control::RefSample;
use crate::params::Lumped;
use crate::rng::Rng;
use crate::text::Message;

/// How a step's law compares with its designed dynamics.
#[cfg_attr(
    target_arch = "wasm32",
    derive(tsify::Tsify),
    tsify(missing_as_null, hashmap_as_object, rename = "LawVerdict")
)]
#[derive(Clone, Debug, PartialEq, serde::Serialize)]
pub struct Verdict {
    /// The step (1–4).
    pub step: u8,
    /// The law checked, as written.
    pub law: String,
    /// The student's own earlier law (v1 for step 2, v3 for step 4) it was judged on, as written.
    pub on: Option<String>,
    /// Whether it gives the designed dynamics (to rounding) at every drawn state.
    pub designed: bool,
    /// The largest |v_i − v_i,ref| over the drawn states, relative to the size of the paper's
    /// terms there; None where it is not a number (the text says why).
    pub worst: Option<f64>,
    /// What it gets wrong, when it can be named: a `law-*` message of `core-law.ftl`.
    pub finding: Option<Message>,
    /// The verdict in words, a `law-*` message of `core-law.ftl`.
    pub text: Message,
}

/// States drawn for the verdict.
pub const DRAWS: usize = 200;
/// The relative residual below which a law gives the designed dynamics: rounding in a sum of
/// about 30 terms, with a margin.
pub const TOLERANCE: f64 = 1e-9;

/// A drawn state: estimates, measurements, residuals, observer gains, reference and flux target;
/// with `vary`, every lumped parameter and gain too, each the scenario's own scaled by a factor
/// between 0.5 and 2 (the small ones, as a3, raised first), so that no term of the law is small
/// beside the others.
fn draw(rng: &mut Rng, model: &Lumped, gains: &Gains, vary: bool) -> (Backstepping, ControlInput) {
    // A parameter scaled by 0.5–2 (when `vary`), a signal of either sign up to `scale`.
    let mut pos = |v: f64| {
        if vary {
            v * (0.5 + 1.5 * rng.uniform())
        } else {
            v
        }
    };
    let p = Lumped {
        a1: pos(model.a1),
        a2: pos(if vary {
            model.a2.abs().max(1.0)
        } else {
            model.a2
        }),
        a3: pos(if vary { model.a3.max(0.01) } else { model.a3 }),
        a5: pos(model.a5),
        a6: pos(model.a6),
        a7: pos(model.a7),
        a8: pos(model.a8),
        // n_p too: a law that writes 2 for a9 is right only for a two-pole-pair motor.
        a9: pos(model.a9),
        a10: pos(model.a10),
        b: pos(model.b),
        j: model.j,
    };
    let g = Gains {
        k1: pos(gains.k1),
        k2: pos(gains.k2),
        k3: pos(gains.k3),
        k4: pos(gains.k4),
        robust: gains.robust,
        eps2: pos(gains.eps2),
        h2: pos(if vary { gains.h2.max(1.0) } else { gains.h2 }),
        eps4: pos(gains.eps4),
        h4: pos(if vary { gains.h4.max(1.0) } else { gains.h4 }),
    };
    let mut v = |scale: f64| scale * (2.0 * rng.uniform() - 1.0);
    let x_hat = [v(100.0), v(5.0), v(5.0), v(0.7), v(0.7)];
    let y = [x_hat[1] + v(0.1), x_hat[2] + v(0.1)];
    let input = ControlInput {
        x_hat,
        y,
        l: std::array::from_fn(|_| [v(1e3), v(1e3)]),
        residual: [y[0] - x_hat[1], y[1] - x_hat[2]],
        speed_ref: RefSample {
            value: v(100.0),
            d1: v(1e3),
            d2: v(1e4),
        },
        psi_d: RefSample {
            value: 0.5 + v(0.25).abs(),
            d1: 0.0,
            d2: 0.0,
        },
    };
    (Backstepping::new(p, g), input)
}

/// One drawn state as step `step` saw it.
struct Drawn {
    /// The signals the step read.
    s: [f64; SIGNALS],
    /// The signals the step before read.
    before: [f64; SIGNALS],
    /// The law's v_i.
    mine: f64,
    /// The v_i that gives the designed dynamics: the paper's, corrected for the student's own
    /// earlier step.
    reference: f64,
    /// The paper's v_i at the same signals.
    paper: f64,
    /// The correction's rate not known: the earlier step is taken as the paper's.
    unchained: bool,
}

/// Step `step` of `laws` at one state drawn around `model` and `gains` (with `vary`, every
/// parameter and gain drawn too, and dâ2/dt); None where the student's own earlier step gave no
/// finite value, so that this step did not run.
fn sample(
    step: u8,
    laws: &Laws,
    rng: &mut Rng,
    model: &Lumped,
    gains: &Gains,
    vary: bool,
) -> Option<Drawn> {
    let (controller, input) = draw(rng, model, gains, vary);
    // dâ2/dt drawn too: the law must hold with the EKF's load state as without it.
    let adapted = vary.then(|| Adapted {
        model: *controller.model(),
        d_a2: 1e3 * (2.0 * rng.uniform() - 1.0),
    });
    let (seen, result) = step_values(&controller, &input, adapted.as_ref(), laws);
    if matches!(result, Err(ControlError::Law { step: failed, .. }) if failed < step) {
        return None;
    }
    let i = step as usize - 1;
    let law = laws.step(step).expect("the step has its own law");
    let s = seen.signals[i];
    let before = if i > 0 { seen.signals[i - 1] } else { s };
    let paper = seen.paper[i];
    let c = if i > 0 {
        laws.correction(step, &before, seen.used[i - 1], seen.paper[i - 1])
    } else {
        0.0
    };
    Some(Drawn {
        mine: law.program.eval(&s),
        s,
        before,
        reference: if c.is_finite() { paper + c } else { paper },
        paper,
        unchained: !c.is_finite(),
    })
}

/// What a step's law is judged on: the laws it runs with, the paper's law of the step, and the
/// drawn states it ran at, each with the size of the paper's law there (its largest term).
struct Drawing {
    laws: Laws,
    paper: Node,
    draws: Vec<(Drawn, f64)>,
}

/// The [`Drawing`] of step `step`: its own law in `texts`, with the student's own earlier step
/// for step 2 or 4, at the [`DRAWS`] drawn states.
fn drawing(
    step: u8,
    texts: &[Option<String>; 4],
    model: &Lumped,
    gains: &Gains,
) -> Result<Drawing, FormulaError> {
    let i = step as usize - 1;
    let mut own: [Option<String>; 4] = Default::default();
    own[i] = texts[i].clone();
    if step % 2 == 0 {
        own[i - 1] = texts[i - 1].clone();
    }
    let laws = Laws::parse(&own).map_err(|(_, e)| e)?;
    if laws.step(step).is_none() {
        return Err(FormulaError::new(0, 0, Message::new("law-no-own-law")));
    }
    let paper = formula::parse(PAPER[i], step).expect("the paper's law parses");
    let terms: Vec<Program> = formula::terms(&paper)
        .iter()
        .map(|(_, node)| Program::new(node).expect("a term compiles"))
        .collect();
    let mut rng = Rng::new(SEED);
    let draws = (0..DRAWS)
        .filter_map(|_| sample(step, &laws, &mut rng, model, gains, true))
        .map(|d| {
            let scale = terms
                .iter()
                .map(|t| t.eval(&d.s).abs())
                .fold(f64::MIN_POSITIVE, f64::max);
            (d, scale)
        })
        .collect();
    Ok(Drawing { laws, paper, draws })
}

/// Why the largest difference of a step's law from its reference is not a number.
#[derive(Clone, Debug, PartialEq)]
pub enum Unjudged {
    /// The student's own earlier step gave no finite value at any drawn state, so step `step`
    /// never ran.
    NeverRuns {
        /// The step.
        step: u8,
    },
    /// The law differs from the reference where the paper's law is all but zero, by no finite
    /// share of its size.
    NoShare {
        /// The step.
        step: u8,
    },
    /// The law differs infinitely from the reference at `count` of the drawn states, the first
    /// of them where it read `names`.
    Infinite {
        /// The step.
        step: u8,
        /// At how many drawn states.
        count: usize,
        /// The names the law reads and their values at the first of them.
        names: Vec<(&'static str, f64)>,
    },
    /// The law is not a finite number at `count` of the drawn states: at the first of them it
    /// gives `value`, reading `names`.
    NotFinite {
        /// The step.
        step: u8,
        /// At how many drawn states.
        count: usize,
        /// What the law gives there (inf, −inf or NaN).
        value: f64,
        /// The names the law reads and their values there.
        names: Vec<(&'static str, f64)>,
    },
}

impl Unjudged {
    /// What it says, as a message of `core-law.ftl`.
    pub fn message(&self) -> Message {
        match self {
            Unjudged::NeverRuns { step } => Message::new("law-never-runs")
                .text("before", OUTPUTS[*step as usize - 2].0)
                .count("draws", DRAWS)
                .count("step", *step),
            Unjudged::NoShare { step } => {
                let (output, unit) = OUTPUTS[*step as usize - 1];
                Message::new("law-no-share")
                    .text("output", output)
                    .text("unit", unit)
            }
            Unjudged::Infinite { step, count, names } => {
                let (output, unit) = OUTPUTS[*step as usize - 1];
                Message::new("law-differs-infinitely")
                    .text("output", output)
                    .text("unit", unit)
                    .count("count", *count)
                    .count("draws", DRAWS)
                    .text("reads", if names.is_empty() { "none" } else { "some" })
                    .list("names", super::named_messages(names))
            }
            Unjudged::NotFinite {
                step,
                count,
                value,
                names,
            } => {
                let (output, unit) = OUTPUTS[*step as usize - 1];
                Message::new("law-not-finite")
                    .text("output", output)
                    .text("unit", unit)
                    .count("count", *count)
                    .count("draws", DRAWS)
                    // inf, -inf or NaN, as Rust writes them.
                    .text("value", value.to_string())
                    .text("reads", if names.is_empty() { "none" } else { "some" })
                    .list("names", super::named_messages(names))
            }
        }
    }
}

/// The largest difference of step `step`'s law from its reference over the drawn states,
/// relative to the paper's law's size at each; or why it is not a number: the step never ran,
/// or the law is not finite at some of them.
fn worst_of(step: u8, drawing: &Drawing) -> Result<f64, Unjudged> {
    let draws = &drawing.draws;
    if draws.is_empty() {
        return Err(Unjudged::NeverRuns { step });
    }
    let not_finite: Vec<&Drawn> = draws
        .iter()
        .map(|(d, _)| d)
        .filter(|d| !(d.mine - d.reference).is_finite())
        .collect();
    let Some(first) = not_finite.first() else {
        let worst = draws.iter().fold(0.0f64, |worst, (d, scale)| {
            worst.max((d.mine - d.reference).abs() / scale)
        });
        // A finite difference where the paper's law is all but zero has no finite share of it.
        return if worst.is_finite() {
            Ok(worst)
        } else {
            Err(Unjudged::NoShare { step })
        };
    };
    let law = drawing.laws.step(step).expect("the step has its own law");
    let names = super::read_values(law, &first.s);
    let count = not_finite.len();
    Err(if first.mine.is_finite() {
        Unjudged::Infinite { step, count, names }
    } else {
        Unjudged::NotFinite {
            step,
            count,
            value: first.mine,
            names,
        }
    })
}

/// The largest [`Verdict::worst`] over the steps with an own law in `texts`, found as [`check`]
/// finds it but without naming what a law gets wrong; or why one of them is not a number (None
/// without own laws, or with one that does not parse).
pub fn worst(
    texts: &[Option<String>; 4],
    model: &Lumped,
    gains: &Gains,
) -> Option<Result<f64, Unjudged>> {
    let mut out: Option<Result<f64, Unjudged>> = None;
    for step in (1..=4u8).filter(|&step| {
        texts[step as usize - 1]
            .as_ref()
            .is_some_and(|t| !t.trim().is_empty())
    }) {
        let this = worst_of(step, &drawing(step, texts, model, gains).ok()?);
        out = Some(match (out, this) {
            (Some(Err(cause)), _) | (_, Err(cause)) => Err(cause),
            (Some(Ok(a)), Ok(b)) => Ok(a.max(b)),
            (None, Ok(b)) => Ok(b),
        });
    }
    out
}

/// Checks the law of step `step` in `texts` (one per step; None: the paper's) against its
/// designed dynamics at [`DRAWS`] states drawn around the scenario's `model` and `gains`. Step 2
/// (4) is judged on the student's own v1 (v3) when `texts` has one; the other steps are the
/// paper's.
pub fn check(
    step: u8,
    texts: &[Option<String>; 4],
    model: &Lumped,
    gains: &Gains,
) -> Result<Verdict, FormulaError> {
    let i = step as usize - 1;
    let drawn = drawing(step, texts, model, gains)?;
    let law = texts[i].clone().unwrap_or_default();
    let worst = match worst_of(step, &drawn) {
        Ok(worst) => worst,
        Err(cause) => {
            let text = if drawn.draws.is_empty() {
                Message::new("law-cannot-judge")
            } else {
                Message::new("law-not-designed-because").text("designed", DESIGNED[i])
            }
            .count("step", step)
            .said("cause", cause.message());
            return Ok(Verdict {
                step,
                law,
                on: None,
                designed: false,
                worst: None,
                finding: None,
                text,
            });
        }
    };
    let Drawing { laws, paper, draws } = drawn;
    let failed = DRAWS - draws.len();
    let mistakes = mistakes(step);
    let terms = formula::terms(&paper);
    let parts = parts(&terms);
    let mut diffs = Vec::with_capacity(DRAWS);
    let mut rows = Vec::with_capacity(DRAWS);
    let mut mistake_match = vec![true; mistakes.len()];
    let mut unchained = None;
    for (d, scale) in &draws {
        let (s, scale) = (&d.s, *scale);
        if d.unchained && unchained.is_none() {
            let (before, _) = laws.chained(step).expect("chained");
            unchained = Some(chain::without_rate(before, &d.before));
        }
        let diff = d.mine - d.reference;
        for (m, (p, _)) in mistake_match.iter_mut().zip(&mistakes) {
            *m &= (p.eval(s) - d.paper - diff).abs() <= TOLERANCE * scale;
        }
        diffs.push(diff / scale);
        rows.push(
            parts
                .iter()
                .map(|p| p.sign * p.program.eval(s) / scale)
                .collect::<Vec<_>>(),
        );
    }
    let (symbol, unit) = OUTPUTS[i];
    let before = if i > 0 { OUTPUTS[i - 1].0 } else { "" };
    let designed = worst <= TOLERANCE;
    // Whose earlier step the step is judged on.
    let on_text = laws
        .chained(step)
        .and_then(|_| laws.step(step - 1))
        .map(|l| l.text.clone());
    let own = matches!((laws.chained(step), &unchained), (Some(_), None));
    let caveats = caveats(before, unchained, failed);
    let verdict = |id: &'static str| {
        Message::new(id)
            .count("step", step)
            .text("designed", DESIGNED[i])
            .text("own", if own { "yes" } else { "no" })
            .text("before", before)
            .text("output", symbol)
            .count("draws", DRAWS)
    };
    if designed {
        return Ok(Verdict {
            step,
            law,
            on: on_text.clone(),
            designed,
            worst: Some(worst),
            finding: None,
            text: verdict("law-designed")
                .sci("worst", worst.max(f64::EPSILON), 0)
                .said("caveats", caveats),
        });
    }
    let finding = mistakes
        .iter()
        .zip(&mistake_match)
        .find(|(_, m)| **m)
        .map(|((_, why), _)| Message::new(why))
        .or_else(|| single_term(&parts, &rows, &diffs))
        .or_else(|| rate_of_z(&laws, step, model, gains));
    let difference = match &finding {
        Some(f) => Message::new("law-difference").said("finding", f.clone()),
        None => Message::new("law-difference-unnamed"),
    };
    let text = with_worst(verdict("law-not-designed"), worst)
        .text("unit", unit)
        .said("difference", difference)
        .said("caveats", caveats);
    Ok(Verdict {
        step,
        law,
        on: on_text,
        designed,
        worst: Some(worst),
        finding,
        text,
    })
}

/// What a verdict adds after its sentence about the student's own earlier step `before`: that
/// it reads the names `unchained` (when it does), whose rates the loop does not have, and that it
/// gave no finite value at `failed` of the drawn states (when it did not at some).
fn caveats(before: &str, unchained: Option<String>, failed: usize) -> Message {
    let unread = unchained.filter(|names| !names.is_empty()).map(|names| {
        Message::new("law-caveat-unchained")
            .text("before", before)
            .text("names", names)
    });
    let failed = (failed > 0).then(|| {
        Message::new("law-caveat-failed")
            .text("before", before)
            .count("failed", failed)
            .count("draws", DRAWS)
    });
    match (unread, failed) {
        (None, None) => Message::new("law-caveat-none"),
        (Some(one), None) | (None, Some(one)) => one,
        (Some(unread), Some(failing)) => Message::new("law-caveat-both")
            .said("unread", unread)
            .said("failing", failing),
    }
}

/// The verdict of every step with its own law in `texts`, checked with the scenario's `model`
/// and `gains` (step 2 and 4 on the student's own earlier step); a law that does not parse is
/// refused with its step.
pub fn verdicts(
    texts: &[Option<String>; 4],
    model: &Lumped,
    gains: &Gains,
) -> Result<Vec<Verdict>, (u8, FormulaError)> {
    Laws::parse(texts)?;
    let mut out = Vec::new();
    for (i, text) in texts.iter().enumerate() {
        let step = i as u8 + 1;
        if text.as_ref().is_some_and(|t| !t.trim().is_empty()) {
            out.push(check(step, texts, model, gains).map_err(|e| (step, e))?);
        }
    }
    Ok(out)
}

/// The drawn states' seed: the same draws for every check.
const SEED: u64 = 20_150_601;

/// A term of the paper's law, or a part of one multiplied out, that a difference may be.
struct Part {
    sign: f64,
    program: Program,
    /// "the term +x" or "the part +y of the term +x".
    label: Message,
}

/// The paper's terms, then the parts of those that are products of sums (2·(a + b)·c gives
/// 2·a·c and 2·b·c): one of them missing, as one injection, is named too.
fn parts(terms: &[(f64, &Node)]) -> Vec<Part> {
    let mut out: Vec<Part> = terms
        .iter()
        .map(|(sign, node)| Part {
            sign: *sign,
            program: Program::new(node).expect("a term compiles"),
            label: Message::new("law-term").text("term", signed(*sign, &formula::text(node))),
        })
        .collect();
    for (sign, node) in terms {
        let monomials = formula::monomials(node);
        if monomials.len() < 2 {
            continue;
        }
        let whole = signed(*sign, &formula::text(node));
        for (s, m) in monomials {
            out.push(Part {
                sign: sign * s,
                program: Program::new(&m).expect("a part compiles"),
                label: Message::new("law-term-part")
                    .text("part", signed(sign * s, &formula::text(&m)))
                    .text("term", whole.as_str()),
            });
        }
    }
    out
}

/// A difference that is one of the paper's terms or parts times a constant: that term missing
/// (−1), with its sign flipped (−2) or twice (+1), or scaled.
fn single_term(parts: &[Part], rows: &[Vec<f64>], diffs: &[f64]) -> Option<Message> {
    for (j, part) in parts.iter().enumerate() {
        let (mut dot, mut norm) = (0.0, 0.0);
        for (row, d) in rows.iter().zip(diffs) {
            dot += row[j] * d;
            norm += row[j] * row[j];
        }
        if norm == 0.0 {
            continue;
        }
        let c = dot / norm;
        let fits = rows
            .iter()
            .zip(diffs)
            .all(|(row, d)| (d - c * row[j]).abs() <= 1e3 * TOLERANCE);
        if !fits {
            continue;
        }
        let what = if (c + 1.0).abs() < 1e-6 {
            Message::new("law-term-missing")
        } else if (c + 2.0).abs() < 1e-6 {
            Message::new("law-term-wrong-sign")
        } else if (c - 1.0).abs() < 1e-6 {
            Message::new("law-term-twice")
        } else {
            digits(Message::new("law-term-scaled"), "factor", three(1.0 + c))
        };
        return Some(what.said("label", part.label.clone()));
    }
    None
}

/// A term of the paper's law with its sign in front: one sign, the term's own minus folded into
/// it (−2·a8·… rather than +−2·a8·…).
fn signed(sign: f64, text: &str) -> String {
    let (minus, body) = match text.strip_prefix('−').or_else(|| text.strip_prefix('-')) {
        Some(body) => (true, body),
        None => (false, text),
    };
    let negative = (sign < 0.0) != minus;
    format!("{}{body}", if negative { "−" } else { "+" })
}

/// With the scenario's own parameters and gains, a law that is the paper's plus c·z_i gives
/// ż_i = −(k_i − c)·z_i + (coupling): the rate its error decays at, against the designed one.
fn rate_of_z(laws: &Laws, step: u8, model: &Lumped, gains: &Gains) -> Option<Message> {
    let i = step as usize - 1;
    let z = formula::index(["z1", "z2", "z3", "z4"][i]).expect("named");
    let mut rng = Rng::new(SEED);
    let (mut dot, mut norm, mut points) = (0.0, 0.0, Vec::with_capacity(DRAWS));
    for _ in 0..DRAWS {
        let Some(d) = sample(step, laws, &mut rng, model, gains, false) else {
            continue;
        };
        let (zi, diff) = (d.s[z], d.mine - d.reference);
        dot += zi * diff;
        norm += zi * zi;
        points.push((zi, diff, d.paper.abs()));
    }
    let c = dot / norm;
    let fits = norm > 0.0
        && points
            .iter()
            .all(|(zi, d, size)| (d - c * zi).abs() <= 1e-6 * size.max(1.0));
    if !fits {
        return None;
    }
    // The same law at this scenario's values, not at the values drawn.
    if points
        .iter()
        .all(|(_, d, size)| d.abs() <= TOLERANCE * size.max(1.0))
    {
        return Some(Message::new("law-scenario-values-only"));
    }
    let designed = gains.designed_rate(step);
    let (now, meant) = distinct(designed - c, designed);
    let message = Message::new("law-rate-of-z")
        .text("sign", if c < 0.0 { "minus" } else { "plus" })
        .text("z", format!("z{step}"));
    let message = digits(message, "gain", three(c.abs()));
    let message = digits(message, "now", now);
    Some(digits(message, "meant", meant))
}

/// `message` with the number written `text` as `name`: as a number (which a language writes with
/// its decimal separator) where Rust writes that number so, else as the text (1.20e-5).
fn digits(message: Message, name: &'static str, text: String) -> Message {
    match text.parse::<f64>() {
        Ok(v) if v.to_string() == text => message.real(name, v),
        _ => message.text(name, text),
    }
}

/// `a` and `b` to three significant digits, or to as many more as tell them apart.
fn distinct(a: f64, b: f64) -> (String, String) {
    let (x, y) = (three(a), three(b));
    if x != y || a == b {
        return (x, y);
    }
    (4..=15)
        .map(|digits| {
            (
                crate::text::significant(a, digits),
                crate::text::significant(b, digits),
            )
        })
        .find(|(x, y)| x != y)
        .unwrap_or((x, y))
}

/// `v` to three significant digits, as plain decimals where they are short (400, 0.833, 1.2e-5).
/// `message` with `v` as its `worst`, as [`three`] writes it: in scientific notation outside
/// 1e-3..1e6, with two decimals in its mantissa.
fn with_worst(message: Message, v: f64) -> Message {
    let text = three(v);
    if text.contains('e') {
        message.sci("worst", v, 2)
    } else {
        digits(message, "worst", text)
    }
}

fn three(v: f64) -> String {
    if v == 0.0 || !v.is_finite() {
        return format!("{v}");
    }
    let e = v.abs().log10().floor() as i32;
    if !(-3..6).contains(&e) {
        return format!("{v:.2e}");
    }
    let factor = 10f64.powi(2 - e);
    format!("{}", (v * factor).round() / factor)
}
