//! What the challenge and grading tests share: a small challenge with every kind of key and its
//! canonical text, a challenge whose runs take milliseconds, and the `imlab` binary.
#![allow(dead_code)]

/// A small challenge with every kind of key.
pub const SMALL: &str = "c=1&title=Quick%20step&base=v%3D1%26preset%3Dstep%26duration%3D0.08\
                     &allow.k2=300..3000&allow.k1=300..3000&allow.ekf=rk4|euler\
                     &need.settling_time=max:0.006&need.current_peak=max:4&need.mean_nis=band\
                     &vary=model.j%3D0.016|model.j%3D0.024&robust=current_peak";

/// SMALL's canonical text.
pub const SMALL_CANONICAL: &str =
    "c=1&title=Quick%20step&base=v%3D1%26preset%3Dstep%26duration%3D0.08\
     &allow.k1=300..3000&allow.k2=300..3000&allow.ekf=euler|rk4\
     &need.settling_time=max:0.006&need.current_peak=max:4&need.mean_nis=band\
     &vary=model.j%3D0.016|model.j%3D0.024&robust=current_peak";

use std::path::PathBuf;
use std::process::{Command, Output, Stdio};

/// A challenge whose runs take milliseconds: no variants, 0.06 s of `step`.
pub const QUICK: &str = "c=1&title=Quick&base=v%3D1%26preset%3Dstep%26duration%3D0.06\
                     &allow.k1=300..3000&need.current_peak=max:4&need.settling_time=max:0.006";

/// A passing submission of [`QUICK`].
pub fn quick_link(k1: u32) -> String {
    format!("{QUICK}&try.k1={k1}")
}

/// A fresh temporary path for this test.
pub fn temp(name: &str) -> PathBuf {
    std::env::temp_dir().join(format!("imlab-grade-{}-{name}", std::process::id()))
}

/// `imlab` with `args`, stdin closed.
pub fn imlab(args: &[&str]) -> Output {
    Command::new(env!("CARGO_BIN_EXE_imlab"))
        .args(args)
        .stdin(Stdio::null())
        .output()
        .unwrap()
}
