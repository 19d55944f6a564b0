//! The measurements the teaching text states: each a figure of a scenario over a sample of noise
//! seeds, reduced by a statistic. The lessons name these measurements instead of typing numbers,
//! `imlab claims` computes them, and the tests recompute the table and fail on any difference.
//!
//! A table is CSV with the header `id,scenario,figure,seeds,statistic,show,value`:
//!
//! - `scenario`: a scenario string, or two joined by ` / ` for their ratio, seed by seed;
//! - `figure`: what is read from each run (see [`Probe`]);
//! - `seeds`: `A..B` (each run with noise seeds A to B), or `-` for the scenario's own seed;
//! - `statistic`: how the seeds' values become one number (see [`Statistic`]);
//! - `show`: how the text shows it (the page's business, kept as written);
//! - `value`: the measured number, in the shortest form that reads back to the same bits.

mod measure;
mod probe;

use crate::scenario::Scenario;
pub use measure::{measure_run, RunValues};
pub use probe::{Probe, Statistic, Time, WindowKind};
use std::collections::BTreeMap;

/// The header of a measurements table.
pub const HEADER: &str = "id,scenario,figure,seeds,statistic,show,value";

/// One row of a table: a measurement and, once taken, its value.
#[derive(Clone, Debug, PartialEq)]
pub struct Measurement {
    /// The name the text uses.
    pub id: String,
    /// The scenario strings as written (two for a ratio).
    pub scenarios: Vec<String>,
    /// The scenario column as written.
    pub scenario_text: String,
    /// The figure column as written.
    pub figure_text: String,
    /// What each run gives.
    pub probe: Probe,
    /// The noise seeds, or None for the scenario's own.
    pub seeds: Option<std::ops::RangeInclusive<u64>>,
    /// The seeds column as written.
    pub seeds_text: String,
    /// How the runs' values become one.
    pub statistic: Statistic,
    /// The statistic column as written.
    pub statistic_text: String,
    /// How the text shows it, as written.
    pub show: String,
    /// The value column as written (empty before the first measurement).
    pub value: String,
}

/// Most runs one measurement may take: a sample of seeds is for the text's ranges, not a study.
const MAX_SEEDS: u64 = 200;

fn parse_seeds(text: &str) -> Result<Option<std::ops::RangeInclusive<u64>>, String> {
    if text == "-" {
        return Ok(None);
    }
    let bad = || format!("'{text}' is not a sample: expected A..B (seeds A to B) or -");
    let (a, b) = text.split_once("..").ok_or_else(bad)?;
    let (a, b) = (
        a.parse::<u64>().map_err(|_| bad())?,
        b.parse::<u64>().map_err(|_| bad())?,
    );
    if a > b || b - a >= MAX_SEEDS {
        return Err(format!(
            "'{text}': expected 1 to {MAX_SEEDS} seeds, the first no larger than the last"
        ));
    }
    Ok(Some(a..=b))
}

/// Reads a measurements table; an error names the line and the field at fault.
pub fn parse_table(text: &str) -> Result<Vec<Measurement>, String> {
    let mut lines = text.lines().enumerate();
    match lines.next() {
        Some((_, h)) if h == HEADER => {}
        Some((_, h)) => {
            return Err(format!(
                "line 1 is '{}': expected the header '{HEADER}'",
                crate::text::excerpt(h)
            ))
        }
        None => {
            return Err(format!(
                "the table is empty: expected the header '{HEADER}'"
            ))
        }
    }
    let mut out: Vec<Measurement> = Vec::new();
    for (i, line) in lines {
        if line.trim().is_empty() {
            continue;
        }
        let at = |e: String| format!("line {}: {e}", i + 1);
        let cells: Vec<&str> = line.split(',').collect();
        let [id, scenario, figure, seeds, statistic, show, value] = cells[..] else {
            return Err(at(format!("{} fields, expected 7", cells.len())));
        };
        if id.is_empty()
            || !id
                .chars()
                .all(|c| c.is_ascii_alphanumeric() || "._".contains(c))
        {
            return Err(at(format!(
                "the id '{id}' must be letters, digits, '.' or '_'"
            )));
        }
        if out.iter().any(|m| m.id == id) {
            return Err(at(format!("the id '{id}' is already used")));
        }
        let scenarios: Vec<String> = scenario.split(" / ").map(str::to_string).collect();
        if scenarios.len() > 2 {
            return Err(at(
                "a scenario is one string or the ratio of two".to_string()
            ));
        }
        for s in &scenarios {
            Scenario::parse(s).map_err(|e| at(format!("scenario '{s}': {e}")))?;
        }
        out.push(Measurement {
            id: id.to_string(),
            scenarios,
            scenario_text: scenario.to_string(),
            figure_text: figure.to_string(),
            probe: Probe::parse(figure).map_err(at)?,
            seeds: parse_seeds(seeds).map_err(at)?,
            seeds_text: seeds.to_string(),
            statistic: Statistic::parse(statistic).map_err(at)?,
            statistic_text: statistic.to_string(),
            show: show.to_string(),
            value: value.to_string(),
        });
    }
    Ok(out)
}

/// One run a table needs: a scenario string with a seed (None: its own).
pub type RunKey = (String, Option<u64>);

/// The runs `table` needs, each once, with the probes read from each.
pub fn runs_of(table: &[Measurement]) -> BTreeMap<RunKey, Vec<Probe>> {
    let mut runs: BTreeMap<RunKey, Vec<Probe>> = BTreeMap::new();
    for m in table {
        let seeds: Vec<Option<u64>> = match &m.seeds {
            Some(r) => r.clone().map(Some).collect(),
            None => vec![None],
        };
        for s in &m.scenarios {
            for seed in &seeds {
                let probes = runs.entry((s.clone(), *seed)).or_default();
                if !probes.contains(&m.probe) {
                    probes.push(m.probe.clone());
                }
            }
        }
    }
    runs
}

/// How a table's runs are looked up: the values of one run by its scenario and seed.
pub type RunLookup<'a> = dyn Fn(&str, Option<u64>) -> Result<RunValues, String> + 'a;

/// The value of measurement `m` from the values of its runs (`of(scenario, seed)` gives a run's
/// values); an error names the seed and scenario where the probe had no value.
pub fn value_of(m: &Measurement, of: &RunLookup) -> Result<f64, String> {
    let seeds: Vec<Option<u64>> = match &m.seeds {
        Some(r) => r.clone().map(Some).collect(),
        None => vec![None],
    };
    let at = |s: &str, seed: Option<u64>, e: String| match seed {
        Some(k) => format!("{s} on seed {k}: {e}"),
        None => format!("{s}: {e}"),
    };
    let read = |s: &str, seed: Option<u64>| -> Result<f64, String> {
        let values = of(s, seed).map_err(|e| at(s, seed, e))?;
        let (_, v) = values
            .iter()
            .find(|(p, _)| *p == m.probe)
            .expect("every probe of the run is read");
        let v = v.clone().map_err(|e| at(s, seed, e))?;
        // A count may read a figure that is infinite (a recovery that never came); no other
        // statistic, and no value at all, may be NaN.
        let counted = matches!(m.statistic, Statistic::Below(_) | Statistic::Above(_));
        if v.is_nan() || (v.is_infinite() && !counted) {
            return Err(at(s, seed, format!("{} is {}", m.figure_text, written(v))));
        }
        Ok(v)
    };
    let mut values = Vec::with_capacity(seeds.len());
    for seed in seeds {
        let v = match m.scenarios.as_slice() {
            [a] => read(a, seed)?,
            [a, b] => read(a, seed)? / read(b, seed)?,
            _ => unreachable!("one scenario or two"),
        };
        values.push(v);
    }
    let value = m.statistic.reduce(&values);
    if value.is_finite() {
        Ok(value)
    } else {
        Err(format!("its {} is {}", m.statistic_text, written(value)))
    }
}

/// Measures every row of `table` on `threads` threads (each run once, however many rows read it),
/// calling `progress(done, total)` after each run; a row's Err names why it has no value.
pub fn measure_table(
    table: &[Measurement],
    threads: usize,
    progress: &(dyn Fn(usize, usize) + Sync),
) -> Vec<Result<f64, String>> {
    use std::sync::atomic::{AtomicUsize, Ordering};
    use std::sync::Mutex;
    let runs: Vec<(RunKey, Vec<Probe>)> = runs_of(table).into_iter().collect();
    let results: Vec<Mutex<Option<Result<RunValues, String>>>> =
        runs.iter().map(|_| Mutex::new(None)).collect();
    let next = AtomicUsize::new(0);
    let done = AtomicUsize::new(0);
    std::thread::scope(|scope| {
        for _ in 0..threads.max(1) {
            scope.spawn(|| loop {
                let i = next.fetch_add(1, Ordering::Relaxed);
                let Some(((scenario, seed), probes)) = runs.get(i) else {
                    break;
                };
                let values = measure_run(scenario, *seed, probes);
                *results[i].lock().expect("no thread panics holding it") = Some(values);
                progress(done.fetch_add(1, Ordering::Relaxed) + 1, runs.len());
            });
        }
    });
    let by_key: BTreeMap<&RunKey, Result<RunValues, String>> = runs
        .iter()
        .zip(results)
        .map(|((key, _), r)| {
            let values = r
                .into_inner()
                .expect("no thread panics holding it")
                .expect("every run measured");
            (key, values)
        })
        .collect();
    let of = |s: &str, seed: Option<u64>| -> Result<RunValues, String> {
        by_key[&(s.to_string(), seed)].clone()
    };
    table.iter().map(|m| value_of(m, &of)).collect()
}

/// A measured value as the table writes it: the shortest form that reads back to the same bits.
pub fn written(value: f64) -> String {
    if value.is_nan() {
        "NaN".to_string()
    } else if value.is_infinite() {
        if value > 0.0 { "inf" } else { "-inf" }.to_string()
    } else if value != 0.0 && !(1e-4..1e15).contains(&value.abs()) {
        format!("{value:e}")
    } else {
        format!("{value}")
    }
}

/// The row of `m` as the table writes it, with `value`.
pub fn table_line(m: &Measurement, value: &str) -> String {
    crate::text::csv::line(&[
        &m.id,
        &m.scenario_text,
        &m.figure_text,
        &m.seeds_text,
        &m.statistic_text,
        &m.show,
        value,
    ])
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_table_names_its_bad_field() {
        let head = format!("{HEADER}\n");
        let bad = |line: &str| parse_table(&format!("{head}{line}")).unwrap_err();
        assert!(bad("a,v=1&preset=step,nope,1..30,min,,").contains("'nope'"));
        assert!(bad("a,v=1&preset=step,tracking_rms,1..30,median,,").contains("'median'"));
        assert!(bad("a,v=1&preset=step,tracking_rms,30..1,min,,").contains("'30..1'"));
        assert!(bad("a,v=1&preset=nope,tracking_rms,1..3,min,,").contains("line 2"));
        assert!(bad("a,v=1&preset=step,at omega 0.1,1..3,min,").contains("6 fields"));
        assert!(bad("a,v=1&preset=step,at speed 0.1,1..3,min,,").contains("'speed'"));
        let twice = "a,v=1&preset=step,tracking_rms,1..3,min,,\n";
        assert!(parse_table(&format!("{head}{twice}{twice}"))
            .unwrap_err()
            .contains("already used"));
    }

    #[test]
    fn statistics_reduce_as_named() {
        let v = [3.0, 1.0, 2.0];
        assert_eq!(Statistic::Min.reduce(&v), 1.0);
        assert_eq!(Statistic::Max.reduce(&v), 3.0);
        assert_eq!(Statistic::Mean.reduce(&v), 2.0);
        assert_eq!(Statistic::Sum.reduce(&v), 6.0);
        assert_eq!(Statistic::Below(2.0).reduce(&v), 1.0);
        assert_eq!(Statistic::Above(1.5).reduce(&v), 2.0);
    }

    #[test]
    fn a_value_is_written_to_read_back_to_its_bits() {
        for v in [0.1 + 0.2, 1e-300, 4.7e-3, -25.4, 3.0] {
            assert_eq!(written(v).parse::<f64>().unwrap().to_bits(), v.to_bits());
        }
        assert_eq!(written(f64::INFINITY), "inf");
    }

    /// The values of `probes` (as the figure column writes them) on `scenario`'s own seed.
    fn read(scenario: &str, probes: &[&str]) -> Vec<f64> {
        let probes: Vec<Probe> = probes.iter().map(|p| Probe::parse(p).unwrap()).collect();
        measure_run(scenario, None, &probes)
            .unwrap()
            .into_iter()
            .map(|(_, v)| v.unwrap())
            .collect()
    }

    #[test]
    fn a_recovery_reads_the_step_filters_settling_time() {
        // The critically damped filter's step response is 1 − (1 + ωn·t)·e^(−ωn·t): it stays
        // within 2 % from ωn·t = 5.8335 on, 4.642 ms at the step preset's ωn = 2π·200 /s; the
        // first 50 µs sample after that is 4.65 ms past the step.
        const WN: f64 = 2.0 * std::f64::consts::PI * 200.0;
        let t = 5.833_5 / WN;
        let sample = (t / 50e-6).ceil() * 50e-6;
        let [recovery] = read("v=1&preset=step", &["recovery omega_ref 0.01 0.05 0.5"])[..] else {
            unreachable!()
        };
        assert!(
            (recovery - sample).abs() < 1e-9,
            "{recovery} against {sample}"
        );
    }

    #[test]
    fn window_probes_agree_with_the_figures_over_the_strips_window() {
        let run = "v=1&preset=sine200-1rad";
        let v = read(
            run,
            &[
                "max i_s transient end",
                "current_peak",
                "mean clipped transient end",
                "saturated_share",
                "rms omega_err transient end",
                "tracking_rms",
                "at omega_ref 0",
            ],
        );
        assert_eq!(v[0], v[1], "peak |i_s|");
        assert!(
            (v[2] - v[3]).abs() < 1e-12,
            "share at the limit {} against {}",
            v[2],
            v[3]
        );
        assert!(
            (v[4] - v[5]).abs() < 1e-9 * v[5],
            "tracking RMS {} against {}",
            v[4],
            v[5]
        );
        assert_eq!(v[6], 0.0, "a sine reference starts at 0");
    }

    #[test]
    fn nis_side_reads_the_mean_nis_against_its_band() {
        // The Euler EKF at 200 Hz lies far above its band; the step's filter inside or near it.
        for (run, expect) in [("v=1&preset=sine200", Some(1.0)), ("v=1&preset=step", None)] {
            let v = read(
                run,
                &["nis_side", "mean_nis", "mean_nis_low", "mean_nis_high"],
            );
            let side = if v[1] < v[2] {
                -1.0
            } else if v[1] > v[3] {
                1.0
            } else {
                0.0
            };
            assert_eq!(v[0], side, "{run}: {v:?}");
            if let Some(e) = expect {
                assert_eq!(v[0], e, "{run}");
            }
        }
    }
}
