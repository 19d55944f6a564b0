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
    /// v1 (rad/s²).
    v1,
    /// v1a.
    v1a,
    /// v1s.
    v1s,
    /// v2 (rad/s³).
    v2,
    /// v2a.
    v2a,
    /// v2s.
    v2s,
    /// v3 (Wb²/s).
    v3,
    /// v3a.
    v3a,
    /// v3s.
    v3s,
    /// v4 (Wb²/s²).
    v4,
    /// v4a.
    v4a,
    /// v4s.
    v4s,
    /// ψ2.
    psi2,
    /// ψ3.
    psi3,
    /// ψ4.
    psi4,
    /// Commanded u_sa before saturation (V).
    u_a_cmd,
    /// Commanded u_sb before saturation (V).
    u_b_cmd,
    /// Speed estimate the controller used: x̂1 (EKF) for backstepping, the MRAS estimate for IFOC (rad/s).
    omega_used,
    /// Lyapunov function V = ½ Σ z_i².
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
    /// Normalised innovation squared.
    nis,
    /// Posterior speed variance P_11 ((rad/s)²).
    p_omega,
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
    /// evaluated then. Never allocates within the capacity given.
    #[inline]
    pub fn record(&mut self, row: impl FnOnce() -> Row) {
        if self.skip == 0 {
            self.rows.push(row());
            self.skip = self.every;
        }
        self.skip -= 1;
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

    /// The value of column `name` in kept row `i`.
    pub fn column_value(&self, i: usize, name: &str) -> Option<f64> {
        Some(self.rows.get(i)?.values()[Self::index(name)?])
    }

    /// A copy of the column named `name`, if there is one.
    pub fn column(&self, name: &str) -> Option<Vec<f64>> {
        let c = Self::index(name)?;
        Some(self.rows.iter().map(|r| r.values()[c]).collect())
    }

    /// Writes the header and every row as CSV (shortest round-trip number format).
    pub fn write_csv(&self, out: &mut impl std::io::Write) -> std::io::Result<()> {
        writeln!(out, "{}", COLUMNS.join(","))?;
        let mut line = String::with_capacity(NUM_COLUMNS * 24);
        for row in &self.rows {
            line.clear();
            for (i, v) in row.values().iter().enumerate() {
                if i > 0 {
                    line.push(',');
                }
                write!(line, "{v}").expect("writing to a String");
            }
            line.push('\n');
            out.write_all(line.as_bytes())?;
        }
        Ok(())
    }

    /// The whole trace as a CSV string.
    pub fn csv(&self) -> String {
        let mut buf = Vec::new();
        self.write_csv(&mut buf).expect("writing to a Vec");
        String::from_utf8(buf).expect("CSV is ASCII")
    }

    /// Min/max envelope of the named columns over rows with t in [t0, t1], in at most `buckets`
    /// buckets. Each bucket gives two points: (first t, min) and (last t, max), so a plot of the
    /// result shows every excursion of the full-rate trace. Returns [t, col1, col2, ...].
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
        let start = self.rows.partition_point(|r| r.t < t0);
        let end = self.rows.partition_point(|r| r.t <= t1).max(start);
        let window = &self.rows[start..end];
        let n = window.len();
        let buckets = buckets.max(1);
        let mut out: Vec<Vec<f64>> = vec![Vec::with_capacity(2 * buckets.min(n)); cols.len() + 1];
        if n <= 2 * buckets {
            for r in window {
                let v = r.values();
                out[0].push(r.t);
                for (o, &c) in out[1..].iter_mut().zip(&cols) {
                    o.push(v[c]);
                }
            }
            return Some(out);
        }
        let mut lo = vec![f64::INFINITY; cols.len()];
        let mut hi = vec![f64::NEG_INFINITY; cols.len()];
        for b in 0..buckets {
            let bucket = &window[split(b, n, buckets)..split(b + 1, n, buckets)];
            out[0].push(bucket[0].t);
            out[0].push(bucket[bucket.len() - 1].t);
            lo.fill(f64::INFINITY);
            hi.fill(f64::NEG_INFINITY);
            for r in bucket {
                let v = r.values();
                for (k, &c) in cols.iter().enumerate() {
                    lo[k] = lo[k].min(v[c]);
                    hi[k] = hi[k].max(v[c]);
                }
            }
            for (k, o) in out[1..].iter_mut().enumerate() {
                o.push(lo[k]);
                o.push(hi[k]);
            }
        }
        Some(out)
    }
}

/// Start of bucket `b` of `buckets` over `n` rows: b·n/buckets in 64 bits (on wasm32 the product
/// of a large trace and a wide plot overflows usize).
fn split(b: usize, n: usize, buckets: usize) -> usize {
    (b as u64 * n as u64 / buckets as u64) as usize
}

/// Min/max envelopes of `series` (functions of the row index) over rows `start..start + n`, as
/// [t, series...] with two points per bucket, like [`Recorder::envelope`].
fn bucketed(
    t: impl Fn(usize) -> f64,
    series: &[&dyn Fn(usize) -> f64],
    start: usize,
    n: usize,
    buckets: usize,
) -> Vec<Vec<f64>> {
    let buckets = buckets.max(1);
    let mut out: Vec<Vec<f64>> = vec![Vec::with_capacity(2 * buckets.min(n)); series.len() + 1];
    if n <= 2 * buckets {
        for i in start..start + n {
            out[0].push(t(i));
            for (o, f) in out[1..].iter_mut().zip(series) {
                o.push(f(i));
            }
        }
        return out;
    }
    for b in 0..buckets {
        let (lo, hi) = (
            start + split(b, n, buckets),
            start + split(b + 1, n, buckets),
        );
        out[0].push(t(lo));
        out[0].push(t(hi - 1));
        for (o, f) in out[1..].iter_mut().zip(series) {
            let (mn, mx) = (lo..hi)
                .map(f)
                .fold((f64::INFINITY, f64::NEG_INFINITY), |(a, b), v| {
                    (a.min(v), b.max(v))
                });
            o.push(mn);
            o.push(mx);
        }
    }
    out
}

impl Recorder {
    /// Overlay of column `name` of this run and of `others` (recorded at the same sampling period),
    /// with the differences this − other, over their common rows with t in [t0, t1]. Returns
    /// [t, this, others..., differences...] as min/max envelopes.
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
        let start = common.partition_point(|r| r.t < t0);
        let end = common.partition_point(|r| r.t <= t1).max(start);
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
        Some(bucketed(
            |i| self.rows[i].t,
            &refs,
            start,
            end - start,
            buckets,
        ))
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
            r.record(|| row);
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
            });
        }
        // Few enough rows for no bucketing: the difference is a − b exactly, over the common 800 rows.
        let o = a.overlay(&[&b], "omega", 0.0, 1e9, 1000).unwrap();
        assert_eq!(o.len(), 4);
        assert_eq!(o[0].len(), 800);
        assert!((0..800).all(|k| o[3][k] == o[1][k] - o[2][k] && o[2][k] == 2.0 * k as f64));
        // Bucketed: the envelope of the difference brackets every sample's difference.
        let e = a.overlay(&[&b], "omega", 0.0, 1e9, 10).unwrap();
        assert_eq!(e[0].len(), 20);
        let a_omega = a.column("omega").unwrap();
        let true_min = (0..800)
            .map(|k| a_omega[k] - 2.0 * k as f64)
            .fold(f64::INFINITY, f64::min);
        assert_eq!(e[3].iter().cloned().fold(f64::INFINITY, f64::min), true_min);
    }

    #[test]
    fn header_starts_with_the_required_columns() {
        assert!(COLUMNS.join(",").starts_with(
            "t,omega_ref,omega,omega_hat,i_sa,i_sb,i_sa_hat,i_sb_hat,phi_ra,phi_rb,phi_ra_hat,phi_rb_hat,u_a,u_b,z1,z2,z3,z4"
        ));
    }

    #[test]
    fn envelope_keeps_extremes_and_bucket_count() {
        let r = ramp_recorder(1000);
        let env = r.envelope(&["omega"], 0.0, 1e9, 50).unwrap();
        assert_eq!(env[0].len(), 100);
        let max = env[1].iter().cloned().fold(f64::NEG_INFINITY, f64::max);
        let min = env[1].iter().cloned().fold(f64::INFINITY, f64::min);
        assert_eq!((min, max), (0.0, 100.0));
        // A window narrower than the bucket count returns the raw samples.
        let win = r.envelope(&["omega"], 30.0, 40.0, 50).unwrap();
        assert_eq!(win[0], (30..=40).map(|k| k as f64).collect::<Vec<_>>());
        assert!(r.envelope(&["nope"], 0.0, 1.0, 10).is_none());
    }
}
