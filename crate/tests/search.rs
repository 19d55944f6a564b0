//! The designs a check of a challenge tries: the grid's rule (ends and the base's values
//! included, geometric or linear spacing, bounded, deterministic, fewest fields changed first)
//! and, graded as `imlab grade` grades a link, a passing design of each built-in challenge within
//! the page's bound.

// Runs simulations of seconds; the crate's tests also build for wasm32.
#![cfg(not(target_arch = "wasm32"))]

use imlab::challenge::grade::grade_one;
use imlab::challenge::{Challenge, Design, BUILTINS, MAX_SEARCH_DESIGNS};
use std::collections::HashSet;

/// The runs a check of a composed challenge takes at most in the page
/// (web/challenge/compose-check.js): it tries `RUN_BUDGET / runs per design` designs.
const RUN_BUDGET: usize = 300;

/// A challenge on the step preset with `allow` (`&allow.FIELD=…` parts).
fn challenge(allow: &str) -> Challenge {
    Challenge::parse(&format!(
        "c=1&title=t&base=v%3D1%26preset%3Dstep{allow}&need.current_peak=max:4"
    ))
    .unwrap()
}

/// The design that sets `field` alone, to `value`.
fn single(field: &str, value: &str) -> Design {
    vec![(field.to_string(), value.to_string())]
}

/// The values `designs` set `field` to, in order of first use.
fn values_of(designs: &[Design], field: &str) -> Vec<String> {
    let mut out: Vec<String> = Vec::new();
    for (f, v) in designs.iter().flatten() {
        if f == field && !out.contains(v) {
            out.push(v.clone());
        }
    }
    out
}

#[test]
fn a_small_grid_is_tried_whole_with_its_ends_and_the_base() {
    // k1 spans a decade: geometric; ekf has one option besides the base's (euler).
    let c = challenge("&allow.k1=300..3000&allow.ekf=euler|rk4");
    let designs = c.search_designs(14);
    // The base (1200, euler) first; the full grid of 6 values of k1 (and k1 unset) by 2 of ekf.
    assert_eq!(designs.len(), 14);
    assert_eq!(designs[0], Vec::new());
    assert_eq!(
        values_of(&designs, "k1"),
        ["300", "3000", "1190", "475", "1890", "754"]
    );
    assert_eq!(values_of(&designs, "ekf"), ["rk4"]);
    let distinct: HashSet<&Design> = designs.iter().collect();
    assert_eq!(distinct.len(), designs.len());
    // Fewest fields first, each a valid submission.
    assert!(designs.windows(2).all(|w| w[0].len() <= w[1].len()));
    for d in &designs {
        c.submit(d).unwrap();
    }
    // One field: as many values as fit, up to 32 (and the base).
    let one = challenge("&allow.k1=300..3000").search_designs(300);
    assert_eq!(one.len(), 33);
    assert_eq!(one[1..3], [single("k1", "300"), single("k1", "3000")]);
}

#[test]
fn spacing_is_linear_within_a_decade_and_the_base_value_is_the_field_unset() {
    // 1200..2400 is less than a decade: linear; its low end is the base's value (k1 = 1200).
    let designs = challenge("&allow.k1=1200..2400").search_designs(6);
    assert_eq!(
        values_of(&designs, "k1"),
        ["2400", "1920", "1440", "2160", "1680"]
    );
    assert_eq!(designs.len(), 6);
    // A range not positive is linear too; a field of whole numbers gets whole numbers.
    let c = Challenge::parse(
        "c=1&title=t&base=v%3D1%26preset%3Dload-step&allow.ekf.load=0..1\
         &allow.ekf.q_speed=0..1000&need.current_peak=max:4",
    )
    .unwrap();
    let designs = c.search_designs(12);
    assert_eq!(values_of(&designs, "ekf.load"), ["1"]);
    assert_eq!(
        values_of(&designs, "ekf.q_speed"),
        ["1000", "600", "200", "800", "400"]
    );
    // Six decades at seven points: a value a decade, the base's (0.001) the field unset.
    let c = Challenge::parse(
        "c=1&title=t&base=v%3D1%26preset%3Dload-step&allow.ekf.q=0.000001..1\
         &need.current_peak=max:4",
    )
    .unwrap();
    let designs = c.search_designs(7);
    assert_eq!(designs.len(), 7);
    let mut q = values_of(&designs, "ekf.q");
    q.sort_by(|a, b| a.parse::<f64>().unwrap().total_cmp(&b.parse().unwrap()));
    assert_eq!(q, ["0.000001", "0.00001", "0.0001", "0.01", "0.1", "1"]);
}

#[test]
fn a_large_grid_is_bounded_deterministic_and_changes_the_fewest_fields_first() {
    let c = BUILTINS[0].challenge(); // step-tune: k1–k4 in 300..5000
    for max in [0, 1, 9, 50, 100] {
        assert_eq!(c.search_designs(max).len(), max);
    }
    let designs = c.search_designs(100);
    assert_eq!(designs, c.search_designs(100));
    // A smaller bound gives the first designs of a larger one.
    assert_eq!(c.search_designs(40)[..], designs[..40]);
    // The base, then each field alone at its ends, then at the rest of its values, then pairs.
    assert_eq!(designs[0], Vec::new());
    assert_eq!(
        designs[1..5],
        [
            single("k1", "300"),
            single("k1", "5000"),
            single("k2", "300"),
            single("k2", "5000")
        ]
    );
    assert!(designs[1..25].iter().all(|d| d.len() == 1));
    assert!(designs[25..].iter().all(|d| d.len() == 2));
    for d in &designs {
        c.submit(d).unwrap();
    }
    // Whatever the bound asked for, at most MAX_SEARCH_DESIGNS: here the full grid of 9 values
    // (and the base's) in each of the four fields.
    let all = c.search_designs(usize::MAX);
    assert_eq!(all.len(), MAX_SEARCH_DESIGNS);
    assert_eq!(all.iter().collect::<HashSet<_>>().len(), MAX_SEARCH_DESIGNS);
}

#[test]
fn each_built_in_has_a_passing_design_within_the_pages_bound() {
    for b in BUILTINS {
        let c = b.challenge();
        let designs = c.search_designs(RUN_BUDGET / c.run_labels().len());
        let graded = |d: &Design| grade_one(&c, 1, &c.submit(d).unwrap().encode());
        assert!(!graded(&designs[0]).pass(), "{}: the base passes", b.name);
        let found = designs.iter().find(|d| graded(d).pass());
        assert!(
            found.is_some(),
            "{}: none of the {} designs passes",
            b.name,
            designs.len()
        );
    }
}
