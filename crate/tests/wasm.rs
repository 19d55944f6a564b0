//! Binding tests, run in Node by `wasm-pack test --node`: the bindings return the core's numbers
//! byte for byte, and errors come back as the codec's readable messages.
#![cfg(target_arch = "wasm32")]

use imlab::record::COLUMNS;
use imlab::scenario::Scenario;
use imlab::sim;
use imlab::wasm::{describe, Simulation};
use tsify::Ts;
use wasm_bindgen_test::wasm_bindgen_test;

/// What a binding threw, in English: its text, or the core's message said as the CLI says it.
fn error_text(e: wasm_bindgen::JsValue) -> String {
    e.as_string().unwrap_or_else(|| message_of(&e).to_string())
}

/// The core's message `value` as the page receives it: its id and its arguments.
fn message_of(value: &wasm_bindgen::JsValue) -> imlab::text::Message {
    use js_sys::{Array, Object, Reflect};
    // A message's id and names are static in the core; a test's few are kept for its life.
    let name = |text: String| -> &'static str { Box::leak(text.into_boxed_str()) };
    let get = |of: &wasm_bindgen::JsValue, key: &str| Reflect::get(of, &key.into()).unwrap();
    let id = get(value, "id").as_string().expect("a text or a message");
    let mut message = imlab::text::Message::new(name(id));
    for entry in Object::entries(&get(value, "args").into()).iter() {
        let entry = Array::from(&entry);
        let (key, arg) = (name(entry.get(0).as_string().unwrap()), entry.get(1));
        message = if let Some(text) = arg.as_string() {
            message.text(key, text)
        } else if let Some(count) = arg.as_f64() {
            message.count(key, count as i64)
        } else if Array::is_array(&arg) {
            let items = Array::from(&arg).iter().map(|m| message_of(&m)).collect();
            message.list(key, items)
        } else if let Some(real) = get(&arg, "real").as_f64() {
            message.real(key, real)
        } else if let Some(fixed) = get(&arg, "fixed").as_f64() {
            message.fixed(key, fixed, get(&arg, "fraction").as_f64().unwrap() as u8)
        } else {
            message.said(key, message_of(&arg))
        };
    }
    message
}

/// A message of the core as the page receives it: its id (its arguments aside).
#[derive(serde::Deserialize, Debug, PartialEq)]
struct Said {
    id: String,
}

/// A paragraph of a challenge's brief, by its messages' ids.
#[derive(serde::Deserialize, Debug, PartialEq)]
struct Paragraph {
    head: Said,
    items: Vec<Said>,
}

/// A challenge's brief, by its messages' ids.
#[derive(serde::Deserialize, Debug, PartialEq)]
struct Brief {
    paragraphs: Vec<Paragraph>,
}

/// A message of the core whose arguments are all text.
#[derive(serde::Deserialize, Debug, PartialEq)]
struct SaidText {
    id: String,
    args: std::collections::BTreeMap<String, String>,
}

#[wasm_bindgen_test]
fn bindings_return_the_core_columns_byte_for_byte() {
    for text in [
        "step",
        "v=1&preset=sine200&duration=0.02&seed=9",
        "v=1&preset=decay&ekf=rk4",
    ] {
        let mut js = Simulation::new(text).unwrap();
        while !js.finished() {
            js.step(777).unwrap();
        }
        let mut core = sim::Simulation::new(&Scenario::parse(text).unwrap(), 1).unwrap();
        core.run().unwrap();
        // The binding replays from checkpoints; the core here keeps every row.
        for name in COLUMNS {
            let a = js.column(name).unwrap().to_vec();
            let b = core.recorder().column(name).unwrap();
            assert_eq!(a.len(), b.len());
            assert!(
                a.iter().zip(&b).all(|(x, y)| x.to_bits() == y.to_bits()),
                "{text}: column {name}"
            );
        }
        let csv = core.csv().into_bytes();
        assert_eq!(js.csv_chunk(0, js.rows()), csv);
        // The export's chunks (the header with the first) concatenate to the same bytes.
        let mut chunks = Vec::new();
        for start in (0..js.rows()).step_by(333) {
            chunks.extend(js.csv_chunk(start, 333));
        }
        assert_eq!(chunks, csv, "{text}");
    }
}

#[wasm_bindgen_test]
fn views_match_the_core() {
    let groups = vec![
        vec!["omega".to_string(), "u_a".to_string()],
        vec!["nis".to_string()],
    ];
    let js_groups = serde_wasm_bindgen::to_value(&groups).unwrap();
    let mut core = sim::Simulation::new(&Scenario::parse("sine200").unwrap(), 1).unwrap();
    core.run().unwrap();
    // The whole run from the overview kept while running, then zoomed windows by replay.
    let mut js = Simulation::new("sine200").unwrap();
    js.keep_overview(js_groups.clone(), 300).unwrap();
    js.step(u32::MAX).unwrap();
    for (t0, t1, buckets) in [
        (0.0, 1.0, 300),
        (0.0, 1.0, 299),
        (0.1, 0.11, 300),
        (0.05, 0.2, 50),
    ] {
        let view = js.view(js_groups.clone(), t0, t1, buckets).unwrap();
        let expected = core.view(&groups, t0, t1, buckets as usize).unwrap();
        assert_eq!(view.length() as usize, expected.len());
        for (g, cols) in expected.iter().enumerate() {
            let got = js_sys::Array::from(&view.get(g as u32));
            for (i, col) in cols.iter().enumerate() {
                let got = js_sys::Float64Array::from(got.get(i as u32)).to_vec();
                assert_eq!(&got, col, "{t0}–{t1} s, {buckets} buckets, group {g}");
            }
        }
    }
}

#[wasm_bindgen_test]
fn errors_are_readable_messages() {
    let e = error_text(Simulation::new("v=1&preset=step&k1=-3").err().unwrap());
    assert!(e.contains("'k1'") && e.contains("0 < k1"), "{e}");
    // A refused scenario is described as refused, with the key of the field at fault.
    struct Rejected {
        key: Option<String>,
        message: String,
    }
    struct Checked {
        info: Option<()>,
        rejected: Vec<Rejected>,
    }
    let checked = |text: &str| -> Checked {
        use js_sys::{Array, Reflect};
        let value: wasm_bindgen::JsValue = describe(text).unwrap().into();
        let get = |of: &wasm_bindgen::JsValue, key: &str| Reflect::get(of, &key.into()).unwrap();
        Checked {
            info: (!get(&value, "info").is_null()).then_some(()),
            rejected: Array::from(&get(&value, "rejected"))
                .iter()
                .map(|r| Rejected {
                    key: get(&r, "key").as_string(),
                    message: error_text(get(&r, "message")),
                })
                .collect(),
        }
    };
    let c = checked("v=1&preset=nope");
    assert!(c.info.is_none() && c.rejected.len() == 1);
    assert_eq!(c.rejected[0].key.as_deref(), Some("preset"));
    assert!(
        c.rejected[0].message.contains("unknown preset"),
        "{}",
        c.rejected[0].message
    );
    let c = checked("v=1&preset=step&k1=-3");
    assert_eq!(c.rejected[0].key.as_deref(), Some("k1"));
    let c = checked("v=1&preset=step&k1=600");
    assert!(c.info.is_some() && c.rejected.is_empty());
    let e = error_text(
        Simulation::new("v=1&preset=step&init_err=1")
            .unwrap()
            .step(10)
            .err()
            .unwrap(),
    );
    assert!(e.contains("singular"), "{e}");
    let e = error_text(
        Simulation::new("step")
            .unwrap()
            .column("nope")
            .err()
            .unwrap(),
    );
    assert!(e.contains("nope"), "{e}");
}

#[wasm_bindgen_test]
fn figures_and_transient_are_the_core_values() {
    use js_sys::{Array, Reflect};
    use wasm_bindgen::JsValue;
    /// `value` as the page receives it, in JSON.
    fn json(value: &impl serde::Serialize) -> String {
        let js = value
            .serialize(&serde_wasm_bindgen::Serializer::json_compatible())
            .unwrap();
        js_sys::JSON::stringify(&js).unwrap().into()
    }
    /// Field `key` of the object `of`, in JSON.
    fn field(of: &JsValue, key: &str) -> String {
        js_sys::JSON::stringify(&Reflect::get(of, &key.into()).unwrap())
            .unwrap()
            .into()
    }
    let mut js = Simulation::new("step").unwrap();
    js.step(u32::MAX).unwrap();
    let mut core = sim::Simulation::new(&Scenario::parse("step").unwrap(), 1).unwrap();
    core.run().unwrap();
    let report: JsValue = js.report().unwrap().into();
    let got = Array::from(&Reflect::get(&report, &"figures".into()).unwrap());
    let expected = core.figures().unwrap();
    assert_eq!(got.length() as usize, expected.len());
    for (g, e) in got.iter().zip(&expected) {
        // The words as the core's messages: their ids and arguments.
        assert_eq!(
            (
                field(&g, "name"),
                field(&g, "label"),
                field(&g, "unit"),
                field(&g, "window")
            ),
            (
                json(&e.name),
                json(&e.label),
                json(&e.unit),
                json(&e.window)
            )
        );
        let value = Reflect::get(&g, &"value".into()).unwrap().as_f64().unwrap();
        assert_eq!(value.to_bits(), e.value.to_bits(), "{}", e.name);
    }
    let got = Reflect::get(&report, &"transient".into()).unwrap();
    assert_eq!(field(&got, "t"), json(&core.transient_end().t));
    assert_eq!(field(&got, "reason"), json(&core.transient_end().reason));
    // Before any sample: no figures.
    let report: JsValue = Simulation::new("step").unwrap().report().unwrap().into();
    assert!(Reflect::get(&report, &"figures".into()).unwrap().is_null());
}

#[wasm_bindgen_test]
fn a_formula_refused_for_an_invisible_character_quotes_it_as_an_escape() {
    /// The reason, a message of the core with the character quoted.
    #[derive(serde::Deserialize)]
    struct Reason {
        id: String,
        args: Quoted,
    }
    #[derive(serde::Deserialize)]
    struct Quoted {
        char: String,
    }
    #[derive(serde::Deserialize)]
    struct Error {
        reason: Reason,
    }
    #[derive(serde::Deserialize)]
    struct Preview {
        error: Option<Error>,
    }
    for c in ['\u{1b}', '\u{9b}', '\u{8}', '\u{7f}', '\0', '\u{202e}'] {
        let law = format!("-si1 + {c}dwd");
        let scenario = format!(
            "v=1&preset=step&law.v1={}",
            imlab::text::percent::encode(&law, b"")
        );
        let escaped = c.escape_default().to_string();
        let e = error_text(Simulation::new(&scenario).err().unwrap());
        assert!(
            e.contains(&escaped) && !e.chars().any(imlab::text::is_invisible),
            "{e:?}"
        );
        let preview: Preview =
            serde_wasm_bindgen::from_value(imlab::wasm::law_preview(1, &law).unwrap().into())
                .unwrap();
        let reason = preview.error.unwrap().reason;
        let quoted = reason.args.char;
        assert_eq!(reason.id, "formula-not-in-language");
        assert!(
            quoted.contains(&escaped) && !quoted.chars().any(imlab::text::is_invisible),
            "{quoted:?}"
        );
    }
}

#[wasm_bindgen_test]
fn quoting_seed_ranges_and_work_are_the_cores() {
    // The page quotes with the core's excerpt: the CLI's escapes and cut.
    for text in [
        "a\u{202e}b\u{2066}c\u{200d}\u{2028}\u{ad}\u{e0041}",
        &"x".repeat(90),
    ] {
        assert_eq!(imlab::wasm::excerpt(text), imlab::text::excerpt(text));
    }
    assert_eq!(imlab::wasm::excerpt("k\u{202e}1"), "k\\u{202e}1");
    // A seed range past 2^53 − 1 is refused with the range before any run.
    assert_eq!(
        imlab::wasm::seed_range(9_007_199_254_740_990.0, 2.0).unwrap(),
        [9_007_199_254_740_990.0, 9_007_199_254_740_991.0]
    );
    let e = error_text(imlab::wasm::seed_range(9_007_199_254_740_991.0, 4.0).unwrap_err());
    assert!(
        e.contains("seeds 9007199254740991 to 9007199254740994"),
        "{e}"
    );
    let e = error_text(imlab::wasm::seed_range(0.5, 4.0).unwrap_err());
    assert!(e.contains("first seed 0.5"), "{e}");
    // The work limit refuses a scenario in the page as in the CLI.
    let e = error_text(
        Simulation::new("v=1&preset=sine200-drive&ts=0.000001&duration=1&substeps=1000")
            .err()
            .unwrap(),
    );
    assert!(e.contains("= 7000000000 steps"), "{e}");
}

#[wasm_bindgen_test]
fn slices_by_the_clock_run_the_same_samples_as_one_call() {
    let text = "v=1&preset=sine200&duration=0.05";
    let mut sliced = Simulation::new(text).unwrap();
    let mut slices = 0;
    while !sliced.finished() {
        // A zero-length slice still runs one batch between two reads of the clock.
        assert!(sliced.step_for(0.0).unwrap() > 0);
        slices += 1;
    }
    assert!(slices > 1, "{slices} slices");
    let mut whole = Simulation::new(text).unwrap();
    whole.step(u32::MAX).unwrap();
    assert_eq!(
        sliced.csv_chunk(0, sliced.rows()),
        whole.csv_chunk(0, whole.rows())
    );
}

#[wasm_bindgen_test]
fn a_model_error_map_through_the_bindings_is_the_cores_csv_byte_for_byte() {
    use imlab::analysis::robust;
    use imlab::wasm::{robust_cells, robust_csv, robust_plan, robust_run};
    let (scenario, text) = (
        "v=1&preset=step&duration=0.06",
        "plant.rr=0%..10%:2;seeds=1..2",
    );
    let axes = serde_wasm_bindgen::to_value(&["plant.rr=0%..10%:2", ""]).unwrap();
    let plan = robust_plan(scenario, axes, Some("1..2".to_string())).unwrap();
    let map = robust::Map::parse(&Scenario::parse(scenario).unwrap(), text).unwrap();
    let runs = js_sys::Array::new();
    let mut core_cells = Vec::new();
    for cell in &map.cells {
        let mut core_runs = Vec::new();
        for &seed in &map.seeds {
            runs.push(&robust_run(&cell.scenario, seed as f64).unwrap().into());
            core_runs.push(robust::map_run(&cell.scenario, seed).unwrap());
        }
        core_cells.push(robust::summarise(cell, &core_runs));
    }
    let cells = robust_cells(plan.clone(), runs.into()).unwrap();
    let cells: js_sys::Array = cells.into_iter().map(wasm_bindgen::JsValue::from).collect();
    assert_eq!(
        robust_csv(plan, cells.into()).unwrap(),
        robust::map_csv(&map, &core_cells)
    );
    let axes = serde_wasm_bindgen::to_value(&["kx=1..2:2"]).unwrap();
    let e = error_text(robust_plan(scenario, axes, None).unwrap_err());
    assert!(e.contains("kx is not a scenario field"), "{e}");
}

#[wasm_bindgen_test]
fn challenge_links_are_written_and_opened_by_the_core() {
    use imlab::challenge::{self, ChallengeParts, FormNumber, NeedPart};
    use imlab::wasm::{challenge_compose, Challenge};
    use serde::Deserialize;
    let b = challenge::builtin("step-tune").unwrap();
    // A submission link in a URL opens its challenge; its tries are not read.
    let c =
        Challenge::from_link(&format!("https://lab.example/?{}&try.k1=%ZZ#top", b.text)).unwrap();
    assert_eq!(c.encode(), b.text);
    assert_eq!(
        Challenge::from_link("?challenge=step-tune")
            .unwrap()
            .encode(),
        b.text
    );
    // The student's values give the canonical submission link, which reads back as it is.
    let pairs = |p: &[(&str, &str)]| serde_wasm_bindgen::to_value(p).unwrap();
    #[derive(Deserialize)]
    struct Written {
        encoded: String,
    }
    let written: Written = serde_wasm_bindgen::from_value(
        c.submission_of(pairs(&[("k2", "2000"), ("k1", "2000.0")]))
            .unwrap()
            .into(),
    )
    .unwrap();
    let link = written.encoded;
    assert_eq!(link, format!("{}&try.k1=2000&try.k2=2000", b.text));
    #[derive(Deserialize)]
    struct Sub {
        kind: String,
        encoded: String,
    }
    let sub: Sub = serde_wasm_bindgen::from_value(c.submission(&link).unwrap().into()).unwrap();
    assert_eq!(
        (sub.kind.as_str(), sub.encoded.as_str()),
        ("ok", link.as_str())
    );
    // The same as the view a submission link gives, without the link.
    #[derive(Deserialize)]
    struct View {
        kind: String,
        message: Option<SaidText>,
        encoded: String,
        scenarios: Vec<String>,
    }
    let view = |v: wasm_bindgen::JsValue| -> View { serde_wasm_bindgen::from_value(v).unwrap() };
    let of = view(
        c.submission_of(pairs(&[("k1", "2000"), ("k2", "2000")]))
            .unwrap()
            .into(),
    );
    assert_eq!(
        (of.kind.as_str(), of.encoded.as_str()),
        ("ok", link.as_str())
    );
    assert_eq!(
        of.scenarios,
        view(c.submission(&link).unwrap().into()).scenarios
    );
    let refused = view(c.submission_of(pairs(&[("k1", "9000")])).unwrap().into());
    assert_eq!(refused.kind, "refused");
    // The core's message, for the page to say in its language.
    let message = refused.message.unwrap();
    assert_eq!(message.id, "challenge-try-outside");
    assert_eq!(
        (
            message.args["setting"].as_str(),
            message.args["range"].as_str()
        ),
        ("k1=9000", "300..5000")
    );
    assert!(refused.encoded.is_empty() && refused.scenarios.is_empty());
    // The composer: the challenge's parts compose to its link and brief, and an error names the
    // part at fault.
    #[derive(Deserialize)]
    struct Fault {
        key: String,
        message: SaidText,
    }
    #[derive(Deserialize)]
    struct Composed {
        encoded: Option<String>,
        brief: Option<Brief>,
        error: Option<Fault>,
    }
    let made: Composed =
        serde_wasm_bindgen::from_value(challenge_compose(c.parts().unwrap()).unwrap().into())
            .unwrap();
    assert_eq!(made.encoded.as_deref(), Some(b.text));
    let brief = serde_wasm_bindgen::to_value(&b.challenge().brief()).unwrap();
    assert_eq!(
        made.brief,
        Some(serde_wasm_bindgen::from_value(brief).unwrap())
    );
    assert!(made.error.is_none());
    let parts = ChallengeParts {
        base: "step".to_string(),
        need: vec![NeedPart {
            figure: "peak".to_string(),
            op: "max".to_string(),
            bound: Some(FormNumber::Number(4.0)),
        }],
        ..ChallengeParts::default()
    };
    let bad: Composed = serde_wasm_bindgen::from_value(
        challenge_compose(Ts::new_unchecked(
            serde_wasm_bindgen::to_value(&parts).unwrap(),
        ))
        .unwrap()
        .into(),
    )
    .unwrap();
    assert!(bad.encoded.is_none() && bad.brief.is_none());
    let fault = bad.error.unwrap();
    assert_eq!(fault.key, "need.peak");
    assert_eq!(
        (
            fault.message.id.as_str(),
            fault.message.args["figure"].as_str()
        ),
        ("challenge-need-unknown-figure", "peak")
    );
}

#[wasm_bindgen_test]
fn a_class_is_graded_by_the_bindings_to_the_bytes_of_the_core() {
    use imlab::challenge::{grade, Challenge};
    use imlab::wasm::{grade_class, grade_link, Challenge as JsChallenge};
    use serde::{Deserialize, Serialize};
    const QUICK: &str = "c=1&title=Quick&base=v%3D1%26preset%3Dstep%26duration%3D0.06\
                         &allow.k1=300..3000&need.current_peak=max:4";
    #[derive(Deserialize)]
    struct Read {
        header: String,
        columns: Vec<String>,
        link_column: Option<String>,
        rows: Vec<grade::ClassRow>,
        error: Option<Said>,
    }
    let read = |challenge: &str, bytes: &[u8]| -> Read {
        serde_wasm_bindgen::from_value(grade_class(challenge, bytes).unwrap().into()).unwrap()
    };
    let mut bytes = format!(
        "Name,Link\r\n\"Lovelace, Adá\",{QUICK}&try.k1=1200\r\n=cmd,=1+1?{QUICK}&try.k1=9000\r\n"
    )
    .into_bytes();
    bytes.extend(b"Eve \xff,c=1&x\r\n");
    let js = read(QUICK, &bytes);
    let c = Challenge::parse(QUICK).unwrap();
    let class = grade::read_class(&bytes).unwrap();
    assert_eq!(js.error, None);
    assert_eq!(js.header, grade::csv_header(&c, &class));
    assert_eq!(
        (js.columns, js.link_column, &js.rows),
        (
            class.columns.clone(),
            class.link_column.clone(),
            &class.rows
        )
    );
    // Each row graded in one call gives the core's CSV line.
    #[derive(Deserialize)]
    struct Graded {
        line: usize,
        status: Said,
        pass: bool,
        csv: String,
    }
    let grade = |row: wasm_bindgen::JsValue| -> Graded {
        serde_wasm_bindgen::from_value(grade_link(QUICK, Ts::new_unchecked(row)).unwrap().into())
            .unwrap()
    };
    let (mut csv, mut expected) = (js.header.clone(), js.header.clone());
    for row in &js.rows {
        let g = grade(serde_wasm_bindgen::to_value(row).unwrap());
        assert_eq!(g.line, row.line);
        csv.push_str(&g.csv);
        expected.push_str(&grade::csv_row(&c, row, &grade::grade_row(&c, row)));
    }
    assert_eq!(csv, expected);
    assert!(
        csv.contains("\nEve \u{fffd},4,c=1&x,malformed: line 4 is not valid UTF-8,,0,0\n"),
        "{csv}"
    );
    assert!(csv.contains("\n'=cmd,3,'=1+1?c=1&"), "{csv}");
    // A single link, without carried cells or status.
    #[derive(Serialize)]
    struct Single {
        line: usize,
        link: String,
    }
    let single = grade(
        serde_wasm_bindgen::to_value(&Single {
            line: 1,
            link: format!("{QUICK}&try.k1=1200"),
        })
        .unwrap(),
    );
    assert!(single.pass && single.status.id == "grade-row-ok");
    // A file or challenge refused whole.
    let utf16: Vec<u8> = "c=1&x\n"
        .encode_utf16()
        .flat_map(u16::to_le_bytes)
        .collect();
    let refused = read(QUICK, &utf16);
    assert_eq!(refused.error.unwrap().id, "grade-file-utf16");
    assert!(refused.header.is_empty() && refused.rows.is_empty());
    assert_eq!(
        read("nope", b"").error.unwrap().id,
        "grade-challenge-refused"
    );
    // The description gives the fingerprint and the built-in an edited challenge passes for.
    #[derive(Deserialize)]
    struct Described {
        fingerprint: String,
        edited_from: Option<String>,
    }
    let describe = |text: &str| -> Described {
        let c = JsChallenge::new(text).unwrap();
        serde_wasm_bindgen::from_value(c.describe().unwrap().into()).unwrap()
    };
    let b = imlab::challenge::builtin("step-tune").unwrap();
    let original = describe(b.name);
    assert_eq!(
        (original.fingerprint.as_str(), original.edited_from),
        ("DSY0-PQ6T", None)
    );
    let edited = describe(&b.text.replace("max:4", "max:40"));
    assert_ne!(edited.fingerprint, "DSY0-PQ6T");
    assert_eq!(edited.edited_from.as_deref(), Some("step-tune"));
}
