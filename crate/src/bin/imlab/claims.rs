//! The `claims` subcommand: the teaching text's tables measured, printed, checked or written.

use crate::output::{stdout_stop, to_stderr, Stop};
use imlab::analysis::claims;
use imlab::text::excerpt;
use std::io::{self, IsTerminal, Write};

/// Measures every row of the tables at `paths` and prints them, checks them, or writes them back.
pub(crate) fn claims(
    paths: &[String],
    check: bool,
    write: bool,
    out: &mut impl Write,
) -> Result<(), Stop> {
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
