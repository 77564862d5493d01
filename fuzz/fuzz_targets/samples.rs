//! Fuzz target of `raylemma check sampler --samples FILE`: a file of samples (first byte:
//! which target density) gives a verdict or a `DataError` with a line of the file, never a
//! panic.

#![no_main]

use libfuzzer_sys::fuzz_target;
use raylemma::check::Options;
use raylemma::check::external::{Sampler, Target};

#[path = "support.rs"]
mod support;

fuzz_target!(|data: &[u8]| {
    let Some((&which, rows)) = data.split_first() else {
        return;
    };
    let target = Target::ALL[usize::from(which) % Target::ALL.len()];
    let sampler = Sampler::Samples {
        path: support::as_file(rows, "csv"),
        target,
    };
    if let Err(e) = raylemma::check::external::sampler(&sampler, &Options::default()) {
        support::line_inside(e.line, rows, &e);
    }
});
