//! The one escaping rule of every CSV the core writes (RFC 4180): a field that holds a comma, a
//! quote or a line break is quoted, its quotes doubled; any other field is written as it is.

use std::borrow::Cow;

/// `text` as one CSV field.
pub fn field(text: &str) -> Cow<'_, str> {
    if text.contains([',', '"', '\n', '\r']) {
        Cow::Owned(format!("\"{}\"", text.replace('"', "\"\"")))
    } else {
        Cow::Borrowed(text)
    }
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
        assert_eq!(field("plain text; 1.5"), "plain text; 1.5");
        assert_eq!(field("a, b"), "\"a, b\"");
        assert_eq!(field("say \"hi\""), "\"say \"\"hi\"\"\"");
        assert_eq!(field("two\nlines"), "\"two\nlines\"");
        assert_eq!(field(""), "");
        assert_eq!(line(&["1", "x,y", ""]), "1,\"x,y\",");
    }
}
