//! A class's file of submissions, read as the grader reads it: the text decoded, the shape told
//! (one link a line, or a course platform's CSV export), and one row per submission with its line
//! in the file.
//!
//! - **Encoding.** UTF-8, with or without a byte-order mark, or UTF-16 (little- or big-endian)
//!   with one. A file with NUL bytes and no byte-order mark is refused whole: as UTF-16 without a
//!   byte-order mark when its NULs fall on every other byte, else as not text. A file without a
//!   byte-order mark that is not valid UTF-8 is read in the legacy encoding its bytes point to
//!   (Windows-1252 for a spreadsheet's export in Western Europe; guessed by chardetng, decoded by
//!   encoding_rs), and [`Class::encoding`] names it. A line that does not decode spoils only
//!   itself: its row is graded `malformed: line N is not valid UTF-8` (or UTF-16, or the legacy
//!   encoding's name; see [`RowFault`]), its text shown with `�` for the bytes at fault.
//! - **Lines** end with LF, CRLF or a lone CR.
//! - **Shape.** The first line that is neither blank nor a `#` comment decides. It is the header
//!   of a CSV export when it has two or more fields (separated by commas, semicolons or tabs,
//!   whichever gives the most) none of which holds `=` (every link holds one), or when it is the
//!   single word `link`, `url` or `submission`. Otherwise the file is one link a line: blank lines
//!   and `#` comments are skipped, each other line (trimmed) is a link.
//! - **CSV export.** RFC 4180 fields: quoted fields may hold the separator, doubled quotes and
//!   line breaks. The links are the column headed `link`, `url` or `submission` (any case), or
//!   else the one column with a cell holding `c=1` or `challenge=`; two candidates, or none, are
//!   refused with the columns named. The other columns are carried to the grades in order.
//!   Records with every field blank are skipped. A record with more fields than the header gives
//!   the extra ones to its link, which was written unquoted and split at its own commas
//!   (`robust=a,b`); one with fewer fields, or without a link, is a row graded `malformed: …`.

use crate::text::{excerpt, Message};
use chardetng::{EncodingDetector, Iso2022JpDetection, Utf8Detection};
use encoding_rs::Encoding;
use serde::{Deserialize, Serialize};

/// A class's file, read: the submissions to grade, in file order.
#[derive(Clone, Debug, Default, PartialEq, Serialize)]
pub struct Class {
    /// The headers of the columns carried to the grades (those of a CSV export but the links'),
    /// in order; empty for a file of one link a line.
    pub columns: Vec<String>,
    /// The header of a CSV export's column of links; None for a file of one link a line.
    pub link_column: Option<String>,
    /// The submissions, in file order.
    pub rows: Vec<ClassRow>,
    /// The encoding the file was read in when it is not UTF-8 and has no byte-order mark,
    /// guessed from its bytes (`windows-1252`, say); None for a file read as UTF-8, or as
    /// UTF-16 by its byte-order mark.
    pub encoding: Option<&'static str>,
}

/// One submission of a class's file.
#[cfg_attr(
    target_arch = "wasm32",
    derive(tsify::Tsify),
    tsify(missing_as_null, hashmap_as_object)
)]
#[derive(Clone, Debug, Default, PartialEq, Serialize, Deserialize)]
pub struct ClassRow {
    /// The line of the file it starts on (the first is 1).
    pub line: usize,
    /// The link, trimmed.
    pub link: String,
    /// The cells of the carried columns, in the order of [`Class::columns`].
    #[serde(default)]
    pub carried: Vec<String>,
    /// Why a row is graded `malformed` as it is read, without a run (its line 4 is not valid
    /// UTF-8, say); None for a row whose link is to be graded.
    #[serde(default)]
    pub fault: Option<RowFault>,
}

/// Why a row of a class's file is malformed as it is read.
#[cfg_attr(
    target_arch = "wasm32",
    derive(tsify::Tsify),
    tsify(missing_as_null, hashmap_as_object)
)]
#[derive(Clone, Debug, PartialEq, Eq, Serialize, Deserialize)]
#[serde(tag = "kind", rename_all = "lowercase")]
pub enum RowFault {
    /// Its line `line` did not decode in `encoding`.
    Undecoded {
        /// The line.
        line: usize,
        /// The name of the encoding the file was read in.
        encoding: String,
    },
    /// A quoted field starting on line `line` is still open at the end of the file.
    Unclosed {
        /// The line.
        line: usize,
    },
    /// The record on line `line` has `fields` fields, the header `header`.
    Fields {
        /// The line.
        line: usize,
        /// Its fields.
        fields: usize,
        /// The header's.
        header: usize,
    },
    /// The record has no link.
    NoLink,
}

impl RowFault {
    /// Why the row is malformed, in words: `line 4 is not valid UTF-8`.
    pub fn message(&self) -> Message {
        match self {
            RowFault::Undecoded { line, encoding } => Message::new("grade-line-undecoded")
                .count("line", *line)
                .text("encoding", encoding.as_str()),
            RowFault::Unclosed { line } => Message::new("grade-line-unclosed").count("line", *line),
            RowFault::Fields {
                line,
                fields,
                header,
            } => Message::new("grade-line-fields")
                .count("line", *line)
                .count("fields", *fields)
                .count("header", *header),
            RowFault::NoLink => Message::new("grade-no-link"),
        }
    }

    /// The row's status: `malformed: line 4 is not valid UTF-8`.
    pub fn status(&self) -> Message {
        Message::new("grade-row-malformed").said("reason", self.message())
    }
}

/// One line of the file, decoded.
struct Line {
    /// Its number (the first is 1).
    number: usize,
    /// Its text, `�` where it did not decode.
    text: String,
    /// Whether it decoded without error.
    valid: bool,
}

/// The text, decoded.
struct Decoded {
    /// Its lines.
    lines: Vec<Line>,
    /// The name of its encoding.
    encoding: &'static str,
    /// Whether the encoding was guessed from the bytes, the file being neither UTF-8 nor
    /// marked.
    guessed: bool,
}

/// Reads a class's file (see the module's documentation for the shapes it takes); refuses a
/// file that is not text, or whose CSV header names no single column of links, with a message
/// saying why.
pub fn read_class(bytes: &[u8]) -> Result<Class, Message> {
    let Decoded {
        lines,
        encoding,
        guessed,
    } = decode(bytes)?;
    let class = match lines.iter().position(|l| !skipped(&l.text)) {
        None => Class::default(),
        Some(first) => match header(&lines, first) {
            Some((delimiter, record)) => csv_class(&lines, record, delimiter, encoding)?,
            None => one_a_line(&lines, encoding),
        },
    };
    Ok(Class {
        encoding: guessed.then_some(encoding),
        ..class
    })
}

/// Whether a line of a file of one link a line is skipped: blank, or a `#` comment.
fn skipped(text: &str) -> bool {
    let text = text.trim();
    text.is_empty() || text.starts_with('#')
}

/// The fault of a row whose line `number` did not decode.
fn undecoded(number: usize, encoding: &str) -> RowFault {
    RowFault::Undecoded {
        line: number,
        encoding: encoding.to_string(),
    }
}

/// The lines of the file, by its byte-order mark or, without one, as UTF-8 when it is, else in
/// the encoding its bytes point to.
fn decode(bytes: &[u8]) -> Result<Decoded, Message> {
    let decoded = |lines, encoding| Decoded {
        lines,
        encoding,
        guessed: false,
    };
    if let Some(rest) = bytes.strip_prefix(b"\xef\xbb\xbf") {
        return Ok(decoded(utf8_lines(rest), "UTF-8"));
    }
    for (bom, from_bytes) in [
        (b"\xff\xfe", u16::from_le_bytes as fn([u8; 2]) -> u16),
        (b"\xfe\xff", u16::from_be_bytes),
    ] {
        if let Some(rest) = bytes.strip_prefix(bom) {
            let lines = utf16_lines(rest, from_bytes);
            if lines.iter().any(|l| l.text.contains('\0')) {
                return Err(Message::new(NOT_TEXT));
            }
            return Ok(decoded(lines, "UTF-16"));
        }
    }
    if bytes.contains(&0) {
        return Err(Message::new(if looks_like_utf16(bytes) {
            "grade-file-utf16"
        } else {
            NOT_TEXT
        }));
    }
    // A file with a line of UTF-8 beyond ASCII is UTF-8 with a few bad bytes (a pasted name, a
    // cut-off copy): those spoil their own lines, and the others keep their names.
    let utf8_beyond_ascii = || {
        bytes
            .split(|&b| b == b'\n')
            .any(|line| !line.is_ascii() && std::str::from_utf8(line).is_ok())
    };
    if std::str::from_utf8(bytes).is_ok() || utf8_beyond_ascii() {
        return Ok(decoded(utf8_lines(bytes), "UTF-8"));
    }
    let mut detector = EncodingDetector::new(Iso2022JpDetection::Deny);
    detector.feed(bytes, true);
    let encoding = detector.guess(None, Utf8Detection::Deny);
    Ok(Decoded {
        lines: legacy_lines(bytes, encoding),
        encoding: encoding.name(),
        guessed: true,
    })
}

/// Why a file with NUL bytes is refused, as the message's id.
const NOT_TEXT: &str = "grade-file-not-text";

/// Whether a file with NUL bytes is UTF-16 without a byte-order mark: in its first 4 KiB, a
/// quarter or more of the bytes at even (or odd) offsets are NUL, and at most a sixteenth as many
/// at the others, as in text of mostly ASCII characters.
fn looks_like_utf16(bytes: &[u8]) -> bool {
    let sample = &bytes[..bytes.len().min(4096)];
    let nuls = |from: usize| {
        sample
            .iter()
            .skip(from)
            .step_by(2)
            .filter(|&&b| b == 0)
            .count()
    };
    let (even, odd) = (nuls(0), nuls(1));
    let (many, few) = (even.max(odd), even.min(odd));
    many > 0 && many * 4 >= sample.len() / 2 && few * 16 <= many
}

/// The lines of UTF-8 text; an invalid sequence decodes to `�` and spoils its line.
fn utf8_lines(bytes: &[u8]) -> Vec<Line> {
    split_lines(bytes.utf8_chunks().flat_map(|chunk| {
        let bad = (!chunk.invalid().is_empty()).then_some(None);
        chunk.valid().chars().map(Some).chain(bad)
    }))
}

/// The lines of UTF-16 text, each unit read from two bytes by `from_bytes`; an unpaired
/// surrogate, or the odd last byte of a cut-off file, decodes to `�` and spoils its line.
fn utf16_lines(bytes: &[u8], from_bytes: fn([u8; 2]) -> u16) -> Vec<Line> {
    let pairs = bytes.chunks_exact(2);
    let odd = (!pairs.remainder().is_empty()).then_some(None);
    let units = pairs.map(|p| from_bytes([p[0], p[1]]));
    split_lines(char::decode_utf16(units).map(Result::ok).chain(odd))
}

/// The lines of text in `encoding`, one of the ASCII-compatible legacy encodings chardetng
/// guesses (in none of them does a byte of CR or LF stand inside another character, so the bytes
/// split at line ends first); a sequence without a character decodes to `�` and spoils its
/// line.
fn legacy_lines(bytes: &[u8], encoding: &'static Encoding) -> Vec<Line> {
    let pieces = bytes.split_inclusive(|&b| b == b'\n' || b == b'\r');
    split_lines(pieces.flat_map(|piece| {
        let (text, bad) = encoding.decode_without_bom_handling(piece);
        text.chars()
            .map(|c| (!(bad && c == '\u{fffd}')).then_some(c))
            .collect::<Vec<_>>()
    }))
}

/// Splits decoded characters (None where the text did not decode) into lines at LF, CRLF and
/// lone CR; a last line without a line end counts, an empty one after the last line end does
/// not.
fn split_lines(chars: impl Iterator<Item = Option<char>>) -> Vec<Line> {
    let mut lines = Vec::new();
    let (mut text, mut valid, mut after_cr) = (String::new(), true, false);
    let mut end = |text: &mut String, valid: &mut bool| {
        lines.push(Line {
            number: lines.len() + 1,
            text: std::mem::take(text),
            valid: std::mem::replace(valid, true),
        });
    };
    for c in chars {
        if after_cr && c == Some('\n') {
            after_cr = false;
            continue;
        }
        after_cr = c == Some('\r');
        match c {
            Some('\n' | '\r') => end(&mut text, &mut valid),
            Some(c) => text.push(c),
            None => {
                text.push('\u{fffd}');
                valid = false;
            }
        }
    }
    if !text.is_empty() || !valid {
        end(&mut text, &mut valid);
    }
    lines
}

/// The rows of a file of one link a line.
fn one_a_line(lines: &[Line], encoding: &str) -> Class {
    let rows = lines
        .iter()
        .filter(|l| !skipped(&l.text))
        .map(|l| ClassRow {
            line: l.number,
            link: l.text.trim().to_string(),
            carried: Vec::new(),
            fault: (!l.valid).then(|| undecoded(l.number, encoding)),
        })
        .collect();
    Class {
        columns: Vec::new(),
        link_column: None,
        rows,
        encoding: None,
    }
}

/// One CSV record: its fields and where it is in the file.
struct Record {
    /// The fields, unquoted; a line break inside quotes is `\n`.
    fields: Vec<String>,
    /// The index (in the lines) of its first line.
    first: usize,
    /// The index of the line after it.
    next: usize,
    /// The number of its first line that did not decode, if one did not.
    undecoded: Option<usize>,
    /// Whether a quoted field was still open at the end of the file.
    open: bool,
}

/// The CSV record starting at `lines[first]`, fields separated by `delimiter`. Lenient where
/// RFC 4180 is strict: a quote inside an unquoted field, or text after a closing quote, is kept
/// as it is.
fn record(lines: &[Line], first: usize, delimiter: char) -> Record {
    let (mut fields, mut field) = (Vec::new(), String::new());
    let (mut quoted, mut at_start) = (false, true);
    let mut undecoded = None;
    let mut i = first;
    loop {
        let line = &lines[i];
        if !line.valid && undecoded.is_none() {
            undecoded = Some(line.number);
        }
        let mut chars = line.text.chars().peekable();
        while let Some(c) = chars.next() {
            match c {
                '"' if quoted && chars.peek() == Some(&'"') => {
                    field.push('"');
                    chars.next();
                }
                '"' if quoted => quoted = false,
                '"' if at_start => quoted = true,
                c if c == delimiter && !quoted => {
                    fields.push(std::mem::take(&mut field));
                    at_start = true;
                    continue;
                }
                c => field.push(c),
            }
            at_start = false;
        }
        i += 1;
        if !quoted || i == lines.len() {
            break;
        }
        field.push('\n');
    }
    fields.push(field);
    Record {
        fields,
        first,
        next: i,
        undecoded,
        open: quoted,
    }
}

/// The names a column of links is known by (compared trimmed, in any case).
const LINK_HEADERS: [&str; 3] = ["link", "url", "submission"];

/// Whether a header names the column of links.
fn is_link_header(name: &str) -> bool {
    LINK_HEADERS.contains(&name.trim().to_lowercase().as_str())
}

/// Whether a cell looks like a challenge or submission link.
fn looks_like_link(cell: &str) -> bool {
    cell.contains("c=1") || cell.contains("challenge=")
}

/// The separator and header record of a CSV export whose header is at `lines[first]`, or None
/// when that line is a link (see the module's documentation).
fn header(lines: &[Line], first: usize) -> Option<(char, Record)> {
    let best = [',', ';', '\t']
        .into_iter()
        .map(|d| (d, record(lines, first, d)))
        .fold(None::<(char, Record)>, |best, (d, r)| match best {
            Some(b) if b.1.fields.len() >= r.fields.len() => Some(b),
            _ => Some((d, r)),
        })?;
    let fields = &best.1.fields;
    let is_header = match fields.len() {
        1 => is_link_header(&fields[0]),
        _ => !fields.iter().any(|f| f.contains('=')),
    };
    is_header.then_some(best)
}

/// The columns, quoted for a message: `'Name', 'Link'`.
fn names(header: &[String], columns: impl Iterator<Item = usize>) -> String {
    columns
        .map(|i| format!("'{}'", excerpt(header[i].trim())))
        .collect::<Vec<_>>()
        .join(", ")
}

/// The rows of a CSV export whose header is `head`.
fn csv_class(
    lines: &[Line],
    head: Record,
    delimiter: char,
    encoding: &str,
) -> Result<Class, Message> {
    if let Some(n) = head.undecoded {
        return Err(Message::new("grade-file-header-undecoded")
            .count("line", n)
            .text("encoding", encoding));
    }
    let header = head.fields;
    let mut records = Vec::new();
    let mut i = head.next;
    while i < lines.len() {
        let r = record(lines, i, delimiter);
        i = r.next;
        if r.fields.iter().any(|f| !f.trim().is_empty()) {
            records.push(r);
        }
    }
    let all = || 0..header.len();
    let named: Vec<usize> = all().filter(|&c| is_link_header(&header[c])).collect();
    let column = match named[..] {
        [c] => c,
        [] => {
            let linked: Vec<usize> = all()
                .filter(|&c| {
                    records
                        .iter()
                        .any(|r| r.fields.get(c).is_some_and(|f| looks_like_link(f)))
                })
                .collect();
            match linked[..] {
                [c] => c,
                [] => {
                    return Err(Message::new("grade-file-no-link-column")
                        .text("columns", names(&header, all())))
                }
                _ => {
                    return Err(Message::new("grade-file-links-everywhere")
                        .text("columns", names(&header, linked.into_iter())))
                }
            }
        }
        _ => {
            return Err(Message::new("grade-file-link-headers")
                .text("columns", names(&header, named.into_iter())))
        }
    };
    let rows = records
        .into_iter()
        .map(|mut r| {
            let number = lines[r.first].number;
            // The fields past the header's count belong to the link: one written unquoted
            // splits at its own commas (`robust=a,b`).
            let extra = r.fields.len().saturating_sub(header.len());
            if extra > 0 {
                let parts: Vec<String> = r.fields.drain(column..=column + extra).collect();
                r.fields.insert(column, parts.join(&delimiter.to_string()));
            }
            let fault = if let Some(n) = r.undecoded {
                Some(undecoded(n, encoding))
            } else if r.open {
                Some(RowFault::Unclosed { line: number })
            } else if r.fields.len() != header.len() {
                Some(RowFault::Fields {
                    line: number,
                    fields: r.fields.len(),
                    header: header.len(),
                })
            } else {
                None
            };
            let link = r.fields.get(column).map_or("", |f| f.trim()).to_string();
            let fault = fault.or_else(|| link.is_empty().then_some(RowFault::NoLink));
            let carried = all()
                .filter(|&c| c != column)
                .map(|c| r.fields.get(c).cloned().unwrap_or_default())
                .collect();
            ClassRow {
                line: number,
                link,
                carried,
                fault,
            }
        })
        .collect();
    let columns = all()
        .filter(|&c| c != column)
        .map(|c| header[c].clone())
        .collect();
    Ok(Class {
        columns,
        link_column: Some(header[column].clone()),
        rows,
        encoding: None,
    })
}
