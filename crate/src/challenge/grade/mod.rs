//! Grading a class: its file read ([`read_class`]), each submission re-run and judged
//! ([`grade_one`]), and the grades written as CSV ([`csv_header`], [`csv_row`]). `imlab grade`
//! and the page's bindings both grade through these, so their CSVs are the same bytes.
//!
//! Every cell of text that comes from the file or from a student (the link, the carried
//! columns and their headers, the status that quotes a link) is written safe to open, by
//! [`csv::text_field`].
//!
//! The numbers the grader computes (line numbers, values, pass flags) are written as they are.

mod class;

pub use class::{read_class, Class, ClassRow, RowFault};

use super::{judge, measure, Challenge, Measures, Verdict};
use crate::rng::Rng;
use crate::sim::Simulation;
use crate::text::{csv, excerpt, Message};
use serde::Serialize;

/// One graded submission: its line, the link, and the status with the verdict (None unless the
/// runs were judged).
#[derive(Clone, Debug, PartialEq, Serialize)]
pub struct Graded {
    /// The line of the class's file the submission starts on.
    pub line: usize,
    /// The link.
    pub link: String,
    /// `ok`, `malformed: …`, `refused: …`, `another challenge` or `run failed: …`.
    pub status: Message,
    /// The verdict, when the runs were judged.
    pub verdict: Option<Verdict>,
}

impl Graded {
    /// A submission graded `status` without a verdict.
    pub fn failed(line: usize, link: &str, status: Message) -> Graded {
        Graded {
            line,
            link: link.to_string(),
            status,
            verdict: None,
        }
    }

    /// A submission whose run failed for `reason` (why, in words: the core's message, or the
    /// text of a run's failure), without a verdict.
    pub fn run_failed(line: usize, link: &str, reason: Message) -> Graded {
        let status = Message::new("grade-row-run-failed").said("reason", reason);
        Graded::failed(line, link, status)
    }

    /// Whether the submission was judged and meets every criterion.
    pub fn pass(&self) -> bool {
        self.verdict.as_ref().is_some_and(|v| v.pass)
    }
}

/// Reads, re-runs (nominal run and variants, one after the other) and judges one submission
/// link of line `line`.
pub fn grade_one(c: &Challenge, line: usize, link: &str) -> Graded {
    let mut graded = Graded::failed(line, link, Message::new("grade-row-ok"));
    let scenarios = match c.submission(link).and_then(|s| s.scenarios()) {
        Ok(s) => s,
        Err(e) => {
            graded.status = e.status();
            return graded;
        }
    };
    let mut runs: Vec<Measures> = Vec::new();
    for s in &scenarios {
        let m = match Simulation::traced(s) {
            Ok(mut sim) => {
                let _ = sim.run();
                measure(&sim)
            }
            Err(e) => Measures {
                failure: Some(e.message().into()),
                ..Measures::default()
            },
        };
        if let Some(f) = &m.failure {
            graded.status = Message::new("grade-row-run-failed").arg("reason", f.clone());
            return graded;
        }
        runs.push(m);
    }
    match judge(c, &runs) {
        Ok(v) => graded.verdict = Some(v),
        Err(e) => graded.status = Message::new("grade-row-run-failed").said("reason", e),
    }
    graded
}

/// Grades one row of a class's file: its status when it was graded as it was read (a line that
/// did not decode, say), else its link by [`grade_one`].
pub fn grade_row(c: &Challenge, row: &ClassRow) -> Graded {
    match &row.fault {
        Some(fault) => Graded::failed(row.line, &row.link, fault.status()),
        None => grade_one(c, row.line, &row.link),
    }
}

/// The CSV header of the grades, with its line end: the carried columns of the class's file,
/// then `line,link,status`, `<figure>,<figure>_pass` for each criterion, and `pass`.
pub fn csv_header(c: &Challenge, class: &Class) -> String {
    let mut out = String::new();
    for name in &class.columns {
        out.push_str(&csv::text_field(name));
        out.push(',');
    }
    out.push_str("line,link,status");
    for n in &c.need {
        out.push_str(&format!(",{0},{0}_pass", n.figure));
    }
    out.push_str(",pass\n");
    out
}

/// The start of a row's CSV line: its carried cells, line and link, each followed by a comma.
fn row_start(row: &ClassRow) -> String {
    let mut out = String::new();
    for cell in &row.carried {
        out.push_str(&csv::text_field(cell));
        out.push(',');
    }
    out.push_str(&format!("{},{},", row.line, csv::text_field(&row.link)));
    out
}

/// The CSV line of a graded row, with its line end: the row's carried cells, line and link, the
/// status, each criterion's value (empty when not measured) and pass (1 or 0), and pass.
pub fn csv_row(c: &Challenge, row: &ClassRow, graded: &Graded) -> String {
    let mut out = row_start(row);
    out.push_str(&csv::text_field(&graded.status.to_string()));
    match &graded.verdict {
        Some(v) => {
            for cv in &v.criteria {
                let value = cv.value.map_or(String::new(), |x| format!("{x}"));
                out.push_str(&format!(",{value},{}", u8::from(cv.pass)));
            }
            out.push_str(&format!(",{}", u8::from(v.pass)));
        }
        None => {
            out.push_str(&",,0".repeat(c.need.len()));
            out.push_str(",0");
        }
    }
    out.push('\n');
    out
}

/// Where an interrupted grading picks up: what to keep of its output, how many rows it holds,
/// and which of them to grade again before going on.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Resume {
    /// The bytes of the output to keep: its complete lines (a cut-off last line is dropped).
    pub keep: usize,
    /// The rows of the class it holds, graded: the grading goes on from the next.
    pub done: usize,
    /// The kept rows to grade again, each to be the same bytes (see [`resume_sample`]).
    pub sample: Vec<KeptRow>,
}

/// A kept row of an interrupted grading's output, to be graded again and compared.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct KeptRow {
    /// Its index in the class's rows (and among the output's rows).
    pub index: usize,
    /// Its CSV line as the output holds it, line end included.
    pub found: String,
}

/// One in this many kept rows is graded again when a grading resumes (and always the last).
pub const RESUME_STRIDE: usize = 20;

/// The indices of the kept rows graded again when a grading resumes with `done` rows kept: every
/// [`RESUME_STRIDE`]th row from an offset drawn by `seed`, and the last. The caller draws the seed
/// afresh each time (`imlab grade --resume` from the system's randomness), so that nothing in the
/// file tells its editor which rows will be graded again.
pub fn resume_sample(seed: u64, done: usize) -> Vec<usize> {
    if done == 0 {
        return Vec::new();
    }
    let offset = (Rng::new(seed).next_u64() % RESUME_STRIDE as u64) as usize;
    let mut sample: Vec<usize> = (offset..done).step_by(RESUME_STRIDE).collect();
    if sample.last() != Some(&(done - 1)) {
        sample.push(done - 1);
    }
    sample
}

/// Where the grading of `class` against `c` resumes from `previous`, an earlier output of the
/// same grading cut off anywhere (empty: from the start). Its complete lines must be the
/// grades' header and then rows of the class's first submissions, in order (each row's carried
/// cells, line and link as they would be written); anything else is refused with what differs,
/// as the output of another grading. The rows of [`Resume::sample`] (drawn by `seed`, see
/// [`resume_sample`]) are then to be graded again and checked by [`check_kept`].
pub fn resume(c: &Challenge, class: &Class, previous: &[u8], seed: u64) -> Result<Resume, Message> {
    let keep = previous
        .iter()
        .rposition(|&b| b == b'\n')
        .map_or(0, |i| i + 1);
    if keep == 0 {
        return Ok(Resume {
            keep,
            done: 0,
            sample: Vec::new(),
        });
    }
    let text = std::str::from_utf8(&previous[..keep])
        .map_err(|_| Message::new("grade-resume-not-utf8"))?;
    let mut lines = text.split_inclusive('\n');
    let header = csv_header(c, class);
    let found = lines.next().unwrap_or_default();
    if found != header {
        return Err(Message::new("grade-resume-header").text("header", header.trim_end()));
    }
    let rows: Vec<&str> = lines.collect();
    for (done, found) in rows.iter().enumerate() {
        let Some(row) = class.rows.get(done) else {
            return Err(Message::new("grade-resume-too-many-rows").count("rows", class.rows.len()));
        };
        if !found.starts_with(&row_start(row)) {
            return Err(Message::new("grade-resume-row")
                .count("row", done + 1)
                .count("line", row.line)
                .text("link", excerpt(&row.link)));
        }
    }
    let sample = resume_sample(seed, rows.len())
        .into_iter()
        .map(|index| KeptRow {
            index,
            found: rows[index].to_string(),
        })
        .collect();
    Ok(Resume {
        keep,
        done: rows.len(),
        sample,
    })
}

/// The cells of a CSV line (without its line end), as written: split at the commas outside
/// quotes, quotes kept.
fn cells(line: &str) -> Vec<&str> {
    let (mut out, mut start, mut quoted) = (Vec::new(), 0, false);
    for (i, b) in line.bytes().enumerate() {
        match b {
            b'"' => quoted = !quoted,
            b',' if !quoted => {
                out.push(&line[start..i]);
                start = i + 1;
            }
            _ => {}
        }
    }
    out.push(&line[start..]);
    out
}

/// Checks a kept row against `graded`, its grading again: the row must be the bytes
/// [`csv_row`] writes for it (its status, values, pass flags and nothing after them), or it is
/// refused, naming the row, its line in the class file and the first cell that differs.
pub fn check_kept(
    c: &Challenge,
    class: &Class,
    kept: &KeptRow,
    graded: &Graded,
) -> Result<(), Message> {
    let row = &class.rows[kept.index];
    let expected = csv_row(c, row, graded);
    if kept.found == expected {
        return Ok(());
    }
    // The cells after the link: the row's start was checked by `resume`.
    let start = row_start(row).len();
    let found = cells(kept.found[start..].trim_end_matches('\n'));
    let expected = cells(expected[start..].trim_end_matches('\n'));
    let mut names = vec!["status".to_string()];
    for n in &c.need {
        names.extend([n.figure.to_string(), format!("{}_pass", n.figure)]);
    }
    names.push("pass".to_string());
    let what = match found.iter().zip(&expected).position(|(f, e)| f != e) {
        Some(i) => Message::new("grade-kept-cell")
            .text("column", names[i].as_str())
            .text("found", excerpt(found[i]))
            .text("expected", excerpt(expected[i])),
        None if found.len() > expected.len() => Message::new("grade-kept-extra")
            .text("extra", excerpt(&found[expected.len()..].join(","))),
        None => Message::new("grade-kept-short").text("column", names[found.len()].as_str()),
    };
    Err(Message::new("grade-kept-differs")
        .count("row", kept.index + 1)
        .count("line", row.line)
        .said("what", what))
}
