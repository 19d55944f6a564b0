//! The challenge composer: a lecturer's parts, as the page's form sends them, give the canonical
//! link the codec reads back, each built-in taken apart composes to its text, and a bad part is
//! refused with its key and the reason.

// The crate's tests also build for wasm32.
#![cfg(not(target_arch = "wasm32"))]

use imlab::challenge::{builtin, Challenge, ChallengeParts, BUILTINS};

mod common;
use common::SMALL_CANONICAL;

/// Parts as the page's composer sends them: text as typed, numbers or their text, choices and
/// variants as one text each.
fn form_parts(json: &str) -> ChallengeParts {
    serde_json::from_str(json).unwrap()
}

#[test]
fn composed_parts_give_the_canonical_link_the_codec_reads_back() {
    let parts = form_parts(
        r#"{"title": " Quick step ", "base": "v=1&preset=step&duration=0.08",
            "allow": [{"field": "k2", "lo": "300", "hi": "3000"}, {"field": "k1", "lo": 300, "hi": 3e3},
                      {"field": "ekf", "options": "rk4 | euler"}],
            "need": [{"figure": "settling_time", "op": "max", "bound": "0.006"},
                     {"figure": "current_peak", "op": "max", "bound": 4},
                     {"figure": "mean_nis", "op": "band", "bound": ""}],
            "vary": " model.j=0.016 | model.j=0.024", "robust": ["current_peak"]}"#,
    );
    let c = Challenge::compose(&parts).unwrap();
    assert_eq!(c.encode(), SMALL_CANONICAL);
    assert_eq!(Challenge::parse(&c.encode()).unwrap(), c);
    assert_eq!(c, Challenge::parse(SMALL_CANONICAL).unwrap());
    // Seeds, no variants at all, and text that needs encoding.
    let parts = form_parts(
        r#"{"title": "Ümlaut & co: 50 %", "base": "step",
            "need": [{"figure": "current_peak", "op": "abs", "bound": "4"}],
            "vary": "seeds:2..4", "robust": ["current_peak"]}"#,
    );
    let c = Challenge::compose(&parts).unwrap();
    assert_eq!(c.title, "Ümlaut & co: 50 %");
    assert_eq!(c.run_labels(), ["nominal", "seed=2", "seed=3", "seed=4"]);
    assert_eq!(Challenge::parse(&c.encode()).unwrap(), c);
    for vary in [r#""""#, "null", "[]"] {
        let parts = form_parts(&format!(
            r#"{{"base": "step", "need": [{{"figure": "current_peak", "op": "max", "bound": 4}}], "vary": {vary}}}"#
        ));
        let c = Challenge::compose(&parts).unwrap();
        assert_eq!(c.vary, None, "{vary}");
        assert_eq!(Challenge::parse(&c.encode()).unwrap(), c);
    }
    // Overrides as a list, one of them with a value the codec must encode.
    let parts = form_parts(
        r#"{"base": "step", "need": [{"figure": "current_peak", "op": "max", "bound": 4}],
            "vary": ["model.j=0.016&k1=1500", "model.j=0.024"], "robust": ["current_peak"]}"#,
    );
    let c = Challenge::compose(&parts).unwrap();
    // Each override canonical: its fields in the codec's order.
    assert!(
        c.encode()
            .contains("&vary=k1%3D1500%26model.j%3D0.016|model.j%3D0.024&"),
        "{}",
        c.encode()
    );
    assert_eq!(Challenge::parse(&c.encode()).unwrap(), c);
}

#[test]
fn each_built_in_taken_apart_and_composed_again_is_its_text() {
    for b in BUILTINS {
        let c = b.challenge();
        let parts = c.parts();
        assert_eq!(
            Challenge::compose(&parts).unwrap().encode(),
            b.text,
            "{}",
            b.name
        );
        // Through the JSON the bindings hand to the page and take back.
        let json = serde_json::to_string(&parts).unwrap();
        let again: ChallengeParts = serde_json::from_str(&json).unwrap();
        assert_eq!(again, parts, "{json}");
        assert_eq!(Challenge::compose(&again).unwrap(), c, "{}", b.name);
    }
    // The shape the page reads.
    let json = serde_json::to_value(builtin("load-observer").unwrap().challenge().parts()).unwrap();
    assert_eq!(
        json["allow"][0],
        serde_json::json!({"field": "ekf", "options": ["euler", "rk4"]})
    );
    assert_eq!(
        json["allow"][1],
        serde_json::json!({"field": "ekf.q", "lo": "0.000001", "hi": "1"})
    );
    assert_eq!(
        json["need"][1],
        serde_json::json!({"figure": "mean_nis", "op": "band"})
    );
    assert_eq!(json["vary"], "seeds:2..3");
    assert_eq!(json["robust"], serde_json::json!(["speed_error_final"]));
}

/// The base of the composer cases, as JSON.
const COMPOSE_BASE: &str = r#""base": "v=1&preset=step""#;
/// A criterion of the composer cases, as JSON.
const COMPOSE_NEED: &str = r#""need": [{"figure": "current_peak", "op": "max", "bound": 4}]"#;

/// Composes each case's JSON and checks that it is refused with the key and the words
/// expected.
fn assert_compose_errors(cases: &[(String, &str, &str)]) {
    for (json, key, needle) in cases {
        let e = Challenge::compose(&form_parts(json)).expect_err(json);
        assert_eq!(e.key, *key, "{json}: {e}");
        assert!(e.to_string().contains(needle), "{json}: {e}");
    }
}

#[test]
fn a_composer_error_names_the_title_or_base() {
    let base = COMPOSE_BASE;
    let need = COMPOSE_NEED;
    let cases: &[(String, &str, &str)] = &[
        (
            format!(r#"{{"title": "{}", {base}, {need}}}"#, "x".repeat(121)),
            "title",
            "121 characters long",
        ),
        (
            format!(r#"{{"base": "v=1&preset=nope", {need}}}"#),
            "base",
            "field 'base': field 'preset'",
        ),
        (format!(r#"{{"base": "", {need}}}"#), "base", "field 'base'"),
    ];
    assert_compose_errors(cases);
}

#[test]
fn a_composer_error_names_the_allowed_field() {
    let base = COMPOSE_BASE;
    let need = COMPOSE_NEED;
    let cases: &[(String, &str, &str)] = &[
        (
            format!(
                r#"{{{base}, {need}, "allow": [{{"field": "k1", "lo": "2000", "hi": "300"}}]}}"#
            ),
            "allow.k1",
            "field 'allow.k1' = '2000..300': expected LO..HI",
        ),
        (
            format!(
                r#"{{{base}, {need}, "allow": [{{"field": "k1", "lo": "fast", "hi": "300"}}]}}"#
            ),
            "allow.k1",
            "expected LO..HI",
        ),
        (
            format!(r#"{{{base}, {need}, "allow": [{{"field": "k1"}}]}}"#),
            "allow.k1",
            "field 'allow.k1' = '..'",
        ),
        (
            format!(r#"{{{base}, {need}, "allow": [{{"field": "kk", "lo": 1, "hi": 2}}]}}"#),
            "allow.kk",
            "'kk' is not a scenario field",
        ),
        (
            format!(r#"{{{base}, {need}, "allow": [{{"field": "ekf", "options": "euler|rk5"}}]}}"#),
            "allow.ekf",
            "expected distinct names from euler|rk4",
        ),
        (
            format!(
                r#"{{{base}, {need}, "allow": [{{"field": "ekf", "options": ["rk4"], "lo": 1}}]}}"#
            ),
            "allow.ekf",
            "not both",
        ),
        (
            format!(
                r#"{{{base}, {need}, "allow": [{{"field": "k1", "lo": 1, "hi": 2}}, {{"field": "k1", "lo": 1, "hi": 3}}]}}"#
            ),
            "allow.k1",
            "field 'allow.k1' is given more than once",
        ),
    ];
    assert_compose_errors(cases);
}

#[test]
fn a_composer_error_names_the_criterion() {
    let base = COMPOSE_BASE;
    let cases: &[(String, &str, &str)] = &[
        (
            format!(r#"{{{base}, "need": [{{"figure": "peak", "op": "max", "bound": 4}}]}}"#),
            "need.peak",
            "'peak' is not a figure",
        ),
        (
            format!(
                r#"{{{base}, "need": [{{"figure": "current_peak", "op": "most", "bound": 4}}]}}"#
            ),
            "need.current_peak",
            "field 'need.current_peak' = 'most:4'",
        ),
        (
            format!(r#"{{{base}, "need": [{{"figure": "current_peak", "op": "max"}}]}}"#),
            "need.current_peak",
            "field 'need.current_peak' = 'max:'",
        ),
        (
            format!(r#"{{{base}, "need": [{{"figure": "current_peak", "op": "band"}}]}}"#),
            "need.current_peak",
            "only mean_nis has a band",
        ),
        (
            format!(
                r#"{{{base}, "need": [{{"figure": "load_recovery_time", "op": "max", "bound": 1}}]}}"#
            ),
            "need.load_recovery_time",
            "the base has no load step",
        ),
        (format!(r#"{{{base}}}"#), "need", "no criteria"),
    ];
    assert_compose_errors(cases);
}

#[test]
fn a_composer_error_names_vary_or_robust() {
    let base = COMPOSE_BASE;
    let need = COMPOSE_NEED;
    let cases: &[(String, &str, &str)] = &[
        (
            format!(r#"{{{base}, {need}, "vary": "seeds:1..30", "robust": ["current_peak"]}}"#),
            "vary",
            "field 'vary' = 'seeds:1..30'",
        ),
        (
            format!(r#"{{{base}, {need}, "vary": "k1=-1", "robust": ["current_peak"]}}"#),
            "vary",
            "field 'vary', variant 1: field 'k1'",
        ),
        (
            format!(r#"{{{base}, {need}, "vary": "model.j=0.016|", "robust": ["current_peak"]}}"#),
            "vary",
            "field 'vary', variant 2 is empty",
        ),
        (
            format!(r#"{{{base}, {need}, "vary": "seed=2"}}"#),
            "vary",
            "no criterion uses the variants",
        ),
        (
            format!(r#"{{{base}, {need}, "robust": ["current_peak"]}}"#),
            "robust",
            "there are no variants",
        ),
        (
            format!(r#"{{{base}, {need}, "vary": "seed=2", "robust": ["mean_nis"]}}"#),
            "robust",
            "'mean_nis' is not the figure of a criterion",
        ),
    ];
    assert_compose_errors(cases);
}

#[test]
fn a_composer_error_for_a_too_long_challenge_names_the_challenge() {
    let base = COMPOSE_BASE;
    let need = COMPOSE_NEED;
    let json = format!(
        r#"{{{base}, {need}, "vary": "{}", "robust": ["current_peak"]}}"#,
        vec![format!("k1=1000.{}", "0".repeat(900)); 20].join("|")
    );
    assert_compose_errors(&[(json, "challenge", "16384 bytes (16 KiB) allowed")]);
}
