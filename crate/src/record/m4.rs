//! M4 envelopes (Jugel et al., VLDB 2014) for plots: per bucket of rows, the first, last,
//! least and greatest sample of each series, so that a line plot of a few thousand points draws
//! every edge the samples have and none they lack.

/// Start of bucket `b` of `buckets` over `n` rows: b·n/buckets in 64 bits (on wasm32 the product
/// of a large trace and a wide plot overflows usize).
pub(super) fn split(b: usize, n: usize, buckets: usize) -> usize {
    (b as u64 * n as u64 / buckets as u64) as usize
}

/// Rows per bucket up to which a window is sent whole: M4 keeps up to four per bucket anyway.
pub(super) const M4_POINTS: usize = 4;

/// M4 envelope of `series` (functions of the row index) over rows `start..start + n`, as
/// [t, series...]: see [`M4`], which it feeds row by row.
pub fn m4(
    t: impl Fn(usize) -> f64,
    series: &[&dyn Fn(usize) -> f64],
    start: usize,
    n: usize,
    buckets: usize,
) -> Vec<Vec<f64>> {
    let mut m = M4::new(
        vec![(0..series.len()).collect()],
        series.len(),
        start,
        n,
        buckets,
    );
    let mut values = vec![0.0; series.len() + 1];
    for i in start..start + n {
        values[0] = t(i);
        for (v, f) in values[1..].iter_mut().zip(series) {
            *v = f(i);
        }
        m.push(i, &values);
    }
    m.finish().pop().expect("one group")
}

/// M4 envelopes (Jugel et al., VLDB 2014) of groups of series over a window of rows
/// `start..start + n`, fed in row order one row at a time, so that a window can be enveloped
/// while it is computed (by the run itself, or by a replay) without holding its rows.
///
/// The rows are split into `buckets` equal buckets; for each group, each bucket keeps its first
/// and last row and, for every series of the group, the row of its minimum and of its maximum
/// (the first such row on ties), in row order and without repeats. Every series of a group is
/// given at every row the group keeps, so each emitted (t, value) pair is a recorded sample, t
/// never decreases, and each bucket keeps the extremes of every series at their own times.
/// Windows of at most four rows per bucket are returned whole. Each series' extremes are found
/// once, however many groups it is in. Allocates only in [`M4::new`].
#[derive(Clone, Debug)]
pub struct M4 {
    start: usize,
    n: usize,
    buckets: usize,
    whole: bool,
    /// Values per row: t and the series.
    width: usize,
    /// Series indices (0-based) of each group.
    groups: Vec<Vec<usize>>,
    /// Current bucket and its rows lo..hi.
    bucket: usize,
    lo: usize,
    hi: usize,
    /// The current bucket's rows so far, one after the other: value c of the row at offset o in
    /// the bucket is at o·width + c.
    rows: Vec<f64>,
    /// Per series, the offset in the bucket of its minimum and of its maximum (the first of
    /// equal values), found when the bucket is complete.
    min_at: Vec<usize>,
    max_at: Vec<usize>,
    kept: Vec<usize>,
    /// Per group, [t, its series...].
    out: Vec<Vec<Vec<f64>>>,
}

impl M4 {
    /// Envelopes of `groups` (each a list of series indices below `series`) over rows
    /// `start..start + n` in at most `buckets` buckets.
    pub fn new(
        groups: Vec<Vec<usize>>,
        series: usize,
        start: usize,
        n: usize,
        buckets: usize,
    ) -> M4 {
        let buckets = buckets.max(1);
        let whole = n <= M4_POINTS.saturating_mul(buckets);
        let per_bucket = n / buckets + 1;
        let width = series + 1;
        let out = groups
            .iter()
            .map(|g| {
                let capacity = if whole {
                    n
                } else {
                    buckets * (2 + 2 * g.len()).min(per_bucket)
                };
                // Each its own capacity (`vec![v; n]` clones, and a clone drops the capacity).
                (0..=g.len())
                    .map(|_| Vec::with_capacity(capacity))
                    .collect()
            })
            .collect();
        let widest = groups.iter().map(Vec::len).max().unwrap_or(0);
        let mut m = M4 {
            start,
            n,
            buckets,
            whole,
            width,
            groups,
            bucket: 0,
            lo: start,
            hi: start,
            rows: if whole {
                Vec::new()
            } else {
                vec![0.0; per_bucket * width]
            },
            min_at: vec![0; series],
            max_at: vec![0; series],
            kept: Vec::with_capacity(2 + 2 * widest),
            out,
        };
        m.hi = m.bucket_end(0);
        m
    }

    /// First row after bucket `b`.
    fn bucket_end(&self, b: usize) -> usize {
        self.start + split(b + 1, self.n, self.buckets)
    }

    /// Feeds row `i` (the rows of the window in order): `values` is [t, series...].
    pub fn push(&mut self, i: usize, values: &[f64]) {
        debug_assert_eq!(values.len(), self.width);
        if self.whole {
            for (g, out) in self.groups.iter().zip(&mut self.out) {
                out[0].push(values[0]);
                for (o, &s) in out[1..].iter_mut().zip(g) {
                    o.push(values[s + 1]);
                }
            }
            return;
        }
        let (width, offset) = (self.width, i - self.lo);
        self.rows[offset * width..(offset + 1) * width].copy_from_slice(values);
        if i + 1 == self.hi {
            // The bucket is complete. Each series' extremes (the first of equal values), with
            // selects rather than branches: which sample is an extreme is unpredictable.
            let len = offset + 1;
            // Four columns at a time: four independent chains of selects overlap (more spill
            // the registers on x86-64).
            const LANES: usize = 4;
            let series = self.min_at.len();
            let rows = &self.rows;
            for first in (0..series).step_by(LANES) {
                let lanes = LANES.min(series - first);
                let at = |l: usize, j: usize| rows[j * width + 1 + first + l];
                let (mut min, mut max) = ([0.0; LANES], [0.0; LANES]);
                let (mut min_at, mut max_at) = ([0; LANES], [0; LANES]);
                for l in 0..lanes {
                    (min[l], max[l]) = (at(l, 0), at(l, 0));
                }
                for j in 1..len {
                    for l in 0..lanes {
                        let v = at(l, j);
                        let (lower, higher) = (v < min[l], v > max[l]);
                        min[l] = if lower { v } else { min[l] };
                        min_at[l] = if lower { j } else { min_at[l] };
                        max[l] = if higher { v } else { max[l] };
                        max_at[l] = if higher { j } else { max_at[l] };
                    }
                }
                self.min_at[first..first + lanes].copy_from_slice(&min_at[..lanes]);
                self.max_at[first..first + lanes].copy_from_slice(&max_at[..lanes]);
            }
            // Per group, its kept rows in row order, each once.
            for (g, out) in self.groups.iter().zip(&mut self.out) {
                self.kept.clear();
                self.kept.extend([0, offset]);
                for &s in g {
                    self.kept.extend([self.min_at[s], self.max_at[s]]);
                }
                self.kept.sort_unstable();
                self.kept.dedup();
                for &k in &self.kept {
                    out[0].push(self.rows[k * width]);
                    for (o, &s) in out[1..].iter_mut().zip(g) {
                        o.push(self.rows[k * width + s + 1]);
                    }
                }
            }
            self.bucket += 1;
            self.lo = self.hi;
            if self.bucket < self.buckets {
                self.hi = self.bucket_end(self.bucket);
            }
        }
    }

    /// The envelopes, per group [t, its series...]: rows not fed are missing from them.
    pub fn finish(self) -> Vec<Vec<Vec<f64>>> {
        self.out
    }
}
