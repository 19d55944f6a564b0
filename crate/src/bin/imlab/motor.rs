//! `imlab motor`: a motor's equivalent circuit from its nameplate and a lab's no-load and
//! locked-rotor tests (IEEE Std 112), written as the fields of a link that uses it.

use crate::output::{stdout_stop, Stop};
use imlab::identify::{identify, Entry};
use std::io::Write;

/// The options of `imlab motor`, as given: the core reads them (`identify::Entry`) and names a bad one.
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

/// Estimates the circuit and prints it, each value with how it was found, and the link of preset
/// `step` that uses it, plant and model alike, with the derived design.
pub(crate) fn motor(a: &MotorArgs, out: &mut impl Write) -> Result<(), Stop> {
    let entry = Entry {
        rs: a.rs.clone(),
        no_load: a.no_load.clone(),
        locked: a.locked.clone(),
        nema: a.nema.clone(),
        rated: a.rated.clone(),
        j: a.j.clone(),
        np: a.np.clone(),
    };
    let found = identify(&entry).map_err(|e| e.to_string())?;
    let write = |out: &mut dyn Write| -> std::io::Result<()> {
        writeln!(out, "# {}", found.heading)?;
        for l in &found.lines {
            writeln!(
                out,
                "{:3} = {:>10} {:6} {}",
                l.key,
                imlab::text::rounded(l.value, 4),
                l.unit,
                l.rule
            )?;
        }
        writeln!(
            out,
            "# {}",
            imlab::text::Message::new("identify-link-heading")
        )?;
        writeln!(out, "{}", found.link)
    };
    write(out).map_err(stdout_stop)
}
