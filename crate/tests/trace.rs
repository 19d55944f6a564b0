//! Traced runs keep checkpoints instead of rows and replay them for every read: each read must
//! give, bit for bit, what a run that keeps every row gives, and the trace must stay small.

use imlab::record::CHECKPOINT_EVERY;
use imlab::scenario::{preset, Scenario, PRESETS};
use imlab::sim::{self, Simulation};

fn both(s: &Scenario) -> (Simulation, Simulation) {
    let mut rows = Simulation::new(s, 1).unwrap();
    let mut traced = Simulation::traced(s).unwrap();
    assert_eq!(rows.run(), traced.run());
    (rows, traced)
}

fn groups(names: &[&[&str]]) -> Vec<Vec<String>> {
    names
        .iter()
        .map(|g| g.iter().map(|n| n.to_string()).collect())
        .collect()
}

/// Every read of a traced run equals the same read of a run that keeps its rows: the CSV, the
/// figures and transient, metrics, the Lyapunov comparison, views of any window, inspect.
#[test]
fn every_read_of_a_traced_run_equals_the_kept_rows_bit_for_bit() {
    let view_groups = groups(&[
        &["omega", "omega_hat", "omega_ref"],
        &["nis"],
        &["u_a", "u_b_cmd"],
    ]);
    for p in PRESETS {
        let s = preset(p.name).unwrap();
        let (rows, traced) = both(&s);
        assert_eq!(rows.len(), traced.len(), "{}", p.name);
        assert_eq!(rows.csv(), traced.csv(), "{}", p.name);
        assert_eq!(
            format!("{:?}", rows.report()),
            format!("{:?}", traced.report()),
            "{}",
            p.name
        );
        assert_eq!(
            format!("{:?}", rows.metrics()),
            format!("{:?}", traced.metrics())
        );
        assert_eq!(
            format!("{:?}", rows.stability()),
            format!("{:?}", traced.stability())
        );
        let end = s.duration;
        for (t0, t1, buckets) in [
            (0.0, end, 1000),
            (0.0, end, 7),
            (0.3 * end, 0.31 * end, 500),
            (0.5 * end, end, 3),
        ] {
            assert_eq!(
                rows.view(&view_groups, t0, t1, buckets),
                traced.view(&view_groups, t0, t1, buckets),
                "{} {t0}–{t1} s",
                p.name
            );
        }
        for t in [0.0, 0.37 * end, end] {
            let a = Simulation::inspect(&s, t).unwrap();
            let b = traced.inspect_at(t).unwrap();
            assert_eq!(format!("{a:?}"), format!("{b:?}"), "{} at {t} s", p.name);
        }
    }
}

/// Chunks of a traced run's CSV start anywhere (each replays from its checkpoint) and
/// concatenate to the whole CSV; the overview kept while running equals the replayed view.
#[test]
fn csv_chunks_and_the_kept_overview_equal_the_whole() {
    let s = preset("ramp").unwrap();
    let g = groups(&[&["omega", "z1"], &["i_sa", "i_sb", "nis"]]);
    let mut traced = Simulation::traced(&s).unwrap();
    traced.keep_overview(&g, 640).unwrap();
    traced.run().unwrap();
    let whole = traced.csv().into_bytes();
    let mut chunks = Vec::new();
    for start in (0..traced.len()).step_by(CHECKPOINT_EVERY + 777) {
        traced
            .write_csv_rows(&mut chunks, start, CHECKPOINT_EVERY + 777)
            .unwrap();
    }
    assert_eq!(chunks, whole);
    let rows = Simulation::new(&s, 1).map(|mut r| {
        r.run().unwrap();
        r
    });
    let rows = rows.unwrap();
    assert_eq!(
        traced.view(&g, 0.0, f64::INFINITY, 640),
        rows.view(&g, 0.0, f64::INFINITY, 640)
    );
    // Too late to keep an overview once the run has started.
    assert!(traced.keep_overview(&g, 640).is_err());
    assert!(traced.view(&groups(&[&["nope"]]), 0.0, 1.0, 10).is_err());
}

/// Overlays of traced runs (each replayed in lockstep) equal those of runs that keep rows,
/// including a run shorter than the others.
#[test]
fn overlays_of_traced_runs_equal_those_of_kept_rows() {
    let a = Scenario::parse("v=1&preset=sine200&duration=0.3").unwrap();
    let b = Scenario::parse("v=1&preset=sine200&duration=0.3&seed=5").unwrap();
    let c = Scenario::parse("v=1&preset=sine200&duration=0.2&ekf=rk4").unwrap();
    let (ra, ta) = both(&a);
    let (rb, tb) = both(&b);
    let (rc, tc) = both(&c);
    for (t0, t1, buckets) in [(0.0, 1.0, 800), (0.05, 0.06, 800), (0.1, 0.25, 13)] {
        let kept = ra.overlay(&[&rb, &rc], "omega", t0, t1, buckets).unwrap();
        let replayed = ta.overlay(&[&tb, &tc], "omega", t0, t1, buckets).unwrap();
        assert_eq!(kept, replayed, "{t0}–{t1} s");
        // The differences are sample by sample: a − b at each emitted row.
        for j in 0..kept[0].len() {
            assert_eq!(kept[4][j], kept[1][j] - kept[2][j]);
        }
    }
    assert!(ta.overlay(&[&tb], "nope", 0.0, 1.0, 10).is_err());
}

/// A traced run that keeps the overlay's column, from its start, by a replay once it has ended
/// (a failed run too, even one that failed after its first sample), or by a replay partway and
/// then as it goes on, gives the same overlay as runs that keep their rows; asking for another
/// column replays the rows again and keeps that one.
#[test]
fn overlays_from_kept_columns_equal_those_of_kept_rows() {
    let a = Scenario::parse("v=1&preset=sine200&duration=0.3").unwrap();
    let b = Scenario::parse("v=1&preset=sine200&duration=0.3&k1=300").unwrap();
    // A 10 kN m load step at 0.1 s: the flux leaves its bounds at 0.16 s.
    let failing =
        Scenario::parse("v=1&preset=sine200&duration=0.3&load.torque=10000&load.time=0.1").unwrap();
    // The same load on a motor a million times lighter: the speed leaves its bounds after the
    // first sample, which is the run's only row.
    let at_once = Scenario::parse(
        "v=1&preset=sine200&duration=0.3&plant.j=1e-6&load.torque=10000&load.time=0",
    )
    .unwrap();
    let (ra, _) = both(&a);
    let (rb, _) = both(&b);
    let (rf, _) = both(&failing);
    let (r0, _) = both(&at_once);
    assert!(
        rf.failure().is_some() && rf.len() > 100,
        "the third run fails after some rows"
    );
    assert!(
        r0.failure().is_some() && r0.len() == 1,
        "the fourth run fails after one row"
    );
    let mut ta = Simulation::traced(&a).unwrap();
    ta.keep_column("omega").unwrap();
    let bytes = ta.recording_bytes();
    let (mut tb, mut tf) = (
        Simulation::traced(&b).unwrap(),
        Simulation::traced(&failing).unwrap(),
    );
    let mut t0 = Simulation::traced(&at_once).unwrap();
    // Kept partway: the rows so far replayed, the rest as the run goes on.
    tb.advance(1000).unwrap();
    tb.keep_column("omega").unwrap();
    assert!(ta.run().is_ok() && tb.run().is_ok() && tf.run().is_err() && t0.run().is_err());
    // The whole run's column is reserved before it starts: 8 bytes a sample.
    assert_eq!(
        bytes - Simulation::traced(&a).unwrap().recording_bytes(),
        8 * a.steps()
    );
    for column in ["omega", "u_a", "omega"] {
        for s in [&mut ta, &mut tb, &mut tf, &mut t0] {
            s.keep_column(column).unwrap();
        }
        for (t_0, t_1, buckets) in [(0.0, 1.0, 800), (0.05, 0.06, 800), (0.1, 0.25, 13)] {
            let kept = ra.overlay(&[&rb, &rf], column, t_0, t_1, buckets).unwrap();
            let read = ta.overlay(&[&tb, &tf], column, t_0, t_1, buckets).unwrap();
            assert_eq!(kept, read, "{column} {t_0}–{t_1} s");
        }
        let kept = ra.overlay(&[&r0], column, 0.0, 1.0, 800).unwrap();
        assert_eq!(
            kept,
            ta.overlay(&[&t0], column, 0.0, 1.0, 800).unwrap(),
            "{column}"
        );
        assert_eq!(kept[0].len(), 1, "one common row");
    }
    assert!(ta.keep_column("nope").is_err());
}

/// A run that fails keeps, traced or not, the same rows before its failure and replays them.
#[test]
fn a_failed_traced_run_reads_the_rows_before_its_failure() {
    for text in [
        "v=1&preset=step&ts=0.001&vmax=100000",
        "v=1&preset=ifoc-step&robust=1&h2=1e9&eps2=5e-324",
    ] {
        let s = Scenario::parse(text).unwrap();
        let (rows, traced) = both(&s);
        assert!(traced.failure().is_some(), "{text}");
        assert_eq!(rows.len(), traced.len(), "{text}");
        assert_eq!(rows.csv(), traced.csv(), "{text}");
        assert_eq!(
            format!("{:?}", rows.report()),
            format!("{:?}", traced.report()),
            "{text}"
        );
    }
}

/// The trace of a traced run: one checkpoint every CHECKPOINT_EVERY samples, under 1 MB per
/// simulated second at 20 kHz (a row trace takes 63 × 8 bytes a sample, 10 MB a second).
#[test]
fn a_traced_run_keeps_under_a_megabyte_per_simulated_second() {
    for text in [
        "v=1&preset=ramp&duration=5",
        "v=1&preset=load-step-est&duration=5",
    ] {
        let s = Scenario::parse(text).unwrap();
        let mut traced = Simulation::traced(&s).unwrap();
        traced.run().unwrap();
        let per_second = traced.recording_bytes() as f64 / s.duration;
        assert!(per_second < 1e6, "{text}: {per_second} B/s");
        // The row trace it replaces.
        assert!(sim::trace_bytes(&s, 1) as f64 / s.duration > 9e6);
    }
}
