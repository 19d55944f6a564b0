//! `imlab`: run IM Lab scenarios from the command line.

use clap::error::{ContextKind, ContextValue};
use clap::{Args, Parser, Subcommand};
use imlab::analysis::claims;
use imlab::analysis::robust::{self, csv_preamble, csv_row, map_run, Axis, Map, MapRun};
use imlab::analysis::{
    checked_grid, seed_range, seed_run, seeds_csv, summarise, sweep_csv, sweep_point,
    SweepSettings, MAX_SEED_RUNS,
};
use imlab::challenge::grade::{self, ClassRow, Graded};
use imlab::challenge::{builtin, Challenge, BUILTINS};
use imlab::control::formula;
use imlab::record::{Figure, Unreached, WarningKind};
use imlab::scenario::{excerpt, Scenario, PRESETS};
use imlab::sim::Simulation;
use std::fmt;
use std::fs::{File, OpenOptions};
use std::io::{self, BufWriter, ErrorKind, IsTerminal, Read, Seek, SeekFrom, Write};
use std::process::ExitCode;

/// Run IM Lab scenarios: speed-sensorless induction-motor control (Zhang et al. 2015).
#[derive(Parser)]
#[command(
    name = "imlab",
    version,
    // A repeated option overrides the earlier one, as in most command lines.
    args_override_self = true,
    after_help = "SCENARIO is a preset name or a query string such as \
                  'v=1&preset=step&step.size=0.3'; `imlab list` names the presets."
)]
struct Cli {
    /// What to do.
    #[command(subcommand)]
    command: Command,
}

/// The scenario argument every subcommand but `list` takes.
#[derive(Args)]
struct ScenarioArg {
    /// Preset name or query string such as 'v=1&preset=step&step.size=0.3'
    /// (`imlab list` names the presets)
    scenario: String,
}

// Option values stay strings for clap: its own "invalid value" message would echo them in full,
// while `number` and `frequencies` quote them through `excerpt`. `allow_hyphen_values` keeps the
// old rule that the word after an option is its value, so `--offset -5` works.
/// The subcommands.
#[derive(Subcommand)]
enum Command {
    /// List the presets, one line each
    List,
    /// Print every field of the effective scenario
    Describe {
        #[command(flatten)]
        target: ScenarioArg,
    },
    /// Run the scenario and write its trace as CSV to stdout or FILE
    Run {
        #[command(flatten)]
        target: ScenarioArg,
        /// Keep every N-th sample (a whole number ≥ 1)
        #[arg(
            long,
            value_name = "N",
            default_value = "1",
            allow_hyphen_values = true
        )]
        every: String,
        /// Write the CSV to FILE instead of stdout
        #[arg(long, value_name = "FILE", allow_hyphen_values = true)]
        out: Option<String>,
    },
    /// Run the scenario and print its figures as CSV: name,value,unit
    Metrics {
        #[command(flatten)]
        target: ScenarioArg,
    },
    /// Check each step's own law (law.v1..law.v4) against its designed error dynamics
    ///
    /// Each law is compared with the paper's at drawn states and parameter values, and the term
    /// it gets wrong is named where it can be; the command fails unless every law gives the
    /// dynamics its step is designed for.
    Law {
        #[command(flatten)]
        target: ScenarioArg,
    },
    /// Measure the closed-loop speed frequency response and print it as CSV
    Sweep {
        #[command(flatten)]
        target: ScenarioArg,
        /// Frequencies (Hz): LO:HI:N for N log-spaced from LO to HI (0 < LO ≤ HI, 1 ≤ N ≤ 200),
        /// or a list, each > 0
        #[arg(
            long,
            value_name = "LO:HI:N|F1,F2,...",
            default_value = "10:1000:20",
            allow_hyphen_values = true
        )]
        freqs: String,
        /// Sine amplitude (rad/s), 0 < A ≤ 1000
        #[arg(
            long,
            value_name = "A",
            default_value_t = SweepSettings::default().amp.to_string(),
            allow_hyphen_values = true
        )]
        amp: String,
        /// Operating speed the sine rides on (rad/s), |W| ≤ 1000
        #[arg(
            long,
            value_name = "W",
            default_value_t = SweepSettings::default().offset.to_string(),
            allow_hyphen_values = true
        )]
        offset: String,
        /// Length of each run (s), 0 < D ≤ 20
        #[arg(
            long,
            value_name = "D",
            default_value_t = SweepSettings::default().duration.to_string(),
            allow_hyphen_values = true
        )]
        duration: String,
    },
    /// Run the scenario once per seed and print each seed's figures as CSV
    Seeds {
        #[command(flatten)]
        target: ScenarioArg,
        /// Number of seeds, 1 to 10000
        #[arg(
            long,
            value_name = "N",
            default_value = "10",
            allow_hyphen_values = true
        )]
        n: String,
        /// First seed, a whole number ≥ 0; the last seed run is at most 2^53 − 1 [default: the
        /// scenario's seed]
        #[arg(long, value_name = "SEED", allow_hyphen_values = true)]
        first: Option<String>,
    },
    /// Run the scenario over a grid of motor or model parameters and seeds: a model-error map
    ///
    /// Each grid point (cell) runs once per seed, on all cores. The CSV has one row a cell, in
    /// order (the last --vary fastest), written as soon as the cell and every cell before it are
    /// done: the axis values and their errors against the other side (in %), the number of runs,
    /// of runs that ran away (the runaway warning, or a diverged simulation), of runs whose EKF
    /// was inconsistent, and of the runs that held what holding cost: those past the motor's
    /// rated current after the start-up (over_rating) and those whose final speed error had not
    /// settled (unsettled), then the minimum, median and maximum over the runs that neither ran away nor
    /// stopped early of
    /// tracking_rms, tracking_peak, speed_error_final, speed_estimate_error_final,
    /// flux_error_final, current_peak, saturated_share and mean_nis, then the cell's scenario.
    Robust {
        #[command(flatten)]
        target: ScenarioArg,
        /// A parameter and its values, KEY=LO..HI:N: N evenly spaced values (1 ≤ N ≤ 101) of a
        /// plant.* or model.* key; LO and HI are values, or both relative errors in per cent
        /// against the other side's value (plant.rr=-10%..+10%:11: the motor's R_r from 10 %
        /// below to 10 % above the model's). Once or twice
        #[arg(
            long,
            value_name = "KEY=LO..HI:N",
            required = true,
            allow_hyphen_values = true,
            action = clap::ArgAction::Append
        )]
        vary: Vec<String>,
        /// Seeds run at every point, A..B (at most 1000)
        #[arg(
            long,
            value_name = "A..B",
            default_value = "1..10",
            allow_hyphen_values = true
        )]
        seeds: String,
    },
    /// Measure the teaching text's tables of measurements and print them as CSV
    ///
    /// Each TABLE is CSV, id,scenario,figure,seeds,statistic,show,value (docs/cli.md describes
    /// each column); ids are unique across the tables. Every row is measured again, each run once
    /// on all cores, and the rows are printed with the values measured; --check prints nothing
    /// and fails, naming each row whose value differs, if any does; --write writes the values
    /// into the tables, and none when a row has no value.
    Claims {
        /// The measurements tables
        #[arg(required = true)]
        tables: Vec<String>,
        /// Compare the measured values with the tables' and fail on any difference
        #[arg(long, conflicts_with = "write")]
        check: bool,
        /// Write the measured values into the tables
        #[arg(long)]
        write: bool,
    },
    /// Print a challenge's canonical link and brief; --list names the built-in ones
    Challenge {
        /// A built-in challenge's name or a challenge link
        #[arg(required_unless_present = "list")]
        challenge: Option<String>,
        /// Name the built-in challenges, one line each
        #[arg(long, conflicts_with = "challenge")]
        list: bool,
    },
    /// Grade a file of submission links and print one CSV row each
    ///
    /// Each link is re-run, nominal and variants, on all cores, and its row written as soon as it
    /// and every row before it are graded. The CSV is
    /// [<carried>,...]line,link,status,<criterion>,<criterion>_pass,...,pass where status is ok,
    /// malformed: …, refused: …, another challenge or run failed: …. Text from FILE is shown
    /// with its invisible characters escaped, and a cell a spreadsheet would run as a formula
    /// starts with '.
    Grade {
        /// A built-in challenge's name or a challenge link
        challenge: String,
        /// File of submission links (UTF-8, or UTF-16 with a byte-order mark): one a line (blank
        /// lines and # comments skipped), or a CSV export with a header whose other columns are
        /// carried to the grades first; - for stdin
        file: String,
        /// Append the grades to OUT, an earlier output of this command cut off anywhere (or
        /// missing), after the rows it holds, instead of writing them to stdout
        #[arg(long, value_name = "OUT", allow_hyphen_values = true)]
        resume: Option<String>,
    },
}

/// Why a subcommand stopped before the end.
enum Stop {
    /// The reader of stdout went away (`imlab … | head`): it has what it wanted.
    Closed,
    /// A failure, reported as `imlab: <message>`.
    Failed(String),
}

impl From<String> for Stop {
    /// A failure with this message.
    fn from(message: String) -> Self {
        Stop::Failed(message)
    }
}

/// Parses the command line, runs the subcommand and turns its end into the exit status.
fn main() -> ExitCode {
    let cli = Cli::try_parse().unwrap_or_else(|e| quoted(e).exit());
    let mut out = BufWriter::new(io::stdout().lock());
    let result = execute(cli.command, &mut out);
    // A failed run has written its trace before the failure: stdout is flushed either way.
    let flushed = out.flush().map_err(stdout_stop);
    match flushed.and(result) {
        Ok(()) | Err(Stop::Closed) => ExitCode::SUCCESS,
        Err(Stop::Failed(message)) => {
            to_stderr(format_args!("imlab: {message}\n"));
            ExitCode::from(2)
        }
    }
}

/// `error` with the user's words in its context (an unknown argument, say) quoted by `excerpt`.
fn quoted(mut error: clap::Error) -> clap::Error {
    let context: Vec<_> = error.context().map(|(k, v)| (k, v.clone())).collect();
    // The words `excerpt` rewrote: a tip that repeats one is dropped rather than cut.
    let mut rewritten = Vec::new();
    for (kind, value) in context {
        let quoted = match value {
            ContextValue::String(s) if excerpt(&s) != s => {
                let q = ContextValue::String(excerpt(&s));
                rewritten.push(s);
                q
            }
            ContextValue::Strings(list) if list.iter().any(|s| excerpt(s) != *s) => {
                let q = ContextValue::Strings(list.iter().map(|s| excerpt(s)).collect());
                rewritten.extend(list);
                q
            }
            _ => continue,
        };
        error.insert(kind, quoted);
    }
    if let Some(ContextValue::StyledStrs(tips)) = error.remove(ContextKind::Suggested) {
        let tips: Vec<_> = tips
            .into_iter()
            .filter(|tip| {
                // With its styling codes: the plain text strips whatever looks like an escape
                // sequence, the user's own included, and would no longer contain the word.
                let tip = tip.ansi().to_string();
                !rewritten.iter().any(|s| tip.contains(s.as_str()))
            })
            .collect();
        if !tips.is_empty() {
            error.insert(ContextKind::Suggested, ContextValue::StyledStrs(tips));
        }
    }
    error
}

/// Writes `text` to stderr; a closed stderr is no reason to stop or to panic.
fn to_stderr(text: fmt::Arguments) {
    let _ = io::stderr().write_fmt(text);
}

/// An error writing to stdout as a [`Stop`]: a closed pipe is the reader's choice, not a failure.
fn stdout_stop(error: io::Error) -> Stop {
    if error.kind() == ErrorKind::BrokenPipe {
        Stop::Closed
    } else {
        Stop::Failed(format!("stdout: {error}"))
    }
}

/// Runs one subcommand, writing its results to `out`.
fn execute(command: Command, out: &mut impl Write) -> Result<(), Stop> {
    match command {
        Command::List => list(out).map_err(stdout_stop),
        Command::Describe { target } => describe(&target.parse()?, out).map_err(stdout_stop),
        Command::Run {
            target,
            every,
            out: file,
        } => {
            let s = target.parse()?;
            let every = number("--every", &every, |&n: &usize| n >= 1, "a whole number ≥ 1")?;
            run(&s, every, file.as_deref(), out)
        }
        Command::Metrics { target } => metrics(&target.parse()?, out),
        Command::Law { target } => law(&target.parse()?, out),
        Command::Sweep {
            target,
            freqs,
            amp,
            offset,
            duration,
        } => {
            let s = target.parse()?;
            let freqs = frequencies(&freqs)?;
            let settings = SweepSettings {
                amp: number(
                    "--amp",
                    &amp,
                    |a: &f64| *a > 0.0 && *a <= 1000.0,
                    "0 < A ≤ 1000 rad/s",
                )?,
                offset: number(
                    "--offset",
                    &offset,
                    |w: &f64| w.abs() <= 1000.0,
                    "|W| ≤ 1000 rad/s",
                )?,
                duration: number(
                    "--duration",
                    &duration,
                    |d: &f64| *d > 0.0 && *d <= 20.0,
                    "0 < D ≤ 20 s",
                )?,
            };
            sweep(&s, &freqs, &settings, out)
        }
        Command::Seeds { target, n, first } => {
            let s = target.parse()?;
            let n = number(
                "--n",
                &n,
                |n: &u64| (1..=MAX_SEED_RUNS).contains(n),
                &format!("a whole number from 1 to {MAX_SEED_RUNS}"),
            )?;
            let first = match first {
                Some(value) => number("--first", &value, |_: &u64| true, "a whole number ≥ 0")?,
                None => s.seed,
            };
            let range = seed_range(first, n).map_err(|e| format!("--first, --n: {e}"))?;
            seeds(&s, range, out)
        }
        Command::Robust {
            target,
            vary,
            seeds,
        } => {
            let s = target.parse()?;
            let axes = vary
                .iter()
                .map(|a| Axis::parse(&s, a).map_err(|e| format!("--vary: {e}")))
                .collect::<Result<Vec<_>, _>>()?;
            let seeds = robust::parse_seeds(&seeds).map_err(|e| format!("--seeds: {e}"))?;
            let map = Map::plan(&s, axes, seeds)?;
            robust_map(&map, out)
        }
        Command::Claims {
            tables,
            check,
            write,
        } => claims(&tables, check, write, out),
        Command::Challenge { challenge, list } => match challenge {
            Some(text) if !list => show_challenge(&text, out),
            _ => list_challenges(out).map_err(stdout_stop),
        },
        Command::Grade {
            challenge,
            file,
            resume,
        } => grade(&challenge, &file, resume.as_deref(), out),
    }
}

impl ScenarioArg {
    /// The scenario the argument names.
    fn parse(&self) -> Result<Scenario, String> {
        Scenario::parse(&self.scenario).map_err(|e| e.to_string())
    }
}

/// The value of option `flag` if it parses and passes `ok`; else a message naming the option, the
/// value and the `expected` range.
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
        .ok_or_else(|| format!("{flag} '{}': expected {expected}", excerpt(value)))
}

/// The frequencies (Hz) of `--freqs`, increasing and distinct.
fn frequencies(value: &str) -> Result<Vec<f64>, String> {
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

/// Writes the presets, one `name  description` line each.
fn list(out: &mut impl Write) -> io::Result<()> {
    let width = PRESETS.iter().map(|p| p.name.len()).max().unwrap_or(0);
    for p in PRESETS {
        writeln!(out, "{:width$}  {}", p.name, p.description)?;
    }
    Ok(())
}

/// Writes the scenario's canonical string, its length and every field with unit and doc.
fn describe(s: &Scenario, out: &mut impl Write) -> io::Result<()> {
    writeln!(out, "# {}", s.encode())?;
    writeln!(out, "# {} samples of {} s", s.steps(), s.ts)?;
    for f in s.describe() {
        let value = match f.value {
            Some(v) if f.formula && v.is_empty() => "paper's".to_string(),
            Some(v) => v,
            None => "-".to_string(),
        };
        let unit = if f.unit.is_empty() {
            String::new()
        } else {
            format!(" {}", f.unit)
        };
        writeln!(
            out,
            "{:12} = {:>22}{:8}  [{}] {}",
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
        writeln!(out, "{:6} {:14} {}{steps}", n.name, n.unit, n.doc)?;
    }
    writeln!(
        out,
        "# With + - * / ^, parentheses, numbers and the functions:"
    )?;
    for (name, _, _, doc) in formula::FUNCTIONS {
        writeln!(out, "{name:6} {doc}")?;
    }
    Ok(())
}

/// Writes the verdict of each step's own law, one paragraph each; fails unless every one gives
/// its designed dynamics.
fn law(s: &Scenario, out: &mut impl Write) -> Result<(), Stop> {
    let model = s
        .model
        .lumped()
        .map_err(|e| format!("model parameters: {e}"))?;
    let verdicts = imlab::control::law::verdicts(&s.law, &model, &s.gains)
        .map_err(|(step, e)| format!("law.v{step}: {e}"))?;
    if verdicts.is_empty() {
        return Err(
            "the scenario has no law of its own: give law.v1, law.v2, law.v3 or law.v4"
                .to_string()
                .into(),
        );
    }
    for v in &verdicts {
        writeln!(out, "law.v{}: {}", v.step, v.text).map_err(stdout_stop)?;
    }
    match (
        verdicts.iter().filter(|v| !v.designed).count(),
        verdicts.len(),
    ) {
        (0, _) => Ok(()),
        (1, 1) => Err("the law does not give its designed dynamics"
            .to_string()
            .into()),
        (n, m) => Err(format!("{n} of {m} laws do not give their designed dynamics").into()),
    }
}

/// Runs the scenario keeping every `every`-th sample and writes the trace as CSV to `file` or
/// `out`; after a failure, the trace up to it, then the failure as the error. Every sample is
/// kept as checkpoints and computed again as it is written (little memory); every N-th as rows.
fn run(s: &Scenario, every: usize, file: Option<&str>, out: &mut impl Write) -> Result<(), Stop> {
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
fn metrics(s: &Scenario, out: &mut impl Write) -> Result<(), Stop> {
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
    // A run that ran away fails as a control run, although the simulation itself completed.
    for w in &report.warnings {
        if w.kind == WarningKind::Runaway {
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

/// Measures every row of the tables at `paths` and prints them, checks them, or writes them back.
fn claims(paths: &[String], check: bool, write: bool, out: &mut impl Write) -> Result<(), Stop> {
    let mut table = Vec::new();
    let mut ends = Vec::new();
    for path in paths {
        let text = std::fs::read_to_string(path)
            .map_err(|e| format!("cannot read the table {}: {e}", excerpt(path)))?;
        let rows = claims::parse_table(&text).map_err(|e| format!("{}: {e}", excerpt(path)))?;
        for m in &rows {
            if let Some(k) = table
                .iter()
                .position(|t: &claims::Measurement| t.id == m.id)
            {
                let other = &paths[ends.iter().position(|&e| k < e).unwrap_or(0)];
                return Err(format!(
                    "{}: the id '{}' is used by {} too",
                    excerpt(path),
                    m.id,
                    excerpt(other)
                )
                .into());
            }
        }
        table.extend(rows);
        ends.push(table.len());
    }
    let threads = std::thread::available_parallelism().map_or(1, usize::from);
    let progress = io::stderr().is_terminal();
    let values = claims::measure_table(&table, threads, &|done, total| {
        if progress {
            to_stderr(format_args!("imlab claims: {done}/{total} runs\r"));
        }
    });
    if progress {
        to_stderr(format_args!("\r{:40}\r", ""));
    }
    let mut failed = Vec::new();
    let mut lines = Vec::new();
    for (m, v) in table.iter().zip(&values) {
        match v {
            Ok(v) => {
                let now = claims::written(*v);
                if check && now != m.value {
                    failed.push(match m.value.as_str() {
                        "" => format!("{}: no value in the table, measured {now}", m.id),
                        was => format!("{}: the table says {was}, measured {now}", m.id),
                    });
                }
                lines.push(claims::table_line(m, &now));
            }
            Err(e) => failed.push(format!("{}: {e}", m.id)),
        }
    }
    if write && failed.is_empty() {
        let mut start = 0;
        for (path, &end) in paths.iter().zip(&ends) {
            let text = std::iter::once(claims::HEADER.to_string())
                .chain(lines[start..end].iter().cloned())
                .collect::<Vec<_>>()
                .join("\n");
            std::fs::write(path, text + "\n")
                .map_err(|e| format!("cannot write the table {}: {e}", excerpt(path)))?;
            start = end;
        }
    } else if !check && !write {
        writeln!(out, "{}", claims::HEADER).map_err(stdout_stop)?;
        for line in &lines {
            writeln!(out, "{line}").map_err(stdout_stop)?;
        }
    }
    let not_written = if write { " (no table written)" } else { "" };
    match failed.len() {
        0 => Ok(()),
        n => Err(format!(
            "{n} of {} measurements differ or have no value{not_written}:\n{}",
            table.len(),
            failed.join("\n")
        )
        .into()),
    }
}

/// Measures the response at each frequency, with progress and a count of the unsettled points on
/// stderr, and writes it as CSV.
fn sweep(
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

/// Runs the scenario with each seed of `range`, with progress on stderr, and writes each run's
/// figures as CSV.
fn seeds(
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

/// Runs every cell of `map` once per seed on all cores, with progress on stderr, and writes each
/// cell's row as soon as it and every cell before it are done (flushed, so that an interrupted
/// map keeps the rows it finished).
fn robust_map(map: &Map, out: &mut impl Write) -> Result<(), Stop> {
    let per_cell = map.seeds.len();
    let total = map.cells.len() * per_cell;
    let threads = std::thread::available_parallelism()
        .map_or(1, |n| n.get())
        .min(total);
    out.write_all(csv_preamble(map).as_bytes())
        .and_then(|()| out.flush())
        .map_err(stdout_stop)?;
    let next = std::sync::atomic::AtomicUsize::new(0);
    let stop = std::sync::atomic::AtomicBool::new(false);
    let (send, receive) = std::sync::mpsc::channel::<(usize, Result<MapRun, String>)>();
    std::thread::scope(|scope| {
        for _ in 0..threads {
            let send = send.clone();
            let (next, stop) = (&next, &stop);
            scope.spawn(move || loop {
                let i = next.fetch_add(1, std::sync::atomic::Ordering::Relaxed);
                if i >= total || stop.load(std::sync::atomic::Ordering::Relaxed) {
                    break;
                }
                let (cell, seed) = (&map.cells[i / per_cell], map.seeds[i % per_cell]);
                if send.send((i, map_run(&cell.scenario, seed))).is_err() {
                    break;
                }
            });
        }
        drop(send);
        let mut runs: Vec<Option<MapRun>> = vec![None; total];
        let (mut written, mut done) = (0, 0);
        let result = (|| {
            for (i, run) in receive.iter() {
                runs[i] =
                    Some(run.map_err(|e| format!("{}: {e}", map.cells[i / per_cell].scenario))?);
                done += 1;
                to_stderr(format_args!("\rimlab robust: {done}/{total} runs   "));
                while written < map.cells.len()
                    && runs[written * per_cell..(written + 1) * per_cell]
                        .iter()
                        .all(Option::is_some)
                {
                    let cell_runs: Vec<MapRun> = runs[written * per_cell..(written + 1) * per_cell]
                        .iter_mut()
                        .map(|r| r.take().expect("checked"))
                        .collect();
                    let row = csv_row(map, &robust::summarise(&map.cells[written], &cell_runs));
                    // Clears the progress line, so that on a terminal the row starts a line.
                    to_stderr(format_args!("\r{:30}\r", ""));
                    out.write_all(row.as_bytes())
                        .and_then(|()| out.flush())
                        .map_err(stdout_stop)?;
                    written += 1;
                }
            }
            Ok(())
        })();
        if result.is_err() {
            stop.store(true, std::sync::atomic::Ordering::Relaxed);
        }
        // Ends the progress line, so that an error message starts a line of its own.
        to_stderr(format_args!("\n"));
        result
    })
}

/// Writes the built-in challenges, one `name  summary` line each.
fn list_challenges(out: &mut impl Write) -> io::Result<()> {
    let width = BUILTINS.iter().map(|b| b.name.len()).max().unwrap_or(0);
    for b in BUILTINS {
        writeln!(out, "{:width$}  {}", b.name, b.summary)?;
    }
    Ok(())
}

/// Writes the challenge's canonical link, its fingerprint (and the built-in it passes for while
/// differing from it), then its brief.
fn show_challenge(text: &str, out: &mut impl Write) -> Result<(), Stop> {
    let c = Challenge::parse(text).map_err(|e| format!("challenge: {e}"))?;
    let mut head = format!("{}\nfingerprint: {}\n", c.encode(), c.fingerprint());
    if let Some(name) = c.edited_builtin() {
        let original = builtin(name).expect("a built-in").challenge();
        head.push_str(&format!(
            "edited: not the built-in {name} (fingerprint {}), whose title it carries\n",
            original.fingerprint()
        ));
    }
    writeln!(out, "{head}\n{}", c.brief().trim_end()).map_err(stdout_stop)
}

/// Grades each submission of `file` against the challenge and writes the grades as CSV to
/// `out`, or with `resume` appended to that file after the rows it already holds; progress on
/// stderr.
fn grade(
    challenge: &str,
    file: &str,
    resume: Option<&str>,
    out: &mut impl Write,
) -> Result<(), Stop> {
    let c = Challenge::parse(challenge).map_err(|e| format!("challenge: {e}"))?;
    let (name, bytes) = if file == "-" {
        let mut bytes = Vec::new();
        let read = io::stdin().read_to_end(&mut bytes).map(|_| bytes);
        ("stdin".to_string(), read)
    } else {
        (format!("'{}'", excerpt(file)), std::fs::read(file))
    };
    let bytes = bytes.map_err(|e| format!("{name}: {e}"))?;
    let class = grade::read_class(&bytes).map_err(|e| format!("{name}: {e}"))?;
    let header = grade::csv_header(&c, &class);
    let Some(path) = resume else {
        return grade_rows(&c, &class.rows, 0, &header, |text| {
            out.write_all(text.as_bytes())
                .and_then(|()| out.flush())
                .map_err(stdout_stop)
        });
    };
    let failed = |e: io::Error| Stop::Failed(format!("--resume '{}': {e}", excerpt(path)));
    let previous = match std::fs::read(path) {
        Ok(bytes) => bytes,
        Err(e) if e.kind() == ErrorKind::NotFound => Vec::new(),
        Err(e) => return Err(failed(e)),
    };
    let from = grade::resume(&c, &class, &previous)
        .map_err(|e| format!("--resume '{}': {e}", excerpt(path)))?;
    let mut file = OpenOptions::new()
        .write(true)
        .create(true)
        .truncate(false)
        .open(path)
        .map_err(failed)?;
    file.set_len(from.keep as u64)
        .and_then(|()| file.seek(SeekFrom::End(0)))
        .map_err(failed)?;
    let header = if from.keep == 0 { &header[..] } else { "" };
    grade_rows(&c, &class.rows, from.done, header, |text| {
        file.write_all(text.as_bytes()).map_err(failed)
    })
}

/// Writes `header`, then grades `rows[done..]` on all cores and writes each one's CSV line as
/// soon as it and every row before it are graded, through `write` (which must flush: an
/// interrupted grading keeps the rows it finished); progress on stderr.
fn grade_rows(
    c: &Challenge,
    rows: &[ClassRow],
    done: usize,
    header: &str,
    mut write: impl FnMut(&str) -> Result<(), Stop>,
) -> Result<(), Stop> {
    write(header)?;
    let todo = &rows[done..];
    let total = rows.len();
    let threads = std::thread::available_parallelism()
        .map_or(1, |n| n.get())
        .min(todo.len().max(1));
    let next = std::sync::atomic::AtomicUsize::new(0);
    let stop = std::sync::atomic::AtomicBool::new(false);
    let (send, receive) = std::sync::mpsc::channel::<(usize, Graded)>();
    std::thread::scope(|scope| {
        for _ in 0..threads {
            let send = send.clone();
            let (next, stop) = (&next, &stop);
            scope.spawn(move || loop {
                let i = next.fetch_add(1, std::sync::atomic::Ordering::Relaxed);
                let Some(row) = todo.get(i) else {
                    break;
                };
                if stop.load(std::sync::atomic::Ordering::Relaxed) {
                    break;
                }
                // A panic in one run is that row's failure, not the end of the grading.
                let graded =
                    std::panic::catch_unwind(|| grade::grade_row(c, row)).unwrap_or_else(|_| {
                        Graded::failed(row.line, &row.link, "run failed: internal error")
                    });
                if send.send((i, graded)).is_err() {
                    break;
                }
            });
        }
        drop(send);
        let mut graded: Vec<Option<Graded>> = vec![None; todo.len()];
        let (mut written, mut finished) = (0, done);
        let result = (|| {
            for (i, g) in receive.iter() {
                graded[i] = Some(g);
                finished += 1;
                if total > 4 {
                    to_stderr(format_args!(
                        "\rimlab grade: graded {finished} of {total}   "
                    ));
                }
                while let Some(g) = graded.get_mut(written).and_then(Option::take) {
                    if total > 4 {
                        // Clears the progress line, so that on a terminal the row starts a line.
                        to_stderr(format_args!("\r{:40}\r", ""));
                    }
                    write(&grade::csv_row(c, &todo[written], &g))?;
                    written += 1;
                }
            }
            Ok(())
        })();
        if result.is_err() {
            stop.store(true, std::sync::atomic::Ordering::Relaxed);
        }
        if total > 4 {
            // Ends the progress line, so that an error message starts a line of its own.
            to_stderr(format_args!("\n"));
        }
        result
    })
}
