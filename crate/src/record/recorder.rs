//! The rows of a run kept in memory: one `Row` per kept sample, preallocated so that the loop
//! never allocates.

#[cfg(test)]
use super::m4::m4;
use super::row::{finite, Row, Sink, COLUMNS};

/// The recorded trace: one `Row` per kept sample, so that recording is a single copy; sample k
/// of the run is kept when k is a multiple of `every`.
#[derive(Clone, Debug)]
pub struct Recorder {
    every: usize,
    /// Samples to skip before the next kept one (a countdown avoids a division per step).
    skip: usize,
    rows: Vec<Row>,
}

impl Recorder {
    /// Bytes one kept row takes.
    pub const ROW_BYTES: usize = std::mem::size_of::<Row>();

    /// A recorder with room for `rows` kept rows.
    pub fn with_capacity(rows: usize, every: usize) -> Recorder {
        Recorder {
            every,
            skip: 0,
            rows: Vec::with_capacity(rows),
        }
    }

    /// Records the next sample if it is kept (samples 0, every, 2·every, ...); `row` is only
    /// evaluated then. See [`Sink`].
    #[cfg(test)]
    pub fn record(&mut self, row: impl FnOnce() -> Row) -> Result<(), (&'static str, f64)> {
        if self.wants() {
            self.take(&row())
        } else {
            Ok(())
        }
    }

    /// Number of kept rows.
    pub fn len(&self) -> usize {
        self.rows.len()
    }

    /// Whether no row has been kept.
    pub fn is_empty(&self) -> bool {
        self.rows.is_empty()
    }

    fn index(name: &str) -> Option<usize> {
        COLUMNS.iter().position(|c| *c == name)
    }

    /// The recorded rows.
    pub fn rows(&self) -> &[Row] {
        &self.rows
    }

    /// A copy of the column named `name`, if there is one.
    pub fn column(&self, name: &str) -> Option<Vec<f64>> {
        let c = Self::index(name)?;
        Some(self.rows.iter().map(|r| r.values()[c]).collect())
    }

    /// M4 envelope (Jugel et al., VLDB 2014) of the named columns over rows with t in [t0, t1],
    /// for the tests of [`m4`] (runs read theirs with `Simulation::view`),
    /// in at most `buckets` buckets: see [`m4`]. Returns [t, col1, col2, ...]; every point is a
    /// recorded sample, so a line plot of it draws no edge the samples do not have.
    #[cfg(test)]
    pub fn envelope(
        &self,
        names: &[&str],
        t0: f64,
        t1: f64,
        buckets: usize,
    ) -> Option<Vec<Vec<f64>>> {
        let cols: Vec<usize> = names
            .iter()
            .map(|n| Self::index(n))
            .collect::<Option<_>>()?;
        let (start, end) = window(&self.rows, t0, t1);
        let rows = &self.rows;
        let series: Vec<Box<dyn Fn(usize) -> f64 + '_>> = cols
            .iter()
            .map(|&c| Box::new(move |i: usize| rows[i].values()[c]) as Box<dyn Fn(usize) -> f64>)
            .collect();
        let refs: Vec<&dyn Fn(usize) -> f64> = series.iter().map(|f| f.as_ref()).collect();
        Some(m4(|i| rows[i].t, &refs, start, end - start, buckets))
    }
}

impl Sink for Recorder {
    /// Samples 0, every, 2·every, ... are kept.
    #[inline]
    fn wants(&mut self) -> bool {
        let kept = self.skip == 0;
        if kept {
            self.skip = self.every;
        }
        self.skip -= 1;
        kept
    }

    /// Keeps `row`, or refuses it naming a column that is not finite. Never allocates within the
    /// capacity given.
    #[inline]
    fn take(&mut self, row: &Row) -> Result<(), (&'static str, f64)> {
        finite(row)?;
        self.rows.push(*row);
        Ok(())
    }
}

/// Row range of `rows` with t in [t0, t1].
#[cfg(test)]
fn window(rows: &[Row], t0: f64, t1: f64) -> (usize, usize) {
    let start = rows.partition_point(|r| r.t < t0);
    let end = rows.partition_point(|r| r.t <= t1).max(start);
    (start, end)
}

#[cfg(test)]
impl Recorder {
    /// Overlay of column `name` of this run and of `others` (recorded at the same sampling period),
    /// for the tests of [`m4`] (runs overlay with `Simulation::overlay`),
    /// with the differences this − other, over their common rows with t in [t0, t1]. Returns
    /// [t, this, others..., differences...] as one M4 envelope ([`m4`]).
    pub fn overlay(
        &self,
        others: &[&Recorder],
        name: &str,
        t0: f64,
        t1: f64,
        buckets: usize,
    ) -> Option<Vec<Vec<f64>>> {
        let c = Self::index(name)?;
        let rows = others.iter().map(|o| o.len()).fold(self.len(), usize::min);
        let common = &self.rows[..rows];
        let (start, end) = window(common, t0, t1);
        let value = |rec: &Recorder, i: usize| rec.rows[i].values()[c];
        let mut series: Vec<Box<dyn Fn(usize) -> f64 + '_>> =
            vec![Box::new(move |i| value(self, i))];
        for &o in others {
            series.push(Box::new(move |i| value(o, i)));
        }
        for &o in others {
            series.push(Box::new(move |i| value(self, i) - value(o, i)));
        }
        let refs: Vec<&dyn Fn(usize) -> f64> = series.iter().map(|f| f.as_ref()).collect();
        Some(m4(|i| self.rows[i].t, &refs, start, end - start, buckets))
    }
}

#[cfg(test)]
mod tests {
    use super::super::m4::{split, M4, M4_POINTS};
    use super::*;

    fn ramp_recorder(n: usize) -> Recorder {
        let mut r = Recorder::with_capacity(n, 1);
        for k in 0..n {
            let row = Row {
                t: k as f64,
                omega: if k == 37 { 100.0 } else { (k % 7) as f64 },
                ..Row::default()
            };
            r.record(|| row).unwrap();
        }
        r
    }

    #[test]
    fn overlay_differences_are_exact_sample_by_sample() {
        let a = ramp_recorder(1000);
        let mut b = Recorder::with_capacity(800, 1);
        for k in 0..800 {
            b.record(|| Row {
                t: k as f64,
                omega: 2.0 * k as f64,
                ..Row::default()
            })
            .unwrap();
        }
        // Few enough rows for no bucketing: the difference is a − b exactly, over the common 800 rows.
        let o = a.overlay(&[&b], "omega", 0.0, 1e9, 1000).unwrap();
        assert_eq!(o.len(), 4);
        assert_eq!(o[0].len(), 800);
        assert!((0..800).all(|k| o[3][k] == o[1][k] - o[2][k] && o[2][k] == 2.0 * k as f64));
        // Bucketed: the envelope of the difference keeps every sample's extreme difference.
        let e = a.overlay(&[&b], "omega", 0.0, 1e9, 10).unwrap();
        assert!(e[0].len() <= 10 * 8);
        let a_omega = a.column("omega").unwrap();
        let true_min = (0..800)
            .map(|k| a_omega[k] - 2.0 * k as f64)
            .fold(f64::INFINITY, f64::min);
        assert_eq!(e[3].iter().cloned().fold(f64::INFINITY, f64::min), true_min);
    }

    #[test]
    fn rows_with_a_value_that_is_not_finite_are_refused_naming_the_column() {
        let mut r = Recorder::with_capacity(2, 1);
        r.record(Row::default).unwrap();
        let bad = Row {
            v2s: f64::INFINITY,
            nis: f64::NAN,
            ..Row::default()
        };
        assert_eq!(r.record(|| bad), Err(("v2s", f64::INFINITY)));
        assert_eq!(r.len(), 1);
        // The bit test agrees with f64::is_finite at the edges, in any column.
        for v in [
            f64::MAX,
            -f64::MAX,
            f64::from_bits(1),
            -0.0,
            f64::NEG_INFINITY,
            f64::NAN,
        ] {
            let row = Row {
                p_omega: v,
                ..Row::default()
            };
            assert_eq!(row.is_finite(), v.is_finite(), "{v}");
            let row = Row {
                t: v,
                ..Row::default()
            };
            assert_eq!(row.is_finite(), v.is_finite(), "{v}");
        }
    }

    #[test]
    fn chunks_of_rows_concatenate_to_the_whole_csv() {
        // A run that keeps its rows, written through the one CSV writer.
        let s = crate::scenario::preset("decay").unwrap();
        let mut sim = crate::sim::Simulation::new(&s, 1).unwrap();
        sim.run().unwrap();
        assert_eq!(sim.len(), 400);
        let whole = sim.csv().into_bytes();
        assert_eq!(String::from_utf8_lossy(&whole).lines().count(), 401);
        let mut chunks = Vec::new();
        for start in (0..400).step_by(133) {
            sim.write_csv_rows(&mut chunks, start, 133).unwrap();
        }
        assert_eq!(chunks, whole);
        let mut past = Vec::new();
        sim.write_csv_rows(&mut past, 5000, 10).unwrap();
        assert!(past.is_empty());
    }

    #[test]
    fn header_starts_with_the_required_columns() {
        assert!(COLUMNS.join(",").starts_with(
            "t,omega_ref,omega,omega_hat,i_sa,i_sb,i_sa_hat,i_sb_hat,phi_ra,phi_rb,phi_ra_hat,phi_rb_hat,u_a,u_b,z1,z2,z3,z4"
        ));
    }

    #[test]
    fn envelope_keeps_extremes_at_their_own_times() {
        let r = ramp_recorder(1000);
        let env = r.envelope(&["omega"], 0.0, 1e9, 50).unwrap();
        // 20 rows a bucket; the extremes of omega = k mod 7 (and the spike at 37) are kept.
        let max = env[1].iter().cloned().fold(f64::NEG_INFINITY, f64::max);
        let min = env[1].iter().cloned().fold(f64::INFINITY, f64::min);
        assert_eq!((min, max), (0.0, 100.0));
        let spike = env[0].iter().position(|&t| t == 37.0).unwrap();
        assert_eq!(env[1][spike], 100.0);
        assert!(env[0].len() <= 4 * 50);
        // A window of at most four rows a bucket returns the raw samples.
        let win = r.envelope(&["omega"], 30.0, 40.0, 50).unwrap();
        assert_eq!(win[0], (30..=40).map(|k| k as f64).collect::<Vec<_>>());
        assert!(r.envelope(&["nope"], 0.0, 1.0, 10).is_none());
    }

    /// A falling edge inside one bucket: an envelope of (first t, min), (last t, max) would draw
    /// a rising sawtooth the samples do not have.
    #[test]
    fn a_falling_edge_stays_falling() {
        let mut r = Recorder::with_capacity(1000, 1);
        for k in 0..1000 {
            r.record(|| Row {
                t: k as f64,
                omega: -(k as f64),
                ..Row::default()
            })
            .unwrap();
        }
        let env = r.envelope(&["omega"], 0.0, 1e9, 10).unwrap();
        assert!(env[1].windows(2).all(|w| w[1] <= w[0]), "{:?}", env[1]);
    }

    #[cfg(not(target_arch = "wasm32"))]
    use proptest::prelude::*;

    /// M4 as its documentation states it, the slow way: per bucket and group, its first and last
    /// row and each series' first least and first greatest row, in row order without repeats.
    #[cfg(not(target_arch = "wasm32"))]
    fn m4_by_definition(
        rows: &[Vec<f64>],
        groups: &[Vec<usize>],
        buckets: usize,
    ) -> Vec<Vec<Vec<f64>>> {
        let n = rows.len();
        groups
            .iter()
            .map(|g| {
                let mut kept = Vec::new();
                if n <= M4_POINTS * buckets {
                    kept.extend(0..n);
                } else {
                    for b in 0..buckets {
                        let (lo, hi) = (split(b, n, buckets), split(b + 1, n, buckets));
                        let mut k = vec![lo, hi - 1];
                        for &s in g {
                            let v = |i: usize| rows[i][s + 1];
                            let first = |better: &dyn Fn(f64, f64) -> bool| {
                                (lo..hi).fold(lo, |at, i| if better(v(i), v(at)) { i } else { at })
                            };
                            k.push(first(&|a, b| a < b));
                            k.push(first(&|a, b| a > b));
                        }
                        k.sort_unstable();
                        k.dedup();
                        kept.extend(k);
                    }
                }
                let mut out = vec![kept.iter().map(|&i| rows[i][0]).collect::<Vec<f64>>()];
                out.extend(
                    g.iter()
                        .map(|&s| kept.iter().map(|&i| rows[i][s + 1]).collect()),
                );
                out
            })
            .collect()
    }

    #[cfg(not(target_arch = "wasm32"))]
    proptest! {
        /// M4 against its definition, with many ties (small integers) and one to nine series in
        /// groups that share some: the first of equal values is kept, whichever lane a series
        /// is found in.
        #[test]
        fn m4_equals_its_definition(
            series in 1usize..10,
            values in prop::collection::vec(0u8..4, 1..9000),
            buckets in 1usize..60,
            split_at in 0usize..10,
        ) {
            let rows: Vec<Vec<f64>> = values
                .chunks_exact(series)
                .enumerate()
                .map(|(i, c)| std::iter::once(i as f64).chain(c.iter().map(|&v| f64::from(v))).collect())
                .collect();
            prop_assume!(!rows.is_empty());
            let all: Vec<usize> = (0..series).collect();
            let cut = split_at.min(series);
            let groups = vec![all.clone(), all[cut..].to_vec(), all[..cut].iter().rev().copied().collect()];
            let mut m = M4::new(groups.clone(), series, 0, rows.len(), buckets);
            for (i, r) in rows.iter().enumerate() {
                m.push(i, r);
            }
            prop_assert_eq!(m.finish(), m4_by_definition(&rows, &groups, buckets));
        }

        /// For random traces, windows and bucket counts: every emitted (t, value) pair is a
        /// recorded sample, t never decreases, and each bucket keeps its samples' min and max.
        #[test]
        fn m4_emits_only_recorded_samples_and_keeps_bucket_extremes(
            values in prop::collection::vec((-1e3f64..1e3, -1e3f64..1e3), 1..3000),
            from in 0usize..3000,
            len in 0usize..3000,
            buckets in 1usize..400,
        ) {
            let mut r = Recorder::with_capacity(values.len(), 1);
            for (k, &(a, b)) in values.iter().enumerate() {
                r.record(|| Row { t: k as f64 * 5e-5, omega: a, z1: b, ..Row::default() }).unwrap();
            }
            let n = values.len();
            let start = from.min(n);
            let end = (start + len).min(n);
            let (t0, t1) = (start as f64 * 5e-5, if end > start { (end - 1) as f64 * 5e-5 } else { -1.0 });
            let env = r.envelope(&["omega", "z1"], t0, t1, buckets).unwrap();
            let index = |t: f64| {
                let k = r.rows().partition_point(|row| row.t < t);
                assert_eq!(r.rows()[k].t, t, "t = {t} is not a recorded time");
                k
            };
            for (j, &t) in env[0].iter().enumerate() {
                let k = index(t);
                prop_assert!(k >= start && k < end);
                prop_assert_eq!(env[1][j], values[k].0);
                prop_assert_eq!(env[2][j], values[k].1);
            }
            prop_assert!(env[0].windows(2).all(|w| w[0] < w[1]));
            let rows = end.saturating_sub(start);
            if rows > M4_POINTS * buckets {
                prop_assert!(env[0].len() <= 6 * buckets);
                for b in 0..buckets {
                    let (lo, hi) = (start + split(b, rows, buckets), start + split(b + 1, rows, buckets));
                    let inside: Vec<usize> = (0..env[0].len()).filter(|&j| (lo..hi).contains(&index(env[0][j]))).collect();
                    for (c, pick) in [(1, 0), (2, 1)] {
                        let field = |k: usize| if pick == 0 { values[k].0 } else { values[k].1 };
                        let min = (lo..hi).map(field).fold(f64::INFINITY, f64::min);
                        let max = (lo..hi).map(field).fold(f64::NEG_INFINITY, f64::max);
                        prop_assert_eq!(inside.iter().map(|&j| env[c][j]).fold(f64::INFINITY, f64::min), min);
                        prop_assert_eq!(inside.iter().map(|&j| env[c][j]).fold(f64::NEG_INFINITY, f64::max), max);
                    }
                }
            } else {
                prop_assert_eq!(env[0].len(), rows);
            }
        }
    }
}
