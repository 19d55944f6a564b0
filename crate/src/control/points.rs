//! A short table of points (t, value), straight between them and held before the first and after
//! the last: a speed reference or a load torque written in a link as `t:value,t:value,...`.

use serde::{Deserialize, Serialize};

/// Most points a table holds: enough for a test cycle of runs, holds and reversals, and few enough
/// that a lookup per sample costs no more than a few comparisons.
pub const MAX_POINTS: usize = 16;

/// Up to [`MAX_POINTS`] points with strictly rising times, kept inline so that a reference stays
/// `Copy` and a run never allocates to read it.
#[derive(Clone, Copy, Debug, PartialEq, Serialize, Deserialize)]
pub struct Points {
    len: u8,
    t: [f64; MAX_POINTS],
    v: [f64; MAX_POINTS],
}

/// Why a table's text was refused.
#[derive(Clone, Debug, PartialEq)]
pub enum PointsError {
    /// A piece that is not `t:value` with two plain numbers.
    Syntax,
    /// More points than [`MAX_POINTS`].
    TooMany {
        /// Points given.
        count: usize,
    },
    /// A time that does not come after the one before it.
    NotRising {
        /// The earlier time (s).
        before: f64,
        /// The time that should have come after it (s).
        after: f64,
    },
}

impl Points {
    /// No points.
    pub const EMPTY: Points = Points {
        len: 0,
        t: [0.0; MAX_POINTS],
        v: [0.0; MAX_POINTS],
    };

    /// The table of `pairs` (t, value), whose times must rise strictly.
    pub fn new(pairs: &[(f64, f64)]) -> Result<Points, PointsError> {
        if pairs.len() > MAX_POINTS {
            return Err(PointsError::TooMany { count: pairs.len() });
        }
        let mut p = Points::EMPTY;
        for (i, &(t, v)) in pairs.iter().enumerate() {
            if i > 0 && t <= p.t[i - 1] {
                return Err(PointsError::NotRising {
                    before: p.t[i - 1],
                    after: t,
                });
            }
            p.t[i] = t;
            p.v[i] = v;
        }
        p.len = pairs.len() as u8;
        Ok(p)
    }

    /// Reads `t:value,t:value,...`: every number plain (as a link's numbers are), the times rising.
    /// An empty text is the empty table.
    pub fn parse(text: &str) -> Result<Points, PointsError> {
        if text.is_empty() {
            return Ok(Points::EMPTY);
        }
        let pieces: Vec<&str> = text.split(',').collect();
        if pieces.len() > MAX_POINTS {
            return Err(PointsError::TooMany {
                count: pieces.len(),
            });
        }
        let mut pairs = Vec::with_capacity(pieces.len());
        for piece in pieces {
            let (t, v) = piece.split_once(':').ok_or(PointsError::Syntax)?;
            let number = |s: &str| crate::scenario::parse_number(s).filter(|x| x.is_finite());
            pairs.push((
                number(t).ok_or(PointsError::Syntax)?,
                number(v).ok_or(PointsError::Syntax)?,
            ));
        }
        Points::new(&pairs)
    }

    /// The table as a link writes it, each number in its shortest round-trip form.
    pub fn encode(&self) -> String {
        self.pairs()
            .map(|(t, v)| format!("{t}:{v}"))
            .collect::<Vec<_>>()
            .join(",")
    }

    /// Whether it holds no points.
    pub fn is_empty(&self) -> bool {
        self.len == 0
    }

    /// Its points (t, value), in order.
    pub fn pairs(&self) -> impl Iterator<Item = (f64, f64)> + '_ {
        let n = self.len as usize;
        self.t[..n].iter().copied().zip(self.v[..n].iter().copied())
    }

    /// The value at time `t` and its slope: the first value before the first point, the last
    /// after the last, straight in between (0 for the empty table). At a point the segment that
    /// starts there holds.
    #[inline]
    pub fn sample(&self, t: f64) -> (f64, f64) {
        let n = self.len as usize;
        if n == 0 {
            return (0.0, 0.0);
        }
        if t < self.t[0] {
            return (self.v[0], 0.0);
        }
        for i in 1..n {
            if t < self.t[i] {
                let (dv, dt) = (self.v[i] - self.v[i - 1], self.t[i] - self.t[i - 1]);
                // The value by the fraction of the segment gone, finite however steep the segment.
                return (self.v[i - 1] + dv * ((t - self.t[i - 1]) / dt), dv / dt);
            }
        }
        (self.v[n - 1], 0.0)
    }

    /// The first point after time `after` from which the value changes (a corner where a ramp
    /// or a hold begins), or None when none does.
    pub fn first_change_after(&self, after: f64) -> Option<f64> {
        let n = self.len as usize;
        (1..n)
            .find(|&i| self.v[i] != self.v[i - 1] && self.t[i - 1] > after)
            .map(|i| self.t[i - 1])
    }
}

impl Default for Points {
    fn default() -> Self {
        Points::EMPTY
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn parses_writes_and_samples_a_table() {
        let p = Points::parse("0:0,0.1:100,0.3:100,0.5:-100").unwrap();
        assert_eq!(p.encode(), "0:0,0.1:100,0.3:100,0.5:-100");
        assert_eq!(Points::parse(&p.encode()).unwrap(), p);
        assert_eq!(p.sample(-1.0), (0.0, 0.0));
        assert_eq!(p.sample(0.05), (50.0, 1000.0));
        assert_eq!(p.sample(0.2), (100.0, 0.0));
        let (v, slope) = p.sample(0.4);
        assert!(v.abs() < 1e-12 && slope == -1000.0, "{v} {slope}");
        assert_eq!(p.sample(0.5), (-100.0, 0.0));
        assert_eq!(p.sample(9.0), (-100.0, 0.0));
        assert_eq!(Points::parse("").unwrap(), Points::EMPTY);
        assert_eq!(Points::EMPTY.sample(1.0), (0.0, 0.0));
    }

    #[test]
    fn refuses_bad_tables_with_the_reason() {
        assert_eq!(Points::parse("0:0,0.1"), Err(PointsError::Syntax));
        assert_eq!(Points::parse("0:0,0.1:nan"), Err(PointsError::Syntax));
        assert_eq!(Points::parse("0:0,,0.2:1"), Err(PointsError::Syntax));
        assert_eq!(
            Points::parse("0:0,0.2:1,0.2:2"),
            Err(PointsError::NotRising {
                before: 0.2,
                after: 0.2
            })
        );
        let long: Vec<String> = (0..=MAX_POINTS).map(|i| format!("{i}:1")).collect();
        assert_eq!(
            Points::parse(&long.join(",")),
            Err(PointsError::TooMany {
                count: MAX_POINTS + 1
            })
        );
        assert!(Points::parse(&long[..MAX_POINTS].join(",")).is_ok());
    }

    #[test]
    fn the_first_change_after_a_time_is_the_corner_it_starts_from() {
        let at = |text: &str, after: f64| Points::parse(text).unwrap().first_change_after(after);
        assert_eq!(at("0:0,0.1:0,0.2:5", 0.0), Some(0.1));
        assert_eq!(at("0:0,0.1:0,0.2:5,0.3:5,0.4:0", 0.15), Some(0.3));
        assert_eq!(at("0:3,0.5:3", 0.0), None);
        assert_eq!(at("0.2:1", 0.0), None);
        assert_eq!(at("", 0.0), None);
    }
}
