//! Closed-loop speed and the cost of recording, native release build, with criterion.
//!
//! Three kinds of group:
//! - `preset/<name>`: each preset run to its end with every sample recorded
//!   (`Simulation::new(&s, 1)` then `run()`);
//! - `long`: `ramp` lasting 5 s and 20 s, each with every sample recorded and with recording off
//!   (only sample 0 kept), side by side so the cost of recording shows as a ratio;
//! - `view`: the recording and view paths on a recorded 5 s `ramp`: M4 envelopes (one plot, and
//!   the page's whole view request) over the whole run and zoomed, the overlay of two runs, a CSV
//!   chunk of 20,000 rows, and inspect at the last sample (a replay of the whole run).
//!
//! Criterion's "elem/s" is steps per second for `preset/*`, `long/*` and `view/inspect`, and rows
//! per second for `view/csv`. Building the simulation (`Simulation::new`) and dropping it are
//! outside the timing; faulting in the fresh trace memory while the run writes it is inside: the
//! allocator maps a large trace afresh for each run and unmaps it on drop, and the kernel's
//! zeroing of those pages is most of what recording costs (on the 2-core VM, first writes to a
//! fresh 45 MB took 25 ms against 6.5 ms to rewrite it: the difference is a third of a recorded
//! 5 s run).
//! A table at the end gives the median of each benchmark just run, with ×real time and the
//! recorded/off ratio.
//!
//! Run everything with `cargo bench --bench closed_loop`; one group with
//! `cargo bench --bench closed_loop -- long` (the argument is a regex on the benchmark id, e.g.
//! `preset/ramp` or `view/envelope`); a short pass with `-- --quick`.

use criterion::{BatchSize, BenchmarkId, Criterion, SamplingMode, Throughput};
use imlab::scenario::{preset, Scenario, PRESETS};
use imlab::sim::{Recorder, Simulation};
use std::hint::black_box;
use std::path::PathBuf;
use std::time::{Duration, SystemTime};

/// Lengths of the long `ramp` runs (s).
const LONG_DURATIONS: [u32; 2] = [5, 20];
/// Plot width the view benchmarks ask for (buckets, about the pixels of a plot).
const BUCKETS: usize = 1000;
/// Rows in the CSV chunk benchmark.
const CSV_ROWS: usize = 20_000;
/// The plots of the page, one envelope each, as `PLOTS` in web/plots.js lists their columns
/// (keep in step): one view request of the worker computes all of them.
const PAGE_PLOTS: &[&[&str]] = &[
    &["omega_ref", "omega_hat", "omega"],
    &["omega_err"],
    &["flux_ref", "flux_hat", "flux"],
    &["i_sa_hat", "i_sb_hat", "i_sa", "i_sb"],
    &["u_a", "u_b"],
    &["z1", "z3"],
    &["z2", "z4"],
    &["omega_est_err", "flux_est_err"],
];

fn scenario(text: &str) -> Scenario {
    Scenario::parse(text).unwrap_or_else(|e| panic!("{text}: {e}"))
}

/// A finished run of `s`, keeping every `every`-th sample.
fn finished(s: &Scenario, every: usize) -> Simulation {
    let mut sim = Simulation::new(s, every).expect("accepted");
    sim.run().expect("runs to the end");
    sim
}

/// Benchmarks a whole run of `s` keeping every `every`-th sample, in steps per second, as `id`
/// within `group` (no `/` in `id`: it is also the name of criterion's folder).
fn bench_run(
    group: &mut criterion::BenchmarkGroup<'_, criterion::measurement::WallTime>,
    id: &str,
    s: &Scenario,
    every: usize,
) {
    // Refused runs (the trace cap) fail here, before timing, with the reason.
    if let Err(e) = Simulation::new(s, every) {
        panic!("{id}, every = {every}: {e}");
    }
    group.throughput(Throughput::Elements(s.steps() as u64));
    group.bench_function(id, |b| {
        b.iter_batched(
            || Simulation::new(s, every).expect("accepted"),
            |mut sim| {
                sim.run().expect("runs to the end");
                // Returned, so that freeing the trace is not timed.
                sim
            },
            BatchSize::PerIteration,
        );
    });
}

/// One group per preset: the closed loop with every sample recorded.
fn presets(c: &mut Criterion) {
    for p in PRESETS {
        let s = preset(p.name).expect("preset");
        let mut group = c.benchmark_group(format!("preset/{}", p.name));
        group
            .sample_size(20)
            .warm_up_time(Duration::from_millis(500))
            .measurement_time(Duration::from_secs(2));
        bench_run(&mut group, "recorded", &s, 1);
        group.finish();
    }
}

/// `ramp` over 5 s and 20 s, recorded and not, in one group.
fn long(c: &mut Criterion) {
    let mut group = c.benchmark_group("long");
    // Runs of 25 ms to a few hundred ms: few samples, each one run.
    group
        .sample_size(10)
        .sampling_mode(SamplingMode::Flat)
        .warm_up_time(Duration::from_secs(1))
        .measurement_time(Duration::from_secs(3));
    for seconds in LONG_DURATIONS {
        let s = scenario(&format!("v=1&preset=ramp&duration={seconds}"));
        bench_run(&mut group, &format!("{seconds}s_recorded"), &s, 1);
        // Keeping every steps-th sample keeps sample 0 only: the loop without the trace.
        bench_run(&mut group, &format!("{seconds}s_off"), &s, s.steps());
    }
    group.finish();
}

/// The paths that read the trace: envelopes, overlay, CSV, inspect.
fn view(c: &mut Criterion) {
    let s = scenario("v=1&preset=ramp&duration=5");
    let current = finished(&s, 1);
    let pinned = finished(&scenario("v=1&preset=ramp&duration=5&seed=2"), 1);
    let rec = current.recorder();
    let end = s.duration;
    // Whole run; 1 s around the ramp (bucketed); 20 ms (400 rows, sent whole).
    let windows = [
        ("whole", 0.0, end),
        ("zoom_1s", 0.0, 1.0),
        ("zoom_20ms", 0.2, 0.22),
    ];

    let mut group = c.benchmark_group("view");
    group
        .sample_size(10)
        .warm_up_time(Duration::from_millis(500))
        .measurement_time(Duration::from_millis(1500));
    for (name, t0, t1) in windows {
        group.bench_function(BenchmarkId::new("envelope", name), |b| {
            b.iter(|| rec.envelope(black_box(PAGE_PLOTS[0]), t0, t1, BUCKETS));
        });
    }
    for (name, t0, t1) in [windows[0], windows[2]] {
        group.bench_function(BenchmarkId::new("page_view", name), |b| {
            b.iter(|| {
                PAGE_PLOTS
                    .iter()
                    .map(|names| rec.envelope(black_box(names), t0, t1, BUCKETS))
                    .collect::<Vec<_>>()
            });
        });
    }
    let others: [&Recorder; 1] = [pinned.recorder()];
    group.bench_function(BenchmarkId::new("overlay", "whole"), |b| {
        b.iter(|| rec.overlay(&others, black_box("omega"), 0.0, end, BUCKETS));
    });
    group.throughput(Throughput::Elements(CSV_ROWS as u64));
    let mut out = Vec::new();
    group.bench_function(BenchmarkId::new("csv", CSV_ROWS), |b| {
        b.iter(|| {
            out.clear();
            // From row 1: a chunk of the export without its header.
            rec.write_csv_rows(&mut out, 1, CSV_ROWS).expect("to a Vec");
            out.len()
        });
    });
    group.throughput(Throughput::Elements(s.steps() as u64));
    group.bench_function(BenchmarkId::new("inspect", "end_of_5s"), |b| {
        b.iter(|| Simulation::inspect(&s, black_box(end)).expect("inspects"));
    });
    group.finish();
}

/// Where criterion keeps its results: `$CRITERION_HOME`, else the `criterion` folder of the
/// target directory this benchmark was built in.
fn criterion_home() -> Option<PathBuf> {
    if let Some(home) = std::env::var_os("CRITERION_HOME") {
        return Some(home.into());
    }
    let exe = std::env::current_exe().ok()?;
    exe.ancestors()
        .map(|dir| dir.join("criterion"))
        .find(|dir| dir.is_dir())
}

/// Median time per iteration (s) of benchmark `id` (its folder under the criterion home), if it
/// was measured by this process (not left over from an earlier run).
fn median(home: &std::path::Path, id: &str, since: SystemTime) -> Option<f64> {
    let path = home.join(id).join("new/estimates.json");
    if std::fs::metadata(&path).ok()?.modified().ok()? < since {
        return None;
    }
    let json: serde_json::Value = serde_json::from_slice(&std::fs::read(path).ok()?).ok()?;
    Some(json["median"]["point_estimate"].as_f64()? * 1e-9)
}

/// Prints the medians of the benchmarks run by this process as steps/s and milliseconds.
fn summary(since: SystemTime) {
    let Some(home) = criterion_home() else {
        return;
    };
    let mut lines = Vec::new();
    let ts = preset("ramp").expect("preset").ts;
    let rate = |id: &str, steps: usize| median(&home, id, since).map(|t| steps as f64 / t);
    for p in PRESETS {
        let s = preset(p.name).expect("preset");
        if let Some(r) = rate(&format!("preset_{}/recorded", p.name), s.steps()) {
            lines.push(format!(
                "preset/{:<22} {:>7.2} M steps/s {:>6.0}× real time",
                p.name,
                r / 1e6,
                r * s.ts
            ));
        }
    }
    for seconds in LONG_DURATIONS {
        let steps = scenario(&format!("v=1&preset=ramp&duration={seconds}")).steps();
        let recorded = rate(&format!("long/{seconds}s_recorded"), steps);
        let off = rate(&format!("long/{seconds}s_off"), steps);
        for (name, r) in [("recorded", recorded), ("off", off)] {
            if let Some(r) = r {
                lines.push(format!(
                    "long/{seconds}s_{name:<17} {:>7.2} M steps/s {:>6.0}× real time",
                    r / 1e6,
                    r * ts
                ));
            }
        }
        if let (Some(recorded), Some(off)) = (recorded, off) {
            lines.push(format!(
                "long/{seconds}s recorded/off       {:>7.0} %",
                100.0 * recorded / off
            ));
        }
    }
    for id in [
        "envelope/whole",
        "envelope/zoom_1s",
        "envelope/zoom_20ms",
        "page_view/whole",
        "page_view/zoom_20ms",
        "overlay/whole",
        &format!("csv/{CSV_ROWS}"),
        "inspect/end_of_5s",
    ] {
        if let Some(t) = median(&home, &format!("view/{id}"), since) {
            lines.push(format!("view/{id:<23} {:>9.3} ms", t * 1e3));
        }
    }
    if !lines.is_empty() {
        println!("\nMedians of the benchmarks run now:");
        for line in lines {
            println!("  {line}");
        }
    }
}

fn main() {
    let since = SystemTime::now();
    let mut c = Criterion::default().without_plots().configure_from_args();
    presets(&mut c);
    long(&mut c);
    view(&mut c);
    c.final_summary();
    summary(since);
}
