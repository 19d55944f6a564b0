//! `imlab grade --resume`: a cut-off output resumed to the bytes of an uninterrupted run, rows
//! written as they are graded, a class file in a legacy encoding, the lock on the output, and the
//! kept rows graded again.

// Runs native processes; the crate's tests also build for wasm32.
#![cfg(not(target_arch = "wasm32"))]

mod common;

use common::{imlab, quick_link, temp, QUICK};
use imlab::challenge::grade::{
    check_kept, grade_row, read_class, resume, resume_sample, RESUME_STRIDE,
};
use imlab::challenge::Challenge;
use std::io::{BufRead, BufReader};
use std::process::{Command, Stdio};

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
            "it holds more rows than the class file has submissions (12)",
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
    let point = resume(&c, &read, &whole, 7).unwrap();
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
fn the_rows_graded_again_are_one_in_twenty_and_the_last_from_an_offset_the_seed_draws() {
    let mut offsets = std::collections::BTreeSet::new();
    for n in [1, 2, 19, 20, 21, 40, 100, 101] {
        for seed in 0..200 {
            let sample = resume_sample(seed, n);
            assert_eq!(
                sample,
                resume_sample(seed, n),
                "the same seed, the same rows"
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
        "every offset is drawn by some seed"
    );
    assert!(resume_sample(1, 0).is_empty());
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
    let c = Challenge::parse(QUICK).unwrap();
    let read = read_class(file.as_bytes()).unwrap();
    for (what, edit) in edits {
        // The first edit of a row but the last, and a seed that draws it among the rows graded
        // again.
        let (j, previous, seed) = (1..99)
            .flat_map(|j| (0..40).map(move |v| (j, v)))
            .find_map(|(j, v)| {
                let mut edited: Vec<String> = lines.iter().map(|l| l.to_string()).collect();
                edited[j + 1] = edit(lines[j + 1], v)?;
                let seed = (0..100).find(|&seed| resume_sample(seed, 100).contains(&j))?;
                Some((j, edited.concat(), seed))
            })
            .unwrap_or_else(|| panic!("no edit '{what}' applies"));
        let point = resume(&c, &read, previous.as_bytes(), seed).unwrap();
        let kept = point.sample.iter().find(|k| k.index == j).unwrap();
        let graded = grade_row(&c, &read.rows[j]);
        let refused = check_kept(&c, &read, kept, &graded)
            .unwrap_err()
            .to_string();
        let message = format!(
            "its row {} (line {} of the class file) is not what grading it again gives: {what}",
            j + 1,
            j + 2
        );
        assert!(refused.contains(&message), "{message}\n{refused}");
    }
    std::fs::remove_file(&class).unwrap();
}
