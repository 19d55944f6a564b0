//! A student's own laws for the four backstepping steps: each written as a formula of the
//! controller's signals (see [`formula`]), run in place of the paper's virtual control v_i, and
//! checked against the error dynamics the step is designed to give.
//!
//! With the nominal residual dynamics (x̃1 = x̃4 = x̃5 = 0), step i of the paper's law is the one
//! value of v_i that gives its designed dynamics:
//!
//!   ż1 = −k1·z1 + z2,   ż2 = −k2·z2 − z1 (− h2²/(4ε2)·z2 with the robust term),
//!   ż3 = −k3·z3 + z4,   ż4 = −k4·z4 − z3 (− h4²/(4ε4)·z4),
//!
//! since ż_i depends on v_i through a unit coefficient (z1's dynamics through z2 = torque − v1).
//! So the residual ż_i + k_i·z_i − (coupling) of a law is its v_i less the paper's v_i at the same
//! signals: [`check`] evaluates both at drawn states and parameter values, and names the term of the
//! paper's law that a wrong law misses.

use super::backstepping::{
    Adapted, Backstepping, ControlError, ControlInput, Custom, Gains, Gathered,
};
use super::formula::{self, FormulaError, Node, Program, NAMES, SIGNALS};
use super::RefSample;
use crate::params::Lumped;
use crate::rng::Rng;
use std::cell::RefCell;

/// The paper's law of each step in the language, with the robust terms (which vanish with
/// `robust` = 0): with it in every step, a run gives the built-in law's bits (checked by the
/// tests). The unknown terms d̃2 and d̃4 are left out, as the built-in law leaves them out.
pub const PAPER: [&str; 4] = [
    // (26)–(28): v1 = v1a + v1s.
    "-si1 + dwd + a3*wd + a2 - k1s1*z1",
    // (34)–(36) with ψ2 of (33) and v̇1 of (31), its typos corrected.
    "-(-(a7 + a8)*v1 - a1*a6*x1h*(x4h*x4h + x5h*x5h) - a1*a9*x1h*(x5h*x3 + x4h*x2) \
     + a1*a10*(x2h*x3 - x3h*x2) + a1*(x3*si4 - x2*si5) \
     - (-k1s1*(-k1*z1 + z2) - (l11*dxt2 + l12*dxt3) + ddwd + a3*dwd + da2)) - z1 \
     + (-k2s1*z2 + -robust*h2*h2/(4*eps2)*z2)",
    // (42)–(46).
    "-(-2*a8*(x4h*x4h + x5h*x5h) - 2*a10*(xt2*x4h + xt3*x5h) + 2*(x4h*si4 + x5h*si5)) - k3*z3",
    // (47)–(51).
    "-(2*a10*a5*(x4h*x4h + x5h*x5h) - 2*a10*a7*(x2h*x4h + x3h*x5h) + 2*a10*(x4h*si2 + x5h*si3) \
     + 2*(l41*x4h + l51*x5h)*dxt2 + 2*(l42*x4h + l52*x5h)*dxt3 \
     + 2*(si4 + a10*x2h - 2*a8*x4h)*dx4h + 2*(si5 + a10*x3h - 2*a8*x5h)*dx5h \
     + k3*(-k3*z3 + z4)) - z3 + (-k4*z4 + -robust*h4*h4/(4*eps4)*z4)",
];

/// Each step's designed error dynamics, as the verdict states them.
pub const DESIGNED: [&str; 4] = [
    "ż1 = −k1·z1 + z2",
    "ż2 = −k2·z2 − z1",
    "ż3 = −k3·z3 + z4",
    "ż4 = −k4·z4 − z3",
];

/// The virtual control each step's law gives, with its unit.
pub const OUTPUTS: [(&str, &str); 4] = [
    ("v1", "rad/s²"),
    ("v2", "rad/s³"),
    ("v3", "Wb²/s"),
    ("v4", "Wb²/s²"),
];

/// Mistakes a student makes in each step, each the paper's law with one part written as the
/// student writes it ([what the paper has, what the student writes, what is wrong]): the verdict
/// names the one a law equals. Single terms missing or with the wrong sign are found without a
/// list (see [`check`]).
const MISTAKES: [&[(&str, &str, &str)]; 4] = [
    &[
        ("k1s1*z1", "k1*z1", "it has k1 where (28) has k1s1 = k1 − a3"),
        ("a3*wd", "a3*x1h", "it has a3·x̂1 where (27) has a3·ω_d"),
    ],
    &[
        (
            "(-k2s1*z2",
            "(-k2*z2",
            "it has k2 where (36) has k2s1 = k2 − a7 − a8: the −(a7 + a8)·z2 of ż2 is then left in",
        ),
        (
            "a3*dwd",
            "a3*wd",
            "it takes v̇1 as printed in (31), with a3·ω_d where the derivative of a3·ω_d is a3·ω̇_d",
        ),
        (
            "+ da2",
            "+ a2",
            "it takes v̇1 as printed in (31), with â2 where the derivative of â2 is its rate (0 for a known load)",
        ),
    ],
    &[(
        "- k3*z3",
        "- k3*(x4h*x4h + x5h*x5h - psi_d*psi_d)",
        "it takes ψ_d as the flux modulus (ψ_d²) where the paper's z3 = x̂4² + x̂5² − ψ_d takes it as the squared modulus",
    )],
    &[(
        "+ 2*(l41*x4h + l51*x5h)*dxt2 + 2*(l42*x4h + l52*x5h)*dxt3 ",
        "",
        "it leaves out the residuals' chain-rule terms 2·(l41·x̂4 + l51·x̂5)·ẋ̃2 and 2·(l42·x̂4 + l52·x̂5)·ẋ̃3 of ψ4",
    )],
];

/// The catalogued mistakes of step `step` as laws, each with what it gets wrong.
fn mistakes(step: u8) -> Vec<(Program, &'static str)> {
    let paper = PAPER[step as usize - 1];
    MISTAKES[step as usize - 1]
        .iter()
        .map(|(has, writes, why)| {
            assert_eq!(
                paper.matches(has).count(),
                1,
                "{has} stands once in the law"
            );
            let text = paper.replacen(has, writes, 1);
            (
                Program::parse(&text, step).expect("a listed mistake parses"),
                *why,
            )
        })
        .collect()
}

/// One step's law: its text and its program.
#[derive(Clone, Debug, PartialEq)]
pub struct Law {
    /// The formula as written.
    pub text: String,
    program: Program,
}

/// The steps a scenario replaces with its own laws (None: the paper's).
#[derive(Clone, Debug, PartialEq, Default)]
pub struct Laws {
    steps: [Option<Law>; 4],
}

impl Laws {
    /// The laws of `texts` (one per step; None or empty: the paper's); the first bad one refused
    /// with its step.
    pub fn parse(texts: &[Option<String>; 4]) -> Result<Laws, (u8, FormulaError)> {
        let mut laws = Laws::default();
        for (i, text) in texts.iter().enumerate() {
            let step = i as u8 + 1;
            if let Some(text) = text.as_ref().filter(|t| !t.trim().is_empty()) {
                let program = Program::parse(text, step).map_err(|e| (step, e))?;
                laws.steps[i] = Some(Law {
                    text: text.clone(),
                    program,
                });
            }
        }
        Ok(laws)
    }

    /// Whether every step is the paper's.
    pub fn is_empty(&self) -> bool {
        self.steps.iter().all(Option::is_none)
    }

    /// Step `step`'s own law, if it has one.
    pub fn step(&self, step: u8) -> Option<&Law> {
        self.steps[step as usize - 1].as_ref()
    }
}

impl Custom for Laws {
    const ON: bool = true;
    type Signals = Gathered;
    #[inline]
    fn replace(&self, step: u8, signals: &[f64; SIGNALS], paper: f64) -> f64 {
        match &self.steps[step as usize - 1] {
            Some(law) => law.program.eval(signals),
            None => paper,
        }
    }
    fn owns(&self, step: u8) -> bool {
        self.step(step).is_some()
    }
}

/// What the laws gave at one sample, step by step: the signals each step read, the paper's
/// value and the value used.
#[derive(Clone, Copy, Debug)]
pub struct StepValues {
    /// The signals step i read.
    pub signals: [[f64; SIGNALS]; 4],
    /// The paper's v_i at those signals.
    pub paper: [f64; 4],
    /// The v_i used (the step's own law's, or the paper's).
    pub used: [f64; 4],
}

/// Laws that keep what each step read and gave: the failure message and the residual plot.
struct Watched<'a, C: Custom> {
    inner: &'a C,
    seen: RefCell<StepValues>,
}

impl<C: Custom> Custom for Watched<'_, C> {
    const ON: bool = true;
    type Signals = Gathered;
    fn replace(&self, step: u8, signals: &[f64; SIGNALS], paper: f64) -> f64 {
        let used = self.inner.replace(step, signals, paper);
        let mut seen = self.seen.borrow_mut();
        let i = step as usize - 1;
        seen.signals[i] = *signals;
        seen.paper[i] = paper;
        seen.used[i] = used;
        used
    }
    fn owns(&self, step: u8) -> bool {
        self.inner.owns(step)
    }
}

/// Laws that keep, for each step, the value used less the paper's at the same signals: the
/// residual of the step's designed dynamics (zero for the paper's own steps).
pub struct Residuals<'a> {
    /// The laws.
    pub laws: &'a Laws,
    /// v_i − v_i,paper of the last sample, step by step.
    pub last: std::cell::Cell<[f64; 4]>,
    /// v_i,paper of the last sample, step by step.
    pub paper: std::cell::Cell<[f64; 4]>,
    /// The signals of a step whose own law gave a value that is not a finite number (the run
    /// stops there and names them).
    pub failed: std::cell::Cell<Option<[f64; SIGNALS]>>,
}

impl Custom for Residuals<'_> {
    const ON: bool = true;
    type Signals = Gathered;
    #[inline]
    fn replace(&self, step: u8, signals: &[f64; SIGNALS], paper: f64) -> f64 {
        let used = self.laws.replace(step, signals, paper);
        if !used.is_finite() && self.laws.owns(step) {
            self.failed.set(Some(*signals));
        }
        let i = step as usize - 1;
        let (mut r, mut p) = (self.last.get(), self.paper.get());
        r[i] = used - paper;
        p[i] = paper;
        self.last.set(r);
        self.paper.set(p);
        used
    }
    fn owns(&self, step: u8) -> bool {
        self.laws.owns(step)
    }
}

/// Every step's signals, the paper's values and those used, for the law `custom` at one sample
/// (a step the law failed at holds what it read; the later ones hold zeros).
pub fn step_values<C: Custom>(
    controller: &Backstepping,
    input: &ControlInput,
    adapted: Option<&Adapted>,
    custom: &C,
) -> (StepValues, Result<(), ControlError>) {
    let watched = Watched {
        inner: custom,
        seen: RefCell::new(StepValues {
            signals: [[0.0; SIGNALS]; 4],
            paper: [0.0; 4],
            used: [0.0; 4],
        }),
    };
    let result = controller
        .control_with(input, adapted, &watched)
        .map(|_| ());
    (watched.seen.into_inner(), result)
}

/// The names a law reads and their values, as "x1h = 3.2, z1 = −0.01".
pub fn named_values(law: &Law, signals: &[f64; SIGNALS]) -> String {
    law.program
        .names()
        .iter()
        .map(|&i| format!("{} = {}", NAMES[i].name, crate::text::short(signals[i])))
        .collect::<Vec<_>>()
        .join(", ")
}

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
    /// Whether it gives the designed dynamics (to rounding) at every drawn state.
    pub designed: bool,
    /// The largest |v_i − v_i,paper| over the drawn states, relative to the size of the paper's
    /// terms there.
    pub worst: f64,
    /// What it gets wrong, when it can be named.
    pub finding: Option<String>,
    /// The verdict in words.
    pub text: String,
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
        psi_d: 0.5 + v(0.25).abs(),
    };
    (Backstepping::new(p, g), input)
}

/// Checks the law of step `step` (text `text`) against its designed dynamics at [`DRAWS`] states
/// drawn around the scenario's `model` and `gains`; the other steps are the paper's.
pub fn check(step: u8, text: &str, model: &Lumped, gains: &Gains) -> Result<Verdict, FormulaError> {
    let program = Program::parse(text, step)?;
    let paper = formula::parse(PAPER[step as usize - 1], step).expect("the paper's law parses");
    let mut texts: [Option<String>; 4] = Default::default();
    texts[step as usize - 1] = Some(text.to_string());
    let laws = Laws::parse(&texts).map_err(|(_, e)| e)?;
    let mistakes = mistakes(step);
    let terms = formula::terms(&paper);
    let term_programs: Vec<(f64, Program)> = terms
        .iter()
        .map(|(sign, node)| (*sign, Program::new(node).expect("a term compiles")))
        .collect();
    let mut rng = Rng::new(SEED);
    let mut worst = 0.0f64;
    let mut diffs = Vec::with_capacity(DRAWS);
    let mut rows = Vec::with_capacity(DRAWS);
    let mut mistake_match = vec![true; mistakes.len()];
    let i = step as usize - 1;
    for _ in 0..DRAWS {
        let (controller, input) = draw(&mut rng, model, gains, true);
        // dâ2/dt drawn too: the law must hold with the EKF's load state as without it.
        let adapted = Adapted {
            model: *controller.model(),
            d_a2: 1e3 * (2.0 * rng.uniform() - 1.0),
        };
        let (seen, _) = step_values(&controller, &input, Some(&adapted), &laws);
        let s = &seen.signals[i];
        let mine = program.eval(s);
        let theirs = seen.paper[i];
        // The size of the paper's law here: the largest of its terms.
        let scale = term_programs
            .iter()
            .map(|(_, t)| t.eval(s).abs())
            .fold(f64::MIN_POSITIVE, f64::max);
        let d = mine - theirs;
        worst = worst.max(if d.is_nan() {
            f64::INFINITY
        } else {
            d.abs() / scale
        });
        for (m, (p, _)) in mistake_match.iter_mut().zip(&mistakes) {
            *m &= (p.eval(s) - mine).abs() <= TOLERANCE * scale;
        }
        diffs.push(d / scale);
        rows.push(
            term_programs
                .iter()
                .map(|(sign, t)| sign * t.eval(s) / scale)
                .collect::<Vec<_>>(),
        );
    }
    let (symbol, unit) = OUTPUTS[i];
    let designed = worst <= TOLERANCE;
    if designed {
        return Ok(Verdict {
            step,
            designed,
            worst,
            finding: None,
            text: format!(
                "Your step {step} gives the designed dynamics {}: your {symbol} equals the paper's to {:.0e} of its size at {DRAWS} drawn states and parameter values.",
                DESIGNED[i],
                worst.max(f64::EPSILON)
            ),
        });
    }
    let finding = mistakes
        .iter()
        .zip(&mistake_match)
        .find(|(_, m)| **m)
        .map(|((_, why), _)| why.to_string())
        .or_else(|| single_term(&terms, &rows, &diffs))
        .or_else(|| rate_of_z(&laws, step, model, gains));
    let text = format!(
        "Your step {step} does not give the designed dynamics {}: your {symbol} ({unit}) differs from the paper's by up to {} of its size at {DRAWS} drawn states. {}",
        DESIGNED[i],
        three(worst),
        finding.as_deref().map_or_else(
            || "The difference is not one term of the paper's law: compare your law with the step's derivation term by term.".to_string(),
            |f| format!("The difference: {f}."),
        )
    );
    Ok(Verdict {
        step,
        designed,
        worst,
        finding,
        text,
    })
}

/// The verdict of every step with its own law in `texts`, checked with the scenario's `model`
/// and `gains`; a law that does not parse is refused with its step.
pub fn verdicts(
    texts: &[Option<String>; 4],
    model: &Lumped,
    gains: &Gains,
) -> Result<Vec<Verdict>, (u8, FormulaError)> {
    let mut out = Vec::new();
    for (i, text) in texts.iter().enumerate() {
        let step = i as u8 + 1;
        if let Some(text) = text.as_ref().filter(|t| !t.trim().is_empty()) {
            out.push(check(step, text, model, gains).map_err(|e| (step, e))?);
        }
    }
    Ok(out)
}

/// A formula as an editor shows it while it is typed: typeset, or refused at its place.
#[cfg_attr(
    target_arch = "wasm32",
    derive(tsify::Tsify),
    tsify(missing_as_null, hashmap_as_object)
)]
#[derive(Clone, Debug, PartialEq, serde::Serialize)]
pub struct Preview {
    /// The formula in TeX, when it parses.
    pub tex: Option<String>,
    /// Where and why it does not, when it does not.
    pub error: Option<FormulaError>,
    /// The step's designed dynamics.
    pub designed: &'static str,
}

/// The preview of `text` as the law of step `step` (1–4).
pub fn preview(step: u8, text: &str) -> Preview {
    let designed = DESIGNED[step as usize - 1];
    match formula::parse(text, step).and_then(|node| Program::new(&node).map(|_| node)) {
        Ok(node) => Preview {
            tex: Some(format!("v_{step} = {}", formula::tex(&node))),
            error: None,
            designed,
        },
        Err(error) => Preview {
            tex: None,
            error: Some(error),
            designed,
        },
    }
}

/// The drawn states' seed: the same draws for every check.
const SEED: u64 = 20_150_601;

/// A difference that is one of the paper's terms times a constant: that term missing (−1), with
/// its sign flipped (−2) or twice (+1), or scaled.
fn single_term(terms: &[(f64, &Node)], rows: &[Vec<f64>], diffs: &[f64]) -> Option<String> {
    for (j, (sign, node)) in terms.iter().enumerate() {
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
        let term = signed(*sign, &formula::text(node));
        let what = if (c + 1.0).abs() < 1e-6 {
            format!("the term {term} of the paper's law is missing")
        } else if (c + 2.0).abs() < 1e-6 {
            format!("the term {term} has the wrong sign")
        } else if (c - 1.0).abs() < 1e-6 {
            format!("the term {term} is there twice")
        } else {
            format!(
                "the term {term} is {} times what it should be",
                three(1.0 + c)
            )
        };
        return Some(what);
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
fn rate_of_z(laws: &Laws, step: u8, model: &Lumped, gains: &Gains) -> Option<String> {
    let i = step as usize - 1;
    let z = formula::index(["z1", "z2", "z3", "z4"][i]).expect("named");
    let mut rng = Rng::new(SEED);
    let (mut dot, mut norm, mut points) = (0.0, 0.0, Vec::with_capacity(DRAWS));
    for _ in 0..DRAWS {
        let (controller, input) = draw(&mut rng, model, gains, false);
        let (seen, _) = step_values(&controller, &input, None, laws);
        let (zi, d) = (seen.signals[i][z], seen.used[i] - seen.paper[i]);
        dot += zi * d;
        norm += zi * zi;
        points.push((zi, d, seen.paper[i].abs()));
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
        return Some(
            "it equals the paper's law at this scenario's parameter values and gains only: a \
             parameter or a gain is written as its number where the law needs its name"
                .to_string(),
        );
    }
    let robust = |h: f64, eps: f64| {
        if gains.robust {
            h * h / (4.0 * eps)
        } else {
            0.0
        }
    };
    let designed = [
        gains.k1,
        gains.k2 + robust(gains.h2, gains.eps2),
        gains.k3,
        gains.k4 + robust(gains.h4, gains.eps4),
    ][i];
    Some(format!(
        "it is the paper's law plus {}·z{step}: with this scenario's parameters your z{step} decays at {} /s, not {} /s; check the gain and the sign of your z{step} terms",
        three(c),
        three(designed - c),
        three(designed)
    ))
}

/// `v` to three significant digits, as plain decimals where they are short (400, 0.833, 1.2e-5).
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
