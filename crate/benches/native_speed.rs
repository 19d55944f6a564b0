//! The native counterpart of tests/bench/node.mjs, for its WASM/native ratio: `ramp` 1 s and 5 s
//! traced runs (checkpoints, every row computed and checked, no plot overview: what `new
//! Simulation` in node.mjs does), the same warm-up and best-of as the Node repetitions
//! (BENCH_WARMUP, default 3; BENCH_RUNS, default 10), printed as one JSON line of steps/s.
//!
//! The machine's speed drifts by tens of percent over seconds (see node.mjs), so node.mjs runs
//! this binary alternately with its own repetitions and takes the ratio of neighbours; figures
//! measured minutes apart would not compare. Criterion's `closed_loop` bench is the place for
//! native figures themselves. Run alone with `cargo bench --bench native_speed`.
//!
//! A traced run writes a checkpoint every 2,048 samples (16 KB a simulated second), so 1 s and
//! 5 s runs should be equally fast.

use imlab::scenario::Scenario;
use imlab::sim::Simulation;
use std::time::Instant;

/// The scenarios of node.mjs, with their labels there.
const SCENARIOS: [(&str, &str); 2] = [
    ("1 s", "v=1&preset=ramp&duration=1"),
    ("5 s", "v=1&preset=ramp&duration=5"),
];

/// A positive whole number from the environment variable `name`, or `fallback`.
fn setting(name: &str, fallback: usize) -> usize {
    match std::env::var(name) {
        Ok(text) => match text.parse() {
            Ok(n) if n >= 1 => n,
            _ => panic!("{name} must be a positive integer, not {text:?}"),
        },
        Err(_) => fallback,
    }
}

/// Steps per second of one whole traced run of `s`.
fn rate(s: &Scenario) -> f64 {
    let mut sim = Simulation::traced(s).expect("accepted");
    let t = Instant::now();
    sim.run().expect("runs to the end");
    let wall = t.elapsed().as_secs_f64();
    std::hint::black_box(sim.len());
    sim.steps_done() as f64 / wall
}

fn main() {
    let (warmup, runs) = (setting("BENCH_WARMUP", 3), setting("BENCH_RUNS", 10));
    let mut fields = Vec::new();
    for (label, text) in SCENARIOS {
        let s = Scenario::parse(text).expect("valid scenario");
        for _ in 0..warmup {
            rate(&s);
        }
        let best = (0..runs).map(|_| rate(&s)).fold(0.0, f64::max);
        fields.push(format!("\"{label}\":{best:.0}"));
    }
    println!("{{{}}}", fields.join(","));
}
