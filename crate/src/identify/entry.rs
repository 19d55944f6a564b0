//! A motor as a lab writes it down: the text of its nameplate and tests (`imlab motor`'s options,
//! the Analysis tab's form), read field by field, and what both show of its circuit: each value
//! with how it was found, and the link that runs it with the design derived from it.

use super::{circuit, readings, IdentifyError, Nema, Reading, Tests, MACHINE, MACHINE_RATING};
use crate::design::Line;
use crate::scenario::{compose, parse_number, Scenario, ScenarioError};
use crate::text::{excerpt, rounded, Message};
use serde::{Deserialize, Serialize};

/// The nameplate and the tests as typed, each field as `imlab motor` takes its option.
#[cfg_attr(
    target_arch = "wasm32",
    derive(tsify::Tsify),
    tsify(missing_as_null, hashmap_as_object)
)]
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub struct Entry {
    /// Stator resistance per phase from the DC test (Ω).
    pub rs: String,
    /// The no-load test at rated voltage: `V,I,P,F` (V rms line to line, A rms, W, Hz).
    pub no_load: String,
    /// The locked-rotor test, as `no_load`.
    pub locked: String,
    /// The rotor's NEMA design letter: A, B, C or D.
    pub nema: String,
    /// The nameplate: `V,F,I` (V rms line to line, Hz, A rms).
    pub rated: String,
    /// Rotor inertia (kg m²).
    pub j: String,
    /// Pole pairs.
    pub np: String,
}

/// The circuit found, for `imlab motor` and the page.
#[cfg_attr(
    target_arch = "wasm32",
    derive(tsify::Tsify),
    tsify(missing_as_null, hashmap_as_object)
)]
#[derive(Clone, Debug, Serialize)]
pub struct Identified {
    /// The method, with the leakage split the design letter sets.
    pub heading: Message,
    /// Each value of the circuit with how it was found: measured, estimated or given.
    pub lines: Vec<Line>,
    /// Preset `step` with that motor as plant and model, its rating and the derived design.
    pub link: String,
}

/// Why an entry gives no motor.
#[derive(Clone, Debug, PartialEq)]
pub enum EntryError {
    /// A field that does not read as what it takes.
    Bad {
        /// The field (`imlab motor`'s option without its dashes).
        key: &'static str,
        /// What was typed.
        value: String,
        /// What it takes.
        expected: Message,
    },
    /// Readings that no circuit gives.
    Circuit(IdentifyError),
    /// A circuit or a rating the scenario refuses.
    Scenario(ScenarioError),
}

impl EntryError {
    /// What it says, as a message of `core-analysis.ftl`.
    pub fn message(&self) -> Message {
        match self {
            EntryError::Bad {
                key,
                value,
                expected,
            } => Message::new("identify-bad-field")
                .text("key", *key)
                .text("value", excerpt(value))
                .said("expected", expected.clone()),
            EntryError::Circuit(e) => e.message(),
            EntryError::Scenario(e) => e.message(),
        }
    }
}

impl std::fmt::Display for EntryError {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        self.message().fmt(f)
    }
}

impl std::error::Error for EntryError {}

/// `N` numbers of field `key`, separated by commas, each accepted by `ok`; `what` names them.
fn numbers<const N: usize>(
    key: &'static str,
    text: &str,
    ok: impl Fn(usize, f64) -> bool,
    what: &'static str,
) -> Result<[f64; N], EntryError> {
    let bad = || EntryError::Bad {
        key,
        value: text.to_string(),
        expected: Message::new(what),
    };
    let values: Vec<f64> = text
        .split(',')
        .map(|v| parse_number(v.trim()))
        .collect::<Option<_>>()
        .ok_or_else(bad)?;
    let values: [f64; N] = values.try_into().map_err(|_| bad())?;
    if values
        .iter()
        .enumerate()
        .all(|(i, &v)| v.is_finite() && ok(i, v))
    {
        Ok(values)
    } else {
        Err(bad())
    }
}

/// A test's reading from `V,I,P,F`: voltage, current and frequency positive, the power not
/// negative.
fn reading(key: &'static str, text: &str) -> Result<Reading, EntryError> {
    let [voltage, current, power, frequency] = numbers(
        key,
        text,
        |i, v| v > 0.0 || (i == 2 && v == 0.0),
        "identify-expect-reading",
    )?;
    Ok(Reading {
        voltage,
        current,
        power,
        frequency,
    })
}

impl Entry {
    /// [`MACHINE`] as a lab would write it down: its rating, and the readings its circuit gives at
    /// no load and locked at a quarter of the rated voltage and frequency, to four digits.
    pub fn example() -> Entry {
        let (v, f, i) = MACHINE_RATING;
        let (no_load, locked) = readings(&MACHINE, (v, f), (v / 4.0, f / 4.0));
        let text = |r: Reading| {
            [r.voltage, r.current, r.power, r.frequency]
                .map(|x| rounded(x, 4))
                .join(",")
        };
        Entry {
            rs: MACHINE.rs.to_string(),
            no_load: text(no_load),
            locked: text(locked),
            nema: "A".into(),
            rated: format!("{v},{f},{i}"),
            j: MACHINE.j.to_string(),
            np: MACHINE.np.to_string(),
        }
    }
}

/// The motor of `e`: its circuit by IEEE Std 112's no-load and locked-rotor tests, and the link that
/// runs it.
pub fn identify(e: &Entry) -> Result<Identified, EntryError> {
    let [rs] = numbers("rs", &e.rs, |_, v| v > 0.0, "identify-expect-positive")?;
    let nema = match e.nema.trim() {
        "A" => Nema::A,
        "B" => Nema::B,
        "C" => Nema::C,
        "D" => Nema::D,
        _ => {
            return Err(EntryError::Bad {
                key: "nema",
                value: e.nema.clone(),
                expected: Message::new("identify-expect-nema"),
            })
        }
    };
    let [voltage, frequency, current] =
        numbers("rated", &e.rated, |_, v| v > 0.0, "identify-expect-rated")?;
    let [j] = numbers("j", &e.j, |_, v| v > 0.0, "identify-expect-positive")?;
    let [np] = numbers(
        "np",
        &e.np,
        |_, v| v >= 1.0 && v.fract() == 0.0,
        "identify-expect-whole",
    )?;
    let tests = Tests {
        rs,
        no_load: reading("no-load", &e.no_load)?,
        locked: reading("locked", &e.locked)?,
        nema,
        frequency,
    };
    let c = circuit(&tests, j, np).map_err(EntryError::Circuit)?;
    let mut fields = Vec::new();
    for side in ["plant", "model"] {
        for (key, v) in [
            ("rs", c.rs),
            ("rr", c.rr),
            ("m", c.m),
            ("ls", c.ls),
            ("lr", c.lr),
            ("j", j),
            ("np", np),
        ] {
            fields.push((format!("{side}.{key}"), v.to_string()));
        }
    }
    fields.push(("i_rated".into(), (current * 2f64.sqrt()).to_string()));
    fields.push(("rated.v".into(), voltage.to_string()));
    fields.push(("rated.f".into(), frequency.to_string()));
    fields.push(("design".into(), "derived".into()));
    let link = Scenario::parse(&compose("step", &fields))
        .map_err(EntryError::Scenario)?
        .encode();
    let split = nema.stator_share();
    let line = |key, value, unit, how: &'static str| Line {
        key,
        value,
        unit,
        rule: Message::new(how),
    };
    Ok(Identified {
        heading: Message::new("identify-heading")
            .short("stator", split)
            .short("rotor", 1.0 - split)
            .text("letter", e.nema.trim()),
        lines: vec![
            line("rs", c.rs, "Ω", "identify-how-rs"),
            line("rr", c.rr, "Ω", "identify-how-rr"),
            line("m", c.m, "H", "identify-how-m"),
            line("ls", c.ls, "H", "identify-how-ls"),
            line("lr", c.lr, "H", "identify-how-lr"),
            line("j", j, "kg m²", "identify-how-given"),
            line("np", np, "", "identify-how-given"),
        ],
        link,
    })
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_example_gives_the_machine_it_was_read_from_and_its_link_runs_it() {
        let found = identify(&Entry::example()).unwrap();
        let s = Scenario::parse(&found.link).unwrap();
        // Four digits of each reading bring the circuit back to about a part in a thousand.
        for (name, got, true_value) in [
            ("rr", s.model.rr, MACHINE.rr),
            ("m", s.model.m, MACHINE.m),
            ("ls", s.model.ls, MACHINE.ls),
        ] {
            assert!(
                (got / true_value - 1.0).abs() < 2e-3,
                "{name}: {got} against {true_value}"
            );
        }
        assert_eq!(s.plant, s.model);
        assert_eq!(found.lines.len(), 7);
        assert!(found.heading.to_string().contains("0.5/0.5"));
    }

    #[test]
    fn a_bad_field_is_named_with_what_it_takes() {
        let refused = |edit: fn(&mut Entry)| {
            let mut e = Entry::example();
            edit(&mut e);
            identify(&e).unwrap_err().to_string()
        };
        let text = refused(|e| e.no_load = "400,2.9,98".into());
        assert!(
            text.starts_with("'no-load' = '400,2.9,98': expected V,I,P,F"),
            "{text}"
        );
        assert!(refused(|e| e.nema = "E".into()).starts_with("'nema' = 'E'"));
        assert!(refused(|e| e.np = "1.5".into()).starts_with("'np' = '1.5'"));
        assert!(refused(|e| e.rs = "-3".into()).starts_with("'rs' = '-3'"));
        assert!(refused(|e| e.rated = "400,50".into()).starts_with("'rated' = '400,50'"));
        // Readings that are numbers but no circuit: the test at fault is named.
        let text = refused(|e| e.locked = "100,9.2,1e6,12.5".into());
        assert!(
            text.starts_with("'locked': ") && text.contains("√3·V·I"),
            "{text}"
        );
        assert!(refused(|e| e.rs = "100".into()).starts_with("'locked': "));
    }
}
