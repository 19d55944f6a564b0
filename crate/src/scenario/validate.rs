//! The checks of a whole scenario: every field in its range, a physical motor and model, a
//! voltage limit the drive can make, and a run whose samples and plant work stay within bounds.

use super::fields::{fields, Access};
use super::{preset, ControllerKind, Scenario, ScenarioError};
use crate::inverter::Shape;
use crate::text::short;

/// Most samples one run may take.
pub const MAX_STEPS: usize = 2_000_000;
/// Most plant RK4 steps one run may take: samples × [`Scenario::plant_steps_per_sample`]. The
/// plant's integration is the one cost of a sample that a field multiplies (up to 8,000 RK4
/// steps a sample, against about ten steps' worth for everything else a sample does), so
/// [`MAX_STEPS`] alone bounds a run's time only with one substep.
///
/// Chosen so that the plant's work adds about a second at most to any run; the measurement is in
/// `docs/figures.md` (the work bound).
pub const MAX_WORK: u64 = 10_000_000;

impl Scenario {
    /// Checks every field's range and the physics of both parameter sets.
    pub fn validate(&self) -> Result<(), ScenarioError> {
        if preset(&self.preset).is_none() {
            return Err(ScenarioError::UnknownPreset {
                name: self.preset.clone(),
            });
        }
        for field in fields() {
            if let Access::Number { get, .. } = field.access {
                if let Some(v) = get(self) {
                    field.check(v)?;
                }
            }
        }
        if self.drive.pwm && self.drive.vlimit == Shape::Box {
            return Err(ScenarioError::OutOfRange {
                key: "pwm".to_string(),
                value: 1.0,
                allowed: "pwm=1 with vlimit=circle or hex: a two-level inverter cannot make the box's corners"
                    .to_string(),
            });
        }
        for (which, p) in [("plant", &self.plant), ("model", &self.model)] {
            p.lumped()
                .map_err(|error| ScenarioError::Physics { which, error })?;
        }
        // In f64, so that a count past usize (or the clamp in `steps`) is still shown as it is.
        let samples = (self.duration / self.ts).round();
        let (duration, ts) = (short(self.duration), short(self.ts));
        if samples > MAX_STEPS as f64 {
            return Err(ScenarioError::TooLarge {
                what: format!(
                    "'duration'/'ts' = {duration} s / {ts} s = {} samples is more than the {MAX_STEPS} allowed; \
                     shorten 'duration' or raise 'ts'",
                    short(samples)
                ),
            });
        }
        if samples < 1.0 {
            return Err(ScenarioError::TooLarge {
                what: format!(
                    "'duration' = {duration} s is shorter than one sample, 'ts' = {ts} s"
                ),
            });
        }
        // At most MAX_STEPS × 8,000 here, far inside u64.
        let per_sample = self.plant_steps_per_sample();
        let work = samples as u64 * per_sample;
        if work > MAX_WORK {
            let substeps = self.substeps;
            let plant = if self.drive.pwm {
                format!("'substeps' = {substeps} on each of 7 PWM intervals")
            } else {
                format!("'substeps' = {substeps}")
            };
            let how = if per_sample / u64::from(substeps) > if self.drive.pwm { 7 } else { 1 } {
                format!(
                    "{plant}, and {substeps} for the perfect observer's prediction ('delay.comp')"
                )
            } else {
                plant
            };
            let pwm_hint = if self.drive.pwm {
                ", or turn 'pwm' off"
            } else {
                ""
            };
            return Err(ScenarioError::TooLarge {
                what: format!(
                    "the run's work, {samples} samples ('duration'/'ts' = {duration} s / {ts} s) × \
                     {per_sample} plant RK4 steps a sample ({how}) = {work} steps, is more than the \
                     {MAX_WORK} allowed; lower 'substeps' or 'duration', or raise 'ts'{pwm_hint}"
                ),
            });
        }
        Ok(())
    }

    /// RK4 steps of the plant per sample: `substeps` on each of the up to seven intervals of
    /// constant voltage of a PWM period (one interval without PWM), and `substeps` more where
    /// the perfect observer's delay compensation advances the true state to the next sample.
    pub fn plant_steps_per_sample(&self) -> u64 {
        let intervals = if self.drive.pwm { 7 } else { 1 };
        let prediction = self.drive.delay
            && self.drive.delay_comp
            && self.perfect
            && self.controller == ControllerKind::Backstepping;
        u64::from(self.substeps) * (intervals + u64::from(prediction))
    }

    /// Number of samples simulated: round(duration / ts).
    pub fn steps(&self) -> usize {
        let n = (self.duration / self.ts).round();
        if n > MAX_STEPS as f64 * 2.0 {
            usize::MAX
        } else {
            n as usize
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::scenario::PRESETS;

    #[test]
    fn cross_field_checks_wait_for_the_whole_scenario() {
        // plant.m = 0.6 alone makes σ < 0; with plant.ls = 1 as well it is physical.
        let s = Scenario::parse("v=1&preset=step&plant.m=0.6&plant.ls=1").unwrap();
        assert!(s.plant.sigma() > 0.0);
        assert_eq!(
            Scenario::parse_lenient("v=1&preset=step&plant.m=0.6&plant.ls=1")
                .unwrap()
                .1,
            vec![]
        );
    }

    #[test]
    fn counts_past_the_limit_are_reported_as_they_are() {
        let err = Scenario::parse("v=1&preset=ifoc-step&ts=1e-7")
            .unwrap_err()
            .to_string();
        assert!(
            err.contains("= 6000000 samples is more than the 2000000"),
            "{err}"
        );
    }

    #[test]
    fn the_work_limit_refuses_runaway_substeps_and_keeps_the_presets_and_long_runs() {
        for p in PRESETS {
            for text in [
                p.name.to_string(),
                format!("v=1&preset={}&duration=20", p.name),
            ] {
                let s = Scenario::parse(&text).unwrap();
                assert!(s.steps() as u64 * s.plant_steps_per_sample() <= MAX_WORK);
            }
        }
        // The largest trace at 20 s, also with PWM; the finest integration of short runs.
        for text in [
            "v=1&preset=step&duration=20&ts=0.00001878",
            "v=1&preset=sine200-drive&duration=20&ts=0.00001878",
            "v=1&preset=step&substeps=1000",
            "v=1&preset=sine200&substeps=1000",
            "v=1&preset=sine200-drive&substeps=100",
            // Exactly at the limit: 10,000 samples × 1,000 substeps.
            "v=1&preset=step&duration=0.5&substeps=1000",
        ] {
            Scenario::parse(text).unwrap();
        }
        // One sample more.
        let err = Scenario::parse("v=1&preset=step&duration=0.50005&substeps=1000")
            .unwrap_err()
            .to_string();
        assert!(
            err.contains("10001 samples") && err.contains("= 10001000 steps"),
            "{err}"
        );
        let err = Scenario::parse("v=1&preset=sine200-drive&ts=0.000001&duration=1&substeps=1000")
            .unwrap_err()
            .to_string();
        assert_eq!(
            err,
            "the run's work, 1000000 samples ('duration'/'ts' = 1 s / 0.000001 s) × 7000 plant \
             RK4 steps a sample ('substeps' = 1000 on each of 7 PWM intervals) = 7000000000 \
             steps, is more than the 10000000 allowed; lower 'substeps' or 'duration', or raise \
             'ts', or turn 'pwm' off"
        );
        // The perfect observer's delay compensation integrates the plant once more a sample.
        let s =
            Scenario::parse("v=1&preset=sine200-drive&perfect=1&delay.comp=1&substeps=3").unwrap();
        assert_eq!(s.plant_steps_per_sample(), 24);
        let err = Scenario::parse(
            "v=1&preset=step&duration=0.5&perfect=1&delay=1&delay.comp=1&substeps=600",
        )
        .unwrap_err()
        .to_string();
        assert!(
            err.contains(
                "1200 plant RK4 steps a sample ('substeps' = 600, and 600 for the \
                 perfect observer's prediction ('delay.comp'))"
            ),
            "{err}"
        );
        // Leniently, the field that would exceed it is left out and named.
        let (s, errors) = Scenario::parse_lenient("v=1&preset=ramp&substeps=1000&k1=1500").unwrap();
        assert_eq!(s.encode(), "v=1&preset=ramp&k1=1500");
        assert!(
            errors[0].to_string().contains("14000000 steps"),
            "{errors:?}"
        );
    }
}
