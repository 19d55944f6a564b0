//! The `imlab` command line as a user meets it: help, refused arguments, closed pipes, exit codes
//! and CSV output identical to the library's.

// Non-UTF-8 arguments and pipes are built with Unix APIs; the crate's tests also build for wasm32.
#![cfg(all(unix, not(target_arch = "wasm32")))]

use imlab::analysis::{seed_run, seeds_csv, sweep_csv, sweep_point, SweepSettings};
use imlab::scenario::Scenario;
use imlab::sim::Simulation;
use std::ffi::{OsStr, OsString};
use std::io::{BufRead, BufReader};
use std::os::unix::ffi::OsStrExt;
use std::process::{Child, Command, Output, Stdio};

/// A step scenario short enough (10 ms, 218 kB of trace) to run in a blink.
const SHORT: &str = "v=1&preset=step&duration=0.01";

/// Every subcommand, with arguments that make it quick; `help run` stands for clap's own output.
const EVERY_SUBCOMMAND: &[&[&str]] = &[
    &["list"],
    &["describe", "step"],
    &["run", SHORT],
    &["metrics", SHORT],
    &["sweep", "step", "--freqs", "100", "--duration", "0.02"],
    &["seeds", SHORT, "--n", "2"],
    &["help", "run"],
];

/// An `imlab` command with `args`, stdin closed.
fn imlab<S: AsRef<OsStr>>(args: impl IntoIterator<Item = S>) -> Command {
    let mut command = Command::new(env!("CARGO_BIN_EXE_imlab"));
    command.args(args).stdin(Stdio::null());
    command
}

/// The output of `imlab args`.
fn output<S: AsRef<OsStr>>(args: impl IntoIterator<Item = S>) -> Output {
    imlab(args).output().expect("imlab runs")
}

/// The stdout of `imlab args`, which must succeed.
fn stdout_of<S: AsRef<OsStr>>(args: impl IntoIterator<Item = S>) -> Vec<u8> {
    let out = output(args);
    assert!(
        out.status.success(),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
    out.stdout
}

/// Spawns `imlab args` with stdout piped or as given and stderr piped.
fn spawn(args: &[&str], stdout: Stdio) -> Child {
    imlab(args)
        .stdout(stdout)
        .stderr(Stdio::piped())
        .spawn()
        .expect("imlab starts")
}

/// Asserts that a child whose stdout was closed early ended with status 0 and said nothing of it.
fn assert_quiet_end(child: Child, args: &[&str], case: &str) {
    let out = child.wait_with_output().expect("imlab ends");
    let stderr = String::from_utf8_lossy(&out.stderr);
    assert_eq!(out.status.code(), Some(0), "{case}: {args:?}: {stderr}");
    // Progress lines of sweep and seeds may stay; an error line or a panic may not.
    for word in ["panicked", "Broken pipe", "imlab:", "error"] {
        assert!(!stderr.contains(word), "{case}: {args:?}: {stderr}");
    }
}

/// The write end of a pipe whose read end is already closed, so the first write fails (EPIPE).
fn widowed_pipe() -> Stdio {
    // std builds pipes only for children before Rust 1.87, newer than the crate's MSRV: the stdin
    // of a process that has exited is a pipe that nobody reads any more.
    let mut reader = Command::new("true")
        .stdin(Stdio::piped())
        .spawn()
        .expect("`true` runs");
    let write_end = reader.stdin.take().expect("piped stdin");
    reader.wait().expect("`true` ends");
    Stdio::from(write_end)
}

#[test]
fn help_lists_every_subcommand_and_option() {
    for args in [&["--help"][..], &["help"]] {
        let help = String::from_utf8(stdout_of(args)).unwrap();
        for sub in ["list", "describe", "run", "metrics", "sweep", "seeds"] {
            assert!(
                help.contains(&format!("\n  {sub} ")),
                "{args:?}: {sub}\n{help}"
            );
        }
        assert!(help.contains("imlab list"), "{help}");
    }
    let run = String::from_utf8(stdout_of(["run", "--help"])).unwrap();
    for word in [
        "--every <N>",
        "[default: 1]",
        "--out <FILE>",
        "v=1&preset=step",
    ] {
        assert!(run.contains(word), "{word}\n{run}");
    }
    let sweep = String::from_utf8(stdout_of(["help", "sweep"])).unwrap();
    let d = SweepSettings::default();
    for word in [
        "--freqs".to_string(),
        "[default: 10:1000:20]".to_string(),
        format!("Sine amplitude (rad/s), 0 < A ≤ 1000 [default: {}]", d.amp),
        format!("[default: {}]", d.offset),
        format!("[default: {}]", d.duration),
    ] {
        assert!(sweep.contains(&word), "{word}\n{sweep}");
    }
}

#[test]
fn non_utf8_arguments_are_refused_with_exit_2() {
    let bad = OsStr::from_bytes(&[0x66, 0xff]);
    let mut cases: Vec<Vec<&OsStr>> = ["describe", "run", "metrics", "sweep", "seeds"]
        .iter()
        .map(|sub| vec![OsStr::new(sub), bad])
        .collect();
    for (sub, option) in [
        ("run", "--every"),
        ("run", "--out"),
        ("sweep", "--freqs"),
        ("sweep", "--amp"),
        ("sweep", "--offset"),
        ("sweep", "--duration"),
        ("seeds", "--n"),
        ("seeds", "--first"),
    ] {
        cases.push(vec![sub.as_ref(), "step".as_ref(), option.as_ref(), bad]);
    }
    for args in &cases {
        let out = output(args);
        let stderr = String::from_utf8_lossy(&out.stderr);
        assert_eq!(out.status.code(), Some(2), "{args:?}: {stderr}");
        assert!(stderr.contains("invalid UTF-8"), "{args:?}: {stderr}");
        assert!(!stderr.contains("panicked"), "{args:?}: {stderr}");
        assert!(out.stdout.is_empty(), "{args:?}");
    }
    // Not a subcommand at all: refused, not a panic.
    let out = output([bad]);
    assert_eq!(out.status.code(), Some(2));
    assert!(!String::from_utf8_lossy(&out.stderr).contains("panicked"));
}

#[test]
fn a_stdout_closed_before_the_first_write_ends_every_subcommand_quietly() {
    for args in EVERY_SUBCOMMAND {
        assert_quiet_end(spawn(args, widowed_pipe()), args, "closed before start");
    }
}

#[test]
fn a_stdout_dropped_at_once_ends_every_subcommand_quietly() {
    for args in EVERY_SUBCOMMAND {
        let mut child = spawn(args, Stdio::piped());
        // run, metrics, sweep and seeds compute before they write, so the read end is gone by
        // then; list, describe and help may win the race and write first, which must succeed as
        // well (the closed-before-start test covers their broken pipe deterministically).
        drop(child.stdout.take());
        assert_quiet_end(child, args, "dropped at once");
    }
}

#[test]
fn a_stdout_closed_after_one_line_ends_every_subcommand_quietly() {
    for args in EVERY_SUBCOMMAND {
        let mut child = spawn(args, Stdio::piped());
        let mut line = String::new();
        BufReader::new(child.stdout.take().expect("piped stdout"))
            .read_line(&mut line)
            .expect("a first line");
        assert!(!line.is_empty(), "{args:?}");
        // Only `run` writes more than a pipe holds (218 kB), so only it is sure to meet the
        // closed pipe here; the others may have finished writing already.
        assert_quiet_end(child, args, "one line read");
    }
}

#[test]
fn other_stdout_and_out_file_errors_are_reported_with_exit_2() {
    if !std::path::Path::new("/dev/full").exists() {
        return;
    }
    let full = || std::fs::OpenOptions::new().write(true).open("/dev/full");
    for args in EVERY_SUBCOMMAND.iter().filter(|a| a[0] != "help") {
        let out = spawn(args, Stdio::from(full().unwrap()))
            .wait_with_output()
            .unwrap();
        let stderr = String::from_utf8_lossy(&out.stderr);
        assert_eq!(out.status.code(), Some(2), "{args:?}: {stderr}");
        assert!(stderr.contains("imlab: stdout: "), "{args:?}: {stderr}");
        assert!(!stderr.contains("panicked"), "{args:?}: {stderr}");
    }
    let out = output(["run", SHORT, "--out", "/dev/full"]);
    let stderr = String::from_utf8_lossy(&out.stderr);
    assert_eq!(out.status.code(), Some(2), "{stderr}");
    assert!(stderr.starts_with("imlab: --out '/dev/full': "), "{stderr}");
}

#[test]
fn usage_errors_exit_2_and_name_the_option_and_value() {
    let cases: &[(&[&str], &[&str])] = &[
        (&["run", "step", "--bogus", "1"], &["'--bogus'"]),
        (&["run", "step", "--every"], &["'--every <N>'"]),
        (&["run", "step", "--every", "0"], &["--every '0'", "≥ 1"]),
        (
            &["run", "step", "--every", "abc"],
            &["--every 'abc'", "≥ 1"],
        ),
        (
            &["sweep", "step", "--freqs", "10:1:3"],
            &["--freqs", "10:1:3", "lo ≤ hi"],
        ),
        (
            &["sweep", "step", "--freqs", "0,5"],
            &["--freqs '0,5'", "> 0"],
        ),
        (&["sweep", "step", "--amp", "0"], &["--amp '0'", "≤ 1000"]),
        (
            &["sweep", "step", "--offset", "-2000"],
            &["--offset '-2000'", "≤ 1000"],
        ),
        (
            &["sweep", "step", "--duration", "30"],
            &["--duration '30'", "≤ 20"],
        ),
        (&["seeds", "step", "--n", "0"], &["--n '0'", "10000"]),
        (
            &["seeds", "step", "--first", "-1"],
            &["--first '-1'", "≥ 0"],
        ),
        (
            &[
                "sweep",
                "step",
                "--freqs",
                "100",
                "--duration",
                "0.05",
                "--amp",
                "1e-200",
            ],
            &["'sine.amp' = 1e-200", "can measure"],
        ),
        (
            &[
                "seeds",
                "step",
                "--n",
                "2",
                "--first",
                "18446744073709551615",
            ],
            &[
                "seeds 18446744073709551615 to 18446744073709551616",
                "largest seed, 9007199254740991",
            ],
        ),
        (
            &["seeds", "step", "--n", "2", "--first", "9007199254740991"],
            &["seeds 9007199254740991 to 9007199254740992"],
        ),
        // Refused at once: run, it would take minutes.
        (
            &[
                "run",
                "v=1&preset=sine200-drive&ts=0.000001&duration=1&substeps=1000",
                "--out",
                "/dev/null",
            ],
            &[
                "1000000 samples",
                "7000 plant RK4 steps a sample",
                "= 7000000000 steps",
                "more than the 10000000 allowed",
                "lower 'substeps'",
            ],
        ),
        (&["describe"], &["<SCENARIO>"]),
        (&["list", "step"], &["'step'"]),
        (&["nonsense"], &["'nonsense'"]),
        (&[], &["Usage: imlab <COMMAND>"]),
    ];
    for (args, words) in cases {
        let out = output(*args);
        let stderr = String::from_utf8_lossy(&out.stderr);
        assert_eq!(out.status.code(), Some(2), "{args:?}: {stderr}");
        assert!(out.stdout.is_empty(), "{args:?}");
        for word in *words {
            assert!(stderr.contains(word), "{args:?}: '{word}' not in {stderr}");
        }
        // A seed range is refused before the first run.
        assert!(!stderr.contains("imlab seeds: 1/"), "{args:?}: {stderr}");
    }
}

#[test]
fn invisible_and_reordering_characters_are_quoted_as_escapes() {
    // A right-to-left override, an isolate, a zero-width joiner, a line separator and a tag:
    // echoed raw, each would change how the rest of the message reads.
    let cases: [(Vec<OsString>, &str); 4] = [
        (
            vec!["run".into(), "v=1&preset=step&k\u{202e}1=5".into()],
            "'k\\u{202e}1'",
        ),
        (
            vec![
                "run".into(),
                "step".into(),
                "--every".into(),
                "\u{2066}7\u{2069}".into(),
            ],
            "--every '\\u{2066}7\\u{2069}'",
        ),
        (
            vec![
                "sweep".into(),
                "step".into(),
                "--freqs".into(),
                "1\u{200d}0\u{2028}".into(),
            ],
            "'1\\u{200d}0\\u{2028}'",
        ),
        (
            vec!["run".into(), "step".into(), "--x\u{e0041}".into()],
            "--x\\u{e0041}",
        ),
    ];
    for (args, quoted) in &cases {
        let out = output(args);
        let stderr = String::from_utf8_lossy(&out.stderr);
        assert_eq!(out.status.code(), Some(2), "{args:?}: {stderr}");
        assert!(
            stderr.contains(quoted),
            "{args:?}: {quoted} not in {stderr}"
        );
        assert!(
            !stderr
                .chars()
                .any(|c| c != '\n' && imlab::text::is_invisible(c)),
            "{args:?}: {stderr:?}"
        );
    }
}

#[test]
fn long_or_binary_values_are_quoted_as_short_escaped_excerpts() {
    let long = format!("{}\u{1b}[2J", "7".repeat(10_000));
    let cases: [Vec<OsString>; 3] = [
        ["run", "step", "--every", long.as_str()]
            .map(OsString::from)
            .into(),
        ["run", "step", format!("--{long}").as_str()]
            .map(OsString::from)
            .into(),
        ["sweep", "step", "--freqs", long.as_str()]
            .map(OsString::from)
            .into(),
    ];
    for args in &cases {
        let out = output(args);
        let stderr = String::from_utf8_lossy(&out.stderr);
        assert_eq!(out.status.code(), Some(2), "{stderr}");
        assert!(stderr.len() < 400, "{} bytes: {stderr}", stderr.len());
        assert!(!stderr.contains('\u{1b}'), "{stderr}");
        assert!(stderr.contains("characters)"), "{stderr}");
    }
}

#[test]
fn run_writes_the_library_csv_byte_for_byte() {
    let library = |text: &str, every: usize| {
        let mut sim = Simulation::new(&Scenario::parse(text).unwrap(), every).unwrap();
        sim.run().unwrap();
        sim.csv()
    };
    assert_eq!(
        String::from_utf8(stdout_of(["run", "step"])).unwrap(),
        library("step", 1)
    );
    let path = std::env::temp_dir().join(format!("imlab-cli-{}.csv", std::process::id()));
    let written = stdout_of([
        OsStr::new("run"),
        OsStr::new(SHORT),
        OsStr::new("--every"),
        OsStr::new("7"),
        OsStr::new("--out"),
        path.as_os_str(),
    ]);
    let file = std::fs::read_to_string(&path).expect("--out writes the file");
    std::fs::remove_file(&path).unwrap();
    assert!(written.is_empty());
    assert_eq!(file, library(SHORT, 7));
}

#[test]
fn a_diverged_run_writes_its_trace_then_exits_2() {
    // 1 kHz sampling with 1200/s gains (k·Ts = 1.2) and no voltage limit runs away.
    let text = "v=1&preset=step&ts=0.001&vmax=100000";
    let out = output(["run", text]);
    let stderr = String::from_utf8_lossy(&out.stderr);
    assert_eq!(out.status.code(), Some(2), "{stderr}");
    assert!(stderr.starts_with("imlab: diverged"), "{stderr}");
    assert!(
        stderr.contains("trace written up to the failure"),
        "{stderr}"
    );
    let mut sim = Simulation::new(&Scenario::parse(text).unwrap(), 1).unwrap();
    sim.run().unwrap_err();
    assert_eq!(String::from_utf8(out.stdout).unwrap(), sim.csv());
}

#[test]
fn sweep_marks_points_that_had_not_settled_in_the_csv_its_summary_and_on_stderr() {
    // IFOC runs of the default 0.2 s still ring from the start (see tests/sweep.rs); 3 s settle.
    let short = output(["sweep", "ifoc-step", "--offset", "40", "--freqs", "300,480"]);
    let long = output([
        "sweep",
        "ifoc-step",
        "--offset",
        "40",
        "--freqs",
        "300,480",
        "--amp",
        "0.05",
        "--duration",
        "3",
    ]);
    for (out, settled, summary, warned) in [
        (
            short,
            "false",
            "# bandwidth_hz=unsettled phase_at_200hz_deg=none unsettled=2",
            true,
        ),
        (
            long,
            "true",
            "# bandwidth_hz=below_lowest_frequency phase_at_200hz_deg=none unsettled=0",
            false,
        ),
    ] {
        let stderr = String::from_utf8_lossy(&out.stderr);
        assert!(out.status.success(), "{stderr}");
        let csv = String::from_utf8(out.stdout).unwrap();
        let lines: Vec<&str> = csv.lines().collect();
        assert_eq!(
            lines[0],
            "freq_hz,gain,gain_db,phase_deg,gain_hat,phase_hat_deg,saturated,failure,\
             settled,gain_change_db,phase_change_deg,peak_current_a",
        );
        for line in &lines[1..3] {
            let fields: Vec<&str> = line.split(',').collect();
            assert_eq!(fields.len(), 12, "{line}");
            assert_eq!(fields[8], settled, "{line}");
            assert!(fields[9].parse::<f64>().unwrap().is_finite(), "{line}");
            // At 40 rad/s the magnetising and torque currents give a few amperes.
            let peak: f64 = fields[11].parse().unwrap();
            assert!((1.0..20.0).contains(&peak), "{line}");
        }
        assert_eq!(lines[3..], [summary]);
        assert_eq!(
            stderr.contains("imlab sweep: 2 of 2 points had not settled"),
            warned,
            "{stderr}"
        );
    }
}

#[test]
fn sweep_and_seeds_write_the_library_csv_byte_for_byte() {
    let step = Scenario::parse("step").unwrap();
    let settings = SweepSettings {
        amp: 0.05,
        offset: -5.0,
        duration: 0.05,
    };
    // The CLI sorts and deduplicates a list of frequencies.
    let points: Vec<_> = [100.0, 300.0]
        .iter()
        .map(|&f| sweep_point(&step, f, &settings).unwrap())
        .collect();
    let args = [
        "sweep",
        "step",
        "--freqs",
        "300,100,300",
        "--amp",
        "0.05",
        "--offset",
        "-5",
        "--duration",
        "0.05",
    ];
    assert_eq!(
        String::from_utf8(stdout_of(args)).unwrap(),
        sweep_csv(&points)
    );

    let short = Scenario::parse(SHORT).unwrap();
    let seeds = |first: u64| {
        let results: Vec<_> = (first..first + 2)
            .map(|seed| seed_run(&short, seed, usize::MAX).unwrap().result)
            .collect();
        seeds_csv(&results)
    };
    let printed = |args: &[&str]| String::from_utf8(stdout_of(args)).unwrap();
    assert_eq!(
        printed(&["seeds", SHORT, "--n", "2", "--first", "7"]),
        seeds(7)
    );
    // Without --first the seeds start at the scenario's own.
    assert_eq!(printed(&["seeds", SHORT, "--n", "2"]), seeds(short.seed));
}

#[test]
fn a_formula_with_an_invisible_character_is_quoted_as_escapes_everywhere() {
    // Controls (ESC, CSI, BS, DEL, NUL), an override and line breaks, at every place of a law:
    // a refusal quotes the one it stops at, a law that parses is shown with its breaks.
    const INSERTED: [char; 9] = [
        '\u{1b}', '\u{9b}', '\u{8}', '\u{7f}', '\0', '\u{202e}', '\r', '\n', '\u{2028}',
    ];
    let law = "-si1 + dwd + a3*wd + a2 - k1s1*z1";
    let shows = |what: &str, text: &str| {
        assert!(
            !text
                .chars()
                .any(|c| c != '\n' && imlab::text::is_invisible(c)),
            "{what}: {text:?}"
        );
    };
    for c in INSERTED {
        for at in (0..=law.len()).step_by(3) {
            let text = format!("{}{c}{}", &law[..at], &law[at..]);
            let encoded = imlab::text::percent::encode(&text, b"");
            let scenario = format!("v=1&preset=step&law.v1={encoded}");
            // What the bindings return: the codec's refusal and the law editor's preview.
            if let Err(e) = Scenario::parse(&scenario) {
                shows(&scenario, &e.to_string());
            }
            if let Some(e) = imlab::control::law::preview(1, &text).error {
                shows(&scenario, &e.reason.to_string());
            }
            let out = output(["describe", scenario.as_str()]);
            shows(&scenario, &String::from_utf8_lossy(&out.stderr));
            shows(&scenario, &String::from_utf8_lossy(&out.stdout));
            // A challenge's brief names the law it starts from.
            let challenge = format!(
                "c=1&base={}&allow.law.v1=formula&need.law_residual=max:1",
                imlab::text::percent::encode(&scenario, b"")
            );
            let out = output(["challenge", challenge.as_str()]);
            shows(&challenge, &String::from_utf8_lossy(&out.stderr));
            shows(&challenge, &String::from_utf8_lossy(&out.stdout));
        }
    }
}

#[test]
fn a_setting_the_run_does_not_read_is_warned_about_and_marked_by_describe() {
    // The perfect observer and the backstepping gains under IFOC: each command that reads the
    // scenario says so on stderr, and the figures are those of the run without them.
    let idle = "v=1&preset=ifoc-step&duration=0.02&perfect=1&k1=600";
    let plain = "v=1&preset=ifoc-step&duration=0.02";
    let out = output(["metrics", idle]);
    assert!(out.status.success());
    let stderr = String::from_utf8_lossy(&out.stderr);
    for key in ["perfect", "k1"] {
        let line = format!("imlab: warning: {key} has no effect with controller=ifoc");
        assert!(stderr.contains(&line), "{stderr}");
    }
    assert_eq!(out.stdout, stdout_of(["metrics", plain]));
    let clean = output(["metrics", plain]);
    assert!(!String::from_utf8_lossy(&clean.stderr).contains("no effect"));
    let described = String::from_utf8(stdout_of(["describe", idle])).unwrap();
    assert!(
        described.contains("\n# perfect has no effect with controller=ifoc\n"),
        "{described}"
    );
    let k1 = described.lines().find(|l| l.starts_with("k1 ")).unwrap();
    assert!(k1.ends_with("(no effect with controller=ifoc)"), "{k1}");
}
