//! Scenario parsing time against input length: linear up to the 16 KiB cap, and a 1 MB input
//! refused at once. Prints microseconds per parse (best of many), strict and lenient.

use imlab::scenario::{Scenario, MAX_SCENARIO_BYTES};
use std::time::{Duration, Instant};

/// `v=1&preset=step` followed by distinct unknown keys up to `bytes` long: every piece is looked
/// up, and the lenient parser keeps going past each one.
fn input(bytes: usize) -> String {
    let mut text = "v=1&preset=step".to_string();
    let mut i = 0;
    while text.len() < bytes {
        text.push_str(&format!("&key{i}=1"));
        i += 1;
    }
    text.truncate(bytes);
    text
}

/// Best wall time of `f` over at least 0.3 s of repeats (µs).
fn best(mut f: impl FnMut()) -> f64 {
    let (begin, mut best) = (Instant::now(), f64::INFINITY);
    while begin.elapsed() < Duration::from_millis(300) {
        let t = Instant::now();
        f();
        best = best.min(t.elapsed().as_secs_f64() * 1e6);
    }
    best
}

fn main() {
    println!(
        "{:>10} {:>12} {:>12} {:>14}",
        "bytes", "strict µs", "lenient µs", "lenient ns/B"
    );
    for bytes in [1 << 10, 4 << 10, MAX_SCENARIO_BYTES, 1 << 20] {
        let text = input(bytes);
        let strict = best(|| {
            std::hint::black_box(Scenario::parse(&text).is_ok());
        });
        let lenient = best(|| {
            std::hint::black_box(Scenario::parse_lenient(&text).is_ok());
        });
        println!(
            "{bytes:>10} {strict:>12.1} {lenient:>12.1} {:>14.1}",
            lenient * 1e3 / bytes as f64
        );
    }
}
