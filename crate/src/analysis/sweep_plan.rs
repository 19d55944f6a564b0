//! A sweep's plan in one line of text, as a link's `#sweep=` fragment and `imlab sweep --plan`
//! take it: `LO,HI,N,AMP,OFFSET,DURATION,VARIANT.VARIANT…`, the frequency grid, how each
//! frequency is measured, and the variants of the scenario to sweep, each a set of field changes.

use super::sweep::{checked_grid, SweepSettings};
use crate::scenario::{Scenario, ScenarioError};
use crate::text::{excerpt, short};
use serde::{Deserialize, Serialize};

/// A variant of the scenario a sweep compares: its name in the plan, its label on a plot, and the
/// field changes that make it from the swept scenario.
#[derive(Clone, Copy, Debug)]
pub struct SweepVariant {
    /// Its name in a plan (`euler`).
    pub name: &'static str,
    /// In words, as a plot's legend shows it.
    pub label: &'static str,
    /// The fields it sets, in order.
    pub changes: &'static [(&'static str, &'static str)],
}

/// The variants a sweep may compare, in the order a page offers them. The like-for-like IFOC
/// baseline feeds the reference's torque forward, as the backstepping feeds ω̇_d forward;
/// `ifocpi` is the plain PI speed loop.
pub const SWEEP_VARIANTS: &[SweepVariant] = &[
    SweepVariant {
        name: "euler",
        label: "Backstepping + Euler EKF (paper)",
        changes: &[
            ("controller", "backstepping"),
            ("perfect", "0"),
            ("ekf", "euler"),
        ],
    },
    SweepVariant {
        name: "rk4",
        label: "Backstepping + RK4 EKF",
        changes: &[
            ("controller", "backstepping"),
            ("perfect", "0"),
            ("ekf", "rk4"),
        ],
    },
    SweepVariant {
        name: "perfect",
        label: "Backstepping + perfect observer",
        changes: &[("controller", "backstepping"), ("perfect", "1")],
    },
    SweepVariant {
        name: "delay",
        label: "Backstepping + Euler EKF, one-sample delay",
        changes: &[
            ("controller", "backstepping"),
            ("perfect", "0"),
            ("ekf", "euler"),
            ("delay", "1"),
            ("delay.comp", "0"),
        ],
    },
    SweepVariant {
        name: "ifoc",
        label: "Classical IFOC + MRAS, torque feedforward",
        changes: &[("controller", "ifoc"), ("perfect", "0"), ("ifoc.ff", "1")],
    },
    SweepVariant {
        name: "ifocpi",
        label: "Classical IFOC + MRAS, no feedforward",
        changes: &[("controller", "ifoc"), ("perfect", "0"), ("ifoc.ff", "0")],
    },
];

/// The variant named `name`, or a message listing the names.
pub fn sweep_variant(name: &str) -> Result<&'static SweepVariant, String> {
    SWEEP_VARIANTS
        .iter()
        .find(|v| v.name == name)
        .ok_or_else(|| {
            let names: Vec<_> = SWEEP_VARIANTS.iter().map(|v| v.name).collect();
            format!(
                "variant '{}' is unknown (expected {})",
                excerpt(name),
                names.join(", ")
            )
        })
}

/// `base` made into the variant `variant`.
pub fn variant_scenario(
    base: &Scenario,
    variant: &SweepVariant,
) -> Result<Scenario, ScenarioError> {
    let mut s = base.clone();
    for (key, value) in variant.changes {
        s.set(key, value)?;
    }
    Ok(s)
}

/// The ranges of a sweep's settings, each with its rule in words: amplitude (rad/s), operating
/// speed (rad/s) and run length (s).
pub const AMP_RULE: (fn(f64) -> bool, &str) = (|a| a > 0.0 && a <= 1000.0, "0 < A ≤ 1000 rad/s");
/// See [`AMP_RULE`].
pub const OFFSET_RULE: (fn(f64) -> bool, &str) = (|w| w.abs() <= 1000.0, "|W| ≤ 1000 rad/s");
/// See [`AMP_RULE`].
pub const DURATION_RULE: (fn(f64) -> bool, &str) = (|d| d > 0.0 && d <= 20.0, "0 < D ≤ 20 s");

/// Below this operating speed (rad/s) the IFOC's MRAS cannot estimate the speed, so a sweep of
/// an IFOC variant there measures nothing meaningful.
pub const IFOC_MIN_OFFSET: f64 = 20.0;

/// A sweep's plan: the grid, the settings of each run, the variants.
#[cfg_attr(
    target_arch = "wasm32",
    derive(tsify::Tsify),
    tsify(missing_as_null, hashmap_as_object)
)]
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub struct SweepPlan {
    /// Lowest frequency (Hz).
    pub lo: f64,
    /// Highest frequency (Hz).
    pub hi: f64,
    /// Number of log-spaced frequencies, 1 to 200.
    pub n: usize,
    /// Amplitude of the sine (rad/s).
    pub amp: f64,
    /// Operating speed the sine rides on (rad/s).
    pub offset: f64,
    /// Length of each run (s).
    pub duration: f64,
    /// The variants' names, in the order given.
    pub variants: Vec<String>,
}

impl SweepPlan {
    /// Reads a plan's text; the message names the first part that is not acceptable.
    pub fn parse(text: &str) -> Result<SweepPlan, String> {
        let parts: Vec<&str> = text.split(',').collect();
        let [lo, hi, n, amp, offset, duration, variants] = parts[..] else {
            return Err(format!(
                "expected 7 parts lo,hi,n,amp,offset,duration,variants, not {}",
                parts.len()
            ));
        };
        let variants: Vec<&str> = variants.split('.').collect();
        SweepPlan::from_parts([lo, hi, n, amp, offset, duration], &variants)
    }

    /// A plan from its parts as written (a form's fields): `[lo, hi, n, amp, offset, duration]`
    /// and the variants' names; the message names the first part that is not acceptable.
    pub fn from_parts(numbers: [&str; 6], variants: &[&str]) -> Result<SweepPlan, String> {
        let [lo, hi, n, amp, offset, duration] = numbers;
        let number = |key: &str, part: &str| -> Result<f64, String> {
            part.trim()
                .parse::<f64>()
                .ok()
                .filter(|v| v.is_finite())
                .ok_or_else(|| format!("{key} = '{}' is not a number", excerpt(part)))
        };
        let (lo, hi) = (number("lo", lo)?, number("hi", hi)?);
        let count = number("n", n)?;
        if !(count >= 0.0 && count.fract() == 0.0 && count < 4_294_967_296.0) {
            return Err(format!(
                "n = {}: expected a whole number of points",
                excerpt(n)
            ));
        }
        let plan = SweepPlan {
            lo,
            hi,
            n: count as usize,
            amp: number("amp", amp)?,
            offset: number("offset", offset)?,
            duration: number("duration", duration)?,
            variants: variants.iter().map(|v| v.to_string()).collect(),
        };
        plan.check()?;
        Ok(plan)
    }

    /// Checks every part: the grid, the settings' ranges, the variants (at least one, each known).
    pub fn check(&self) -> Result<(), String> {
        checked_grid(self.lo, self.hi, self.n)?;
        for (key, value, (ok, rule)) in [
            ("amp", self.amp, AMP_RULE),
            ("offset", self.offset, OFFSET_RULE),
            ("duration", self.duration, DURATION_RULE),
        ] {
            if !ok(value) {
                return Err(format!("{key} = {value}: expected {rule}"));
            }
        }
        if self.variants.is_empty() || self.variants.iter().any(String::is_empty) {
            return Err("no variant: choose at least one".to_string());
        }
        for v in &self.variants {
            sweep_variant(v)?;
        }
        Ok(())
    }

    /// The plan's text, as [`SweepPlan::parse`] reads it: each number in its shortest form
    /// (scientific where that is long), −0 as 0.
    pub fn text(&self) -> String {
        let number = |v: f64| short(v + 0.0);
        format!(
            "{},{},{},{},{},{},{}",
            number(self.lo),
            number(self.hi),
            self.n,
            number(self.amp),
            number(self.offset),
            number(self.duration),
            self.variants.join(".")
        )
    }

    /// How each frequency is measured.
    pub fn settings(&self) -> SweepSettings {
        SweepSettings {
            amp: self.amp,
            duration: self.duration,
            offset: self.offset,
        }
    }

    /// The frequencies (Hz), log-spaced.
    pub fn frequencies(&self) -> Result<Vec<f64>, String> {
        checked_grid(self.lo, self.hi, self.n)
    }

    /// What a reader of the plan's results must know: that an IFOC variant swept near
    /// standstill measures nothing meaningful.
    pub fn caveats(&self) -> Vec<String> {
        let ifoc = self.variants.iter().any(|v| v.starts_with("ifoc"));
        if ifoc && self.offset.abs() < IFOC_MIN_OFFSET {
            vec![format!(
                "The IFOC figures are not meaningful here: its MRAS cannot estimate the speed near \
                 standstill. Sweep it about an operating speed (offset ≥ {IFOC_MIN_OFFSET} rad/s) \
                 with longer runs (3 s)."
            )]
        } else {
            Vec::new()
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_plan_reads_back_from_its_text() {
        let plan = SweepPlan::parse("10,1000,20,0.02,-0,0.2,euler.rk4").unwrap();
        assert_eq!(plan.text(), "10,1000,20,0.02,0,0.2,euler.rk4");
        assert_eq!(SweepPlan::parse(&plan.text()).unwrap(), plan);
        assert_eq!(plan.frequencies().unwrap().len(), 20);
        let far = SweepPlan::parse("1,1e300,2,0.02,0,0.2,euler").unwrap();
        assert_eq!(far.text(), "1,1e300,2,0.02,0,0.2,euler");
    }

    #[test]
    fn a_bad_plan_names_its_first_bad_part() {
        for (text, message) in [
            ("10,1000,20", "expected 7 parts"),
            ("x,1000,2.5,0.02,0,0.2,euler", "lo = 'x' is not a number"),
            (
                "10,1000,2.5,0.02,0,0.2,euler",
                "n = 2.5: expected a whole number of points",
            ),
            ("-5,1000,20,0.02,0,0.2,euler", "frequency grid -5:1000:20"),
            (
                "10,1000,20,0,0,0.2,euler",
                "amp = 0: expected 0 < A ≤ 1000 rad/s",
            ),
            (
                "10,1000,20,0.02,0,30,euler",
                "duration = 30: expected 0 < D ≤ 20 s",
            ),
            ("10,1000,20,0.02,0,0.2,", "no variant"),
            (
                "10,1000,20,0.02,0,0.2,euler.constructor",
                "variant 'constructor' is unknown",
            ),
        ] {
            let e = SweepPlan::parse(text).unwrap_err();
            assert!(e.starts_with(message), "{text}: {e}");
        }
    }

    #[test]
    fn an_ifoc_variant_near_standstill_carries_its_caveat() {
        let near = SweepPlan::parse("10,1000,20,0.02,0,0.2,euler.ifocpi").unwrap();
        assert_eq!(near.caveats().len(), 1);
        let about = SweepPlan::parse("10,1000,20,0.02,40,0.2,ifoc").unwrap();
        assert!(about.caveats().is_empty());
        let backstepping = SweepPlan::parse("10,1000,20,0.02,0,0.2,euler").unwrap();
        assert!(backstepping.caveats().is_empty());
    }

    #[test]
    fn every_variant_makes_a_scenario_of_the_preset() {
        let base = Scenario::parse("v=1&preset=step").unwrap();
        for v in SWEEP_VARIANTS {
            variant_scenario(&base, v).unwrap();
        }
    }
}
