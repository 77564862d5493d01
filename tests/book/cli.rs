//! Tests of the `raylemma` command line and of the figure job's all-or-nothing writing.
//! (Chapter: *Introduction*; the program itself is described in README.md.)

use std::fs;
use std::process::Command;

use raylemma::figures::{Output, Settings, write_outputs};

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

#[test]
fn unknown_figure_name_is_reported_with_the_list() {
    let out = raylemma(&["figures", "--only", "no_such_figure"]);
    assert_eq!(out.status.code(), Some(1));
    let err = String::from_utf8_lossy(&out.stderr);
    assert!(
        err.contains("no_such_figure") && err.contains("sphere_far_error.png"),
        "{err}"
    );
}

fn good(_: &Settings) -> Result<Vec<u8>, raylemma::plot::BoxError> {
    Ok(b"new".to_vec())
}

fn bad(_: &Settings) -> Result<Vec<u8>, raylemma::plot::BoxError> {
    Err("planted failure".into())
}

#[test]
fn a_failed_figure_leaves_the_previous_figures_intact() {
    let dir = std::env::temp_dir().join(format!("raylemma-figures-test-{}", std::process::id()));
    let _ = fs::remove_dir_all(&dir);
    fs::create_dir_all(&dir).unwrap();
    fs::write(dir.join("a.md"), "old").unwrap();
    let outputs = [
        Output {
            file: "a.md",
            what: "good",
            make: good,
        },
        Output {
            file: "b.md",
            what: "bad",
            make: bad,
        },
    ];
    let err = write_outputs(&dir, &outputs, &Settings::default())
        .unwrap_err()
        .to_string();
    assert!(
        err.contains("b.md") && err.contains("planted failure"),
        "{err}"
    );
    assert_eq!(fs::read_to_string(dir.join("a.md")).unwrap(), "old");
    assert!(!dir.join("b.md").exists());
    // And when every output succeeds, all are written.
    let ok = [Output {
        file: "a.md",
        what: "good",
        make: good,
    }];
    write_outputs(&dir, &ok, &Settings::default()).unwrap();
    assert_eq!(fs::read_to_string(dir.join("a.md")).unwrap(), "new");
    let leftovers: Vec<_> = fs::read_dir(dir.parent().unwrap())
        .unwrap()
        .filter_map(Result::ok)
        .filter(|e| {
            e.file_name()
                .to_string_lossy()
                .starts_with(&format!("raylemma-figures-test-{}.tmp", std::process::id()))
        })
        .collect();
    assert!(leftovers.is_empty(), "staging directory left behind");
    fs::remove_dir_all(&dir).unwrap();
}
