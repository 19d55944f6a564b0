//! Closed-loop speed: plant + EKF + controller + recording, per preset, native release build.
//! Prints steps per second and simulated seconds per wall-clock second.

use imlab::scenario::{preset, PRESETS};
use imlab::sim::Simulation;
use std::time::{Duration, Instant};

fn main() {
    println!(
        "{:14} {:>12} {:>14} {:>12}",
        "preset", "steps", "steps/s", "× real time"
    );
    for p in PRESETS {
        let s = preset(p.name).expect("preset");
        let mut steps = 0usize;
        let mut best = f64::INFINITY;
        let begin = Instant::now();
        // Repeat for at least a second; report the fastest run (least disturbed by the OS).
        while begin.elapsed() < Duration::from_secs(1) {
            let mut sim = Simulation::new(&s, 1).expect("valid preset");
            let t = Instant::now();
            let result = sim.run();
            let wall = t.elapsed().as_secs_f64();
            std::hint::black_box(sim.recorder().len());
            if result.is_ok() {
                best = best.min(wall / sim.steps_done() as f64);
            }
            steps = sim.steps_done();
        }
        let per_sec = 1.0 / best;
        println!(
            "{:14} {:>12} {:>14.0} {:>12.0}",
            p.name,
            steps,
            per_sec,
            per_sec * s.ts
        );
    }
}
