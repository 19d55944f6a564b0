//! The challenges' and the grading's messages: each one the core says is in the English file, and
//! each one there is said.
#![cfg(not(target_arch = "wasm32"))]

/// Every message the challenges' and the grading's code names is an English message of
/// web/locales/en/core-challenge.ftl, and every message there is named: none is said with an id
/// the page cannot find, and none is left for translators that nothing says.
#[test]
fn every_challenge_message_named_is_in_the_english_file_and_every_one_there_is_named() {
    let root = std::path::Path::new(env!("CARGO_MANIFEST_DIR"));
    let ftl = std::fs::read_to_string(root.join("../web/locales/en/core-challenge.ftl")).unwrap();
    let defined: std::collections::BTreeSet<&str> = ftl
        .lines()
        .filter_map(|l| l.split_once(" = ").map(|(id, _)| id))
        .filter(|id| !id.starts_with(['#', ' ']))
        .collect();
    fn sources(dir: &std::path::Path, out: &mut Vec<String>) {
        for entry in std::fs::read_dir(dir).unwrap() {
            let path = entry.unwrap().path();
            if path.is_dir() {
                sources(&path, out);
            } else if path.extension().is_some_and(|e| e == "rs") {
                out.push(std::fs::read_to_string(path).unwrap());
            }
        }
    }
    let mut texts = Vec::new();
    sources(&root.join("src/challenge"), &mut texts);
    for file in [
        "src/wasm/challenge.rs",
        "src/wasm/grade.rs",
        "src/bin/imlab/grade.rs",
    ] {
        texts.push(std::fs::read_to_string(root.join(file)).unwrap());
    }
    let mut named = std::collections::BTreeSet::new();
    for text in &texts {
        let starts = text
            .match_indices("\"challenge-")
            .chain(text.match_indices("\"grade-"));
        for (at, _) in starts {
            let rest = &text[at + 1..];
            let id = &rest[..rest.find('"').unwrap()];
            if id
                .chars()
                .all(|c| c.is_ascii_lowercase() || c.is_ascii_digit() || c == '-')
            {
                named.insert(id);
            }
        }
    }
    let missing: Vec<_> = named.difference(&defined).collect();
    assert!(
        missing.is_empty(),
        "named, not in core-challenge.ftl: {missing:?}"
    );
    let unused: Vec<_> = defined.difference(&named).collect();
    assert!(
        unused.is_empty(),
        "in core-challenge.ftl, never named: {unused:?}"
    );
}
