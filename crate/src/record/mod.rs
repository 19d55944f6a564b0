//! What a run keeps of its samples, and the figures read from them.
//!
//! The loop hands each sample's [`Row`] to a [`Sink`], and reads its rows back through
//! [`Samples`]; nothing here knows how the loop computes a row. A run keeps its rows in memory
//! ([`Recorder`]) or keeps checkpoints of the loop's state and replays any window from them
//! ([`Trace`]), tallying as the rows come what its figures need of every row ([`StabilityTally`],
//! [`TransientTally`]). The
//! figures ([`report`], [`metrics`], [`load_recovery`]) and the plots' envelopes ([`M4`]) read
//! rows in order.

mod figures;
mod m4;
mod metrics;
mod recorder;
mod recovery;
mod row;
mod samples;
mod tally;
mod trace;
mod transient;
mod warnings;
mod window;

pub use figures::{
    figure_info, report, Figure, FigureInfo, Report, Trend, TrendState, Unreached, FIGURE_INFO,
};
pub use m4::{m4, M4};
pub use metrics::{metrics, Metrics};
pub use recorder::Recorder;
pub use recovery::{load_recovery, recovery_band, LOAD_RECOVERY, LOAD_RECOVERY_INFO};
pub use row::{
    first_not, is_saturated, write_csv, Row, RowVisitor, Sink, COLUMNS, COLUMN_DOCS, NUM_COLUMNS,
};
pub use samples::Samples;
pub use tally::{Stability, StabilityCause, StabilityTally, TransientTally, CHECKPOINT_EVERY};
pub use trace::{Column, Overview, Trace};
pub use transient::{transient, Transient};
pub use warnings::{Warning, WarningKind};
pub use window::WindowTally;
