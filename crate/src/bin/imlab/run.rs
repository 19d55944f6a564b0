//! The subcommands on one scenario's run: list, describe, run and metrics.

use crate::output::{stdout_stop, to_stderr, Stop};
use imlab::control::formula;
use imlab::record::{Figure, Unreached, WarningKind};
use imlab::scenario::{Scenario, PRESETS};
use imlab::sim::Simulation;
use imlab::text::{escape_invisible, excerpt};
use std::fs::File;
use std::io::{self, BufWriter, Write};

/// Writes the presets, one `name  description` line each.
pub(crate) fn list(out: &mut impl Write) -> io::Result<()> {
    let width = PRESETS.iter().map(|p| p.name.len()).max().unwrap_or(0);
    for p in PRESETS {
        writeln!(out, "{:width$}  {}", p.name, p.description)?;
    }
    Ok(())
}

/// `imlab design`: the design derived from the scenario's model, rating and sampling, a value a
/// line with the rule behind it, and the scenario that uses it.
pub(crate) fn design(s: &Scenario, out: &mut impl Write) -> Result<(), Stop> {
    let derived = s
        .derived()
        .map_err(|e| Stop::Failed(e.message().to_string()))?;
    // The scenario with the derived design; one that has it keeps its own overrides.
    let mut with = s.clone();
    if s.design != imlab::scenario::DesignKind::Derived {
        with.set("design", "derived")
            .map_err(|e| Stop::Failed(e.to_string()))?;
    }
    let write = |out: &mut dyn Write| -> io::Result<()> {
        writeln!(
            out,
            "# the design derived from the model's motor, its rating and Ts"
        )?;
        writeln!(out, "# {}", with.encode())?;
        for line in derived.lines(&s.design_inputs()) {
            let value = if line.value != 0.0 && line.value.abs() < 1e-3 {
                format!("{:e}", line.value)
            } else {
                imlab::text::rounded(line.value, 4)
            };
            // A setting the link gives itself stands in place of the rule's.
            let own = with
                .describe()
                .into_iter()
                .find(|f| f.key == line.key)
                .and_then(|f| f.value)
                .filter(|v| v.parse::<f64>().ok() != Some(line.value))
                .map_or(String::new(), |v| format!(" (this link sets {v})"));
            writeln!(
                out,
                "{:12} = {:>10} {:16} {}{own}",
                line.key, value, line.unit, line.rule
            )?;
        }
        writeln!(
            out,
            "# the runs that check it (crate/tests/design.rs runs them on seeds 1-30):"
        )?;
        match imlab::design::checks(&with, &derived) {
            Ok(runs) => {
                for (name, link) in runs {
                    writeln!(out, "# {name:8} {link}")?;
                }
            }
            Err(e) => writeln!(out, "# none: {e}")?,
        }
        Ok(())
    };
    write(out).map_err(stdout_stop)
}

/// Writes the scenario's canonical string, its length and every field with unit and doc.
pub(crate) fn describe(s: &Scenario, out: &mut impl Write) -> io::Result<()> {
    writeln!(out, "# {}", s.encode())?;
    writeln!(out, "# {} samples of {} s", s.steps(), s.ts)?;
    for idle in s.idle_settings() {
        writeln!(out, "# {idle}")?;
    }
    if let Some(m) = imlab::motors::motor(&s.motor).filter(|m| m.name != "paper") {
        let (amplitude, estimated) = m.rated_current();
        let how = if estimated {
            format!(
                "estimated from its equivalent circuit at {} V, {} Hz and {} kW",
                m.voltage,
                m.frequency,
                m.power / 1e3
            )
        } else {
            "published".to_string()
        };
        writeln!(
            out,
            "# motor {}: {}; rated current amplitude {} A ({how})",
            m.name,
            m.source(),
            imlab::text::rounded(amplitude, 4)
        )?;
    }
    for f in s.describe() {
        let value = match f.value {
            Some(v) if f.formula.is_some() && v.is_empty() => "paper's".to_string(),
            // A law's text shows its line breaks and controls as escapes, as a message quotes it.
            Some(v) => escape_invisible(&v),
            None => "-".to_string(),
        };
        let unit = if f.unit.is_empty() {
            String::new()
        } else {
            format!(" {}", f.unit)
        };
        let idle = s
            .idle_because(f.key)
            .map_or(String::new(), |b| format!(" (no effect with {b})"));
        writeln!(
            out,
            "{:12} = {:>22}{:8}  [{}] {}{idle}",
            f.key, value, unit, f.group, f.doc
        )?;
    }
    writeln!(
        out,
        "# The names a step's own law (law.v1..law.v4) may use, with their units:"
    )?;
    for n in formula::NAMES {
        let steps = match n.from_step {
            1 => "",
            2 => " (steps 2–4)",
            _ => " (step 4)",
        };
        writeln!(out, "{:6} {:14} {}{steps}", n.name, n.unit, n.doc())?;
    }
    writeln!(
        out,
        "# With + - * / ^, parentheses, numbers and the functions:"
    )?;
    for &(name, _, _, doc) in formula::FUNCTIONS {
        writeln!(out, "{name:6} {}", imlab::text::Message::new(doc))?;
    }
    Ok(())
}

/// Runs the scenario keeping every `every`-th sample and writes the trace as CSV to `file` or
/// `out`; after a failure, the trace up to it, then the failure as the error. Every sample is
/// kept as checkpoints and computed again as it is written (little memory); every N-th as rows.
pub(crate) fn run(
    s: &Scenario,
    every: usize,
    file: Option<&str>,
    out: &mut impl Write,
) -> Result<(), Stop> {
    let sim = if every == 1 {
        Simulation::traced(s)
    } else {
        Simulation::new(s, every)
    };
    let mut sim = sim.map_err(|e| e.to_string())?;
    let result = sim.run();
    match file {
        Some(path) => {
            let failed = |e: io::Error| format!("--out '{}': {e}", excerpt(path));
            let mut file = BufWriter::new(File::create(path).map_err(failed)?);
            sim.write_csv(&mut file)
                .and_then(|()| file.flush())
                .map_err(failed)?;
        }
        None => sim.write_csv(out).map_err(stdout_stop)?,
    }
    result.map_err(|e| format!("{e} (trace written up to the failure)").into())
}

/// Runs the scenario, keeping a checkpoint every 2,048 samples, and writes its figures as
/// `name,value,unit` lines; after a failure, the figures of the samples before it, then the
/// failure as the error.
pub(crate) fn metrics(s: &Scenario, out: &mut impl Write) -> Result<(), Stop> {
    let mut sim = Simulation::traced(s).map_err(|e| e.to_string())?;
    let result = sim.run();
    let report = sim.report();
    write_figures(
        report.figures.as_deref().unwrap_or(&[]),
        &report.unreached,
        out,
    )
    .map_err(stdout_stop)?;
    let printed = if report.figures.is_some() {
        "figures printed of the samples before the failure"
    } else {
        "nothing recorded before the failure"
    };
    result.map_err(|e| format!("{e} ({printed})"))?;
    // A run that ran away fails as a control run, although the simulation itself completed; a
    // figure that is not a number fails it with its cause.
    for w in &report.warnings {
        if matches!(w.kind, WarningKind::Runaway | WarningKind::NotFinite) {
            return Err(format!("{} (figures printed)", w.text).into());
        }
        to_stderr(format_args!("imlab metrics: warning: {}\n", w.text));
    }
    Ok(())
}

/// Writes the header `name,value,unit` and one line per figure; a value read at the last sample
/// is followed by its trend, `NAME_rate` (the slope of its line over the last tenth of the run,
/// its unit per second) and `NAME_settled` (1 when the value had settled by the end of the run, 0
/// when it was still changing, fluctuating, drifting, or the run ran away). A figure the run had not
/// reached by its end is `NAME_reached,0,` in its place, with no value.
fn write_figures(list: &[Figure], unreached: &[Unreached], out: &mut impl Write) -> io::Result<()> {
    writeln!(out, "name,value,unit")?;
    let not_reached = |i: usize| unreached.iter().filter(move |u| u.index == i);
    for (i, f) in list.iter().enumerate() {
        for u in not_reached(i) {
            writeln!(out, "{}_reached,0,", u.name)?;
        }
        writeln!(out, "{},{},{}", f.name, f.value, f.unit)?;
        if let Some(t) = &f.trend {
            writeln!(out, "{}_rate,{},{}/s", f.name, t.rate, f.unit)?;
            writeln!(out, "{}_settled,{},", f.name, u8::from(t.settled))?;
        }
    }
    for u in not_reached(list.len()) {
        writeln!(out, "{}_reached,0,", u.name)?;
    }
    Ok(())
}
