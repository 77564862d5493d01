//! Fuzz target of the scene parser (`raylemma::render::parse`): any bytes must give
//! a scene or a `DataError` with a line inside the text, never a panic.
//!
//! `tools/fuzz/run 60 scene` (chapter *Bad input*; the seeds are the canonical scenes).

#![no_main]

use std::path::Path;

use libfuzzer_sys::fuzz_target;

fuzz_target!(|data: &[u8]| {
    let Ok(text) = std::str::from_utf8(data) else {
        return;
    };
    let scenes = Path::new(env!("CARGO_MANIFEST_DIR")).join("../scenes");
    if let Err(e) = raylemma::render::parse(text, "fuzz.toml", &scenes) {
        let lines = text.lines().count().max(1) + 1;
        assert!(
            e.file != "fuzz.toml" || e.line <= lines,
            "line {} of {lines}: {e}",
            e.line
        );
    }
});
