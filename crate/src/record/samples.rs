//! How the figures read a run's rows: in order, from memory or by replay.

use super::row::{first_not, Row};
use super::tally::TransientTally;
use super::window::WindowTally;

/// Recorded rows, read in order: a run's (from memory or by replay) or a hand-made trace's.
pub trait Samples {
    /// Number of rows.
    fn count(&self) -> usize;
    /// Time of row `i` (s).
    fn time(&self, i: usize) -> f64;
    /// Calls `f(i, row)` for rows `start..end` in order until it returns false.
    fn visit(&self, start: usize, end: usize, f: &mut dyn FnMut(usize, &Row) -> bool);

    /// What a traced run tallied for the transient as its rows came, if it did.
    fn tally(&self) -> Option<&TransientTally> {
        None
    }

    /// What a traced run kept of every row for the window figures as its rows came, if it did.
    fn window_tally(&self) -> Option<&WindowTally> {
        None
    }

    /// Row `i`.
    fn row(&self, i: usize) -> Row {
        let mut out = Row::default();
        self.visit(i, i + 1, &mut |_, r| {
            out = *r;
            false
        });
        out
    }

    /// The first row at or after time `t` (the number of rows if none is).
    fn first_at(&self, t: f64) -> usize {
        first_not(self.count(), |i| self.time(i) < t)
    }
}

/// Hand-made traces of the tests.
#[cfg(test)]
pub(crate) mod testing {
    use super::{Row, Samples};

    /// Sample period of the hand-made traces (s).
    pub const TS: f64 = 1e-3;

    /// `n` rows at times k·TS, each filled by `fill(k, row)`.
    pub fn trace(n: usize, fill: impl Fn(usize, &mut Row)) -> Vec<Row> {
        (0..n)
            .map(|k| {
                let mut r = Row {
                    t: k as f64 * TS,
                    ..Row::default()
                };
                fill(k, &mut r);
                r
            })
            .collect()
    }

    impl Samples for Vec<Row> {
        fn count(&self) -> usize {
            self.len()
        }
        fn time(&self, i: usize) -> f64 {
            self[i].t
        }
        fn visit(&self, start: usize, end: usize, f: &mut dyn FnMut(usize, &Row) -> bool) {
            for (i, row) in self.iter().enumerate().take(end).skip(start) {
                if !f(i, row) {
                    return;
                }
            }
        }
    }
}
