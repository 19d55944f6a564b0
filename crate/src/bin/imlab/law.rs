//! The `law` subcommand: a scenario's own law checked against its designed error dynamics.

use crate::output::{stdout_stop, Stop};
use imlab::scenario::Scenario;
use imlab::text::Message;
use std::io::Write;

/// Writes the verdict of each step's own law, one paragraph each; fails unless every one gives
/// its designed dynamics.
pub(crate) fn law(s: &Scenario, out: &mut impl Write) -> Result<(), Stop> {
    let model = s.model.lumped().map_err(|e| {
        Message::new("scenario-physics")
            .text("which", "model")
            .said("error", e.message())
            .to_string()
    })?;
    let verdicts = imlab::control::law::verdicts(&s.law, &model, &s.gains)
        .map_err(|(step, e)| imlab::control::law::refused(step, &e).to_string())?;
    if verdicts.is_empty() {
        return Err(Message::new("law-none").to_string().into());
    }
    for v in &verdicts {
        writeln!(out, "law.v{}: {}", v.step, v.text).map_err(stdout_stop)?;
    }
    match (
        verdicts.iter().filter(|v| !v.designed).count(),
        verdicts.len(),
    ) {
        (0, _) => Ok(()),
        (1, 1) => Err(Message::new("law-not-designed-one").to_string().into()),
        (n, m) => Err(Message::new("law-not-designed-some")
            .count("failed", n)
            .count("laws", m)
            .to_string()
            .into()),
    }
}
