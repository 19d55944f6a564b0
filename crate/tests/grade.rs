//! Grading a class: the class file read in every encoding, line end and shape, the grades' cells
//! safe for a spreadsheet and a terminal, the fingerprint of a challenge, and `imlab grade`
//! streaming its rows and resuming a cut-off output to the same bytes.

// Runs native processes; the crate's tests also build for wasm32.
#![cfg(not(target_arch = "wasm32"))]

use imlab::challenge::grade::{
    csv_header, csv_row, grade_row, read_class, resume, resume_sample, Class, ClassRow, Graded,
    RESUME_STRIDE,
};
use imlab::challenge::{builtin, Challenge, CriterionVerdict, Verdict, BUILTINS};
use imlab::text::csv::text_field;
use std::io::{BufRead, BufReader};
use std::path::PathBuf;
use std::process::{Command, Output, Stdio};

/// A challenge whose runs take milliseconds: no variants, 0.06 s of `step`.
const QUICK: &str = "c=1&title=Quick&base=v%3D1%26preset%3Dstep%26duration%3D0.06\
                     &allow.k1=300..3000&need.current_peak=max:4&need.settling_time=max:0.006";

/// A passing submission of [`QUICK`].
fn quick_link(k1: u32) -> String {
    format!("{QUICK}&try.k1={k1}")
}

/// The (line, link, status) of each row.
fn rows(class: &Class) -> Vec<(usize, String, Option<String>)> {
    class
        .rows
        .iter()
        .map(|r| (r.line, r.link.clone(), r.status.clone()))
        .collect()
}

/// `text` in UTF-16 with a byte-order mark.
fn utf16(text: &str, big_endian: bool) -> Vec<u8> {
    let mut out = if big_endian {
        vec![0xfe, 0xff]
    } else {
        vec![0xff, 0xfe]
    };
    for u in text.encode_utf16() {
        out.extend(if big_endian {
            u.to_be_bytes()
        } else {
            u.to_le_bytes()
        });
    }
    out
}

#[test]
fn every_encoding_and_line_end_reads_the_same_rows() {
    let lines = ["# class", "", "c=1&a", "  c=1&b  ", "#x", "step-tune"];
    let lf = lines.join("\n");
    let expected = vec![
        (3, "c=1&a".to_string(), None),
        (4, "c=1&b".to_string(), None),
        (6, "step-tune".to_string(), None),
    ];
    let mut bom = b"\xef\xbb\xbf".to_vec();
    bom.extend(lf.as_bytes());
    let files: Vec<(&str, Vec<u8>)> = vec![
        ("LF", lf.clone().into_bytes()),
        ("LF, last line ended", format!("{lf}\n").into_bytes()),
        ("CRLF", lines.join("\r\n").into_bytes()),
        ("CR", lines.join("\r").into_bytes()),
        ("BOM", bom),
        ("UTF-16 LE", utf16(&lines.join("\r\n"), false)),
        ("UTF-16 BE", utf16(&lf, true)),
    ];
    for (name, bytes) in files {
        let class = read_class(&bytes).unwrap_or_else(|e| panic!("{name}: {e}"));
        assert_eq!(rows(&class), expected, "{name}");
        assert!(class.columns.is_empty() && class.link_column.is_none());
    }
    assert_eq!(read_class(b"").unwrap(), Class::default());
}

#[test]
fn utf16_without_a_byte_order_mark_and_binary_files_are_refused_saying_what_they_are() {
    let text = "c=1&title=x\nc=1&title=y\n";
    for big_endian in [false, true] {
        let bytes = utf16(text, big_endian)[2..].to_vec();
        assert_eq!(
            read_class(&bytes).unwrap_err(),
            "the file is UTF-16 without a byte-order mark; save it as UTF-8"
        );
    }
    let zip = b"PK\x03\x04\x14\x00\x06\x00\x08\x00\x00\x00!\x00\xb1\x82\xa5\xc3xlsx";
    let message = read_class(zip).unwrap_err();
    assert!(message.starts_with("the file is not text"), "{message}");
}

#[test]
fn an_invalid_utf8_byte_spoils_only_its_own_line() {
    // The byte-order mark says UTF-8: without it, the file would be read as Windows-1252.
    let class = read_class(b"\xef\xbb\xbfc=1&a\nc=1&\xff&b\nc=1&c\n").unwrap();
    assert_eq!(
        rows(&class),
        [
            (1, "c=1&a".to_string(), None),
            (
                2,
                "c=1&\u{fffd}&b".to_string(),
                Some("malformed: line 2 is not valid UTF-8".to_string())
            ),
            (3, "c=1&c".to_string(), None),
        ]
    );
    // In a UTF-16 file, an unpaired surrogate spoils its line the same way.
    let mut bytes = utf16("c=1&a\nc=1&b\n", false);
    bytes.splice(8..8, [0x00, 0xd8]);
    let class = read_class(&bytes).unwrap();
    assert_eq!(
        class.rows[0].status,
        Some("malformed: line 1 is not valid UTF-16".to_string())
    );
    assert_eq!(class.rows[1].status, None);
    // The row is graded with its status, without a run.
    let c = Challenge::parse(QUICK).unwrap();
    let graded = grade_row(&c, &read_class(b"\xef\xbb\xbf\xfe").unwrap().rows[0]);
    assert_eq!(graded.status, "malformed: line 1 is not valid UTF-8");
    assert_eq!(graded.verdict, None);
}

#[test]
fn a_csv_export_carries_its_other_columns_and_reads_quoted_fields() {
    let file = "Name,Email,Submission,Notes\r\n\
                \"Lovelace, Ada\",ada@example.org,c=1&a,\"first line\r\nsecond \"\"quoted\"\" line\"\r\n\
                ,,,\r\n\
                Bob,bob@example.org, c=1&b ,\r\n\
                Carol,carol@example.org,,absent\r\n\
                Dan,dan@example.org,c=1&d\r\n";
    let class = read_class(file.as_bytes()).unwrap();
    assert_eq!(class.columns, ["Name", "Email", "Notes"]);
    assert_eq!(class.link_column.as_deref(), Some("Submission"));
    let carried: Vec<(usize, &str, Vec<&str>, Option<&str>)> = class
        .rows
        .iter()
        .map(|r| {
            (
                r.line,
                r.link.as_str(),
                r.carried.iter().map(String::as_str).collect(),
                r.status.as_deref(),
            )
        })
        .collect();
    assert_eq!(
        carried,
        [
            (
                2,
                "c=1&a",
                vec![
                    "Lovelace, Ada",
                    "ada@example.org",
                    "first line\nsecond \"quoted\" line"
                ],
                None
            ),
            (5, "c=1&b", vec!["Bob", "bob@example.org", ""], None),
            (
                6,
                "",
                vec!["Carol", "carol@example.org", "absent"],
                Some("malformed: no link")
            ),
            (
                7,
                "c=1&d",
                vec!["Dan", "dan@example.org", ""],
                Some("malformed: line 7 has 3 fields, the header 4")
            ),
        ]
    );
    // The header and rows as written: carried cells first, quoted and escaped.
    let c = Challenge::parse(QUICK).unwrap();
    assert_eq!(
        csv_header(&c, &class),
        "Name,Email,Notes,line,link,status,current_peak,current_peak_pass,\
         settling_time,settling_time_pass,pass\n"
    );
    let row = &class.rows[0];
    assert_eq!(
        csv_row(&c, row, &grade_row(&c, row)),
        "\"Lovelace, Ada\",ada@example.org,\"first line\\nsecond \"\"quoted\"\" line\",2,c=1&a,\
         malformed: 'a' is not of the form key=value,,0,,0,0\n"
    );
}

#[test]
fn the_column_of_links_is_found_by_its_header_or_its_cells_and_ambiguity_is_refused() {
    // By content, with semicolons (a spreadsheet's export in many locales).
    let class = read_class(b"Student;Answer\nAda;https://lab.example/?c=1&x\n").unwrap();
    assert_eq!(class.link_column.as_deref(), Some("Answer"));
    assert_eq!(class.rows[0].link, "https://lab.example/?c=1&x");
    // By header, in any case, even alone.
    let class = read_class(b"URL\nc=1&x\n").unwrap();
    assert_eq!(rows(&class), [(2, "c=1&x".to_string(), None)]);
    assert_eq!(
        read_class(b"Name,Link,Old link\nAda,c=1&a,challenge=step-tune\n")
            .unwrap()
            .link_column
            .as_deref(),
        Some("Link")
    );
    assert_eq!(
        read_class(b"Name,First,Second\nAda,c=1&a,challenge=step-tune\n").unwrap_err(),
        "the columns 'First', 'Second' all hold links; head the one to grade 'link'"
    );
    assert_eq!(
        read_class(b"Name,Mark\nAda,12\n").unwrap_err(),
        "no column of links in this CSV export (its columns: 'Name', 'Mark'); head the column \
         of links 'link'"
    );
    assert_eq!(
        read_class(b"link,URL\nc=1&a,c=1&b\n").unwrap_err(),
        "the columns 'link', 'URL' are all headed as links; keep one"
    );
    // A link written unquoted takes the fields its commas split off.
    let b = builtin("step-tune").unwrap();
    assert!(b.text.contains(','));
    let class = read_class(format!("Name,Link,Mark\nAda,{},12\n", b.text).as_bytes()).unwrap();
    assert_eq!(class.rows[0].link, b.text);
    assert_eq!(class.rows[0].carried, ["Ada", "12"]);
    assert_eq!(class.rows[0].status, None);
    // A first line that is a link, even one with commas, keeps the file one link a line.
    let class = read_class(format!("{}\nc=1,x\n", b.text).as_bytes()).unwrap();
    assert_eq!(class.rows.len(), 2);
    assert_eq!(class.rows[0].link, b.text);
}

#[test]
fn cells_from_students_cannot_run_formulas_or_carry_invisible_characters() {
    let valid = quick_link(1200);
    // A link that opens as a valid submission behind a formula: graded ok, written as text.
    let c = Challenge::parse(QUICK).unwrap();
    let row = ClassRow {
        line: 3,
        link: format!("=1+1?{valid}"),
        carried: vec![
            "=HYPERLINK(\"http://x\")".into(),
            "\u{1b}[31mred\u{202e}".into(),
        ],
        status: None,
    };
    let graded = grade_row(&c, &row);
    assert_eq!(graded.status, "ok");
    let line = csv_row(&c, &row, &graded);
    assert!(
        line.starts_with(&format!(
            "\"'=HYPERLINK(\"\"http://x\"\")\",\\u{{1b}}[31mred\\u{{202e}},3,'=1+1?{valid},ok,"
        )),
        "{line}"
    );
    for (text, cell) in [
        ("=1+1", "'=1+1"),
        ("+1", "'+1"),
        ("-1", "'-1"),
        ("@SUM(A1)", "'@SUM(A1)"),
        ("\tx", "'\\tx"),
        ("\r=1", "'\\r=1"),
        ("\u{ff1d}1", "'\u{ff1d}1"),
        ("a=1", "a=1"),
        (
            "x\u{0}\u{7f}\u{85}\u{200e}\u{200f}\u{61c}\u{2066}\u{2069}",
            "x\\u{0}\\u{7f}\\u{85}\\u{200e}\\u{200f}\\u{61c}\\u{2066}\\u{2069}",
        ),
        ("a\nb", "a\\nb"),
        ("a,b", "\"a,b\""),
        // A spreadsheet may split on a semicolon or a tab too: such a cell is quoted, and a
        // formula's start after any separator is written as text as well.
        ("a;b", "\"a;b\""),
        ("a\tb", "a\\tb"),
        ("a\t=1", "a\\t'=1"),
        ("c=1#;=cmd|' /C calc'!A0;", "\"c=1#;'=cmd|' /C calc'!A0;\""),
        ("x,@SUM(A1)", "\"x,'@SUM(A1)\""),
        ("x;+1;-1", "\"x;'+1;'-1\""),
        ("x,\u{ff1d}1", "\"x,'\u{ff1d}1\""),
        ("x;;=1", "\"x;;'=1\""),
        ("a;b=1", "\"a;b=1\""),
    ] {
        assert_eq!(text_field(text), cell, "{text:?}");
    }
    // The numbers the grader computes are written as they are, a negative one too.
    let verdict = Verdict {
        criteria: vec![CriterionVerdict {
            figure: "current_peak".into(),
            label: String::new(),
            bound: String::new(),
            value: Some(-0.5),
            unit: "A".into(),
            run: "nominal".into(),
            pass: true,
            reason: String::new(),
        }],
        pass: true,
    };
    let one = Challenge::parse("c=1&base=step&need.current_peak=max:4").unwrap();
    let graded = Graded {
        verdict: Some(verdict),
        ..Graded::failed(7, "c=1", "ok")
    };
    let row = ClassRow {
        line: 7,
        link: "c=1".into(),
        ..ClassRow::default()
    };
    assert_eq!(csv_row(&one, &row, &graded), "7,c=1,ok,-0.5,1,1\n");
}

#[test]
fn fingerprints_are_short_stable_and_tell_edited_built_ins() {
    let expected = [
        ("step-tune", "DSY0-PQ6T"),
        ("load-observer", "AS23-M8PB"),
        ("ifoc-load", "X913-2SR0"),
    ];
    for (b, (name, fingerprint)) in BUILTINS.iter().zip(expected) {
        assert_eq!(b.name, name);
        assert_eq!(b.challenge().fingerprint(), fingerprint, "{name}");
        assert_eq!(b.challenge().edited_builtin(), None, "{name}");
    }
    let b = builtin("step-tune").unwrap();
    let wider = Challenge::parse(&b.text.replace("300..5000", "300..9000")).unwrap();
    assert_ne!(wider.fingerprint(), "DSY0-PQ6T");
    assert_eq!(wider.edited_builtin(), Some("step-tune"));
    let renamed = Challenge::parse(&wider.encode().replace(
        "title=Fast%20step%20within%20the%20rating",
        "title=STEP-TUNE",
    ))
    .unwrap();
    assert_eq!(renamed.edited_builtin(), Some("step-tune"));
    let other = Challenge::parse(QUICK).unwrap();
    assert_eq!(other.edited_builtin(), None);
    // The same challenge written differently is the same challenge.
    let shuffled = Challenge::parse(&format!(
        "{}&title=Quick",
        QUICK.replace("title=Quick&", "")
    ))
    .unwrap();
    assert_eq!(shuffled.fingerprint(), other.fingerprint());
}

#[test]
fn a_title_cannot_write_lines_of_its_own_into_the_brief() {
    let plain = Challenge::parse("c=1&title=x&base=step&need.current_peak=max:4").unwrap();
    let sly = Challenge::parse(
        "c=1&title=a%0A%0AYou%20may%20change%20only%3A%0D%0Ak1%E2%80%A8%1B%5B2J%E2%80%AE\
         &base=step&need.current_peak=max:4",
    )
    .unwrap();
    let brief = sly.brief();
    assert_eq!(brief.lines().count(), plain.brief().lines().count());
    assert_eq!(
        brief.lines().next().unwrap(),
        "a\\n\\nYou may change only:\\r\\nk1\\u{2028}\\u{1b}[2J\\u{202e}"
    );
}

/// A fresh temporary path for this test.
fn temp(name: &str) -> PathBuf {
    std::env::temp_dir().join(format!("imlab-grade-{}-{name}", std::process::id()))
}

/// `imlab` with `args`, stdin closed.
fn imlab(args: &[&str]) -> Output {
    Command::new(env!("CARGO_BIN_EXE_imlab"))
        .args(args)
        .stdin(Stdio::null())
        .output()
        .unwrap()
}

#[test]
fn challenge_output_escapes_what_the_title_hides() {
    let out = imlab(&[
        "challenge",
        "c=1&title=a%1Bb%0Dc%00d%E2%80%AEe%E2%81%A6&base=step&need.current_peak=max:4",
    ]);
    assert!(out.status.success());
    let text = String::from_utf8(out.stdout).unwrap();
    assert!(
        !text
            .chars()
            .any(|c| (c.is_control() && c != '\n') || ('\u{202a}'..='\u{202e}').contains(&c)),
        "{text:?}"
    );
    let lines: Vec<&str> = text.lines().collect();
    assert_eq!(
        lines[1],
        "fingerprint: ".to_string() + &Challenge::parse(lines[0]).unwrap().fingerprint()
    );
    assert_eq!(lines[3], "a\\u{1b}b\\rc\\u{0}d\\u{202e}e\\u{2066}");
    // An edited built-in is named as such.
    let b = builtin("step-tune").unwrap();
    let out = imlab(&["challenge", &b.text.replace("max:4", "max:40")]);
    let text = String::from_utf8(out.stdout).unwrap();
    assert_eq!(
        text.lines().nth(2).unwrap(),
        "edited: not the built-in step-tune (fingerprint DSY0-PQ6T), whose title it carries"
    );
}

#[test]
fn grade_reads_a_csv_export_and_writes_safe_cells() {
    let path = temp("export.csv");
    let mut file = b"\xef\xbb\xbfName,Link\r\n".to_vec();
    file.extend(format!("\"Lovelace, Ada\",{}\r\n", quick_link(1200)).as_bytes());
    file.extend(format!("\u{1b}[2JMallory,=1+1?{}\r\n", quick_link(2000)).as_bytes());
    file.extend(b"Eve \xff,c=1&x\r\n");
    std::fs::write(&path, &file).unwrap();
    let out = imlab(&["grade", QUICK, path.to_str().unwrap()]);
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
        "Name,line,link,status,current_peak,current_peak_pass,settling_time,settling_time_pass,pass"
    );
    assert!(lines[1].starts_with(&format!("\"Lovelace, Ada\",2,{},ok,", quick_link(1200))));
    assert!(lines[2].starts_with(&format!(
        "\\u{{1b}}[2JMallory,3,'=1+1?{},ok,",
        quick_link(2000)
    )));
    assert_eq!(
        lines[3],
        "Eve \u{fffd},4,c=1&x,malformed: line 4 is not valid UTF-8,,0,,0,0"
    );
    assert_eq!(lines.len(), 4);
    // A file refused whole is the command's failure, with the reason.
    std::fs::write(&path, &utf16("c=1&x\n", false)[2..]).unwrap();
    let out = imlab(&["grade", QUICK, path.to_str().unwrap()]);
    std::fs::remove_file(&path).unwrap();
    assert_eq!(out.status.code(), Some(2));
    assert!(
        String::from_utf8_lossy(&out.stderr)
            .ends_with(": the file is UTF-16 without a byte-order mark; save it as UTF-8\n"),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
}

/// A class of `QUICK` mixing rows graded in milliseconds (ok, refused, malformed) with a CSV
/// export's carried column.
fn class_file() -> String {
    let mut file = "Name,Link\n".to_string();
    for i in 0..12u32 {
        let link = match i % 4 {
            0 => quick_link(600 + 100 * i),
            1 => quick_link(9000),
            2 => format!("c=1&garbage{i}"),
            _ => format!("{QUICK}&try.k1=fast"),
        };
        file.push_str(&format!("Student {i},{link}\n"));
    }
    file
}

#[test]
fn a_cut_off_output_resumes_to_the_bytes_of_an_uninterrupted_run() {
    let class = temp("class.csv");
    std::fs::write(&class, class_file()).unwrap();
    let class_arg = class.to_str().unwrap();
    let whole = imlab(&["grade", QUICK, class_arg]);
    assert!(whole.status.success());
    let whole = whole.stdout;
    let header_end = whole.iter().position(|&b| b == b'\n').unwrap() + 1;
    let row_ends: Vec<usize> = whole
        .iter()
        .enumerate()
        .filter(|(_, &b)| b == b'\n')
        .map(|(i, _)| i + 1)
        .collect();
    let out = temp("resumed.csv");
    let out_arg = out.to_str().unwrap();
    let cuts = [
        0,
        5,
        header_end - 1,
        header_end,
        header_end + 3,
        row_ends[3] - 1,
        row_ends[3],
        row_ends[6] + 40,
        whole.len() - 1,
        whole.len(),
    ];
    for cut in cuts {
        std::fs::write(&out, &whole[..cut]).unwrap();
        let resumed = imlab(&["grade", QUICK, class_arg, "--resume", out_arg]);
        assert!(
            resumed.status.success(),
            "cut at {cut}: {}",
            String::from_utf8_lossy(&resumed.stderr)
        );
        assert!(resumed.stdout.is_empty());
        assert!(std::fs::read(&out).unwrap() == whole, "cut at {cut}");
    }
    // A missing OUT is started.
    std::fs::remove_file(&out).unwrap();
    assert!(imlab(&["grade", QUICK, class_arg, "--resume", out_arg])
        .status
        .success());
    assert!(std::fs::read(&out).unwrap() == whole);
    // The output of another challenge or class is refused, and left as it is.
    let refusals = [
        (
            QUICK.replace("&need.settling_time=max:0.006", ""),
            whole[..row_ends[2]].to_vec(),
            "its first line is not this grading's header",
        ),
        (
            QUICK.to_string(),
            [&whole[..header_end], &whole[row_ends[1]..row_ends[3]]].concat(),
            "its row 1 is not that of line 2 ('c=1&title=Quick&base=v%3D1%26preset%3Dst… (143 characters)') of the class file",
        ),
        (
            QUICK.to_string(),
            [&whole[..], &whole[row_ends[1]..row_ends[2]]].concat(),
            "it holds more rows than the class file's 12 submissions",
        ),
    ];
    for (challenge, previous, message) in refusals {
        std::fs::write(&out, &previous).unwrap();
        let refused = imlab(&["grade", &challenge, class_arg, "--resume", out_arg]);
        assert_eq!(refused.status.code(), Some(2));
        let stderr = String::from_utf8_lossy(&refused.stderr);
        assert!(stderr.contains(message), "{stderr}");
        assert!(std::fs::read(&out).unwrap() == previous);
    }
    // The core's resume point of the whole output is its end.
    let c = Challenge::parse(QUICK).unwrap();
    let read = read_class(class_file().as_bytes()).unwrap();
    let point = resume(&c, &read, &whole).unwrap();
    assert_eq!((point.keep, point.done), (whole.len(), 12));
    std::fs::remove_file(&out).unwrap();
    std::fs::remove_file(&class).unwrap();
}

#[test]
#[cfg(unix)]
fn rows_are_written_as_they_are_graded_and_a_killed_grading_keeps_them() {
    // A malformed first row, then rows of many long runs each: the first row must arrive while
    // the others still run.
    let slow = "c=1&title=Slow&base=v%3D1%26preset%3Dstep%26duration%3D2&allow.k1=300..3000\
                &need.current_peak=max:4&vary=seeds:1..20&robust=current_peak";
    let mut file = "c=1&garbage\n".to_string();
    for k1 in 0..40 {
        file.push_str(&format!("{slow}&try.k1={}\n", 1000 + k1));
    }
    let class = temp("slow.txt");
    std::fs::write(&class, &file).unwrap();
    let mut child = Command::new(env!("CARGO_BIN_EXE_imlab"))
        .args(["grade", slow, class.to_str().unwrap()])
        .stdin(Stdio::null())
        .stdout(Stdio::piped())
        .stderr(Stdio::null())
        .spawn()
        .unwrap();
    let mut stdout = BufReader::new(child.stdout.take().unwrap());
    let mut lines = Vec::new();
    for _ in 0..2 {
        let mut line = String::new();
        stdout.read_line(&mut line).unwrap();
        lines.push(line);
    }
    let running = child.try_wait().unwrap().is_none();
    child.kill().unwrap();
    child.wait().unwrap();
    std::fs::remove_file(&class).unwrap();
    assert!(
        lines[0].starts_with("line,link,status,current_peak"),
        "{}",
        lines[0]
    );
    assert_eq!(
        lines[1],
        "1,c=1&garbage,malformed: 'garbage' is not of the form key=value,,0,0\n"
    );
    assert!(running, "the first row came only at the end");
}

/// `text` in Windows-1252, as a spreadsheet on Windows saves CSV.
fn windows_1252(text: &str) -> Vec<u8> {
    let (bytes, _, unmappable) = encoding_rs::WINDOWS_1252.encode(text);
    assert!(!unmappable, "{text}");
    bytes.into_owned()
}

/// A CSV export whose names are accented and whose links are valid.
fn accented_export() -> String {
    format!(
        "Name,Link\r\n\"Müller, José\",{}\r\nFrançoise Œuvre – “Zoë”,{}\r\nÅsa Ørsted,c=1&x\r\n",
        quick_link(1200),
        quick_link(2000)
    )
}

#[test]
fn a_windows_1252_export_is_read_in_its_encoding_and_graded_like_its_utf8_twin() {
    let text = accented_export();
    let utf8 = read_class(text.as_bytes()).unwrap();
    let legacy = read_class(&windows_1252(&text)).unwrap();
    assert_eq!(utf8.encoding, None);
    assert_eq!(legacy.encoding, Some("windows-1252"));
    assert_eq!(legacy.rows, utf8.rows);
    assert_eq!(legacy.rows[0].carried, ["Müller, José"]);
    assert_eq!(legacy.rows[1].carried, ["Françoise Œuvre – “Zoë”"]);
    // The command grades both to the same bytes, and says which encoding it read.
    let path = temp("accented.csv");
    let mut outputs = Vec::new();
    for bytes in [text.into_bytes(), windows_1252(&accented_export())] {
        std::fs::write(&path, &bytes).unwrap();
        let out = imlab(&["grade", QUICK, path.to_str().unwrap()]);
        assert!(out.status.success());
        outputs.push(out);
    }
    std::fs::remove_file(&path).unwrap();
    assert!(outputs[0].stdout == outputs[1].stdout);
    let csv = String::from_utf8(outputs[1].stdout.clone()).unwrap();
    assert!(
        csv.lines()
            .nth(1)
            .unwrap()
            .starts_with(&format!("\"Müller, José\",2,{},ok,", quick_link(1200))),
        "{csv}"
    );
    assert!(outputs[0].stderr.is_empty());
    assert_eq!(
        String::from_utf8_lossy(&outputs[1].stderr),
        format!(
            "imlab grade: read '{}' as windows-1252 (it is not UTF-8)\n",
            path.display()
        )
    );
}

#[test]
fn a_second_grader_of_the_same_output_is_refused_and_leaves_it_as_it_is() {
    use fs4::FileExt;
    let class = temp("locked-class.csv");
    std::fs::write(&class, class_file()).unwrap();
    let out = temp("locked.csv");
    let whole = imlab(&["grade", QUICK, class.to_str().unwrap()]).stdout;
    let cut = whole[..whole.len() / 2].to_vec();
    std::fs::write(&out, &cut).unwrap();
    let args = [
        "grade",
        QUICK,
        class.to_str().unwrap(),
        "--resume",
        out.to_str().unwrap(),
    ];
    // This process stands for a grader still running on OUT.
    let held = std::fs::File::open(&out).unwrap();
    FileExt::lock(&held).unwrap();
    let refused = imlab(&args);
    assert_eq!(refused.status.code(), Some(2));
    assert_eq!(
        String::from_utf8_lossy(&refused.stderr),
        format!(
            "imlab: --resume '{}': another grading holds this file (it is locked by a running \
             `imlab grade --resume`); it is left as it is\n",
            out.display()
        )
    );
    assert!(std::fs::read(&out).unwrap() == cut);
    // Once the first grader ends, the file is free.
    drop(held);
    assert!(imlab(&args).status.success());
    assert!(std::fs::read(&out).unwrap() == whole);
    std::fs::remove_file(&out).unwrap();
    std::fs::remove_file(&class).unwrap();
}

#[test]
fn a_kept_row_edited_after_its_grading_is_caught_when_it_is_the_last() {
    let class = temp("edited-class.csv");
    std::fs::write(&class, class_file()).unwrap();
    let whole = imlab(&["grade", QUICK, class.to_str().unwrap()]).stdout;
    let text = String::from_utf8(whole).unwrap();
    let lines: Vec<&str> = text.split_inclusive('\n').collect();
    // Row 5 of the grades (line 6 of the class) is `ok`, with values and pass flags.
    let row = lines[5];
    assert!(row.starts_with("Student 4,6,"), "{row}");
    let out = temp("edited.csv");
    for (edit, edited) in [
        ("status", row.replacen(",ok,", ",run failed: x,", 1)),
        ("value", {
            let cells: Vec<&str> = row.trim_end().split(',').collect();
            let mut cells: Vec<String> = cells.iter().map(|c| c.to_string()).collect();
            let n = cells.len();
            cells[n - 3] = "0.001".to_string();
            format!("{}\n", cells.join(","))
        }),
        ("pass", {
            let flipped = if row.ends_with(",0\n") { "1" } else { "0" };
            format!("{}{flipped}\n", &row[..row.len() - 2])
        }),
        ("text after", format!("{},looks fine\n", row.trim_end())),
    ] {
        let previous = [lines[..5].concat(), edited].concat();
        std::fs::write(&out, &previous).unwrap();
        let refused = imlab(&[
            "grade",
            QUICK,
            class.to_str().unwrap(),
            "--resume",
            out.to_str().unwrap(),
        ]);
        let stderr = String::from_utf8_lossy(&refused.stderr);
        assert_eq!(refused.status.code(), Some(2), "{edit}: {stderr}");
        assert!(
            stderr.contains(
                "its row 5 (line 6 of the class file) is not what grading it again gives"
            ),
            "{edit}: {stderr}"
        );
        assert!(
            std::fs::read(&out).unwrap() == previous.as_bytes(),
            "{edit}"
        );
    }
    std::fs::remove_file(&out).unwrap();
    std::fs::remove_file(&class).unwrap();
}

#[test]
fn the_rows_graded_again_are_one_in_twenty_and_the_last_from_an_offset_the_bytes_choose() {
    let mut offsets = std::collections::BTreeSet::new();
    for n in [1, 2, 19, 20, 21, 40, 100, 101] {
        for k in 0..200 {
            let kept = format!("header\n{k}\n");
            let sample = resume_sample(kept.as_bytes(), n);
            assert_eq!(
                sample,
                resume_sample(kept.as_bytes(), n),
                "the same bytes, the same rows"
            );
            assert_eq!(sample.last(), Some(&(n - 1)));
            let (stride, last) = sample.split_at(sample.len() - 1);
            let offset = stride.first().map_or(last[0], |&f| f);
            assert!(offset < RESUME_STRIDE);
            assert!(stride
                .iter()
                .enumerate()
                .all(|(i, &r)| r == offset + RESUME_STRIDE * i));
            assert!(last[0] < offset + RESUME_STRIDE * (stride.len() + 1));
            if n >= RESUME_STRIDE {
                offsets.insert(offset);
            }
        }
    }
    assert_eq!(
        offsets.len(),
        RESUME_STRIDE,
        "every offset is chosen by some bytes"
    );
    assert!(resume_sample(b"header\n", 0).is_empty());
}

/// The cells of a CSV line written without quotes, with the `back`th from the end set to `cell`.
fn with_cell(line: &str, back: usize, cell: &str) -> String {
    let mut cells: Vec<&str> = line.trim_end().split(',').collect();
    let n = cells.len();
    cells[n - back] = cell;
    format!("{}\n", cells.join(","))
}

/// An edit of a row of grades, the `v`th of its kind; None where it does not apply.
type Edit = dyn Fn(&str, usize) -> Option<String>;

#[test]
fn each_edit_of_a_kept_row_graded_again_is_refused_naming_what_differs() {
    // A hundred rows, one in ten `ok`, the others `malformed` with pass 0.
    let mut file = "Name,Link\n".to_string();
    for i in 0..100u32 {
        let link = if i % 10 == 0 {
            quick_link(600 + 20 * i)
        } else {
            format!("c=1&garbage{i}")
        };
        file.push_str(&format!("Student {i},{link}\n"));
    }
    let class = temp("sampled-class.csv");
    std::fs::write(&class, &file).unwrap();
    let whole =
        String::from_utf8(imlab(&["grade", QUICK, class.to_str().unwrap()]).stdout).unwrap();
    let lines: Vec<&str> = whole.split_inclusive('\n').collect();
    assert_eq!(lines.len(), 101);
    // Cells from the end: 1 pass, 3 settling_time, 5 current_peak, 6 status.
    let edits: [(&str, &Edit); 4] = [
        ("its status is 'ok', not 'malformed: ", &|row, _| {
            row.contains(",malformed: ")
                .then(|| with_cell(row, 6, "ok"))
        }),
        ("its current_peak is '3.", &|row, v| {
            row.contains(",ok,")
                .then(|| with_cell(row, 5, &format!("3.{v}")))
        }),
        ("its pass is '1', not '0'", &|row, _| {
            row.ends_with(",0\n").then(|| with_cell(row, 1, "1"))
        }),
        ("it has 'checked ", &|row, v| {
            Some(format!("{},checked {v}\n", row.trim_end()))
        }),
    ];
    let out = temp("sampled.csv");
    for (what, edit) in edits {
        // The first edit of a row but the last that lands in the rows graded again.
        let (j, previous) = (1..99)
            .flat_map(|j| (0..40).map(move |v| (j, v)))
            .find_map(|(j, v)| {
                let mut edited: Vec<String> = lines.iter().map(|l| l.to_string()).collect();
                edited[j + 1] = edit(lines[j + 1], v)?;
                let previous = edited.concat();
                resume_sample(previous.as_bytes(), 100)
                    .contains(&j)
                    .then_some((j, previous))
            })
            .unwrap_or_else(|| panic!("no edit '{what}' lands in the rows graded again"));
        std::fs::write(&out, &previous).unwrap();
        let refused = imlab(&[
            "grade",
            QUICK,
            class.to_str().unwrap(),
            "--resume",
            out.to_str().unwrap(),
        ]);
        let stderr = String::from_utf8_lossy(&refused.stderr);
        assert_eq!(refused.status.code(), Some(2), "{what}: {stderr}");
        let message = format!(
            "its row {} (line {} of the class file) is not what grading it again gives: {what}",
            j + 1,
            j + 2
        );
        assert!(stderr.contains(&message), "{message}\n{stderr}");
        assert!(
            std::fs::read(&out).unwrap() == previous.as_bytes(),
            "{what}"
        );
    }
    std::fs::remove_file(&out).unwrap();
    std::fs::remove_file(&class).unwrap();
}
