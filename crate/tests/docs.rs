//! The command lines of the guides are test cases: every ```console block of docs/*.md and of the
//! README runs the `imlab` binary of this build and must print what the block shows, so the CLI
//! reference and the figures quoted with their commands cannot drift from the code.
//!
//! `TRYCMD=overwrite cargo test --release --test docs` rewrites the blocks from the binary's output
//! (read the diff before committing it: a changed figure is a changed claim).

// trycmd runs native processes; the crate's tests also build for wasm32.
#![cfg(not(target_arch = "wasm32"))]

#[test]
fn docs_console_examples() {
    trycmd::TestCases::new()
        .register_bin("imlab", trycmd::cargo::cargo_bin!("imlab"))
        .case("../README.md")
        .case("../docs/*.md");
}
