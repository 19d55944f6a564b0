//! Model-error maps: a scenario run over a grid of one or two numeric fields, times the noise
//! seeds, to show how far a result holds when the model the EKF and controller use is not the
//! motor (a motor or model parameter), or how a design depends on its own choices (a gain, the
//! EKF's tuning, the flux target). The CLI (`imlab robust`), the page's workers and the tests share these
//! functions: [`Map::plan`] checks and bounds the grid before any run, [`map_run`] is one run of
//! one cell, [`summarise`] turns a cell's runs into its row and [`map_csv`] writes the rows.

use crate::record::WarningKind;
use crate::scenario::{Scenario, MAX_LAW_WORK, MAX_SEED};
use crate::sim::Simulation;
use crate::text::{excerpt, Arg, Message};
use serde::{Deserialize, Serialize};

mod table;
pub use table::{csv_preamble, csv_row, map_csv};

/// The figures a map keeps of each run, by their `imlab metrics` names.
pub const MAP_FIGURES: &[&str] = &[
    "tracking_rms",
    "tracking_peak",
    "speed_error_final",
    "speed_estimate_error_final",
    "flux_error_final",
    "current_peak",
    "saturated_share",
    "mean_nis",
];

/// Most points on one axis.
pub const MAX_POINTS: usize = 101;

/// Most seeds a map runs at each cell.
pub const MAX_MAP_SEEDS: u64 = 1000;

/// Most runs (cells × seeds) in one map: each run is a message and a result in the page's
/// workers, whatever its length.
pub const MAX_MAP_RUNS: usize = 100_000;

/// Most plant steps (samples × RK4 substeps) a whole map may take: 40 of the longest single runs
/// the codec accepts, a few minutes on each of two cores.
pub const MAX_MAP_WORK: u64 = 400_000_000;

/// Most operations of own laws (see [`Laws::work`](crate::control::law::Laws::work)) a whole map
/// may take: 40 of the costliest laws a single run accepts ([`MAX_LAW_WORK`]), as for the plant.
pub const MAX_MAP_LAW_WORK: u64 = 40 * MAX_LAW_WORK;

/// One axis of a map: a numeric field (a motor's `plant.*` or the model's `model.*` parameter, a
/// gain, the EKF's tuning…) and its values.
#[cfg_attr(
    target_arch = "wasm32",
    derive(tsify::Tsify),
    tsify(missing_as_null, hashmap_as_object)
)]
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub struct Axis {
    /// The scenario key, e.g. `plant.rr`.
    pub key: String,
    /// The axis as written, `KEY=LO..HI:N`, for the map's text.
    pub text: String,
    /// Whether LO and HI were relative errors (the axis is read in per cent of the other side).
    pub relative: bool,
    /// The axis in words for a plot, e.g. "plant.rr against the model (%)" or "model.j (kg m²)":
    /// the core's message; or, for a map that crossed the page on its way back to the core, the
    /// text the page said it as.
    #[cfg_attr(target_arch = "wasm32", tsify(type = "Message | string"))]
    pub label: Arg,
    /// The key's values, in order.
    pub values: Vec<f64>,
    /// Each value's relative error against its reference in the base scenario (for a `plant.*`
    /// key the model's value, for a `model.*` key the motor's, for any other key its own):
    /// value / reference − 1.
    pub errors: Vec<f64>,
}

/// One cell of a map: its values on each axis and the scenario that runs there.
#[cfg_attr(
    target_arch = "wasm32",
    derive(tsify::Tsify),
    tsify(missing_as_null, hashmap_as_object)
)]
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub struct CellPlan {
    /// The cell's place on each axis.
    pub index: Vec<usize>,
    /// The cell's value on each axis.
    pub values: Vec<f64>,
    /// The base scenario with those values and the map's first seed, as the codec writes it
    /// (each run replaces the seed by one of the map's seeds).
    pub scenario: String,
}

/// A checked map: its axes, its cells (the first axis varying slowest) and its seeds.
#[cfg_attr(
    target_arch = "wasm32",
    derive(tsify::Tsify),
    tsify(missing_as_null, hashmap_as_object, rename = "RobustMap")
)]
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub struct Map {
    /// The base scenario, as the codec writes it.
    pub scenario: String,
    /// One or two axes.
    pub axes: Vec<Axis>,
    /// The cells, the last axis varying fastest.
    pub cells: Vec<CellPlan>,
    /// The noise seeds run at every cell, in order.
    pub seeds: Vec<u64>,
    /// Plant steps the whole map takes.
    pub work: u64,
    /// Operations of own laws the whole map takes (0 without them).
    pub law_work: u64,
    /// The map as [`Map::parse`] reads it: `AXIS[;AXIS];seeds=A..B`.
    pub text: String,
}

/// One run of one cell: the figures of [`MAP_FIGURES`] (NaN where the run has none) and what
/// went wrong.
#[cfg_attr(
    target_arch = "wasm32",
    derive(tsify::Tsify),
    tsify(missing_as_null, hashmap_as_object)
)]
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub struct MapRun {
    /// The noise seed.
    pub seed: u64,
    /// The figures, in the order of [`MAP_FIGURES`].
    pub figures: Vec<f64>,
    /// The run ran away: it ended with the "runaway" warning, or the simulation stopped because
    /// a state diverged.
    pub ran_away: bool,
    /// The EKF's mean NIS was far outside a consistent filter's band (the "inconsistent"
    /// warning).
    pub inconsistent: bool,
    /// The peak stator current after the start-up transient passed the motor's rating.
    pub over_rating: bool,
    /// The final speed error had not settled by the end (still changing, drifting or
    /// fluctuating).
    pub unsettled: bool,
    /// Why the simulation stopped early, if it did.
    pub failure: Option<String>,
}

/// A cell's row: how many runs ran away or were inconsistent, and each figure's minimum,
/// median and maximum over the runs that completed.
#[cfg_attr(
    target_arch = "wasm32",
    derive(tsify::Tsify),
    tsify(missing_as_null, hashmap_as_object)
)]
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub struct Cell {
    /// The cell's place on each axis.
    pub index: Vec<usize>,
    /// The cell's value on each axis.
    pub values: Vec<f64>,
    /// The cell's scenario (see [`CellPlan::scenario`]).
    pub scenario: String,
    /// Runs (one a seed).
    pub runs: usize,
    /// Runs that ran away (see [`MapRun::ran_away`]).
    pub ran_away: usize,
    /// Runs whose filter was inconsistent.
    pub inconsistent: usize,
    /// Runs that did not run away but drew more than the motor's rated current after the
    /// start-up transient: what holding cost.
    pub over_rating: usize,
    /// Runs that did not run away but ended with the speed error not settled.
    pub unsettled: usize,
    /// Per figure of [`MAP_FIGURES`]: [minimum, median, maximum] over the runs that neither ran
    /// away nor stopped early and have the figure; NaN when none has.
    pub stats: Vec<[f64; 3]>,
}

/// The other side of a motor or model key (`plant.rr` ↔ `model.rr`), or None for other keys.
fn counterpart(key: &str) -> Option<String> {
    if let Some(name) = key.strip_prefix("plant.") {
        Some(format!("model.{name}"))
    } else {
        key.strip_prefix("model.")
            .map(|name| format!("plant.{name}"))
    }
}

/// The value and unit of numeric field `key` of `s`.
fn value_of(s: &Scenario, key: &str) -> Option<(f64, &'static str)> {
    let f = s.describe().into_iter().find(|f| f.key == key)?;
    Some((f.value?.parse().ok()?, f.unit))
}

/// One end of an axis (`end`, LO or HI, of the axis of `key`): a number, or a relative error in
/// per cent (`-10%`, `+5%`).
fn end(text: &str, key: &str, end: &'static str) -> Result<(f64, bool), Message> {
    let t = text.trim();
    let (number, relative) = match t.strip_suffix('%') {
        Some(n) => (n, true),
        None => (t, false),
    };
    let unsigned = number
        .strip_prefix('+')
        .filter(|n| !n.starts_with(['-', '+']));
    let v: f64 = unsigned
        .unwrap_or(number)
        .parse()
        .ok()
        .filter(|v: &f64| v.is_finite())
        .ok_or_else(|| {
            Message::new("map-axis-end")
                .text("key", excerpt(key))
                .text("end", end)
                .text("text", excerpt(text))
        })?;
    Ok((if relative { v / 100.0 } else { v }, relative))
}

impl Axis {
    /// Parses `KEY=LO..HI:N` against the base scenario `base`: N values evenly spaced from LO to
    /// HI of the numeric field KEY. LO and HI are both values of KEY or both relative errors in
    /// per cent against a reference in `base`: the other side's value for a motor or model
    /// parameter (`plant.rr=-10%..+10%:11`: the motor's R_r from 10 % below to 10 % above the
    /// model's), else KEY's own (`k1=-20%..+20%:5`). N = 1 takes LO alone. A field that takes
    /// whole numbers, a choice or a formula, or one that has no effect in `base` (a gain of the
    /// controller not chosen), is refused.
    pub fn parse(base: &Scenario, text: &str) -> Result<Axis, Message> {
        let axis = || excerpt(text);
        let form = || Message::new("map-axis-form").text("axis", axis());
        let (key, rest) = text.split_once('=').ok_or_else(form)?;
        let key = key.trim();
        let info = base
            .describe()
            .into_iter()
            .find(|f| f.key == key)
            .ok_or_else(|| {
                Message::new("map-axis-unknown")
                    .text("axis", axis())
                    .text("key", excerpt(key))
            })?;
        let refused = |id: &'static str| {
            Message::new(id)
                .text("axis", axis())
                .text("key", key.to_string())
        };
        if !info.options.is_empty() || info.formula.is_some() {
            return Err(refused("map-axis-not-numeric"));
        }
        if info.integer {
            return Err(refused("map-axis-whole"));
        }
        if !info.acts || info.value.is_none() {
            return Err(refused("map-axis-inactive"));
        }
        let other = counterpart(key);
        let reference_key = other.as_deref().unwrap_or(key);
        let (theirs, unit) =
            value_of(base, reference_key).ok_or_else(|| refused("map-axis-not-numeric"))?;
        let (range, count) = rest.rsplit_once(':').ok_or_else(form)?;
        let (lo, hi) = range.split_once("..").ok_or_else(form)?;
        let (lo_text, hi_text) = (lo.trim(), hi.trim());
        let (lo, lo_rel) = end(lo_text, key, "LO")?;
        let (hi, hi_rel) = end(hi_text, key, "HI")?;
        if lo_rel != hi_rel {
            return Err(refused("map-axis-mixed"));
        }
        let n: usize = count
            .trim()
            .parse()
            .ok()
            .filter(|n| (1..=MAX_POINTS).contains(n))
            .ok_or_else(|| {
                Message::new("map-axis-count")
                    .text("key", key.to_string())
                    .text("text", excerpt(count))
                    .count("max", MAX_POINTS)
            })?;
        if lo_rel && theirs == 0.0 {
            return Err(refused("map-axis-zero").text("other", reference_key.to_string()));
        }
        if lo > hi {
            return Err(Message::new("map-axis-order")
                .text("key", key.to_string())
                .text("lo", excerpt(lo_text))
                .text("hi", excerpt(hi_text)));
        }
        let at = |i: usize| {
            if n == 1 {
                lo
            } else {
                lo + (hi - lo) * i as f64 / (n - 1) as f64
            }
        };
        // A relative point's value is written as a user would type it (5.1975, not
        // 5.197500000000001), so a cell's scenario is the one its link names.
        let values: Vec<f64> = (0..n)
            .map(|i| {
                rounded(if lo_rel {
                    theirs * (1.0 + at(i))
                } else {
                    at(i)
                })
            })
            .collect();
        // Against a zero reference no relative error exists (NaN, an empty CSV field).
        let errors = values
            .iter()
            .map(|v| {
                if theirs == 0.0 {
                    f64::NAN
                } else {
                    rounded(v / theirs - 1.0)
                }
            })
            .collect();
        let against = if key.starts_with("plant.") {
            "map-axis-against-model"
        } else if key.starts_with("model.") {
            "map-axis-against-motor"
        } else {
            "map-axis-against-base"
        };
        let label = if lo_rel {
            Message::new(against).text("key", key.to_string()).into()
        } else if unit.is_empty() {
            Arg::Text(key.to_string())
        } else {
            Message::new("map-axis-unit")
                .text("key", key.to_string())
                .text("unit", unit)
                .into()
        };
        Ok(Axis {
            key: key.to_string(),
            text: format!("{key}={lo_text}..{hi_text}:{n}"),
            relative: lo_rel,
            label,
            values,
            errors,
        })
    }
}

/// `v` to 12 significant digits: the rounding of a product such as 4.95 × 1.05 removed.
pub(super) fn rounded(v: f64) -> f64 {
    format!("{v:.11e}").parse().unwrap_or(v)
}

/// Parses `A..B` (seeds A to B) or a single seed.
pub fn parse_seeds(text: &str) -> Result<Vec<u64>, Message> {
    let whole = |t: &str| {
        t.trim()
            .parse::<u64>()
            .ok()
            .filter(|s| *s <= MAX_SEED)
            .ok_or_else(|| {
                Message::new("map-seeds-form")
                    .text("seeds", excerpt(text))
                    .count("max", MAX_SEED)
            })
    };
    let (a, b) = match text.split_once("..") {
        Some((a, b)) => (whole(a)?, whole(b)?),
        None => {
            let s = whole(text)?;
            (s, s)
        }
    };
    if a > b {
        return Err(Message::new("map-seeds-order").text("seeds", excerpt(text)));
    }
    if b - a + 1 > MAX_MAP_SEEDS {
        return Err(Message::new("map-seeds-many")
            .text("seeds", excerpt(text))
            .count("count", b - a + 1)
            .count("max", MAX_MAP_SEEDS));
    }
    Ok((a..=b).collect())
}

impl Map {
    /// Checks a map of `base` over `axes` (one or two, of different keys) and `seeds`: every
    /// cell's scenario must be valid, and the whole map's work within [`MAX_MAP_WORK`] and
    /// [`MAX_MAP_LAW_WORK`]; refused
    /// before any run, with the number it would need.
    pub fn plan(base: &Scenario, axes: Vec<Axis>, seeds: Vec<u64>) -> Result<Map, Message> {
        if axes.is_empty() || axes.len() > 2 {
            return Err(Message::new("map-axes-count").count("count", axes.len()));
        }
        if axes.len() == 2 && axes[0].key == axes[1].key {
            return Err(Message::new("map-axes-repeated").text("key", axes[0].key.clone()));
        }
        if axes.len() == 2 && counterpart(&axes[0].key).as_ref() == Some(&axes[1].key) {
            return Err(Message::new("map-axes-sides")
                .text("first", axes[0].key.clone())
                .text("second", axes[1].key.clone()));
        }
        if seeds.is_empty() {
            return Err(Message::new("map-no-seeds"));
        }
        let shape: Vec<usize> = axes.iter().map(|a| a.values.len()).collect();
        let count: usize = shape.iter().product();
        if count * seeds.len() > MAX_MAP_RUNS {
            return Err(Message::new("map-runs-many")
                .count("runs", count * seeds.len())
                .count("cells", count)
                .count("seeds", seeds.len())
                .count("max", MAX_MAP_RUNS));
        }
        let mut cells = Vec::with_capacity(count);
        let (mut work, mut law_work, mut most_per_run) = (0u64, 0u64, 0u64);
        for index in 0..count {
            let mut s = base.clone();
            s.seed = seeds[0];
            let mut rest = index;
            let mut values = vec![0.0; axes.len()];
            let mut place = vec![0; axes.len()];
            for (k, axis) in axes.iter().enumerate().rev() {
                let i = rest % shape[k];
                rest /= shape[k];
                values[k] = axis.values[i];
                place[k] = i;
                s.set(&axis.key, &axis.values[i].to_string()).map_err(|e| {
                    Message::new("map-cell-refused")
                        .text("key", axis.key.clone())
                        .short("value", axis.values[i])
                        .said("reason", e.message())
                })?;
            }
            let runs = seeds.len() as u64;
            work = work.saturating_add(
                (s.steps() as u64)
                    .saturating_mul(s.plant_steps_per_sample())
                    .saturating_mul(runs),
            );
            // An axis may change the run's length, so each cell's laws are counted apart.
            let per_run = s.law_work().map_err(|e| e.message())?;
            most_per_run = most_per_run.max(per_run);
            law_work = law_work.saturating_add(per_run.saturating_mul(runs));
            cells.push(CellPlan {
                index: place,
                values,
                scenario: s.encode(),
            });
        }
        if work > MAX_MAP_WORK {
            return Err(Message::new("map-work")
                .count("work", work)
                .count("cells", count)
                .count("seeds", seeds.len())
                .count("max", MAX_MAP_WORK));
        }
        if law_work > MAX_MAP_LAW_WORK {
            return Err(Message::new("map-law-work")
                .count("work", law_work)
                .count("cells", count)
                .count("seeds", seeds.len())
                .count("per-run", most_per_run)
                .count("max", MAX_MAP_LAW_WORK)
                .count("runs", MAX_MAP_LAW_WORK / most_per_run));
        }
        let mut parts: Vec<String> = axes.iter().map(|a| a.text.clone()).collect();
        parts.push(format!("seeds={}..{}", seeds[0], seeds[seeds.len() - 1]));
        Ok(Map {
            scenario: base.encode(),
            text: parts.join(";"),
            axes,
            cells,
            seeds,
            work,
            law_work,
        })
    }

    /// Parses the map's text `AXIS[;AXIS][;seeds=A..B]` (AXIS as in [`Axis::parse`]; seeds 1..10
    /// when not given) against `base`, then checks it (see [`Map::plan`]).
    pub fn parse(base: &Scenario, text: &str) -> Result<Map, Message> {
        let parts = MapParts::split(text)?;
        Map::from_parts(base, &parts.axes, parts.seeds.as_deref())
    }

    /// The map of its parts as written (a form's): each axis's text (empty ones left out) and
    /// the seeds' `A..B` (1..10 when none), read against `base` and checked as [`Map::parse`]
    /// reads a map's text.
    pub fn from_parts(
        base: &Scenario,
        axes: &[String],
        seeds: Option<&str>,
    ) -> Result<Map, Message> {
        let axes = axes
            .iter()
            .filter(|a| !a.trim().is_empty())
            .map(|a| Axis::parse(base, a))
            .collect::<Result<Vec<_>, _>>()?;
        let seeds = match seeds {
            Some(range) => parse_seeds(range)?,
            None => (1..=10).collect(),
        };
        Map::plan(base, axes, seeds)
    }
}

/// A map's text in its parts, as written: the axes' texts and the seeds' `A..B`, if given.
#[cfg_attr(
    target_arch = "wasm32",
    derive(tsify::Tsify),
    tsify(missing_as_null, hashmap_as_object)
)]
#[derive(Clone, Debug, PartialEq, Serialize)]
pub struct MapParts {
    /// Each axis's text, in order.
    pub axes: Vec<String>,
    /// The seeds' range as written after `seeds=`, if given.
    pub seeds: Option<String>,
}

impl MapParts {
    /// Splits a map's text `AXIS[;AXIS…][;seeds=A..B]` at its `;`, reading no part but for
    /// seeds given twice.
    pub fn split(text: &str) -> Result<MapParts, Message> {
        let mut parts = MapParts {
            axes: Vec::new(),
            seeds: None,
        };
        for part in text.split(';').filter(|p| !p.trim().is_empty()) {
            match part.trim().strip_prefix("seeds=") {
                Some(_) if parts.seeds.is_some() => return Err(Message::new("map-seeds-twice")),
                Some(range) => parts.seeds = Some(range.to_string()),
                None => parts.axes.push(part.to_string()),
            }
        }
        Ok(parts)
    }
}

/// Runs cell scenario `scenario` (as the codec writes it) with noise seed `seed`.
pub fn map_run(scenario: &str, seed: u64) -> Result<MapRun, String> {
    let mut s = Scenario::parse(scenario).map_err(|e| e.to_string())?;
    s.seed = seed;
    let mut sim = Simulation::traced(&s).map_err(|e| e.to_string())?;
    let failure = sim.run().err().map(|e| e.to_string());
    let report = sim.report();
    let list = report.figures.unwrap_or_default();
    let figures = MAP_FIGURES
        .iter()
        .map(|name| {
            list.iter()
                .find(|f| f.name == *name)
                .map_or(f64::NAN, |f| f.value)
        })
        .collect();
    let warned = |kind: WarningKind| report.warnings.iter().any(|w| w.kind == kind);
    let value = |name: &str| list.iter().find(|f| f.name == name).map(|f| f.value);
    let over_rating = matches!(
        (value("current_peak"), value("current_rated")),
        (Some(peak), Some(rated)) if peak > rated
    );
    let unsettled = list
        .iter()
        .find(|f| f.name == "speed_error_final")
        .and_then(|f| f.trend.as_ref())
        .is_some_and(|t| !t.settled);
    Ok(MapRun {
        seed,
        figures,
        ran_away: failure.is_some() || warned(WarningKind::Runaway),
        inconsistent: warned(WarningKind::Inconsistent),
        over_rating,
        unsettled,
        failure,
    })
}

/// Minimum, median and maximum of `values` (NaN for none).
fn stats(mut values: Vec<f64>) -> [f64; 3] {
    if values.is_empty() {
        return [f64::NAN; 3];
    }
    values.sort_by(f64::total_cmp);
    let n = values.len();
    let median = if n % 2 == 1 {
        values[n / 2]
    } else {
        0.5 * (values[n / 2 - 1] + values[n / 2])
    };
    [values[0], median, values[n - 1]]
}

/// The row of `cell` from its runs (one a seed; their order does not matter).
pub fn summarise(cell: &CellPlan, runs: &[MapRun]) -> Cell {
    let done: Vec<&MapRun> = runs
        .iter()
        .filter(|r| r.failure.is_none() && !r.ran_away)
        .collect();
    Cell {
        index: cell.index.clone(),
        values: cell.values.clone(),
        scenario: cell.scenario.clone(),
        runs: runs.len(),
        ran_away: runs.iter().filter(|r| r.ran_away).count(),
        inconsistent: runs.iter().filter(|r| r.inconsistent).count(),
        over_rating: done.iter().filter(|r| r.over_rating).count(),
        unsettled: done.iter().filter(|r| r.unsettled).count(),
        stats: (0..MAP_FIGURES.len())
            .map(|k| {
                stats(
                    done.iter()
                        .map(|r| r.figures[k])
                        .filter(|v| v.is_finite())
                        .collect(),
                )
            })
            .collect(),
    }
}

#[cfg(test)]
mod tests;
