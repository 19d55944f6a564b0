//! The one escaping rule of every CSV the core writes (RFC 4180): a field that holds a separator
//! a spreadsheet may split on (a comma, a semicolon or a tab), a quote or a line break is quoted,
//! its quotes doubled; any other field is written as it is. A cell of text from a user is first
//! made safe to open ([`text_field`]).

use super::escape_invisible;
use std::borrow::Cow;

/// The separators a spreadsheet may split a line on: a comma, or in many locales a semicolon,
/// or a tab.
const SEPARATORS: [char; 3] = [',', ';', '\t'];

/// The characters a spreadsheet may take as the start of a formula.
const FORMULA_STARTS: [char; 10] = [
    '=', '+', '-', '@', '\t', '\r', '\u{ff1d}', '\u{ff0b}', '\u{ff0d}', '\u{ff20}',
];

/// `text` as one CSV field.
pub fn field(text: &str) -> Cow<'_, str> {
    if text.contains(SEPARATORS) || text.contains(['"', '\n', '\r']) {
        Cow::Owned(format!("\"{}\"", text.replace('"', "\"\"")))
    } else {
        Cow::Borrowed(text)
    }
}

/// A cell of text from a user (a file or a student), safe to open in a spreadsheet and a
/// terminal: invisible characters escaped ([`escape_invisible`]); a `'` before the cell and
/// before each part of it after a separator that starts as a formula (OWASP's advice on CSV
/// injection: a spreadsheet set to another separator starts a cell there); then a [`field`].
pub fn text_field(text: &str) -> String {
    let mut shown = String::with_capacity(text.len() + 2);
    for part in text.split_inclusive(SEPARATORS) {
        if part.starts_with(FORMULA_STARTS) {
            shown.push('\'');
        }
        shown.push_str(&escape_invisible(part));
    }
    field(&shown).into_owned()
}

/// `fields` as one CSV line, without its line end.
pub fn line<S: AsRef<str>>(fields: &[S]) -> String {
    fields
        .iter()
        .map(|f| field(f.as_ref()))
        .collect::<Vec<_>>()
        .join(",")
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_field_is_quoted_only_when_it_must_be() {
        assert_eq!(field("plain text. 1.5"), "plain text. 1.5");
        assert_eq!(field("a, b"), "\"a, b\"");
        assert_eq!(field("a; b"), "\"a; b\"");
        assert_eq!(field("a\tb"), "\"a\tb\"");
        assert_eq!(field("say \"hi\""), "\"say \"\"hi\"\"\"");
        assert_eq!(field("two\nlines"), "\"two\nlines\"");
        assert_eq!(field(""), "");
        assert_eq!(line(&["1", "x,y", ""]), "1,\"x,y\",");
    }
}
