//! The settling check of frequency sweeps: a run too short to reach a periodic steady state is
//! flagged and never read as a bandwidth; a run that has settled is not flagged.

use imlab::analysis::{summarise, sweep_point, SweepSettings, SETTLED_GAIN_DB, SETTLED_PHASE_DEG};
use imlab::scenario::preset;
use imlab::text::Arg;

#[test]
fn ifoc_runs_too_short_to_reach_their_operating_speed_are_flagged_and_give_no_bandwidth() {
    // The MRAS starts 10 % off, and the speed still rings by about ±1.5 rad/s at 14 Hz when the
    // default 0.2 s runs end: 75 times the 0.02 rad/s sine. The fits of the two halves differ by
    // dB, and the measured gain falls through 1/√2 between these two points (the 388 Hz
    // "bandwidth" of `imlab sweep ifoc-step --offset 40`).
    let ifoc = preset("ifoc-step").unwrap();
    let short = SweepSettings {
        offset: 40.0,
        ..SweepSettings::default()
    };
    let points = [300.0, 480.0].map(|f| sweep_point(&ifoc, f, &short).unwrap());
    let cutoff = std::f64::consts::FRAC_1_SQRT_2;
    assert!(
        points[0].gain >= cutoff && points[1].gain < cutoff,
        "{points:?}"
    );
    for p in &points {
        assert!(p.gain_change_db.abs() > SETTLED_GAIN_DB, "{p:?}");
        assert!(
            matches!(&p.unsettled, Some(Arg::Said(m)) if m.to_string().contains("not settled")),
            "{p:?}"
        );
    }
    let s = summarise(&points);
    assert!(
        s.bandwidth.is_none() && s.bandwidth_unsettled && !s.below_grid,
        "{s:?}"
    );
    assert_eq!(s.unsettled, 2);

    // The same frequencies in 3 s runs (the IFOC sweep of docs/figures.md) settle.
    let long = SweepSettings {
        amp: 0.05,
        duration: 3.0,
        offset: 40.0,
    };
    for f in [300.0, 480.0] {
        let p = sweep_point(&ifoc, f, &long).unwrap();
        assert!(p.unsettled.is_none(), "{p:?}");
    }
}

#[test]
fn a_backstepping_point_of_the_default_sweep_settles_within_the_noise() {
    // The designed error dynamics decay at 1200/s, so well before the fit window; what is left
    // between the halves is the measurement noise's share of a 0.02 rad/s sine.
    let step = preset("step").unwrap();
    for f in [42.8, 183.3] {
        let p = sweep_point(&step, f, &SweepSettings::default()).unwrap();
        assert!(p.unsettled.is_none(), "{p:?}");
        assert!(
            p.gain_change_db.abs() < 0.5 * SETTLED_GAIN_DB
                && p.phase_change.abs() < 0.5 * SETTLED_PHASE_DEG,
            "{p:?}"
        );
    }
}

#[test]
fn the_saturated_share_of_a_point_is_against_the_scenarios_own_limit() {
    // 0.5 rad/s at 250 Hz needs about 350 V: inside the paper's ±400 V box, beyond the 312 V
    // that the hexagon of a 540 V link allows in every direction.
    let settings = SweepSettings {
        amp: 0.5,
        ..SweepSettings::default()
    };
    let share = |text: &str| {
        let s = imlab::scenario::Scenario::parse(text).unwrap();
        sweep_point(&s, 250.0, &settings).unwrap().saturated
    };
    let (boxed, hex) = (
        share("sine200"),
        share("v=1&preset=sine200&vlimit=hex&vdc=540"),
    );
    assert!(boxed < 0.01 && hex > 0.3, "box {boxed}, hex {hex}");
}

#[test]
fn the_peak_current_of_a_point_is_the_largest_stator_current_of_its_fit_window() {
    // The same run as an ordinary scenario: 10 whole periods of 100 Hz in the second half of
    // 0.2 s, so the fit window starts at 0.1 s.
    let step = preset("step").unwrap();
    let point = sweep_point(&step, 100.0, &SweepSettings::default()).unwrap();
    let s = imlab::scenario::Scenario::parse(
        "v=1&preset=step&ref=sine&sine.amp=0.02&sine.freq=100&sine.offset=0&duration=0.2",
    )
    .unwrap();
    let mut sim = imlab::sim::Simulation::new(&s, 1).unwrap();
    sim.run().unwrap();
    let rows = sim.recorder().rows();
    let magnitude = |r: &imlab::record::Row| (r.i_sa * r.i_sa + r.i_sb * r.i_sb).sqrt();
    let window = rows.iter().filter(|r| r.t >= 0.1 - 0.5 * s.ts);
    let peak = window.map(magnitude).fold(0.0, f64::max);
    assert_eq!(point.peak_current, peak);
    // The start (|i_s(0)| = 2√2 A) lies outside the window and is larger: the window decides.
    assert!(magnitude(&rows[0]) > peak, "{peak}");
    assert_eq!(point.rated_current, s.i_rated);
}

#[test]
fn an_amplitude_too_small_to_measure_is_refused_naming_it() {
    let step = preset("step").unwrap();
    // Its square underflows; against a 100 rad/s offset it rounds away; both before any run.
    for (amp, offset) in [(1e-200, 0.0), (1e-20, 100.0)] {
        let settings = SweepSettings {
            amp,
            duration: 0.05,
            offset,
        };
        let err = sweep_point(&step, 100.0, &settings)
            .unwrap_err()
            .to_string();
        assert!(
            err.contains(&format!("'sine.amp' = {amp:e}")) && err.contains("can measure"),
            "{err}"
        );
    }
    // Tiny but resolved amplitudes are measured, with finite figures.
    let settings = SweepSettings {
        amp: 1e-9,
        duration: 0.05,
        offset: 0.0,
    };
    let p = sweep_point(&step, 100.0, &settings).unwrap();
    assert!(p.gain_db.is_finite() && p.phase.is_finite(), "{p:?}");
}
