//! A closed-loop run: the loop (`closed_loop.rs`) advanced in chunks, with what it records
//! ([`crate::record`]), read back (`replay.rs`) for windows, figures, CSV and the inspect panel.

mod closed_loop;
mod error;
mod replay;

use crate::control::LyapunovBound;
use crate::record::{
    self, write_csv, Metrics, Recorder, Report, Row, Stability, StabilityTally, Trace, Transient,
    COLUMNS, COLUMN_DOCS, NUM_COLUMNS,
};
use crate::scenario::{Scenario, ScenarioError};
use crate::text::Message;
use closed_loop::{with_filter, Loop, LoopState, Observer};
pub use error::{LawFailure, SimError};
use serde::Serialize;

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
pub fn mib(bytes: usize) -> f64 {
    (bytes as f64 / f64::from(1 << 20) * 10.0).ceil() / 10.0
}

/// How a run keeps its samples.
// One per simulation, so the size of its larger variant does not matter.
#[allow(clippy::large_enum_variant)]
#[derive(Clone, Debug)]
enum Recording {
    /// Every kept row in memory (analysis runs, tests, `--every`).
    Rows(Recorder),
    /// Checkpoints, replayed for any window (the page and the CLI).
    Trace(Trace<LoopState>),
}

/// A closed-loop run that can be advanced in chunks.
#[derive(Clone, Debug)]
pub struct Simulation {
    lp: Loop,
    state: LoopState,
    recording: Recording,
    failure: Option<SimError>,
}

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
                allowed: Message::new("scenario-allowed-every"),
            });
        }
        let steps = scenario.steps();
        let rows = steps.div_ceil(every);
        // A traced run keeps checkpoints, not rows: a few bytes a sample (and 8 for a column kept
        // for an overlay), so every scenario the codec accepts fits. Only a run that keeps its
        // rows is bounded by their memory.
        let bytes = trace_bytes(scenario, every);
        if !traced && bytes > MAX_TRACE_BYTES {
            // Only a caller that keeps every n-th sample can keep fewer.
            return Err(ScenarioError::TooLarge {
                what: Message::new("scenario-trace-too-large")
                    .count("rows", rows)
                    .count("columns", NUM_COLUMNS)
                    .fixed("mib", mib(bytes), 1)
                    .count("max", MAX_TRACE_BYTES >> 20)
                    .text("fewer", if every > 1 { "yes" } else { "no" }),
            });
        }
        let (lp, state) = Loop::new(scenario)?;
        Ok(Simulation {
            lp,
            state,
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
                    let next = trace.checkpoint(self.state.k, &self.state).min(end);
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

    /// Writes recorded rows `start..start + count` (clamped to those recorded) as CSV lines,
    /// preceded by the header when `start` is 0, so that consecutive chunks concatenate to the
    /// whole CSV (shortest round-trip number format).
    pub fn write_csv_rows(
        &self,
        out: &mut impl std::io::Write,
        start: usize,
        count: usize,
    ) -> std::io::Result<()> {
        write_csv(out, start, &mut |f| {
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

    /// The end of the start-up transient of the rows recorded so far (see [`record::transient`]).
    pub fn transient_end(&self) -> Transient {
        record::transient(&self.lp.scenario, self).0
    }

    /// The transient, figures and warnings of the rows recorded so far (see [`record::report`]).
    pub fn report(&self) -> Report {
        let mut report = record::report(&self.lp.scenario, self);
        // With own laws, how far they are from their steps' designed dynamics over the run; a
        // residual that is not a number is a warning with its cause, never a figure.
        let Some(figures) = report.figures.as_mut() else {
            return report;
        };
        let info = record::figure_info("law_residual").expect("a figure of the table");
        match self.lp.law_residual() {
            Some(Ok(value)) => figures.push(record::Figure {
                name: info.name,
                label: info.label.clone(),
                value,
                unit: info.unit,
                window: Message::new("window-law-residual"),
                trend: None,
            }),
            Some(Err(cause)) => report.warnings.push(record::Warning {
                kind: record::WarningKind::NotFinite,
                figure: Some(info.name),
                text: Message::new("warning-not-finite")
                    .text("figure", info.name)
                    .said("cause", cause),
            }),
            None => {}
        }
        report
    }

    /// The figures of [`Simulation::report`]; None when nothing is recorded.
    pub fn figures(&self) -> Option<Vec<record::Figure>> {
        self.report().figures
    }

    /// RMS errors, mean NIS and saturation after the start-up transient (see [`Metrics`]).
    pub fn metrics(&self) -> Option<Metrics> {
        record::metrics(&self.lp.scenario, self)
    }
}

/// Every recorded value at one sample, with the Kalman gain, for the inspect panel.
#[cfg_attr(
    target_arch = "wasm32",
    derive(tsify::Tsify),
    tsify(missing_as_null, hashmap_as_object)
)]
#[derive(Clone, Debug, Serialize)]
pub struct Snapshot {
    /// Sample index k.
    pub k: usize,
    /// Column names, in CSV order.
    pub columns: &'static [&'static str],
    /// What each column is, without its unit.
    pub meanings: Vec<&'static str>,
    /// Each column's unit ("" for none).
    pub units: Vec<&'static str>,
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
            meanings: COLUMN_DOCS.iter().map(|d| meaning_and_unit(d).0).collect(),
            units: COLUMN_DOCS.iter().map(|d| meaning_and_unit(d).1).collect(),
            values: row.values().to_vec(),
            gain,
            l: gain.map(|r| r.map(|g| g * self.lp.rate)),
        }
    }
}

/// A column's doc split into its meaning and its unit: "Speed error z1 (rad/s)." gives
/// ("Speed error z1", "rad/s"); a doc that ends in no parenthesis has no unit.
fn meaning_and_unit(doc: &'static str) -> (&'static str, &'static str) {
    let doc = doc.strip_suffix('.').unwrap_or(doc);
    doc.strip_suffix(')')
        .and_then(|d| d.rsplit_once('('))
        .filter(|(_, unit)| !unit.contains(')'))
        .map_or((doc, ""), |(meaning, unit)| (meaning.trim_end(), unit))
}

#[cfg(test)]
mod tests {
    use super::meaning_and_unit;
    use crate::record::COLUMN_DOCS;

    #[test]
    fn a_doc_splits_into_its_meaning_and_its_unit() {
        assert_eq!(
            meaning_and_unit("Speed error z1 (rad/s)."),
            ("Speed error z1", "rad/s")
        );
        assert_eq!(meaning_and_unit("Mean NIS."), ("Mean NIS", ""));
        assert_eq!(meaning_and_unit("A (b) c"), ("A (b) c", ""));
        for doc in COLUMN_DOCS {
            let (meaning, unit) = meaning_and_unit(doc);
            assert!(!meaning.is_empty() && !meaning.ends_with(' '), "{doc}");
            assert!(!unit.contains(['(', ')']), "{doc}");
        }
    }
}
