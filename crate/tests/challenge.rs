//! Challenges: the link codec and its refusals, the measures and verdicts, the built-in
//! challenges (their bases fail, their solutions pass) and `imlab grade` on a class's file. The
//! composer's are in compose.rs.

// Runs native processes and simulations of seconds; the crate's tests also build for wasm32.
#![cfg(not(target_arch = "wasm32"))]

use imlab::challenge::{
    builtin, figure_info, judge, measure, Challenge, ErrorKind, Measure, Measures, Submission,
    Verdict, BUILTINS, LOAD_RECOVERY,
};
use imlab::sim::Simulation;
use std::process::{Command, Stdio};

mod common;
use common::{SMALL, SMALL_CANONICAL};

/// Runs `submission`'s scenarios and judges them.
fn run(s: &Submission) -> (Verdict, Vec<Measures>) {
    let runs: Vec<Measures> = s
        .scenarios()
        .unwrap()
        .iter()
        .map(|sc| {
            let mut sim = Simulation::traced(sc).unwrap();
            sim.run().unwrap();
            measure(&sim)
        })
        .collect();
    (judge(&s.challenge, &runs).unwrap(), runs)
}

#[test]
fn the_codec_round_trips_in_a_fixed_order() {
    let c = Challenge::parse(SMALL).unwrap();
    let text = c.encode();
    // Allowed fields in the scenario's field order, choices in the field's order, criteria as
    // written.
    assert_eq!(
        text,
        "c=1&title=Quick%20step&base=v%3D1%26preset%3Dstep%26duration%3D0.08\
         &allow.k1=300..3000&allow.k2=300..3000&allow.ekf=euler|rk4\
         &need.settling_time=max:0.006&need.current_peak=max:4&need.mean_nis=band\
         &vary=model.j%3D0.016|model.j%3D0.024&robust=current_peak"
    );
    assert_eq!(Challenge::parse(&text).unwrap(), c);
    assert_eq!(Challenge::parse(&text).unwrap().encode(), text);
    assert_eq!(c.title, "Quick step");
    assert_eq!(
        c.run_labels(),
        ["nominal", "model.j=0.016", "model.j=0.024"]
    );
    // The short form of seeds, and a base written differently but meaning the same.
    let seeds = Challenge::parse(
        "c=1&base=v%3D1%26preset%3Dstep%26k1%3D1200&need.current_peak=max:4&vary=seeds:1..10&robust=current_peak",
    )
    .unwrap();
    assert_eq!(seeds.base, "v=1&preset=step");
    assert_eq!(seeds.run_labels().len(), 11);
    assert_eq!(seeds.run_labels()[10], "seed=10");
    assert_eq!(Challenge::parse(&seeds.encode()).unwrap(), seeds);
    // Submissions: canonical order of the tries, from a full URL.
    let url = format!("https://lab.example/im/?{SMALL}&try.ekf=rk4&try.k1=2000.0#results");
    let s = Submission::parse(&url).unwrap();
    assert_eq!(
        s.tries,
        [("k1".into(), "2000".into()), ("ekf".into(), "rk4".into())]
    );
    assert_eq!(s.encode(), format!("{text}&try.k1=2000&try.ekf=rk4"));
    assert_eq!(Submission::parse(&s.encode()).unwrap(), s);
    let runs = s.scenarios().unwrap();
    assert_eq!(runs.len(), 3);
    assert_eq!(
        runs[0].encode(),
        "v=1&preset=step&k1=2000&ekf=rk4&duration=0.08"
    );
    assert_eq!(runs[2].model.j, 0.024);
    assert_eq!(runs[2].gains.k1, 2000.0);
}

#[test]
fn a_refused_try_names_its_key_or_field() {
    let refused = |text: &str| Submission::parse(text).expect_err(text);
    let cases: &[(&str, ErrorKind, &str)] = &[
        (
            "&try.k3=500",
            ErrorKind::Refused,
            "field 'k3' is not allowed",
        ),
        (
            "&try.k1=5000",
            ErrorKind::Refused,
            "k1=5000 is outside 300..3000",
        ),
        (
            "&try.k1=299.5",
            ErrorKind::Refused,
            "k1=299.5 is outside 300..3000",
        ),
        (
            "&try.ekf=rk5",
            ErrorKind::Refused,
            "ekf=rk5 is not one of euler|rk4",
        ),
        (
            "&try.k1=12x",
            ErrorKind::Malformed,
            "'try.k1' = '12x': not a number",
        ),
        ("&try.k1=inf", ErrorKind::Malformed, "'try.k1'"),
        (
            "&try.k1=1&try.k1=2",
            ErrorKind::Malformed,
            "'try.k1' is given more than once",
        ),
        (
            "&bogus=1",
            ErrorKind::Malformed,
            "field 'bogus' is not a challenge field",
        ),
        (
            "&garbage",
            ErrorKind::Malformed,
            "'garbage' is not of the form key=value",
        ),
        ("&try.k1=%ZZ", ErrorKind::Malformed, "'try.k1'"),
    ];
    for (tail, kind, needle) in cases {
        let e = refused(&format!("{SMALL}{tail}"));
        assert_eq!(e.kind, *kind, "{tail}: {e}");
        assert!(e.to_string().contains(needle), "{tail}: {e}");
    }
}

#[test]
fn a_figure_takes_a_band_exactly_when_its_bounds_offer_one() {
    for f in imlab::challenge::figures() {
        let link = format!(
            "c=1&title=t&base=v%3D1%26preset%3Dstep&need.{}=band",
            f.name
        );
        let (ops, op) = imlab::challenge::criterion_ops(f.name);
        assert!(ops.contains(&op), "{}", f.name);
        assert_eq!(
            Challenge::parse(&link).is_ok(),
            ops.contains(&"band"),
            "{}",
            f.name
        );
    }
}

#[test]
fn a_refused_challenge_names_its_field() {
    let challenge_cases: &[(&str, &str)] = &[
        (
            "c=2&base=step&need.current_peak=max:4",
            "field 'c' = '2': unsupported challenge version",
        ),
        ("base=step&need.current_peak=max:4", "field 'c' is missing"),
        ("c=1&need.current_peak=max:4", "field 'base' is missing"),
        (
            "c=1&base=v%3D1%26preset%3Dnope&need.current_peak=max:4",
            "field 'base': field 'preset'",
        ),
        (
            "c=1&base=step&need.current_peak=max:4&allow.kk=1..2",
            "field 'allow.kk'",
        ),
        (
            "c=1&base=step&need.current_peak=max:4&allow.k1=2..1",
            "field 'allow.k1' = '2..1'",
        ),
        (
            "c=1&base=step&need.current_peak=max:4&allow.k1=-5..1",
            "field 'allow.k1' = '-5..1'",
        ),
        (
            "c=1&base=step&need.current_peak=max:4&allow.ekf=euler|rk5",
            "field 'allow.ekf'",
        ),
        (
            "c=1&base=step&need.peak=max:4",
            "field 'need.peak': 'peak' is not a figure",
        ),
        (
            "c=1&base=step&need.current_peak=most:4",
            "field 'need.current_peak' = 'most:4'",
        ),
        (
            "c=1&base=step&need.current_peak=band",
            "only mean_nis has a band",
        ),
        (
            "c=1&base=step&need.load_recovery_time=max:1",
            "the base has no load step",
        ),
        ("c=1&base=step", "no criteria"),
        (
            "c=1&base=step&need.current_peak=max:4&vary=seed%3D2",
            "field 'vary': no criterion uses",
        ),
        (
            "c=1&base=step&need.current_peak=max:4&robust=current_peak",
            "field 'robust'",
        ),
        (
            "c=1&base=step&need.current_peak=max:4&vary=k1%3D-1&robust=current_peak",
            "field 'vary', variant 1: field 'k1'",
        ),
        (
            "c=1&base=step&need.current_peak=max:4&vary=seeds:1..30&robust=current_peak",
            "field 'vary' = 'seeds:1..30'",
        ),
        (
            "c=1&base=step&need.current_peak=max:4&vary=seed%3D2&robust=mean_nis",
            "field 'robust' = 'mean_nis'",
        ),
        (
            "c=1&base=step&need.current_peak=max:4&try.k1=5",
            "field 'try.k1': this is a submission",
        ),
        (
            "no-such-challenge",
            "'no-such-challenge' is neither a challenge link nor a built-in",
        ),
    ];
    for (text, needle) in challenge_cases {
        let e = Challenge::parse(text).expect_err(text);
        assert_eq!(e.kind, ErrorKind::Malformed, "{text}");
        assert!(e.to_string().contains(needle), "{text}: {e}");
    }
}

#[test]
fn user_text_in_a_refusal_is_cut_and_escaped() {
    // User text is quoted through `excerpt`: cut, and invisible characters escaped.
    let e = Challenge::parse(&format!(
        "c=1&base=step&need.current_peak=max:4&{}\u{202e}=1",
        "x".repeat(60)
    ))
    .unwrap_err();
    assert!(e.to_string().contains("… (61 characters)"), "{e}");
    assert!(!e.to_string().contains('\u{202e}'));
}

#[test]
fn a_long_challenge_text_is_refused_at_once() {
    // Long texts are refused at once.
    let e = Challenge::parse(&format!("c=1&title={}", "x".repeat(20_000))).unwrap_err();
    assert!(
        e.to_string().contains("16384 bytes (16 KiB) allowed"),
        "{e}"
    );
}

#[test]
fn a_submission_of_another_challenge_is_told_apart() {
    let c = Challenge::parse(SMALL).unwrap();
    let mine = format!("{}&try.k1=2000", c.encode());
    assert!(c.submission(&mine).is_ok());
    // The same challenge written in another order is the same challenge.
    assert!(c.submission(&format!("{SMALL}&try.k1=2000")).is_ok());
    // A widened range, a changed title, a dropped criterion: another challenge, even where the
    // try would be refused by the original.
    for edited in [
        mine.replace("allow.k1=300..3000", "allow.k1=300..9000")
            .replace("k1=2000", "k1=8000"),
        mine.replace("Quick%20step", "Quick%20steps"),
        mine.replace("&need.mean_nis=band", ""),
    ] {
        let e = c.submission(&edited).unwrap_err();
        assert_eq!(e.kind, ErrorKind::Another, "{edited}");
        assert_eq!(e.status().to_string(), "another challenge");
    }
}

#[test]
fn the_figures_criteria_name_are_the_reports() {
    // Every figure of a report with PWM and a step is one criteria may name, with its label and
    // unit (the band's ends and the rating excepted), so the table cannot drift from the report.
    for text in [
        "v=1&preset=sine200-drive&duration=0.02",
        "v=1&preset=step&duration=0.08",
    ] {
        let s = imlab::scenario::Scenario::parse(text).unwrap();
        let mut sim = Simulation::traced(&s).unwrap();
        sim.run().unwrap();
        for f in sim.report().figures.unwrap() {
            if matches!(f.name, "mean_nis_low" | "mean_nis_high" | "current_rated") {
                continue;
            }
            let info = figure_info(f.name).expect(f.name);
            assert_eq!((&info.label, info.unit), (&f.label, f.unit), "{}", f.name);
        }
    }
}

#[test]
fn criteria_judge_values_bounds_settling_and_the_worst_variant() {
    let m = |name: &str, value: f64, settled: Option<bool>| Measure {
        name: name.into(),
        value,
        unit: String::new(),
        settled,
    };
    let c = Challenge::parse(
        "c=1&base=v%3D1%26preset%3Dload-step&need.speed_error_final=abs:0.1&need.mean_nis=band\
         &need.current_peak=max:4&need.load_recovery_time=max:0.2&vary=seed%3D2&robust=current_peak",
    )
    .unwrap();
    let nominal = Measures {
        figures: vec![
            m("speed_error_final", -0.05, Some(false)),
            m("mean_nis", 2.1, None),
            m("mean_nis_low", 1.9, None),
            m("mean_nis_high", 2.05, None),
            m("current_peak", 3.5, None),
            m(LOAD_RECOVERY, f64::INFINITY, None),
        ],
        ..Measures::default()
    };
    let variant = Measures {
        figures: vec![m("current_peak", 4.5, None)],
        ..Measures::default()
    };
    let v = judge(&c, &[nominal.clone(), variant.clone()]).unwrap();
    let reasons: Vec<String> = v
        .criteria
        .iter()
        .map(|c| c.reason.as_ref().map_or(String::new(), |r| r.to_string()))
        .collect();
    // The verdict says which value was still changing, apart from its words.
    let settled: Vec<bool> = v.criteria.iter().map(|c| c.settled).collect();
    assert_eq!(settled[..2], [false, true]);
    let rows: Vec<_> = v
        .criteria
        .iter()
        .zip(&reasons)
        .map(|(c, reason)| {
            (
                c.figure.as_str(),
                c.value,
                c.pass,
                reason.as_str(),
                c.run.as_str(),
            )
        })
        .collect();
    assert_eq!(
        rows,
        [
            // Within the bound, but still changing: a moving final value never passes.
            (
                "speed_error_final",
                Some(-0.05),
                false,
                "still changing",
                "nominal"
            ),
            ("mean_nis", Some(2.1), false, "above the band", "nominal"),
            // The worst run counts.
            (
                "current_peak",
                Some(4.5),
                false,
                "above the bound",
                "seed=2"
            ),
            (
                LOAD_RECOVERY,
                Some(f64::INFINITY),
                false,
                "not recovered by the end of the run",
                "nominal"
            ),
        ]
    );
    assert!(!v.pass);
    assert_eq!(v.criteria[2].bound.to_string(), "≤ 4 A");
    // Settled, inside the band, every run within the bound, recovered.
    let mut good = nominal;
    good.figures[0].settled = Some(true);
    good.figures[1].value = 2.0;
    good.figures[5].value = 0.15;
    let mut ok_variant = variant;
    ok_variant.figures[0].value = 3.9;
    let v = judge(&c, &[good.clone(), ok_variant.clone()]).unwrap();
    assert!(v.pass, "{v:?}");
    assert_eq!(v.criteria[2].value, Some(3.9));
    // A failed run fails every criterion it enters; a missing figure is not a pass.
    let failed = Measures {
        failure: Some(imlab::text::Message::new("challenge-run-unfinished").into()),
        ..Measures::default()
    };
    let v = judge(&c, &[good.clone(), failed]).unwrap();
    let reason = |v: &Verdict, i: usize| v.criteria[i].reason.clone().unwrap();
    assert_eq!(
        reason(&v, 2).to_string(),
        "run failed: the run did not finish"
    );
    assert!(!v.pass);
    good.figures.retain(|f| f.name != "current_peak");
    let v = judge(&c, &[good, ok_variant]).unwrap();
    assert!(
        reason(&v, 2).to_string().starts_with("not measured"),
        "{v:?}"
    );
    // The count of runs must match.
    assert!(judge(&c, &[]).is_err());
}

#[test]
fn load_recovery_time_follows_the_lessons_rule() {
    // The lessons' IFOC load run (tests/lessons.test.mjs: recovery(IFOC_LOAD, 1, 0.5) ≈ 0.1 s).
    let s = imlab::scenario::Scenario::parse(
        "v=1&preset=load-step&controller=ifoc&load.time=1&duration=2",
    )
    .unwrap();
    let mut sim = Simulation::traced(&s).unwrap();
    sim.run().unwrap();
    let m = measure(&sim);
    let t = m.get(LOAD_RECOVERY).unwrap().value;
    assert!((t - 0.1).abs() < 0.01, "{t}");
    // A run ending before the step has no recovery time.
    let s = imlab::scenario::Scenario::parse("v=1&preset=load-step&duration=0.1").unwrap();
    let mut sim = Simulation::traced(&s).unwrap();
    sim.run().unwrap();
    assert!(measure(&sim).get(LOAD_RECOVERY).is_none());
}

/// Each built-in: its canonical text is its text, the untouched base fails at least one
/// criterion, the known solution passes every one.
#[test]
fn built_ins_fail_untouched_and_pass_with_their_solution() {
    for b in BUILTINS {
        let c = b.challenge();
        assert_eq!(c.encode(), b.text, "{}", b.name);
        assert_eq!(Challenge::parse(b.name).unwrap(), c);
        let untouched = c.submission(b.text).unwrap();
        let (base, _) = run(&untouched);
        assert!(!base.pass, "{}: {base:?}", b.name);
        let (solved, _) = run(&b.solved());
        assert!(solved.pass, "{}: {solved:?}", b.name);
        let value = |v: &Verdict, f: &str| {
            v.criteria
                .iter()
                .find(|c| c.figure == f)
                .unwrap()
                .value
                .unwrap()
        };
        match b.name {
            "step-tune" => {
                // Default gains: 5.9 ms, and within the rating once the start-up is over (seed 3
                // draws 6.1 A during it); tuned: 3.45 ms and 3.63 A.
                assert!(value(&base, "settling_time") > 0.0055);
                assert!(value(&base, "current_peak") < 4.0);
                assert!(value(&solved, "settling_time") < 0.0036);
                assert!(value(&solved, "current_peak") < 3.7);
            }
            "load-observer" => {
                // The 5-state EKF: −24.8 rad/s, mean NIS 35.6; with the load as a state: 2.4 mrad/s.
                assert!(value(&base, "speed_error_final").abs() > 20.0);
                assert!(value(&base, "mean_nis") > 30.0);
                assert!(value(&solved, "speed_error_final").abs() < 0.005);
            }
            "ifoc-load" => {
                // Defaults: 0.139 s and 20.3 A; tuned: 0.051 s and 3.91 A.
                assert!(value(&base, LOAD_RECOVERY) > 0.13);
                assert!(value(&base, "current_peak") > 20.0);
                assert!(value(&solved, LOAD_RECOVERY) < 0.06);
            }
            other => panic!("no checks for {other}"),
        }
    }
}

/// The cells of one CSV line (RFC 4180 quoting).
fn csv_row(line: &str) -> Vec<String> {
    let (mut cells, mut cell, mut quoted, mut chars) =
        (Vec::new(), String::new(), false, line.chars().peekable());
    while let Some(c) = chars.next() {
        match (c, quoted) {
            ('"', true) if chars.peek() == Some(&'"') => {
                cell.push('"');
                chars.next();
            }
            ('"', _) => quoted = !quoted,
            (',', false) => cells.push(std::mem::take(&mut cell)),
            _ => cell.push(c),
        }
    }
    cells.push(cell);
    cells
}

#[test]
#[cfg(unix)]
fn grade_writes_one_row_per_link_with_status_and_pass() {
    let b = BUILTINS.iter().find(|b| b.name == "step-tune").unwrap();
    let good = b.solved().encode();
    let file = [
        "# class of 2026".to_string(),
        String::new(),
        good.clone(),
        b.text.to_string(),
        good.replace("try.k1=2000", "try.k1=6000"),
        format!("{}&try.ekf=rk4", b.text),
        good.replace("allow.k1=300..5000", "allow.k1=300..9000"),
        format!("https://lab.example/?{good}#top"),
        "c=1&title=x&garbage".to_string(),
        good.replace("try.k2=2000", "try.k2=fast"),
    ]
    .join("\n");
    let path = std::env::temp_dir().join(format!("imlab-grade-{}.txt", std::process::id()));
    std::fs::write(&path, &file).unwrap();
    let out = Command::new(env!("CARGO_BIN_EXE_imlab"))
        .args(["grade", "step-tune"])
        .arg(&path)
        .stdin(Stdio::null())
        .output()
        .unwrap();
    std::fs::remove_file(&path).unwrap();
    assert!(
        out.status.success(),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
    let text = String::from_utf8(out.stdout).unwrap();
    let lines: Vec<&str> = text.lines().collect();
    assert_eq!(
        lines[0],
        "line,link,status,settling_time,settling_time_pass,current_peak,current_peak_pass,pass"
    );
    // line, link, status, then the judged columns.
    let rows: Vec<(String, String, Vec<String>)> = lines[1..]
        .iter()
        .map(|l| {
            let cells = csv_row(l);
            (cells[0].clone(), cells[2].clone(), cells[3..].to_vec())
        })
        .collect();
    // The links holding a comma (robust=a,b) are quoted.
    assert!(lines[1].starts_with("3,\"c=1&"), "{}", lines[1]);
    let status: Vec<(&str, &str)> = rows
        .iter()
        .map(|(l, s, _)| (l.as_str(), s.as_str()))
        .collect();
    assert_eq!(
        status,
        [
            ("3", "ok"),
            ("4", "ok"),
            ("5", "refused: k1=6000 is outside 300..5000"),
            ("6", "refused: field 'ekf' is not allowed"),
            ("7", "another challenge"),
            ("8", "ok"),
            ("9", "malformed: 'garbage' is not of the form key=value"),
            ("10", "malformed: field 'try.k2' = 'fast': not a number"),
        ]
    );
    let pass_columns: Vec<Vec<&str>> = rows
        .iter()
        .map(|(_, _, c)| vec![c[1].as_str(), c[3].as_str(), c[4].as_str()])
        .collect();
    // The untouched gains (line 4) keep the rating and fail on the settling time alone.
    assert_eq!(
        pass_columns,
        [
            vec!["1", "1", "1"],
            vec!["0", "1", "0"],
            vec!["0", "0", "0"],
            vec!["0", "0", "0"],
            vec!["0", "0", "0"],
            vec!["1", "1", "1"],
            vec!["0", "0", "0"],
            vec!["0", "0", "0"],
        ]
    );
    // Judged rows carry the worst values; refused ones none.
    let peak: f64 = rows[0].2[2].parse().unwrap();
    assert!(peak > 3.5 && peak < 3.7, "{peak}");
    assert_eq!(rows[2].2[0], "");
    // A link with a quote in it is escaped by doubling.
    let out = Command::new(env!("CARGO_BIN_EXE_imlab"))
        .args(["grade", "step-tune", "-"])
        .stdin(Stdio::piped())
        .stdout(Stdio::piped())
        .spawn()
        .and_then(|mut child| {
            use std::io::Write;
            child.stdin.take().unwrap().write_all(b"c=1&\"x\"=1\n")?;
            child.wait_with_output()
        })
        .unwrap();
    let text = String::from_utf8(out.stdout).unwrap();
    let row = text.lines().nth(1).unwrap();
    assert!(row.starts_with("1,\"c=1&\"\"x\"\"=1\","), "{row}");
    assert_eq!(
        csv_row(row)[1..3],
        ["c=1&\"x\"=1", "malformed: field '\"x\"' is not a challenge field (c, title, base, allow.FIELD, need.FIGURE, vary, robust, try.FIELD)"]
    );
    // A bad challenge or file is the command's failure.
    for args in [
        ["grade", "nope", "-"],
        ["grade", "step-tune", "/no/such/file"],
    ] {
        let out = Command::new(env!("CARGO_BIN_EXE_imlab"))
            .args(args)
            .stdin(Stdio::null())
            .output()
            .unwrap();
        assert_eq!(out.status.code(), Some(2), "{args:?}");
    }
}

#[test]
fn any_link_of_a_challenge_opens_it() {
    let c = Challenge::parse(SMALL).unwrap();
    let step_tune = builtin("step-tune").unwrap().challenge();
    for link in [
        SMALL.to_string(),
        SMALL_CANONICAL.to_string(),
        format!("{SMALL}&try.k1=2000&try.ekf=rk4"),
        // The tries are left out unread: a bad or repeated one does not stop the challenge.
        format!("{SMALL}&try.k1=%ZZ&try.k1=2&try.=x"),
        format!("https://lab.example/im/?{SMALL}&try.k1=2000#results"),
        format!("?try.k2=900&{SMALL}"),
    ] {
        assert_eq!(Challenge::from_link(&link).unwrap(), c, "{link}");
    }
    for link in [
        "step-tune",
        "challenge=step-tune",
        "?challenge=step-tune",
        "https://lab.example/im/?challenge=step-tune#top",
    ] {
        assert_eq!(Challenge::from_link(link).unwrap(), step_tune, "{link}");
    }
    let refused = |link: &str| Challenge::from_link(link).unwrap_err().to_string();
    assert!(refused("challenge=nope").contains("'nope' is neither a challenge link nor a built-in"));
    assert!(refused("v=1&preset=step").contains("field 'c' is missing"));
    assert!(refused(&format!("{SMALL}&need.bogus=max:1")).contains("'need.bogus'"));
    assert!(refused(&format!("{SMALL}&try.k1={}", "9".repeat(20_000))).contains("16 KiB"));
}

#[test]
fn a_submission_written_from_values_is_the_canonical_link_and_reads_back() {
    let c = Challenge::parse(SMALL).unwrap();
    let tries = |pairs: &[(&str, &str)]| -> Vec<(String, String)> {
        pairs
            .iter()
            .map(|(f, v)| (f.to_string(), v.to_string()))
            .collect()
    };
    let s = c
        .submit(&tries(&[("ekf", "rk4"), ("k1", "2000.0")]))
        .unwrap();
    assert_eq!(
        s.encode(),
        format!("{SMALL_CANONICAL}&try.k1=2000&try.ekf=rk4")
    );
    assert_eq!(c.submission(&s.encode()).unwrap(), s);
    assert_eq!(Submission::parse(&s.encode()).unwrap(), s);
    // No values: the challenge's own link.
    let none = c.submit(&[]).unwrap();
    assert_eq!(none.encode(), SMALL_CANONICAL);
    assert_eq!(c.submission(&none.encode()).unwrap(), none);
    // A value is encoded, so it cannot add parts of its own to the link.
    let e = c.submit(&tries(&[("k1", "1&try.k2=5")])).unwrap_err();
    assert_eq!(e.kind, ErrorKind::Malformed);
    assert!(
        e.to_string()
            .contains("'try.k1' = '1&try.k2=5': not a number"),
        "{e}"
    );
    // Refusals as the codec words them.
    for (pairs, kind, needle) in [
        (
            &[("k3", "500")][..],
            ErrorKind::Refused,
            "field 'k3' is not allowed",
        ),
        (
            &[("k1", "5000")][..],
            ErrorKind::Refused,
            "k1=5000 is outside 300..3000",
        ),
        (
            &[("ekf", "rk5")][..],
            ErrorKind::Refused,
            "ekf=rk5 is not one of euler|rk4",
        ),
        (
            &[("k1", "1000"), ("k1", "2000")][..],
            ErrorKind::Malformed,
            "'try.k1' is given more than once",
        ),
    ] {
        let e = c.submit(&tries(pairs)).unwrap_err();
        assert_eq!(e.kind, kind, "{pairs:?}: {e}");
        assert!(e.to_string().contains(needle), "{pairs:?}: {e}");
    }
    // Every built-in's solution, written from its values, is the link its solution reads as.
    for b in BUILTINS {
        let pairs: Vec<(String, String)> = b
            .solution
            .split('&')
            .map(|p| {
                let (f, v) = p.split_once('=').unwrap();
                (f.to_string(), v.to_string())
            })
            .collect();
        let s = b.challenge().submit(&pairs).unwrap();
        assert_eq!(s, b.solved(), "{}", b.name);
        assert_eq!(s.encode(), b.solved().encode(), "{}", b.name);
    }
}

#[test]
fn a_built_ins_name_may_carry_a_try_and_stray_characters_are_named() {
    let b = builtin("step-tune").unwrap();
    let c = b.challenge();
    let solved = b.solved().encode();
    let tries = solved.strip_prefix(b.text).unwrap();
    assert!(tries.starts_with("&try."), "{solved}");
    let short = format!("challenge=step-tune{tries}");
    assert_eq!(c.submission(&short).unwrap(), b.solved());
    assert_eq!(
        c.submission(&format!("https://lab.example/im/?{short}#x"))
            .unwrap(),
        b.solved()
    );
    assert_eq!(Challenge::from_link(&short).unwrap(), c);
    let other = builtin("ifoc-load").unwrap().challenge();
    assert_eq!(
        other.submission(&short).unwrap_err().kind,
        ErrorKind::Another
    );
    let refused = |link: &str| c.submission(link).unwrap_err().to_string();
    assert_eq!(
        refused("challenge=step-tune&title=Easy&try.k1=2000"),
        "field 'title' cannot follow challenge=step-tune: a built-in challenge's link holds \
         only challenge=NAME and the student's try.FIELD parts"
    );
    // A stray character before the link is named, not taken for a missing field.
    assert_eq!(
        refused(&format!("={solved}")),
        "the link starts with the stray character '=' before its c=1: remove it"
    );
    assert_eq!(
        refused(&format!("\"'{solved}")),
        "the link starts with the stray characters '\"'' before its c=1: remove them"
    );
    assert!(refused("v=1&preset=step").contains("field 'c' is missing"));
    assert!(refused("xc=1&title=a").contains("field 'c' is missing"));
}
