//! Grading a class: the class file read in every encoding, line end and shape, the grades' cells
//! safe for a spreadsheet and a terminal, and the fingerprint of a challenge (resuming is in
//! resume.rs).

// Runs native processes; the crate's tests also build for wasm32.
#![cfg(not(target_arch = "wasm32"))]

mod common;

use common::{imlab, quick_link, temp, QUICK};
use imlab::challenge::grade::{
    csv_header, csv_row, grade_row, read_class, Class, ClassRow, Graded,
};
use imlab::challenge::{builtin, Challenge, CriterionVerdict, Verdict, BUILTINS};
use imlab::text::csv::text_field;
use imlab::text::Message;

/// The status a row is graded as it is read, in English, if it has one.
fn status(row: &ClassRow) -> Option<String> {
    row.fault.as_ref().map(|f| f.status().to_string())
}

/// The (line, link, status) of each row.
fn rows(class: &Class) -> Vec<(usize, String, Option<String>)> {
    class
        .rows
        .iter()
        .map(|r| (r.line, r.link.clone(), status(r)))
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
            read_class(&bytes).unwrap_err().to_string(),
            "the file is UTF-16 without a byte-order mark; save it as UTF-8"
        );
    }
    let zip = b"PK\x03\x04\x14\x00\x06\x00\x08\x00\x00\x00!\x00\xb1\x82\xa5\xc3xlsx";
    let message = read_class(zip).unwrap_err().to_string();
    assert!(message.starts_with("the file is not text"), "{message}");
}

#[test]
fn an_invalid_utf8_byte_spoils_only_its_own_line() {
    // The byte-order mark says UTF-8; without it, a line of UTF-8 beyond ASCII says so too (a
    // file with no such line would be read in the legacy encoding its bytes point to).
    let class = read_class(b"\xef\xbb\xbfc=1&a\nc=1&\xff&b\nc=1&c\n").unwrap();
    let unmarked = read_class("c=1&a\nc=1&\u{fc}&b\nc=1&c\n".as_bytes()).unwrap();
    let mut bytes = b"c=1&a\nc=1&\xff&b\nc=1&c\n".to_vec();
    bytes.splice(6..6, "# Jos\u{e9} M\u{fc}ller\n".bytes());
    let spoilt = read_class(&bytes).unwrap();
    assert_eq!(unmarked.encoding, None);
    assert_eq!(spoilt.encoding, None);
    assert_eq!(
        status(&spoilt.rows[1]).as_deref(),
        Some("malformed: line 3 is not valid UTF-8")
    );
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
        status(&class.rows[0]),
        Some("malformed: line 1 is not valid UTF-16".to_string())
    );
    assert_eq!(class.rows[1].fault, None);
    // The row is graded with its status, without a run.
    let c = Challenge::parse(QUICK).unwrap();
    let graded = grade_row(&c, &read_class(b"\xef\xbb\xbf\xfe").unwrap().rows[0]);
    assert_eq!(
        graded.status.to_string(),
        "malformed: line 1 is not valid UTF-8"
    );
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
    let carried: Vec<(usize, &str, Vec<&str>, Option<String>)> = class
        .rows
        .iter()
        .map(|r| {
            (
                r.line,
                r.link.as_str(),
                r.carried.iter().map(String::as_str).collect(),
                status(r),
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
                Some("malformed: no link".to_string())
            ),
            (
                7,
                "c=1&d",
                vec!["Dan", "dan@example.org", ""],
                Some("malformed: line 7 has 3 fields, the header 4".to_string())
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
        read_class(b"Name,First,Second\nAda,c=1&a,challenge=step-tune\n")
            .unwrap_err()
            .to_string(),
        "the columns 'First', 'Second' all hold links; head the one to grade 'link'"
    );
    assert_eq!(
        read_class(b"Name,Mark\nAda,12\n").unwrap_err().to_string(),
        "no column of links in this CSV export (its columns: 'Name', 'Mark'); head the column \
         of links 'link'"
    );
    assert_eq!(
        read_class(b"link,URL\nc=1&a,c=1&b\n")
            .unwrap_err()
            .to_string(),
        "the columns 'link', 'URL' are all headed as links; keep one"
    );
    // A link written unquoted takes the fields its commas split off.
    let b = builtin("step-tune").unwrap();
    assert!(b.text.contains(','));
    let class = read_class(format!("Name,Link,Mark\nAda,{},12\n", b.text).as_bytes()).unwrap();
    assert_eq!(class.rows[0].link, b.text);
    assert_eq!(class.rows[0].carried, ["Ada", "12"]);
    assert_eq!(class.rows[0].fault, None);
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
        fault: None,
    };
    let graded = grade_row(&c, &row);
    assert_eq!(graded.status.to_string(), "ok");
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
            label: Message::new("figure-current_peak"),
            bound: Message::new("challenge-bound-band"),
            value: Some(-0.5),
            unit: "A".into(),
            run: "nominal".into(),
            pass: true,
            reason: None,
            settled: true,
        }],
        pass: true,
    };
    let one = Challenge::parse("c=1&base=step&need.current_peak=max:4").unwrap();
    let graded = Graded {
        verdict: Some(verdict),
        ..Graded::failed(7, "c=1", Message::new("grade-row-ok"))
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
    let brief = sly.brief().to_string();
    let plain = plain.brief().to_string();
    assert_eq!(brief.lines().count(), plain.lines().count());
    assert_eq!(
        brief.lines().next().unwrap(),
        "a\\n\\nYou may change only:\\r\\nk1\\u{2028}\\u{1b}[2J\\u{202e}"
    );
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
