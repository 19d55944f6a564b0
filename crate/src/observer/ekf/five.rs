//! The paper's filter (five states, the Euler predictor) on plain arrays: the general filter's
//! operations in the same order, bit for bit, without the general matrices' overhead, and with
//! the products by the Jacobian's structural zeros left out.

use crate::model::{self, Input};
use crate::params::Lumped;

/// Where the paper's Jacobian (11) is structurally zero: the stator currents do not drive each
/// other (∂ẋ2/∂x3 = ∂ẋ3/∂x2 = 0) nor the other flux's derivative (∂ẋ4/∂x3 = ∂ẋ5/∂x2 = 0).
/// Φ = I + Ts·J of the Euler predictor has the same zeros.
const EULER5_ZERO: [[bool; 5]; 5] = {
    let mut z = [[false; 5]; 5];
    z[1][2] = true;
    z[2][1] = true;
    z[3][2] = true;
    z[4][1] = true;
    z
};

/// Φ·P·Φᵀ + Q for the five states and the Euler predictor's Φ (row-major), with P and the result
/// as columns (`p[j][k]` = P_kj): each sum over k in increasing order, from the first term, as the
/// general product computes it, with the products by Φ's exact zeros left out. Adding a zero
/// product changes no sum that is not itself zero, so the result is the general one, bit for bit,
/// for less work.
///
/// Φ·P takes P_kj from `p[k][j]` (= P_jk) rather than `p[j][k]`: P is exactly symmetric (P0 is
/// diagonal and every step writes both triangles from one value), so it is the same number, read
/// where row k of P lies contiguous in memory, which the compiler turns into paired loads.
#[inline(always)]
fn euler5_propagate(phi: &[[f64; 5]; 5], p: &[[f64; 5]; 5], q: &[f64; 5]) -> [[f64; 5]; 5] {
    let mut n = [[0.0; 5]; 5];
    for i in 0..5 {
        for j in 0..5 {
            // Column 0 of every row is nonzero.
            let mut s = phi[i][0] * p[0][j];
            for k in 1..5 {
                if !EULER5_ZERO[i][k] {
                    s += phi[i][k] * p[k][j];
                }
            }
            n[i][j] = s;
        }
    }
    let mut out = [[0.0; 5]; 5];
    for i in 0..5 {
        for j in i..5 {
            let mut s = n[i][0] * phi[j][0];
            for k in 1..5 {
                if !EULER5_ZERO[j][k] {
                    s += n[i][k] * phi[j][k];
                }
            }
            // Q is diagonal: adding its zeros keeps the general sum's bits (a zero sum becomes +0).
            let v = s + if i == j { q[i] } else { 0.0 };
            out[i][j] = v;
            out[j][i] = v;
        }
    }
    out
}

/// [`super::Filter::predict`] of the paper's filter (N = 5, Euler) on plain arrays, x and P (as columns,
/// `p[5j + i]` = P_ij): x += Ts·f(x, u) and P = Φ·P·Φᵀ + Q with Φ = I + Ts·A, the same operations
/// in the same order as the general step, bit for bit.
#[inline(always)]
pub(super) fn euler5_predict(
    m: &Lumped,
    ts: f64,
    q: &[f64; 5],
    u: &Input,
    x: &mut [f64; 5],
    p: &mut [f64; 25],
) {
    let a = model::jacobian(m, x);
    let dx = model::f(m, x, u, 0.0);
    for i in 0..5 {
        x[i] += ts * dx[i];
    }
    let phi = arr5(|i| arr5(|j| (if i == j { 1.0 } else { 0.0 }) + a[i][j] * ts));
    let cols = arr5(|c| arr5(|r| p[5 * c + r]));
    let next = euler5_propagate(&phi, &cols, q);
    for c in 0..5 {
        p[5 * c..5 * c + 5].copy_from_slice(&next[c]);
    }
}

/// What [`update5`] leaves besides x and P, in nalgebra's column-major layouts.
pub(super) struct Update5 {
    /// K: `gain[5c + i]` = K_ic.
    pub(super) gain: [f64; 10],
    /// ỹ.
    pub(super) innovation: [f64; 2],
    /// S: [s11, s21, s12, s22].
    pub(super) s: [f64; 4],
}

/// [`super::Filter::update`] of the paper's filter (N = 5) on plain arrays, x and P (as columns,
/// `p[5j + i]` = P_ij): the operations of the general step in the same order, bit for bit. Each
/// entry is read from the element the general step reads; only the matrices are plain arrays and
/// no value is computed differently.
#[inline(always)]
pub(super) fn update5(r2: f64, y: &[f64; 2], x: &mut [f64; 5], p: &mut [f64; 25]) -> Update5 {
    let col = |j: usize| arr5(|i| p[5 * j + i]);
    let e = [y[0] - x[1], y[1] - x[2]];
    // S = [[s11, s12], [s21, s22]] and its determinant as nalgebra's: s11·s22 − s21·s12.
    let (s11, s12, s21, s22) = (p[6] + r2, p[11], p[7], p[12] + r2);
    let inv_det = 1.0 / (s11 * s22 - s21 * s12);
    let (i11, i12, i22) = (s22 * inv_det, -s12 * inv_det, s11 * inv_det);
    // K by columns: k0[i] = K_i0 = P_i1·i11 + P_i2·i12, k1[i] = K_i1 = P_i1·i12 + P_i2·i22.
    let (c1, c2) = (col(1), col(2));
    let k0 = arr5(|i| c1[i] * i11 + c2[i] * i12);
    let k1 = arr5(|i| c1[i] * i12 + c2[i] * i22);
    // x += K·ỹ: nalgebra's product is K_i0·ỹ0 (times an exact 1), then K_i1·ỹ1 + that.
    for i in 0..5 {
        x[i] += k0[i] * e[0] + k1[i] * e[1];
    }
    // Joseph form as the general step: A = P − K·(C·P), row-major, A_ij = P_ij − K_i0·P_1j −
    // K_i1·P_2j; then the upper triangle of A − (A·Cᵀ)·Kᵀ + r²·K·Kᵀ, mirrored.
    let a = arr5(|i| arr5(|j| p[5 * j + i] - k0[i] * p[5 * j + 1] - k1[i] * p[5 * j + 2]));
    for i in 0..5 {
        for j in i..5 {
            let v =
                a[i][j] - a[i][1] * k0[j] - a[i][2] * k1[j] + r2 * (k0[i] * k0[j] + k1[i] * k1[j]);
            p[5 * j + i] = v;
            p[5 * i + j] = v;
        }
    }
    let mut gain = [0.0; 10];
    gain[..5].copy_from_slice(&k0);
    gain[5..].copy_from_slice(&k1);
    Update5 {
        gain,
        innovation: e,
        s: [s11, s21, s12, s22],
    }
}

/// [f(0), …, f(4)], evaluated in that order (unlike `std::array::from_fn`, always inlined).
#[inline(always)]
fn arr5<T>(f: impl Fn(usize) -> T) -> [T; 5] {
    [f(0), f(1), f(2), f(3), f(4)]
}
