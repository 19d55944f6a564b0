//! The trace of a run as checkpoints: a copy of the loop's state every [`CHECKPOINT_EVERY`]
//! samples, from which any window of rows is computed again, bit for bit, by replay. The run
//! checks every row it computes (finite values only) and can feed an M4 overview of the whole
//! run as it goes, so that the first plot needs no replay.

use super::m4::M4;
use super::row::{finite, Row, Sink, COLUMNS};
use super::tally::{StabilityTally, TransientTally, CHECKPOINT_EVERY};
use super::window::WindowTally;
use crate::scenario::Scenario;

/// M4 envelopes of groups of columns over a window of rows, fed row by row: while the run goes
/// (the overview of the whole run) or by a replay.
#[derive(Clone, Debug)]
pub struct Overview {
    /// Column indices per group.
    pub groups: Vec<Vec<usize>>,
    /// Buckets of the envelopes (at least 1).
    pub buckets: usize,
    /// The distinct columns of the groups.
    columns: Vec<usize>,
    envelopes: M4,
    /// [t, columns...] of the current row.
    values: Vec<f64>,
}

impl Overview {
    /// Column indices of `names`, or the first unknown name.
    pub fn indices(names: &[impl AsRef<str>]) -> Result<Vec<usize>, String> {
        names
            .iter()
            .map(|n| {
                let n = n.as_ref();
                COLUMNS
                    .iter()
                    .position(|c| *c == n)
                    .ok_or_else(|| format!("no column '{}'", crate::text::excerpt(n)))
            })
            .collect()
    }

    /// Envelopes of `groups` over rows `start..start + n`, in `buckets` buckets.
    pub fn new(groups: Vec<Vec<usize>>, start: usize, n: usize, buckets: usize) -> Overview {
        let mut columns: Vec<usize> = groups.iter().flatten().copied().collect();
        columns.sort_unstable();
        columns.dedup();
        let series = groups
            .iter()
            .map(|g| {
                g.iter()
                    .map(|c| columns.binary_search(c).expect("a column of the groups"))
                    .collect()
            })
            .collect();
        Overview {
            envelopes: M4::new(series, columns.len(), start, n, buckets),
            values: vec![0.0; columns.len() + 1],
            columns,
            groups,
            buckets: buckets.max(1),
        }
    }

    /// Feeds row `i`.
    #[inline]
    pub fn push(&mut self, i: usize, row: &Row) {
        let all = row.values();
        self.values[0] = row.t;
        for (v, &c) in self.values[1..].iter_mut().zip(&self.columns) {
            *v = all[c];
        }
        self.envelopes.push(i, &self.values);
    }

    /// The envelopes, per group [t, columns...].
    pub fn finish(self) -> Vec<Vec<Vec<f64>>> {
        self.envelopes.finish()
    }

    /// A copy of the envelopes so far.
    pub fn result(&self) -> Vec<Vec<Vec<f64>>> {
        self.envelopes.clone().finish()
    }
}

/// Checkpoints of a run (copies of its loop's state `S`, whatever that holds), and the rows it
/// has run.
#[derive(Clone, Debug)]
pub struct Trace<S> {
    /// The state before sample j·CHECKPOINT_EVERY, for each j reached.
    pub checkpoints: Vec<S>,
    /// Rows computed and checked so far.
    pub len: usize,
    /// The whole run's envelope, when asked for before the run started.
    pub overview: Option<Box<Overview>>,
    /// The stability report and what the start-up transient needs, tallied as the rows come, so
    /// that neither replays the whole run.
    pub stability: StabilityTally,
    /// See [`TransientTally`].
    pub transient: TransientTally,
    /// See [`WindowTally`]: none for a run longer than it keeps.
    pub window: Option<WindowTally>,
    /// One column of every row recorded, when asked for (the overlay of runs reads it instead of
    /// replaying them): filled by a replay of the rows so far, then as the run goes.
    pub column: Option<Column>,
}

/// The values of one column, row by row.
#[derive(Clone, Debug)]
pub struct Column {
    /// Its index in [`COLUMNS`].
    pub index: usize,
    /// Its value at each row so far.
    pub values: Vec<f64>,
}

impl<S: Clone> Trace<S> {
    /// A trace with room for the checkpoints of the `steps` samples of `scenario`.
    pub fn new(scenario: &Scenario, steps: usize) -> Trace<S> {
        Trace {
            checkpoints: Vec::with_capacity(steps.div_ceil(CHECKPOINT_EVERY)),
            len: 0,
            overview: None,
            stability: StabilityTally::new(scenario.gains, scenario.limit()),
            transient: TransientTally::new(steps, scenario.ts),
            window: WindowTally::new(scenario, steps),
            column: None,
        }
    }

    /// Keeps a copy of `st`, the state before sample `k`, when `k` starts a checkpoint interval;
    /// returns the first sample of the next interval.
    pub fn checkpoint(&mut self, k: usize, st: &S) -> usize {
        let j = k / CHECKPOINT_EVERY;
        if k % CHECKPOINT_EVERY == 0 && j == self.checkpoints.len() {
            self.checkpoints.push(st.clone());
        }
        (j + 1) * CHECKPOINT_EVERY
    }

    /// Bytes the trace holds.
    pub fn bytes(&self) -> usize {
        self.checkpoints.capacity() * std::mem::size_of::<S>()
            + self.transient.bytes()
            + self.window.as_ref().map_or(0, WindowTally::bytes)
            + self
                .column
                .as_ref()
                .map_or(0, |c| c.values.capacity() * std::mem::size_of::<f64>())
    }
}

impl<S> Sink for Trace<S> {
    #[inline]
    fn wants(&mut self) -> bool {
        true
    }

    #[inline]
    fn take(&mut self, row: &Row) -> Result<(), (&'static str, f64)> {
        finite(row)?;
        if let Some(o) = &mut self.overview {
            o.push(self.len, row);
        }
        self.stability.push(row);
        self.transient.push(self.len, row);
        if let Some(w) = &mut self.window {
            w.push(self.len, row);
        }
        if let Some(c) = &mut self.column {
            // Within the capacity reserved for the whole run: no allocation.
            c.values.push(row.get(c.index));
        }
        self.len += 1;
        Ok(())
    }
}
