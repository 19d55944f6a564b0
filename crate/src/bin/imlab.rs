//! `imlab`: run IM Lab scenarios from the command line.

use imlab::analysis::{
    checked_grid, log_grid, seed_run, seeds_csv, sweep_csv, sweep_point, SweepSettings,
};
use imlab::scenario::{Scenario, PRESETS};
use imlab::sim::{figures, Simulation};
use std::io::{BufWriter, Write};
use std::process::ExitCode;

const USAGE: &str = "usage:
  imlab list                                   presets, one line each
  imlab describe SCENARIO                      every field of the effective scenario
  imlab run SCENARIO [--every N] [--out FILE]  CSV trace to stdout or FILE
  imlab metrics SCENARIO                       figures of the run as CSV: name,value,unit
  imlab sweep SCENARIO [--freqs LO:HI:N | F1,F2,...] [--amp A] [--offset W] [--duration D]
                                               closed-loop frequency response as CSV (default
                                               10:1000:20 Hz, 0.02 rad/s about 0 rad/s, 0.2 s)
  imlab seeds SCENARIO [--n N] [--first SEED]  per-seed figures as CSV (default 10 seeds
                                               from the scenario's seed)

SCENARIO is a preset name or a query string such as 'v=1&preset=step&step.size=0.3'.";

fn main() -> ExitCode {
    let args: Vec<String> = std::env::args().skip(1).collect();
    match run(&args) {
        Ok(()) => ExitCode::SUCCESS,
        Err(message) => {
            eprintln!("imlab: {message}");
            ExitCode::from(2)
        }
    }
}

fn run(args: &[String]) -> Result<(), String> {
    match args.first().map(String::as_str) {
        Some("list") if args.len() == 1 => {
            let width = PRESETS.iter().map(|p| p.name.len()).max().unwrap_or(0);
            for p in PRESETS {
                println!("{:width$}  {}", p.name, p.description);
            }
            Ok(())
        }
        Some("describe") if args.len() == 2 => {
            let s = Scenario::parse(&args[1]).map_err(|e| e.to_string())?;
            println!("# {}", s.encode());
            println!("# {} samples of {} s", s.steps(), s.ts);
            for f in s.describe() {
                let value = f.value.unwrap_or_else(|| "-".to_string());
                let unit = if f.unit.is_empty() {
                    String::new()
                } else {
                    format!(" {}", f.unit)
                };
                println!(
                    "{:12} = {:>22}{:8}  [{}] {}",
                    f.key, value, unit, f.group, f.doc
                );
            }
            Ok(())
        }
        Some("run") if args.len() >= 2 => {
            let s = Scenario::parse(&args[1]).map_err(|e| e.to_string())?;
            let (mut every, mut out) = (1usize, None);
            let mut rest = args[2..].iter();
            while let Some(flag) = rest.next() {
                let value = rest
                    .next()
                    .ok_or(format!("{flag} needs a value\n{USAGE}"))?;
                match flag.as_str() {
                    "--every" => {
                        every = value
                            .parse()
                            .ok()
                            .filter(|&n| n >= 1)
                            .ok_or(format!("--every '{value}': expected a whole number ≥ 1"))?
                    }
                    "--out" => out = Some(value.clone()),
                    _ => return Err(format!("unknown option '{flag}'\n{USAGE}")),
                }
            }
            let mut sim = Simulation::new(&s, every).map_err(|e| e.to_string())?;
            let result = sim.run();
            let write = |w: &mut dyn Write| -> std::io::Result<()> {
                let mut w = BufWriter::new(w);
                sim.recorder().write_csv(&mut w)?;
                w.flush()
            };
            match &out {
                Some(path) => {
                    let mut file =
                        std::fs::File::create(path).map_err(|e| format!("--out {path}: {e}"))?;
                    write(&mut file).map_err(|e| format!("--out {path}: {e}"))?;
                }
                None => write(&mut std::io::stdout().lock()).map_err(|e| format!("stdout: {e}"))?,
            }
            // The trace up to the failure is written; the failure itself is an error.
            result.map_err(|e| format!("{e} (trace written up to the failure)"))
        }
        Some("metrics") if args.len() == 2 => metrics(&args[1]),
        Some("sweep") if args.len() >= 2 => sweep(
            &args[1],
            &options(&args[2..], &["--freqs", "--amp", "--offset", "--duration"])?,
        ),
        Some("seeds") if args.len() >= 2 => {
            seeds(&args[1], &options(&args[2..], &["--n", "--first"])?)
        }
        _ => Err(USAGE.to_string()),
    }
}

/// Runs the scenario, recording every sample, and prints its figures as `name,value,unit` lines;
/// after a failure, the figures of the samples before it, then the failure as the error.
fn metrics(text: &str) -> Result<(), String> {
    let s = Scenario::parse(text).map_err(|e| e.to_string())?;
    let mut sim = Simulation::new(&s, 1).map_err(|e| e.to_string())?;
    let result = sim.run();
    let list = figures(&sim);
    let write = |w: &mut dyn Write| -> std::io::Result<()> {
        let mut w = BufWriter::new(w);
        writeln!(w, "name,value,unit")?;
        for f in list.iter().flatten() {
            writeln!(w, "{},{},{}", f.name, f.value, f.unit)?;
        }
        w.flush()
    };
    write(&mut std::io::stdout().lock()).map_err(|e| format!("stdout: {e}"))?;
    let printed = if list.is_some() {
        "figures printed of the samples before the failure"
    } else {
        "nothing recorded before the failure"
    };
    result.map_err(|e| format!("{e} ({printed})"))
}

/// `--flag value` pairs, each flag one of `allowed`.
fn options<'a>(args: &'a [String], allowed: &[&str]) -> Result<Vec<(&'a str, &'a str)>, String> {
    let mut out = Vec::new();
    let mut rest = args.iter();
    while let Some(flag) = rest.next() {
        if !allowed.contains(&flag.as_str()) {
            return Err(format!("unknown option '{flag}'\n{USAGE}"));
        }
        let value = rest
            .next()
            .ok_or(format!("{flag} needs a value\n{USAGE}"))?;
        out.push((flag.as_str(), value.as_str()));
    }
    Ok(out)
}

fn number<T: std::str::FromStr>(
    flag: &str,
    value: &str,
    ok: impl Fn(&T) -> bool,
    expected: &str,
) -> Result<T, String> {
    value
        .parse()
        .ok()
        .filter(ok)
        .ok_or(format!("{flag} '{value}': expected {expected}"))
}

fn frequencies(value: &str) -> Result<Vec<f64>, String> {
    let bad =
        || format!("--freqs '{value}': expected LO:HI:N (log spaced) or F1,F2,... in Hz, each > 0");
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

fn sweep(text: &str, opts: &[(&str, &str)]) -> Result<(), String> {
    let s = Scenario::parse(text).map_err(|e| e.to_string())?;
    let mut settings = SweepSettings::default();
    let mut freqs = log_grid(10.0, 1000.0, 20);
    for &(flag, value) in opts {
        match flag {
            "--freqs" => freqs = frequencies(value)?,
            "--amp" => {
                settings.amp = number(
                    flag,
                    value,
                    |a: &f64| *a > 0.0 && *a <= 1000.0,
                    "0 < A ≤ 1000 rad/s",
                )?
            }
            "--offset" => {
                settings.offset =
                    number(flag, value, |w: &f64| w.abs() <= 1000.0, "|W| ≤ 1000 rad/s")?
            }
            _ => {
                settings.duration = number(
                    flag,
                    value,
                    |d: &f64| *d > 0.0 && *d <= 20.0,
                    "0 < D ≤ 20 s",
                )?
            }
        }
    }
    let mut points = Vec::new();
    for (i, &f) in freqs.iter().enumerate() {
        eprint!("\rimlab sweep: {}/{} ({f:.4} Hz)   ", i + 1, freqs.len());
        points.push(sweep_point(&s, f, &settings).map_err(|e| e.to_string())?);
    }
    eprintln!();
    print!("{}", sweep_csv(&points));
    Ok(())
}

fn seeds(text: &str, opts: &[(&str, &str)]) -> Result<(), String> {
    let s = Scenario::parse(text).map_err(|e| e.to_string())?;
    let (mut n, mut first) = (10u64, s.seed);
    for &(flag, value) in opts {
        match flag {
            "--n" => {
                n = number(
                    flag,
                    value,
                    |n: &u64| (1..=10_000).contains(n),
                    "a whole number from 1 to 10000",
                )?
            }
            _ => first = number(flag, value, |_: &u64| true, "a whole number ≥ 0")?,
        }
    }
    let mut results = Vec::new();
    for (i, seed) in (first..first.saturating_add(n)).enumerate() {
        eprint!("\rimlab seeds: {}/{n}   ", i + 1);
        results.push(
            seed_run(&s, seed, usize::MAX)
                .map_err(|e| e.to_string())?
                .result,
        );
    }
    eprintln!();
    print!("{}", seeds_csv(&results));
    Ok(())
}
