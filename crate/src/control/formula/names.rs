//! The signals a formula may read: their names, TeX, units and meanings, in the controller's order.

/// A named signal a formula may use: its name, its symbol in TeX, its unit and its meaning, and
/// the first step whose formula may use it (the later steps' errors and virtual controls follow
/// from the earlier steps' laws).
#[cfg_attr(
    target_arch = "wasm32",
    derive(tsify::Tsify),
    tsify(missing_as_null, hashmap_as_object)
)]
#[derive(Clone, Copy, Debug, serde::Serialize)]
pub struct Name {
    /// The name in a formula.
    pub name: &'static str,
    /// Its symbol, in TeX.
    pub tex: &'static str,
    /// Its unit.
    pub unit: &'static str,
    /// Its meaning.
    pub doc: &'static str,
    /// The first step (1–4) whose law may use it.
    pub from_step: u8,
}

const fn name(
    name: &'static str,
    tex: &'static str,
    unit: &'static str,
    doc: &'static str,
    from_step: u8,
) -> Name {
    Name {
        name,
        tex,
        unit,
        doc,
        from_step,
    }
}

/// Every name a formula may use, in the order of the signal vector the controller fills.
#[rustfmt::skip]
pub const NAMES: &[Name] = &[
    name("x1h", r"\hat{x}_1", "rad/s", "estimated rotor speed ω̂ (posterior x̂1)", 1),
    name("x2h", r"\hat{x}_2", "A", "estimated stator current î_sa", 1),
    name("x3h", r"\hat{x}_3", "A", "estimated stator current î_sb", 1),
    name("x4h", r"\hat{x}_4", "Wb", "estimated rotor flux φ̂_ra", 1),
    name("x5h", r"\hat{x}_5", "Wb", "estimated rotor flux φ̂_rb", 1),
    name("x2", "x_2", "A", "measured stator current i_sa", 1),
    name("x3", "x_3", "A", "measured stator current i_sb", 1),
    name("xt2", r"\tilde{x}_2", "A", "residual x̃2 = x2 − x̂2", 1),
    name("xt3", r"\tilde{x}_3", "A", "residual x̃3 = x3 − x̂3", 1),
    name("dxt2", r"\dot{\tilde{x}}_2", "A/s", "nominal rate of x̃2: −(a7 + l21)·x̃2 − l22·x̃3", 1),
    name("dxt3", r"\dot{\tilde{x}}_3", "A/s", "nominal rate of x̃3: −l31·x̃2 − (a7 + l32)·x̃3", 1),
    name("dx4h", r"\dot{\hat{x}}_4", "Wb/s", "observer rate of x̂4: −a8·x̂4 − a9·x̂1·x̂5 + a10·x̂2 + si4", 1),
    name("dx5h", r"\dot{\hat{x}}_5", "Wb/s", "observer rate of x̂5: −a8·x̂5 + a9·x̂1·x̂4 + a10·x̂3 + si5", 1),
    name("wd", r"\omega_d", "rad/s", "speed reference ω_d", 1),
    name("dwd", r"\dot{\omega}_d", "rad/s²", "its first derivative", 1),
    name("ddwd", r"\ddot{\omega}_d", "rad/s³", "its second derivative", 1),
    name("psi_d", r"\psi_d", "Wb²", "flux target for x̂4² + x̂5²", 1),
    name("si1", r"\mathit{si}_1", "rad/s²", "observer injection into x̂1: l11·x̃2 + l12·x̃3", 1),
    name("si2", r"\mathit{si}_2", "A/s", "observer injection into x̂2", 1),
    name("si3", r"\mathit{si}_3", "A/s", "observer injection into x̂3", 1),
    name("si4", r"\mathit{si}_4", "Wb/s", "observer injection into x̂4", 1),
    name("si5", r"\mathit{si}_5", "Wb/s", "observer injection into x̂5", 1),
    name("l11", "l_{11}", "rad/(A s²)", "observer gain L = K/Ts, row 1, column 1", 1),
    name("l12", "l_{12}", "rad/(A s²)", "observer gain, row 1, column 2", 1),
    name("l21", "l_{21}", "1/s", "observer gain, row 2, column 1", 1),
    name("l22", "l_{22}", "1/s", "observer gain, row 2, column 2", 1),
    name("l31", "l_{31}", "1/s", "observer gain, row 3, column 1", 1),
    name("l32", "l_{32}", "1/s", "observer gain, row 3, column 2", 1),
    name("l41", "l_{41}", "Wb/(A s)", "observer gain, row 4, column 1", 1),
    name("l42", "l_{42}", "Wb/(A s)", "observer gain, row 4, column 2", 1),
    name("l51", "l_{51}", "Wb/(A s)", "observer gain, row 5, column 1", 1),
    name("l52", "l_{52}", "Wb/(A s)", "observer gain, row 5, column 2", 1),
    name("a1", "a_1", "1/(kg m²)", "μ = 3·np·M/(2·J·Lr): a1·(x3·x̂4 − x2·x̂5) is the torque over J", 1),
    name("a2", "a_2", "rad/s²", "T0/J (the estimate â2 when the EKF estimates the load)", 1),
    name("a3", "a_3", "1/s", "Cf/J", 1),
    name("a5", "a_5", "1/(H s)", "α·β, with α = Rr/Lr and β = M/(σ·Lr)", 1),
    name("a6", "a_6", "1/H", "np·β", 1),
    name("a7", "a_7", "1/s", "γ = Rs/σ + α·β·M", 1),
    name("a8", "a_8", "1/s", "α = Rr/Lr", 1),
    name("a9", "a_9", "", "np", 1),
    name("a10", "a_{10}", "Ω", "α·M", 1),
    name("b", "b", "1/H", "1/σ", 1),
    name("da2", r"\dot{\hat{a}}_2", "rad/s³", "rate of â2 (its injection) when the EKF estimates the load, else 0", 1),
    name("k1", "k_1", "1/s", "speed-error rate", 1),
    name("k2", "k_2", "1/s", "torque-error rate (k2 = a7 + a8 + k2s1)", 1),
    name("k3", "k_3", "1/s", "flux-error rate", 1),
    name("k4", "k_4", "1/s", "flux-rate-error rate", 1),
    name("k1s1", "k_{1s1}", "1/s", "k1 − a3", 1),
    name("k2s1", "k_{2s1}", "1/s", "k2 − a7 − a8", 1),
    name("h2", "h_2", "rad/s³", "bound on |d̃2| of (38)", 1),
    name("eps2", r"\varepsilon_2", "rad²/s⁵", "ε2 of (38)", 1),
    name("h4", "h_4", "Wb²/s²", "bound on |d̃4| of (53)", 1),
    name("eps4", r"\varepsilon_4", "Wb⁴/s³", "ε4 of (53)", 1),
    name("robust", r"\rho", "", "1 when the robust terms (38) and (53) are on, else 0", 1),
    name("z1", "z_1", "rad/s", "speed error x̂1 − ω_d", 1),
    name("z3", "z_3", "Wb²", "flux error x̂4² + x̂5² − ψ_d", 1),
    name("v1", "v_1", "rad/s²", "step 1's virtual control (yours when you wrote it)", 2),
    name("z2", "z_2", "rad/s²", "torque error a1·(x3·x̂4 − x2·x̂5) − v1", 2),
    name("v3", "v_3", "Wb²/s", "step 3's virtual control (yours when you wrote it)", 4),
    name("z4", "z_4", "Wb²/s", "flux-rate error 2·a10·(x2·x̂4 + x3·x̂5) − v3", 4),
];

/// The number of signals the controller fills.
pub const SIGNALS: usize = NAMES.len();

/// The index of `name` in [`NAMES`].
pub fn index(name: &str) -> Option<usize> {
    NAMES.iter().position(|n| n.name == name)
}

/// The index of `name` in [`NAMES`], when compiled (a name that is not there fails the build).
pub const fn at(name: &str) -> usize {
    let mut i = 0;
    while i < NAMES.len() {
        let (a, b) = (NAMES[i].name.as_bytes(), name.as_bytes());
        if a.len() == b.len() {
            let mut j = 0;
            while j < a.len() && a[j] == b[j] {
                j += 1;
            }
            if j == a.len() {
                return i;
            }
        }
        i += 1;
    }
    panic!("not a signal name")
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::control::formula::FUNCTIONS;

    #[test]
    fn every_name_is_unique_and_documented() {
        for (i, n) in NAMES.iter().enumerate() {
            assert_eq!(index(n.name), Some(i), "{}", n.name);
            assert!(!n.doc.is_empty() && !n.tex.is_empty(), "{}", n.name);
            assert!((1..=4).contains(&n.from_step));
            assert!(FUNCTIONS.iter().all(|f| f.0 != n.name));
        }
    }
}
