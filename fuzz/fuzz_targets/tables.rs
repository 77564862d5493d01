//! Fuzz target of the readers of published tables (first byte: which): spectra
//! (`spectral::spectrum::parse_csv`), Sellmeier glasses (`optics::dispersion::parse`) and
//! emission images (`spectral::emission::parse_image`). A table or a `DataError` with a
//! line of the input, never a panic.

#![no_main]

use libfuzzer_sys::fuzz_target;
use raylemma::optics::dispersion;
use raylemma::spectral::{emission, spectrum};

#[path = "support.rs"]
mod support;

fuzz_target!(|data: &[u8]| {
    let Some((&which, body)) = data.split_first() else {
        return;
    };
    let error = match which % 3 {
        0 => std::str::from_utf8(body)
            .ok()
            .and_then(|t| spectrum::parse_csv(t, "fuzz.csv").err()),
        1 => std::str::from_utf8(body)
            .ok()
            .and_then(|t| dispersion::parse(t, "fuzz.csv").err()),
        _ => emission::parse_image(body, "fuzz.png").err(),
    };
    if let Some(e) = error
        && which % 3 != 2
    {
        support::line_inside(e.line, body, &e);
    }
});
