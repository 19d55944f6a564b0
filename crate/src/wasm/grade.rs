//! The grading bindings: a class's file read, one submission graded and its CSV row written, all
//! by the core's grader ([`crate::challenge::grade`]), so that the page's grades are the bytes
//! `imlab grade` writes: the header of [`grade_class`], then each row's `csv` from
//! [`grade_link`], in the rows' order.

use super::{from_js, js_error, to_js};
use crate::challenge::grade::{self, ClassRow};
use crate::challenge::{Challenge, Verdict};
use crate::text::{escape_invisible, Message};
use serde::Serialize;
use tsify::Ts;
use wasm_bindgen::prelude::*;

/// What [`grade_class`] gives the page.
#[cfg_attr(
    target_arch = "wasm32",
    derive(tsify::Tsify),
    tsify(missing_as_null, hashmap_as_object)
)]
#[derive(Serialize)]
pub struct ClassView {
    /// The CSV header line, with its line end ("" when the file is refused).
    header: String,
    /// The headers of the carried columns, as the page shows them (see [`ShownRow`]).
    columns: Vec<String>,
    /// The header of a CSV export's column of links, or null.
    link_column: Option<String>,
    /// The submissions, in file order.
    rows: Vec<ClassRow>,
    /// The encoding the file was read in when it is not UTF-8 (guessed from its bytes:
    /// "windows-1252", say), or null.
    encoding: Option<String>,
    /// Each submission as the page's table shows it, in the same order.
    shown: Vec<ShownRow>,
    /// Why the challenge or the file is refused whole, or null.
    error: Option<Message>,
}

/// A submission's text as the page's table shows it: its invisible characters escaped, as in
/// every message, so that a name or a link cannot hide or reorder what it holds.
#[cfg_attr(
    target_arch = "wasm32",
    derive(tsify::Tsify),
    tsify(missing_as_null, hashmap_as_object)
)]
#[derive(Serialize)]
pub struct ShownRow {
    /// The link.
    link: String,
    /// The cells of the carried columns.
    carried: Vec<String>,
}

/// Reads a class's file against a challenge: `challenge` is a challenge link or a built-in's
/// name, `bytes` (a `Uint8Array`) the file as it is (UTF-8, UTF-16 with a byte-order mark, or
/// a legacy encoding such as Windows-1252, which the core tells from the bytes; one link a line
/// or a CSV export; see the core's `challenge::grade` documentation). Never throws; returns
///
/// ```text
/// {header: string (the CSV header line, "\n" included; "" on error),
///  columns: [string] (the carried columns' headers, escaped), link_column: string | null,
///  rows: [{line: number, link: string, carried: [string], fault: RowFault | null}],
///  encoding: string | null (the encoding read, when the file is not UTF-8),
///  shown: [{link: string, carried: [string]}] (each row as the table shows it, escaped),
///  error: Message | null (why the challenge or the file is refused whole)}
/// ```
///
/// where a row's `fault` is set when it is graded malformed as it is read (its line 4 is not
/// valid UTF-8, say). Each row goes as it is to [`grade_link`].
#[wasm_bindgen]
pub fn grade_class(challenge: &str, bytes: &[u8]) -> Result<Ts<ClassView>, JsValue> {
    let read = Challenge::parse(challenge)
        .map_err(|e| Message::new("grade-challenge-refused").said("error", e.message))
        .and_then(|c| Ok((grade::read_class(bytes)?, c)));
    let view = match read {
        Ok((class, c)) => ClassView {
            header: grade::csv_header(&c, &class),
            columns: class.columns.iter().map(|c| escape_invisible(c)).collect(),
            link_column: class.link_column,
            shown: class
                .rows
                .iter()
                .map(|r| ShownRow {
                    link: escape_invisible(&r.link),
                    carried: r.carried.iter().map(|c| escape_invisible(c)).collect(),
                })
                .collect(),
            rows: class.rows,
            encoding: class.encoding.map(str::to_string),
            error: None,
        },
        Err(e) => ClassView {
            header: String::new(),
            columns: Vec::new(),
            link_column: None,
            rows: Vec::new(),
            encoding: None,
            shown: Vec::new(),
            error: Some(e),
        },
    };
    to_js(&view)
}

/// What [`grade_link`] gives the page.
#[cfg_attr(
    target_arch = "wasm32",
    derive(tsify::Tsify),
    tsify(missing_as_null, hashmap_as_object)
)]
#[derive(Serialize)]
pub struct GradedView {
    line: usize,
    link: String,
    /// "ok", "malformed: …", "refused: …", "another challenge" or "run failed: …".
    status: Message,
    pass: bool,
    #[cfg_attr(target_arch = "wasm32", tsify(type = "ChallengeVerdict | null"))]
    verdict: Option<Verdict>,
    /// The row's CSV line, "\n" included.
    csv: String,
}

/// Grades one row completely in one call (it runs the nominal run and every variant, so the page
/// calls it in a worker): `challenge` as for [`grade_class`], `row` one of its rows, `{line,
/// link, carried?, fault?}` (a single link: `{line: 1, link}`). Returns
///
/// ```text
/// {line: number, link: string,
///  status: Message ("ok", "malformed: …", "refused: …", "another challenge", "run failed: …"),
///  pass: boolean (judged and every criterion met),
///  verdict: {criteria: [{figure, label, bound, value, unit, run, pass, reason}], pass} | null,
///  csv: string (the row's CSV line, "\n" included, as `imlab grade` writes it)}
/// ```
///
/// Throws when the challenge does not parse or `row` is not of that shape.
#[wasm_bindgen]
pub fn grade_link(challenge: &str, row: Ts<ClassRow>) -> Result<Ts<GradedView>, JsValue> {
    let c = Challenge::parse(challenge).map_err(js_error)?;
    let row: ClassRow = from_js(&row)?;
    let graded = grade::grade_row(&c, &row);
    to_js(&GradedView {
        csv: grade::csv_row(&c, &row, &graded),
        pass: graded.pass(),
        line: graded.line,
        link: graded.link,
        status: graded.status,
        verdict: graded.verdict,
    })
}
