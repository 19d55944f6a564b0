//! A challenge as plain text for a slide, an LMS page or the terminal: its lines as messages,
//! which the page says in the reader's language and the CLI in English.

use super::codec::field_info;
use super::judge::{figure_info, quantity};
use super::{Allowed, Challenge, Op, Variants};
use crate::record::{recovery_band, LOAD_RECOVERY};
use crate::text::{escape_invisible, Message};
use serde::Serialize;
use std::fmt;

/// A challenge's task in words: paragraphs of lines. Its `Display` is the English text, each
/// paragraph's head on a line, its items under it indented by two spaces, a blank line between
/// paragraphs and a line end after the last line.
#[cfg_attr(
    target_arch = "wasm32",
    derive(tsify::Tsify),
    tsify(missing_as_null, hashmap_as_object)
)]
#[derive(Clone, Debug, PartialEq, Serialize)]
pub struct Brief {
    /// The paragraphs, in order.
    pub paragraphs: Vec<Paragraph>,
}

/// One paragraph of a [`Brief`]: a line, and the lines of a list under it (none for a plain
/// sentence).
#[cfg_attr(
    target_arch = "wasm32",
    derive(tsify::Tsify),
    tsify(missing_as_null, hashmap_as_object)
)]
#[derive(Clone, Debug, PartialEq, Serialize)]
pub struct Paragraph {
    /// Its first line.
    pub head: Message,
    /// The list under it, one line each, shown indented.
    pub items: Vec<Message>,
}

impl Paragraph {
    fn line(head: Message) -> Paragraph {
        Paragraph {
            head,
            items: Vec::new(),
        }
    }
}

impl fmt::Display for Brief {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        for (i, p) in self.paragraphs.iter().enumerate() {
            if i > 0 {
                f.write_str("\n")?;
            }
            writeln!(f, "{}", p.head)?;
            for item in &p.items {
                writeln!(f, "  {item}")?;
            }
        }
        Ok(())
    }
}

impl Challenge {
    /// The task in words: the title (its invisible characters, line breaks among them, escaped
    /// by [`escape_invisible`], so it stays one line and shows what it holds), the scenario to
    /// start from, what may change (with ranges, units and the base's values), each criterion
    /// with its bound and unit, and the variants.
    pub fn brief(&self) -> Brief {
        let title = if self.title.is_empty() {
            Message::new("challenge-untitled")
        } else {
            Message::new("challenge-title").text("title", escape_invisible(&self.title))
        };
        let mut paragraphs = vec![Paragraph::line(title)];
        paragraphs.extend(self.task().paragraphs);
        Brief { paragraphs }
    }

    /// The brief without its title: from the scenario to start from to the variants.
    pub fn task(&self) -> Brief {
        let base = self.base_scenario();
        let mut out = vec![Paragraph::line(
            Message::new("challenge-brief-start").text("base", self.base.as_str()),
        )];
        let mut allowed = Paragraph::line(Message::new(if self.allow.is_empty() {
            "challenge-brief-nothing-allowed"
        } else {
            "challenge-brief-allowed"
        }));
        for a in &self.allow {
            let info = field_info(&base, &a.field).expect("checked when parsed");
            let range = match &a.allowed {
                Allowed::Range { lo, hi } => quantity(
                    Message::new("challenge-brief-range").real("lo", *lo),
                    "hi",
                    *hi,
                    info.unit,
                ),
                Allowed::Choice { options } => {
                    Message::new("challenge-brief-one-of").text("options", options.join(", "))
                }
                Allowed::Formula if info.unit.is_empty() => Message::new("challenge-brief-formula"),
                Allowed::Formula => {
                    Message::new("challenge-brief-formula-unit").text("unit", info.unit)
                }
            };
            // A law's text may hold line breaks: shown as escapes, as a message quotes it.
            let now = info
                .value
                .map_or_else(|| "–".to_string(), |v| escape_invisible(&v));
            allowed.items.push(
                Message::new("challenge-brief-allow")
                    .text("field", format!("{:<14}", a.field))
                    .said("range", range)
                    .text("now", now)
                    .said("doc", info.doc),
            );
        }
        out.push(allowed);
        let mut needs = Paragraph::line(Message::new("challenge-brief-needs"));
        for (i, c) in self.need.iter().enumerate() {
            let f = figure_info(&c.figure).expect("checked when parsed");
            let bound = match c.op {
                Op::Max(b) => quantity(Message::new("challenge-brief-at-most"), "bound", b, f.unit),
                Op::Min(b) => {
                    quantity(Message::new("challenge-brief-at-least"), "bound", b, f.unit)
                }
                Op::Abs(b) => quantity(Message::new("challenge-brief-within"), "bound", b, f.unit),
                Op::Band => Message::new("challenge-brief-band"),
            };
            let yes = |on: bool| if on { "yes" } else { "no" };
            needs.items.push(
                Message::new("challenge-brief-need")
                    .count("number", i + 1)
                    .said("label", f.label.clone())
                    .text("figure", c.figure.as_str())
                    .said("bound", bound)
                    .text("settled", yes(c.figure.ends_with("_final")))
                    .text("robust", yes(self.is_robust(&c.figure))),
            );
        }
        out.push(needs);
        if let Some(v) = &self.vary {
            out.push(Paragraph::line(match v {
                Variants::Seeds { first, last } => Message::new("challenge-brief-variants-seeds")
                    .text("first", first.to_string())
                    .text("last", last.to_string()),
                Variants::List { overrides } => {
                    Message::new("challenge-brief-variants").text("overrides", overrides.join("; "))
                }
            }));
        }
        if self.need.iter().any(|c| c.figure == LOAD_RECOVERY) {
            let at_step = base.reference.sample(base.load_step.time).value;
            out.push(Paragraph::line(
                Message::new("challenge-brief-load-recovery")
                    .real("time", base.load_step.time)
                    .real("band", recovery_band(at_step))
                    .real("speed", at_step),
            ));
        }
        if self.need.iter().any(|c| c.figure.ends_with("_final")) {
            out.push(Paragraph::line(Message::new("challenge-brief-settled")));
        }
        Brief { paragraphs: out }
    }
}
