//! Closed-loop speed and the cost of recording, native release build, with criterion.
//!
//! Three kinds of group:
//! - `preset/<name>`: each preset run to its end as the page runs it: traced (checkpoints), with
//!   the overview of the page's plots at 1000 buckets computed as it goes;
//! - `long`: `ramp` lasting 5 s and 20 s, traced as the page runs it (`recorded`), traced without
//!   the overview (`checkpoints`), with every row kept in memory (`rows`, the design before
//!   checkpoints) and with recording off (`off`: only sample 0 kept, no row computed or checked
//!   otherwise), side by side;
//! - `view`: the read paths on a traced 5 s `ramp`: the page's view request (every plot) over the
//!   whole run from the overview and replayed, zoomed to 1 s and to 20 ms; one plot zoomed; the
//!   overlay of two runs, replayed and from the column they keep; a CSV chunk of 20,000 rows; inspect at the last sample.
//!
//! Criterion's "elem/s" is steps per second for `preset/*` and `long/*`, and rows per second for
//! `view/csv`. Building the simulation and dropping it are outside the timing; faulting in fresh
//! memory while the run writes it is inside: for `rows` the allocator maps its 50 MB afresh for
//! each run and the kernel zeroes every page on first write.
//! A table at the end gives the median of each benchmark just run, with ×real time and the
//! recorded/off ratio.
//!
//! Run everything with `cargo bench --bench closed_loop`; one group with
//! `cargo bench --bench closed_loop -- long` (the argument is a regex on the benchmark id, e.g.
//! `preset/ramp` or `view/envelope`); a short pass with `-- --quick`.

mod page;

use criterion::{BatchSize, BenchmarkId, Criterion, SamplingMode, Throughput};
use imlab::scenario::{preset, Scenario, PRESETS};
use imlab::sim::Simulation;
use page::{page_groups, BUCKETS};
use std::hint::black_box;
use std::path::PathBuf;
use std::time::{Duration, SystemTime};

/// Lengths of the long `ramp` runs (s).
const LONG_DURATIONS: [u32; 2] = [5, 20];
/// Rows in the CSV chunk benchmark.
const CSV_ROWS: usize = 20_000;
fn scenario(text: &str) -> Scenario {
    Scenario::parse(text).unwrap_or_else(|e| panic!("{text}: {e}"))
}

/// How a benchmarked run keeps its samples.
#[derive(Clone, Copy)]
enum Keep {
    /// As the page runs it: checkpoints, and the overview of the page's plots at BUCKETS.
    Traced,
    /// Checkpoints only, no overview: what the overview costs is the difference.
    Checkpoints,
    /// Every row in memory (the design before checkpoints; analysis runs still use it).
    Rows,
    /// Sample 0 only: the loop without recording.
    Off,
}

/// A prepared run of `s`.
fn prepare(s: &Scenario, keep: Keep) -> Simulation {
    match keep {
        Keep::Traced => {
            let mut sim = Simulation::traced(s).expect("accepted");
            sim.keep_overview(&page_groups(), BUCKETS).expect("columns");
            sim
        }
        Keep::Checkpoints => Simulation::traced(s).expect("accepted"),
        Keep::Rows => Simulation::new(s, 1).expect("accepted"),
        Keep::Off => Simulation::new(s, s.steps()).expect("accepted"),
    }
}

/// A finished traced run of `s`.
fn finished(s: &Scenario) -> Simulation {
    let mut sim = prepare(s, Keep::Traced);
    sim.run().expect("runs to the end");
    sim
}

/// Benchmarks a whole run of `s` in steps per second, as `id` within `group` (no `/` in `id`:
/// it is also the name of criterion's folder).
fn bench_run(
    group: &mut criterion::BenchmarkGroup<'_, criterion::measurement::WallTime>,
    id: &str,
    s: &Scenario,
    keep: Keep,
) {
    group.throughput(Throughput::Elements(s.steps() as u64));
    group.bench_function(id, |b| {
        b.iter_batched(
            || prepare(s, keep),
            |mut sim| {
                sim.run().expect("runs to the end");
                // Returned, so that freeing the trace is not timed.
                sim
            },
            BatchSize::PerIteration,
        );
    });
}

/// One group per preset: the closed loop as the page runs it.
fn presets(c: &mut Criterion) {
    for p in PRESETS {
        let s = preset(p.name).expect("preset");
        let mut group = c.benchmark_group(format!("preset/{}", p.name));
        group
            .sample_size(20)
            .warm_up_time(Duration::from_millis(500))
            .measurement_time(Duration::from_secs(2));
        bench_run(&mut group, "recorded", &s, Keep::Traced);
        group.finish();
    }
}

/// `ramp` over 5 s and 20 s: traced as the page runs it, every row kept, and recording off, in
/// one group.
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
        bench_run(
            &mut group,
            &format!("{seconds}s_recorded"),
            &s,
            Keep::Traced,
        );
        bench_run(
            &mut group,
            &format!("{seconds}s_checkpoints"),
            &s,
            Keep::Checkpoints,
        );
        bench_run(&mut group, &format!("{seconds}s_rows"), &s, Keep::Rows);
        bench_run(&mut group, &format!("{seconds}s_off"), &s, Keep::Off);
    }
    group.finish();
}

/// The paths that read a traced run: views, overlay, CSV, inspect.
fn view(c: &mut Criterion) {
    let s = scenario("v=1&preset=ramp&duration=5");
    let current = finished(&s);
    let pinned = finished(&scenario("v=1&preset=ramp&duration=5&seed=2"));
    let end = s.duration;
    let groups = page_groups();
    let speed = &groups[..1];

    let mut group = c.benchmark_group("view");
    group
        .sample_size(10)
        .warm_up_time(Duration::from_millis(500))
        .measurement_time(Duration::from_millis(1500));
    // The whole run at the overview's width (kept while running), and one pixel narrower
    // (replayed); 1 s around the ramp (bucketed); 20 ms (400 rows, sent whole).
    for (name, t0, t1, buckets) in [
        ("whole", 0.0, end, BUCKETS),
        ("whole_replayed", 0.0, end, BUCKETS - 1),
        ("zoom_1s", 0.0, 1.0, BUCKETS),
        ("zoom_20ms", 0.2, 0.22, BUCKETS),
    ] {
        group.bench_function(BenchmarkId::new("page_view", name), |b| {
            b.iter(|| current.view(black_box(&groups), t0, t1, buckets));
        });
    }
    group.bench_function(BenchmarkId::new("speed_plot", "zoom_1s"), |b| {
        b.iter(|| current.view(black_box(speed), 0.0, 1.0, BUCKETS));
    });
    group.bench_function(BenchmarkId::new("overlay", "whole"), |b| {
        b.iter(|| current.overlay(&[&pinned], black_box("omega"), 0.0, end, BUCKETS));
    });
    // As the page overlays a run with a pin once both keep the column (a run keeps it from its
    // start when runs are pinned, a pin from its own run, any run after one replay).
    let (mut current_kept, mut pinned_kept) = (current.clone(), pinned.clone());
    for s in [&mut current_kept, &mut pinned_kept] {
        s.keep_column("omega").expect("a column");
    }
    group.bench_function(BenchmarkId::new("overlay", "whole_kept"), |b| {
        b.iter(|| current_kept.overlay(&[&pinned_kept], black_box("omega"), 0.0, end, BUCKETS));
    });
    group.throughput(Throughput::Elements(CSV_ROWS as u64));
    let mut out = Vec::new();
    group.bench_function(BenchmarkId::new("csv", CSV_ROWS), |b| {
        b.iter(|| {
            out.clear();
            // From row 1: a chunk of the export without its header.
            current
                .write_csv_rows(&mut out, 1, CSV_ROWS)
                .expect("to a Vec");
            out.len()
        });
    });
    group.bench_function(BenchmarkId::new("inspect", "end_of_5s"), |b| {
        b.iter(|| current.inspect_at(black_box(end)).expect("inspects"));
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
        let checkpoints = rate(&format!("long/{seconds}s_checkpoints"), steps);
        let rows = rate(&format!("long/{seconds}s_rows"), steps);
        let off = rate(&format!("long/{seconds}s_off"), steps);
        for (name, r) in [
            ("recorded", recorded),
            ("checkpoints", checkpoints),
            ("rows", rows),
            ("off", off),
        ] {
            if let Some(r) = r {
                lines.push(format!(
                    "long/{seconds}s_{name:<17} {:>7.2} M steps/s {:>6.0}× real time",
                    r / 1e6,
                    r * ts
                ));
            }
        }
        if let (Some(recorded), Some(off)) = (recorded, off) {
            // The bar: at least 85 %.
            lines.push(format!(
                "long/{seconds}s recorded/off       {:>7.0} %",
                100.0 * recorded / off
            ));
        }
    }
    for id in [
        "page_view/whole",
        "page_view/whole_replayed",
        "page_view/zoom_1s",
        "page_view/zoom_20ms",
        "speed_plot/zoom_1s",
        "overlay/whole",
        "overlay/whole_kept",
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
