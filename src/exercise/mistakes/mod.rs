//! The typical mistakes of every exercise, each a planted twin the card must reject, and
//! correct answers written differently, each of which it must pass. Chapter: *Coursework*
//! (`chapters/coursework.md`, section *What the card catches*).
//!
//! Each exercise has one [`Table`]: the crate's own function on fixed probe inputs
//! ([`Table::probe`]), its typical [`Mistake`]s (the ones its chapter warns about, the
//! errata's, a wrong constant, a wrong power, a swapped argument, a missing factor, a wrong
//! branch), and its correct [`Alternative`]s. A mistake's `check` runs the exercise's own
//! checks (the ones [`super::registry`] runs on the crate's function) on the twin; its
//! `probe` is the twin's outputs on the same probe inputs. When a failing answer's outputs
//! match a mistake's on every probe input, the card names that mistake ([`recognise`]).
//!
//! The tables live in one file per part of the book: [`sampling`] (the sampling and
//! geometry chapters and *Reflection and refraction*), [`optics`], [`transport`],
//! [`spectral`].

use crate::check::Verdict;

pub mod optics;
pub mod sampling;
pub mod spectral;
pub mod transport;

/// Where a typical mistake comes from.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Source {
    /// A mistake the exercise's chapter warns about.
    Chapter,
    /// One of the errata (the seeds' mistakes, `chapters/appendix/errata.md`).
    Errata,
    /// A wrong constant (`pi` for `2 pi`, `12.92` for `1.055`).
    Constant,
    /// A wrong power or root.
    Power,
    /// Arguments swapped (`n1` and `n2`, `u1` and `u2`).
    Swapped,
    /// A factor left out.
    Factor,
    /// A wrong branch (the wrong side of a threshold, a case left out).
    Branch,
}

impl Source {
    /// The word the chapter's table prints.
    pub fn word(self) -> &'static str {
        match self {
            Source::Chapter => "the chapter's warning",
            Source::Errata => "errata",
            Source::Constant => "wrong constant",
            Source::Power => "wrong power",
            Source::Swapped => "swapped arguments",
            Source::Factor => "missing factor",
            Source::Branch => "wrong branch",
        }
    }
}

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
    /// The twin's outputs on the exercise's probe inputs.
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
    /// The crate's own function (the student's, in a hand-out) on the probe inputs.
    pub probe: fn() -> Vec<f64>,
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

/// The table of the exercise `name`.
pub fn table(name: &str) -> Option<&'static Table> {
    tables().find(|t| t.exercise == name)
}

/// Whether two probes give the same outputs: equal lengths, and each pair equal to a
/// relative `1e-9` (an absolute `1e-12` near zero), or both NaN. A correct answer written
/// in another order of operations differs from the crate's in the last bits; a mistake
/// differs from it by far more on some probe input (the tests hold every mistake's probe
/// apart from the crate's).
pub fn same_outputs(a: &[f64], b: &[f64]) -> bool {
    a.len() == b.len()
        && a.iter().zip(b).all(|(&x, &y)| {
            (x.is_nan() && y.is_nan())
                || x == y
                || (x - y).abs() <= 1e-12_f64.max(1e-9 * x.abs().max(y.abs()))
        })
}

/// The mistake of the exercise `name` whose outputs match `outputs` (the crate's own
/// function on the probe inputs), if one does.
pub fn matching(name: &str, outputs: &[f64]) -> Option<&'static Mistake> {
    table(name)?
        .mistakes
        .iter()
        .find(|m| same_outputs(&(m.probe)(), outputs))
}

/// The mistake the crate's own function of exercise `name` behaves like, if any: its probe
/// run (a panic there means no match) and compared with each mistake's.
pub fn recognise(name: &str) -> Option<&'static Mistake> {
    let table = table(name)?;
    let outputs = std::panic::catch_unwind(table.probe).ok()?;
    matching(name, &outputs)
}
