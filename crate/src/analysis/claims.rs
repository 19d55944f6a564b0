//! The measurements the teaching text states: each a figure of a scenario over a sample of noise
//! seeds, reduced by a statistic. The lessons name these measurements instead of typing numbers,
//! `imlab claims` computes them, and the tests recompute the table and fail on any difference.
//!
//! A table is CSV with the header `id,scenario,figure,seeds,statistic,show,value`:
//!
//! - `scenario`: a scenario string, or two joined by ` / ` for their ratio, seed by seed;
//! - `figure`: what is read from each run (see [`Probe`]);
//! - `seeds`: `A..B` (each run with noise seeds A to B), or `-` for the scenario's own seed;
//! - `statistic`: how the seeds' values become one number (see [`Statistic`]);
//! - `show`: how the text shows it (the page's business, kept as written);
//! - `value`: the measured number, in the shortest form that reads back to the same bits.

use crate::inverter::Limit;
use crate::record::{figure_info, is_saturated, Figure, Row, Samples, WarningKind};
use crate::scenario::Scenario;
use crate::sim::Simulation;
use std::collections::BTreeMap;

/// The header of a measurements table.
pub const HEADER: &str = "id,scenario,figure,seeds,statistic,show,value";

/// What one run gives a measurement.
#[derive(Clone, Debug, PartialEq)]
pub enum Probe {
    /// A figure of `imlab metrics` by its name (`tracking_rms`, `settling_time`, …), or
    /// `NAME_rate` / `NAME_settled` / `NAME_tolerance` for a final value's trend.
    Figure(String),
    /// 1 when the run ran away (or failed), else 0.
    RanAway,
    /// −1, 0 or 1 when the mean NIS after the start-up lies below, inside or above its 95 %
    /// band: `nis_side`.
    NisSide,
    /// 1 when figure NAME was reached (a step's settling time), else 0: `reached NAME`.
    Reached(String),
    /// A column at the first row at or after time T: `at COLUMN T`.
    At(String, Time),
    /// A statistic of a column over the rows with T0 ≤ t ≤ T1: `KIND COLUMN T0 T1`.
    Window(WindowKind, String, Time, Time),
    /// The time from T until |COLUMN − TARGET| stays within BAND to the end:
    /// `recovery COLUMN BAND T [TARGET]`, BAND and TARGET in the column's unit (TARGET 0 unless
    /// given), the result in seconds (infinite when it is outside at the last row).
    Recovery(String, f64, Time, f64),
}

/// A time in a probe: seconds, `transient` (the end of the start-up transient, where the figures
/// strip's window starts) or `end` (the last row).
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Time {
    /// Seconds from the start.
    At(f64),
    /// The end of the start-up transient.
    Transient,
    /// The last recorded row.
    End,
}

/// How a window probe reduces its rows.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum WindowKind {
    /// Arithmetic mean.
    Mean,
    /// Root mean square.
    Rms,
    /// Standard deviation about the mean.
    Sd,
    /// Largest value.
    Max,
    /// Smallest value.
    Min,
    /// Largest magnitude.
    MaxAbs,
    /// The share of the mean square that the mean carries: mean² / (mean² + sd²).
    MeanShare,
}

/// How the values of the runs over the sample become one number.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Statistic {
    /// The smallest.
    Min,
    /// The largest.
    Max,
    /// The mean.
    Mean,
    /// The sum (with a 0/1 probe: on how many runs it holds).
    Sum,
    /// On how many runs the value is below the bound: `count<X`.
    Below(f64),
    /// On how many runs the value is above the bound: `count>X`.
    Above(f64),
}

/// One row of a table: a measurement and, once taken, its value.
#[derive(Clone, Debug, PartialEq)]
pub struct Measurement {
    /// The name the text uses.
    pub id: String,
    /// The scenario strings as written (two for a ratio).
    pub scenarios: Vec<String>,
    /// The scenario column as written.
    pub scenario_text: String,
    /// The figure column as written.
    pub figure_text: String,
    /// What each run gives.
    pub probe: Probe,
    /// The noise seeds, or None for the scenario's own.
    pub seeds: Option<std::ops::RangeInclusive<u64>>,
    /// The seeds column as written.
    pub seeds_text: String,
    /// How the runs' values become one.
    pub statistic: Statistic,
    /// The statistic column as written.
    pub statistic_text: String,
    /// How the text shows it, as written.
    pub show: String,
    /// The value column as written (empty before the first measurement).
    pub value: String,
}

/// Most runs one measurement may take: a sample of seeds is for the text's ranges, not a study.
const MAX_SEEDS: u64 = 200;

fn parse_time(word: &str) -> Result<Time, String> {
    match word {
        "transient" => Ok(Time::Transient),
        "end" => Ok(Time::End),
        _ => word
            .parse::<f64>()
            .ok()
            .filter(|t| t.is_finite() && *t >= 0.0)
            .map(Time::At)
            .ok_or_else(|| {
                format!("'{word}' is not a time: expected seconds ≥ 0, 'transient' or 'end'")
            }),
    }
}

fn column_known(name: &str) -> Result<String, String> {
    if name == "i_s" || name == "clipped" || crate::record::COLUMNS.contains(&name) {
        Ok(name.to_string())
    } else {
        Err(format!(
            "'{name}' is not a column: expected one of `imlab run`'s columns, i_s or clipped"
        ))
    }
}

impl Probe {
    /// Reads a probe as the figure column writes it.
    pub fn parse(text: &str) -> Result<Probe, String> {
        let words: Vec<&str> = text.split_whitespace().collect();
        let number = |w: &str| {
            w.parse::<f64>()
                .ok()
                .filter(|v| v.is_finite())
                .ok_or_else(|| format!("'{w}' is not a number"))
        };
        let window = |kind| -> Result<Probe, String> {
            match words[1..] {
                [c, t0, t1] => Ok(Probe::Window(
                    kind,
                    column_known(c)?,
                    parse_time(t0)?,
                    parse_time(t1)?,
                )),
                _ => Err(format!("'{text}': expected '{} COLUMN T0 T1'", words[0])),
            }
        };
        match words.as_slice() {
            ["ran_away"] => Ok(Probe::RanAway),
            ["nis_side"] => Ok(Probe::NisSide),
            ["reached", name] => figure_info(name)
                .map(|_| Probe::Reached((*name).to_string()))
                .ok_or_else(|| format!("'{name}' is not a figure of `imlab metrics`")),
            ["at", c, t] => Ok(Probe::At(column_known(c)?, parse_time(t)?)),
            ["recovery", c, band, t] => Ok(Probe::Recovery(
                column_known(c)?,
                number(band)?,
                parse_time(t)?,
                0.0,
            )),
            ["recovery", c, band, t, target] => Ok(Probe::Recovery(
                column_known(c)?,
                number(band)?,
                parse_time(t)?,
                number(target)?,
            )),
            ["mean", ..] => window(WindowKind::Mean),
            ["rms", ..] => window(WindowKind::Rms),
            ["sd", ..] => window(WindowKind::Sd),
            ["max", ..] => window(WindowKind::Max),
            ["min", ..] => window(WindowKind::Min),
            ["maxabs", ..] => window(WindowKind::MaxAbs),
            ["mean_share", ..] => window(WindowKind::MeanShare),
            [name] => {
                let base = name
                    .strip_suffix("_rate")
                    .or_else(|| name.strip_suffix("_settled"))
                    .or_else(|| name.strip_suffix("_tolerance"))
                    .unwrap_or(name);
                figure_info(base)
                    .map(|_| Probe::Figure((*name).to_string()))
                    .ok_or_else(|| {
                        format!("'{name}' is not a figure of `imlab metrics` or a probe")
                    })
            }
            _ => Err(format!("'{text}' is not a figure or a probe")),
        }
    }
}

impl Statistic {
    /// Reads a statistic as its column writes it.
    pub fn parse(text: &str) -> Result<Statistic, String> {
        let bound = |rest: &str| {
            rest.parse::<f64>()
                .ok()
                .filter(|v| v.is_finite())
                .ok_or_else(|| format!("'{text}': the bound '{rest}' is not a number"))
        };
        match text {
            "min" => Ok(Statistic::Min),
            "max" => Ok(Statistic::Max),
            "mean" => Ok(Statistic::Mean),
            "sum" => Ok(Statistic::Sum),
            _ => {
                if let Some(rest) = text.strip_prefix("count<") {
                    Ok(Statistic::Below(bound(rest)?))
                } else if let Some(rest) = text.strip_prefix("count>") {
                    Ok(Statistic::Above(bound(rest)?))
                } else {
                    Err(format!(
                        "'{text}' is not a statistic: expected min, max, mean, sum, count<X or count>X"
                    ))
                }
            }
        }
    }

    fn reduce(self, values: &[f64]) -> f64 {
        match self {
            Statistic::Min => values.iter().copied().fold(f64::INFINITY, f64::min),
            Statistic::Max => values.iter().copied().fold(f64::NEG_INFINITY, f64::max),
            Statistic::Mean => values.iter().sum::<f64>() / values.len() as f64,
            Statistic::Sum => values.iter().sum(),
            Statistic::Below(x) => values.iter().filter(|&&v| v < x).count() as f64,
            Statistic::Above(x) => values.iter().filter(|&&v| v > x).count() as f64,
        }
    }
}

fn parse_seeds(text: &str) -> Result<Option<std::ops::RangeInclusive<u64>>, String> {
    if text == "-" {
        return Ok(None);
    }
    let bad = || format!("'{text}' is not a sample: expected A..B (seeds A to B) or -");
    let (a, b) = text.split_once("..").ok_or_else(bad)?;
    let (a, b) = (
        a.parse::<u64>().map_err(|_| bad())?,
        b.parse::<u64>().map_err(|_| bad())?,
    );
    if a > b || b - a >= MAX_SEEDS {
        return Err(format!(
            "'{text}': expected 1 to {MAX_SEEDS} seeds, the first no larger than the last"
        ));
    }
    Ok(Some(a..=b))
}

/// Reads a measurements table; an error names the line and the field at fault.
pub fn parse_table(text: &str) -> Result<Vec<Measurement>, String> {
    let mut lines = text.lines().enumerate();
    match lines.next() {
        Some((_, h)) if h == HEADER => {}
        Some((_, h)) => {
            return Err(format!(
                "line 1 is '{}': expected the header '{HEADER}'",
                crate::quote::excerpt(h)
            ))
        }
        None => {
            return Err(format!(
                "the table is empty: expected the header '{HEADER}'"
            ))
        }
    }
    let mut out: Vec<Measurement> = Vec::new();
    for (i, line) in lines {
        if line.trim().is_empty() {
            continue;
        }
        let at = |e: String| format!("line {}: {e}", i + 1);
        let cells: Vec<&str> = line.split(',').collect();
        let [id, scenario, figure, seeds, statistic, show, value] = cells[..] else {
            return Err(at(format!("{} fields, expected 7", cells.len())));
        };
        if id.is_empty()
            || !id
                .chars()
                .all(|c| c.is_ascii_alphanumeric() || "._".contains(c))
        {
            return Err(at(format!(
                "the id '{id}' must be letters, digits, '.' or '_'"
            )));
        }
        if out.iter().any(|m| m.id == id) {
            return Err(at(format!("the id '{id}' is already used")));
        }
        let scenarios: Vec<String> = scenario.split(" / ").map(str::to_string).collect();
        if scenarios.len() > 2 {
            return Err(at(
                "a scenario is one string or the ratio of two".to_string()
            ));
        }
        for s in &scenarios {
            Scenario::parse(s).map_err(|e| at(format!("scenario '{s}': {e}")))?;
        }
        out.push(Measurement {
            id: id.to_string(),
            scenarios,
            scenario_text: scenario.to_string(),
            figure_text: figure.to_string(),
            probe: Probe::parse(figure).map_err(at)?,
            seeds: parse_seeds(seeds).map_err(at)?,
            seeds_text: seeds.to_string(),
            statistic: Statistic::parse(statistic).map_err(at)?,
            statistic_text: statistic.to_string(),
            show: show.to_string(),
            value: value.to_string(),
        });
    }
    Ok(out)
}

/// One run a table needs: a scenario string with a seed (None: its own).
pub type RunKey = (String, Option<u64>);

/// The runs `table` needs, each once, with the probes read from each.
pub fn runs_of(table: &[Measurement]) -> BTreeMap<RunKey, Vec<Probe>> {
    let mut runs: BTreeMap<RunKey, Vec<Probe>> = BTreeMap::new();
    for m in table {
        let seeds: Vec<Option<u64>> = match &m.seeds {
            Some(r) => r.clone().map(Some).collect(),
            None => vec![None],
        };
        for s in &m.scenarios {
            for seed in &seeds {
                let probes = runs.entry((s.clone(), *seed)).or_default();
                if !probes.contains(&m.probe) {
                    probes.push(m.probe.clone());
                }
            }
        }
    }
    runs
}

/// What one run gave each of its probes (Err: the probe has no value on this run, and why).
pub type RunValues = Vec<(Probe, Result<f64, String>)>;

/// An accumulator of a window or time probe over the rows.
struct Reading {
    probe: Probe,
    column: String,
    t0: f64,
    t1: f64,
    n: f64,
    sum: f64,
    sum_sq: f64,
    min: f64,
    max: f64,
    max_abs: f64,
    first: Option<f64>,
    /// For a recovery: the time of the row after the last one outside the band, and whether the
    /// last row was outside.
    back: f64,
    outside_at_end: bool,
    /// A row of its window held a value that is not finite.
    not_finite: bool,
}

fn column_value(name: &str, row: &Row, limit: &Limit) -> f64 {
    match name {
        // As the figures compute it, so that a window probe and `current_peak` agree to the bit.
        "i_s" => (row.i_sa * row.i_sa + row.i_sb * row.i_sb).sqrt(),
        "clipped" => f64::from(u8::from(is_saturated(row, limit))),
        _ => {
            let i = crate::record::COLUMNS
                .iter()
                .position(|c| *c == name)
                .expect("a column checked when parsed");
            row.get(i)
        }
    }
}

impl Reading {
    /// A reading of `probe` over [t0, t1] (None for a probe that reads no rows).
    fn new(probe: &Probe, time: &dyn Fn(Time) -> f64) -> Option<Reading> {
        let (column, t0, t1) = match probe {
            Probe::At(c, t) => (c, time(*t), f64::INFINITY),
            Probe::Window(_, c, t0, t1) => (c, time(*t0), time(*t1)),
            Probe::Recovery(c, _, t, _) => (c, time(*t), f64::INFINITY),
            _ => return None,
        };
        Some(Reading {
            probe: probe.clone(),
            column: column.clone(),
            t0,
            t1,
            n: 0.0,
            sum: 0.0,
            sum_sq: 0.0,
            min: f64::INFINITY,
            max: f64::NEG_INFINITY,
            max_abs: 0.0,
            first: None,
            back: f64::NAN,
            outside_at_end: false,
            not_finite: false,
        })
    }

    /// Takes value `v` of the row at time `t`, one of its window's.
    fn take(&mut self, t: f64, v: f64) {
        self.not_finite |= !v.is_finite();
        if self.first.is_none() {
            self.first = Some(v);
        }
        self.n += 1.0;
        self.sum += v;
        self.sum_sq += v * v;
        self.min = self.min.min(v);
        self.max = self.max.max(v);
        self.max_abs = self.max_abs.max(v.abs());
        if let Probe::Recovery(_, band, _, target) = self.probe {
            // A value that is not finite is outside any band.
            let outside = v.is_nan() || (v - target).abs() > band;
            if outside {
                self.back = f64::NAN;
            } else if self.back.is_nan() {
                self.back = t;
            }
            self.outside_at_end = outside;
        }
    }

    /// The probe's value over the rows taken.
    fn value(&self) -> Result<f64, String> {
        if self.n == 0.0 {
            return Err("no recorded row in its window".to_string());
        }
        if self.not_finite {
            return Err(format!("{} is not finite in its window", self.column));
        }
        let mean = self.sum / self.n;
        let var = (self.sum_sq / self.n - mean * mean).max(0.0);
        Ok(match self.probe {
            Probe::At(..) => self.first.expect("a row was read"),
            Probe::Recovery(..) if self.outside_at_end => f64::INFINITY,
            Probe::Recovery(..) => (self.back - self.t0).max(0.0),
            Probe::Window(kind, ..) => match kind {
                WindowKind::Mean => mean,
                WindowKind::Rms => (self.sum_sq / self.n).sqrt(),
                WindowKind::Sd => var.sqrt(),
                WindowKind::Max => self.max,
                WindowKind::Min => self.min,
                WindowKind::MaxAbs => self.max_abs,
                WindowKind::MeanShare => mean * mean / (self.sum_sq / self.n),
            },
            _ => unreachable!("row probes only"),
        })
    }
}

/// Figure `name` of a run's figures, or `NAME_rate` / `NAME_settled` / `NAME_tolerance` of a
/// final value's trend.
fn figure_value(figures: &[Figure], name: &str) -> Result<f64, String> {
    let (base, part) = if let Some(b) = name.strip_suffix("_rate") {
        (b, 1)
    } else if let Some(b) = name.strip_suffix("_settled") {
        (b, 2)
    } else if let Some(b) = name.strip_suffix("_tolerance") {
        (b, 3)
    } else {
        (name, 0)
    };
    let f = figures
        .iter()
        .find(|f| f.name == base)
        .ok_or_else(|| format!("the run has no figure {base}"))?;
    match (part, &f.trend) {
        (0, _) => Ok(f.value),
        (1, Some(t)) => Ok(t.rate),
        (2, Some(t)) => Ok(f64::from(u8::from(t.settled))),
        (3, Some(t)) => Ok(t.tolerance),
        _ => Err(format!("{base} is not a final value, so it has no trend")),
    }
}

/// −1, 0 or 1 as the mean NIS lies below, inside or above its 95 % band.
fn nis_side(figures: &[Figure]) -> Result<f64, String> {
    let nis = figure_value(figures, "mean_nis")?;
    Ok(if nis < figure_value(figures, "mean_nis_low")? {
        -1.0
    } else if nis > figure_value(figures, "mean_nis_high")? {
        1.0
    } else {
        0.0
    })
}

/// Runs `scenario` with `seed` (None: its own) and reads every probe of `probes` from it.
pub fn measure_run(
    scenario: &str,
    seed: Option<u64>,
    probes: &[Probe],
) -> Result<RunValues, String> {
    let mut s = Scenario::parse(scenario).map_err(|e| e.to_string())?;
    if let Some(seed) = seed {
        s.seed = seed;
    }
    let mut sim = Simulation::traced(&s).map_err(|e| e.to_string())?;
    let failure = sim.run().err().map(|e| e.to_string());
    let report = sim.report();
    let ran_away = failure.is_some()
        || report
            .warnings
            .iter()
            .any(|w| w.kind == WarningKind::Runaway);
    let len = sim.count();
    let transient = report.transient.t;
    let end = if len > 0 { sim.time(len - 1) } else { 0.0 };
    let time = |t: Time| match t {
        Time::At(v) => v,
        Time::Transient => transient,
        Time::End => end,
    };
    let mut readings: Vec<Reading> = probes
        .iter()
        .filter_map(|p| Reading::new(p, &time))
        .collect();
    if !readings.is_empty() && len > 0 {
        // Half a sample of slack, so that a time written in the text's decimals finds its row.
        let slack = 0.5 * s.ts;
        let limit = s.limit();
        let from = readings.iter().map(|r| r.t0).fold(f64::INFINITY, f64::min);
        let first = sim.first_at(from - slack);
        sim.visit(first, len, &mut |_, row| {
            for r in &mut readings {
                if row.t >= r.t0 - slack && row.t <= r.t1 + slack {
                    r.take(row.t, column_value(&r.column, row, &limit));
                }
            }
            true
        });
    }
    let figures = report.figures.unwrap_or_default();
    let values = probes
        .iter()
        .map(|p| {
            let v = match p {
                Probe::Figure(name) => figure_value(&figures, name),
                Probe::RanAway => Ok(f64::from(u8::from(ran_away))),
                Probe::NisSide => nis_side(&figures),
                Probe::Reached(name) => {
                    Ok(f64::from(u8::from(figures.iter().any(|f| f.name == name))))
                }
                _ => readings
                    .iter()
                    .find(|r| r.probe == *p)
                    .expect("a reading for each row probe")
                    .value(),
            };
            (p.clone(), v)
        })
        .collect();
    Ok(values)
}

/// How a table's runs are looked up: the values of one run by its scenario and seed.
pub type RunLookup<'a> = dyn Fn(&str, Option<u64>) -> Result<RunValues, String> + 'a;

/// The value of measurement `m` from the values of its runs (`of(scenario, seed)` gives a run's
/// values); an error names the seed and scenario where the probe had no value.
pub fn value_of(m: &Measurement, of: &RunLookup) -> Result<f64, String> {
    let seeds: Vec<Option<u64>> = match &m.seeds {
        Some(r) => r.clone().map(Some).collect(),
        None => vec![None],
    };
    let at = |s: &str, seed: Option<u64>, e: String| match seed {
        Some(k) => format!("{s} on seed {k}: {e}"),
        None => format!("{s}: {e}"),
    };
    let read = |s: &str, seed: Option<u64>| -> Result<f64, String> {
        let values = of(s, seed).map_err(|e| at(s, seed, e))?;
        let (_, v) = values
            .iter()
            .find(|(p, _)| *p == m.probe)
            .expect("every probe of the run is read");
        let v = v.clone().map_err(|e| at(s, seed, e))?;
        // A count may read a figure that is infinite (a recovery that never came); no other
        // statistic, and no value at all, may be NaN.
        let counted = matches!(m.statistic, Statistic::Below(_) | Statistic::Above(_));
        if v.is_nan() || (v.is_infinite() && !counted) {
            return Err(at(s, seed, format!("{} is {}", m.figure_text, written(v))));
        }
        Ok(v)
    };
    let mut values = Vec::with_capacity(seeds.len());
    for seed in seeds {
        let v = match m.scenarios.as_slice() {
            [a] => read(a, seed)?,
            [a, b] => read(a, seed)? / read(b, seed)?,
            _ => unreachable!("one scenario or two"),
        };
        values.push(v);
    }
    let value = m.statistic.reduce(&values);
    if value.is_finite() {
        Ok(value)
    } else {
        Err(format!("its {} is {}", m.statistic_text, written(value)))
    }
}

/// Measures every row of `table` on `threads` threads (each run once, however many rows read it),
/// calling `progress(done, total)` after each run; a row's Err names why it has no value.
pub fn measure_table(
    table: &[Measurement],
    threads: usize,
    progress: &(dyn Fn(usize, usize) + Sync),
) -> Vec<Result<f64, String>> {
    use std::sync::atomic::{AtomicUsize, Ordering};
    use std::sync::Mutex;
    let runs: Vec<(RunKey, Vec<Probe>)> = runs_of(table).into_iter().collect();
    let results: Vec<Mutex<Option<Result<RunValues, String>>>> =
        runs.iter().map(|_| Mutex::new(None)).collect();
    let next = AtomicUsize::new(0);
    let done = AtomicUsize::new(0);
    std::thread::scope(|scope| {
        for _ in 0..threads.max(1) {
            scope.spawn(|| loop {
                let i = next.fetch_add(1, Ordering::Relaxed);
                let Some(((scenario, seed), probes)) = runs.get(i) else {
                    break;
                };
                let values = measure_run(scenario, *seed, probes);
                *results[i].lock().expect("no thread panics holding it") = Some(values);
                progress(done.fetch_add(1, Ordering::Relaxed) + 1, runs.len());
            });
        }
    });
    let by_key: BTreeMap<&RunKey, Result<RunValues, String>> = runs
        .iter()
        .zip(results)
        .map(|((key, _), r)| {
            let values = r
                .into_inner()
                .expect("no thread panics holding it")
                .expect("every run measured");
            (key, values)
        })
        .collect();
    let of = |s: &str, seed: Option<u64>| -> Result<RunValues, String> {
        by_key[&(s.to_string(), seed)].clone()
    };
    table.iter().map(|m| value_of(m, &of)).collect()
}

/// A measured value as the table writes it: the shortest form that reads back to the same bits.
pub fn written(value: f64) -> String {
    if value.is_nan() {
        "NaN".to_string()
    } else if value.is_infinite() {
        if value > 0.0 { "inf" } else { "-inf" }.to_string()
    } else if value != 0.0 && !(1e-4..1e15).contains(&value.abs()) {
        format!("{value:e}")
    } else {
        format!("{value}")
    }
}

/// The row of `m` as the table writes it, with `value`.
pub fn table_line(m: &Measurement, value: &str) -> String {
    format!(
        "{},{},{},{},{},{},{}",
        m.id, m.scenario_text, m.figure_text, m.seeds_text, m.statistic_text, m.show, value
    )
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_table_names_its_bad_field() {
        let head = format!("{HEADER}\n");
        let bad = |line: &str| parse_table(&format!("{head}{line}")).unwrap_err();
        assert!(bad("a,v=1&preset=step,nope,1..30,min,,").contains("'nope'"));
        assert!(bad("a,v=1&preset=step,tracking_rms,1..30,median,,").contains("'median'"));
        assert!(bad("a,v=1&preset=step,tracking_rms,30..1,min,,").contains("'30..1'"));
        assert!(bad("a,v=1&preset=nope,tracking_rms,1..3,min,,").contains("line 2"));
        assert!(bad("a,v=1&preset=step,at omega 0.1,1..3,min,").contains("6 fields"));
        assert!(bad("a,v=1&preset=step,at speed 0.1,1..3,min,,").contains("'speed'"));
        let twice = "a,v=1&preset=step,tracking_rms,1..3,min,,\n";
        assert!(parse_table(&format!("{head}{twice}{twice}"))
            .unwrap_err()
            .contains("already used"));
    }

    #[test]
    fn statistics_reduce_as_named() {
        let v = [3.0, 1.0, 2.0];
        assert_eq!(Statistic::Min.reduce(&v), 1.0);
        assert_eq!(Statistic::Max.reduce(&v), 3.0);
        assert_eq!(Statistic::Mean.reduce(&v), 2.0);
        assert_eq!(Statistic::Sum.reduce(&v), 6.0);
        assert_eq!(Statistic::Below(2.0).reduce(&v), 1.0);
        assert_eq!(Statistic::Above(1.5).reduce(&v), 2.0);
    }

    #[test]
    fn a_value_is_written_to_read_back_to_its_bits() {
        for v in [0.1 + 0.2, 1e-300, 4.7e-3, -25.4, 3.0] {
            assert_eq!(written(v).parse::<f64>().unwrap().to_bits(), v.to_bits());
        }
        assert_eq!(written(f64::INFINITY), "inf");
    }

    /// The values of `probes` (as the figure column writes them) on `scenario`'s own seed.
    fn read(scenario: &str, probes: &[&str]) -> Vec<f64> {
        let probes: Vec<Probe> = probes.iter().map(|p| Probe::parse(p).unwrap()).collect();
        measure_run(scenario, None, &probes)
            .unwrap()
            .into_iter()
            .map(|(_, v)| v.unwrap())
            .collect()
    }

    #[test]
    fn a_recovery_reads_the_step_filters_settling_time() {
        // The critically damped filter's step response is 1 − (1 + ωn·t)·e^(−ωn·t): it stays
        // within 2 % from ωn·t = 5.8335 on, 4.642 ms at the step preset's ωn = 2π·200 /s; the
        // first 50 µs sample after that is 4.65 ms past the step.
        const WN: f64 = 2.0 * std::f64::consts::PI * 200.0;
        let t = 5.833_5 / WN;
        let sample = (t / 50e-6).ceil() * 50e-6;
        let [recovery] = read("v=1&preset=step", &["recovery omega_ref 0.01 0.05 0.5"])[..] else {
            unreachable!()
        };
        assert!(
            (recovery - sample).abs() < 1e-9,
            "{recovery} against {sample}"
        );
    }

    #[test]
    fn window_probes_agree_with_the_figures_over_the_strips_window() {
        let run = "v=1&preset=sine200-1rad";
        let v = read(
            run,
            &[
                "max i_s transient end",
                "current_peak",
                "mean clipped transient end",
                "saturated_share",
                "rms omega_err transient end",
                "tracking_rms",
                "at omega_ref 0",
            ],
        );
        assert_eq!(v[0], v[1], "peak |i_s|");
        assert!(
            (v[2] - v[3]).abs() < 1e-12,
            "share at the limit {} against {}",
            v[2],
            v[3]
        );
        assert!(
            (v[4] - v[5]).abs() < 1e-9 * v[5],
            "tracking RMS {} against {}",
            v[4],
            v[5]
        );
        assert_eq!(v[6], 0.0, "a sine reference starts at 0");
    }

    #[test]
    fn nis_side_reads_the_mean_nis_against_its_band() {
        // The Euler EKF at 200 Hz lies far above its band; the step's filter inside or near it.
        for (run, expect) in [("v=1&preset=sine200", Some(1.0)), ("v=1&preset=step", None)] {
            let v = read(
                run,
                &["nis_side", "mean_nis", "mean_nis_low", "mean_nis_high"],
            );
            let side = if v[1] < v[2] {
                -1.0
            } else if v[1] > v[3] {
                1.0
            } else {
                0.0
            };
            assert_eq!(v[0], side, "{run}: {v:?}");
            if let Some(e) = expect {
                assert_eq!(v[0], e, "{run}");
            }
        }
    }
}
