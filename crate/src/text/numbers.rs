//! Numbers as the core's texts write them: a message's value (`short`), a figure's digits.

/// `v` for a message: the codec's shortest form, or scientific notation where that is long
/// (5e-324 rather than 324 digits).
pub fn short(v: f64) -> String {
    let plain = format!("{v}");
    if plain.len() > 12 {
        format!("{v:e}")
    } else {
        plain
    }
}

/// `v` rounded to `digits` significant digits, the integer part included (179361 → 179400 at 4).
pub fn rounded(v: f64, digits: i32) -> String {
    if v == 0.0 || !v.is_finite() {
        return format!("{v}");
    }
    let scale = 10f64.powi(v.abs().log10().floor() as i32 + 1 - digits);
    if scale >= 1.0 {
        format!("{}", ((v / scale).round() * scale) as i64)
    } else {
        significant(v, digits)
    }
}

/// `t` (s) with up to 4 significant digits: in ms below 1 s, in s from 1 s on.
pub fn time_text(t: f64) -> String {
    if t.abs() < 1.0 {
        format!("{} ms", significant(t * 1e3, 4))
    } else {
        format!("{} s", significant(t, 4))
    }
}

/// `v` rounded to `digits` significant digits (all digits before the point are kept), without
/// trailing zeros.
pub fn significant(v: f64, digits: i32) -> String {
    if v == 0.0 || !v.is_finite() {
        return format!("{v}");
    }
    let mut decimals = digits - 1;
    let mut m = v.abs();
    while m >= 10.0 && decimals > 0 {
        m /= 10.0;
        decimals -= 1;
    }
    while m < 1.0 {
        m *= 10.0;
        decimals += 1;
    }
    let text = format!("{v:.*}", decimals as usize);
    if text.contains('.') {
        text.trim_end_matches('0').trim_end_matches('.').to_string()
    } else {
        text
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn times_read_with_up_to_4_significant_digits() {
        for (t, text) in [
            (0.0, "0 ms"),
            (5.0 / 1200.0, "4.167 ms"),
            (84.0 * 50e-6, "4.2 ms"),
            (0.00045, "0.45 ms"),
            (0.09995, "99.95 ms"),
            (0.05, "50 ms"),
            (0.6, "600 ms"),
            (1.0, "1 s"),
            (12.34567, "12.35 s"),
        ] {
            assert_eq!(time_text(t), text);
        }
    }
}
