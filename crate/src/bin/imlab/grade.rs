//! The `grade` subcommand: a class's submission links graded on all cores, a CSV row each.

use crate::output::{stdout_stop, to_stderr, Stop};
use fs4::{FileExt, TryLockError};
use imlab::challenge::grade::{self, Class, ClassRow, Graded};
use imlab::challenge::Challenge;
use imlab::text::{excerpt, Message};
use std::collections::hash_map::RandomState;
use std::fs::OpenOptions;
use std::hash::{BuildHasher, Hasher};
use std::io::{self, Read, Seek, SeekFrom, Write};

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
    if let Some(encoding) = class.encoding {
        to_stderr(format_args!(
            "imlab grade: read {name} as {encoding} (it is not UTF-8)\n"
        ));
    }
    let header = grade::csv_header(&c, &class);
    match resume {
        None => grade_rows(&c, &class.rows, 0, &header, |text| {
            out.write_all(text.as_bytes())
                .and_then(|()| out.flush())
                .map_err(stdout_stop)
        }),
        Some(path) => resume_into(&c, &class, &header, path),
    }
}

/// Appends the grades of `class` to the file `path` after the rows it already holds (see
/// [`grade::resume`]), holding the file's lock from before it is read until the process ends,
/// and after grading a sample of its rows again; a file another grading holds, or whose rows
/// are not this grading's, is refused and left as it is.
fn resume_into(c: &Challenge, class: &Class, header: &str, path: &str) -> Result<(), Stop> {
    let named = |e: String| Stop::Failed(format!("--resume '{}': {e}", excerpt(path)));
    let failed = |e: io::Error| named(e.to_string());
    let mut file = OpenOptions::new()
        .read(true)
        .write(true)
        .create(true)
        .truncate(false)
        .open(path)
        .map_err(failed)?;
    // The trait's, not the standard library's method of the same name (Rust 1.89 and later).
    match FileExt::try_lock(&file) {
        Ok(()) => {}
        Err(TryLockError::WouldBlock) => {
            return Err(named(
                "another grading holds this file (it is locked by a running `imlab grade \
                 --resume`); it is left as it is"
                    .to_string(),
            ))
        }
        Err(TryLockError::Error(e)) => return Err(failed(e)),
    }
    let mut previous = Vec::new();
    file.read_to_end(&mut previous).map_err(failed)?;
    // A seed of the system's randomness (std's hash keys), drawn afresh each time.
    let seed = RandomState::new().build_hasher().finish();
    let from = grade::resume(c, class, &previous, seed).map_err(|e| named(e.to_string()))?;
    let sample: Vec<&ClassRow> = from.sample.iter().map(|k| &class.rows[k.index]).collect();
    grade_each(
        c,
        &sample,
        ("checking kept rows: graded", 0),
        |i, graded| {
            grade::check_kept(c, class, &from.sample[i], &graded).map_err(|e| named(e.to_string()))
        },
    )?;
    file.set_len(from.keep as u64)
        .and_then(|()| file.seek(SeekFrom::End(0)))
        .map_err(failed)?;
    let header = if from.keep == 0 { header } else { "" };
    grade_rows(c, &class.rows, from.done, header, |text| {
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
    let todo: Vec<&ClassRow> = rows[done..].iter().collect();
    grade_each(c, &todo, ("graded", done), |i, graded| {
        write(&grade::csv_row(c, todo[i], &graded))
    })
}

/// Grades `rows` on all cores and hands each one's grading, with its index, to `take` as soon as
/// it and every row before it are graded; stops at the first error of `take`. More than four
/// rows in all show progress on stderr, `imlab grade: <label> <n> of <total>`, where `progress`
/// is the label and the rows counted before these.
fn grade_each(
    c: &Challenge,
    rows: &[&ClassRow],
    progress: (&str, usize),
    mut take: impl FnMut(usize, Graded) -> Result<(), Stop>,
) -> Result<(), Stop> {
    let (label, before) = progress;
    let total = before + rows.len();
    let threads = std::thread::available_parallelism()
        .map_or(1, |n| n.get())
        .min(rows.len().max(1));
    let next = std::sync::atomic::AtomicUsize::new(0);
    let stop = std::sync::atomic::AtomicBool::new(false);
    let (send, receive) = std::sync::mpsc::channel::<(usize, Graded)>();
    std::thread::scope(|scope| {
        for _ in 0..threads {
            let send = send.clone();
            let (next, stop) = (&next, &stop);
            scope.spawn(move || loop {
                let i = next.fetch_add(1, std::sync::atomic::Ordering::Relaxed);
                let Some(row) = rows.get(i) else {
                    break;
                };
                if stop.load(std::sync::atomic::Ordering::Relaxed) {
                    break;
                }
                // A panic in one run is that row's failure, not the end of the grading.
                let graded =
                    std::panic::catch_unwind(|| grade::grade_row(c, row)).unwrap_or_else(|_| {
                        let internal = Message::new("grade-internal-error");
                        Graded::run_failed(row.line, &row.link, internal)
                    });
                if send.send((i, graded)).is_err() {
                    break;
                }
            });
        }
        drop(send);
        let mut graded: Vec<Option<Graded>> = vec![None; rows.len()];
        let (mut taken, mut finished) = (0, before);
        let result = (|| {
            for (i, g) in receive.iter() {
                graded[i] = Some(g);
                finished += 1;
                if total > 4 {
                    to_stderr(format_args!(
                        "\rimlab grade: {label} {finished} of {total}   "
                    ));
                }
                while let Some(g) = graded.get_mut(taken).and_then(Option::take) {
                    if total > 4 {
                        // Clears the progress line, so that on a terminal the row starts a line.
                        to_stderr(format_args!("\r{:40}\r", ""));
                    }
                    take(taken, g)?;
                    taken += 1;
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
