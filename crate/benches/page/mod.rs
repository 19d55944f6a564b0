//! What the page asks of a run, shared by the benchmarks that run scenarios as the page does.

/// Plot width the benchmarks ask for (buckets, about the pixels of a plot).
pub const BUCKETS: usize = 1000;

/// The plots of the page, one envelope each, as `PLOTS` in web/plots/plots.js lists their columns
/// (keep in step): one view request of the worker computes all of them.
pub const PAGE_PLOTS: &[&[&str]] = &[
    &["omega_ref", "omega_hat", "omega"],
    &["omega_err"],
    &["flux_ref", "flux_hat", "flux"],
    &["i_sa_hat", "i_sb_hat", "i_sa", "i_sb"],
    &["u_a", "u_b"],
    &["z1", "z3"],
    &["z2", "z4"],
    &["omega_est_err", "flux_est_err"],
];

/// The page's plots as owned groups of column names.
pub fn page_groups() -> Vec<Vec<String>> {
    PAGE_PLOTS
        .iter()
        .map(|g| g.iter().map(|n| n.to_string()).collect())
        .collect()
}
