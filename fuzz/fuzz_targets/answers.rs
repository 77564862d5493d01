//! Fuzz target of the reading of a program's answers (`raylemma check corpus --program`,
//! the same reader as every `check --program`): the program is `cat` of the input, asked
//! the Fresnel corpus's questions, so the bytes are its standard output. A verdict or a
//! `DataError` naming the output's line, never a panic, and memory bounded however long
//! the output (the reader stops at 1024 bytes a line and one line past the answers).

#![no_main]

use std::path::Path;
use std::sync::LazyLock;

use libfuzzer_sys::fuzz_target;
use raylemma::check::accuracy::{self, Corpus, corpus};
use raylemma::check::external::Program;

#[path = "support.rs"]
mod support;

static FRESNEL: LazyLock<Corpus> = LazyLock::new(|| {
    let file = Path::new(env!("CARGO_MANIFEST_DIR")).join("../data/corpus/fresnel.txt");
    corpus::load(&file).expect("the Fresnel corpus reads")
});

fuzz_target!(
    init: {
        // A Rust program's runtime ignores SIGPIPE before main; libFuzzer's main does not,
        // and the question writer's pipe breaks whenever `cat` exits without reading it.
        // SAFETY: setting a signal's disposition to SIG_IGN, before any thread is started.
        unsafe {
            libc::signal(libc::SIGPIPE, libc::SIG_IGN);
        }
    },
    |data: &[u8]| {
    let path = support::as_file(data, "txt");
    let program = Program::new(format!("cat '{}'", path.display()));
    let verbs = ["fresnel".to_string()];
    if let Err(e) = accuracy::check_program(&FRESNEL, &verbs, &program) {
        support::line_inside(e.line, data, &e);
    }
    }
);
