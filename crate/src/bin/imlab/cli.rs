//! The command line's grammar: the subcommands, their options and the checks of option values.

use clap::{Args, Parser, Subcommand};
use imlab::analysis::SweepSettings;
use imlab::scenario::Scenario;
use imlab::text::excerpt;

/// Run IM Lab scenarios: speed-sensorless induction-motor control (Zhang et al. 2015).
#[derive(Parser)]
#[command(
    name = "imlab",
    version,
    // A repeated option overrides the earlier one, as in most command lines.
    args_override_self = true,
    after_help = "SCENARIO is a preset name or a query string such as \
                  'v=1&preset=step&step.size=0.3'; `imlab list` names the presets."
)]
pub(crate) struct Cli {
    /// What to do.
    #[command(subcommand)]
    pub(crate) command: Command,
}

/// The scenario argument every subcommand but `list` takes.
#[derive(Args)]
pub(crate) struct ScenarioArg {
    /// Preset name or query string such as 'v=1&preset=step&step.size=0.3'
    /// (`imlab list` names the presets)
    scenario: String,
}

// Option values stay strings for clap: its own "invalid value" message would echo them in full,
// while `number` and `frequencies` quote them through `excerpt`. `allow_hyphen_values` keeps the
// old rule that the word after an option is its value, so `--offset -5` works.
/// The subcommands.
#[derive(Subcommand)]
pub(crate) enum Command {
    /// List the presets, one line each
    List,
    /// Print every field of the effective scenario
    Describe {
        #[command(flatten)]
        target: ScenarioArg,
    },
    /// Print the design derived from the scenario's motor, rating and sampling, with its rules
    Design {
        #[command(flatten)]
        target: ScenarioArg,
    },
    /// Estimate a motor's equivalent circuit from its nameplate and the no-load and locked-rotor
    /// tests (IEEE Std 112), and print the link that uses it
    Motor(crate::motor::MotorArgs),
    /// Run the scenario and write its trace as CSV to stdout or FILE
    Run {
        #[command(flatten)]
        target: ScenarioArg,
        /// Keep every N-th sample (a whole number ≥ 1)
        #[arg(
            long,
            value_name = "N",
            default_value = "1",
            allow_hyphen_values = true
        )]
        every: String,
        /// Write the CSV to FILE instead of stdout
        #[arg(long, value_name = "FILE", allow_hyphen_values = true)]
        out: Option<String>,
    },
    /// Run the scenario and print its figures as CSV: name,value,unit
    Metrics {
        #[command(flatten)]
        target: ScenarioArg,
    },
    /// Check each step's own law (law.v1..law.v4) against its designed error dynamics
    ///
    /// Each law is compared with the paper's at drawn states and parameter values, and the term
    /// it gets wrong is named where it can be; the command fails unless every law gives the
    /// dynamics its step is designed for.
    Law {
        #[command(flatten)]
        target: ScenarioArg,
    },
    /// Measure the closed-loop speed frequency response and print it as CSV
    Sweep {
        #[command(flatten)]
        target: ScenarioArg,
        /// Frequencies (Hz): LO:HI:N for N log-spaced from LO to HI (0 < LO ≤ HI, 1 ≤ N ≤ 200),
        /// or a list, each > 0
        #[arg(
            long,
            value_name = "LO:HI:N|F1,F2,...",
            default_value = "10:1000:20",
            allow_hyphen_values = true
        )]
        freqs: String,
        /// Sine amplitude (rad/s), 0 < A ≤ 1000
        #[arg(
            long,
            value_name = "A",
            default_value_t = SweepSettings::default().amp.to_string(),
            allow_hyphen_values = true
        )]
        amp: String,
        /// Operating speed the sine rides on (rad/s), |W| ≤ 1000
        #[arg(
            long,
            value_name = "W",
            default_value_t = SweepSettings::default().offset.to_string(),
            allow_hyphen_values = true
        )]
        offset: String,
        /// Length of each run (s), 0 < D ≤ 20
        #[arg(
            long,
            value_name = "D",
            default_value_t = SweepSettings::default().duration.to_string(),
            allow_hyphen_values = true
        )]
        duration: String,
        /// A sweep's plan, as a link's #sweep= holds it: LO,HI,N,AMP,OFFSET,DURATION and the
        /// variants joined by '.' (euler, rk4, perfect, delay, ifoc, ifocpi); runs each variant
        /// of the scenario in turn, its CSV after a line '# variant=NAME'
        #[arg(
            long,
            value_name = "PLAN",
            conflicts_with_all = ["freqs", "amp", "offset", "duration"],
            allow_hyphen_values = true
        )]
        plan: Option<String>,
    },
    /// Run the scenario once per seed and print each seed's figures as CSV
    Seeds {
        #[command(flatten)]
        target: ScenarioArg,
        /// Number of seeds, 1 to 10000
        #[arg(
            long,
            value_name = "N",
            default_value = "10",
            allow_hyphen_values = true
        )]
        n: String,
        /// First seed, a whole number ≥ 0; the last seed run is at most 2^53 − 1 [default: the
        /// scenario's seed]
        #[arg(long, value_name = "SEED", allow_hyphen_values = true)]
        first: Option<String>,
    },
    /// Run the scenario over a grid of motor or model parameters and seeds: a model-error map
    ///
    /// Each grid point (cell) runs once per seed, on all cores. The CSV has one row a cell, in
    /// order (the last --vary fastest), written as soon as the cell and every cell before it are
    /// done: the axis values and their errors against the other side (in %), the number of runs,
    /// of runs that ran away (the runaway warning, or a diverged simulation), of runs whose EKF
    /// was inconsistent, and of the runs that held what holding cost: those past the motor's
    /// rated current after the start-up (over_rating) and those whose final speed error had not
    /// settled (unsettled), then the minimum, median and maximum over the runs that neither ran away nor
    /// stopped early of
    /// tracking_rms, tracking_peak, speed_error_final, speed_estimate_error_final,
    /// flux_error_final, current_peak, saturated_share and mean_nis, then the cell's scenario.
    Robust {
        #[command(flatten)]
        target: ScenarioArg,
        /// A parameter and its values, KEY=LO..HI:N: N evenly spaced values (1 ≤ N ≤ 101) of a
        /// plant.* or model.* key; LO and HI are values, or both relative errors in per cent
        /// against the other side's value (plant.rr=-10%..+10%:11: the motor's R_r from 10 %
        /// below to 10 % above the model's). Once or twice
        #[arg(
            long,
            value_name = "KEY=LO..HI:N",
            required = true,
            allow_hyphen_values = true,
            action = clap::ArgAction::Append
        )]
        vary: Vec<String>,
        /// Seeds run at every point, A..B (at most 1000)
        #[arg(
            long,
            value_name = "A..B",
            default_value = "1..10",
            allow_hyphen_values = true
        )]
        seeds: String,
    },
    /// Measure the teaching text's tables of measurements and print them as CSV
    ///
    /// Each TABLE is CSV, id,scenario,figure,seeds,statistic,show,value (docs/cli.md describes
    /// each column); ids are unique across the tables. Every row is measured again, each run once
    /// on all cores, and the rows are printed with the values measured; --check prints nothing
    /// and fails, naming each row whose value differs, if any does; --write writes the values
    /// into the tables, and none when a row has no value.
    Claims {
        /// The measurements tables
        #[arg(required = true)]
        tables: Vec<String>,
        /// Compare the measured values with the tables' and fail on any difference
        #[arg(long, conflicts_with = "write")]
        check: bool,
        /// Write the measured values into the tables
        #[arg(long)]
        write: bool,
    },
    /// Print a challenge's canonical link and brief; --list names the built-in ones
    Challenge {
        /// A built-in challenge's name or a challenge link
        #[arg(required_unless_present = "list")]
        challenge: Option<String>,
        /// Name the built-in challenges, one line each
        #[arg(long, conflicts_with = "challenge")]
        list: bool,
    },
    /// Grade a file of submission links and print one CSV row each
    ///
    /// Each link is re-run, nominal and variants, on all cores, and its row written as soon as it
    /// and every row before it are graded. The CSV is
    /// [<carried>,...]line,link,status,<criterion>,<criterion>_pass,...,pass where status is ok,
    /// malformed: …, refused: …, another challenge or run failed: …. Text from FILE is shown
    /// with its invisible characters escaped, and a cell a spreadsheet would run as a formula
    /// starts with '.
    Grade {
        /// A built-in challenge's name or a challenge link
        challenge: String,
        /// File of submission links (UTF-8, UTF-16 with a byte-order mark, or a legacy encoding
        /// such as Windows-1252, told from its bytes): one a line (blank lines and # comments
        /// skipped), or a CSV export with a header whose other columns are carried to the grades
        /// first; - for stdin
        file: String,
        /// Append the grades to OUT, an earlier output of this command cut off anywhere (or
        /// missing), after the rows it holds, instead of writing them to stdout. OUT is locked
        /// while it is graded, and one in twenty of its rows (and its last) is graded again
        /// and must be unchanged
        #[arg(long, value_name = "OUT", allow_hyphen_values = true)]
        resume: Option<String>,
    },
}

impl ScenarioArg {
    /// The scenario the argument names.
    /// A setting the scenario changes that has no effect in it is warned about on stderr.
    pub(crate) fn parse(&self) -> Result<Scenario, String> {
        let s = Scenario::parse(&self.scenario).map_err(|e| e.to_string())?;
        for idle in s.idle_settings() {
            crate::output::to_stderr(format_args!("imlab: warning: {idle}\n"));
        }
        Ok(s)
    }
}

/// The value of option `flag` if it parses and passes `ok`; else a message naming the option, the
/// value and the `expected` range.
pub(crate) fn number<T: std::str::FromStr>(
    flag: &str,
    value: &str,
    ok: impl Fn(&T) -> bool,
    expected: &str,
) -> Result<T, String> {
    value
        .parse()
        .ok()
        .filter(ok)
        .ok_or_else(|| format!("{flag} '{}': expected {expected}", excerpt(value)))
}
