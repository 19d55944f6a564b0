//! `imlab`: run IM Lab scenarios from the command line. This file parses it, hands each
//! subcommand to its module and turns the subcommand's end into the exit status.

mod analysis;
mod challenge;
mod claims;
mod cli;
mod grade;
mod law;
mod motor;
mod output;
mod robust;
mod run;

use clap::error::{ContextKind, ContextValue};
use clap::Parser;
use cli::{number, Cli, Command};
use imlab::text::excerpt;
use output::{stdout_stop, to_stderr, Stop};
use std::io::{self, BufWriter, Write};
use std::process::ExitCode;

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

/// Runs one subcommand, writing its results to `out`.
fn execute(command: Command, out: &mut impl Write) -> Result<(), Stop> {
    match command {
        Command::List => run::list(out).map_err(stdout_stop),
        Command::Describe { target } => run::describe(&target.parse()?, out).map_err(stdout_stop),
        Command::Design { target } => run::design(&target.parse()?, out),
        Command::Motor(args) => motor::motor(&args, out),
        Command::Run {
            target,
            every,
            out: file,
        } => {
            let s = target.parse()?;
            let every = number("--every", &every, |&n: &usize| n >= 1, "a whole number ≥ 1")?;
            run::run(&s, every, file.as_deref(), out)
        }
        Command::Metrics { target } => run::metrics(&target.parse()?, out),
        Command::Law { target } => law::law(&target.parse()?, out),
        Command::Sweep {
            target,
            freqs,
            amp,
            offset,
            duration,
            plan,
        } => {
            let s = target.parse()?;
            if let Some(plan) = plan {
                return analysis::sweep_plan(&s, &plan, out);
            }
            let freqs = analysis::frequencies(&freqs)?;
            let settings = analysis::sweep_settings(&amp, &offset, &duration)?;
            analysis::sweep(&s, &freqs, &settings, out)
        }
        Command::Seeds { target, n, first } => {
            let s = target.parse()?;
            let range = analysis::seed_options(&s, &n, first.as_deref())?;
            analysis::seeds(&s, range, out)
        }
        Command::Robust {
            target,
            vary,
            seeds,
        } => {
            let s = target.parse()?;
            let map = robust::plan(&s, &vary, &seeds)?;
            robust::robust_map(&map, out)
        }
        Command::Claims {
            tables,
            check,
            write,
        } => claims::claims(&tables, check, write, out),
        Command::Challenge { challenge, list } => match challenge {
            Some(text) if !list => challenge::show_challenge(&text, out),
            _ => challenge::list_challenges(out).map_err(stdout_stop),
        },
        Command::Grade {
            challenge,
            file,
            resume,
        } => grade::grade(&challenge, &file, resume.as_deref(), out),
    }
}
