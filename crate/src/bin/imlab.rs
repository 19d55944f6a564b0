//! `imlab`: run IM Lab scenarios from the command line.

use imlab::scenario::{Scenario, PRESETS};
use imlab::sim::Simulation;
use std::io::{BufWriter, Write};
use std::process::ExitCode;

const USAGE: &str = "usage:
  imlab list                                   presets, one line each
  imlab describe SCENARIO                      every field of the effective scenario
  imlab run SCENARIO [--every N] [--out FILE]  CSV trace to stdout or FILE

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
        _ => Err(USAGE.to_string()),
    }
}
