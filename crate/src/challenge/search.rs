//! A bounded search over a challenge's allowed fields: the designs to try, so that a lecturer
//! learns whether any design within the allowed ranges meets the criteria before setting the
//! challenge. A design is what a student submits: the fields set and their values, each value as
//! the codec writes it; [`Challenge::submit`] makes it a submission, run and judged as any other.
//!
//! The rule of [`Challenge::search_designs`]:
//!
//! - **Values.** A range field is tried at [`SEARCH_POINTS`] values spanning its range, both ends
//!   included: spaced geometrically when the range is positive and spans a decade or more
//!   (`hi ≥ 10·lo`), else linearly; the interior values are rounded to three significant digits
//!   (to whole numbers for a field of whole numbers). A choice field is tried at every option. A
//!   value equal to the base's is the field left unset, so the base's own values are among those
//!   tried.
//! - **More points when they fit.** While the full grid (every combination of the values) still
//!   fits in `max_designs` with one more value per range, up to [`MOST_SEARCH_POINTS`], the range
//!   fields get one more.
//! - **Order.** The base first (no field set); then the designs that set one field, then two,
//!   and so on: the fewest fields changed first. Among those that set as many fields, coarse to
//!   fine: first the designs whose values are all ends of their ranges (or options), then those
//!   that also take the value nearest the middle, then those nearest the quarters, the eighths,
//!   …; then the fields in allow order, each field's values from low to high (options in their
//!   order).
//! - **Bound.** The first `max_designs` designs of that order (at most [`MAX_SEARCH_DESIGNS`]):
//!   the full grid when it fits, else the designs that change the fewest fields, coarsest first.
//!
//! The designs depend on the challenge and `max_designs` alone.

use super::codec::{field_info, number};
use super::{Allowed, Challenge};
use crate::analysis::log_grid;
use crate::scenario::Scenario;

/// Values tried across a range field (ends included) when the full grid does not fit.
pub const SEARCH_POINTS: usize = 6;
/// Most values tried across a range field, when the full grid at that many fits.
pub const MOST_SEARCH_POINTS: usize = 32;
/// Most designs a search gives, whatever it is asked for.
pub const MAX_SEARCH_DESIGNS: usize = 10_000;

/// A design: the fields set and their values (as the codec writes them), in allow order.
pub type Design = Vec<(String, String)>;

/// One value to try: its codec text and its depth (0 for the ends and options, 1 for the point
/// nearest the middle, 2 for those nearest the quarters, …).
struct Value {
    text: String,
    depth: u32,
}

/// An allowed field and its values to try besides the base's, from low to high.
struct Field {
    name: String,
    values: Vec<Value>,
}

/// The depth of point `i` of `n` (`n ≥ 2`): the first `k` for which `i` is the point nearest to
/// a multiple of 1/2ᵏ of the range.
fn depth(i: usize, n: usize) -> u32 {
    let span = n - 1;
    let mut k = 0;
    loop {
        let parts = 1usize << k;
        // Point nearest j/parts of the range, halves rounded up.
        if (0..=parts).any(|j| (2 * j * span + parts) / (2 * parts) == i) {
            return k;
        }
        k += 1;
    }
}

/// `v` to three significant digits: the number nearest the decimal `d.dd·10ˣ`, so that the codec
/// writes it with three digits at most.
fn three_digits(v: f64) -> f64 {
    if v == 0.0 || !v.is_finite() {
        return v;
    }
    // Powers of ten up to 10²² are exact, so the division rounds once, to the decimal's nearest.
    let e = libm::log10(v.abs()).floor() as i32 - 2;
    if e >= 0 {
        (v / 10f64.powi(e)).round() * 10f64.powi(e)
    } else {
        (v * 10f64.powi(-e)).round() / 10f64.powi(-e)
    }
}

/// The `n` values spanning `lo..=hi`, with their depths, in order; `integer` rounds them to
/// whole numbers. Geometric spacing is the frequency sweeps' ([`log_grid`]): the same numbers in
/// the browser as in the CLI.
fn spanning(lo: f64, hi: f64, n: usize, integer: bool) -> Vec<(f64, u32)> {
    let grid = if lo > 0.0 && hi >= 10.0 * lo {
        log_grid(lo, hi, n)
    } else {
        (0..n)
            .map(|i| lo + (hi - lo) * i as f64 / (n - 1) as f64)
            .collect()
    };
    grid.into_iter()
        .enumerate()
        .map(|(i, v)| {
            let v = if i == 0 {
                lo
            } else if i == n - 1 {
                hi
            } else if integer {
                v.round()
            } else {
                three_digits(v)
            };
            (v.clamp(lo, hi), depth(i, n))
        })
        .collect()
}

/// Each allowed field with its values to try at `points` values per range: the base's value
/// left out (the field unset), repeats merged at their smallest depth, values the field refuses
/// left out.
fn fields(c: &Challenge, base: &Scenario, points: usize) -> Vec<Field> {
    c.allow
        .iter()
        .map(|a| {
            let info = field_info(base, &a.field).expect("checked when parsed");
            let now = info.value.as_deref();
            let mut values: Vec<Value> = Vec::new();
            let mut keep = |text: String, depth: u32| {
                if let Some(last) = values.last_mut().filter(|v| v.text == text) {
                    last.depth = last.depth.min(depth);
                } else if base.clone().set(&a.field, &text).is_ok() {
                    values.push(Value { text, depth });
                }
            };
            match &a.allowed {
                Allowed::Range { lo, hi } => {
                    let base_value = now.and_then(number);
                    for (v, d) in spanning(*lo, *hi, points, info.integer) {
                        if base_value != Some(v) {
                            keep(format!("{v}"), d);
                        }
                    }
                }
                Allowed::Choice { options } => {
                    for o in options.iter().filter(|o| Some(o.as_str()) != now) {
                        keep(o.clone(), 0);
                    }
                }
                // A law is the student's to derive: the search keeps the base's.
                Allowed::Formula => {}
            }
            Field {
                name: a.field.clone(),
                values,
            }
        })
        .filter(|f| !f.values.is_empty())
        .collect()
}

/// How many designs the full grid of `fields` holds (saturating).
fn grid_size(fields: &[Field]) -> usize {
    fields
        .iter()
        .fold(1usize, |n, f| n.saturating_mul(f.values.len() + 1))
}

/// Steps `idx` to the next combination of indices below `lens` (the last fastest); false after
/// the last.
fn advance(idx: &mut [usize], lens: &[usize]) -> bool {
    for k in (0..idx.len()).rev() {
        idx[k] += 1;
        if idx[k] < lens[k] {
            return true;
        }
        idx[k] = 0;
    }
    false
}

/// Steps `subset` (increasing indices below `n`) to the next subset of its size in
/// lexicographic order; false after the last.
fn next_subset(subset: &mut [usize], n: usize) -> bool {
    let size = subset.len();
    for i in (0..size).rev() {
        if subset[i] < n - size + i {
            subset[i] += 1;
            for j in i + 1..size {
                subset[j] = subset[j - 1] + 1;
            }
            return true;
        }
    }
    false
}

/// Pushes onto `out` the designs that set the fields `subset` of `fields` at values of depth at
/// most `depth`, one of them exactly `depth`; stops at `max` designs.
fn push_designs(out: &mut Vec<Design>, fields: &[Field], subset: &[usize], depth: u32, max: usize) {
    let lists: Vec<Vec<&Value>> = subset
        .iter()
        .map(|&f| {
            fields[f]
                .values
                .iter()
                .filter(|v| v.depth <= depth)
                .collect()
        })
        .collect();
    if lists.iter().any(|l| l.is_empty()) {
        return;
    }
    let lens: Vec<usize> = lists.iter().map(Vec::len).collect();
    let mut idx = vec![0; subset.len()];
    loop {
        let values: Vec<&Value> = idx.iter().zip(&lists).map(|(&i, l)| l[i]).collect();
        if values.iter().any(|v| v.depth == depth) {
            if out.len() >= max {
                return;
            }
            out.push(
                subset
                    .iter()
                    .zip(&values)
                    .map(|(&f, v)| (fields[f].name.clone(), v.text.clone()))
                    .collect(),
            );
        }
        if !advance(&mut idx, &lens) {
            return;
        }
    }
}

impl Challenge {
    /// The designs a check of the challenge tries, at most `max_designs` (and at most
    /// [`MAX_SEARCH_DESIGNS`]), by the rule of the module's documentation: the base first (no
    /// field set), then the designs that change the fewest fields, coarsest first; the full grid
    /// when it fits. Each design is [field, value] pairs in allow order, for
    /// [`Challenge::submit`].
    pub fn search_designs(&self, max_designs: usize) -> Vec<Design> {
        let max = max_designs.min(MAX_SEARCH_DESIGNS);
        if max == 0 {
            return Vec::new();
        }
        let base = self.base_scenario();
        let mut grid = fields(self, &base, SEARCH_POINTS);
        for points in SEARCH_POINTS + 1..=MOST_SEARCH_POINTS {
            let finer = fields(self, &base, points);
            if grid_size(&finer) > max {
                break;
            }
            grid = finer;
        }
        let deepest = grid
            .iter()
            .flat_map(|f| f.values.iter().map(|v| v.depth))
            .max()
            .unwrap_or(0);
        let mut out: Vec<Design> = vec![Vec::new()];
        for count in 1..=grid.len() {
            for depth in 0..=deepest {
                let mut subset: Vec<usize> = (0..count).collect();
                loop {
                    push_designs(&mut out, &grid, &subset, depth, max);
                    if out.len() >= max {
                        return out;
                    }
                    if !next_subset(&mut subset, grid.len()) {
                        break;
                    }
                }
            }
        }
        out
    }
}
