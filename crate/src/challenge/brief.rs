//! A challenge as plain text for a slide, an LMS page or the terminal.

use super::codec::field_info;
use super::judge::figure_info;
use super::{Allowed, Challenge, Op, Variants};
use crate::record::{recovery_band, LOAD_RECOVERY};
use crate::text::escape_invisible;
use std::fmt::Write;

impl Challenge {
    /// The task in words: the title (its invisible characters, line breaks among them, escaped
    /// by [`escape_invisible`], so it stays one line and shows what it holds), the scenario to
    /// start from, what may change (with ranges, units and the base's values), each criterion
    /// with its bound and unit, and the variants.
    pub fn brief(&self) -> String {
        let title = if self.title.is_empty() {
            "Design challenge".to_string()
        } else {
            escape_invisible(&self.title)
        };
        format!("{title}\n\n{}", self.task())
    }

    /// The brief without its title: from the scenario to start from to the variants.
    pub fn task(&self) -> String {
        let base = self.base_scenario();
        let mut out = String::new();
        let _ = writeln!(out, "Start from the scenario {}", self.base);
        if self.allow.is_empty() {
            let _ = writeln!(
                out,
                "\nNothing may be changed: the base is judged as it is."
            );
        } else {
            let _ = writeln!(out, "\nYou may change only:");
        }
        for a in &self.allow {
            let info = field_info(&base, &a.field).expect("checked when parsed");
            let unit = if info.unit.is_empty() {
                String::new()
            } else {
                format!(" {}", info.unit)
            };
            let range = match &a.allowed {
                Allowed::Range { lo, hi } => format!("{lo} to {hi}{unit}"),
                Allowed::Choice { options } => format!("one of {}", options.join(", ")),
                Allowed::Formula => format!("a formula of your own, in{unit}"),
            };
            // A law's text may hold line breaks: shown as escapes, as a message quotes it.
            let now = info
                .value
                .map_or_else(|| "–".to_string(), |v| escape_invisible(&v));
            let _ = writeln!(out, "  {:<14} {range} (now {now}) — {}", a.field, info.doc);
        }
        let _ = writeln!(out, "\nYour design must meet:");
        for (i, c) in self.need.iter().enumerate() {
            let f = figure_info(&c.figure).expect("checked when parsed");
            let u = if f.unit.is_empty() {
                String::new()
            } else {
                format!(" {}", f.unit)
            };
            let bound = match c.op {
                Op::Max(b) => format!("at most {b}{u}"),
                Op::Min(b) => format!("at least {b}{u}"),
                Op::Abs(b) => format!("within ±{b}{u}"),
                Op::Band => {
                    "inside the 95 % band of a consistent filter (mean_nis_low to mean_nis_high)"
                        .to_string()
                }
            };
            let settled = if c.figure.ends_with("_final") {
                ", and settled by the end of the run"
            } else {
                ""
            };
            let robust = if self.is_robust(&c.figure) {
                " — on the nominal run and on every variant"
            } else {
                ""
            };
            let _ = writeln!(
                out,
                "  {}. {} ({}): {bound}{settled}{robust}",
                i + 1,
                f.label,
                c.figure
            );
        }
        if let Some(v) = &self.vary {
            let list = match v {
                Variants::Seeds { first, last } => format!("noise seeds {first} to {last}"),
                Variants::List { overrides } => overrides.join("; "),
            };
            let _ = writeln!(
                out,
                "\nVariants (applied on top of your settings; the worst run counts): {list}"
            );
        }
        if self.need.iter().any(|c| c.figure == LOAD_RECOVERY) {
            let _ = writeln!(
                out,
                "\nLoad recovery time: the time from the load step (t = {} s) until |ω − ω_d| \
                 stays within max(1 % of |ω_d| at the step, 0.5 rad/s) to the end of the run \
                 (here {} rad/s at ω_d = {} rad/s); not recovered if it is still outside at the end.",
                base.load_step.time,
                recovery_band(base.reference.sample(base.load_step.time).value),
                base.reference.sample(base.load_step.time).value
            );
        }
        if self.need.iter().any(|c| c.figure.ends_with("_final")) {
            let _ = writeln!(
                out,
                "\nA final value counts only if it has settled: a value still changing over the \
                 last tenth of the run fails."
            );
        }
        out
    }
}
