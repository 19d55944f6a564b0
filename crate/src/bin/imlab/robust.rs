//! The `robust` subcommand: a model-error map run on all cores, a CSV row a cell.

use crate::output::{stdout_stop, to_stderr, Stop};
use imlab::analysis::robust::{self, csv_preamble, csv_row, map_run, Axis, Map, MapRun};
use imlab::scenario::Scenario;
use std::io::Write;

/// The map of the `--vary` axes and `--seeds` around the scenario `s`.
pub(crate) fn plan(s: &Scenario, vary: &[String], seeds: &str) -> Result<Map, String> {
    let axes = vary
        .iter()
        .map(|a| Axis::parse(s, a).map_err(|e| format!("--vary: {e}")))
        .collect::<Result<Vec<_>, _>>()?;
    let seeds = robust::parse_seeds(seeds).map_err(|e| format!("--seeds: {e}"))?;
    Map::plan(s, axes, seeds).map_err(|e| e.to_string())
}

/// Runs every cell of `map` once per seed on all cores, with progress on stderr, and writes each
/// cell's row as soon as it and every cell before it are done (flushed, so that an interrupted
/// map keeps the rows it finished).
pub(crate) fn robust_map(map: &Map, out: &mut impl Write) -> Result<(), Stop> {
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
