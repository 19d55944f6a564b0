//! `imlab metrics`: the figures of a run as the CLI prints them, checked against the physics
//! (settling through the reference filter, saturation, EKF consistency) and against the library.

use imlab::scenario::Scenario;
use imlab::sim::{figures, Simulation};
use std::process::Command;

/// Runs `imlab metrics SCENARIO` and returns its (name, value, unit) lines after the header.
fn metrics(scenario: &str) -> Vec<(String, f64, String)> {
    let out = Command::new(env!("CARGO_BIN_EXE_imlab"))
        .args(["metrics", scenario])
        .output()
        .expect("imlab runs");
    assert!(
        out.status.success(),
        "imlab metrics {scenario}: {}",
        String::from_utf8_lossy(&out.stderr)
    );
    let text = String::from_utf8(out.stdout).expect("UTF-8 output");
    let mut lines = text.lines();
    assert_eq!(lines.next(), Some("name,value,unit"));
    lines
        .map(|line| {
            let fields: Vec<&str> = line.split(',').collect();
            assert_eq!(fields.len(), 3, "{scenario}: '{line}'");
            let value: f64 = fields[1]
                .parse()
                .unwrap_or_else(|_| panic!("{scenario}: '{line}'"));
            assert!(value.is_finite(), "{scenario}: '{line}'");
            (fields[0].to_string(), value, fields[2].to_string())
        })
        .collect()
}

fn get(lines: &[(String, f64, String)], name: &str) -> Option<f64> {
    lines.iter().find(|l| l.0 == name).map(|l| l.1)
}

/// The reference filter ω_n²/(s + ω_n)² at ω_n = 2π·200 rad/s reaches 98 % after 4.6 ms; the
/// 1200/s loop adds a few tenths of a millisecond.
const STEP_SETTLING: (f64, f64) = (4.6e-3, 5.0e-3);

#[test]
fn step_figures_show_the_filter_settling_and_a_consistent_ekf() {
    let m = metrics("step");
    let settling = get(&m, "settling_time").expect("a step has a settling time");
    assert!(
        (STEP_SETTLING.0..=STEP_SETTLING.1).contains(&settling),
        "2 % settling time {settling} s"
    );
    assert_eq!(get(&m, "saturated_share"), Some(0.0));
    // The EKF's estimates, 10 % off at the start, converge after the controller's 5/1200 s:
    // about 10 ms.
    let end = get(&m, "transient_end").unwrap();
    assert!((5e-3..=15e-3).contains(&end), "transient ends at {end} s");
    let (low, high) = (
        get(&m, "mean_nis_low").unwrap(),
        get(&m, "mean_nis_high").unwrap(),
    );
    assert!(low < 2.0 && 2.0 < high, "band [{low}, {high}]");
    // After the transient the paper's EKF is consistent at the step's low speeds.
    let nis = get(&m, "mean_nis").unwrap();
    assert!(
        (low..=high).contains(&nis),
        "mean NIS {nis} outside [{low}, {high}]"
    );
    let units: Vec<(&str, &str)> = m.iter().map(|l| (l.0.as_str(), l.2.as_str())).collect();
    assert_eq!(
        units,
        [
            ("transient_end", "s"),
            ("tracking_rms", "rad/s"),
            ("tracking_peak", "rad/s"),
            ("settling_time", "s"),
            ("saturated_share", ""),
            ("mean_nis", ""),
            ("mean_nis_low", ""),
            ("mean_nis_high", ""),
            ("current_peak", "A"),
            ("current_rms", "A"),
            ("current_rated", "A"),
            ("flux_error_final", "Wb"),
            ("speed_error_final", "rad/s"),
            ("speed_estimate_error_final", "rad/s"),
        ]
    );
}

#[test]
fn one_rad_at_200_hz_saturates_and_a_ramp_has_no_settling_time() {
    let share = get(&metrics("sine200-1rad"), "saturated_share").unwrap();
    assert!(share > 0.0 && share < 1.0, "saturated share {share}");
    let ramp = metrics("ramp");
    assert_eq!(get(&ramp, "settling_time"), None);
    assert!(get(&ramp, "tracking_rms").is_some());
}

#[test]
fn printed_figures_are_the_library_figures_exactly() {
    for text in ["step", "ifoc-step"] {
        let printed = metrics(text);
        let mut sim = Simulation::new(&Scenario::parse(text).unwrap(), 1).unwrap();
        sim.run().unwrap();
        let lib = figures(&sim).unwrap();
        assert_eq!(printed.len(), lib.len(), "{text}");
        for (p, f) in printed.iter().zip(&lib) {
            assert_eq!((p.0.as_str(), p.2.as_str()), (f.name, f.unit), "{text}");
            // `{}` prints the shortest string that parses back to the same f64.
            assert!(
                p.1 == f.value,
                "{text}: {} printed {} ≠ {}",
                f.name,
                p.1,
                f.value
            );
        }
    }
}

#[test]
fn a_diverged_run_prints_the_figures_before_the_failure_and_fails() {
    // 1 kHz sampling with 1200/s gains (k·Ts = 1.2) and no voltage limit runs away.
    let text = "v=1&preset=step&ts=0.001&vmax=100000";
    let out = Command::new(env!("CARGO_BIN_EXE_imlab"))
        .args(["metrics", text])
        .output()
        .expect("imlab runs");
    assert!(!out.status.success());
    let stderr = String::from_utf8_lossy(&out.stderr);
    assert!(stderr.contains("diverged"), "{stderr}");
    let mut sim = Simulation::new(&Scenario::parse(text).unwrap(), 1).unwrap();
    sim.run().unwrap_err();
    let mut expected = String::from("name,value,unit\n");
    for f in figures(&sim).expect("samples before the failure") {
        expected.push_str(&format!("{},{},{}\n", f.name, f.value, f.unit));
    }
    assert_eq!(String::from_utf8_lossy(&out.stdout), expected);
}
