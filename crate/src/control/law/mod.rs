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
//!
//! Steps 2 and 4 are judged on the student's own earlier step when there is one (see
//! [`chain`](super::chain)). One job per file: this one runs the laws; `check` gives a step's
//! verdict, `mistakes` lists the slips it names.

mod check;
mod mistakes;

pub use check::{check, verdicts, worst, Unjudged, Verdict, DRAWS, TOLERANCE};

use super::backstepping::{Adapted, Backstepping, ControlError, ControlInput, Custom, Gathered};
use super::chain;
use super::formula::{self, FormulaError, Program, NAMES, SIGNALS};
use crate::text::Message;
use std::cell::{Cell, RefCell};

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
    /// For step 2 (4) when it and the step before have own laws: the paper's law of the step
    /// before, which step 2's (4's) reference is corrected from (see [`chain`]).
    before: [Option<Program>; 4],
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
        // An earlier step written as the paper's law, operation for operation, gives its bits:
        // there is nothing to correct for.
        for step in [2u8, 4] {
            if let (Some(_), Some(earlier)) = (laws.step(step), laws.step(step - 1)) {
                let paper = Program::parse(PAPER[step as usize - 2], step - 1)
                    .expect("the paper's law parses");
                if paper != earlier.program {
                    laws.before[step as usize - 1] = Some(paper);
                }
            }
        }
        Ok(laws)
    }

    /// For step 2 or 4 judged on the student's own earlier step: that step's own law and the
    /// paper's.
    pub fn chained(&self, step: u8) -> Option<(&Program, &Program)> {
        let paper = self.before[step as usize - 1].as_ref()?;
        let own = &self.step(step - 1)?.program;
        Some((own, paper))
    }

    /// What the reference of step `step` (2 or 4) adds to the paper's v_i for the student's own
    /// earlier step, read at its signals `before` where it gave `used` and the paper's law `paper`
    /// (see [`chain::correction`]): 0 when the earlier step is the paper's, NaN when its own law's
    /// rate is not known there.
    pub fn correction(&self, step: u8, before: &[f64; SIGNALS], used: f64, paper: f64) -> f64 {
        match self.chained(step) {
            Some((own, theirs)) => chain::correction(step, own, theirs, before, used - paper),
            None => 0.0,
        }
    }

    /// What the laws cost each sample, in simple operations (see [`Program::work`]): every own
    /// law evaluated once, and for step 2 (4) judged on an own earlier step, the rates of that
    /// step's law and of the paper's.
    pub fn work(&self) -> u64 {
        let own: u64 = self.steps.iter().flatten().map(|l| l.program.work()).sum();
        let chains: u64 = [2u8, 4]
            .into_iter()
            .filter_map(|step| self.chained(step))
            .map(|(own, paper)| own.rate_work() + paper.rate_work())
            .sum();
        own + chains
    }

    /// Each own law's [`Program::work`], step by step (0 for the paper's).
    pub fn works(&self) -> [u64; 4] {
        self.steps
            .each_ref()
            .map(|l| l.as_ref().map_or(0, |l| l.program.work()))
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

/// Laws that keep, for each step, the value used less the reference at the same signals (the
/// paper's v_i, corrected for the student's own earlier step): the residual of the step's
/// designed dynamics (zero for the paper's own steps).
pub struct Residuals<'a> {
    /// The laws.
    pub laws: &'a Laws,
    /// v_i − v_i,ref of the last sample, step by step.
    pub last: Cell<[f64; 4]>,
    /// v_i,paper of the last sample, step by step.
    pub paper: Cell<[f64; 4]>,
    /// The signals of a step whose own law gave a value that is not a finite number (the run
    /// stops there and names them).
    pub failed: Cell<Option<[f64; SIGNALS]>>,
    /// What step 2's and step 4's references add for the student's own v1, v3 at this sample
    /// (see [`Laws::correction`]), found when step 1 and step 3 ran.
    corrections: Cell<[f64; 4]>,
}

impl<'a> Residuals<'a> {
    /// Residuals of `laws`, none yet.
    pub fn new(laws: &'a Laws) -> Residuals<'a> {
        Residuals {
            laws,
            last: Cell::new([0.0; 4]),
            paper: Cell::new([0.0; 4]),
            failed: Cell::new(None),
            corrections: Cell::new([0.0; 4]),
        }
    }
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
        let mut c = self.corrections.get();
        if step % 2 == 1 && self.laws.chained(step + 1).is_some() {
            c[i + 1] = self.laws.correction(step + 1, signals, used, paper);
            self.corrections.set(c);
        }
        // The paper's reference where the earlier step's own law has no known rate.
        let reference = if c[i].is_finite() {
            paper + c[i]
        } else {
            paper
        };
        let (mut r, mut p) = (self.last.get(), self.paper.get());
        r[i] = used - reference;
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
    read_values(law, signals)
        .iter()
        .map(|(name, v)| format!("{name} = {}", crate::text::short(*v)))
        .collect::<Vec<_>>()
        .join(", ")
}

/// The names a law reads, each with its value in `signals`.
fn read_values(law: &Law, signals: &[f64; SIGNALS]) -> Vec<(&'static str, f64)> {
    law.program
        .names()
        .iter()
        .map(|&i| (NAMES[i].name, signals[i]))
        .collect()
}

/// Names and their values as messages, "x1h = 3.2" each, for a list.
fn named_messages(names: &[(&'static str, f64)]) -> Vec<Message> {
    names
        .iter()
        .map(|(name, v)| {
            Message::new("law-named-value")
                .text("name", *name)
                .short("value", *v)
        })
        .collect()
}

/// Step `step`'s own law refused for `error`, as a message of `core-law.ftl`
/// ("law.v2: at character 3: …").
pub fn refused(step: u8, error: &FormulaError) -> Message {
    Message::new("law-refused")
        .count("step", step)
        .said("error", error.message())
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
