//! The bindings of the analysis tools: frequency sweeps, seed sweeps and model-error maps, and the
//! editor of a step's own law (its preview, its language, the verdicts). Built only with the
//! `tools` feature, into the module the page fetches when a tool is first used; the first run
//! needs none of them.

use super::{from_js, js_error, read_js, to_js, to_js_list};
use crate::analysis;
use crate::analysis::robust;
use crate::scenario::{Scenario, MAX_SEED};
use serde::Serialize;
use tsify::Ts;
use wasm_bindgen::prelude::*;

/// The closed-loop response of the variant `variant` (a name of [`analysis::SWEEP_VARIANTS`]) of
/// `scenario` at `freq` (Hz).
#[wasm_bindgen]
pub fn sweep_point(
    scenario: &str,
    variant: &str,
    freq: f64,
    amp: f64,
    duration: f64,
    offset: f64,
) -> Result<Ts<analysis::SweepPoint>, JsValue> {
    let base = Scenario::parse(scenario).map_err(js_error)?;
    let s = analysis::variant_scenario(&base, analysis::sweep_variant(variant).map_err(js_error)?)
        .map_err(js_error)?;
    let settings = analysis::SweepSettings {
        amp,
        duration,
        offset,
    };
    to_js(&analysis::sweep_point(&s, freq, &settings).map_err(js_error)?)
}

/// A sweep's plan as the page runs it: the plan, its text (a link's `#sweep=`), its
/// frequencies, its variants' labels and what a reader of its results must know.
#[cfg_attr(
    target_arch = "wasm32",
    derive(tsify::Tsify),
    tsify(missing_as_null, hashmap_as_object)
)]
#[derive(Serialize)]
pub struct PlanView {
    plan: analysis::SweepPlan,
    text: String,
    frequencies: Vec<f64>,
    labels: Vec<&'static str>,
    caveats: Vec<String>,
}

fn plan_view(plan: Result<analysis::SweepPlan, String>) -> Result<Ts<PlanView>, JsValue> {
    let plan = plan.map_err(js_error)?;
    let labels = plan
        .variants
        .iter()
        .map(|v| analysis::sweep_variant(v).map(|v| v.label))
        .collect::<Result<_, _>>()
        .map_err(js_error)?;
    to_js(&PlanView {
        text: plan.text(),
        frequencies: plan.frequencies().map_err(js_error)?,
        labels,
        caveats: plan.caveats(),
        plan,
    })
}

/// The sweep plan `text` (`LO,HI,N,AMP,OFFSET,DURATION,VARIANT.VARIANT…`, as `imlab sweep --plan`
/// reads it); throws the message naming the first part that is not acceptable.
#[wasm_bindgen]
pub fn sweep_plan(text: &str) -> Result<Ts<PlanView>, JsValue> {
    plan_view(analysis::SweepPlan::parse(text))
}

/// The sweep plan of a form's parts as written: `numbers` `[lo, hi, n, amp, offset, duration]`,
/// `variants` their names; throws as [`sweep_plan`] does.
#[wasm_bindgen]
pub fn sweep_plan_of(
    #[wasm_bindgen(unchecked_param_type = "string[]")] numbers: JsValue,
    #[wasm_bindgen(unchecked_param_type = "string[]")] variants: JsValue,
) -> Result<Ts<PlanView>, JsValue> {
    let numbers: Vec<String> = read_js(numbers)?;
    let variants: Vec<String> = read_js(variants)?;
    let numbers: [&str; 6] = numbers
        .iter()
        .map(String::as_str)
        .collect::<Vec<_>>()
        .try_into()
        .map_err(|_| {
            js_error("a sweep's plan has six numbers: lo, hi, n, amp, offset, duration")
        })?;
    let variants: Vec<&str> = variants.iter().map(String::as_str).collect();
    plan_view(analysis::SweepPlan::from_parts(numbers, &variants))
}

/// The bandwidth, the phase at 200 Hz and the counts and peaks of sweep points.
#[wasm_bindgen]
pub fn sweep_summary(
    #[wasm_bindgen(unchecked_param_type = "SweepPoint[]")] points: JsValue,
) -> Result<Ts<analysis::SweepSummary>, JsValue> {
    let points: Vec<analysis::SweepPoint> = read_js(points)?;
    to_js(&analysis::summarise(&points))
}

/// Sweep points as the CSV `imlab sweep` prints.
#[wasm_bindgen]
pub fn sweep_csv(
    #[wasm_bindgen(unchecked_param_type = "SweepPoint[]")] points: JsValue,
) -> Result<String, JsValue> {
    let points: Vec<analysis::SweepPoint> = read_js(points)?;
    Ok(analysis::sweep_csv(&points))
}

/// The seeds of a seed sweep of `count` seeds from `first`, in order; throws, naming the range,
/// when it would run past the largest seed (2^53 − 1), before any run.
#[wasm_bindgen]
pub fn seed_range(first: f64, count: f64) -> Result<Vec<f64>, JsValue> {
    let range = analysis::seed_range(whole("first seed", first)?, whole("seeds", count)?)
        .map_err(js_error)?;
    // Every seed is at most 2^53 − 1, so each is a JavaScript number exactly.
    Ok(range.map(|seed| seed as f64).collect())
}

/// One seed's run of `scenario`, keeping every `every`-th sample of its error traces:
/// `{result: {seed, tracking_rms, speed_estimate_error_rms, tracking_peak, failure}, t, error,
/// estimate}`.
#[wasm_bindgen]
pub fn seed_run(scenario: &str, seed: f64, every: usize) -> Result<Ts<analysis::SeedRun>, JsValue> {
    let s = Scenario::parse(scenario).map_err(js_error)?;
    let seed = whole("seed", seed)?;
    to_js(&analysis::seed_run(&s, seed, every).map_err(js_error)?)
}

/// Mean and min–max bands over seed runs (in seed order).
#[wasm_bindgen]
pub fn seed_bands(
    #[wasm_bindgen(unchecked_param_type = "SeedRun[]")] runs: JsValue,
) -> Result<Ts<analysis::SeedBands>, JsValue> {
    let runs: Vec<analysis::SeedRun> = read_js(runs)?;
    to_js(&analysis::seed_bands(&runs).map_err(js_error)?)
}

/// Per-seed figures as the CSV `imlab seeds` prints.
#[wasm_bindgen]
pub fn seeds_csv(
    #[wasm_bindgen(unchecked_param_type = "SeedResult[]")] results: JsValue,
) -> Result<String, JsValue> {
    let results: Vec<analysis::SeedResult> = read_js(results)?;
    Ok(analysis::seeds_csv(&results))
}

/// A map's text (`AXIS[;AXIS][;seeds=A..B]`, as `imlab robust` reads its options) in its parts,
/// for a form to show; throws for seeds given twice.
#[wasm_bindgen]
pub fn robust_parts(text: &str) -> Result<Ts<robust::MapParts>, JsValue> {
    to_js(&robust::MapParts::split(text).map_err(js_error)?)
}

/// The model-error map of `scenario` with the axes `axes` (each `KEY=LO..HI:N`; empty ones left
/// out) and the seeds `seeds` (`A..B`; 1..10 when null), checked and bounded before any run: its
/// axes, cells and seeds.
#[wasm_bindgen]
pub fn robust_plan(
    scenario: &str,
    #[wasm_bindgen(unchecked_param_type = "string[]")] axes: JsValue,
    seeds: Option<String>,
) -> Result<Ts<robust::Map>, JsValue> {
    let s = Scenario::parse(scenario).map_err(js_error)?;
    let axes: Vec<String> = read_js(axes)?;
    to_js(&robust::Map::from_parts(&s, &axes, seeds.as_deref()).map_err(js_error)?)
}

/// One run of a map's cell: its scenario as the plan wrote it, with noise seed `seed`.
#[wasm_bindgen]
pub fn robust_run(scenario: &str, seed: f64) -> Result<Ts<robust::MapRun>, JsValue> {
    to_js(&robust::map_run(scenario, whole("seed", seed)?).map_err(js_error)?)
}

/// The rows of a map's cells from its runs, cell after cell, each cell's seeds in the map's order.
#[wasm_bindgen]
pub fn robust_cells(
    map: Ts<robust::Map>,
    #[wasm_bindgen(unchecked_param_type = "MapRun[]")] runs: JsValue,
) -> Result<Vec<Ts<robust::Cell>>, JsValue> {
    let map = from_js(&map)?;
    let runs: Vec<robust::MapRun> = read_js(runs)?;
    let per = map.seeds.len();
    if per == 0 || runs.len() != map.cells.len() * per {
        return Err(js_error(format!(
            "{} runs for {} cells × {per} seeds",
            runs.len(),
            map.cells.len()
        )));
    }
    let cells: Vec<robust::Cell> = map
        .cells
        .iter()
        .zip(runs.chunks(per))
        .map(|(c, r)| robust::summarise(c, r))
        .collect();
    to_js_list(&cells)
}

/// A map's rows as the CSV `imlab robust` prints; `cells` may be some of `map`'s (a stopped map),
/// which the CSV then says.
#[wasm_bindgen]
pub fn robust_csv(
    map: Ts<robust::Map>,
    #[wasm_bindgen(unchecked_param_type = "Cell[]")] cells: JsValue,
) -> Result<String, JsValue> {
    let map = from_js(&map)?;
    let cells: Vec<robust::Cell> = read_js(cells)?;
    Ok(robust::map_csv(&map, &cells))
}

/// The figures a map keeps of each run, in its order: `[{name, label, unit}]`.
#[wasm_bindgen]
pub fn robust_figures() -> Result<Vec<Ts<crate::record::FigureInfo>>, JsValue> {
    let info: Vec<_> = robust::MAP_FIGURES
        .iter()
        .map(|f| {
            crate::record::figure_info(f)
                .expect("a map's figures are report figures")
                .clone()
        })
        .collect();
    to_js_list(&info)
}

/// `value` as a seed, or a message naming it as `what`.
fn whole(what: &str, value: f64) -> Result<u64, JsValue> {
    if !(0.0..=MAX_SEED as f64).contains(&value) || value.fract() != 0.0 {
        return Err(js_error(format!(
            "{what} {value}: expected a whole number from 0 to 2^53 − 1"
        )));
    }
    Ok(value as u64)
}

#[cfg_attr(
    target_arch = "wasm32",
    derive(tsify::Tsify),
    tsify(missing_as_null, hashmap_as_object)
)]
/// A function a law may call, with its meaning.
#[derive(Serialize)]
pub struct LawFunction {
    name: &'static str,
    doc: crate::text::Message,
}

#[cfg_attr(
    target_arch = "wasm32",
    derive(tsify::Tsify),
    tsify(missing_as_null, hashmap_as_object)
)]
/// A name a law may use (see [`crate::control::formula::Name`]): its symbol in TeX, its unit, its
/// meaning and the first step whose law may use it.
#[derive(Serialize)]
pub struct LawName {
    name: &'static str,
    tex: &'static str,
    unit: &'static str,
    doc: crate::text::Message,
    from_step: u8,
}

#[cfg_attr(
    target_arch = "wasm32",
    derive(tsify::Tsify),
    tsify(missing_as_null, hashmap_as_object)
)]
/// The names and functions a step's own law may use.
#[derive(Serialize)]
pub struct Language {
    names: Vec<LawName>,
    functions: Vec<LawFunction>,
    paper: [&'static str; 4],
}

/// The language of the steps' own laws: `{names: [{name, tex, unit, doc, from_step}],
/// functions: [{name, doc}], paper: [string]}` (`paper`: each step's law of the paper in it).
#[wasm_bindgen]
pub fn law_language() -> Result<Ts<Language>, JsValue> {
    use crate::control::formula::{FUNCTIONS, NAMES};
    to_js(&Language {
        names: NAMES
            .iter()
            .map(|n| LawName {
                name: n.name,
                tex: n.tex,
                unit: n.unit,
                doc: n.doc(),
                from_step: n.from_step,
            })
            .collect(),
        functions: FUNCTIONS
            .iter()
            .map(|&(name, _, _, doc)| LawFunction {
                name,
                doc: crate::text::Message::new(doc),
            })
            .collect(),
        paper: crate::control::law::PAPER,
    })
}

/// The law `text` of step `step` (1–4) as an editor shows it: `{tex, error: {at, len, reason},
/// designed}` (see [`crate::control::law::preview`]).
#[wasm_bindgen]
pub fn law_preview(step: u8, text: &str) -> Result<Ts<crate::control::law::Preview>, JsValue> {
    if !(1..=4).contains(&step) {
        return Err(js_error(
            crate::text::Message::new("law-no-such-step").count("step", step),
        ));
    }
    to_js(&crate::control::law::preview(step, text))
}

/// The verdict of each step with its own law in `scenario`, against its designed dynamics:
/// `[{step, law, on, designed, worst, finding, text}]`.
#[wasm_bindgen]
pub fn law_verdicts(scenario: &str) -> Result<Vec<Ts<crate::control::law::Verdict>>, JsValue> {
    let s = Scenario::parse(scenario).map_err(js_error)?;
    let model = s.model.lumped().map_err(js_error)?;
    let verdicts = crate::control::law::verdicts(&s.law, &model, &s.gains)
        .map_err(|(step, e)| js_error(crate::control::law::refused(step, &e)))?;
    to_js_list(&verdicts)
}

/// The design `design=derived` gives the motor of `scenario`: each value with the rule behind it
/// and its reason (as `imlab design` prints them).
#[wasm_bindgen]
pub fn design_lines(scenario: &str) -> Result<Vec<Ts<crate::design::Line>>, JsValue> {
    let s = Scenario::parse(scenario).map_err(js_error)?;
    let derived = s.derived().map_err(|e| js_error(e.message()))?;
    to_js_list(&derived.lines(&s.design_inputs()))
}

/// How scenario `text` differs from scenario `from`, field by field ("key: from's → text's unit").
#[wasm_bindgen]
pub fn scenario_differences(from: &str, text: &str) -> Result<Vec<String>, JsValue> {
    let from = Scenario::parse(from).map_err(js_error)?;
    let to = Scenario::parse(text).map_err(js_error)?;
    Ok(to.differences(&from))
}

/// The circuit a motor's nameplate and lab tests give (`imlab motor`), each value with how it was
/// found, and the link that runs it with the derived design.
#[wasm_bindgen]
pub fn motor_from_tests(
    entry: Ts<crate::identify::Entry>,
) -> Result<Ts<crate::identify::Identified>, JsValue> {
    let entry = from_js(&entry)?;
    to_js(&crate::identify::identify(&entry).map_err(|e| js_error(e.message()))?)
}

/// The example the motor form fills in: the 2.2 kW machine's rating and the readings its circuit
/// gives, as a lab writes them down.
#[wasm_bindgen]
pub fn motor_example() -> Result<Ts<crate::identify::Entry>, JsValue> {
    to_js(&crate::identify::Entry::example())
}
