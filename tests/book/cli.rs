//! Tests of the `raylemma` command line. (Chapter: *Introduction*; the program itself is
//! described in README.md.) The figure job's own tests (all-or-nothing writing, unknown
//! figure names) are in its crate, `tools/figures/`.

use std::process::Command;

fn raylemma(args: &[&str]) -> std::process::Output {
    Command::new(env!("CARGO_BIN_EXE_raylemma"))
        .args(args)
        .output()
        .expect("the binary runs")
}

#[test]
fn help_lists_the_subcommands() {
    let out = raylemma(&["--help"]);
    assert!(out.status.success());
    let text = String::from_utf8_lossy(&out.stdout);
    for word in ["figures", "book", "--quick"] {
        assert!(
            text.contains(word),
            "--help does not mention {word}:\n{text}"
        );
    }
}

#[test]
fn unknown_subcommand_is_a_usage_error_not_a_panic() {
    let out = raylemma(&["frobnicate"]);
    assert_eq!(out.status.code(), Some(2));
    let err = String::from_utf8_lossy(&out.stderr);
    assert!(
        err.contains("unrecognized subcommand") && err.contains("Usage"),
        "{err}"
    );
    assert!(!err.contains("panicked"), "{err}");
}

#[test]
fn unknown_flag_is_a_usage_error() {
    let out = raylemma(&["figures", "--colour"]);
    assert_eq!(out.status.code(), Some(2));
    let err = String::from_utf8_lossy(&out.stderr);
    assert!(err.contains("--colour") && err.contains("Usage"), "{err}");
}
