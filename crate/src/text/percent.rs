//! The one percent codec of the query strings the core writes and reads (scenarios, challenges,
//! submissions): `%XX` escapes of bytes, strict on the way in.

/// `text` with every byte percent-encoded (`%XX`, upper-case hex) but the ASCII letters and
/// digits and the bytes of `keep`.
pub fn encode(text: &str, keep: &[u8]) -> String {
    let mut out = String::with_capacity(text.len());
    for b in text.bytes() {
        if b.is_ascii_alphanumeric() || keep.contains(&b) {
            out.push(char::from(b));
        } else {
            out.push_str(&format!("%{b:02X}"));
        }
    }
    out
}

/// How a `+` reads: a space in a form-encoded value, itself in a formula (where it is the sum).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Plus {
    /// `+` is a space.
    Space,
    /// `+` is a plus.
    Plus,
}

/// `text` with its `%XX` escapes decoded (two hex digits each, nothing else: `%+1` and `%1`
/// are refused) and `+` read as `plus` says; None unless the bytes decoded are UTF-8.
pub fn decode(text: &str, plus: Plus) -> Option<String> {
    let bytes = text.as_bytes();
    let mut out = Vec::with_capacity(bytes.len());
    let mut i = 0;
    while i < bytes.len() {
        match bytes[i] {
            b'%' => {
                let hex = bytes.get(i + 1..i + 3)?;
                let digit = |b: u8| char::from(b).to_digit(16);
                let (hi, lo) = (digit(hex[0])?, digit(hex[1])?);
                out.push((hi * 16 + lo) as u8);
                i += 3;
            }
            b'+' if plus == Plus::Space => {
                out.push(b' ');
                i += 1;
            }
            b => {
                out.push(b);
                i += 1;
            }
        }
    }
    String::from_utf8(out).ok()
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn it_round_trips_and_refuses_what_is_not_two_hex_digits() {
        for text in ["", "a b&c=d", "ω̂ − ω_d", "x1h*(k1-a3)/2", "100%", "a+b"] {
            for keep in [&b"-._~"[..], &b"-._~*()"[..]] {
                let coded = encode(text, keep);
                assert!(coded.bytes().all(|b| b.is_ascii_graphic()), "{coded}");
                assert_eq!(decode(&coded, Plus::Space).as_deref(), Some(text));
                assert_eq!(decode(&coded, Plus::Plus).as_deref(), Some(text));
            }
        }
        assert_eq!(encode("a b+c", b"-._~"), "a%20b%2Bc");
        assert_eq!(encode("k*(x)", b"-._~*()"), "k*(x)");
        // The two readings of '+'.
        assert_eq!(decode("a+b", Plus::Space).as_deref(), Some("a b"));
        assert_eq!(decode("a+b", Plus::Plus).as_deref(), Some("a+b"));
        // Two hex digits, either case, or nothing.
        assert_eq!(decode("%2b%2B", Plus::Plus).as_deref(), Some("++"));
        for bad in ["%+1", "%-1", "%1", "%", "%ZZ", "% 1", "%1G"] {
            assert_eq!(decode(bad, Plus::Space), None, "{bad}");
        }
        // Bytes that are not UTF-8.
        assert_eq!(decode("%FF", Plus::Space), None);
        assert_eq!(decode("%C3%A9", Plus::Space).as_deref(), Some("é"));
    }
}
