//! How messages quote what a user typed: characters that do not show, or that reorder the text
//! around them, are written as escapes, so a message shows the input as it is and cannot be
//! disguised by it. The CLI, the codec's errors and the page (through the bindings) all quote
//! with [`excerpt`].

/// Longest excerpt of user input quoted in a message (characters).
pub const EXCERPT_CHARS: usize = 40;

/// The code points of the Unicode general categories Cc (controls), Cf (format: the soft hyphen,
/// zero-width characters, bidi embeddings, overrides and isolates, the BOM, tags), Zl (line
/// separator) and Zp (paragraph separator), as of Unicode 16.0; sorted, not overlapping. A table
/// of 25 ranges rather than a general-category crate: a full table (such as
/// `unicode-general-category`) adds 52 KB to the WASM for these four categories. The test
/// `matches_the_general_categories` checks it against that crate for every code point.
const INVISIBLE: [(u32, u32); 25] = [
    (0x0000, 0x001f),   // Cc: C0 controls
    (0x007f, 0x009f),   // Cc: DEL and C1 controls
    (0x00ad, 0x00ad),   // Cf: soft hyphen
    (0x0600, 0x0605),   // Cf: Arabic number signs
    (0x061c, 0x061c),   // Cf: Arabic letter mark
    (0x06dd, 0x06dd),   // Cf: Arabic end of ayah
    (0x070f, 0x070f),   // Cf: Syriac abbreviation mark
    (0x0890, 0x0891),   // Cf: Arabic pound and piastre marks above
    (0x08e2, 0x08e2),   // Cf: Arabic disputed end of ayah
    (0x180e, 0x180e),   // Cf: Mongolian vowel separator
    (0x200b, 0x200f),   // Cf: ZWSP, ZWNJ, ZWJ, LRM, RLM
    (0x2028, 0x2028),   // Zl: line separator
    (0x2029, 0x2029),   // Zp: paragraph separator
    (0x202a, 0x202e),   // Cf: bidi embeddings and overrides
    (0x2060, 0x2064),   // Cf: word joiner, invisible operators
    (0x2066, 0x206f),   // Cf: bidi isolates, deprecated format characters
    (0xfeff, 0xfeff),   // Cf: zero-width no-break space (BOM)
    (0xfff9, 0xfffb),   // Cf: interlinear annotation
    (0x110bd, 0x110bd), // Cf: Kaithi number sign
    (0x110cd, 0x110cd), // Cf: Kaithi number sign above
    (0x13430, 0x1343f), // Cf: Egyptian hieroglyph format controls
    (0x1bca0, 0x1bca3), // Cf: shorthand format controls
    (0x1d173, 0x1d17a), // Cf: musical symbol beams and phrases
    (0xe0001, 0xe0001), // Cf: language tag
    (0xe0020, 0xe007f), // Cf: tag characters
];

/// Whether `c` is of the general category Cc, Cf, Zl or Zp: it does not show, or it changes how
/// the text around it shows.
pub fn is_invisible(c: char) -> bool {
    let u = u32::from(c);
    let i = INVISIBLE.partition_point(|&(_, last)| last < u);
    INVISIBLE.get(i).is_some_and(|&(first, _)| first <= u)
}

/// `text` with each character of the categories Cc, Cf, Zl and Zp written as an escape: `\n`,
/// `\t` and `\r` as such, any other as `\u{202e}`.
pub fn escape_invisible(text: &str) -> String {
    let mut out = String::with_capacity(text.len());
    for c in text.chars() {
        if is_invisible(c) {
            out.extend(c.escape_default());
        } else {
            out.push(c);
        }
    }
    out
}

/// `text` as quoted in a message: invisible characters escaped ([`escape_invisible`]), cut to
/// [`EXCERPT_CHARS`] characters with the full length noted.
pub fn excerpt(text: &str) -> String {
    let count = text.chars().count();
    let cut = match text.char_indices().nth(EXCERPT_CHARS) {
        Some((end, _)) => &text[..end],
        None => text,
    };
    let mut out = escape_invisible(cut);
    if count > EXCERPT_CHARS {
        out.push_str(&format!("… ({count} characters)"));
    }
    out
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_table_is_sorted_and_its_ranges_are_apart() {
        for w in INVISIBLE.windows(2) {
            assert!(w[0].0 <= w[0].1 && w[0].1 < w[1].0, "{w:x?}");
        }
    }

    #[test]
    fn bidi_controls_separators_and_tags_are_escaped() {
        let cases = [
            ("a\u{202e}b", "a\\u{202e}b"),
            ("\u{2066}x\u{2069}", "\\u{2066}x\\u{2069}"),
            ("\u{200e}\u{200f}", "\\u{200e}\\u{200f}"),
            ("1\u{2028}2\u{2029}", "1\\u{2028}2\\u{2029}"),
            ("soft\u{ad}hyphen", "soft\\u{ad}hyphen"),
            ("\u{1f468}\u{200d}\u{1f469}", "\u{1f468}\\u{200d}\u{1f469}"),
            ("\u{e0041}\u{e007f}", "\\u{e0041}\\u{e007f}"),
            ("\u{feff}\u{200b}", "\\u{feff}\\u{200b}"),
            ("1\n\t\r\u{1b}", "1\\n\\t\\r\\u{1b}"),
        ];
        for (text, quoted) in cases {
            assert_eq!(escape_invisible(text), quoted);
        }
        // What shows stays as it is: letters, marks, spaces, symbols, quotes and backslashes.
        let visible = "é ü\u{301} ß İ ﬀ ０ 😀 \u{a0}\u{3000} '\"\\ ١٢ ∑";
        assert_eq!(escape_invisible(visible), visible);
    }

    #[test]
    fn excerpts_are_cut_before_escaping_and_count_characters() {
        let text = format!("{}\u{202e}{}", "x".repeat(39), "y".repeat(20));
        assert_eq!(
            excerpt(&text),
            format!("{}\\u{{202e}}… (60 characters)", "x".repeat(39))
        );
        assert_eq!(excerpt("short"), "short");
    }
}

/// The table against a maintained general-category table (native only: a dev-dependency).
#[cfg(all(test, not(target_arch = "wasm32")))]
mod categories {
    use super::*;
    use unicode_general_category::{get_general_category, GeneralCategory};

    #[test]
    fn matches_the_general_categories() {
        assert_eq!(unicode_general_category::UNICODE_VERSION, (16, 0, 0));
        for c in (0..=0x10ffff).filter_map(char::from_u32) {
            let expected = matches!(
                get_general_category(c),
                GeneralCategory::Control
                    | GeneralCategory::Format
                    | GeneralCategory::LineSeparator
                    | GeneralCategory::ParagraphSeparator
            );
            assert_eq!(is_invisible(c), expected, "U+{:04X}", u32::from(c));
        }
        // Rust's own notion of a control character is the category Cc.
        for c in (0..=0x10ffff).filter_map(char::from_u32) {
            if c.is_control() {
                assert!(is_invisible(c), "U+{:04X}", u32::from(c));
            }
        }
    }
}
