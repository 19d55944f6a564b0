//! The `grade` subcommand: a class's submission links graded on all cores, a CSV row each.

use crate::output::{stdout_stop, to_stderr, Stop};
use imlab::challenge::grade::{self, ClassRow, Graded};
use imlab::challenge::Challenge;
use imlab::text::excerpt;
use std::fs::OpenOptions;
use std::io::{self, ErrorKind, Read, Seek, SeekFrom, Write};

/// Grades each submission of `file` against the challenge and writes the grades as CSV to
/// `out`, or with `resume` appended to that file after the rows it already holds; progress on
/// stderr.
pub(crate) fn grade(
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
