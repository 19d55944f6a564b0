//! Whether a final value had settled, on real runs: a slow decay that moves little over the last
//! tenth is still changing, a settled value with noise on it stays settled over seeds, a run that
//! ran away has no final value, and a step's settling time that the run did not reach says so.
#![cfg(not(target_arch = "wasm32"))]

use imlab::challenge::{judge, measure, Submission, BUILTINS};
use imlab::record::{Figure, Report, Trend, TrendState, WarningKind};
use imlab::scenario::Scenario;
use imlab::sim::Simulation;
use std::process::Command;

/// The noise seeds every claim here must hold on.
const SEEDS: std::ops::RangeInclusive<u64> = 1..=10;

/// A longer run tells what a value settles to: this many times the run's duration (capped at the
/// longest run accepted), as "settled" promises.
const LONGER: f64 = 4.0;

/// The longest run a scenario accepts (s).
const MAX_DURATION: f64 = 20.0;

/// How closely what an approach has still to go, read from three means, matches the decay a
/// longer run then shows (relative): the step's decay is that of a second-order loop, not a pure
/// exponential, so the ratio of its changes drifts from tenth to tenth.
const TO_GO_MATCH: f64 = 0.5;

/// The final values' names.
const FINALS: [&str; 3] = [
    "flux_error_final",
    "speed_error_final",
    "speed_estimate_error_final",
];

fn report(link: &str, longer: f64) -> Report {
    let mut s = Scenario::parse(link).unwrap_or_else(|e| panic!("{link}: {e}"));
    s.duration = (s.duration * longer).min(MAX_DURATION);
    let mut sim = Simulation::traced(&s).unwrap();
    sim.run().unwrap();
    sim.report()
}

fn figure<'a>(r: &'a Report, name: &str) -> &'a Figure {
    r.figures
        .iter()
        .flatten()
        .find(|f| f.name == name)
        .unwrap_or_else(|| panic!("no {name}"))
}

fn trend(r: &Report, name: &str) -> Trend {
    figure(r, name).trend.expect("a final value has a trend")
}

#[test]
fn a_slow_decay_that_moves_little_over_the_last_tenth_is_still_changing() {
    // The model's inertia 20 % above the motor's: after the step at 50 ms the speed error decays
    // with a time constant near 27 ms, so at 0.1 s it is 0.022 rad/s and moves only 0.008 rad/s
    // over the last 10 ms (within its 0.01 rad/s tolerance), yet it ends near −0.0006 rad/s.
    for seed in SEEDS {
        let link = format!("v=1&preset=step&model.j=0.024&seed={seed}");
        let r = report(&link, 1.0);
        let longer = report(&link, LONGER);
        for name in ["speed_error_final", "speed_estimate_error_final"] {
            let t = trend(&r, name);
            let (value, later) = (figure(&r, name).value, figure(&longer, name).value);
            assert!(
                (value - later).abs() > t.tolerance,
                "{link} {name}: {value} then {later}: it was still decaying"
            );
            assert!(
                (t.rate * t.over).abs() < t.tolerance && t.settled_in_last_tenth,
                "{link} {name}: the last tenth alone would not tell: {t:?}"
            );
            assert_eq!(t.state, TrendState::Changing, "{link} {name}: {t:?}");
            assert!(!t.settled);
            // What the approach has to go is the decay still to come.
            let to_go = t.to_go.expect("the means approach a value");
            assert!(
                to_go > t.tolerance && (to_go / (value - later).abs() - 1.0).abs() < TO_GO_MATCH,
                "{link} {name}: {to_go} to go against {} seen",
                (value - later).abs()
            );
        }
    }
}

#[test]
fn a_settled_value_ends_there_in_a_run_four_times_longer() {
    // Each run ends well after its slow modes: the rotor-resistance mismatch's (a time constant
    // near 0.6 s) by 6 s, the unknown load's fall (about a second) by 3 s, the step's by 0.1 s.
    // Their speed errors are settled on every seed; a value called settled, on any of these runs
    // and on the 200 Hz sine, ends within its tolerance in a run four times longer (at most
    // 20 s). The speed errors wander by up to 0.002 rad/s between seconds, which a line through
    // the last tenth alone would extrapolate well past the tolerance.
    let always = [
        "v=1&preset=rr-mismatch&duration=6",
        "v=1&preset=load-step&duration=3",
        "v=1&preset=step",
    ];
    for link in always.into_iter().chain(["v=1&preset=sine200"]) {
        for seed in SEEDS {
            let link = format!("{link}&seed={seed}");
            let r = report(&link, 1.0);
            let longer = report(&link, LONGER);
            for name in FINALS {
                let t = trend(&r, name);
                let (value, later) = (figure(&r, name).value, figure(&longer, name).value);
                if name == "speed_error_final" && always.iter().any(|a| link.starts_with(a)) {
                    assert_eq!(
                        t.state,
                        TrendState::Settled,
                        "{link} {name} = {value}: {t:?}"
                    );
                }
                if t.settled {
                    assert!(
                        (value - later).abs() <= t.tolerance,
                        "{link} {name}: {value} then {later}"
                    );
                }
            }
        }
    }
}

#[test]
fn the_200_hz_sines_final_speed_error_is_fluctuating_on_every_seed() {
    // Over the last tenth the error swings through whole periods of the sine by about twice its
    // 0.01 rad/s tolerance: its last sample does not stand for the run's end.
    for seed in SEEDS {
        let link = format!("v=1&preset=sine200&seed={seed}");
        let t = trend(&report(&link, 1.0), "speed_error_final");
        assert_eq!(t.state, TrendState::Fluctuating, "{link}: {t:?}");
        assert!(4.0 * t.scatter > t.tolerance, "{link}: {t:?}");
    }
}

#[test]
fn a_run_that_ran_away_has_no_settled_final_value() {
    // 1 rad/s with the rotor resistance 10 % off and an exact start: the estimates drift away
    // at low speed and the flux ends at 33 Wb against its 0.71 Wb target. The flux error's line
    // over the last tenth is flat: by the last tenth alone it would count as settled.
    let link = "v=1&preset=rr-mismatch&ref.value=1&ekf=rk4&init_err=0&duration=3";
    let r = report(link, 1.0);
    assert!(
        r.warnings.iter().any(|w| w.kind == WarningKind::Runaway),
        "{r:?}"
    );
    assert!(trend(&r, "flux_error_final").settled_in_last_tenth);
    for name in FINALS {
        let t = trend(&r, name);
        assert_eq!(
            (t.state, t.settled),
            (TrendState::RanAway, false),
            "{name}: {t:?}"
        );
    }
    // The command prints no final value as settled.
    let out = Command::new(env!("CARGO_BIN_EXE_imlab"))
        .args(["metrics", link])
        .output()
        .expect("imlab runs");
    assert!(!out.status.success());
    let text = String::from_utf8(out.stdout).unwrap();
    for name in FINALS {
        assert!(text.contains(&format!("\n{name}_settled,0,\n")), "{text}");
    }
}

#[test]
fn a_settling_time_not_reached_by_the_end_is_reported_as_such() {
    // With the model's inertia 20 % off, ω is still outside the step's 2 % band at 0.1 s.
    let link = "v=1&preset=step&model.j=0.024";
    let mut sim = Simulation::traced(&Scenario::parse(link).unwrap()).unwrap();
    sim.run().unwrap();
    let r = sim.report();
    let figures = r.figures.as_deref().unwrap();
    assert!(figures.iter().all(|f| f.name != "settling_time"));
    let [u] = r.unreached.as_slice() else {
        panic!("one unreached figure: {:?}", r.unreached)
    };
    assert_eq!(u.name, "settling_time");
    // In the settling time's place: after the tracking figures.
    assert_eq!(figures[u.index - 1].name, "tracking_peak");
    assert_eq!(figures[u.index].name, "saturated_share");
    assert_eq!(u.window.to_string(), "from the step at 50 ms");
    assert_eq!(u.end, sim.time(sim.len() - 1));
    assert_eq!(
        u.text.to_string(),
        "not settled by the end of the run (t = 99.95 ms)"
    );
    // The command says so in its place, and prints no settling time.
    let out = Command::new(env!("CARGO_BIN_EXE_imlab"))
        .args(["metrics", link])
        .output()
        .expect("imlab runs");
    assert!(out.status.success());
    let text = String::from_utf8(out.stdout).unwrap();
    assert!(
        text.contains("\ntracking_peak,")
            && text.contains(",rad/s\nsettling_time_reached,0,\nsaturated_share,"),
        "{text}"
    );
    assert!(!text.contains("\nsettling_time,"), "{text}");
    // Run long enough, the same step settles and has a settling time; the paper's step settles
    // within its run.
    for link in ["v=1&preset=step&model.j=0.024&duration=0.3", "step"] {
        let r = report(link, 1.0);
        assert!(r.unreached.is_empty(), "{link}: {:?}", r.unreached);
        figure(&r, "settling_time");
    }
}

#[test]
fn a_challenge_judges_final_values_by_the_last_tenth_as_its_brief_states() {
    // "A final value counts only if it has settled: a value still changing over the last tenth
    // of the run fails." The slow decay above moves by less than its tolerance over the last
    // tenth, so a challenge counts it as settled, though the figures call it still changing.
    let s = Scenario::parse("v=1&preset=step&model.j=0.024").unwrap();
    let mut sim = Simulation::traced(&s).unwrap();
    sim.run().unwrap();
    let m = measure(&sim);
    assert_eq!(m.get("speed_error_final").unwrap().settled, Some(true));
    assert!(!trend(&sim.report(), "speed_error_final").settled);
    // The untouched base of the load challenge is 25 rad/s low and still falling at its 1 s end
    // (the figures say still changing), and fails on the bound, as it always has.
    let b = BUILTINS.iter().find(|b| b.name == "load-observer").unwrap();
    let base = Submission::parse(b.text).unwrap();
    let runs: Vec<_> = base
        .scenarios()
        .unwrap()
        .iter()
        .map(|sc| {
            let mut sim = Simulation::traced(sc).unwrap();
            sim.run().unwrap();
            assert!(!trend(&sim.report(), "speed_error_final").settled);
            measure(&sim)
        })
        .collect();
    let v = judge(&base.challenge, &runs).unwrap();
    let c = v
        .criteria
        .iter()
        .find(|c| c.figure == "speed_error_final")
        .unwrap();
    let reason = c.reason.as_ref().map(|r| r.to_string());
    assert_eq!(
        (c.pass, reason.as_deref()),
        (false, Some("beyond the bound"))
    );
}

#[test]
fn states_causes_and_kinds_reach_the_page_by_their_names() {
    assert_eq!(
        [
            TrendState::Settled,
            TrendState::Changing,
            TrendState::Fluctuating,
            TrendState::RanAway
        ]
        .map(|s| json(&s)),
        [
            "\"settled\"",
            "\"changing\"",
            "\"fluctuating\"",
            "\"ran away\""
        ]
    );
    use imlab::record::StabilityCause as C;
    assert_eq!(
        [
            C::None,
            C::Saturation,
            C::Sampling,
            C::EstimationErrors,
            C::EpsOrSampling
        ]
        .map(|c| json(&c)),
        [
            "\"none\"",
            "\"saturation\"",
            "\"sampling\"",
            "\"estimation_errors\"",
            "\"eps_or_sampling\""
        ]
    );
    assert_eq!(
        [WarningKind::Runaway, WarningKind::Inconsistent].map(|k| json(&k)),
        ["\"runaway\"", "\"inconsistent\""]
    );
}

/// `value` as JSON, as the bindings hand it to the page.
fn json(value: &impl serde::Serialize) -> String {
    serde_json::to_string(value).unwrap()
}

#[test]
fn a_value_that_follows_a_random_walk_estimate_is_drifting() {
    // With the load as a random-walk state, the final speed error wanders with its estimate:
    // seed 1 ends at −0.012 rad/s at 0.3 s and at +0.018 at 1.2 s, past the 0.01 tolerance; with
    // R_r as one, at 0.017 rad/s at 4 s and at 0.030 at 16 s.
    for link in [
        "v=1&preset=load-step-est",
        "v=1&preset=rr-mismatch-est&duration=4",
    ] {
        let r = report(link, 1.0);
        let t = trend(&r, "speed_error_final");
        assert!(
            matches!(t.state, TrendState::Drifting | TrendState::Fluctuating),
            "{link}: {t:?}"
        );
        assert!(!t.settled);
        // And the line through its last tenth would have called it settled: it is the random
        // walk that the state names, which a run four times longer shows.
        assert!(t.settled_in_last_tenth, "{link}: {t:?}");
        let (value, later) = (
            figure(&r, "speed_error_final").value,
            figure(&report(link, LONGER), "speed_error_final").value,
        );
        assert!(
            (value - later).abs() > t.tolerance,
            "{link}: {value} then {later}"
        );
    }
}

#[test]
fn no_seeds_strip_reads_a_start_up_peak_as_the_runs_current() {
    // The paper's step draws 2.8–3.0 A once started on seeds 1–30; the EKF's start-up draws up
    // to 6 A just after 4.2 ms on some seeds (seed 7: 5.4 A), while a 2 ms window or two of low
    // NIS come and go: the start-up ends only once the NIS and the flux estimate stay at their
    // later level. On the 200 Hz sines the Euler EKF's NIS stays high throughout, and its
    // start-up drew up to 9.6 A (0.5 rad/s) and 16.4 A (1 rad/s) against 6.6 and 12.8 A once
    // over; on load-step, whose speed starts 10 % off at 50 rad/s, up to 11 A against 2.3 A: the
    // speed estimate's start-up, and the controller's after it, end those.
    for preset in ["step", "sine200", "sine200-1rad", "load-step"] {
        let peaks: Vec<f64> = (1..=30)
            .map(|seed| {
                let r = report(&format!("v=1&preset={preset}&seed={seed}"), 1.0);
                figure(&r, "current_peak").value
            })
            .collect();
        let least = peaks.iter().copied().fold(f64::INFINITY, f64::min);
        let most = peaks.iter().copied().fold(0.0, f64::max);
        assert!(most < 1.1 * least, "{preset}: {least} to {most}: {peaks:?}");
    }
}
