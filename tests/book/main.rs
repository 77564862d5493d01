//! The book's tests: one module per chapter, in the book's order, compiled into one test
//! binary (one link of the library instead of one per chapter).
//!
//! A chapter's tests run on their own with its module path as the filter, for example
//! `cargo test --test book sampling::disc` or `cargo test --test book geometry::sphere`.

mod coursework;

mod geometry {
    mod sphere;
}

mod checking {
    mod accuracy;
    mod external;
    mod statistics;
    mod warps;
}

mod sampling {
    mod cosine;
    mod disc;
    mod frame;
    mod importance;
    mod sphere;
    mod tabulated;
}

mod optics {
    mod dispersion;
    mod fresnel;
    mod reflect;
    mod specular;
    mod thinfilm;
}

mod transport {
    mod lambert;
    mod rectangle;
    mod roulette;
    mod shadow;
}

mod spectral {
    mod colour;
    mod display;
    mod emission;
    mod upsample;
    mod wavelength;
}

mod renderer {
    pub(crate) mod compare;
    mod export;
    mod render;
    mod scene;
    mod testing;
}

mod appendix {
    mod command_line;
}

/// The command line: subcommands end to end, their errors and exit statuses.
mod cli;

/// The one writer of every file (`tools/output/src/lib.rs`, the library's `raylemma::output`):
/// atomic files, sets, staged folders.
mod output;

/// What the tests share: the root, scratch folders (`support.rs`).
mod support;

/// Starts the watchdog that ends a run in which a test never returns, with the report card
/// printed (`report_card::watchdog`). Named to be the first test in libtest's order, which
/// is by name, so that it starts before any exercise's test can take every thread; it
/// returns at once, and a run filtered to some tests goes without it (libtest then names a
/// test that hangs after 60 s).
///
/// It also silences the panic of a stub, counting it (`report_card::silent_stubs`): in the
/// hand-out's first run most tests fail on a stub, and a message each would bury the card.
#[test]
fn a_watchdog_for_tests_that_never_return() {
    report_card::silent_stubs();
    report_card::watchdog();
}

/// The report card of the student edition: every exercise's checkers on this crate's
/// functions, printed at the end of the run (`cargo test --test book report_card`).
mod report_card;
