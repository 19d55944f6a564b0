//! Analysis over many runs: closed-loop frequency response (sweeps of sinusoidal speed
//! references), seed sweeps, model-error maps (`robust`) and measurement tables (`claims`). Each run is an ordinary `Simulation`, so the CLI, the browser's
//! parallel workers and the tests share these functions.

pub mod claims;
pub mod robust;
mod seeds;
mod sweep;
mod sweep_plan;

pub use seeds::{
    seed_bands, seed_range, seed_run, seeds_csv, Band, SeedBands, SeedResult, SeedRun,
    MAX_SEED_RUNS,
};
pub use sweep::{
    checked_grid, log_grid, summarise, sweep_csv, sweep_point, SweepPoint, SweepSettings,
    SweepSummary, SETTLED_GAIN_DB, SETTLED_PHASE_DEG, SWEEP_AMP_TOL,
};
pub use sweep_plan::{
    sweep_variant, variant_scenario, SweepPlan, SweepVariant, AMP_RULE, DURATION_RULE,
    IFOC_MIN_OFFSET, OFFSET_RULE, SWEEP_VARIANTS,
};
