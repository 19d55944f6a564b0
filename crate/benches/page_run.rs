//! One run of a scenario as the page runs it, natively, for the floor bench's whole-process
//! timing (tests/bench/floor.mjs): traced (checkpoints, every row computed and checked), with the
//! overview of the page's plots kept as it goes, then what the worker sends when the run is done:
//! the whole run's view, the stability analysis and the report (figures, transient, warnings).
//!
//! Usage: `page_run SCENARIO` (the executable `cargo bench --bench page_run --no-run` builds).

mod page;

use imlab::scenario::Scenario;
use imlab::sim::Simulation;
use page::{page_groups, BUCKETS};
use std::hint::black_box;

fn main() {
    let text = std::env::args().nth(1).expect("usage: page_run SCENARIO");
    let s = Scenario::parse(&text).unwrap_or_else(|e| panic!("{text}: {e}"));
    let groups = page_groups();
    let mut sim = Simulation::traced(&s).expect("accepted");
    sim.keep_overview(&groups, BUCKETS).expect("columns");
    sim.run().expect("runs to the end");
    black_box(sim.view(&groups, 0.0, f64::MAX, BUCKETS).expect("columns"));
    black_box(sim.stability());
    black_box(sim.report());
}
