//! Binding tests, run in Node by `wasm-pack test --node`: the bindings return the core's numbers
//! byte for byte, and errors come back as the codec's readable messages.
#![cfg(target_arch = "wasm32")]

use imlab::scenario::Scenario;
use imlab::sim::{self, COLUMNS};
use imlab::wasm::{describe, Simulation};
use wasm_bindgen_test::wasm_bindgen_test;

fn error_text(e: wasm_bindgen::JsValue) -> String {
    e.as_string().expect("errors are strings")
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
        for name in COLUMNS {
            let a = js.column(name).unwrap().to_vec();
            let b = core.recorder().column(name).unwrap();
            assert_eq!(a.len(), b.len());
            assert!(
                a.iter().zip(&b).all(|(x, y)| x.to_bits() == y.to_bits()),
                "{text}: column {name}"
            );
        }
        assert_eq!(
            js.csv_chunk(0, js.rows()),
            core.recorder().csv().into_bytes()
        );
        // The export's chunks (the header with the first) concatenate to the same bytes.
        let mut chunks = Vec::new();
        for start in (0..js.rows()).step_by(333) {
            chunks.extend(js.csv_chunk(start, 333));
        }
        assert_eq!(chunks, core.recorder().csv().into_bytes(), "{text}");
    }
}

#[wasm_bindgen_test]
fn envelope_matches_the_core() {
    let mut js = Simulation::new("sine200").unwrap();
    js.step(u32::MAX).unwrap();
    let mut core = sim::Simulation::new(&Scenario::parse("sine200").unwrap(), 1).unwrap();
    core.run().unwrap();
    let names = vec!["omega".to_string(), "u_a".to_string()];
    let env = js.envelope(names, 0.0, 1.0, 300).unwrap();
    let expected = core
        .recorder()
        .envelope(&["omega", "u_a"], 0.0, 1.0, 300)
        .unwrap();
    assert_eq!(env.length() as usize, expected.len());
    for (i, col) in expected.iter().enumerate() {
        let got = js_sys::Float64Array::from(env.get(i as u32)).to_vec();
        assert_eq!(&got, col);
    }
}

#[wasm_bindgen_test]
fn errors_are_readable_messages() {
    let e = error_text(Simulation::new("v=1&preset=step&k1=-3").err().unwrap());
    assert!(e.contains("'k1'") && e.contains("0 < k1"), "{e}");
    let e = error_text(describe("v=1&preset=nope").err().unwrap());
    assert!(e.contains("unknown preset"), "{e}");
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
    #[derive(serde::Deserialize)]
    struct Figure {
        name: String,
        label: String,
        value: f64,
        unit: String,
        window: String,
    }
    #[derive(serde::Deserialize)]
    struct Transient {
        t: f64,
        reason: String,
    }
    let mut js = Simulation::new("step").unwrap();
    js.step(u32::MAX).unwrap();
    let mut core = sim::Simulation::new(&Scenario::parse("step").unwrap(), 1).unwrap();
    core.run().unwrap();
    let got: Vec<Figure> = serde_wasm_bindgen::from_value(js.figures().unwrap()).unwrap();
    let expected = sim::figures(&core).unwrap();
    assert_eq!(got.len(), expected.len());
    for (g, e) in got.iter().zip(&expected) {
        assert_eq!(
            (
                g.name.as_str(),
                g.label.as_str(),
                g.unit.as_str(),
                g.window.as_str()
            ),
            (e.name, e.label, e.unit, e.window.as_str())
        );
        assert_eq!(g.value.to_bits(), e.value.to_bits(), "{}", e.name);
    }
    let got: Transient = serde_wasm_bindgen::from_value(js.transient().unwrap()).unwrap();
    let expected = sim::transient_end(&core);
    assert_eq!((got.t, got.reason), (expected.t, expected.reason));
    // Before any sample: no figures.
    assert!(Simulation::new("step")
        .unwrap()
        .figures()
        .unwrap()
        .is_null());
}
