//! JavaScript bindings: type conversion and error mapping only; no physics lives here.

use crate::params::Lumped;
use crate::record::COLUMNS;
use crate::scenario::{Scenario, PRESETS};
use crate::sim;
use js_sys::{Array, Float64Array};
use serde::Serialize;
use tsify::{Ts, Tsify};
use wasm_bindgen::prelude::*;
use wasm_bindgen::JsCast;

// The page's other tools, apart from the run: challenges, class grading, sweeps and maps.
#[cfg(feature = "tools")]
mod challenge;
#[cfg(feature = "tools")]
mod grade;
#[cfg(feature = "tools")]
mod tools;

#[cfg(feature = "tools")]
pub use challenge::{challenge_builtins, challenge_compose, challenge_figures, Challenge};
#[cfg(feature = "tools")]
pub use grade::{grade_class, grade_link};
#[cfg(feature = "tools")]
pub use tools::*;

thread_local! {
    /// The text of the last Rust panic, kept for the worker to report after the trap it causes.
    static LAST_PANIC: std::cell::RefCell<Option<String>> = const { std::cell::RefCell::new(None) };
}

/// Installs the panic hook when the module starts: a panic's text goes to the console (the
/// maintained `console_error_panic_hook`) and is kept for [`panic_message`].
#[wasm_bindgen(start)]
fn start() {
    std::panic::set_hook(Box::new(|info| {
        LAST_PANIC.with(|p| *p.borrow_mut() = Some(info.to_string()));
        console_error_panic_hook::hook(info);
    }));
}

/// The text of the last Rust panic in this module, if one happened (the module is unusable after it).
#[wasm_bindgen]
pub fn panic_message() -> Option<String> {
    LAST_PANIC.with(|p| p.borrow().clone())
}

/// An error as the page receives it: the core's message (its id and arguments, which the page
/// renders in the reader's language) where the error has one, else its text.
trait Refusal {
    fn refusal(&self) -> JsValue;
}

/// Errors said as their text.
macro_rules! said_as_text {
    ($($t:ty),*) => {$(
        impl Refusal for $t {
            fn refusal(&self) -> JsValue {
                JsValue::from_str(&self.to_string())
            }
        }
    )*};
}

impl Refusal for crate::text::Message {
    /// As every value the page receives (see [`raw_js`]): its arguments a plain object, which
    /// the page's `said()` reads (the default serializer would make them a `Map`).
    fn refusal(&self) -> JsValue {
        raw_js(self).unwrap_or_else(|e| e)
    }
}

said_as_text!(String, &str, serde_wasm_bindgen::Error);

impl Refusal for crate::params::ParamError {
    fn refusal(&self) -> JsValue {
        self.message().refusal()
    }
}

impl Refusal for crate::scenario::ScenarioError {
    fn refusal(&self) -> JsValue {
        self.message().refusal()
    }
}

impl Refusal for crate::control::formula::FormulaError {
    fn refusal(&self) -> JsValue {
        self.message().refusal()
    }
}

impl Refusal for crate::sim::SimError {
    fn refusal(&self) -> JsValue {
        self.message().refusal()
    }
}

impl Refusal for crate::challenge::ChallengeError {
    fn refusal(&self) -> JsValue {
        self.message.refusal()
    }
}

fn js_error(e: impl Refusal) -> JsValue {
    e.refusal()
}

/// A closed-loop run, advanced in chunks from JavaScript.
#[wasm_bindgen]
pub struct Simulation {
    inner: sim::Simulation,
}

#[wasm_bindgen]
impl Simulation {
    /// Parses `scenario` (the query-string codec) and prepares the run. It keeps checkpoints,
    /// not rows: every read below replays the rows it needs, bit for bit.
    #[wasm_bindgen(constructor)]
    pub fn new(scenario: &str) -> Result<Simulation, JsValue> {
        let s = Scenario::parse(scenario).map_err(js_error)?;
        let inner = sim::Simulation::traced(&s).map_err(js_error)?;
        Ok(Simulation { inner })
    }

    /// Before the first step: computes the whole run's view of `groups` (an array of arrays of
    /// column names) in `buckets` buckets while it runs, so that the first plot needs no replay.
    pub fn keep_overview(
        &mut self,
        #[wasm_bindgen(unchecked_param_type = "string[][]")] groups: JsValue,
        buckets: u32,
    ) -> Result<(), JsValue> {
        let groups: Vec<Vec<String>> = read_js(groups)?;
        self.inner
            .keep_overview(&groups, buckets as usize)
            .map_err(js_error)
    }

    /// Keeps column `name` of every sample for overlays (see [`Comparison::overlay`]): the samples
    /// run so far by one replay, then each further one as the run goes.
    pub fn keep_column(&mut self, name: &str) -> Result<(), JsValue> {
        self.inner.keep_column(name).map_err(js_error)
    }

    /// Runs up to `max_steps` samples; returns how many ran, or throws the failure message.
    pub fn step(&mut self, max_steps: u32) -> Result<u32, JsValue> {
        let done = self.inner.advance(max_steps as usize).map_err(js_error)?;
        Ok(done as u32)
    }

    /// Runs samples for about `ms` milliseconds of the worker's clock (at least one sample, fewer
    /// if the run ends); returns the number run. A chunk bounded by time, not by a count: one
    /// sample with many substeps and PWM costs as much as thousands of ordinary ones, and Cancel
    /// must still come within a slice. The same samples as any other division of the run.
    pub fn step_for(&mut self, ms: f64) -> Result<u32, JsValue> {
        let start = now();
        let mut done = 0;
        loop {
            done += self.inner.advance(CLOCK_EVERY).map_err(js_error)?;
            // Without a clock, one batch is the slice.
            let late = match (start, now()) {
                (Some(start), Some(t)) => t - start >= ms,
                _ => true,
            };
            if self.inner.is_finished() || late {
                return Ok(done as u32);
            }
        }
    }

    /// Samples run so far.
    #[wasm_bindgen(getter)]
    pub fn done(&self) -> u32 {
        self.inner.steps_done() as u32
    }

    /// Samples in the whole run.
    #[wasm_bindgen(getter)]
    pub fn total(&self) -> u32 {
        self.inner.steps_total() as u32
    }

    /// Whether every sample has run.
    #[wasm_bindgen(getter)]
    pub fn finished(&self) -> bool {
        self.inner.is_finished()
    }

    /// The scenario in its compact form.
    #[wasm_bindgen(getter)]
    pub fn scenario(&self) -> String {
        self.inner.scenario().encode()
    }

    /// Rows recorded so far.
    #[wasm_bindgen(getter)]
    pub fn rows(&self) -> u32 {
        self.inner.len() as u32
    }

    /// Bytes the run's trace holds (its checkpoints, and the column it keeps for overlays).
    #[wasm_bindgen(getter)]
    pub fn trace_bytes(&self) -> u32 {
        self.inner.recording_bytes() as u32
    }

    /// A whole column, copied into a new `Float64Array`.
    pub fn column(&self, name: &str) -> Result<Float64Array, JsValue> {
        let c = COLUMNS
            .iter()
            .position(|c| *c == name)
            .ok_or_else(|| js_error(format!("no column '{}'", crate::text::excerpt(name))))?;
        let mut out = Vec::with_capacity(self.inner.len());
        self.inner.visit(0, usize::MAX, &mut |_, row| {
            out.push(row.get(c));
            true
        });
        Ok(Float64Array::from(out.as_slice()))
    }

    /// M4 envelopes of each group of columns (an array of arrays of names) over t in [t0, t1] in
    /// `buckets` buckets: an array, per group, of `Float64Array`s [t, col1, col2, ...].
    #[wasm_bindgen(unchecked_return_type = "Float64Array[][]")]
    pub fn view(
        &self,
        #[wasm_bindgen(unchecked_param_type = "string[][]")] groups: JsValue,
        t0: f64,
        t1: f64,
        buckets: u32,
    ) -> Result<Array, JsValue> {
        let groups: Vec<Vec<String>> = read_js(groups)?;
        let views = self
            .inner
            .view(&groups, t0, t1, buckets as usize)
            .map_err(js_error)?;
        Ok(views
            .iter()
            .map(|cols| {
                cols.iter()
                    .map(|c| Float64Array::from(c.as_slice()))
                    .collect::<Array>()
            })
            .collect())
    }

    /// The unknown terms d̃2, d̃4 of steps 2 and 4 evaluated from the simulated truth over t in
    /// [t0, t1], as one M4 envelope in `buckets` buckets: `Float64Array`s [t, d̃2, d̃4].
    #[wasm_bindgen(unchecked_return_type = "Float64Array[]")]
    pub fn disturbances(&self, t0: f64, t1: f64, buckets: u32) -> Result<Array, JsValue> {
        float_arrays(
            self.inner
                .disturbances(t0, t1, buckets as usize)
                .map_err(js_error)?,
        )
    }

    /// The residual of each step's designed dynamics, v_i − v_i,paper, over t in [t0, t1], as
    /// one M4 envelope in `buckets` buckets: `Float64Array`s [t, r1, r2, r3, r4]; throws for a
    /// scenario without its own laws.
    #[wasm_bindgen(unchecked_return_type = "Float64Array[]")]
    pub fn law_residuals(&self, t0: f64, t1: f64, buckets: u32) -> Result<Array, JsValue> {
        float_arrays(
            self.inner
                .law_residuals(t0, t1, buckets as usize)
                .map_err(js_error)?,
        )
    }

    /// Each step's error dynamics as the run made them against the designed ones, over the rows
    /// with t in [t0, t1] (s), as one M4 envelope in `buckets` buckets: `Float64Array`s
    /// [t, ż1, d1, ż2, d2, ż3, d3, ż4, d4] (see [`crate::sim::Simulation::designed_dynamics`]);
    /// throws for the IFOC baseline.
    #[wasm_bindgen(unchecked_return_type = "Float64Array[]")]
    pub fn designed_dynamics(&self, t0: f64, t1: f64, buckets: u32) -> Result<Array, JsValue> {
        float_arrays(
            self.inner
                .designed_dynamics(t0, t1, buckets as usize)
                .map_err(js_error)?,
        )
    }

    /// Every recorded value and the Kalman gain at the recorded sample nearest to `t` (s),
    /// replayed from the checkpoint before it.
    pub fn inspect(&self, t: f64) -> Result<Ts<crate::sim::Snapshot>, JsValue> {
        to_js(&self.inner.inspect_at(t).map_err(js_error)?)
    }

    /// The Lyapunov bound (59) at each time in `t` (s), from this run's V(0) and gains.
    pub fn lyapunov_bound(&self, t: &[f64]) -> Result<Float64Array, JsValue> {
        let bound = self
            .inner
            .lyapunov_bound()
            .ok_or_else(|| js_error("nothing recorded"))?;
        let values: Vec<f64> = t.iter().map(|&t| bound.at(t)).collect();
        Ok(Float64Array::from(values.as_slice()))
    }

    /// How V(t) compares with the bound (59); undefined when nothing is recorded.
    pub fn stability(&self) -> Result<Option<Ts<crate::record::Stability>>, JsValue> {
        self.inner.stability().as_ref().map(to_js).transpose()
    }

    /// RMS tracking and estimation errors, mean NIS and saturation of the run, by the report's
    /// names where it gives the figure too; undefined when nothing is recorded.
    pub fn metrics(&self) -> Result<Option<Ts<crate::record::Metrics>>, JsValue> {
        self.inner.metrics().as_ref().map(to_js).transpose()
    }

    /// Where the start-up transient ends and the figures of the run so far, as `imlab metrics`
    /// prints them (null when nothing is recorded), with the figures the run had not reached by
    /// its end in words, the warnings, and what the page derives from the figures (see
    /// [`crate::record::Report`]).
    pub fn report(&self) -> Result<Ts<crate::record::Report>, JsValue> {
        to_js(&self.inner.report())
    }

    /// Recorded rows `start..start + count` as CSV bytes (with the header when `start` is 0):
    /// the chunks of a run, in order, concatenate to the CSV `imlab run` writes, byte for byte.
    pub fn csv_chunk(&self, start: u32, count: u32) -> Vec<u8> {
        let mut out = Vec::new();
        self.inner
            .write_csv_rows(&mut out, start as usize, count as usize)
            .expect("writing to a Vec");
        out
    }
}

/// A preset as the page lists it.
#[cfg_attr(
    target_arch = "wasm32",
    derive(tsify::Tsify),
    tsify(missing_as_null, hashmap_as_object)
)]
#[derive(Serialize)]
pub struct PresetInfo {
    name: &'static str,
    /// What it shows (`preset-NAME`).
    description: crate::text::Message,
}

/// Presets as `[{name, description}]`.
#[wasm_bindgen]
pub fn presets() -> Result<Vec<Ts<PresetInfo>>, JsValue> {
    let list: Vec<PresetInfo> = PRESETS
        .iter()
        .map(|p| PresetInfo {
            name: p.name,
            description: p.description.clone(),
        })
        .collect();
    to_js_list(&list)
}

/// An envelope's columns as `Float64Array`s.
fn float_arrays(cols: Vec<Vec<f64>>) -> Result<Array, JsValue> {
    Ok(cols
        .iter()
        .map(|c| Float64Array::from(c.as_slice()))
        .collect())
}

/// `value` as the page receives it, typed by its declaration in the bindings' `.d.ts` (written
/// from the Rust type by `tsify`): maps as objects, `None` as null, numbers as numbers.
fn to_js<T: Tsify + Serialize>(value: &T) -> Result<Ts<T>, JsValue> {
    raw_js(value).map(Ts::new_unchecked)
}

/// Each of `values` as [`to_js`] writes it: an array of them.
fn to_js_list<T: Tsify + Serialize>(values: &[T]) -> Result<Vec<Ts<T>>, JsValue> {
    values.iter().map(to_js).collect()
}

/// A value whose type the binding names itself (`unchecked_return_type`: lists of pairs),
/// written by the same rules.
fn raw_js(value: &impl Serialize) -> Result<JsValue, JsValue> {
    value
        .serialize(&serde_wasm_bindgen::Serializer::json_compatible())
        .map_err(js_error)
}

#[cfg_attr(
    target_arch = "wasm32",
    derive(tsify::Tsify),
    tsify(missing_as_null, hashmap_as_object)
)]
/// A scenario as the page shows it: its fields, what it changes of its preset, its motors.
#[derive(Serialize)]
pub struct Description {
    /// The scenario as the codec writes it.
    encoded: String,
    /// The preset it starts from.
    preset: String,
    steps: usize,
    /// The largest value one voltage component can take under the limit (V).
    component_limit: f64,
    /// The keys of the fields that differ from the preset, in the codec's order.
    changed: Vec<&'static str>,
    /// Those of them that have no effect in this scenario, each said with why.
    idle: Vec<crate::text::Message>,
    fields: Vec<crate::scenario::FieldInfo>,
    plant: Lumped,
    model: Lumped,
}

impl Description {
    fn of(s: &Scenario) -> Result<Description, JsValue> {
        let lumped = |p: &crate::params::MotorParams| p.lumped().map_err(js_error);
        Ok(Description {
            encoded: s.encode(),
            preset: s.preset.clone(),
            steps: s.steps(),
            component_limit: s.limit().component_max(),
            changed: s.changed_keys(),
            idle: s.idle_settings(),
            fields: s.describe(),
            plant: lumped(&s.plant)?,
            model: lumped(&s.model)?,
        })
    }
}

/// A field of a scenario that the core refused: its key (null when the fault is not one field's)
/// and the codec's message.
#[cfg_attr(
    target_arch = "wasm32",
    derive(tsify::Tsify),
    tsify(missing_as_null, hashmap_as_object)
)]
#[derive(Serialize)]
pub struct Rejected {
    key: Option<String>,
    message: crate::text::Message,
}

impl Rejected {
    fn of(e: &crate::scenario::ScenarioError) -> Rejected {
        Rejected {
            key: e.key().map(str::to_string),
            message: e.message(),
        }
    }
}

/// The description of a scenario checked field by field, or the field at fault.
#[cfg_attr(
    target_arch = "wasm32",
    derive(tsify::Tsify),
    tsify(missing_as_null, hashmap_as_object)
)]
#[derive(Serialize)]
pub struct Checked {
    /// The description; null when the scenario is refused (a fault that is not a field's too) or, for
    /// [`recover`], when nothing of it can be kept (no `v` or `preset`, or a bad one; a text too
    /// long; motors that are not physical).
    info: Option<Description>,
    /// The fields refused: the one fault that refuses the scenario, or every field [`recover`]
    /// left out.
    rejected: Vec<Rejected>,
}

/// Checks `scenario`: its description, or the fault that refuses it (never throws for a bad
/// scenario, so the page marks the field the core names).
#[wasm_bindgen]
pub fn describe(scenario: &str) -> Result<Ts<Checked>, JsValue> {
    to_js(&match Scenario::parse(scenario) {
        Ok(s) => Checked {
            info: Some(Description::of(&s)?),
            rejected: Vec::new(),
        },
        Err(e) => Checked {
            info: None,
            rejected: vec![Rejected::of(&e)],
        },
    })
}

/// Checks the scenario of a form: `preset` with each of `fields` (`[key, value]` pairs, each
/// value as its control holds it) set, read by the codec's rules as [`describe`] reads a text.
#[wasm_bindgen]
pub fn describe_form(
    preset: &str,
    #[wasm_bindgen(unchecked_param_type = "[string, string][]")] fields: JsValue,
) -> Result<Ts<Checked>, JsValue> {
    let fields: Vec<(String, String)> = read_js(fields)?;
    describe(&crate::scenario::compose(preset, &fields))
}

/// `scenario` with its bad fields left out: the description of what is kept and every field
/// left out; a fault that is no one field's keeps nothing (see [`Checked`]).
#[wasm_bindgen]
pub fn recover(scenario: &str) -> Result<Ts<Checked>, JsValue> {
    to_js(&match Scenario::parse_lenient(scenario) {
        Ok((s, errors)) => Checked {
            info: Some(Description::of(&s)?),
            rejected: errors.iter().map(Rejected::of).collect(),
        },
        Err(e) => Checked {
            info: None,
            rejected: vec![Rejected::of(&e)],
        },
    })
}

/// `scenario` with one field changed, in its compact form.
#[wasm_bindgen]
pub fn variant(scenario: &str, key: &str, value: &str) -> Result<String, JsValue> {
    let mut s = Scenario::parse(scenario).map_err(js_error)?;
    s.set(key, value).map_err(js_error)?;
    Ok(s.encode())
}

/// The 95 % band of one sample's NIS for a consistent filter, `[low, high]`.
#[wasm_bindgen]
pub fn nis_band() -> Vec<f64> {
    let (lo, hi) = crate::observer::nis_band(0.95);
    vec![lo, hi]
}

/// Names of the recorded columns in CSV order.
#[wasm_bindgen]
pub fn columns() -> Vec<String> {
    COLUMNS.iter().map(|c| c.to_string()).collect()
}

#[cfg(feature = "tools")]
/// The Rust value of a typed argument; throws the mismatch for one of another shape.
fn from_js<T: Tsify + serde::de::DeserializeOwned>(value: &Ts<T>) -> Result<T, JsValue> {
    serde_wasm_bindgen::from_value(value.js_value()).map_err(js_error)
}

/// An argument whose type the binding names itself (`unchecked_param_type`): lists, which
/// wasm-bindgen would otherwise copy whole before any check, and pairs. A value of another shape
/// is refused with serde's message.
fn read_js<T: serde::de::DeserializeOwned>(value: JsValue) -> Result<T, JsValue> {
    serde_wasm_bindgen::from_value(value).map_err(js_error)
}

/// `text` as every message of the core quotes input: the characters of the Unicode categories
/// Cc, Cf, Zl and Zp escaped (`\u{202e}`), cut to 40 characters with the full length noted.
#[wasm_bindgen]
pub fn excerpt(text: &str) -> String {
    crate::text::excerpt(text)
}

/// Pinned runs to compare with the current one (at most four).
#[wasm_bindgen]
#[derive(Default)]
pub struct Comparison {
    pins: Vec<sim::Simulation>,
}

/// Most pinned runs at once.
const MAX_PINS: usize = 4;

/// Samples between two reads of the clock in [`Simulation::step_for`]: the clock costs a call
/// out of the module, and 16 of the heaviest samples the codec accepts take well under 10 ms.
const CLOCK_EVERY: usize = 16;

/// The worker's clock, `performance.now()` (ms); in a page or in Node the global scope has the
/// same `performance`.
fn now() -> Option<f64> {
    js_sys::global()
        .unchecked_into::<web_sys::WorkerGlobalScope>()
        .performance()
        .map(|p| p.now())
}
#[wasm_bindgen]
impl Comparison {
    /// An empty set of pins.
    #[wasm_bindgen(constructor)]
    pub fn new() -> Comparison {
        Comparison::default()
    }

    /// Whether another run can be pinned; throws, naming the limit, when not.
    pub fn check_room(&self) -> Result<(), JsValue> {
        if self.pins.len() >= MAX_PINS {
            return Err(js_error(
                crate::text::Message::new("pin-room-full").count("max", MAX_PINS),
            ));
        }
        Ok(())
    }

    /// Pins `run`, a run the worker has run in slices (to its end, or its failure) after asking
    /// it to keep the overlay's column; it leaves the caller.
    pub fn adopt(&mut self, run: Simulation) -> Result<(), JsValue> {
        self.check_room()?;
        self.pins.push(run.inner);
        Ok(())
    }

    /// Runs `scenario` to the end (or its failure) and pins it, keeping its column `column` for
    /// overlays; throws for a bad scenario or an unknown column, and pins nothing then.
    pub fn pin(&mut self, scenario: &str, column: &str) -> Result<(), JsValue> {
        self.check_room()?;
        let s = Scenario::parse(scenario).map_err(js_error)?;
        // A pin keeps its checkpoints (under 1 MB for the longest run) and the overlay's column
        // (8 bytes a sample: 8.5 MB for the longest run), so the number of pins is the only
        // limit.
        let mut sim = sim::Simulation::traced(&s).map_err(js_error)?;
        sim.keep_column(column).map_err(js_error)?;
        // A run that stops early stays pinned with the samples before its failure.
        let _ = sim.run();
        self.pins.push(sim);
        Ok(())
    }

    /// Removes pin `index`.
    pub fn unpin(&mut self, index: usize) {
        if index < self.pins.len() {
            self.pins.remove(index);
        }
    }

    /// The pinned scenarios, in pin order.
    pub fn scenarios(&self) -> Vec<String> {
        self.pins.iter().map(|p| p.scenario().encode()).collect()
    }

    /// For each pin, what differs between it and `current` ("key: pin → current; …"), or the
    /// message that nothing does.
    #[wasm_bindgen(unchecked_return_type = "(Message | string)[]")]
    pub fn legends(&self, current: &Simulation) -> Result<JsValue, JsValue> {
        let now = current.inner.scenario();
        let legends: Vec<crate::text::Arg> = self
            .pins
            .iter()
            .map(|p| {
                let d = now.differences(p.scenario());
                if d.is_empty() {
                    crate::text::Message::new("pin-legend-same").into()
                } else {
                    crate::text::Arg::Text(d.join("; "))
                }
            })
            .collect();
        raw_js(&legends)
    }

    /// Column `name` of `current` and of each pin, then current − pin for each, as min/max
    /// envelopes over t in [t0, t1]: an array of `Float64Array`s [t, current, pins..., diffs...].
    /// Each run keeps the column (one replay for a run that did not yet), so that the next
    /// overlay of it replays none.
    #[wasm_bindgen(unchecked_return_type = "Float64Array[]")]
    pub fn overlay(
        &mut self,
        current: &mut Simulation,
        name: &str,
        t0: f64,
        t1: f64,
        buckets: u32,
    ) -> Result<Array, JsValue> {
        let ts = current.inner.scenario().ts;
        if let Some(p) = self.pins.iter().find(|p| p.scenario().ts != ts) {
            return Err(js_error(
                crate::text::Message::new("overlay-ts-differs")
                    .text("scenario", p.scenario().encode())
                    .real("pinned", p.scenario().ts)
                    .real("current", ts),
            ));
        }
        for s in std::iter::once(&mut current.inner).chain(&mut self.pins) {
            s.keep_column(name).map_err(js_error)?;
        }
        let others: Vec<&sim::Simulation> = self.pins.iter().collect();
        let cols = current
            .inner
            .overlay(&others, name, t0, t1, buckets as usize)
            .map_err(js_error)?;
        Ok(cols
            .iter()
            .map(|c| Float64Array::from(c.as_slice()))
            .collect())
    }
}

/// The measures of a finished run for judging a challenge: `{figures: [{name, value, unit,
/// settled}], not_finite: [{name, cause}], failure}` (`value` may be Infinity: a load never
/// recovered from; `not_finite` the figures with no number, each with why; `failure` a message
/// when the run failed or ran away, else null).
#[wasm_bindgen]
pub fn challenge_measure(sim: &Simulation) -> Result<Ts<crate::challenge::Measures>, JsValue> {
    to_js(&crate::challenge::measure(&sim.inner))
}
