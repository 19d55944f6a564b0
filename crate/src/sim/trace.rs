//! The trace of a run as checkpoints: a copy of the loop's state every [`CHECKPOINT_EVERY`]
//! samples, from which any window of rows is computed again, bit for bit, by replay. The run
//! checks every row it computes (finite values only) and can feed an M4 overview of the whole
//! run as it goes, so that the first plot needs no replay.

use super::recorder::{finite, M4};
use super::{first_not, LoopState, Row, Sink, StabilityTally, COLUMNS};
use crate::scenario::Scenario;

/// Samples between checkpoints: a replay starts at most this many samples before the first row
/// it is asked for (about 0.1 s at 20 kHz, under a millisecond of computing).
pub const CHECKPOINT_EVERY: usize = 2048;

/// M4 envelopes of groups of columns over a window of rows, fed row by row: while the run goes
/// (the overview of the whole run) or by a replay.
#[derive(Clone, Debug)]
pub(super) struct Overview {
    /// Column indices per group.
    pub(super) groups: Vec<Vec<usize>>,
    pub(super) buckets: usize,
    /// The distinct columns of the groups.
    columns: Vec<usize>,
    envelopes: M4,
    /// [t, columns...] of the current row.
    values: Vec<f64>,
}

impl Overview {
    /// Column indices of `names`, or the first unknown name.
    pub(super) fn indices(names: &[impl AsRef<str>]) -> Result<Vec<usize>, String> {
        names
            .iter()
            .map(|n| {
                let n = n.as_ref();
                COLUMNS
                    .iter()
                    .position(|c| *c == n)
                    .ok_or_else(|| format!("no column '{}'", crate::quote::excerpt(n)))
            })
            .collect()
    }

    pub(super) fn new(groups: Vec<Vec<usize>>, start: usize, n: usize, buckets: usize) -> Overview {
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
    pub(super) fn push(&mut self, i: usize, row: &Row) {
        let all = row.values();
        self.values[0] = row.t;
        for (v, &c) in self.values[1..].iter_mut().zip(&self.columns) {
            *v = all[c];
        }
        self.envelopes.push(i, &self.values);
    }

    /// The envelopes, per group [t, columns...].
    pub(super) fn finish(self) -> Vec<Vec<Vec<f64>>> {
        self.envelopes.finish()
    }

    /// A copy of the envelopes so far.
    pub(super) fn result(&self) -> Vec<Vec<Vec<f64>>> {
        self.envelopes.clone().finish()
    }
}

/// Checkpoints of a run, and the rows it has run.
#[derive(Clone, Debug)]
pub(super) struct Trace {
    /// The state before sample j·CHECKPOINT_EVERY, for each j reached.
    pub(super) checkpoints: Vec<LoopState>,
    /// Rows computed and checked so far.
    pub(super) len: usize,
    /// The whole run's envelope, when asked for before the run started.
    pub(super) overview: Option<Box<Overview>>,
    /// The stability report and what the start-up transient needs, tallied as the rows come, so
    /// that neither replays the whole run.
    pub(super) stability: StabilityTally,
    pub(super) transient: TransientTally,
    /// One column of every row recorded, when asked for (the overlay of runs reads it instead of
    /// replaying them): filled by a replay of the rows so far, then as the run goes.
    pub(super) column: Option<Column>,
}

/// The values of one column, row by row.
#[derive(Clone, Debug)]
pub(super) struct Column {
    /// Its index in [`COLUMNS`].
    pub(super) index: usize,
    pub(super) values: Vec<f64>,
}

impl Trace {
    /// A trace with room for the checkpoints of the `steps` samples of `scenario`.
    pub(super) fn new(scenario: &Scenario, steps: usize) -> Trace {
        Trace {
            checkpoints: Vec::with_capacity(steps.div_ceil(CHECKPOINT_EVERY)),
            len: 0,
            overview: None,
            stability: StabilityTally::new(scenario.gains, scenario.limit()),
            transient: TransientTally::new(steps, scenario.ts),
            column: None,
        }
    }

    /// Keeps a copy of `st` when its next sample starts a checkpoint interval; returns the first
    /// sample of the next interval.
    pub(super) fn checkpoint(&mut self, st: &LoopState) -> usize {
        let j = st.k / CHECKPOINT_EVERY;
        if st.k % CHECKPOINT_EVERY == 0 && j == self.checkpoints.len() {
            self.checkpoints.push(st.clone());
        }
        (j + 1) * CHECKPOINT_EVERY
    }

    /// Bytes the trace holds.
    pub(super) fn bytes(&self) -> usize {
        self.checkpoints.capacity() * std::mem::size_of::<LoopState>()
            + self.transient.bytes()
            + self
                .column
                .as_ref()
                .map_or(0, |c| c.values.capacity() * std::mem::size_of::<f64>())
    }
}

impl Sink for Trace {
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
        if let Some(c) = &mut self.column {
            // Within the capacity reserved for the whole run: no allocation.
            c.values.push(row.get(c.index));
        }
        self.len += 1;
        Ok(())
    }
}

/// What the transient (`figures::transient`) reads from every row, gathered by a traced run as its rows come: per
/// interval of [`CHECKPOINT_EVERY`] rows the least and the greatest innovation band, and the sum
/// of the NIS over the second half of the run as planned (from −0, in row order, as the
/// transient sums it). A run that ends early has another second half; the transient then
/// reads the rows again.
#[derive(Clone, Debug)]
pub(super) struct TransientTally {
    pub(super) band: Vec<(f64, f64)>,
    pub(super) half_index: usize,
    pub(super) late_sum: f64,
}

impl TransientTally {
    /// For a run of `steps` samples of `ts` (row k at time k·ts).
    pub(super) fn new(steps: usize, ts: f64) -> TransientTally {
        let last = steps.saturating_sub(1);
        // `transient`'s half of a run whose rows are 0..steps, at times k·ts.
        let half = 0.0 + 0.5 * (last as f64 * ts - 0.0);
        TransientTally {
            band: Vec::with_capacity(steps.div_ceil(CHECKPOINT_EVERY)),
            half_index: first_not(steps, |k| (k as f64 * ts) < half).min(last),
            late_sum: -0.0,
        }
    }

    /// Takes row `i`, the rows coming in order from 0.
    #[inline]
    pub(super) fn push(&mut self, i: usize, r: &Row) {
        let band = r.innov_band_a;
        if i % CHECKPOINT_EVERY == 0 {
            self.band.push((band, band));
        } else if let Some((lo, hi)) = self.band.last_mut() {
            *lo = if band < *lo { band } else { *lo };
            *hi = if band > *hi { band } else { *hi };
        }
        if i >= self.half_index {
            self.late_sum += r.nis;
        }
    }

    /// Bytes it holds.
    pub(super) fn bytes(&self) -> usize {
        self.band.capacity() * std::mem::size_of::<(f64, f64)>()
    }
}
