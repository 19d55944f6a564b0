//! The `sweep` and `seeds` subcommands: a scenario run again and again, one CSV row a run.

use crate::cli::number;
use crate::output::{stdout_stop, to_stderr, Stop};
use imlab::analysis::{
    checked_grid, seed_range, seed_run, seeds_csv, summarise, sweep_csv, sweep_point,
    sweep_variant, variant_scenario, SweepPlan, SweepSettings, AMP_RULE, DURATION_RULE,
    MAX_SEED_RUNS, OFFSET_RULE,
};
use imlab::scenario::Scenario;
use imlab::text::excerpt;
use std::io::Write;

/// The frequencies (Hz) of `--freqs`, increasing and distinct.
pub(crate) fn frequencies(value: &str) -> Result<Vec<f64>, String> {
    let bad = || {
        format!(
            "--freqs '{}': expected LO:HI:N (log spaced) or F1,F2,... in Hz, each > 0",
            excerpt(value)
        )
    };
    if let [lo, hi, n] = value.split(':').collect::<Vec<_>>()[..] {
        let lo: f64 = lo.parse().map_err(|_| bad())?;
        let hi: f64 = hi.parse().map_err(|_| bad())?;
        let n: usize = n.parse().map_err(|_| bad())?;
        return checked_grid(lo, hi, n).map_err(|e| format!("--freqs: {e}"));
    }
    let mut freqs = value
        .split(',')
        .map(|f| f.parse::<f64>().map_err(|_| bad()))
        .collect::<Result<Vec<_>, _>>()?;
    if freqs.iter().any(|f| !(f.is_finite() && *f > 0.0)) {
        return Err(bad());
    }
    // The summary reads the response in increasing frequency.
    freqs.sort_by(f64::total_cmp);
    freqs.dedup();
    Ok(freqs)
}

/// The sine of `--amp`, `--offset` and `--duration`, each checked against its range.
pub(crate) fn sweep_settings(
    amp: &str,
    offset: &str,
    duration: &str,
) -> Result<SweepSettings, String> {
    Ok(SweepSettings {
        amp: number("--amp", amp, |a: &f64| AMP_RULE.0(*a), AMP_RULE.1)?,
        offset: number(
            "--offset",
            offset,
            |w: &f64| OFFSET_RULE.0(*w),
            OFFSET_RULE.1,
        )?,
        duration: number(
            "--duration",
            duration,
            |d: &f64| DURATION_RULE.0(*d),
            DURATION_RULE.1,
        )?,
    })
}

/// The seeds of `--n` and `--first` (the scenario's seed when `first` is absent).
pub(crate) fn seed_options(
    s: &Scenario,
    n: &str,
    first: Option<&str>,
) -> Result<std::ops::RangeInclusive<u64>, String> {
    let n = number(
        "--n",
        n,
        |n: &u64| (1..=MAX_SEED_RUNS).contains(n),
        &format!("a whole number from 1 to {MAX_SEED_RUNS}"),
    )?;
    let first = match first {
        Some(value) => number("--first", value, |_: &u64| true, "a whole number ≥ 0")?,
        None => s.seed,
    };
    seed_range(first, n).map_err(|e| format!("--first, --n: {e}"))
}

/// Measures the response at each frequency, with progress and a count of the unsettled points on
/// stderr, and writes it as CSV.
pub(crate) fn sweep(
    s: &Scenario,
    freqs: &[f64],
    settings: &SweepSettings,
    out: &mut impl Write,
) -> Result<(), Stop> {
    let points: Result<Vec<_>, _> = freqs
        .iter()
        .enumerate()
        .map(|(i, &f)| {
            to_stderr(format_args!(
                "\rimlab sweep: {}/{} ({f:.4} Hz)   ",
                i + 1,
                freqs.len()
            ));
            sweep_point(s, f, settings)
        })
        .collect();
    // Ends the progress line, so that an error message starts a line of its own.
    to_stderr(format_args!("\n"));
    let points = points.map_err(|e| e.to_string())?;
    let unsettled = summarise(&points).unsettled;
    if unsettled > 0 {
        to_stderr(format_args!(
            "imlab sweep: {unsettled} of {} points had not settled (settled = false); no \
             bandwidth or phase is interpolated from them. Longer runs (--duration) may settle.\n",
            points.len()
        ));
    }
    out.write_all(sweep_csv(&points).as_bytes())
        .map_err(stdout_stop)
}

/// Runs the plan `text` (a link's `#sweep=`): each of its variants of the scenario in turn, its
/// CSV after a line `# variant=NAME`, with what a reader must know of the plan on stderr.
pub(crate) fn sweep_plan(s: &Scenario, text: &str, out: &mut impl Write) -> Result<(), Stop> {
    let plan = SweepPlan::parse(text).map_err(|e| format!("--plan: {e}"))?;
    for caveat in plan.caveats() {
        to_stderr(format_args!("imlab sweep: {caveat}\n"));
    }
    let freqs = plan.frequencies()?;
    for name in &plan.variants {
        let variant = variant_scenario(s, sweep_variant(name)?).map_err(|e| e.to_string())?;
        writeln!(out, "# variant={name}").map_err(stdout_stop)?;
        sweep(&variant, &freqs, &plan.settings(), out)?;
    }
    Ok(())
}

/// Runs the scenario with each seed of `range`, with progress on stderr, and writes each run's
/// figures as CSV.
pub(crate) fn seeds(
    s: &Scenario,
    range: std::ops::RangeInclusive<u64>,
    out: &mut impl Write,
) -> Result<(), Stop> {
    let n = range.end() - range.start() + 1;
    let results: Result<Vec<_>, _> = range
        .enumerate()
        .map(|(i, seed)| {
            to_stderr(format_args!("\rimlab seeds: {}/{n}   ", i + 1));
            seed_run(s, seed, usize::MAX).map(|run| run.result)
        })
        .collect();
    // Ends the progress line, so that an error message starts a line of its own.
    to_stderr(format_args!("\n"));
    let results = results.map_err(|e| e.to_string())?;
    out.write_all(seeds_csv(&results).as_bytes())
        .map_err(stdout_stop)
}
