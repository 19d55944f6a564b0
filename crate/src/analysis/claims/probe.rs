//! What a measurement reads from each run (a figure or a probe of the trace, with its times) and
//! how a sample's values become one number: the words of a table's `figure` and `statistic`.

use crate::record::figure_info;

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

    pub(super) fn reduce(self, values: &[f64]) -> f64 {
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
