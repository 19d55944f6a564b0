//! What a run's figures must not be read without: a run that ran away, an EKF whose mean NIS is
//! far outside the band of a consistent filter; and that band.

use super::row::Row;
use crate::text::Message;
use serde::Serialize;

/// Standard-normal quantile of 97.5 %: the 95 % two-sided band.
pub(super) const Z_975: f64 = 1.959963984540054;

/// What a [`Warning`] is about; the page and the JSON see it as "runaway", "inconsistent" or
/// "not-finite".
#[cfg_attr(
    target_arch = "wasm32",
    derive(tsify::Tsify),
    tsify(missing_as_null, hashmap_as_object)
)]
#[derive(Clone, Copy, Debug, PartialEq, Eq, Serialize)]
#[serde(rename_all = "lowercase")]
pub enum WarningKind {
    /// The true state left the region the design holds it in, so the run failed as a control
    /// run, however its samples look.
    Runaway,
    /// The EKF's mean NIS is far outside the band of a filter whose model fits, so its estimates
    /// cannot be trusted.
    Inconsistent,
    /// A figure is not a finite number, so the run gives none in its place: the text says why.
    #[serde(rename = "not-finite")]
    NotFinite,
    /// The speed ends the run away from its reference, and has been away from it since a time
    /// the text gives: the run does not do what it was asked.
    #[serde(rename = "not-following")]
    NotFollowing,
}

/// A finding about the whole run that its figures alone would hide.
#[cfg_attr(
    target_arch = "wasm32",
    derive(tsify::Tsify),
    tsify(missing_as_null, hashmap_as_object)
)]
#[derive(Clone, Debug, PartialEq, Serialize)]
pub struct Warning {
    /// What it is about.
    pub kind: WarningKind,
    /// The figure it stands in place of, for [`WarningKind::NotFinite`].
    pub figure: Option<&'static str>,
    /// One or two sentences that name what happened, with the run's numbers (`warning-*` of
    /// `core-run.ftl`).
    pub text: Message,
}

/// A mean NIS this many times past an end of its 95 % band is called inconsistent.
const FAR_OUTSIDE: f64 = 5.0;

/// A run has run away when its true speed ends further than this from the reference, beyond
/// twice the largest reference of the window (rad/s)...
const RUNAWAY_SPEED: f64 = 100.0;

/// ... or its true flux modulus ends above this multiple of the flux target √ψ_d.
const RUNAWAY_FLUX: f64 = 4.0;

/// A run ends not following its reference when ω has stayed off it (see
/// [`following`](super::window::following)) over at least this share of the window, to its end.
const ASTRAY_SHARE: f64 = 0.1;

/// Where a run's speed has stayed off its reference, to its last sample.
pub(super) struct Astray {
    /// Time of the first sample of that stretch (s).
    pub(super) since: f64,
    /// Whether the stretch starts with the window (it may have started earlier).
    pub(super) from_window_start: bool,
    /// Its share of the window's samples.
    pub(super) share: f64,
}

/// The warnings of a run whose last row is `last`, whose reference stayed within
/// ±`reference_peak` over the window, whose mean NIS over it is `nis` against `band`, and whose
/// speed has stayed off its reference as `astray` says, if it has.
pub(super) fn warnings_of(
    last: &Row,
    reference_peak: f64,
    nis: f64,
    band: (f64, f64),
    astray: Option<Astray>,
) -> Vec<Warning> {
    let mut out = Vec::new();
    let target = last.flux_ref;
    if last.omega_err.abs() > 2.0 * reference_peak + RUNAWAY_SPEED
        || last.flux > RUNAWAY_FLUX * target
    {
        out.push(Warning {
            kind: WarningKind::Runaway,
            figure: None,
            text: Message::new("warning-runaway")
                .rounded("speed", last.omega_err, 3)
                .rounded("estimate", -last.omega_est_err, 3)
                .rounded("flux", last.flux, 3)
                .rounded("target", target, 3),
        });
    }
    // A run that ran away is said to, not also to stray.
    let ran_away = !out.is_empty();
    if let Some(a) = astray.filter(|a| !ran_away && a.share >= ASTRAY_SHARE) {
        let id = if a.from_window_start {
            "warning-not-following-window"
        } else {
            "warning-not-following"
        };
        out.push(Warning {
            kind: WarningKind::NotFollowing,
            figure: None,
            text: Message::new(id)
                .time("since", a.since)
                .rounded("error", last.omega_err, 3)
                .rounded("reference", last.omega_ref, 4)
                .real("share", 100.0 * super::window::FOLLOW_SHARE)
                .real("margin", super::window::FOLLOW_MARGIN),
        });
    }
    let (low, high) = band;
    let describe = |id: &'static str| Warning {
        kind: WarningKind::Inconsistent,
        figure: None,
        text: Message::new(id)
            .rounded("nis", nis, 4)
            .rounded("low", low, 3)
            .rounded("high", high, 3),
    };
    if nis > FAR_OUTSIDE * high {
        out.push(describe("warning-inconsistent-above"));
    } else if nis < low / FAR_OUTSIDE {
        out.push(describe("warning-inconsistent-below"));
    }
    out
}

/// The 95 % band (low, high) of the mean NIS of a consistent filter over `samples` samples.
///
/// For a consistent filter with 2 measurements, each NIS is χ²(2); if the samples were
/// independent, N·mean would be χ²(2N). Its quantiles come from the Wilson–Hilferty
/// approximation k(1 − 2/(9k) + z·(2/(9k))^½)³ with k = 2N, z = ∓1.96. The NIS of a filter that
/// is not consistent is correlated from sample to sample, so the band only tells a consistent
/// filter from one that is not; it is not a confidence interval for an inconsistent one.
pub(super) fn mean_nis_band(samples: usize) -> (f64, f64) {
    let n = samples as f64;
    let k = 2.0 * n;
    let a = 2.0 / (9.0 * k);
    let quantile = |z: f64| {
        let c = 1.0 - a + z * a.sqrt();
        k * c * c * c / n
    };
    (quantile(-Z_975), quantile(Z_975))
}
