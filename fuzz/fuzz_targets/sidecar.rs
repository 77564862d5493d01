//! Fuzz target of the reader of a render's JSON sidecar (`raylemma::render::Sidecar::read`,
//! read by `compare` and `references`): a sidecar or a `FileError`, never a panic.

#![no_main]

use libfuzzer_sys::fuzz_target;
use raylemma::render::Sidecar;

#[path = "support.rs"]
mod support;

fuzz_target!(|data: &[u8]| {
    let _ = Sidecar::read(&support::as_file(data, "json"));
});
