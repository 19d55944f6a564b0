//! The 20 kHz closed loop: plant, measurement noise, EKF, controller, saturation and recording.
//!
//! This is the only module that sees the true plant state; the observer and controller get the
//! measured currents and the applied voltages (or, with the `perfect` teaching switch, the truth).

mod figures;
mod recorder;
mod trace;

pub use figures::{figures, report, transient_end, Figure, Report, Transient, Warning};
pub use recorder::{m4, Recorder, Row, COLUMNS, COLUMN_DOCS, M4, NUM_COLUMNS};
use trace::Trace;
pub use trace::CHECKPOINT_EVERY;

use crate::control::{
    Adapted, Backstepping, ControlError, ControlInput, Gains, Ifoc, LyapunovBound,
};
use crate::inverter::{self, Limit};
use crate::model::{self, Input, State};
use crate::observer::Filter;
use crate::params::Lumped;
use crate::rng::Rng;
use crate::scenario::{ControllerKind, Scenario, ScenarioError};
use serde::Serialize;
use std::fmt;

/// Largest trace a run may record (bytes); beyond it the run is refused before it starts.
pub const MAX_TRACE_BYTES: usize = 512 << 20;

/// Bytes the trace of `scenario` takes when every `every`-th sample is kept.
pub fn trace_bytes(scenario: &Scenario, every: usize) -> usize {
    scenario
        .steps()
        .div_ceil(every.max(1))
        .saturating_mul(Recorder::ROW_BYTES)
}

/// `bytes` in MiB, rounded up to a tenth, so a size just over a limit never reads as equal to it.
pub fn mib(bytes: usize) -> String {
    format!(
        "{:.1}",
        (bytes as f64 / f64::from(1 << 20) * 10.0).ceil() / 10.0
    )
}

/// Bounds past which the plant or the estimate is declared diverged.
const MAX_SPEED: f64 = 1e5; // rad/s, ~1 million rpm
const MAX_CURRENT: f64 = 1e5; // A
const MAX_FLUX: f64 = 1e3; // Wb

/// Why a run stopped early.
#[derive(Clone, Debug, PartialEq)]
pub enum SimError {
    /// A state left its physical bounds or became NaN.
    Diverged {
        /// Time of the sample (s).
        t: f64,
        /// Which signal.
        signal: &'static str,
        /// Its value.
        value: f64,
    },
    /// A recorded signal would not be a finite number (the trace keeps finite numbers only).
    NotFinite {
        /// Time of the sample (s).
        t: f64,
        /// The column.
        column: &'static str,
        /// Its value (±inf or NaN).
        value: f64,
    },
    /// The controller could not compute a voltage.
    Control {
        /// Time of the sample (s).
        t: f64,
        /// The reason.
        error: ControlError,
    },
}

impl fmt::Display for SimError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            SimError::Diverged { t, signal, value } => {
                write!(
                    f,
                    "diverged at t = {t:.5} s: {signal} = {value:e} left its bounds"
                )
            }
            SimError::NotFinite { t, column, value } => write!(
                f,
                "stopped at t = {t:.5} s: column '{column}' would record {value}, not a finite number"
            ),
            SimError::Control { t, error } => {
                write!(f, "controller failed at t = {t:.5} s: {error}")
            }
        }
    }
}

impl std::error::Error for SimError {}

/// The EKF, sized by the parameters it estimates besides the five states.
// One per simulation, so its size does not matter; inline, the loop reaches it without a pointer.
#[allow(clippy::large_enum_variant)]
#[derive(Clone, Debug)]
enum Observer {
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

/// What the loop keeps from sample to sample: everything a replay needs to go on from sample k
/// (a checkpoint is a copy of it). Holds no heap memory, so copying it never allocates.
#[derive(Clone, Debug)]
struct LoopState {
    /// The IFOC baseline, when the scenario selects it.
    ifoc: Option<Ifoc>,
    ekf: Observer,
    rng: Rng,
    x: State,
    /// The voltage applied over the last sample, [t_{k−1}, t_k).
    u: Input,
    /// With the computation delay: the voltage committed for the next sample, [t_k, t_{k+1}).
    pending: Input,
    /// The next sample to run.
    k: usize,
}

/// What stays fixed during a run: the scenario and what is derived from it.
#[derive(Clone, Debug)]
struct Loop {
    scenario: Scenario,
    plant: Lumped,
    controller: Backstepping,
    /// The lumped parameters the controller assumes, for the delay compensation's prediction.
    model: Lumped,
    /// The inverter's voltage limit.
    limit: Limit,
    steps: usize,
    /// Sampling rate 1/Ts (Hz).
    rate: f64,
}

/// Where the rows of the loop go: asked once per sample, in order, whether it wants that
/// sample's row; the row is only computed when it does.
trait Sink {
    /// Whether the row of the next sample is wanted.
    fn wants(&mut self) -> bool;
    /// Takes the wanted row; a value that is not finite is refused, naming its column.
    fn take(&mut self, row: &Row) -> Result<(), (&'static str, f64)>;
}

/// How a run keeps its samples.
// One per simulation, so the size of its larger variant does not matter.
#[allow(clippy::large_enum_variant)]
#[derive(Clone, Debug)]
enum Recording {
    /// Every kept row in memory (analysis runs, tests, `--every`).
    Rows(Recorder),
    /// Checkpoints, replayed for any window (the page and the CLI).
    Trace(Trace),
}

/// A closed-loop run that can be advanced in chunks.
#[derive(Clone, Debug)]
pub struct Simulation {
    lp: Loop,
    state: LoopState,
    recording: Recording,
    failure: Option<SimError>,
}

/// The first of `0..n` for which `holds` is false, where it holds for a prefix of `0..n` (row times
/// increase with the row): a binary search.
fn first_not(n: usize, holds: impl Fn(usize) -> bool) -> usize {
    let (mut lo, mut hi) = (0, n);
    while lo < hi {
        let mid = lo + (hi - lo) / 2;
        if holds(mid) {
            lo = mid + 1;
        } else {
            hi = mid;
        }
    }
    lo
}

/// Whether the commanded voltage of `row` is beyond the inverter's limit.
fn is_saturated(row: &Row, limit: &Limit) -> bool {
    limit.exceeds(&[row.u_a_cmd, row.u_b_cmd])
}

fn check_state(t: f64, x: &State, what: [&'static str; 5]) -> Result<(), SimError> {
    let bounds = [MAX_SPEED, MAX_CURRENT, MAX_CURRENT, MAX_FLUX, MAX_FLUX];
    for i in 0..5 {
        if x[i].is_nan() || x[i].abs() > bounds[i] {
            return Err(SimError::Diverged {
                t,
                signal: what[i],
                value: x[i],
            });
        }
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

impl Simulation {
    /// Prepares a run of `scenario` that keeps every `every`-th row in memory.
    pub fn new(scenario: &Scenario, every: usize) -> Result<Simulation, ScenarioError> {
        Simulation::prepare(scenario, every, false)
    }

    /// Prepares a run of `scenario` that keeps checkpoints of its state instead of rows (see
    /// [`Simulation::visit`]): every sample can be read back, bit for bit, for a fraction of the
    /// memory.
    pub fn traced(scenario: &Scenario) -> Result<Simulation, ScenarioError> {
        Simulation::prepare(scenario, 1, true)
    }

    fn prepare(
        scenario: &Scenario,
        every: usize,
        traced: bool,
    ) -> Result<Simulation, ScenarioError> {
        scenario.validate()?;
        if every == 0 {
            return Err(ScenarioError::OutOfRange {
                key: "every".to_string(),
                value: 0.0,
                allowed: "1 ≤ every".to_string(),
            });
        }
        let steps = scenario.steps();
        let rows = steps.div_ceil(every);
        // A traced run keeps checkpoints, not rows: a few bytes a sample (and 8 for a column kept
        // for an overlay), so every scenario the codec accepts fits. Only a run that keeps its
        // rows is bounded by their memory.
        let bytes = trace_bytes(scenario, every);
        if !traced && bytes > MAX_TRACE_BYTES {
            return Err(ScenarioError::TooLarge {
                what: format!(
                    "recording {rows} samples × {NUM_COLUMNS} columns needs {} MiB, more than the {} MiB allowed; \
                     shorten 'duration' or keep fewer samples (--every)",
                    mib(bytes),
                    MAX_TRACE_BYTES >> 20
                ),
            });
        }
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
        // Section 5: x(0) = [ω_d(0), 2, 2, 0.5, 0.5]; x̂(0) = (1 − e)·x(0); P0 = diag((e·x(0))²) + Q.
        let x0 = [scenario.reference.sample(0.0).value, 2.0, 2.0, 0.5, 0.5];
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
        Ok(Simulation {
            lp: Loop {
                scenario: scenario.clone(),
                plant,
                controller: Backstepping::new(model, scenario.gains),
                model,
                limit: scenario.limit(),
                steps,
                rate: 1.0 / scenario.ts,
            },
            state: LoopState {
                ifoc,
                ekf,
                rng: Rng::new(scenario.seed),
                x: x0,
                u: [0.0; 2],
                pending: [0.0; 2],
                k: 0,
            },
            recording: if traced {
                Recording::Trace(Trace::new(scenario, steps))
            } else {
                Recording::Rows(Recorder::with_capacity(rows, every))
            },
            failure: None,
        })
    }

    /// Runs up to `max_steps` more samples. Returns the number run; stops at the end or at the
    /// first failure, which is returned (and kept: later calls return it again).
    pub fn advance(&mut self, max_steps: usize) -> Result<usize, SimError> {
        if let Some(e) = &self.failure {
            return Err(e.clone());
        }
        let start = self.state.k;
        let end = self.lp.steps.min(start.saturating_add(max_steps));
        let result = match &mut self.recording {
            Recording::Rows(recorder) => self.lp.run(&mut self.state, end, recorder),
            Recording::Trace(trace) => {
                let mut result = Ok(());
                while result.is_ok() && self.state.k < end {
                    // Up to the next checkpoint, or the end, at a time.
                    let next = trace.checkpoint(&self.state).min(end);
                    result = self.lp.run(&mut self.state, next, trace);
                }
                result
            }
        };
        match result {
            Ok(()) => Ok(end - start),
            Err(e) => {
                self.failure = Some(e.clone());
                Err(e)
            }
        }
    }

    /// Runs to the end.
    pub fn run(&mut self) -> Result<(), SimError> {
        self.advance(usize::MAX).map(|_| ())
    }
}

impl Loop {
    /// Runs samples `st.k..end`, giving `sink` the rows it wants; stops at the first failure.
    fn run(&self, st: &mut LoopState, end: usize, sink: &mut dyn Sink) -> Result<(), SimError> {
        while st.k < end {
            self.step(st, sink)?;
            st.k += 1;
        }
        Ok(())
    }

    /// One sample k, in the loop order of the design: measure, predict, update, control, limit,
    /// hold (one sample later with the computation delay).
    fn step(&self, st: &mut LoopState, sink: &mut dyn Sink) -> Result<(), SimError> {
        let s = &self.scenario;
        let ts = s.ts;
        let t = st.k as f64 * ts;
        // 1. Measure.
        let y = [
            st.x[1] + s.noise * st.rng.normal(),
            st.x[2] + s.noise * st.rng.normal(),
        ];
        // 2–3. EKF predict with u_{k−1} (none before the first sample), then update with y_k.
        let u = st.u;
        let previous = (st.k > 0).then_some(&u);
        let estimate = with_filter!(&mut st.ekf, f => f.sample(previous, &y));
        let x_hat = estimate.x_hat;
        check_state(t, &x_hat, ESTIMATE_NAMES)?;
        let gain = estimate.gain;
        let (load, rotor_resistance) = (estimate.load, estimate.rotor_resistance);
        let residual = [y[0] - x_hat[1], y[1] - x_hat[2]];
        // The estimated parameters, when the observer has any: â2 with its rate l_a·(x̃2, x̃3)
        // (L = K/Ts), and the lumped parameters at R̂_r.
        let adapted = estimate.adapted_model.map(|model| Adapted {
            model,
            d_a2: load.map_or(0.0, |(_, _, k)| {
                (k[0] * residual[0] + k[1] * residual[1]) * self.rate
            }),
        });
        // 4. Controller from the posterior, the measured currents, L = K/Ts and the posterior residual.
        let speed_ref = s.reference.sample(t);
        let l = if s.perfect {
            [[0.0; 2]; 5]
        } else {
            // L = K/Ts, eq (20), as a product with 1/Ts (ten divisions per sample are slow).
            gain.map(|row| row.map(|k| k * self.rate))
        };
        let input = if s.drive.delay && s.drive.delay_comp && st.ifoc.is_none() {
            // Delay compensation: u_k acts from t_{k+1}, so control the one-step prediction
            // x̂_{k+1|k} under the voltage committed for [t_k, t_{k+1}), towards ω_d(t_{k+1}):
            // the EKF's own prior for the next sample (its predictor, its estimated parameters),
            // or the true state advanced by the plant's integrator for the perfect observer.
            // The prediction's currents stand in for the measurement, with a zero residual.
            let x_next = if s.perfect {
                model::advance(&self.model, &st.x, &st.pending, 0.0, ts, s.substeps)
            } else {
                with_filter!(&st.ekf, f => f.predicted_state(&st.pending))
            };
            ControlInput {
                x_hat: x_next,
                y: [x_next[1], x_next[2]],
                l,
                residual: [0.0; 2],
                speed_ref: s.reference.sample((st.k + 1) as f64 * ts),
                psi_d: s.psi_d,
            }
        } else if s.perfect {
            ControlInput {
                x_hat: st.x,
                y: [st.x[1], st.x[2]],
                l,
                residual: [0.0; 2],
                speed_ref,
                psi_d: s.psi_d,
            }
        } else {
            ControlInput {
                x_hat,
                y,
                l,
                residual,
                speed_ref,
                psi_d: s.psi_d,
            }
        };
        let backstepping = match &adapted {
            Some(a) if !s.perfect => self.controller.control_adapted(&input, a),
            _ => self.controller.control(&input),
        };
        let (terms, u_cmd, omega_used) = match &mut st.ifoc {
            None => {
                let terms = backstepping.map_err(|error| SimError::Control { t, error })?;
                (terms, terms.u, input.x_hat[0])
            }
            // The baseline drives the motor; the backstepping terms are evaluated from the EKF
            // for comparison only (zero where its decoupling matrix is singular).
            Some(ifoc) => {
                let u = ifoc.control(&y, &st.u, &speed_ref, self.limit.radius());
                let w = ifoc.speed_estimate();
                if w.is_nan() || w.abs() > MAX_SPEED {
                    return Err(SimError::Diverged {
                        t,
                        signal: "IFOC speed estimate",
                        value: w,
                    });
                }
                (backstepping.unwrap_or_default(), u, w)
            }
        };
        for (i, name) in ["commanded u_sa", "commanded u_sb"].into_iter().enumerate() {
            if !u_cmd[i].is_finite() {
                return Err(SimError::Diverged {
                    t,
                    signal: name,
                    value: u_cmd[i],
                });
            }
        }
        // 5. The inverter's limit; with the computation delay, the result waits one sample.
        let u_out = self.limit.apply(&u_cmd);
        st.u = if s.drive.delay {
            std::mem::replace(&mut st.pending, u_out)
        } else {
            u_out
        };
        // 6. Hold u over [t_k, t_k + Ts), averaged or switched; the unknown load step acts from
        // its time on.
        let extra_load = if t >= s.load_step.time {
            s.load_step.torque
        } else {
            0.0
        };
        let deceleration = extra_load / self.plant.j;
        let (x_next, ripple) = if s.drive.pwm {
            let vdc = s.drive.vdc;
            inverter::advance(&self.plant, &st.x, &st.u, vdc, deceleration, ts, s.substeps)
        } else {
            let x = model::advance(&self.plant, &st.x, &st.u, deceleration, ts, s.substeps);
            (x, 0.0)
        };

        let x = &st.x;
        let flux = (x[3] * x[3] + x[4] * x[4]).sqrt();
        let flux_sq_hat = x_hat[3] * x_hat[3] + x_hat[4] * x_hat[4];
        let p_omega = estimate.p_omega;
        let [innov_a, innov_b] = estimate.innovation;
        let [s_aa, s_ab, s_bb] = estimate.innovation_cov;
        let nis = estimate.nis;
        let j_model = s.model.j;
        if sink.wants() {
            let row = Row {
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
                flux_ref: s.psi_d.sqrt(),
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
                omega_used,
                lyapunov: terms.lyapunov,
                innov_a,
                innov_b,
                innov_band_a: 2.0 * s_aa.sqrt(),
                innov_band_b: 2.0 * s_bb.sqrt(),
                s_aa,
                s_ab,
                s_bb,
                nis,
                p_omega,
                load_hat: load.map_or(s.model.t0, |(a2, _, _)| a2 * j_model),
                rr_hat: rotor_resistance.map_or(s.model.rr, |(rr, _)| rr),
                load: s.plant.t0 + extra_load,
                load_band: load.map_or(0.0, |(_, var, _)| 2.0 * var.sqrt() * j_model),
                rr: s.plant.rr,
                rr_band: rotor_resistance.map_or(0.0, |(_, var)| 2.0 * var.sqrt()),
                i_ripple: ripple,
            };
            if let Err((column, value)) = sink.take(&row) {
                return Err(SimError::NotFinite { t, column, value });
            }
        }
        st.x = x_next;
        check_state(t + ts, &st.x, PLANT_NAMES)
    }
}

impl Simulation {
    /// Samples run so far.
    pub fn steps_done(&self) -> usize {
        self.state.k
    }

    /// Samples in the whole run.
    pub fn steps_total(&self) -> usize {
        self.lp.steps
    }

    /// Whether every sample has run.
    pub fn is_finished(&self) -> bool {
        self.state.k >= self.lp.steps
    }

    /// The failure that stopped the run, if any.
    pub fn failure(&self) -> Option<&SimError> {
        self.failure.as_ref()
    }

    /// The rows kept in memory, for a run made with [`Simulation::new`]. Panics for a traced run
    /// (see [`Simulation::visit`]).
    pub fn recorder(&self) -> &Recorder {
        match &self.recording {
            Recording::Rows(r) => r,
            Recording::Trace(_) => panic!("a traced run keeps no rows: read them with visit"),
        }
    }

    /// The scenario being run.
    pub fn scenario(&self) -> &Scenario {
        &self.lp.scenario
    }

    /// Bytes the recording holds: the rows, or the checkpoints of a traced run (with the column
    /// it keeps for overlays, if any).
    pub fn recording_bytes(&self) -> usize {
        match &self.recording {
            Recording::Rows(r) => r.len() * Recorder::ROW_BYTES,
            Recording::Trace(t) => t.bytes(),
        }
    }

    /// Rows recorded so far (only finite rows from before any failure).
    pub fn len(&self) -> usize {
        match &self.recording {
            Recording::Rows(r) => r.len(),
            Recording::Trace(t) => t.len,
        }
    }

    /// Whether no row has been recorded.
    pub fn is_empty(&self) -> bool {
        self.len() == 0
    }

    /// Time of recorded row `i` (s).
    pub fn time(&self, i: usize) -> f64 {
        match &self.recording {
            Recording::Rows(r) => r.rows()[i].t,
            // The loop's own t_k = k·Ts.
            Recording::Trace(_) => i as f64 * self.lp.scenario.ts,
        }
    }

    /// Calls `f(i, row)` for the recorded rows `start..end` (clamped to those recorded) in order,
    /// until it returns false. A traced run computes them again from the checkpoint before
    /// `start`: the same rows, bit for bit, as the run computed.
    pub fn visit(&self, start: usize, end: usize, f: &mut dyn FnMut(usize, &Row) -> bool) {
        let end = end.min(self.len());
        match &self.recording {
            Recording::Rows(r) => {
                for (i, row) in r.rows().iter().enumerate().take(end).skip(start) {
                    if !f(i, row) {
                        return;
                    }
                }
            }
            Recording::Trace(_) => {
                if start >= end {
                    return;
                }
                let mut cursor = self.cursor(start);
                for i in start..end {
                    if !f(i, &cursor.next_row()) {
                        return;
                    }
                }
            }
        }
    }

    /// Recorded row `i`, if there is one.
    pub fn row(&self, i: usize) -> Option<Row> {
        let mut out = None;
        self.visit(i, i + 1, &mut |_, r| {
            out = Some(*r);
            false
        });
        out
    }

    /// A replay of a traced run positioned at row `i` (< len).
    fn cursor(&self, i: usize) -> Cursor<'_> {
        let Recording::Trace(trace) = &self.recording else {
            unreachable!("only traced runs replay")
        };
        let mut state = trace.checkpoints[i / CHECKPOINT_EVERY].clone();
        let mut skip = Capture::default();
        // The rows before `i` ran without failing, so their replay does too.
        self.lp
            .run(&mut state, i, &mut skip)
            .expect("a replay of rows that ran");
        Cursor {
            lp: &self.lp,
            state,
        }
    }

    /// Row indices with t in [t0, t1].
    fn window(&self, t0: f64, t1: f64) -> (usize, usize) {
        let start = first_not(self.len(), |i| self.time(i) < t0);
        let end = first_not(self.len(), |i| self.time(i) <= t1).max(start);
        (start, end)
    }

    /// Asks a traced run that has not started for the M4 envelope of its whole run, per group of
    /// columns, in `buckets` buckets: [`Simulation::view`] of the whole run then answers without
    /// a replay. Errs for an unknown column or a run already started.
    pub fn keep_overview(&mut self, groups: &[Vec<String>], buckets: usize) -> Result<(), String> {
        let groups = groups
            .iter()
            .map(|g| trace::Overview::indices(g))
            .collect::<Result<Vec<_>, _>>()?;
        match &mut self.recording {
            Recording::Trace(t) if self.state.k == 0 => {
                t.overview = Some(Box::new(trace::Overview::new(
                    groups,
                    0,
                    self.lp.steps,
                    buckets,
                )));
                Ok(())
            }
            _ => Err("the overview is kept by a traced run from its start".to_string()),
        }
    }

    /// M4 envelopes (see [`M4`]) of each group of columns over the rows with t in [t0, t1], in at
    /// most `buckets` buckets: per group [t, columns...]. Every point is a recorded sample, so a
    /// line plot of it draws no edge the samples do not have. Errs for an unknown column.
    pub fn view(
        &self,
        groups: &[Vec<String>],
        t0: f64,
        t1: f64,
        buckets: usize,
    ) -> Result<Vec<Vec<Vec<f64>>>, String> {
        let indices = groups
            .iter()
            .map(|g| trace::Overview::indices(g))
            .collect::<Result<Vec<_>, _>>()?;
        let (start, end) = self.window(t0, t1);
        if let Recording::Trace(trace) = &self.recording {
            if let Some(o) = &trace.overview {
                let whole = start == 0 && end == self.lp.steps && trace.len == end;
                if whole && o.groups == indices && o.buckets == buckets.max(1) {
                    return Ok(o.result());
                }
            }
        }
        let mut overview = trace::Overview::new(indices, start, end - start, buckets);
        self.visit(start, end, &mut |i, row| {
            overview.push(i, row);
            true
        });
        Ok(overview.finish())
    }

    /// Column `name` of this run and of `others` (recorded at the same sampling period), then the
    /// differences this − other, over their common rows with t in [t0, t1], as one M4 envelope
    /// [t, this, others..., differences...]. Errs for an unknown column.
    pub fn overlay(
        &self,
        others: &[&Simulation],
        name: &str,
        t0: f64,
        t1: f64,
        buckets: usize,
    ) -> Result<Vec<Vec<f64>>, String> {
        let c = trace::Overview::indices(&[name])?[0];
        let rows = others.iter().map(|o| o.len()).fold(self.len(), usize::min);
        let (start, end) = self.window(t0, t1);
        let end = end.min(rows);
        let start = start.min(end);
        let series = 2 * others.len() + 1;
        let mut m4 = M4::new(
            vec![(0..series).collect()],
            series,
            start,
            end - start,
            buckets,
        );
        if start == end {
            return Ok(m4.finish().pop().expect("one group"));
        }
        let mut values = vec![0.0; 2 * others.len() + 2];
        let mut readers: Vec<_> = std::iter::once(self)
            .chain(others.iter().copied())
            .map(|s| s.column(c, start))
            .collect();
        for i in start..end {
            values[0] = self.time(i);
            for (j, r) in readers.iter_mut().enumerate() {
                values[1 + j] = r.next().expect("a recorded row");
            }
            for j in 0..others.len() {
                values[2 + others.len() + j] = values[1] - values[2 + j];
            }
            m4.push(i, &values);
        }
        Ok(m4.finish().pop().expect("one group"))
    }

    /// Column `c` of the rows from `i` on: kept in memory (the rows, or the column a traced run
    /// keeps), or replayed.
    fn column(&self, c: usize, i: usize) -> Box<dyn Iterator<Item = f64> + '_> {
        match &self.recording {
            Recording::Rows(r) => Box::new(r.rows()[i..].iter().map(move |row| row.get(c))),
            Recording::Trace(Trace {
                column: Some(kept), ..
            }) if kept.index == c => Box::new(kept.values[i..].iter().copied()),
            Recording::Trace(_) => {
                let mut cursor = self.cursor(i);
                Box::new(std::iter::from_fn(move || Some(cursor.next_row().get(c))))
            }
        }
    }

    /// Keeps column `name` of every row of a traced run, so that [`Simulation::overlay`] reads it
    /// instead of replaying the run: the rows recorded so far by one replay now (none before the
    /// run starts), then each further row as the run goes. One column at a time: another
    /// replaces it. A run that keeps its rows needs none. Errs for an unknown column.
    pub fn keep_column(&mut self, name: &str) -> Result<(), String> {
        let index = trace::Overview::indices(&[name])?[0];
        let Recording::Trace(trace) = &self.recording else {
            return Ok(());
        };
        if trace.column.as_ref().is_some_and(|c| c.index == index) {
            return Ok(());
        }
        // Room for every row the run can still record: its pushes do not allocate.
        let ended = self.is_finished() || self.failure.is_some();
        let mut values = Vec::with_capacity(if ended { self.len() } else { self.lp.steps });
        self.visit(0, self.len(), &mut |_, row| {
            values.push(row.get(index));
            true
        });
        if let Recording::Trace(trace) = &mut self.recording {
            trace.column = Some(trace::Column { index, values });
        }
        Ok(())
    }

    /// Writes recorded rows `start..start + count` (clamped to those recorded) as CSV lines,
    /// preceded by the header when `start` is 0, so that consecutive chunks concatenate to the
    /// whole CSV (shortest round-trip number format).
    pub fn write_csv_rows(
        &self,
        out: &mut impl std::io::Write,
        start: usize,
        count: usize,
    ) -> std::io::Result<()> {
        recorder::write_csv(out, start, &mut |f| {
            self.visit(start, start.saturating_add(count), &mut |_, row| f(row));
        })
    }

    /// Writes the header and every recorded row as CSV.
    pub fn write_csv(&self, out: &mut impl std::io::Write) -> std::io::Result<()> {
        self.write_csv_rows(out, 0, usize::MAX)
    }

    /// The header and every recorded row as one CSV string.
    pub fn csv(&self) -> String {
        let mut out = Vec::new();
        self.write_csv(&mut out).expect("writing to a Vec");
        String::from_utf8(out).expect("CSV is ASCII")
    }

    /// The EKF's posterior covariance P_{k|k} (5×5, or larger with estimated parameters).
    pub fn covariance(&self) -> nalgebra::DMatrix<f64> {
        with_filter!(&self.state.ekf, f => nalgebra::DMatrix::from_column_slice(f.covariance().nrows(), f.covariance().ncols(), f.covariance().as_slice()))
    }

    /// The Lyapunov bound (59) of this run, from the recorded V(0).
    pub fn lyapunov_bound(&self) -> Option<LyapunovBound> {
        let v0 = self.row(0)?.lyapunov;
        Some(LyapunovBound::new(&self.lp.scenario.gains, v0))
    }

    /// Where the recorded V(t) leaves the bound (59), and whether the voltage limit was active then.
    /// A traced run counts as its rows come; a run that keeps its rows counts them now.
    pub fn stability(&self) -> Option<Stability> {
        let perfect = self.lp.scenario.perfect;
        match &self.recording {
            Recording::Trace(t) => t.stability.finish(perfect),
            Recording::Rows(_) => {
                let mut tally = StabilityTally::new(self.lp.scenario.gains, self.lp.limit);
                self.visit(0, self.len(), &mut |_, r| {
                    tally.push(r);
                    true
                });
                tally.finish(perfect)
            }
        }
    }
}

/// Where V(t) leaves the bound (59), counted row by row from the first (whose V is V(0)).
#[derive(Clone, Debug)]
struct StabilityTally {
    gains: Gains,
    limit: Limit,
    bound: Option<LyapunovBound>,
    samples: usize,
    outside: usize,
    outside_saturated: usize,
    saturated: usize,
    first_outside: Option<f64>,
}

impl StabilityTally {
    fn new(gains: Gains, limit: Limit) -> StabilityTally {
        StabilityTally {
            gains,
            limit,
            bound: None,
            samples: 0,
            outside: 0,
            outside_saturated: 0,
            saturated: 0,
            first_outside: None,
        }
    }

    /// Counts the next row.
    #[inline]
    fn push(&mut self, r: &Row) {
        let gains = &self.gains;
        let bound = *self
            .bound
            .get_or_insert_with(|| LyapunovBound::new(gains, r.lyapunov));
        let at_limit = is_saturated(r, &self.limit);
        self.samples += 1;
        self.saturated += usize::from(at_limit);
        if r.lyapunov > bound.at(r.t) * (1.0 + BOUND_TOL) + f64::MIN_POSITIVE {
            self.outside += 1;
            self.outside_saturated += usize::from(at_limit);
            self.first_outside.get_or_insert(r.t);
        }
    }

    /// The report of the rows counted; None before the first.
    fn finish(&self, perfect: bool) -> Option<Stability> {
        let bound = self.bound?;
        let outside = self.outside;
        // Most likely reason: saturation when most samples above the bound had the limit active;
        // the sampled loop when the observer is perfect (d̃ = 0); otherwise the unbounded
        // estimation errors when ε = 0; otherwise ε or the sampling.
        let cause = if outside == 0 {
            "none"
        } else if 2 * self.outside_saturated > outside {
            "saturation"
        } else if perfect {
            "sampling"
        } else if bound.eps == 0.0 {
            "estimation_errors"
        } else {
            "eps_or_sampling"
        };
        Some(Stability {
            bound,
            samples: self.samples,
            outside,
            outside_saturated: self.outside_saturated,
            saturated: self.saturated,
            first_outside: self.first_outside,
            cause,
        })
    }
}

/// A sink that keeps the one row it is given, when it wants one: replays with no trace.
#[derive(Default)]
struct Capture {
    want: bool,
    row: Option<Row>,
}

impl Sink for Capture {
    fn wants(&mut self) -> bool {
        self.want
    }

    fn take(&mut self, row: &Row) -> Result<(), (&'static str, f64)> {
        self.row = Some(*row);
        Ok(())
    }
}

/// A replay of a traced run from a checkpoint.
struct Cursor<'a> {
    lp: &'a Loop,
    state: LoopState,
}

impl Cursor<'_> {
    /// The next row. The run recorded it, so it is computed again, bit for bit; a failure the
    /// run met just after recording its last row is met again after it and ignored here.
    fn next_row(&mut self) -> Row {
        let mut capture = Capture {
            want: true,
            row: None,
        };
        let _ = self.lp.step(&mut self.state, &mut capture);
        self.state.k += 1;
        capture.row.expect("a replay of a recorded row")
    }
}

/// Summary figures of a run, for comparing variants.
#[derive(Clone, Copy, Debug, Serialize)]
pub struct Metrics {
    /// Start of the window the figures cover (s): the end of the start-up transient, the window
    /// of the run's figures ([`figures`]), so that a figure has one value wherever it is shown.
    pub from: f64,
    /// RMS of ω − ω_d (rad/s).
    pub tracking_rms: f64,
    /// Largest |ω − ω_d| (rad/s).
    pub tracking_max: f64,
    /// RMS of ω − ω̂ (rad/s).
    pub speed_estimate_rms: f64,
    /// RMS of |φ| − |φ̂| (Wb).
    pub flux_estimate_rms: f64,
    /// Mean NIS (2 for a consistent filter).
    pub mean_nis: f64,
    /// Fraction of samples with a commanded voltage beyond the limit.
    pub saturated: f64,
}

impl Simulation {
    /// RMS errors, mean NIS and saturation after the start-up transient (see [`Metrics::from`]).
    pub fn metrics(&self) -> Option<Metrics> {
        let len = self.len();
        if len == 0 {
            return None;
        }
        let start = transient_end(self).t;
        let from = first_not(len, |i| self.time(i) < start);
        let n = (len - from) as f64;
        let limit = self.lp.limit;
        // Sums in row order, as `Iterator::sum` adds.
        let mut sums = [-0.0; 4];
        let (mut max, mut saturated) = (0.0f64, 0usize);
        self.visit(from, len, &mut |_, r| {
            sums[0] += r.omega_err * r.omega_err;
            sums[1] += r.omega_est_err * r.omega_est_err;
            sums[2] += r.flux_est_err * r.flux_est_err;
            sums[3] += r.nis;
            max = max.max(r.omega_err.abs());
            saturated += usize::from(is_saturated(r, &limit));
            true
        });
        Some(Metrics {
            from: self.time(from),
            tracking_rms: (sums[0] / n).sqrt(),
            tracking_max: max,
            speed_estimate_rms: (sums[1] / n).sqrt(),
            flux_estimate_rms: (sums[2] / n).sqrt(),
            mean_nis: sums[3] / n,
            saturated: saturated as f64 / n,
        })
    }
}

/// Relative margin before V counts as outside the bound: rounding in V and the bound.
const BOUND_TOL: f64 = 1e-9;

/// How a run's V(t) compares with the bound (59).
#[derive(Clone, Copy, Debug, Serialize)]
pub struct Stability {
    /// The bound.
    pub bound: LyapunovBound,
    /// Recorded samples.
    pub samples: usize,
    /// Samples where V is above the bound.
    pub outside: usize,
    /// Of those, samples where a commanded voltage exceeded the limit.
    pub outside_saturated: usize,
    /// Samples where a commanded voltage exceeded the limit.
    pub saturated: usize,
    /// First time V is above the bound (s).
    pub first_outside: Option<f64>,
    /// Most likely reason V leaves the bound: "none", "saturation", "sampling" (perfect observer),
    /// "estimation_errors" (ε = 0 with the robust terms off) or "eps_or_sampling".
    pub cause: &'static str,
}

/// Every recorded value at one sample, with the Kalman gain, for the inspect panel.
#[derive(Clone, Debug, Serialize)]
pub struct Snapshot {
    /// Sample index k.
    pub k: usize,
    /// Column names, in CSV order.
    pub columns: &'static [&'static str],
    /// What each column is, with its unit.
    pub docs: &'static [&'static str],
    /// The values of sample k, in the same order.
    pub values: Vec<f64>,
    /// Kalman gain K_k (5×2).
    pub gain: [[f64; 2]; 5],
    /// Observer gain L = K_k/Ts of eq (20) (5×2, 1/s).
    pub l: [[f64; 2]; 5],
}

impl Simulation {
    /// Replays `scenario` up to sample `k` (the nearest to time `t`) and returns every term there.
    /// The run is deterministic, so this equals row k of the full run bit for bit.
    pub fn inspect(scenario: &Scenario, t: f64) -> Result<Snapshot, String> {
        let steps = scenario.steps();
        let k = ((t / scenario.ts).round().max(0.0) as usize).min(steps.saturating_sub(1));
        // Keeping every k-th sample records samples 0 and k only.
        let mut sim = Simulation::new(scenario, k.max(1)).map_err(|e| e.to_string())?;
        sim.advance(k + 1).map_err(|e| e.to_string())?;
        let row = sim.recorder().rows().last().ok_or("nothing recorded")?;
        Ok(sim.snapshot(k, row, &sim.state))
    }

    /// [`Simulation::inspect`] of this traced run at the recorded sample nearest to `t`, replayed
    /// from the checkpoint before it.
    pub fn inspect_at(&self, t: f64) -> Result<Snapshot, String> {
        if self.is_empty() || !matches!(self.recording, Recording::Trace(_)) {
            return Err("nothing recorded".to_string());
        }
        let k = ((t / self.lp.scenario.ts).round().max(0.0) as usize).min(self.len() - 1);
        let mut cursor = self.cursor(k);
        let row = cursor.next_row();
        Ok(self.snapshot(k, &row, &cursor.state))
    }

    fn snapshot(&self, k: usize, row: &Row, state: &LoopState) -> Snapshot {
        let gain = with_filter!(&state.ekf, f => f.gain());
        Snapshot {
            k,
            columns: COLUMNS,
            docs: COLUMN_DOCS,
            values: row.values().to_vec(),
            gain,
            l: gain.map(|r| r.map(|g| g * self.lp.rate)),
        }
    }
}
