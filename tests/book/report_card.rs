//! The report card (chapter *Coursework*, `src/exercise/card.rs`): every exercise's
//! checkers on this crate's own functions. In the student edition this is what says
//! which exercises are not started, waiting, failing or passing.
//!
//! The card is printed at the very end of the test binary's output, after libtest's
//! summary (from a C `atexit` handler, which runs when libtest exits), so that it is the
//! last thing `cargo test` shows; the test itself fails, with the total, unless every
//! exercise passes. `cargo test --test book report_card` runs it alone.

use std::io::Write as _;
use std::path::Path;
use std::sync::OnceLock;

use raylemma::exercise::{card, edition};

static CARD: OnceLock<String> = OnceLock::new();

unsafe extern "C" {
    /// The C library's `atexit`: `callback` runs when the process exits normally.
    fn atexit(callback: extern "C" fn()) -> std::ffi::c_int;
}

/// Prints the card (called once, at exit; never unwinds).
extern "C" fn print_card() {
    if let Some(text) = CARD.get() {
        let mut out = std::io::stdout();
        let _ = writeln!(out, "\n{text}");
        let _ = out.flush();
    }
}

#[test]
fn report_card() {
    let root = Path::new(env!("CARGO_MANIFEST_DIR"));
    let markers = edition::markers_under(root).unwrap_or_else(|e| panic!("{e}"));
    let card = card::run(&markers);
    if CARD.set(card.to_string()).is_ok() {
        // SAFETY: `atexit` is the C library's own; `print_card` takes no argument, returns
        // nothing and cannot unwind (it ignores every error).
        unsafe {
            atexit(print_card);
        }
    }
    assert!(
        card.passed(),
        "report card: {}; the card is printed at the end of this run",
        card.total()
    );
}
