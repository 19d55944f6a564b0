//! The unknown extra load torque: a step, or a table of points.

use crate::control::Points;
use serde::{Deserialize, Serialize};

/// An extra load torque applied from a given time on, unknown to the controller and observer.
#[derive(Clone, Copy, Debug, PartialEq, Serialize, Deserialize)]
pub struct LoadStep {
    /// Time the step is applied (s).
    pub time: f64,
    /// Extra load torque (N m); 0 means no step.
    pub torque: f64,
    /// A load torque that follows a table (t, N m) instead of the step, when it has points.
    #[serde(default)]
    pub table: Points,
}

impl LoadStep {
    /// The extra load torque at time `t` (N m): the table's, or the step's (zero before its time).
    #[inline(always)]
    pub fn at(&self, t: f64) -> f64 {
        if !self.table.is_empty() {
            self.table.sample(t).0
        } else if t >= self.time {
            self.torque
        } else {
            0.0
        }
    }

    /// The first change of the extra load after time `after` (s): the step, or the first corner
    /// of the table from which the load moves; None when there is none.
    pub fn change_after(&self, after: f64) -> Option<f64> {
        if !self.table.is_empty() {
            self.table.first_change_after(after)
        } else {
            (self.torque != 0.0 && self.time > after).then_some(self.time)
        }
    }

    /// The time and size of its step, when the load is a step (not a table) of some torque: what
    /// the recovery after a load step is measured from.
    pub fn step(&self) -> Option<(f64, f64)> {
        (self.table.is_empty() && self.torque != 0.0).then_some((self.time, self.torque))
    }
}

#[cfg(test)]
mod tests {
    use super::super::{preset, Scenario};

    #[test]
    fn a_table_reference_and_a_load_table_round_trip_and_bad_tables_are_refused() {
        let text =
            "v=1&preset=step&ref=table&ref.table=0:0,0.1:100,0.2:-50&load.table=0.05:0,0.06:2";
        let s = Scenario::parse(text).unwrap();
        assert_eq!(s.encode(), text);
        assert_eq!(s.reference.sample(0.05).value, 50.0);
        assert_eq!(s.reference.sample(0.15).d1, -1500.0);
        assert_eq!(s.load_step.at(0.055), 1.0);
        assert_eq!(s.load_step.change_after(0.0), Some(0.05));
        // The load step's fields then do nothing, and say so; the recovery has no step to time.
        assert_eq!(s.idle_because("load.torque").as_deref(), Some("load.table"));
        assert_eq!(s.load_step.step(), None);
        // Escaped separators read as typed.
        let escaped = Scenario::parse("v=1&preset=step&ref=table&ref.table=0%3A0%2C0.1%3A100,0.2%3A-50&load.table=0.05:0,0.06:2").unwrap();
        assert_eq!(escaped, s);
        let refused = |t: &str| {
            Scenario::parse(&format!("v=1&preset=step&ref=table&ref.table={t}"))
                .unwrap_err()
                .to_string()
        };
        assert!(
            refused("0:0,0.1").contains("points t:value"),
            "{}",
            refused("0:0,0.1")
        );
        assert!(refused("0:0,0.1:1,0.1:2").contains("0.1 s is not after 0.1 s"));
        assert!(refused("0:0,21:1").contains("21 s is outside"));
        assert!(refused("0:0,1:1001").contains("1001: out of range"));
        let long: Vec<String> = (0..17).map(|i| format!("{i}:1")).collect();
        assert!(refused(&long.join(",")).contains("at most 16 points; this table has 17"));
        // A reference table needs a point, and its slopes are bounded as a ramp's are.
        assert!(refused("").contains("points t:value"), "{}", refused(""));
        let steep = refused("0:0,1e-9:100");
        assert!(
            steep.contains(
                "at most 1000000 rad/s a second between points; from 0 s to 0.000000001 s"
            ),
            "{steep}"
        );
        // A table of another reference kind does not apply.
        let err = Scenario::parse("v=1&preset=step&ref.table=0:1")
            .unwrap_err()
            .to_string();
        assert!(
            err.contains("does not apply to the reference 'step'"),
            "{err}"
        );
        // An empty load table is no table: the preset's step stays.
        let s = Scenario::parse("v=1&preset=load-step&load.table=").unwrap();
        assert_eq!(s, preset("load-step").unwrap());
    }
}
