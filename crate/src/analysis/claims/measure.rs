//! One run measured: the scenario run with its seed, and each of its probes read from the
//! figures or from the recorded rows.

use super::probe::{Probe, Time, WindowKind};
use crate::inverter::Limit;
use crate::record::{is_saturated, Figure, Row, Samples, WarningKind};
use crate::scenario::Scenario;
use crate::sim::Simulation;

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
    if !nis.is_finite() {
        return Err("the mean NIS is not finite".to_string());
    }
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
