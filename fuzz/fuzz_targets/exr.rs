//! Fuzz target of the EXR reader that `raylemma compare` uses
//! (`raylemma::image::ExrContents::read`): any bytes give the image or a
//! `FileError`, never a panic, and no allocation the file's own size does not justify
//! (`tools/fuzz/run` runs it with `-malloc_limit_mb` and `-rss_limit_mb`). The seeds are
//! the crafted headers of `tests/data/exr/` and a small render.

#![no_main]

use libfuzzer_sys::fuzz_target;
use raylemma::image::ExrContents;

#[path = "support.rs"]
mod support;

fuzz_target!(|data: &[u8]| {
    let path = support::as_file(data, "exr");
    if let Ok(image) = ExrContents::read(&path) {
        let pixels = image.width as usize * image.height as usize;
        assert_eq!(image.mean.len(), pixels);
        assert!(image.var.as_ref().is_none_or(|v| v.len() == pixels));
    }
});
