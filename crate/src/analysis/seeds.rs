//! Seed sweeps: one run per noise seed, each run's figures, and the mean and min–max bands of the
//! error traces over the seeds.

use crate::scenario::{Scenario, ScenarioError, MAX_SEED};
use crate::sim::{trace_bytes, Simulation, MAX_TRACE_BYTES};
use crate::text::csv;
use serde::{Deserialize, Serialize};

/// Figures of one seed's run: those of its [`crate::record::Metrics`], by their names.
#[cfg_attr(
    target_arch = "wasm32",
    derive(tsify::Tsify),
    tsify(missing_as_null, hashmap_as_object)
)]
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub struct SeedResult {
    /// The noise seed.
    pub seed: u64,
    /// RMS of ω − ω_d over the samples from the end of the start-up transient on (the window of
    /// the run's figures, see [`crate::record::transient`]) (rad/s); NaN when nothing was
    /// recorded.
    pub tracking_rms: f64,
    /// RMS of the speed-estimate error ω − ω̂ over the same window (rad/s).
    pub speed_estimate_error_rms: f64,
    /// Largest |ω − ω_d| over the same window (rad/s).
    pub tracking_peak: f64,
    /// Why the run stopped early, if it did.
    pub failure: Option<String>,
}

/// One seed's run: its figures and its decimated error traces.
#[cfg_attr(
    target_arch = "wasm32",
    derive(tsify::Tsify),
    tsify(missing_as_null, hashmap_as_object)
)]
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub struct SeedRun {
    /// Figures of the run.
    pub result: SeedResult,
    /// Sample times (s).
    pub t: Vec<f64>,
    /// ω − ω_d at those times (rad/s).
    pub error: Vec<f64>,
    /// ω − ω̂ at those times (rad/s).
    pub estimate: Vec<f64>,
}

/// Most seeds one seed sweep runs.
pub const MAX_SEED_RUNS: u64 = 10_000;

/// The seeds of a seed sweep, `first` to `first + count − 1`, after checking that there are 1 to
/// [`MAX_SEED_RUNS`] of them and that the last is a seed ([`MAX_SEED`] at most): a range that
/// would run past it is refused before any run, naming the range.
pub fn seed_range(first: u64, count: u64) -> Result<std::ops::RangeInclusive<u64>, String> {
    if !(1..=MAX_SEED_RUNS).contains(&count) {
        return Err(format!("{count} seeds: expected 1 to {MAX_SEED_RUNS} runs"));
    }
    // In u128: first + count − 1 may pass u64.
    let last = u128::from(first) + u128::from(count) - 1;
    if last > u128::from(MAX_SEED) {
        return Err(format!(
            "seeds {first} to {last} ({count} from {first}): past the largest seed, {MAX_SEED} \
             (2^53 − 1); start at {} at most",
            MAX_SEED.saturating_sub(count - 1)
        ));
    }
    Ok(first..=first + (count - 1))
}

/// Runs `base` with noise seed `seed`; the figures use every sample, the traces keep every
/// `every`-th one. A run whose rows do not fit in memory keeps checkpoints instead and computes
/// its rows again for the figures and traces: the same values, bit for bit.
pub fn seed_run(base: &Scenario, seed: u64, every: usize) -> Result<SeedRun, ScenarioError> {
    let mut s = base.clone();
    s.seed = seed;
    s.validate()?;
    run_seed(&s, every, trace_bytes(&s, 1) > MAX_TRACE_BYTES)
}

/// [`seed_run`] of `s`, from checkpoints when `traced`.
fn run_seed(s: &Scenario, every: usize, traced: bool) -> Result<SeedRun, ScenarioError> {
    let mut sim = if traced {
        Simulation::traced(s)?
    } else {
        Simulation::new(s, 1)?
    };
    let failure = sim.run().err().map(|e| e.to_string());
    // The figures are the run's own metrics; a run that recorded nothing has none.
    let m = sim.metrics();
    let figure = |f: fn(&crate::record::Metrics) -> f64| m.as_ref().map_or(f64::NAN, f);
    let (mut t, mut error, mut estimate) = (Vec::new(), Vec::new(), Vec::new());
    let every = every.max(1);
    let mut keep = |r: &crate::record::Row| {
        t.push(r.t);
        error.push(r.omega_err);
        estimate.push(r.omega_est_err);
    };
    if traced && every >= crate::record::CHECKPOINT_EVERY {
        // Kept samples farther apart than the checkpoints: each computed from the one before it,
        // not the whole run again.
        for i in (0..sim.len()).step_by(every) {
            sim.visit(i, i + 1, &mut |_, r| {
                keep(r);
                true
            });
        }
    } else {
        sim.visit(0, sim.len(), &mut |i, r| {
            if i % every == 0 {
                keep(r);
            }
            true
        });
    }
    Ok(SeedRun {
        result: SeedResult {
            seed: s.seed,
            tracking_rms: figure(|m| m.tracking_rms),
            speed_estimate_error_rms: figure(|m| m.speed_estimate_error_rms),
            tracking_peak: figure(|m| m.tracking_peak),
            failure,
        },
        t,
        error,
        estimate,
    })
}

/// Mean, minimum and maximum over runs at each sample.
#[cfg_attr(
    target_arch = "wasm32",
    derive(tsify::Tsify),
    tsify(missing_as_null, hashmap_as_object)
)]
#[derive(Clone, Debug, Default, PartialEq, Serialize)]
pub struct Band {
    /// Mean over the runs.
    pub mean: Vec<f64>,
    /// Minimum over the runs.
    pub min: Vec<f64>,
    /// Maximum over the runs.
    pub max: Vec<f64>,
}

impl Band {
    /// Statistics of `traces` (in the order given) over their common length.
    pub fn of<'a>(traces: impl Iterator<Item = &'a [f64]> + Clone) -> Band {
        let n = traces.clone().map(<[f64]>::len).min().unwrap_or(0);
        let count = traces.clone().count() as f64;
        let mut band = Band {
            mean: vec![0.0; n],
            min: vec![f64::INFINITY; n],
            max: vec![f64::NEG_INFINITY; n],
        };
        for trace in traces {
            for (i, &v) in trace.iter().take(n).enumerate() {
                band.mean[i] += v;
                band.min[i] = band.min[i].min(v);
                band.max[i] = band.max[i].max(v);
            }
        }
        band.mean.iter_mut().for_each(|m| *m /= count);
        band
    }
}

/// Seed-sweep statistics: the speed error and the estimation error over every completed run.
#[cfg_attr(
    target_arch = "wasm32",
    derive(tsify::Tsify),
    tsify(missing_as_null, hashmap_as_object)
)]
#[derive(Clone, Debug, Default, PartialEq, Serialize)]
pub struct SeedBands {
    /// Sample times (s).
    pub t: Vec<f64>,
    /// ω − ω_d over the seeds.
    pub error: Band,
    /// ω − ω̂ over the seeds.
    pub estimate: Band,
    /// Runs included (those that did not stop early).
    pub runs: usize,
}

/// Statistics of completed seed runs; grouping the runs differently gives the same bits as long
/// as they come in seed order. Refuses a run whose times and traces differ in length (only runs
/// from outside, through the bindings, can).
pub fn seed_bands(runs: &[SeedRun]) -> Result<SeedBands, String> {
    if let Some(r) = runs
        .iter()
        .find(|r| r.t.len() != r.error.len() || r.t.len() != r.estimate.len())
    {
        return Err(format!(
            "seed run {}: {} times for {} speed errors and {} estimation errors; expected as many of each",
            r.result.seed,
            r.t.len(),
            r.error.len(),
            r.estimate.len()
        ));
    }
    let ok: Vec<&SeedRun> = runs.iter().filter(|r| r.result.failure.is_none()).collect();
    let error = Band::of(ok.iter().map(|r| r.error.as_slice()));
    Ok(SeedBands {
        t: ok
            .first()
            .map(|r| r.t[..error.mean.len()].to_vec())
            .unwrap_or_default(),
        estimate: Band::of(ok.iter().map(|r| r.estimate.as_slice())),
        error,
        runs: ok.len(),
    })
}

/// Per-seed figures as CSV.
pub fn seeds_csv(results: &[SeedResult]) -> String {
    let mut out =
        String::from("seed,tracking_rms,speed_estimate_error_rms,tracking_peak,failure\n");
    for r in results {
        let failure = csv::field(r.failure.as_deref().unwrap_or(""));
        out += &format!(
            "{},{},{},{},{failure}\n",
            r.seed, r.tracking_rms, r.speed_estimate_error_rms, r.tracking_peak
        );
    }
    out
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_run_too_long_to_keep_its_rows_runs_from_checkpoints_with_the_same_values() {
        let short = Scenario::parse("v=1&preset=step&seed=4").unwrap();
        let rows = run_seed(&short, 7, false).unwrap();
        let traced = run_seed(&short, 7, true).unwrap();
        assert_eq!(format!("{rows:?}"), format!("{traced:?}"));
        // About 1.1 million samples: their rows pass the memory bound, and the run is not refused.
        let long = Scenario::parse("v=1&preset=step&duration=20&ts=0.0000187").unwrap();
        assert!(trace_bytes(&long, 1) > MAX_TRACE_BYTES);
        let run = seed_run(&long, 3, 100_000).unwrap();
        assert!(run.result.failure.is_none() && run.result.tracking_rms.is_finite());
        assert_eq!(run.t.len(), long.steps().div_ceil(100_000));
    }

    #[test]
    fn band_statistics_do_not_depend_on_how_runs_are_produced() {
        let base = crate::scenario::preset("step").unwrap();
        let runs: Vec<SeedRun> = (5..9)
            .map(|seed| seed_run(&base, seed, 50).unwrap())
            .collect();
        let again: Vec<SeedRun> = (5..9)
            .rev()
            .map(|seed| seed_run(&base, seed, 50).unwrap())
            .rev()
            .collect();
        assert_eq!(seed_bands(&runs), seed_bands(&again));
        let b = seed_bands(&runs).unwrap();
        assert_eq!(b.runs, 4);
        assert!((0..b.t.len())
            .all(|i| b.error.min[i] <= b.error.mean[i] && b.error.mean[i] <= b.error.max[i]));
        assert!(
            runs[0].result.tracking_rms != runs[1].result.tracking_rms,
            "seeds change the noise"
        );
    }

    #[test]
    fn a_failure_keeps_its_words_in_its_csv_field() {
        let failed = SeedResult {
            seed: 3,
            tracking_rms: f64::NAN,
            speed_estimate_error_rms: f64::NAN,
            tracking_peak: f64::NAN,
            failure: Some("diverged at t = 0.1 s: x1 = inf, \"speed\"".to_string()),
        };
        let csv = seeds_csv(&[failed]);
        assert_eq!(
            csv.lines().nth(1),
            Some("3,NaN,NaN,NaN,\"diverged at t = 0.1 s: x1 = inf, \"\"speed\"\"\"")
        );
    }
}
