//! The signals a formula may read: their names, TeX, units and meanings, in the controller's order.

use crate::text::Message;

/// A named signal a formula may use: its name, its symbol in TeX, its unit and its meaning, and
/// the first step whose formula may use it (the later steps' errors and virtual controls follow
/// from the earlier steps' laws).
#[derive(Clone, Copy, Debug)]
pub struct Name {
    /// The name in a formula.
    pub name: &'static str,
    /// Its symbol, in TeX.
    pub tex: &'static str,
    /// Its unit.
    pub unit: &'static str,
    /// The id of its meaning in `core-law.ftl` (see [`Name::doc`]).
    pub meaning: &'static str,
    /// The first step (1–4) whose law may use it.
    pub from_step: u8,
}

const fn name(
    name: &'static str,
    tex: &'static str,
    unit: &'static str,
    meaning: &'static str,
    from_step: u8,
) -> Name {
    Name {
        name,
        tex,
        unit,
        meaning,
        from_step,
    }
}

impl Name {
    /// Its meaning, a message of `core-law.ftl`.
    pub fn doc(&self) -> Message {
        Message::new(self.meaning)
    }
}

/// Every name a formula may use, in the order of the signal vector the controller fills, each with
/// the id of its meaning (`formula-name-` and the name, `_` written `-`).
#[rustfmt::skip]
pub const NAMES: &[Name] = &[
    name("x1h", r"\hat{x}_1", "rad/s", "formula-name-x1h", 1),
    name("x2h", r"\hat{x}_2", "A", "formula-name-x2h", 1),
    name("x3h", r"\hat{x}_3", "A", "formula-name-x3h", 1),
    name("x4h", r"\hat{x}_4", "Wb", "formula-name-x4h", 1),
    name("x5h", r"\hat{x}_5", "Wb", "formula-name-x5h", 1),
    name("x2", "x_2", "A", "formula-name-x2", 1),
    name("x3", "x_3", "A", "formula-name-x3", 1),
    name("xt2", r"\tilde{x}_2", "A", "formula-name-xt2", 1),
    name("xt3", r"\tilde{x}_3", "A", "formula-name-xt3", 1),
    name("dxt2", r"\dot{\tilde{x}}_2", "A/s", "formula-name-dxt2", 1),
    name("dxt3", r"\dot{\tilde{x}}_3", "A/s", "formula-name-dxt3", 1),
    name("dx4h", r"\dot{\hat{x}}_4", "Wb/s", "formula-name-dx4h", 1),
    name("dx5h", r"\dot{\hat{x}}_5", "Wb/s", "formula-name-dx5h", 1),
    name("wd", r"\omega_d", "rad/s", "formula-name-wd", 1),
    name("dwd", r"\dot{\omega}_d", "rad/s²", "formula-name-dwd", 1),
    name("ddwd", r"\ddot{\omega}_d", "rad/s³", "formula-name-ddwd", 1),
    name("psi_d", r"\psi_d", "Wb²", "formula-name-psi-d", 1),
    name("si1", r"\mathit{si}_1", "rad/s²", "formula-name-si1", 1),
    name("si2", r"\mathit{si}_2", "A/s", "formula-name-si2", 1),
    name("si3", r"\mathit{si}_3", "A/s", "formula-name-si3", 1),
    name("si4", r"\mathit{si}_4", "Wb/s", "formula-name-si4", 1),
    name("si5", r"\mathit{si}_5", "Wb/s", "formula-name-si5", 1),
    name("l11", "l_{11}", "rad/(A s²)", "formula-name-l11", 1),
    name("l12", "l_{12}", "rad/(A s²)", "formula-name-l12", 1),
    name("l21", "l_{21}", "1/s", "formula-name-l21", 1),
    name("l22", "l_{22}", "1/s", "formula-name-l22", 1),
    name("l31", "l_{31}", "1/s", "formula-name-l31", 1),
    name("l32", "l_{32}", "1/s", "formula-name-l32", 1),
    name("l41", "l_{41}", "Wb/(A s)", "formula-name-l41", 1),
    name("l42", "l_{42}", "Wb/(A s)", "formula-name-l42", 1),
    name("l51", "l_{51}", "Wb/(A s)", "formula-name-l51", 1),
    name("l52", "l_{52}", "Wb/(A s)", "formula-name-l52", 1),
    name("a1", "a_1", "1/(kg m²)", "formula-name-a1", 1),
    name("a2", "a_2", "rad/s²", "formula-name-a2", 1),
    name("a3", "a_3", "1/s", "formula-name-a3", 1),
    name("a5", "a_5", "1/(H s)", "formula-name-a5", 1),
    name("a6", "a_6", "1/H", "formula-name-a6", 1),
    name("a7", "a_7", "1/s", "formula-name-a7", 1),
    name("a8", "a_8", "1/s", "formula-name-a8", 1),
    name("a9", "a_9", "", "formula-name-a9", 1),
    name("a10", "a_{10}", "Ω", "formula-name-a10", 1),
    name("b", "b", "1/H", "formula-name-b", 1),
    name("da2", r"\dot{\hat{a}}_2", "rad/s³", "formula-name-da2", 1),
    name("k1", "k_1", "1/s", "formula-name-k1", 1),
    name("k2", "k_2", "1/s", "formula-name-k2", 1),
    name("k3", "k_3", "1/s", "formula-name-k3", 1),
    name("k4", "k_4", "1/s", "formula-name-k4", 1),
    name("k1s1", "k_{1s1}", "1/s", "formula-name-k1s1", 1),
    name("k2s1", "k_{2s1}", "1/s", "formula-name-k2s1", 1),
    name("h2", "h_2", "rad/s³", "formula-name-h2", 1),
    name("eps2", r"\varepsilon_2", "rad²/s⁵", "formula-name-eps2", 1),
    name("h4", "h_4", "Wb²/s²", "formula-name-h4", 1),
    name("eps4", r"\varepsilon_4", "Wb⁴/s³", "formula-name-eps4", 1),
    name("robust", r"\rho", "", "formula-name-robust", 1),
    name("z1", "z_1", "rad/s", "formula-name-z1", 1),
    name("z3", "z_3", "Wb²", "formula-name-z3", 1),
    name("v1", "v_1", "rad/s²", "formula-name-v1", 2),
    name("z2", "z_2", "rad/s²", "formula-name-z2", 2),
    name("v3", "v_3", "Wb²/s", "formula-name-v3", 4),
    name("z4", "z_4", "Wb²/s", "formula-name-z4", 4),
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
            assert!(
                !n.doc().to_string().is_empty() && !n.tex.is_empty(),
                "{}",
                n.name
            );
            assert_eq!(
                n.meaning,
                format!("formula-name-{}", n.name.replace('_', "-"))
            );
            assert!((1..=4).contains(&n.from_step));
            assert!(FUNCTIONS.iter().all(|f| f.0 != n.name));
        }
    }
}
