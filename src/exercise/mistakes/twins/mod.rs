//! The typical mistakes of every exercise as planted twins, and correct alternatives
//! (see [`super`]); one file per part of the book: [`sampling`] (the sampling and geometry
//! chapters), [`optics`] (with *Reflection and refraction*), [`transport`], [`spectral`].
//! Not in the hand-out (the `twins` feature).
//!
//! A mistake's `check` runs the exercise's own checks (the ones [`crate::exercise::registry`]
//! runs on the crate's function) on the twin; its `probe` runs the exercise's probe
//! ([`super::probes`]) on it. [`known_rs`] writes what the hand-out keeps of them,
//! `src/exercise/mistakes/known.rs`.

use std::fmt::Write;

use super::{Source, fingerprint};
use crate::check::Verdict;

pub mod optics;
pub mod sampling;
pub mod spectral;
pub mod transport;

/// A typical mistake in one exercise: its planted twin.
#[derive(Clone, Copy)]
pub struct Mistake {
    /// What the twin does, in the words the card prints after "this behaves like"
    /// (`r = u1: the radius without its square root`).
    pub words: &'static str,
    /// Where the mistake comes from.
    pub source: Source,
    /// The exercise's checks run on the twin: the card must reject it.
    pub check: fn() -> Vec<Verdict>,
    /// The exercise's probe run on the twin.
    pub probe: fn() -> Vec<f64>,
}

/// A correct answer written differently from the crate's (another order of operations,
/// another branch structure, an explicit `if`): the card must pass it.
#[derive(Clone, Copy)]
pub struct Alternative {
    /// How it differs, in words.
    pub words: &'static str,
    /// The exercise's checks run on it.
    pub check: fn() -> Vec<Verdict>,
}

/// One exercise's mistakes and alternatives.
#[derive(Clone, Copy)]
pub struct Table {
    /// The exercise's name (its marker's).
    pub exercise: &'static str,
    /// Its typical mistakes.
    pub mistakes: &'static [Mistake],
    /// Its correct alternatives.
    pub alternatives: &'static [Alternative],
}

/// Every exercise's table, in the book's order.
pub fn tables() -> impl Iterator<Item = &'static Table> {
    sampling::TABLES
        .iter()
        .chain(optics::TABLES)
        .chain(transport::TABLES)
        .chain(spectral::TABLES)
}

/// The text of `src/exercise/mistakes/known.rs`: every mistake's exercise, words and
/// fingerprint, in the tables' order.
pub fn known_rs() -> String {
    let mut out = String::from(
        "//! What the hand-out knows of each typical mistake (see [`super`]): its words and the\n\
         //! fingerprint of its twin's probe. Written by the chapter's tests from the twins\n\
         //! (`RAYLEMMA_WRITE_KNOWN=1 cargo test --test book coursework::mistakes`); do not edit.\n\n\
         use super::Known;\n\n\
         /// Every typical mistake, in the book's order.\n\
         pub const KNOWN: &[Known] = &[\n",
    );
    for t in tables() {
        for m in t.mistakes {
            let _ = write!(
                out,
                "    Known {{\n        exercise: {:?},\n        words: {:?},\n        fingerprint: 0x{:016x},\n    }},\n",
                t.exercise,
                m.words,
                fingerprint(&(m.probe)())
            );
        }
    }
    out.push_str("];\n");
    out
}
