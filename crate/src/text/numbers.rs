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
