//! The checks of a whole scenario: every field in its range, a physical motor and model, a
//! voltage limit the drive can make, and a run whose samples and plant work stay within bounds.

use super::fields::{fields, Access};
use super::{preset, ControllerKind, Scenario, ScenarioError};
use crate::control::law::Laws;
use crate::inverter::Shape;
use crate::text::Message;

/// `v` rounded down to three significant digits.
fn down3(v: f64) -> f64 {
    let scale = 10f64.powi(2 - v.log10().floor() as i32);
    (v * scale).floor() / scale
}

/// `v` rounded up to three significant digits.
fn up3(v: f64) -> f64 {
    let scale = 10f64.powi(2 - v.log10().floor() as i32);
    (v * scale).ceil() / scale
}

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

/// Most simple operations (see [`Program::work`](crate::control::formula::Program::work)) a
/// run's own laws may take, over all its samples. The paper's four laws written out take 166 a
/// sample, and 295 when steps 2 and 4 are judged on a student's own v1 and v3 through their
/// rates, so they fit at the most samples a run may take, [`MAX_STEPS`]; laws of sines of huge
/// arguments fit at fewer. Chosen so that the laws add under three seconds to a run's computing,
/// each time it is computed; the measurement is in `docs/figures.md` (the work of own laws).
pub const MAX_LAW_WORK: u64 = 600_000_000;

impl Scenario {
    /// The steps' own laws, parsed; the first bad one refused with its field.
    pub fn laws(&self) -> Result<Laws, ScenarioError> {
        Laws::parse(&self.law).map_err(|(step, error)| ScenarioError::BadFormula {
            key: ["law.v1", "law.v2", "law.v3", "law.v4"][step as usize - 1],
            error,
        })
    }

    /// Checks every field's range and the physics of both parameter sets.
    pub fn validate(&self) -> Result<(), ScenarioError> {
        if preset(&self.preset).is_none() {
            return Err(ScenarioError::UnknownPreset {
                name: self.preset.clone(),
            });
        }
        // A derived design must follow from the motor's data, however the scenario was set.
        if self.design == super::DesignKind::Derived {
            self.derived()
                .map_err(|error| ScenarioError::Design { error })?;
        }
        // An own law of step 3 or 4 is a formula of constant ψ_d: it has no ψ̇_d or ψ̈_d to read.
        if self.fw && self.controller == ControllerKind::Backstepping {
            if let Some(step) = [2, 3].into_iter().find(|&i| self.law[i].is_some()) {
                return Err(ScenarioError::Refused {
                    key: ["law.v3", "law.v4"][step - 2],
                    why: Message::new("scenario-law-fw"),
                });
            }
        }
        for field in fields() {
            match field.access {
                Access::Number { get, .. } => {
                    if let Some(v) = get(self) {
                        field.check(v)?;
                    }
                }
                Access::Table { get, .. } => {
                    if let Some(p) = get(self) {
                        field.check_points(&p)?;
                    }
                }
                Access::Choice { .. } | Access::Formula { .. } => {}
            }
        }
        if self.drive.pwm && self.drive.vlimit == Shape::Box {
            return Err(ScenarioError::OutOfRange {
                key: "pwm".to_string(),
                value: 1.0,
                allowed: Message::new("scenario-allowed-pwm"),
            });
        }
        for (which, p) in [("plant", &self.plant), ("model", &self.model)] {
            p.lumped()
                .map_err(|error| ScenarioError::Physics { which, error })?;
        }
        // In f64, so that a count past usize (or the clamp in `steps`) is still shown as it is.
        let samples = (self.duration / self.ts).round();
        if samples > MAX_STEPS as f64 {
            return Err(ScenarioError::TooLarge {
                what: Message::new("scenario-too-many-samples")
                    .short("duration", self.duration)
                    .short("ts", self.ts)
                    .short("samples", samples)
                    .count("max", MAX_STEPS),
            });
        }
        if samples < 1.0 {
            return Err(ScenarioError::TooLarge {
                what: Message::new("scenario-shorter-than-sample")
                    .short("duration", self.duration)
                    .short("ts", self.ts),
            });
        }
        // At most MAX_STEPS × 8,000 here, far inside u64.
        let per_sample = self.plant_steps_per_sample();
        let work = samples as u64 * per_sample;
        if work > MAX_WORK {
            let substeps = self.substeps;
            let plant = Message::new(if self.drive.pwm {
                "scenario-work-substeps-pwm"
            } else {
                "scenario-work-substeps"
            })
            .count("substeps", substeps);
            let how = if per_sample / u64::from(substeps) > if self.drive.pwm { 7 } else { 1 } {
                Message::new("scenario-work-prediction")
                    .said("plant", plant)
                    .count("substeps", substeps)
            } else {
                plant
            };
            return Err(ScenarioError::TooLarge {
                what: Message::new("scenario-too-much-work")
                    .real("samples", samples)
                    .short("duration", self.duration)
                    .short("ts", self.ts)
                    .count("per_sample", per_sample)
                    .said("how", how)
                    .count("work", work)
                    .count("max", MAX_WORK)
                    .text("pwm", if self.drive.pwm { "yes" } else { "no" }),
            });
        }
        self.check_law_work(samples)
    }

    /// Operations the own laws take over the whole run (see [`Laws::work`]): 0 without them.
    /// The baseline evaluates them too, for the backstepping's columns it records beside its
    /// own.
    pub fn law_work(&self) -> Result<u64, ScenarioError> {
        Ok((self.steps() as u64).saturating_mul(self.laws()?.work()))
    }

    /// Refuses own laws whose work over the run's `samples` passes [`MAX_LAW_WORK`], naming
    /// the work and the run that would fit.
    fn check_law_work(&self, samples: f64) -> Result<(), ScenarioError> {
        let work = self.law_work()?;
        if work <= MAX_LAW_WORK {
            return Ok(());
        }
        let laws = self.laws()?;
        let per_sample = laws.work();
        let works = laws.works();
        let mut parts: Vec<Message> = (0..4)
            .filter(|&i| works[i] > 0)
            .map(|i| {
                Message::new("scenario-law-work-step")
                    .count("step", i + 1)
                    .count("work", works[i])
            })
            .collect();
        let chains = per_sample - works.iter().sum::<u64>();
        if chains > 0 {
            parts.push(Message::new("scenario-law-work-rates").count("work", chains));
        }
        let fits = (MAX_LAW_WORK / per_sample) as f64;
        Err(ScenarioError::TooLarge {
            what: Message::new("scenario-law-work")
                .real("samples", samples)
                .short("duration", self.duration)
                .short("ts", self.ts)
                .count("per_sample", per_sample)
                .list("parts", parts)
                .count("work", work)
                .count("max", MAX_LAW_WORK)
                .count("fits", MAX_LAW_WORK / samples as u64)
                .short("duration_fit", down3(fits * self.ts))
                .short("ts_fit", up3(self.duration / fits)),
        })
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

    /// The `step` preset with `fields` and `laws` as steps 1–4's own laws.
    fn with_laws(fields: &[(&str, String)], laws: [&str; 4]) -> Result<Scenario, ScenarioError> {
        let mut all: Vec<(String, String)> = fields
            .iter()
            .map(|(k, v)| (k.to_string(), v.clone()))
            .collect();
        all.extend((0..4).map(|i| (format!("law.v{}", i + 1), laws[i].to_string())));
        Scenario::parse(&super::super::compose("step", &all))
    }

    #[test]
    fn the_law_work_limit_prices_functions_and_keeps_the_papers_laws() {
        use crate::control::law::PAPER;
        // The paper's four laws at the most samples a run may take, also with steps 1 and 3
        // written differently, so that steps 2 and 4 are judged on them through their rates.
        let at = |d: f64| [("duration", d.to_string()), ("ts", "0.00001".to_string())];
        let longest = at(20.0);
        let s = with_laws(&longest, PAPER).unwrap();
        assert_eq!(s.law_work().unwrap(), 2_000_000 * 166);
        let v3 = format!("{} + 0", PAPER[2]);
        let chained = [
            "-si1 + dwd + a3*wd + a2 - (k1 - a3)*z1",
            PAPER[1],
            &v3,
            PAPER[3],
        ];
        let s = with_laws(&longest, chained).unwrap();
        assert!(
            s.law_work().unwrap() > 2_000_000 * 166,
            "{}",
            s.law_work().unwrap()
        );
        // The same with 100 sines of a huge argument added to each: its sines are priced as
        // such, not as one operation each.
        let sines = ["sin(1e300*x1h)"; 100].join(" + ");
        let costly = PAPER.map(|law| format!("{law} + 0*({sines})"));
        let costly = [0, 1, 2, 3].map(|i| costly[i].as_str());
        let err = with_laws(&longest, costly).unwrap_err().to_string();
        assert!(
            err.starts_with("the laws' work, 2000000 samples")
                && err.contains("is more than the 600000000 allowed"),
            "{err}"
        );
        // What the refusal says fits, fits, and a little more does not.
        let fits = err.split("shorten 'duration' to ").nth(1).unwrap();
        let fits: f64 = fits.split(' ').next().unwrap().parse().unwrap();
        let s = with_laws(&at(fits), costly).unwrap();
        assert!(s.law_work().unwrap() <= MAX_LAW_WORK);
        assert!(with_laws(&at(fits * 1.01), costly).is_err());
        // Each of the 100 sines counts 64 operations.
        let ops = [0u8, 1, 2, 3]
            .map(|i| crate::control::formula::Program::parse(costly[i as usize], i + 1).unwrap());
        assert!(ops.iter().all(|p| p.work() > 6400));
        // The baseline evaluates the laws too (for the backstepping's columns): it is bounded
        // alike.
        let mut ifoc = longest.to_vec();
        ifoc.push(("controller", "ifoc".to_string()));
        let err = with_laws(&ifoc, costly).unwrap_err().to_string();
        assert!(err.starts_with("the laws' work, 2000000 samples"), "{err}");
    }
}
