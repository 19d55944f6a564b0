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

        /// Number of columns.
        pub const NUM_COLUMNS: usize = COLUMNS.len();

        impl Row {
            fn values(&self) -> [f64; NUM_COLUMNS] {
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
    /// True flux modulus squared φ_ra² + φ_rb² (Wb²).
    flux_sq,
    /// Estimated flux modulus squared x̂4² + x̂5² (Wb²).
    flux_sq_hat,
    /// Flux target ψ_d (Wb²).
    psi_d,
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
    /// Lyapunov function V = ½ Σ z_i².
    lyapunov,
    /// Innovation ỹ_a (A).
    innov_a,
    /// Innovation ỹ_b (A).
    innov_b,
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
    /// Kalman gain K_11.
    k11,
    /// K_12.
    k12,
    /// K_21.
    k21,
    /// K_22.
    k22,
    /// K_31.
    k31,
    /// K_32.
    k32,
    /// K_41.
    k41,
    /// K_42.
    k42,
    /// K_51.
    k51,
    /// K_52.
    k52,
}

/// Recorded columns; row k of the run is kept when k is a multiple of `every`.
#[derive(Clone, Debug)]
pub struct Recorder {
    every: usize,
    columns: Vec<Vec<f64>>,
}

impl Recorder {
    /// Bytes one kept row takes.
    pub const ROW_BYTES: usize = NUM_COLUMNS * std::mem::size_of::<f64>();

    /// A recorder with room for `rows` kept rows.
    pub fn with_capacity(rows: usize, every: usize) -> Recorder {
        Recorder {
            every,
            columns: (0..NUM_COLUMNS).map(|_| Vec::with_capacity(rows)).collect(),
        }
    }

    /// Records step `k` if it is kept. Never allocates within the capacity given.
    #[inline]
    pub fn record(&mut self, k: usize, row: &Row) {
        if k % self.every == 0 {
            for (col, v) in self.columns.iter_mut().zip(row.values()) {
                col.push(v);
            }
        }
    }

    /// Number of kept rows.
    pub fn len(&self) -> usize {
        self.columns[0].len()
    }

    /// Whether no row has been kept.
    pub fn is_empty(&self) -> bool {
        self.len() == 0
    }

    /// The column named `name`, if there is one.
    pub fn column(&self, name: &str) -> Option<&[f64]> {
        COLUMNS
            .iter()
            .position(|c| *c == name)
            .map(|i| self.columns[i].as_slice())
    }

    /// Writes the header and every row as CSV (shortest round-trip number format).
    pub fn write_csv(&self, out: &mut impl std::io::Write) -> std::io::Result<()> {
        writeln!(out, "{}", COLUMNS.join(","))?;
        let mut line = String::with_capacity(NUM_COLUMNS * 24);
        for r in 0..self.len() {
            line.clear();
            for (i, col) in self.columns.iter().enumerate() {
                if i > 0 {
                    line.push(',');
                }
                write!(line, "{}", col[r]).expect("writing to a String");
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
        let cols: Vec<&[f64]> = names
            .iter()
            .map(|n| self.column(n))
            .collect::<Option<_>>()?;
        let t = &self.columns[0];
        let start = t.partition_point(|&x| x < t0);
        let end = t.partition_point(|&x| x <= t1);
        let n = end.saturating_sub(start);
        let buckets = buckets.max(1);
        let mut out: Vec<Vec<f64>> = vec![Vec::with_capacity(2 * buckets.min(n)); names.len() + 1];
        if n <= 2 * buckets {
            out[0].extend_from_slice(&t[start..end]);
            for (o, c) in out[1..].iter_mut().zip(&cols) {
                o.extend_from_slice(&c[start..end]);
            }
            return Some(out);
        }
        for b in 0..buckets {
            let lo = start + b * n / buckets;
            let hi = start + (b + 1) * n / buckets;
            out[0].push(t[lo]);
            out[0].push(t[hi - 1]);
            for (o, c) in out[1..].iter_mut().zip(&cols) {
                let (mn, mx) = c[lo..hi]
                    .iter()
                    .fold((f64::INFINITY, f64::NEG_INFINITY), |(a, b), &v| {
                        (a.min(v), b.max(v))
                    });
                o.push(mn);
                o.push(mx);
            }
        }
        Some(out)
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
            r.record(k, &row);
        }
        r
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
