//! Why a run stopped early, as a message of the core (`sim-*` in `core-run.ftl`).

use crate::control::ControlError;
use crate::text::Message;
use std::fmt;

/// Why a run stopped early.
#[derive(Clone, Debug, PartialEq)]
pub enum SimError {
    /// A state left its physical bounds or became NaN.
    Diverged {
        /// Time of the sample (s).
        t: f64,
        /// Which signal.
        signal: &'static str,
        /// Its value.
        value: f64,
    },
    /// A recorded signal would not be a finite number (the trace keeps finite numbers only).
    NotFinite {
        /// Time of the sample (s).
        t: f64,
        /// The column.
        column: &'static str,
        /// Its value (±inf or NaN).
        value: f64,
    },
    /// The controller could not compute a voltage.
    Control {
        /// Time of the sample (s).
        t: f64,
        /// The reason.
        error: ControlError,
    },
    /// A step's own law gave a value that is not a finite number.
    Law(Box<LawFailure>),
}

/// Where a step's own law failed: the formula, the time and the signals it read.
#[derive(Clone, Debug, PartialEq)]
pub struct LawFailure {
    /// Time of the sample (s).
    pub t: f64,
    /// The step (1–4).
    pub step: u8,
    /// The formula.
    pub text: String,
    /// What it gave (±inf or NaN).
    pub value: f64,
    /// The names it reads and their values there (empty when it reads none).
    pub signals: String,
}

impl SimError {
    /// Why the run stopped, as a message of `core-run.ftl`. A value that is not a finite number
    /// (inf, NaN) is said as Rust writes it, as a name.
    pub fn message(&self) -> Message {
        match self {
            SimError::Diverged { t, signal, value } => Message::new("sim-diverged")
                .fixed("t", *t, 5)
                .text("signal", *signal)
                .text("value", format!("{value:e}")),
            SimError::NotFinite { t, column, value } => Message::new("sim-not-finite")
                .fixed("t", *t, 5)
                .text("column", *column)
                .text("value", value.to_string()),
            SimError::Control { t, error } => Message::new("sim-control")
                .fixed("t", *t, 5)
                .said("error", error.message()),
            SimError::Law(l) => Message::new("sim-law")
                .count("step", l.step)
                .text("formula", crate::text::excerpt(&l.text))
                .text("value", l.value.to_string())
                .fixed("t", l.t, 5)
                .said(
                    "reading",
                    if l.signals.is_empty() {
                        Message::new("sim-law-reads-nothing")
                    } else {
                        Message::new("sim-law-reads").text("signals", l.signals.as_str())
                    },
                ),
        }
    }
}

impl fmt::Display for SimError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        self.message().fmt(f)
    }
}

impl std::error::Error for SimError {}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn why_a_run_stopped_reads_in_english() {
        let says = |e: SimError| e.to_string();
        assert_eq!(
            says(SimError::Diverged {
                t: 0.005,
                signal: "speed ω",
                value: -3.6521172027055076e6
            }),
            "diverged at t = 0.00500 s: speed ω = -3.6521172027055076e6 left its bounds"
        );
        assert_eq!(
            says(SimError::NotFinite {
                t: 0.0123,
                column: "nis",
                value: f64::INFINITY
            }),
            "stopped at t = 0.01230 s: column 'nis' would record inf, not a finite number"
        );
        assert_eq!(
            says(SimError::Control {
                t: 0.1,
                error: ControlError::SingularDecoupling { flux_sq: 1.5e-9 }
            }),
            "controller failed at t = 0.10000 s: decoupling matrix (55) is singular: estimated \
             flux x̂4² + x̂5² = 1.500e-9 Wb² is below 1e-6 Wb²"
        );
        assert_eq!(
            says(SimError::Control {
                t: 0.0,
                error: ControlError::Law {
                    step: 2,
                    value: f64::NAN
                }
            }),
            "controller failed at t = 0.00000 s: the law of step 2 gave NaN, not a finite number"
        );
        let law = |signals: &str| LawFailure {
            t: 0.00005,
            step: 1,
            text: "1/z1".to_string(),
            value: f64::NEG_INFINITY,
            signals: signals.to_string(),
        };
        assert_eq!(
            says(SimError::Law(Box::new(law("z1 = -0")))),
            "your law.v1 = 1/z1 gave -inf at t = 0.00005 s, from z1 = -0"
        );
        assert_eq!(
            says(SimError::Law(Box::new(law("")))),
            "your law.v1 = 1/z1 gave -inf at t = 0.00005 s, reading no signal"
        );
    }
}
