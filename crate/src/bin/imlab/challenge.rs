//! The `challenge` subcommand: a challenge's link and brief, or the built-ins' names.

use crate::output::{stdout_stop, Stop};
use imlab::challenge::{builtin, Challenge, BUILTINS};
use std::io::{self, Write};

/// Writes the built-in challenges, one `name  summary` line each.
pub(crate) fn list_challenges(out: &mut impl Write) -> io::Result<()> {
    let width = BUILTINS.iter().map(|b| b.name.len()).max().unwrap_or(0);
    for b in BUILTINS {
        writeln!(out, "{:width$}  {}", b.name, b.summary)?;
    }
    Ok(())
}

/// Writes the challenge's canonical link, its fingerprint (and the built-in it passes for while
/// differing from it), then its brief.
pub(crate) fn show_challenge(text: &str, out: &mut impl Write) -> Result<(), Stop> {
    let c = Challenge::parse(text).map_err(|e| format!("challenge: {e}"))?;
    let mut head = format!("{}\nfingerprint: {}\n", c.encode(), c.fingerprint());
    if let Some(name) = c.edited_builtin() {
        let original = builtin(name).expect("a built-in").challenge();
        head.push_str(&format!(
            "edited: not the built-in {name} (fingerprint {}), whose title it carries\n",
            original.fingerprint()
        ));
    }
    let brief = c.brief().to_string();
    writeln!(out, "{head}\n{}", brief.trim_end()).map_err(stdout_stop)
}
