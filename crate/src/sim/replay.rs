//! Reading a run's rows back: from memory, or for a traced run by replaying the loop from the
//! checkpoint before them, bit for bit as the run computed them; the windows, envelopes and
//! overlays the page plots are read this way.

use super::closed_loop::{Loop, LoopState};
use super::{Recording, Simulation};
use crate::record::{
    first_not, Column, Overview, Row, Samples, Sink, Trace, TransientTally, WindowTally,
    CHECKPOINT_EVERY, M4,
};
use crate::scenario::ControllerKind;

impl Simulation {
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
    pub(super) fn cursor(&self, i: usize) -> Cursor<'_> {
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
            .map(|g| Overview::indices(g))
            .collect::<Result<Vec<_>, _>>()?;
        match &mut self.recording {
            Recording::Trace(t) if self.state.k == 0 => {
                t.overview = Some(Box::new(Overview::new(groups, 0, self.lp.steps, buckets)));
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
            .map(|g| Overview::indices(g))
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
        let mut overview = Overview::new(indices, start, end - start, buckets);
        self.visit(start, end, &mut |i, row| {
            overview.push(i, row);
            true
        });
        Ok(overview.finish())
    }

    /// The unknown terms d̃2 and d̃4 of steps 2 and 4 over the rows with t in [t0, t1], evaluated
    /// from the simulated truth at each sample (see [`crate::control::disturbances`]), as one M4
    /// envelope [t, d̃2, d̃4] in `buckets` buckets: a replay of the window. Errs for a run that
    /// keeps its rows (no replay) or a controller they are not evaluated for.
    pub fn disturbances(&self, t0: f64, t1: f64, buckets: usize) -> Result<Vec<Vec<f64>>, String> {
        if let Some(why) = self.lp.disturbances_refused() {
            return Err(why.to_string());
        }
        let Recording::Trace(_) = &self.recording else {
            return Err("d̃2 and d̃4 are evaluated by a replay of a traced run".to_string());
        };
        let (start, end) = self.window(t0, t1);
        let mut envelope = M4::new(vec![vec![0, 1]], 2, start, end - start, buckets);
        if start < end {
            let mut cursor = self.cursor(start);
            for i in start..end {
                let row = cursor.next_row();
                let [d2, d4] = self.lp.disturbances_at(&cursor.state, &row);
                envelope.push(i, &[row.t, d2, d4]);
            }
        }
        Ok(envelope.finish().pop().expect("one group"))
    }

    /// The residual of each step's designed dynamics, v_i − v_i,ref at the same signals (see
    /// [`crate::control::law`]), over the rows with t in [t0, t1], as one M4 envelope
    /// [t, r1, r2, r3, r4] in `buckets` buckets: a replay of the window. Errs for a run without
    /// own laws or one that keeps its rows (no replay).
    pub fn law_residuals(&self, t0: f64, t1: f64, buckets: usize) -> Result<Vec<Vec<f64>>, String> {
        if !self.lp.has_laws() {
            return Err("the scenario has no law of its own (law.v1..law.v4)".to_string());
        }
        let Recording::Trace(_) = &self.recording else {
            return Err(
                "the laws' residuals are evaluated by a replay of a traced run".to_string(),
            );
        };
        let (start, end) = self.window(t0, t1);
        let mut envelope = M4::new(vec![vec![0, 1, 2, 3]], 4, start, end - start, buckets);
        if start < end {
            let mut cursor = self.cursor(start);
            for i in start..end {
                let row = cursor.next_row();
                let [r1, r2, r3, r4] = self.lp.law_residuals();
                envelope.push(i, &[row.t, r1, r2, r3, r4]);
            }
        }
        Ok(envelope.finish().pop().expect("one group"))
    }

    /// Each step's error dynamics as the run made them, against those it is designed to give, over
    /// the rows with t in [t0, t1], as one M4 envelope [t, ż1, d1, ż2, d2, ż3, d3, ż4, d4] in
    /// `buckets` buckets: ż_i is z_i's change over the sample after t_k divided by Ts (at the run's
    /// last sample, over the sample before it), and d_i the
    /// designed rate at t_k, −k1·z1 + z2, −k2·z2 − z1, −k3·z3 + z4 and −k4·z4 − z3 (each with its
    /// robust term when the robust terms are on). Errs for the IFOC baseline, whose errors are not designed to any rate, and for a run that
    /// keeps its rows (no replay; its rows may be more than Ts apart).
    pub fn designed_dynamics(
        &self,
        t0: f64,
        t1: f64,
        buckets: usize,
    ) -> Result<Vec<Vec<f64>>, String> {
        let s = self.scenario();
        if s.controller != ControllerKind::Backstepping {
            return Err(
                "the designed error dynamics are the backstepping's: not for the IFOC baseline"
                    .to_string(),
            );
        }
        let Recording::Trace(_) = &self.recording else {
            return Err(
                "the designed error dynamics are evaluated by a replay of a traced run".to_string(),
            );
        };
        let g = &s.gains;
        let (k2, k4) = (g.designed_rate(2), g.designed_rate(4));
        let (start, end) = self.window(t0, t1);
        let mut envelope = M4::new(vec![(0..8).collect()], 8, start, end - start, buckets);
        // Row `k` (`r`) with its rate from `from` to `to`, `dt` apart.
        let mut push = |k: usize, r: &Row, from: &Row, to: &Row| {
            let rate = |a: f64, b: f64| (b - a) / (to.t - from.t);
            envelope.push(
                k,
                &[
                    r.t,
                    rate(from.z1, to.z1),
                    -g.k1 * r.z1 + r.z2,
                    rate(from.z2, to.z2),
                    -k2 * r.z2 - r.z1,
                    rate(from.z3, to.z3),
                    -g.k3 * r.z3 + r.z4,
                    rate(from.z4, to.z4),
                    -k4 * r.z4 - r.z3,
                ],
            );
        };
        // Each row with the next one, which its rate needs; the run's last row, which has none,
        // with the one before it.
        let mut seen: [Option<(usize, Row)>; 2] = [None, None];
        self.visit(start.saturating_sub(1), end + 1, &mut |i, row| {
            if let Some((k, r)) = seen[1].filter(|(k, _)| *k >= start) {
                push(k, &r, &r, row);
            }
            seen = [seen[1], Some((i, *row))];
            true
        });
        if let [Some((_, before)), Some((k, last))] = seen {
            if k + 1 == self.len() && (start..end).contains(&k) {
                push(k, &last, &before, &last);
            }
        }
        Ok(envelope.finish().pop().expect("one group"))
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
        let c = Overview::indices(&[name])?[0];
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
        let index = Overview::indices(&[name])?[0];
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
            trace.column = Some(Column { index, values });
        }
        Ok(())
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
pub(super) struct Cursor<'a> {
    lp: &'a Loop,
    pub(super) state: LoopState,
}

impl Cursor<'_> {
    /// The next row. The run recorded it, so it is computed again, bit for bit; a failure the
    /// run met just after recording its last row is met again after it and ignored here.
    pub(super) fn next_row(&mut self) -> Row {
        let mut capture = Capture {
            want: true,
            row: None,
        };
        let _ = self.lp.step(&mut self.state, &mut capture);
        self.state.k += 1;
        capture.row.expect("a replay of a recorded row")
    }
}

impl Samples for Simulation {
    fn count(&self) -> usize {
        self.len()
    }
    fn time(&self, i: usize) -> f64 {
        Simulation::time(self, i)
    }
    fn visit(&self, start: usize, end: usize, f: &mut dyn FnMut(usize, &Row) -> bool) {
        Simulation::visit(self, start, end, f);
    }
    fn tally(&self) -> Option<&TransientTally> {
        match &self.recording {
            Recording::Trace(t) => Some(&t.transient),
            Recording::Rows(_) => None,
        }
    }
    fn window_tally(&self) -> Option<&WindowTally> {
        match &self.recording {
            Recording::Trace(t) => t.window.as_ref(),
            Recording::Rows(_) => None,
        }
    }
}
