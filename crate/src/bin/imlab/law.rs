//! The `law` subcommand: a scenario's own law checked against its designed error dynamics.

use crate::output::{stdout_stop, Stop};
use imlab::scenario::Scenario;
use std::io::Write;

/// Writes the verdict of each step's own law, one paragraph each; fails unless every one gives
/// its designed dynamics.
pub(crate) fn law(s: &Scenario, out: &mut impl Write) -> Result<(), Stop> {
    let model = s
        .model
        .lumped()
        .map_err(|e| format!("model parameters: {e}"))?;
    let verdicts = imlab::control::law::verdicts(&s.law, &model, &s.gains)
        .map_err(|(step, e)| format!("law.v{step}: {e}"))?;
    if verdicts.is_empty() {
        return Err(
            "the scenario has no law of its own: give law.v1, law.v2, law.v3 or law.v4"
                .to_string()
                .into(),
        );
    }
    for v in &verdicts {
        writeln!(out, "law.v{}: {}", v.step, v.text).map_err(stdout_stop)?;
    }
    match (
        verdicts.iter().filter(|v| !v.designed).count(),
        verdicts.len(),
    ) {
        (0, _) => Ok(()),
        (1, 1) => Err("the law does not give its designed dynamics"
            .to_string()
            .into()),
        (n, m) => Err(format!("{n} of {m} laws do not give their designed dynamics").into()),
    }
}
