//! Fuzz target of the reader of accuracy corpora (`raylemma::check::accuracy::corpus::parse`,
//! `raylemma check corpus FILE`): a corpus or a `DataError` with a line of the text, never a
//! panic.

#![no_main]

use libfuzzer_sys::fuzz_target;
use raylemma::check::accuracy::corpus;

#[path = "support.rs"]
mod support;

fuzz_target!(|data: &[u8]| {
    let Ok(text) = std::str::from_utf8(data) else {
        return;
    };
    if let Err(e) = corpus::parse(text, "fuzz.txt") {
        support::line_inside(e.line, data, &e);
    }
});
