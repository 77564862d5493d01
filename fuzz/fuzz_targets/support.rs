//! What the fuzz targets share: the input as a file (the readers under test take paths,
//! as the command line gives them) and the check that an error's line is inside the input.

#![allow(dead_code, reason = "each target uses what it needs of this file")]

use std::path::PathBuf;

/// Writes `data` to a file of this process's own in the temporary directory and returns its
/// path (the same path for every input of a run: each overwrites the last).
pub fn as_file(data: &[u8], extension: &str) -> PathBuf {
    let path =
        std::env::temp_dir().join(format!("raylemma-fuzz-{}.{extension}", std::process::id()));
    std::fs::write(&path, data).expect("the temporary directory is writable");
    path
}

/// An error's line is 0 (the whole file) or a line of the input (or the one after its
/// last, where a reader reports what is missing at the end).
pub fn line_inside(line: usize, data: &[u8], what: &dyn std::fmt::Display) {
    let lines = data.split(|&b| b == b'\n').count() + 1;
    assert!(
        line <= lines,
        "line {line} of an input of {lines} lines: {what}"
    );
}
