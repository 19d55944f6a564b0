//! `imlab motor`: a motor's equivalent circuit from its nameplate and a lab's no-load and
//! locked-rotor tests (IEEE Std 112), written as the fields of a link that uses it.

use crate::cli::number;
use crate::output::{stdout_stop, Stop};
use imlab::identify::{circuit, Nema, Reading, Tests};
use imlab::scenario::Scenario;
use std::io::Write;

/// The values of option `flag`, `count` positive numbers separated by commas.
fn numbers<const N: usize>(flag: &str, text: &str, what: &str) -> Result<[f64; N], String> {
    let values: Vec<f64> = text
        .split(',')
        .map(|v| number(flag, v.trim(), |x: &f64| x.is_finite() && *x >= 0.0, what))
        .collect::<Result<_, _>>()?;
    values.try_into().map_err(|_| {
        format!(
            "{flag} '{}': expected {N} numbers separated by commas ({what})",
            imlab::text::excerpt(text)
        )
    })
}

/// A test's reading from `V,I,P,F`.
fn reading(flag: &str, text: &str) -> Result<Reading, String> {
    let [voltage, current, power, frequency] =
        numbers(flag, text, "V,I,P,F: volts, amperes, watts, hertz")?;
    Ok(Reading {
        voltage,
        current,
        power,
        frequency,
    })
}

/// The options of `imlab motor`, as given (strings: `number` quotes a bad one through `excerpt`).
#[derive(clap::Args)]
pub(crate) struct MotorArgs {
    /// Stator resistance per phase from the DC test (Ω)
    #[arg(long, value_name = "OHMS", allow_hyphen_values = true)]
    rs: String,
    /// The no-load test at rated voltage: line voltage (V rms), line current (A rms), input
    /// power (W), frequency (Hz)
    #[arg(long, value_name = "V,I,P,F", allow_hyphen_values = true)]
    no_load: String,
    /// The locked-rotor test, as --no-load
    #[arg(long, value_name = "V,I,P,F", allow_hyphen_values = true)]
    locked: String,
    /// The rotor's NEMA design letter, which splits the locked-rotor leakage: A or D half each,
    /// B 40/60, C 30/70 (stator/rotor)
    #[arg(long, value_name = "LETTER", default_value = "B")]
    nema: String,
    /// The nameplate: rated line voltage (V rms), frequency (Hz) and current (A rms)
    #[arg(long, value_name = "V,F,I", allow_hyphen_values = true)]
    rated: String,
    /// Rotor inertia (kg m²)
    #[arg(long, value_name = "KG_M2", allow_hyphen_values = true)]
    j: String,
    /// Pole pairs
    #[arg(long, value_name = "N", allow_hyphen_values = true)]
    np: String,
}

/// Estimates the circuit and prints it with the link of preset `step` that uses it, plant and
/// model alike, with the derived design.
pub(crate) fn motor(a: &MotorArgs, out: &mut impl Write) -> Result<(), Stop> {
    let positive = |x: &f64| x.is_finite() && *x > 0.0;
    let rs = number("--rs", &a.rs, positive, "a positive resistance in Ω")?;
    let nema = match a.nema.as_str() {
        "A" => Nema::A,
        "B" => Nema::B,
        "C" => Nema::C,
        "D" => Nema::D,
        _ => Err(format!(
            "--nema '{}': expected A, B, C or D",
            imlab::text::excerpt(&a.nema)
        ))?,
    };
    let [voltage, frequency, current] =
        numbers("--rated", &a.rated, "V,F,I: volts, hertz, amperes rms")?;
    let j = number("--j", &a.j, positive, "a positive inertia in kg m²")?;
    let np = number(
        "--np",
        &a.np,
        |n: &f64| *n >= 1.0 && n.fract() == 0.0,
        "a whole number ≥ 1",
    )?;
    let tests = Tests {
        rs,
        no_load: reading("--no-load", &a.no_load)?,
        locked: reading("--locked", &a.locked)?,
        nema,
        frequency,
    };
    let c = circuit(&tests, j, np).map_err(|e| e.to_string())?;
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
    let s =
        Scenario::parse(&imlab::scenario::compose("step", &fields)).map_err(|e| e.to_string())?;
    let write = |out: &mut dyn Write| -> std::io::Result<()> {
        let split = nema.stator_share();
        writeln!(
            out,
            "# the equivalent circuit from the no-load and locked-rotor tests (IEEE Std 112), the locked-rotor leakage split {}/{} between stator and rotor (NEMA design {})",
            split,
            1.0 - split,
            a.nema
        )?;
        for (key, v, unit, how) in [
            ("rs", c.rs, "Ω", "DC test"),
            (
                "rr",
                c.rr,
                "Ω",
                "estimate: locked-rotor resistance less rs, through the magnetising branch",
            ),
            (
                "m",
                c.m,
                "H",
                "estimate: no-load reactance less the stator's leakage",
            ),
            (
                "ls",
                c.ls,
                "H",
                "estimate: m and the stator's share of the locked-rotor leakage",
            ),
            (
                "lr",
                c.lr,
                "H",
                "estimate: m and the rotor's share of the locked-rotor leakage",
            ),
            ("j", j, "kg m²", "given"),
            ("np", np, "", "given"),
        ] {
            writeln!(
                out,
                "{key:3} = {:>10} {unit:6} {how}",
                imlab::text::rounded(v, 4)
            )?;
        }
        writeln!(out, "# the motor in preset step, plant and model alike, with its rating and the derived design:")?;
        writeln!(out, "{}", s.encode())
    };
    write(out).map_err(stdout_stop)
}
