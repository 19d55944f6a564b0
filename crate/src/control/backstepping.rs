//! The four-step backstepping controller of Section 4, derived from the error definitions
//!
//!   z1 = x̂1 − ω_d,                     z2 = a1(x3·x̂4 − x2·x̂5) − v1,
//!   z3 = x̂4² + x̂5² − ψ_d,              z4 = 2·a10(x2·x̂4 + x3·x̂5) − v3,
//!
//! with the observer in the general form (4), x̂̇ = f̂ + L·(x̃2, x̃3), and the measured currents
//! x2, x3 obeying the true model (2). With x̃1 = x̃4 = x̃5 = 0 the law below gives exactly
//!
//!   ż1 = −k1 z1 + z2,   ż2 = −k2 z2 − z1,   ż3 = −k3 z3 + z4,   ż4 = −k4 z4 − z3.
//!
//! The unknown disturbances d̃2 and d̃4 (which vanish when x̃1 = x̃4 = x̃5 = 0) are left out of the
//! feedforward. Names follow the paper, hence `non_snake_case` is not needed but short names are.

use crate::control::formula::SIGNALS;
use crate::control::RefSample;
use crate::model::State;
use crate::params::Lumped;
use crate::text::Message;
use serde::{Deserialize, Serialize};
use std::fmt;

/// Design gains of the controller (closed-loop error rates, 1/s) and the robust terms.
#[derive(Clone, Copy, Debug, PartialEq, Serialize, Deserialize)]
pub struct Gains {
    /// k1: closed-loop rate of the speed error z1 (1/s).
    pub k1: f64,
    /// k2 = a7 + a8 + k2s1: closed-loop rate of the torque error z2 (1/s), eq (36).
    pub k2: f64,
    /// k3 = k3s1: closed-loop rate of the flux error z3 (1/s), eq (46).
    pub k3: f64,
    /// k4: closed-loop rate of the flux-derivative error z4 (1/s), eq (51).
    pub k4: f64,
    /// Whether the robust terms v2s2 (38) and v4s2 (53) are applied.
    pub robust: bool,
    /// ε2 of eq (38).
    pub eps2: f64,
    /// h2 of eq (38): bound on |d̃2|.
    pub h2: f64,
    /// ε4 of eq (53).
    pub eps4: f64,
    /// h4 of eq (53): bound on |d̃4|.
    pub h4: f64,
}

impl Gains {
    /// The rate step `step` (1–4) is designed to make its error decay at: k_i, plus the robust
    /// term's h²/(4ε) in steps 2 and 4 when the robust terms are on.
    pub fn designed_rate(&self, step: u8) -> f64 {
        let robust = |h: f64, eps: f64| {
            if self.robust {
                h * h / (4.0 * eps)
            } else {
                0.0
            }
        };
        match step {
            1 => self.k1,
            2 => self.k2 + robust(self.h2, self.eps2),
            3 => self.k3,
            4 => self.k4 + robust(self.h4, self.eps4),
            _ => unreachable!("four steps"),
        }
    }
}

/// What the controller sees at one sample: only signals a real drive has.
#[derive(Clone, Copy, Debug)]
pub struct ControlInput {
    /// Posterior estimate x̂_{k|k}.
    pub x_hat: State,
    /// Measured stator currents y = [x2, x3] (A).
    pub y: [f64; 2],
    /// Observer gain L = K/Ts of eq (20), row-major 5×2 (1/s).
    pub l: [[f64; 2]; 5],
    /// Residual (x̃2, x̃3) = y − C·x̂_{k|k} (A).
    pub residual: [f64; 2],
    /// Speed reference and its derivatives.
    pub speed_ref: RefSample,
    /// Flux target ψ_d for x̂4² + x̂5² (Wb²) and its time derivatives, zero unless the field
    /// weakens above base speed.
    pub psi_d: RefSample,
}

/// Parameters the observer adapts: the controller uses them in place of its model's.
#[derive(Clone, Copy, Debug)]
pub struct Adapted {
    /// The lumped parameters at the estimate: â2 and R̂_r (through a5, a7, a8, a10) in place of
    /// the model's values where they are estimated.
    pub model: Lumped,
    /// dâ2/dt: in the observer form (4), â2 is a state whose rate is its injection
    /// l_a·(x̃2, x̃3) (rad/s³); 0 when a2 is not estimated.
    pub d_a2: f64,
}

/// Every term of the four steps at one sample, for teaching and checking.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct Terms {
    /// Errors z1..z4 (rad/s, rad/s², Wb², Wb²/s).
    pub z: [f64; 4],
    /// Virtual control v1 = v1a + v1s (rad/s²), eq (26).
    pub v1: f64,
    /// Feedforward v1a, eq (27).
    pub v1a: f64,
    /// Feedback v1s = −k1s1 z1, eq (28).
    pub v1s: f64,
    /// v2 = v2a + v2s (rad/s³), eq (34).
    pub v2: f64,
    /// Feedforward v2a = −ψ2 − z1, eq (35) without d̃2.
    pub v2a: f64,
    /// Feedback v2s = v2s1 + v2s2, eq (36).
    pub v2s: f64,
    /// Virtual control v3 = v3a + v3s (Wb²/s), eq (45).
    pub v3: f64,
    /// Feedforward v3a = −ψ3 + ψ̇_d (ψ̇_d = 0 for a constant target).
    pub v3a: f64,
    /// Feedback v3s = −k3 z3.
    pub v3s: f64,
    /// v4 = v4a + v4s (Wb²/s²), eq (49).
    pub v4: f64,
    /// Feedforward v4a = −ψ4 − z3, eq (50).
    pub v4a: f64,
    /// Feedback v4s = v4s1 + v4s2, eq (51).
    pub v4s: f64,
    /// ψ2 of eq (33) (typos of (31) corrected).
    pub psi2: f64,
    /// ψ3 of eq (43).
    pub psi3: f64,
    /// ψ4 of eq (47), less ψ̈_d for a moving target.
    pub psi4: f64,
    /// Estimated torque term a1(x3·x̂4 − x2·x̂5) that tracks v1 (rad/s²).
    pub torque: f64,
    /// Voltage from eq (54) before saturation (V).
    pub u: [f64; 2],
    /// Lyapunov function V = ½ Σ z_i².
    pub lyapunov: f64,
}

/// Why the controller cannot produce a voltage.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum ControlError {
    /// The decoupling matrix (55) is singular: the flux estimate x̂4² + x̂5² is nearly zero.
    SingularDecoupling {
        /// x̂4² + x̂5² (Wb²).
        flux_sq: f64,
    },
    /// A step's own law (a formula) gave a value that is not a finite number.
    Law {
        /// The step (1–4).
        step: u8,
        /// Its value (±inf or NaN).
        value: f64,
    },
}

/// Laws that replace some of the four steps' virtual controls v1..v4: the paper's law calls
/// [`Custom::replace`] after each step with the step's signals (indexed as
/// [`crate::control::formula::NAMES`]) and the paper's value, and uses what it returns.
pub trait Custom {
    /// False for the paper's law alone: the signals are then neither gathered nor passed.
    const ON: bool;
    /// Where the law keeps the signals: nothing at all for the paper's law (so that its loop
    /// does not even clear them), the whole vector otherwise.
    type Signals: Signals;
    /// The value step `step` (1–4) uses: the paper's `paper`, or another law's.
    fn replace(&self, step: u8, signals: &[f64; SIGNALS], paper: f64) -> f64;
    /// Whether step `step` (1–4) uses another law than the paper's.
    fn owns(&self, step: u8) -> bool;
}

/// The signals a law reads, as the law gathers them.
pub trait Signals: Default {
    /// Sets signal `i`.
    fn set(&mut self, i: usize, value: f64);
    /// Every signal.
    fn all(&self) -> &[f64; SIGNALS];
}

/// No signals: the paper's law reads none.
impl Signals for () {
    #[inline(always)]
    fn set(&mut self, _: usize, _: f64) {}
    #[inline(always)]
    fn all(&self) -> &[f64; SIGNALS] {
        &[0.0; SIGNALS]
    }
}

/// Every signal, as a step's own law reads them.
pub struct Gathered(pub [f64; SIGNALS]);

impl Default for Gathered {
    fn default() -> Gathered {
        Gathered([0.0; SIGNALS])
    }
}

impl Signals for Gathered {
    #[inline(always)]
    fn set(&mut self, i: usize, value: f64) {
        self.0[i] = value;
    }
    #[inline(always)]
    fn all(&self) -> &[f64; SIGNALS] {
        &self.0
    }
}

/// The paper's law, every step.
pub struct Paper;

impl Custom for Paper {
    const ON: bool = false;
    type Signals = ();
    #[inline(always)]
    fn replace(&self, _: u8, _: &[f64; SIGNALS], paper: f64) -> f64 {
        paper
    }
    fn owns(&self, _: u8) -> bool {
        false
    }
}

/// The value step `step` uses; one of another law's is refused unless finite (a paper's step
/// that is not finite reaches the voltage, which the loop refuses as diverged).
#[inline(always)]
fn chosen<C: Custom>(
    custom: &C,
    step: u8,
    s: &[f64; SIGNALS],
    paper: f64,
) -> Result<f64, ControlError> {
    if !C::ON {
        return Ok(paper);
    }
    let value = custom.replace(step, s, paper);
    if value.is_finite() || !custom.owns(step) {
        Ok(value)
    } else {
        Err(ControlError::Law { step, value })
    }
}

impl ControlError {
    /// Why the controller cannot produce a voltage, as a message of `core-run.ftl`.
    pub fn message(&self) -> Message {
        match self {
            ControlError::SingularDecoupling { flux_sq } => Message::new("control-singular")
                .text("flux", format!("{flux_sq:.3e}"))
                .text("min", format!("{MIN_FLUX_SQ:e}")),
            ControlError::Law { step, value } => Message::new("control-law")
                .count("step", *step)
                .text("value", value.to_string()),
        }
    }
}

impl fmt::Display for ControlError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        self.message().fmt(f)
    }
}

impl std::error::Error for ControlError {}

/// Smallest x̂4² + x̂5² (Wb²) for which (54) is solved: a flux modulus of 1 mWb, 0.14 % of the
/// paper's 0.707 Wb. Below it the voltages would be dominated by rounding.
pub const MIN_FLUX_SQ: f64 = 1e-6;

/// The backstepping controller with the model parameters it assumes.
#[derive(Clone, Copy, Debug)]
pub struct Backstepping {
    model: Lumped,
    gains: Gains,
}

impl Backstepping {
    /// A controller for the lumped `model` with `gains`.
    pub fn new(model: Lumped, gains: Gains) -> Backstepping {
        Backstepping { model, gains }
    }

    /// The lumped parameters of the model the controller assumes.
    pub fn model(&self) -> &Lumped {
        &self.model
    }

    /// The controller's gains.
    pub fn gains(&self) -> &Gains {
        &self.gains
    }

    /// Computes every term and the voltage (54) for one sample, with the model's parameters.
    // Inlined into the 20 kHz loop: its terms are not copied out through memory each sample, and
    // the one only a recorded row reads (V) is left out of the samples not recorded.
    #[inline(always)]
    pub fn control(&self, input: &ControlInput) -> Result<Terms, ControlError> {
        self.law(&self.model, None, input, &Paper)
    }

    /// As [`Backstepping::control`] (with the observer's estimated parameters when `adapted` is
    /// given), with the steps `custom` replaces. Its own function: the paper's law in the loop is
    /// compiled without the signals a custom law reads.
    #[inline(never)]
    pub fn control_with<C: Custom>(
        &self,
        input: &ControlInput,
        adapted: Option<&Adapted>,
        custom: &C,
    ) -> Result<Terms, ControlError> {
        match adapted {
            Some(a) => self.law(&a.model, Some(a.d_a2), input, custom),
            None => self.law(&self.model, None, input, custom),
        }
    }

    /// As [`Backstepping::control`], with the parameters the observer estimates (Section 3.1's
    /// remedies). The lumped parameters follow the estimates each sample; their own rates
    /// (dR̂_r/dt through a5, a7, a8, a10) are neglected in the derivatives.
    #[inline(always)]
    pub fn control_adapted(
        &self,
        input: &ControlInput,
        adapted: &Adapted,
    ) -> Result<Terms, ControlError> {
        self.law(&adapted.model, Some(adapted.d_a2), input, &Paper)
    }

    /// The four steps with lumped parameters `p` and, when a2 is estimated, dâ2/dt; the steps
    /// `custom` replaces take its values.
    #[inline(always)]
    fn law<C: Custom>(
        &self,
        p: &Lumped,
        d_a2: Option<f64>,
        input: &ControlInput,
        custom: &C,
    ) -> Result<Terms, ControlError> {
        let g = &self.gains;
        let [x1h, x2h, x3h, x4h, x5h] = input.x_hat;
        let [x2, x3] = input.y;
        let [e2, e3] = input.residual;
        let l = &input.l;
        let r = input.speed_ref;
        let shared = Shared::new(p, g, input);
        let Shared {
            si,
            de2,
            de3,
            flux_sq,
            dx4h,
            dx5h,
            k1s1,
            k2s1,
            z1,
            z3,
        } = shared;
        // What a step's own law may read, gathered only when there is one.
        let mut s = C::Signals::default();
        if C::ON {
            gather(&mut s, p, g, d_a2, input, &shared);
        }

        // Step 1, speed loop: eqs (23)–(30). â2 = a2 (the model's constant load) unless the
        // observer estimates it; then dâ2/dt is the observer's injection into â2.
        let v1a = -si[0] + r.d1 + p.a3 * r.value + p.a2;
        let v1s = -k1s1 * z1;
        let v1 = chosen(custom, 1, s.all(), v1a + v1s)?;
        let torque = p.a1 * (x3 * x4h - x2 * x5h);
        let z2 = torque - v1;
        if C::ON {
            s.set(sig!("v1"), v1);
            s.set(sig!("z2"), z2);
        }
        // dv1/dt of eq (31) with its typos corrected (a3·ω̇_d, dâ2/dt = 0).
        let mut dv1 =
            -k1s1 * (-g.k1 * z1 + z2) - (l[0][0] * de2 + l[0][1] * de3) + r.d2 + p.a3 * r.d1;
        if let Some(d) = d_a2 {
            dv1 += d;
        }

        // Step 2, torque loop: eq (32) is ż2 = v2 + ψ2 − (a7 + a8) z2 + d̃2; the printed (32)
        // drops −(a7+a8) z2, which is what makes k2 = a7 + a8 + k2s1 in (36) true.
        let psi2 = -(p.a7 + p.a8) * v1
            - p.a1 * p.a6 * x1h * flux_sq
            - p.a1 * p.a9 * x1h * (x5h * x3 + x4h * x2)
            + p.a1 * p.a10 * (x2h * x3 - x3h * x2)
            + p.a1 * (x3 * si[3] - x2 * si[4])
            - dv1;
        let v2a = -psi2 - z1;
        let v2s2 = if g.robust {
            -g.h2 * g.h2 / (4.0 * g.eps2) * z2
        } else {
            0.0
        };
        let v2s = -k2s1 * z2 + v2s2;
        let v2 = chosen(custom, 2, s.all(), v2a + v2s)?;

        // Step 3, flux outer loop: eqs (42)–(46).
        let psi3 = -2.0 * p.a8 * flux_sq - 2.0 * p.a10 * (e2 * x4h + e3 * x5h)
            + 2.0 * (x4h * si[3] + x5h * si[4]);
        // With a moving target, ż3 gains −ψ̇_d, which v3a takes up (a constant target adds 0.0,
        // which leaves every bit as it was).
        let v3a = -(psi3 - input.psi_d.d1);
        let v3s = -g.k3 * z3;
        let v3 = chosen(custom, 3, s.all(), v3a + v3s)?;
        let z4 = 2.0 * p.a10 * (x2 * x4h + x3 * x5h) - v3;
        if C::ON {
            s.set(sig!("v3"), v3);
            s.set(sig!("z4"), z4);
        }

        // Step 4, flux inner loop: eqs (47)–(51).
        let psi4 = 2.0 * p.a10 * p.a5 * flux_sq - 2.0 * p.a10 * p.a7 * (x2h * x4h + x3h * x5h)
            + 2.0 * p.a10 * (x4h * si[1] + x5h * si[2])
            + 2.0 * (l[3][0] * x4h + l[4][0] * x5h) * de2
            + 2.0 * (l[3][1] * x4h + l[4][1] * x5h) * de3
            + 2.0 * (si[3] + p.a10 * x2h - 2.0 * p.a8 * x4h) * dx4h
            + 2.0 * (si[4] + p.a10 * x3h - 2.0 * p.a8 * x5h) * dx5h
            + g.k3 * (-g.k3 * z3 + z4)
            - input.psi_d.d2;
        let v4a = -psi4 - z3;
        let v4s2 = if g.robust {
            -g.h4 * g.h4 / (4.0 * g.eps4) * z4
        } else {
            0.0
        };
        let v4s = -g.k4 * z4 + v4s2;
        let v4 = chosen(custom, 4, s.all(), v4a + v4s)?;

        let u = decouple(p, x4h, x5h, flux_sq, v2, v4)?;

        let z = [z1, z2, z3, z4];
        Ok(Terms {
            z,
            v1,
            v1a,
            v1s,
            v2,
            v2a,
            v2s,
            v3,
            v3a,
            v3s,
            v4,
            v4a,
            v4s,
            psi2,
            psi3,
            psi4,
            torque,
            u,
            lyapunov: 0.5 * (z1 * z1 + z2 * z2 + z3 * z3 + z4 * z4),
        })
    }
}

/// What the four steps share at one sample, derived once from the estimate, the residual and the
/// observer gain before step 1.
#[derive(Clone, Copy)]
struct Shared {
    /// Observer injections si_i = l_i1 x̃2 + l_i2 x̃3, eq (5).
    si: [f64; 5],
    /// Nominal residual dynamics (x̃1 = x̃4 = x̃5 = 0): d/dt x̃2.
    de2: f64,
    /// Likewise d/dt x̃3.
    de3: f64,
    /// x̂4² + x̂5² (Wb²).
    flux_sq: f64,
    /// x̂̇4 of the observer (4).
    dx4h: f64,
    /// x̂̇5 of the observer (4).
    dx5h: f64,
    /// k1s1 = k1 − a3, the speed loop's feedback gain.
    k1s1: f64,
    /// k2s1 = k2 − a7 − a8, the torque loop's feedback gain.
    k2s1: f64,
    /// Speed error z1 = x̂1 − ω_d.
    z1: f64,
    /// Flux error z3 = x̂4² + x̂5² − ψ_d.
    z3: f64,
}

impl Shared {
    /// The shared quantities of `input` with lumped parameters `p` and gains `g`: step 1's
    /// start, eqs (23)–(30).
    #[inline(always)]
    fn new(p: &Lumped, g: &Gains, input: &ControlInput) -> Shared {
        let [x1h, x2h, x3h, x4h, x5h] = input.x_hat;
        let [e2, e3] = input.residual;
        let l = &input.l;
        // Observer injections si_i = l_i1 x̃2 + l_i2 x̃3, eq (5).
        let si: [f64; 5] = std::array::from_fn(|i| l[i][0] * e2 + l[i][1] * e3);
        // Nominal residual dynamics (x̃1 = x̃4 = x̃5 = 0): d/dt x̃2, d/dt x̃3.
        let de2 = -(p.a7 + l[1][0]) * e2 - l[1][1] * e3;
        let de3 = -l[2][0] * e2 - (p.a7 + l[2][1]) * e3;
        let flux_sq = x4h * x4h + x5h * x5h;
        let k1s1 = g.k1 - p.a3;
        let k2s1 = g.k2 - p.a7 - p.a8;
        let z1 = x1h - input.speed_ref.value;
        let z3 = flux_sq - input.psi_d.value;
        // x̂̇4, x̂̇5 of the observer (4).
        let dx4h = -p.a8 * x4h - p.a9 * x1h * x5h + p.a10 * x2h + si[3];
        let dx5h = -p.a8 * x5h + p.a9 * x1h * x4h + p.a10 * x3h + si[4];
        Shared {
            si,
            de2,
            de3,
            flux_sq,
            dx4h,
            dx5h,
            k1s1,
            k2s1,
            z1,
            z3,
        }
    }
}

/// Sets in `s` every signal a step's own law may read before step 1: the sample's estimate,
/// measurement and reference, the parameters `p` (with dâ2/dt `d_a2`), the gains `g` and the
/// `shared` quantities. The steps' own v1, z2, v3 and z4 are set as they come.
#[inline(always)]
fn gather<S: Signals>(
    s: &mut S,
    p: &Lumped,
    g: &Gains,
    d_a2: Option<f64>,
    input: &ControlInput,
    shared: &Shared,
) {
    let [x1h, x2h, x3h, x4h, x5h] = input.x_hat;
    let [x2, x3] = input.y;
    let [e2, e3] = input.residual;
    let r = input.speed_ref;
    let named = [
        (sig!("x1h"), x1h),
        (sig!("x2h"), x2h),
        (sig!("x3h"), x3h),
        (sig!("x4h"), x4h),
        (sig!("x5h"), x5h),
        (sig!("x2"), x2),
        (sig!("x3"), x3),
        (sig!("xt2"), e2),
        (sig!("xt3"), e3),
        (sig!("dxt2"), shared.de2),
        (sig!("dxt3"), shared.de3),
        (sig!("dx4h"), shared.dx4h),
        (sig!("dx5h"), shared.dx5h),
        (sig!("wd"), r.value),
        (sig!("dwd"), r.d1),
        (sig!("ddwd"), r.d2),
        (sig!("psi_d"), input.psi_d.value),
        (sig!("a1"), p.a1),
        (sig!("a2"), p.a2),
        (sig!("a3"), p.a3),
        (sig!("a5"), p.a5),
        (sig!("a6"), p.a6),
        (sig!("a7"), p.a7),
        (sig!("a8"), p.a8),
        (sig!("a9"), p.a9),
        (sig!("a10"), p.a10),
        (sig!("b"), p.b),
        (sig!("da2"), d_a2.unwrap_or(0.0)),
        (sig!("k1"), g.k1),
        (sig!("k2"), g.k2),
        (sig!("k3"), g.k3),
        (sig!("k4"), g.k4),
        (sig!("k1s1"), shared.k1s1),
        (sig!("k2s1"), shared.k2s1),
        (sig!("h2"), g.h2),
        (sig!("eps2"), g.eps2),
        (sig!("h4"), g.h4),
        (sig!("eps4"), g.eps4),
        (sig!("robust"), if g.robust { 1.0 } else { 0.0 }),
        (sig!("z1"), shared.z1),
        (sig!("z3"), shared.z3),
    ];
    for (i, v) in named {
        s.set(i, v);
    }
    for (i, v) in shared.si.iter().enumerate() {
        s.set(sig!("si1") + i, *v);
    }
    for (i, row) in input.l.iter().enumerate() {
        s.set(sig!("l11") + 2 * i, row[0]);
        s.set(sig!("l11") + 2 * i + 1, row[1]);
    }
}

/// The voltage of eq (54), b·[[−a1x̂5, a1x̂4], [2a10x̂4, 2a10x̂5]]·u = [v2, v4], with lumped
/// parameters `p` and flux estimate (x̂4, x̂5) of square modulus `flux_sq`; refused when the
/// matrix is singular (det = −2 a1 a10 b (x̂4²+x̂5²)).
#[inline(always)]
fn decouple(
    p: &Lumped,
    x4h: f64,
    x5h: f64,
    flux_sq: f64,
    v2: f64,
    v4: f64,
) -> Result<[f64; 2], ControlError> {
    if flux_sq.is_nan() || flux_sq < MIN_FLUX_SQ {
        return Err(ControlError::SingularDecoupling { flux_sq });
    }
    let (m11, m12, m21, m22) = (
        -p.a1 * x5h,
        p.a1 * x4h,
        2.0 * p.a10 * x4h,
        2.0 * p.a10 * x5h,
    );
    let det = p.b * (m11 * m22 - m12 * m21);
    Ok([(m22 * v2 - m12 * v4) / det, (m11 * v4 - m21 * v2) / det])
}
