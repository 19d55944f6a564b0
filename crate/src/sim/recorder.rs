//! The recorded trace: one column per signal, preallocated so the loop never allocates,
//! plus CSV export and min/max-envelope decimation for plots.

use std::fmt::Write;

macro_rules! define_row {
    ($($(#[doc = $doc:literal])* $name:ident),* $(,)?) => {
        /// One recorded sample; field names are the CSV column names.
        #[derive(Clone, Copy, Debug, Default)]
        pub struct Row {
            $($(#[doc = $doc])* pub $name: f64,)*
        }

        /// Column names in CSV order.
        pub const COLUMNS: &[&str] = &[$(stringify!($name)),*];

        /// What each column is, with its unit, in CSV order (the field docs).
        pub const COLUMN_DOCS: &[&str] = &[$(concat!($($doc),*).trim_ascii()),*];

        /// Number of columns.
        pub const NUM_COLUMNS: usize = COLUMNS.len();

        impl Row {
            /// The values in CSV order.
            pub fn values(&self) -> [f64; NUM_COLUMNS] {
                [$(self.$name),*]
            }

            /// The value of column `i` (in CSV order); panics past the last column.
            #[inline]
            pub fn get(&self, i: usize) -> f64 {
                const FIELDS: &[fn(&Row) -> f64] = &[$(|r| r.$name),*];
                FIELDS[i](self)
            }

            /// Whether every value is finite. Straight-line bit operations with no early exit:
            /// an exponent of all ones (inf or NaN) plus one carries into the sign bit.
            #[inline]
            pub fn is_finite(&self) -> bool {
                const EXPONENT: u64 = 0x7ff0_0000_0000_0000;
                let mut carry = 0u64;
                $(carry |= (self.$name.to_bits() & EXPONENT).wrapping_add(1 << 52);)*
                carry >> 63 == 0
            }
        }
    };
}

define_row! {
    /// Time t_k (s).
    t,
    /// Speed reference ω_d (rad/s).
    omega_ref,
    /// True speed ω = x1 (rad/s).
    omega,
    /// Posterior speed estimate x̂1 (rad/s).
    omega_hat,
    /// True stator current i_sa (A).
    i_sa,
    /// True stator current i_sb (A).
    i_sb,
    /// Posterior estimate of i_sa (A).
    i_sa_hat,
    /// Posterior estimate of i_sb (A).
    i_sb_hat,
    /// True rotor flux φ_ra (Wb).
    phi_ra,
    /// True rotor flux φ_rb (Wb).
    phi_rb,
    /// Posterior estimate of φ_ra (Wb).
    phi_ra_hat,
    /// Posterior estimate of φ_rb (Wb).
    phi_rb_hat,
    /// Applied voltage u_sa after saturation (V).
    u_a,
    /// Applied voltage u_sb after saturation (V).
    u_b,
    /// Speed error z1 (rad/s).
    z1,
    /// Torque error z2 (rad/s²).
    z2,
    /// Flux error z3 (Wb²).
    z3,
    /// Flux-derivative error z4 (Wb²/s).
    z4,
    /// Measured current y_a (A).
    y_a,
    /// Measured current y_b (A).
    y_b,
    /// True rotor-flux modulus |φ_r| (Wb).
    flux,
    /// Estimated rotor-flux modulus (x̂4² + x̂5²)^½ (Wb).
    flux_hat,
    /// Target flux modulus ψ_d^½ (Wb).
    flux_ref,
    /// Speed tracking error ω − ω_d (rad/s).
    omega_err,
    /// Speed estimation error ω − ω̂ (rad/s).
    omega_est_err,
    /// Flux-modulus estimation error |φ_r| − |φ̂_r| (Wb).
    flux_est_err,
    /// Estimated flux modulus squared x̂4² + x̂5², regulated by step 3 (Wb²).
    flux_sq_hat,
    /// Estimated torque term a1(x3·x̂4 − x2·x̂5) (rad/s²).
    torque_hat,
    /// Virtual control v1 = v1a + v1s, eq (26): the torque term step 1 asks for (rad/s²).
    v1,
    /// Feedforward part v1a of v1, eq (27) (rad/s²).
    v1a,
    /// Feedback part v1s = −k1s1·z1 of v1, eq (28) (rad/s²).
    v1s,
    /// Input v2 = v2a + v2s of step 2, eq (34) (rad/s³).
    v2,
    /// Feedforward part v2a = −ψ2 − z1 of v2, eq (35) (rad/s³).
    v2a,
    /// Feedback part v2s = v2s1 + v2s2 of v2, eq (36) (rad/s³).
    v2s,
    /// Virtual control v3 = v3a + v3s of step 3, eq (45) (Wb²/s).
    v3,
    /// Feedforward part v3a = −ψ3 of v3 (Wb²/s).
    v3a,
    /// Feedback part v3s = −k3·z3 of v3 (Wb²/s).
    v3s,
    /// Input v4 = v4a + v4s of step 4, eq (49) (Wb²/s²).
    v4,
    /// Feedforward part v4a = −ψ4 − z3 of v4, eq (50) (Wb²/s²).
    v4a,
    /// Feedback part v4s = v4s1 + v4s2 of v4, eq (51) (Wb²/s²).
    v4s,
    /// Known part ψ2 of ż2, eq (33) (rad/s³).
    psi2,
    /// Known part ψ3 of ż3, eq (43) (Wb²/s).
    psi3,
    /// Known part ψ4 of ż4, eq (47) (Wb²/s²).
    psi4,
    /// Commanded u_sa before saturation (V).
    u_a_cmd,
    /// Commanded u_sb before saturation (V).
    u_b_cmd,
    /// Speed estimate the controller used: x̂1 (EKF) for backstepping, the MRAS estimate for IFOC (rad/s).
    omega_used,
    /// Lyapunov function V = ½ Σ z_i² (mixed units).
    lyapunov,
    /// Innovation ỹ_a (A).
    innov_a,
    /// Innovation ỹ_b (A).
    innov_b,
    /// 2σ band of the innovation ỹ_a: 2·S_aa^½ (A).
    innov_band_a,
    /// 2σ band of the innovation ỹ_b: 2·S_bb^½ (A).
    innov_band_b,
    /// Innovation covariance S_aa (A²).
    s_aa,
    /// Innovation covariance S_ab (A²).
    s_ab,
    /// Innovation covariance S_bb (A²).
    s_bb,
    /// Normalised innovation squared ỹᵀS⁻¹ỹ (dimensionless).
    nis,
    /// Posterior speed variance P_11 ((rad/s)²).
    p_omega,
    /// Estimated constant load torque â2·J (N m); the model's T0 when the load is not estimated.
    load_hat,
    /// Estimated rotor resistance R̂_r (Ω); the model's R_r when it is not estimated.
    rr_hat,
    /// True constant load torque T0 plus the unknown step (N m).
    load,
    /// 2σ band of the load-torque estimate from P (N m); 0 when the load is not estimated.
    load_band,
    /// True rotor resistance R_r of the plant (Ω).
    rr,
    /// 2σ band of the rotor-resistance estimate from P (Ω); 0 when it is not estimated.
    rr_band,
    /// PWM current ripple over [t_k, t_k + Ts): the largest distance of i_s at a switching
    /// instant from the straight line between its values at t_k and t_k + Ts (A); 0 without PWM.
    i_ripple,
}

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
    /// evaluated then. See [`super::Sink`].
    #[cfg(test)]
    pub fn record(&mut self, row: impl FnOnce() -> Row) -> Result<(), (&'static str, f64)> {
        use super::Sink;
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

/// A visitor of rows in order: it returns false to stop.
pub(super) type RowVisitor<'a> = dyn FnMut(&Row) -> bool + 'a;

/// Writes the rows that `rows` gives (it calls its argument with each, in order, until that
/// returns false) as CSV lines, preceded by the header when they start at row 0 (shortest
/// round-trip number format).
pub(super) fn write_csv(
    out: &mut impl std::io::Write,
    start: usize,
    rows: &mut dyn FnMut(&mut RowVisitor<'_>),
) -> std::io::Result<()> {
    if start == 0 {
        writeln!(out, "{}", COLUMNS.join(","))?;
    }
    let mut line = String::with_capacity(NUM_COLUMNS * 24);
    let mut result = Ok(());
    rows(&mut |row| {
        line.clear();
        for (i, v) in row.values().iter().enumerate() {
            if i > 0 {
                line.push(',');
            }
            write!(line, "{v}").expect("writing to a String");
        }
        line.push('\n');
        result = out.write_all(line.as_bytes());
        result.is_ok()
    });
    result
}

/// `Ok` when every value of `row` is finite; otherwise the first column that is not, and its
/// value, so that a trace holds finite numbers only.
#[inline]
pub(super) fn finite(row: &Row) -> Result<(), (&'static str, f64)> {
    if row.is_finite() {
        return Ok(());
    }
    let values = row.values();
    let i = values
        .iter()
        .position(|v| !v.is_finite())
        .expect("one is not finite");
    Err((COLUMNS[i], values[i]))
}

impl super::Sink for Recorder {
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

/// Start of bucket `b` of `buckets` over `n` rows: b·n/buckets in 64 bits (on wasm32 the product
/// of a large trace and a wide plot overflows usize).
fn split(b: usize, n: usize, buckets: usize) -> usize {
    (b as u64 * n as u64 / buckets as u64) as usize
}

/// Rows per bucket up to which a window is sent whole: M4 keeps up to four per bucket anyway.
const M4_POINTS: usize = 4;

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
        let mut sim = super::super::Simulation::new(&s, 1).unwrap();
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
