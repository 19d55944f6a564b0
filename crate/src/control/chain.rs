//! A student's own chain: step 2 judged on the student's own v1, step 4 on their own v3.
//!
//! Step 2's law is the one that gives ż2 = −k2·z2 − z1 with whatever v1 the loop runs, so its v̇1
//! is the derivative of that v1. The paper's v2 holds the derivative of the paper's v1, (31),
//! with ż1 taken as its designed −k1·z1 + z2. When step 1 runs a law of the student's own that
//! differs from the paper's by Δ1 = v1 − v1,paper, then ż1 = −k1·z1 + z2 + Δ1, and the v2 that
//! gives step 2's designed dynamics is the paper's v2 (written with the loop's v1 and z2) plus
//!
//!   Δ̇1 − k1s1·Δ1,
//!
//! and likewise step 4's v4 is the paper's plus Δ̇3 − k3·Δ3 (ż3 = −k3·z3 + z4 + Δ3). Δ̇ is
//! evaluated by forward mode ([`Program::eval_rate`]) over the signals' nominal rates
//! ([`rates`]): the observer (4) with the residuals' nominal dynamics (x̃1 = x̃4 = x̃5 = 0), and
//! the lumped parameters, gains and observer gains held constant, as the paper's derivatives hold
//! L. The flux target is held constant too: the paper keeps ψ̇_d and ψ̈_d, which are zero here.

use super::formula::{Program, NAMES, SIGNALS};

/// The nominal rate of each signal a step-1 or step-3 law may read, from the signals `s` of that
/// step; NaN where the rate is not known: the currents and the estimated currents (and so
/// x̂̇4, x̂̇5), and z2, whose rates hold the voltage the later steps choose; ω̈_d, whose rate is the
/// reference's third derivative, which the loop does not have; dâ2/dt, whose rate needs the
/// load row of L, which is not a signal; and v1, v3, z4, which a step-1 or step-3 law cannot read
/// or whose rate holds the voltage too.
pub fn rates(s: &[f64; SIGNALS]) -> [f64; SIGNALS] {
    let mut r = [0.0; SIGNALS];
    for i in [
        sig!("x2h"),
        sig!("x3h"),
        sig!("x2"),
        sig!("x3"),
        sig!("dx4h"),
        sig!("dx5h"),
        sig!("ddwd"),
        sig!("da2"),
        sig!("v1"),
        sig!("z2"),
        sig!("v3"),
        sig!("z4"),
    ] {
        r[i] = f64::NAN;
    }
    let v = |i: usize| s[i];
    let (dxt2, dxt3) = (v(sig!("dxt2")), v(sig!("dxt3")));
    let (dx4h, dx5h) = (v(sig!("dx4h")), v(sig!("dx5h")));
    // The observer's x̂̇1 of (4): the torque term reads the measured currents.
    let dx1h = v(sig!("a1")) * (v(sig!("x3")) * v(sig!("x4h")) - v(sig!("x2")) * v(sig!("x5h")))
        - v(sig!("a3")) * v(sig!("x1h"))
        - v(sig!("a2"))
        + v(sig!("si1"));
    let a7 = v(sig!("a7"));
    let known = [
        (sig!("x1h"), dx1h),
        (sig!("x4h"), dx4h),
        (sig!("x5h"), dx5h),
        (sig!("xt2"), dxt2),
        (sig!("xt3"), dxt3),
        (
            sig!("dxt2"),
            -(a7 + v(sig!("l21"))) * dxt2 - v(sig!("l22")) * dxt3,
        ),
        (
            sig!("dxt3"),
            -v(sig!("l31")) * dxt2 - (a7 + v(sig!("l32"))) * dxt3,
        ),
        (sig!("wd"), v(sig!("dwd"))),
        (sig!("dwd"), v(sig!("ddwd"))),
        (sig!("a2"), v(sig!("da2"))),
        (sig!("z1"), dx1h - v(sig!("dwd"))),
        (
            sig!("z3"),
            2.0 * (v(sig!("x4h")) * dx4h + v(sig!("x5h")) * dx5h),
        ),
    ];
    for (i, rate) in known {
        r[i] = rate;
    }
    // si_k = l_k1·x̃2 + l_k2·x̃3, with L held.
    for k in 0..5 {
        let l = sig!("l11") + 2 * k;
        r[sig!("si1") + k] = v(l) * dxt2 + v(l + 1) * dxt3;
    }
    r
}

/// What step `step` (2 or 4) adds to the paper's law when the step before it runs `own` in place
/// of `paper` (the paper's law of that step): Δ̇ − k·Δ, from the earlier step's signals `s` and
/// `delta` = Δ, its own value less the paper's there; NaN when `own` reads a signal whose rate is
/// not known.
pub fn correction(step: u8, own: &Program, paper: &Program, s: &[f64; SIGNALS], delta: f64) -> f64 {
    let r = rates(s);
    let rate = own.eval_rate(s, &r) - paper.eval_rate(s, &r);
    let k = match step {
        2 => s[sig!("k1s1")],
        4 => s[sig!("k3")],
        _ => unreachable!("steps 2 and 4 follow a law of their own"),
    };
    rate - k * delta
}

/// The names `own` reads whose rates are not known, as "x2, x2h".
pub fn without_rate(own: &Program, s: &[f64; SIGNALS]) -> String {
    let r = rates(s);
    own.names()
        .into_iter()
        .filter(|&i| r[i].is_nan())
        .map(|i| NAMES[i].name)
        .collect::<Vec<_>>()
        .join(", ")
}
