//! The 20 kHz loop, one sample at a time, in the order of the design: measure, estimate,
//! control, limit, apply; the drive's effects (the computation delay and its compensation, the
//! voltage limit, PWM) are named steps of it. The only code that sees the true plant state: the
//! observer and the controller get the measured currents and the applied voltages (or, with the
//! `perfect` teaching switch, the truth).

use super::error::{LawFailure, SimError};
use crate::control::law::{self, Laws};
use crate::control::{
    self, Adapted, Backstepping, ControlError, ControlInput, Ifoc, RefSample, Terms,
};
use crate::inverter::{self, Limit};
use crate::model::{self, Input, State};
use crate::observer::{Estimate, Filter};
use crate::params::Lumped;
use crate::record::{Row, Sink};
use crate::rng::Rng;
use crate::scenario::{ControllerKind, Scenario, ScenarioError};
use crate::text::Message;
use std::cell::{Cell, OnceCell};

/// Bounds past which the plant or the estimate is declared diverged.
const MAX_SPEED: f64 = 1e5; // rad/s, ~1 million rpm
const MAX_CURRENT: f64 = 1e5; // A
const MAX_FLUX: f64 = 1e3; // Wb

/// The EKF, sized by the parameters it estimates besides the five states.
// One per simulation, so its size does not matter; inline, the loop reaches it without a pointer.
#[allow(clippy::large_enum_variant)]
#[derive(Clone, Debug)]
pub(super) enum Observer {
    /// The paper's five states.
    Plain(Filter<5>),
    /// Plus the load or the rotor resistance.
    One(Filter<6>),
    /// Plus both.
    Two(Filter<7>),
}

/// Calls the same method on whichever filter the observer holds.
macro_rules! with_filter {
    ($observer:expr, $f:ident => $body:expr) => {
        match $observer {
            Observer::Plain($f) => $body,
            Observer::One($f) => $body,
            Observer::Two($f) => $body,
        }
    };
}
pub(super) use with_filter;

/// What the loop keeps from sample to sample: everything a replay needs to go on from sample k
/// (a checkpoint is a copy of it). Holds no heap memory, so copying it never allocates.
#[derive(Clone, Debug)]
pub(super) struct LoopState {
    /// The IFOC baseline, when the scenario selects it.
    ifoc: Option<Ifoc>,
    pub(super) ekf: Observer,
    rng: Rng,
    x: State,
    /// The voltage applied over the last sample, [t_{k−1}, t_k).
    u: Input,
    /// With the computation delay: the voltage committed for the next sample, [t_k, t_{k+1}).
    pending: Input,
    /// The next sample to run.
    pub(super) k: usize,
}

/// What stays fixed during a run: the scenario and what is derived from it.
#[derive(Clone, Debug)]
pub(super) struct Loop {
    pub(super) scenario: Scenario,
    plant: Lumped,
    controller: Backstepping,
    /// The steps' own laws, when the scenario has any.
    laws: Option<Laws>,
    /// With them, each step's v_i − v_i,ref at the last sample run (v_i,ref: the paper's v_i, or
    /// the one that gives the designed dynamics after the student's own earlier step): the
    /// residual of its designed dynamics (the walkthrough plots it through a replay).
    law_residuals: Cell<[f64; 4]>,
    /// With them, each step's largest |v_i − v_i,ref| and largest |v_i,paper| over the samples
    /// run (a replay runs the same samples again, which leaves the largest values as they are).
    law_peaks: Cell<[[f64; 2]; 4]>,
    /// With them, the largest difference of a law from the one that gives its step's designed
    /// dynamics at the verdict's drawn states and parameter values (see
    /// [`crate::control::law::check`]): what the run's own samples cannot tell, as a parameter
    /// written as its number.
    law_drawn: OnceCell<Option<Result<f64, law::Unjudged>>>,
    /// The lumped parameters the controller assumes, for the delay compensation's prediction.
    model: Lumped,
    /// The inverter's voltage limit.
    pub(super) limit: Limit,
    pub(super) steps: usize,
    /// Sampling rate 1/Ts (Hz).
    pub(super) rate: f64,
}

/// What the observer gives the controller at one sample.
struct Observed {
    estimate: Estimate,
    /// y_k − x̂_{k|k} of the currents (A).
    residual: [f64; 2],
    /// The estimated parameters, when the observer has any.
    adapted: Option<Adapted>,
}

/// What the controller commands at one sample.
struct Commanded {
    /// The backstepping terms (evaluated for comparison when the IFOC baseline drives).
    terms: Terms,
    /// The commanded voltage, before the limit.
    u_cmd: Input,
    /// The speed the driving controller used.
    omega_used: f64,
}

/// The backstepping terms with a scenario's own laws in place of the paper's steps; a law that
/// fails is named with its formula and the signals it read.
#[inline(never)]
fn custom_terms(
    controller: &Backstepping,
    input: ControlInput,
    adapted: Option<Adapted>,
    laws: &Laws,
    t: f64,
    residuals: &Cell<[f64; 4]>,
    peaks: &Cell<[[f64; 2]; 4]>,
) -> Result<Terms, SimError> {
    let kept = law::Residuals::new(laws);
    let terms = controller.control_with(&input, adapted.as_ref(), &kept);
    let (r, paper) = (kept.last.get(), kept.paper.get());
    residuals.set(r);
    let mut p = peaks.get();
    for i in 0..4 {
        p[i] = [p[i][0].max(r[i].abs()), p[i][1].max(paper[i].abs())];
    }
    peaks.set(p);
    terms.map_err(|error| match error {
        ControlError::Law { step, value } => {
            let own = laws.step(step).expect("a failing step has its own law");
            let signals = kept.failed.get().expect("a failing law keeps its signals");
            SimError::Law(Box::new(LawFailure {
                t,
                step,
                text: own.text.clone(),
                value,
                signals: law::named_values(own, &signals),
            }))
        }
        error => SimError::Control { t, error },
    })
}

fn check_state(t: f64, x: &State, what: [&'static str; 5]) -> Result<(), SimError> {
    let bounds = [MAX_SPEED, MAX_CURRENT, MAX_CURRENT, MAX_FLUX, MAX_FLUX];
    for i in 0..5 {
        // One comparison: false for NaN as for a value past its bound.
        if x[i].abs() <= bounds[i] {
            continue;
        }
        return Err(SimError::Diverged {
            t,
            signal: what[i],
            value: x[i],
        });
    }
    Ok(())
}

const PLANT_NAMES: [&str; 5] = [
    "speed ω",
    "current i_sa",
    "current i_sb",
    "flux φ_ra",
    "flux φ_rb",
];
const ESTIMATE_NAMES: [&str; 5] = [
    "estimated speed ω̂",
    "estimated i_sa",
    "estimated i_sb",
    "estimated φ_ra",
    "estimated φ_rb",
];

impl Loop {
    /// The loop of `scenario` and its state before the first sample: x(0) its start state (Section
    /// 5's [ω_d(0), 2, 2, 0.5, 0.5] in the presets); x̂(0) = (1 − e)·x(0); P0 = diag((e·x(0))²) + Q.
    pub(super) fn new(scenario: &Scenario) -> Result<(Loop, LoopState), ScenarioError> {
        let plant = scenario
            .plant
            .lumped()
            .map_err(|error| ScenarioError::Physics {
                which: "plant",
                error,
            })?;
        let model = scenario
            .model
            .lumped()
            .map_err(|error| ScenarioError::Physics {
                which: "model",
                error,
            })?;
        let x0 = scenario.start_state();
        let e = scenario.init_error;
        let (x0_hat, p0_std) = (x0.map(|v| (1.0 - e) * v), x0.map(|v| e * v));
        let (m, ts, cfg) = (&scenario.model, scenario.ts, &scenario.ekf);
        let ekf = match (cfg.load, cfg.rr) {
            (false, false) => Observer::Plain(Filter::new(m, model, ts, cfg, x0_hat, p0_std)),
            (true, true) => Observer::Two(Filter::new(m, model, ts, cfg, x0_hat, p0_std)),
            _ => Observer::One(Filter::new(m, model, ts, cfg, x0_hat, p0_std)),
        };
        // The baseline starts from the same 10 % initial error as the EKF.
        let ifoc = (scenario.controller == ControllerKind::Ifoc).then(|| {
            let start = x0.map(|v| (1.0 - e) * v);
            Ifoc::new(
                &scenario.model,
                &scenario.ifoc,
                scenario.ts,
                scenario.psi_d,
                start[0],
                [start[3], start[4]],
                [start[1], start[2]],
            )
        });
        let lp = Loop {
            scenario: scenario.clone(),
            plant,
            controller: Backstepping::new(model, scenario.gains),
            laws: {
                let laws = scenario.laws()?;
                (!laws.is_empty()).then_some(laws)
            },
            law_residuals: Cell::new([0.0; 4]),
            law_peaks: Cell::new([[0.0; 2]; 4]),
            law_drawn: OnceCell::new(),
            model,
            limit: scenario.limit(),
            steps: scenario.steps(),
            rate: 1.0 / scenario.ts,
        };
        let state = LoopState {
            ifoc,
            ekf,
            rng: Rng::new(scenario.seed),
            x: x0,
            u: [0.0; 2],
            pending: [0.0; 2],
            k: 0,
        };
        Ok((lp, state))
    }

    /// Each step's v_i − v_i,ref at the sample run last (zeros without own laws).
    pub(super) fn law_residuals(&self) -> [f64; 4] {
        self.law_residuals.get()
    }

    /// The largest residual of the own laws' designed dynamics, relative to the paper's law: over
    /// the samples run, max over the steps with an own law of max|v_i − v_i,ref| / max|v_i,paper|,
    /// and at the verdict's drawn states and parameter values, whichever is larger; or why it is
    /// not a number (None without own laws, or before a sample).
    pub(super) fn law_residual(&self) -> Option<Result<f64, Message>> {
        let laws = self.laws.as_ref().filter(|_| self.has_laws())?;
        let peaks = self.law_peaks.get();
        let run = (1..=4u8)
            .filter(|&step| laws.step(step).is_some())
            .map(|step| {
                let [r, paper] = peaks[step as usize - 1];
                r / paper
            })
            .reduce(f64::max)
            .filter(|v| !v.is_nan())?;
        if run.is_infinite() {
            return Some(Err(Message::new("law-paper-zero")));
        }
        // Checked once, when first asked for: most runs never report it.
        let drawn = self
            .law_drawn
            .get_or_init(|| law::worst(&self.scenario.law, &self.model, &self.scenario.gains));
        Some(match drawn {
            Some(Ok(drawn)) => Ok(run.max(*drawn)),
            Some(Err(cause)) => Err(cause.message()),
            None => Ok(run),
        })
    }

    /// Whether the scenario has its own laws (that drive the motor).
    pub(super) fn has_laws(&self) -> bool {
        self.laws.is_some() && self.scenario.controller == ControllerKind::Backstepping
    }

    /// Why d̃2 and d̃4 cannot be evaluated for this run's controller, if they cannot: they are
    /// the backstepping's unknown terms for the five-state observer's posterior estimate.
    pub(super) fn disturbances_refused(&self) -> Option<&'static str> {
        let s = &self.scenario;
        if s.ekf.load || s.ekf.rr {
            Some("d̃2 and d̃4 are evaluated for the five-state EKF: not with ekf.load or ekf.rr")
        } else if s.drive.delay && s.drive.delay_comp {
            Some("d̃2 and d̃4 are evaluated for the posterior estimate: not with delay.comp")
        } else {
            None
        }
    }

    /// [d̃2, d̃4] at the sample `st` has just run and recorded as `row` (see
    /// [`crate::control::disturbances`]); NaN where the estimated flux is zero.
    pub(super) fn disturbances_at(&self, st: &LoopState, row: &Row) -> [f64; 2] {
        let s = &self.scenario;
        let l = if s.perfect {
            [[0.0; 2]; 5]
        } else {
            with_filter!(&st.ekf, f => f.gain()).map(|r| r.map(|k| k * self.rate))
        };
        let x = [row.omega, row.i_sa, row.i_sb, row.phi_ra, row.phi_rb];
        // The perfect observer gives the controller the true state.
        let x_hat = if s.perfect {
            x
        } else {
            [
                row.omega_hat,
                row.i_sa_hat,
                row.i_sb_hat,
                row.phi_ra_hat,
                row.phi_rb_hat,
            ]
        };
        let sample = control::Sample {
            plant: &self.plant,
            x,
            x_hat,
            u: [row.u_a, row.u_b],
            l,
            extra_load: self.load_step(row.t) / self.plant.j,
            speed_ref: s.reference.sample(row.t),
            psi_d: s.flux_target(&s.reference.sample(row.t)),
        };
        control::disturbances(&self.controller, &sample).unwrap_or([f64::NAN; 2])
    }

    /// Runs samples `st.k..end`, giving `sink` the rows it wants; stops at the first failure.
    pub(super) fn run(
        &self,
        st: &mut LoopState,
        end: usize,
        sink: &mut dyn Sink,
    ) -> Result<(), SimError> {
        while st.k < end {
            self.step(st, sink)?;
            st.k += 1;
        }
        Ok(())
    }

    /// One sample k: measure, estimate, control, limit, apply (one sample later with the
    /// computation delay), then record.
    pub(super) fn step(&self, st: &mut LoopState, sink: &mut dyn Sink) -> Result<(), SimError> {
        let t = st.k as f64 * self.scenario.ts;
        let y = self.measure(st);
        let observed = self.estimate(st, &y, t)?;
        let speed_ref = self.scenario.reference.sample(t);
        let commanded = self.control(st, &observed, &y, &speed_ref, t)?;
        self.limit(st, &commanded.u_cmd);
        let extra_load = self.load_step(t);
        let (x_next, ripple) = self.apply(st, extra_load);
        if sink.wants() {
            let row = self.row(
                st, t, &y, &observed, &speed_ref, &commanded, extra_load, ripple,
            );
            if let Err((column, value)) = sink.take(&row) {
                return Err(SimError::NotFinite { t, column, value });
            }
        }
        st.x = x_next;
        check_state(t + self.scenario.ts, &st.x, PLANT_NAMES)
    }

    /// Measure (step 1): the true currents with the sensors' noise.
    #[inline(always)]
    fn measure(&self, st: &mut LoopState) -> [f64; 2] {
        let noise = self.scenario.noise;
        [
            st.x[1] + noise * st.rng.normal(),
            st.x[2] + noise * st.rng.normal(),
        ]
    }

    /// Estimate (steps 2–3): the EKF predicts with u_{k−1} (none before the first sample), then updates
    /// with y_k.
    #[inline(always)]
    fn estimate(&self, st: &mut LoopState, y: &[f64; 2], t: f64) -> Result<Observed, SimError> {
        let u = st.u;
        let previous = (st.k > 0).then_some(&u);
        let estimate = with_filter!(&mut st.ekf, f => f.sample(previous, y));
        check_state(t, &estimate.x_hat, ESTIMATE_NAMES)?;
        let x_hat = estimate.x_hat;
        let residual = [y[0] - x_hat[1], y[1] - x_hat[2]];
        // The estimated parameters, when the observer has any: â2 with its rate l_a·(x̃2, x̃3)
        // (L = K/Ts), and the lumped parameters at R̂_r.
        let adapted = estimate.adapted_model.map(|model| Adapted {
            model,
            d_a2: estimate.load.map_or(0.0, |(_, _, k)| {
                (k[0] * residual[0] + k[1] * residual[1]) * self.rate
            }),
        });
        Ok(Observed {
            estimate,
            residual,
            adapted,
        })
    }

    /// Control (step 4): the backstepping controller from what it is given (see
    /// [`Loop::control_input`]), or the IFOC baseline from the measured currents.
    #[inline(always)]
    fn control(
        &self,
        st: &mut LoopState,
        observed: &Observed,
        y: &[f64; 2],
        speed_ref: &RefSample,
        t: f64,
    ) -> Result<Commanded, SimError> {
        let s = &self.scenario;
        let input = self.control_input(st, observed, y, speed_ref);
        let backstepping = match &self.laws {
            // Out of line, taking copies: the paper's law below keeps its inputs in registers.
            Some(laws) => custom_terms(
                &self.controller,
                input,
                observed.adapted.filter(|_| !s.perfect),
                laws,
                t,
                &self.law_residuals,
                &self.law_peaks,
            ),
            None => match &observed.adapted {
                Some(a) if !s.perfect => self.controller.control_adapted(&input, a),
                _ => self.controller.control(&input),
            }
            .map_err(|error| SimError::Control { t, error }),
        };
        let commanded = match &mut st.ifoc {
            None => {
                let terms = backstepping?;
                Commanded {
                    terms,
                    u_cmd: terms.u,
                    omega_used: input.x_hat[0],
                }
            }
            // The baseline drives the motor; the backstepping terms are evaluated from the EKF
            // for comparison only (zero where its decoupling matrix is singular).
            Some(ifoc) => {
                let u = ifoc.control(y, &st.u, speed_ref, self.limit.radius());
                let w = ifoc.speed_estimate();
                if w.is_nan() || w.abs() > MAX_SPEED {
                    return Err(SimError::Diverged {
                        t,
                        signal: "IFOC speed estimate",
                        value: w,
                    });
                }
                Commanded {
                    terms: backstepping.unwrap_or_default(),
                    u_cmd: u,
                    omega_used: w,
                }
            }
        };
        for (i, name) in ["commanded u_sa", "commanded u_sb"].into_iter().enumerate() {
            if !commanded.u_cmd[i].is_finite() {
                return Err(SimError::Diverged {
                    t,
                    signal: name,
                    value: commanded.u_cmd[i],
                });
            }
        }
        Ok(commanded)
    }

    /// What the backstepping controller is given: the posterior, the measured currents,
    /// L = K/Ts and the posterior residual; the truth for the perfect observer; with the delay
    /// compensation, the one-step prediction.
    #[inline(always)]
    fn control_input(
        &self,
        st: &LoopState,
        observed: &Observed,
        y: &[f64; 2],
        speed_ref: &RefSample,
    ) -> ControlInput {
        let s = &self.scenario;
        let l = if s.perfect {
            [[0.0; 2]; 5]
        } else {
            // L = K/Ts, eq (20), as a product with 1/Ts (ten divisions per sample are slow).
            observed.estimate.gain.map(|row| row.map(|k| k * self.rate))
        };
        if s.drive.delay && s.drive.delay_comp && st.ifoc.is_none() {
            // Delay compensation: u_k acts from t_{k+1}, so control the one-step prediction
            // x̂_{k+1|k} under the voltage committed for [t_k, t_{k+1}), towards ω_d(t_{k+1}):
            // the EKF's own prior for the next sample (its predictor, its estimated parameters),
            // or the true state advanced by the plant's integrator for the perfect observer.
            // The prediction's currents stand in for the measurement, with a zero residual.
            let x_next = if s.perfect {
                model::advance(&self.model, &st.x, &st.pending, 0.0, s.ts, s.substeps)
            } else {
                with_filter!(&st.ekf, f => f.predicted_state(&st.pending))
            };
            ControlInput {
                x_hat: x_next,
                y: [x_next[1], x_next[2]],
                l,
                residual: [0.0; 2],
                speed_ref: s.reference.sample((st.k + 1) as f64 * s.ts),
                psi_d: s.flux_target(&s.reference.sample((st.k + 1) as f64 * s.ts)),
            }
        } else if s.perfect {
            ControlInput {
                x_hat: st.x,
                y: [st.x[1], st.x[2]],
                l,
                residual: [0.0; 2],
                speed_ref: *speed_ref,
                psi_d: s.flux_target(speed_ref),
            }
        } else {
            ControlInput {
                x_hat: observed.estimate.x_hat,
                y: *y,
                l,
                residual: observed.residual,
                speed_ref: *speed_ref,
                psi_d: s.flux_target(speed_ref),
            }
        }
    }

    /// Limit (step 5): the inverter's voltage limit; with the computation delay, the result waits one
    /// sample.
    #[inline(always)]
    fn limit(&self, st: &mut LoopState, u_cmd: &Input) {
        let u_out = self.limit.apply(u_cmd);
        st.u = if self.scenario.drive.delay {
            std::mem::replace(&mut st.pending, u_out)
        } else {
            u_out
        };
    }

    /// The unknown extra load torque at time `t` (N m).
    #[inline(always)]
    fn load_step(&self, t: f64) -> f64 {
        self.scenario.load_step.at(t)
    }

    /// Apply (step 6): hold u over [t_k, t_k + Ts), averaged or switched by PWM, with the extra load;
    /// the plant's next state and the PWM current ripple.
    #[inline(always)]
    fn apply(&self, st: &LoopState, extra_load: f64) -> (State, f64) {
        let s = &self.scenario;
        let deceleration = extra_load / self.plant.j;
        if s.drive.pwm {
            let vdc = s.drive.vdc;
            inverter::advance(
                &self.plant,
                &st.x,
                &st.u,
                vdc,
                deceleration,
                s.ts,
                s.substeps,
            )
        } else {
            let x = model::advance(&self.plant, &st.x, &st.u, deceleration, s.ts, s.substeps);
            (x, 0.0)
        }
    }

    /// The row of sample k: every signal the loop computed, before the plant moves on.
    #[allow(clippy::too_many_arguments)]
    #[inline(always)]
    fn row(
        &self,
        st: &LoopState,
        t: f64,
        y: &[f64; 2],
        observed: &Observed,
        speed_ref: &RefSample,
        commanded: &Commanded,
        extra_load: f64,
        ripple: f64,
    ) -> Row {
        let s = &self.scenario;
        let (x, x_hat, e) = (&st.x, &observed.estimate.x_hat, &observed.estimate);
        let (terms, u_cmd) = (&commanded.terms, &commanded.u_cmd);
        let flux = (x[3] * x[3] + x[4] * x[4]).sqrt();
        let flux_sq_hat = x_hat[3] * x_hat[3] + x_hat[4] * x_hat[4];
        let [innov_a, innov_b] = e.innovation;
        let [s_aa, s_ab, s_bb] = e.innovation_cov;
        let j_model = s.model.j;
        Row {
            t,
            omega_ref: speed_ref.value,
            omega: x[0],
            omega_hat: x_hat[0],
            i_sa: x[1],
            i_sb: x[2],
            i_sa_hat: x_hat[1],
            i_sb_hat: x_hat[2],
            phi_ra: x[3],
            phi_rb: x[4],
            phi_ra_hat: x_hat[3],
            phi_rb_hat: x_hat[4],
            u_a: st.u[0],
            u_b: st.u[1],
            z1: terms.z[0],
            z2: terms.z[1],
            z3: terms.z[2],
            z4: terms.z[3],
            y_a: y[0],
            y_b: y[1],
            flux,
            flux_hat: flux_sq_hat.sqrt(),
            flux_ref: s.flux_target(speed_ref).value.sqrt(),
            omega_err: x[0] - speed_ref.value,
            omega_est_err: x[0] - x_hat[0],
            flux_est_err: flux - flux_sq_hat.sqrt(),
            flux_sq_hat,
            torque_hat: terms.torque,
            v1: terms.v1,
            v1a: terms.v1a,
            v1s: terms.v1s,
            v2: terms.v2,
            v2a: terms.v2a,
            v2s: terms.v2s,
            v3: terms.v3,
            v3a: terms.v3a,
            v3s: terms.v3s,
            v4: terms.v4,
            v4a: terms.v4a,
            v4s: terms.v4s,
            psi2: terms.psi2,
            psi3: terms.psi3,
            psi4: terms.psi4,
            u_a_cmd: u_cmd[0],
            u_b_cmd: u_cmd[1],
            omega_used: commanded.omega_used,
            lyapunov: terms.lyapunov,
            innov_a,
            innov_b,
            innov_band_a: 2.0 * s_aa.sqrt(),
            innov_band_b: 2.0 * s_bb.sqrt(),
            s_aa,
            s_ab,
            s_bb,
            nis: e.nis(),
            p_omega: e.p_omega,
            load_hat: e.load.map_or(s.model.t0, |(a2, _, _)| a2 * j_model),
            rr_hat: e.rotor_resistance.map_or(s.model.rr, |(rr, _)| rr),
            load: s.plant.t0 + extra_load,
            load_band: e.load.map_or(0.0, |(_, var, _)| 2.0 * var.sqrt() * j_model),
            rr: s.plant.rr,
            rr_band: e.rotor_resistance.map_or(0.0, |(_, var)| 2.0 * var.sqrt()),
            i_ripple: ripple,
        }
    }
}
