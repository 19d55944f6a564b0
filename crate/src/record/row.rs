//! One recorded sample of the loop: its columns, their docs, the check that a row holds finite
//! numbers only, CSV writing, and where the loop puts its rows ([`Sink`]).

use crate::inverter::Limit;
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

/// A visitor of rows in order: it returns false to stop.
pub type RowVisitor<'a> = dyn FnMut(&Row) -> bool + 'a;

/// Writes the rows that `rows` gives (it calls its argument with each, in order, until that
/// returns false) as CSV lines, preceded by the header when they start at row 0 (shortest
/// round-trip number format).
pub fn write_csv(
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
pub fn finite(row: &Row) -> Result<(), (&'static str, f64)> {
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

/// Where the rows of the loop go: asked once per sample, in order, whether it wants that
/// sample's row; the row is only computed when it does.
pub trait Sink {
    /// Whether the row of the next sample is wanted.
    fn wants(&mut self) -> bool;
    /// Takes the wanted row; a value that is not finite is refused, naming its column.
    fn take(&mut self, row: &Row) -> Result<(), (&'static str, f64)>;
}

/// The first of `0..n` for which `holds` is false, where it holds for a prefix of `0..n` (row times
/// increase with the row): a binary search.
pub fn first_not(n: usize, holds: impl Fn(usize) -> bool) -> usize {
    let (mut lo, mut hi) = (0, n);
    while lo < hi {
        let mid = lo + (hi - lo) / 2;
        if holds(mid) {
            lo = mid + 1;
        } else {
            hi = mid;
        }
    }
    lo
}

/// Whether the commanded voltage of `row` is beyond the inverter's limit.
pub fn is_saturated(row: &Row, limit: &Limit) -> bool {
    limit.exceeds(&[row.u_a_cmd, row.u_b_cmd])
}
