//! Only finite numbers are recorded: settings at the edges of every field's range give either a
//! named refusal or a trace of finite numbers (a run that would record inf or NaN stops, naming
//! the column). The first three cases are the ones that once wrote inf or NaN into the CSV.

use imlab::scenario::Scenario;
use imlab::sim::{SimError, Simulation};

/// Runs `text`; returns the parse error, or the run's result with the trace checked finite.
fn run(text: &str) -> Result<Result<(), SimError>, String> {
    let s = Scenario::parse(text).map_err(|e| e.to_string())?;
    let mut sim = Simulation::new(&s, 1).map_err(|e| e.to_string())?;
    let result = sim.run();
    for row in sim.recorder().rows() {
        assert!(
            row.values().iter().all(|v| v.is_finite()),
            "{text}: a recorded row is not finite: {row:?}"
        );
    }
    Ok(result)
}

#[test]
fn robust_terms_that_overflow_stop_the_run_naming_the_column() {
    // In IFOC mode the backstepping terms are only recorded, so the recorder catches them.
    for text in [
        "v=1&preset=ifoc-step&robust=1&h2=1e9&eps2=5e-324",
        "v=1&preset=ifoc-step&robust=1&h4=1e9&eps4=5e-324",
    ] {
        let err = run(text).expect("valid scenario").expect_err(text);
        assert!(
            matches!(err, SimError::NotFinite { t, .. } if t == 0.0),
            "{text}: {err}"
        );
        assert!(err.to_string().contains("column 'v"), "{text}: {err}");
    }
    // With backstepping driving, the infinite command itself stops the run.
    let text = "v=1&preset=step&robust=1&h2=1e9&eps2=5e-324";
    let err = run(text).expect("valid scenario").expect_err(text);
    assert!(
        err.to_string().contains("commanded u_sa = -inf"),
        "{text}: {err}"
    );
}

#[test]
fn a_numerically_zero_r_or_inertia_is_refused_with_its_range() {
    for (text, field, range) in [
        (
            "v=1&preset=step&ekf.r_std=1e-200&ekf.q=5e-324",
            "'ekf.r_std'",
            "0.000001 ≤ ekf.r_std ≤ 10 (A)",
        ),
        (
            "v=1&preset=step&model.j=1e-155",
            "'model.j'",
            "0.000001 ≤ model.j ≤ 10000 (kg m²)",
        ),
        (
            "v=1&preset=step&plant.j=1e-155",
            "'plant.j'",
            "0.000001 ≤ plant.j",
        ),
    ] {
        let err = run(text).expect_err(text);
        assert!(err.contains(field) && err.contains(range), "{text}: {err}");
    }
}

/// The smallest value a field takes: its minimum, or the next number above an open minimum.
fn lowest(min: f64, open: bool) -> f64 {
    if !open {
        min
    } else if min == 0.0 {
        f64::from_bits(1) // 5e-324, the smallest positive number
    } else {
        f64::from_bits(min.to_bits() + 1)
    }
}

#[test]
fn every_field_at_the_edges_of_its_range_gives_a_named_error_or_finite_numbers() {
    let bases = [
        "v=1&preset=step",
        "v=1&preset=step&robust=1&h2=1&h4=1",
        "v=1&preset=ifoc-step",
        "v=1&preset=decay",
        "v=1&preset=sine200&ekf=rk4",
    ];
    let (mut runs, mut refused, mut stopped) = (0, 0, 0);
    for base in bases {
        let fields = Scenario::parse(base).unwrap().describe();
        for f in fields
            .iter()
            .filter(|f| f.options.is_empty() && f.value.is_some())
        {
            for value in [lowest(f.min, f.min_open), f.max] {
                // Short runs, except where the field is the length of the run itself.
                let length = if matches!(f.key, "duration" | "ts") {
                    ""
                } else {
                    "&duration=0.01"
                };
                let text = format!("{base}{length}&{}={value:e}", f.key);
                match run(&text) {
                    Err(message) => {
                        refused += 1;
                        assert!(
                            message.contains("field '")
                                || message.contains("parameters:")
                                || message.contains("'duration'"),
                            "{text}: {message}"
                        )
                    }
                    Ok(Err(e)) => {
                        stopped += 1;
                        // The stop names what stopped it: a column, a signal or the decoupling.
                        let message = e.to_string();
                        assert!(
                            message.contains("column '")
                                || message.contains("left its bounds")
                                || message.contains("decoupling matrix (55)"),
                            "{text}: {message}"
                        )
                    }
                    Ok(Ok(())) => runs += 1,
                }
            }
        }
    }
    println!("edges of every field: {runs} finished, {stopped} stopped with a named error, {refused} refused");
    assert!(
        runs > 100 && stopped > 0,
        "{runs} finished, {stopped} stopped"
    );
}
