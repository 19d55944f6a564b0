//! Where a scenario's motor and design come from: `motor=` sets the plant, the model and the
//! rating from the library; `design=derived` sets the controller's and observer's settings from
//! them (see [`crate::design`]); and the state the motor starts from.

use super::Scenario;
use crate::design::Derived;
use crate::inverter::Shape;
use crate::motors::motor;
use crate::observer::Predictor;
use crate::params::MotorParams;
use serde::{Deserialize, Serialize};

/// Where the controller's and observer's settings come from.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Serialize, Deserialize)]
#[serde(rename_all = "lowercase")]
pub enum DesignKind {
    /// The values the scenario holds: the presets hold the paper's design.
    #[default]
    Paper,
    /// Derived from the model's motor, its rating and the sampling by [`crate::design`], for the
    /// settings the link does not give.
    Derived,
}

/// The state the motor starts from, and the estimate (1 − e) times it.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Serialize, Deserialize)]
#[serde(rename_all = "lowercase")]
pub enum Start {
    /// Section 5's x(0) = [ω_d(0), 2, 2, 0.5, 0.5].
    #[default]
    Paper,
    /// Magnetised at the flux target, with the current that holds that flux in steady state at
    /// rest, at 45°, at the reference's start speed ω_d(0) (0 in the presets).
    Magnetized,
}

impl Scenario {
    /// The design [`crate::design`] derives from this scenario's model, rating and sampling
    /// (whether or not the scenario uses it).
    pub fn derived(&self) -> Result<Derived, crate::design::DesignError> {
        crate::design::derive(&self.design_inputs())
    }

    /// What [`crate::design`] derives the design from: the model, the rating and the sampling.
    pub fn design_inputs(&self) -> crate::design::Inputs {
        crate::design::Inputs {
            model: self.model,
            i_rated: self.i_rated,
            voltage: self.rated_v,
            frequency: self.rated_f,
            ts: self.ts,
            noise: self.noise,
        }
    }

    /// The flux target and its derivatives at speed reference `r`: ψ_d, weakened above base
    /// speed with `fw`.
    pub fn flux_target(&self, r: &crate::control::RefSample) -> crate::control::RefSample {
        // The IFOC baseline regulates a constant flux: field weakening is the backstepping's.
        let weakens = self.fw && self.controller == super::ControllerKind::Backstepping;
        crate::control::flux_target(self.psi_d, weakens.then_some(self.fw_base), r)
    }

    /// The state x(0) the motor starts from.
    pub fn start_state(&self) -> [f64; 5] {
        let w = self.reference.sample(0.0).value;
        match self.start {
            Start::Paper => [w, 2.0, 2.0, 0.5, 0.5],
            Start::Magnetized => {
                // The flux at the target (weakened at the start speed), and the current M·i = φ.
                let flux = (self.flux_target(&self.reference.sample(0.0)).value / 2.0).sqrt();
                let i = flux / self.plant.m;
                [w, i, i, flux, flux]
            }
        }
    }
}

/// The fields [`set_motor`] sets: each side's circuit and inertia, and the rating.
const MOTOR_SET: &[&str] = &[
    "plant.rs", "plant.rr", "plant.m", "plant.ls", "plant.lr", "plant.j", "plant.np", "model.rs",
    "model.rr", "model.m", "model.ls", "model.lr", "model.j", "model.np", "i_rated", "rated.v",
    "rated.f",
];

/// The fields a new value of field `key` sets afresh in `s` (see [`FieldInfo::resets`]): a new
/// reference kind has parameters of its own, a motor sets its values, and with the derived
/// design, a value the design is derived from sets it.
pub(super) fn resets(key: &str, s: &Scenario) -> &'static [&'static str] {
    let derived = s.design == DesignKind::Derived || key == "design";
    match key {
        "ref" => {
            static KINDS: std::sync::OnceLock<Vec<&'static str>> = std::sync::OnceLock::new();
            KINDS.get_or_init(|| {
                let of_a_kind = ["ref.", "sine.", "step.", "ramp.", "rev."];
                super::fields::fields()
                    .iter()
                    .map(|f| f.key)
                    .filter(|k| of_a_kind.iter().any(|p| k.starts_with(p)))
                    .collect()
            })
        }
        "motor" if derived => {
            // The fields a motor and the derived design set.
            static BOTH: std::sync::OnceLock<Vec<&'static str>> = std::sync::OnceLock::new();
            BOTH.get_or_init(|| [MOTOR_SET, DESIGN_SET].concat())
        }
        "motor" => MOTOR_SET,
        _ if derived && DESIGN_INPUTS.contains(&key) => DESIGN_SET,
        _ => &[],
    }
}

/// Sets the plant and the model to library motor `name` (their load, T_0 and C_f, kept), and the
/// rated current to its rating.
pub(super) fn set_motor(s: &mut Scenario, name: &str) {
    let m = motor(name).expect("checked option");
    for side in [&mut s.plant, &mut s.model] {
        *side = MotorParams {
            t0: side.t0,
            cf: side.cf,
            ..m.params
        };
    }
    s.i_rated = m.rated_current().0;
    s.rated_v = m.voltage;
    s.rated_f = m.frequency;
    s.motor = m.name.to_string();
}

/// The settings the derived design gives (see [`crate::design`]).
pub const DESIGN_SET: &[&str] = &[
    "psi_d",
    "fw",
    "fw.base",
    "k1",
    "k2",
    "k3",
    "k4",
    "ekf",
    "ekf.q",
    "ekf.q_speed",
    "ekf.r_std",
    "ekf.q_load",
    "ekf.load_std",
    "start",
    "vlimit",
    "vdc",
];

/// The fields the derived design is derived from: in a form, a new value of one sets the design
/// afresh (see [`resets`]), as a link is derived again when it is parsed. [`Scenario::set`] keeps
/// the design as it stands: a map's or a sweep's axis varies one value under a fixed design.
const DESIGN_INPUTS: &[&str] = &[
    "design", "motor", "model.rs", "model.rr", "model.m", "model.ls", "model.lr", "model.j",
    "model.np", "i_rated", "rated.v", "rated.f", "ts", "noise",
];

/// Sets in `s` each setting of design `d` for which `keep` is false.
pub(super) fn apply_design(s: &mut Scenario, d: &Derived, keep: &dyn Fn(&str) -> bool) {
    macro_rules! put {
        ($($key:literal => $place:expr, $value:expr;)*) => {
            $(if !keep($key) {
                $place = $value;
            })*
        };
    }
    put! {
        "psi_d" => s.psi_d, d.psi_d;
        "fw" => s.fw, true;
        "fw.base" => s.fw_base, d.base;
        "k1" => s.gains.k1, d.gains[0];
        "k2" => s.gains.k2, d.gains[1];
        "k3" => s.gains.k3, d.gains[2];
        "k4" => s.gains.k4, d.gains[3];
        "ekf" => s.ekf.predictor, Predictor::Rk4;
        "ekf.q" => s.ekf.q, d.q;
        "ekf.q_speed" => s.ekf.q_speed, d.q_speed;
        "ekf.r_std" => s.ekf.r_std, d.r_std;
        "ekf.q_load" => s.ekf.q_load, d.q_load;
        "ekf.load_std" => s.ekf.load_std, d.load_std;
        "start" => s.start, Start::Magnetized;
        "vlimit" => s.drive.vlimit, Shape::Circle;
        "vdc" => s.drive.vdc, d.vdc;
    }
}

/// `design=`: the derived design from the scenario as it stands (the parser derives it again
/// from the link's final motor, rating and sampling), or the preset's settings back.
pub(super) fn set_design(s: &mut Scenario, name: &str) {
    if name == "derived" {
        s.design = DesignKind::Derived;
        if let Ok(d) = s.derived() {
            apply_design(s, &d, &|_| false);
        }
    } else {
        let o = super::preset(&s.preset).expect("a scenario's preset exists");
        s.design = DesignKind::Paper;
        s.psi_d = o.psi_d;
        (s.fw, s.fw_base, s.start) = (o.fw, o.fw_base, o.start);
        s.gains.k1 = o.gains.k1;
        s.gains.k2 = o.gains.k2;
        s.gains.k3 = o.gains.k3;
        s.gains.k4 = o.gains.k4;
        let (e, oe) = (&mut s.ekf, &o.ekf);
        (e.predictor, e.q, e.q_speed, e.r_std) = (oe.predictor, oe.q, oe.q_speed, oe.r_std);
        (e.q_load, e.load_std) = (oe.q_load, oe.load_std);
        (s.drive.vlimit, s.drive.vdc) = (o.drive.vlimit, o.drive.vdc);
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::scenario::{preset, DESIGN_SET};

    /// The text of field `key` in `s`.
    fn value(s: &Scenario, key: &str) -> Option<String> {
        s.describe()
            .into_iter()
            .find(|f| f.key == key)
            .unwrap()
            .value
    }

    #[test]
    fn the_derived_design_round_trips_keeps_a_links_own_values_and_goes_back_to_the_papers() {
        let s = Scenario::parse("v=1&preset=step&design=derived&motor=2.2kw&k1=100").unwrap();
        let d = s.derived().unwrap();
        // The link's own k1 stands; the rest is the rule's, from the motor set after `design`.
        assert_eq!(s.gains.k1, 100.0);
        assert_eq!(
            (s.gains.k2, s.psi_d, s.fw_base),
            (d.gains[1], d.psi_d, d.base)
        );
        assert!(s.fw && s.start == Start::Magnetized && s.drive.vlimit == Shape::Circle);
        assert_eq!(
            s.encode(),
            "v=1&preset=step&design=derived&k1=100&motor=2.2kw"
        );
        assert_eq!(Scenario::parse(&s.encode()).unwrap(), s);
        // Back to the paper's design: every setting of the design is the preset's again.
        let mut back = s.clone();
        back.set("design", "paper").unwrap();
        let step = preset("step").unwrap();
        for key in DESIGN_SET {
            assert_eq!(value(&back, key), value(&step, key), "{key}");
        }
    }

    #[test]
    fn a_magnetized_start_holds_the_flux_target_with_the_current_that_makes_it() {
        let s = Scenario::parse("v=1&preset=step&design=derived&motor=15kw").unwrap();
        let [w, ia, ib, fa, fb] = s.start_state();
        assert_eq!(w, s.reference.sample(0.0).value);
        assert!(((fa * fa + fb * fb) / s.psi_d - 1.0).abs() < 1e-12);
        assert!((ia * s.plant.m / fa - 1.0).abs() < 1e-12 && ia == ib);
        // The presets start where Section 5 does.
        assert_eq!(
            preset("step").unwrap().start_state(),
            [0.0, 2.0, 2.0, 0.5, 0.5]
        );
    }
}
