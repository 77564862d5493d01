//! The typical mistakes of every exercise, and how the card names one. Chapter:
//! *Coursework* (`chapters/coursework.md`, section *What the card catches*).
//!
//! Every exercise has a probe ([`probes::of`]): its function run on fixed inputs, the
//! outputs flattened. Its typical mistakes (the ones its chapter warns about, the errata's,
//! a wrong constant, a wrong power, a swapped argument, a missing factor, a wrong branch)
//! are planted twins in [`twins`], each of which the exercise's own checks must reject,
//! beside correct alternatives written differently, each of which they must pass. The
//! hand-out leaves [`twins`] out (the `twins` feature is off there): a twin is an answer
//! with one thing changed, an alternative an answer. What it keeps is [`known`]: each
//! mistake's words and the [`fingerprint`] of its probe, written from the twins by the
//! chapter's tests. When a failing answer's fingerprint is a mistake's, the card names
//! that mistake ([`recognise`]).

pub mod known;
pub mod probes;
#[cfg(feature = "twins")]
pub mod twins;

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
    /// The words the chapter's table prints.
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

/// A typical mistake as the hand-out knows it: no code, only what the card prints and the
/// fingerprint of the twin's probe.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Known {
    /// The exercise.
    pub exercise: &'static str,
    /// What the mistake does, in the words the card prints after "this behaves like"
    /// (`r = u1: the radius without its square root`).
    pub words: &'static str,
    /// [`fingerprint`] of the twin's probe.
    pub fingerprint: u64,
}

/// A probe's outputs reduced to one number that a correct answer written in another order
/// of operations shares with the crate's own (each output rounded to eight significant
/// digits, those below `1e-8` in size to 0, NaNs and infinities kept apart), hashed with
/// FNV-1a. Two probes that differ by more than the rounding get different fingerprints,
/// but for a collision of the hash (about one in 2^64).
pub fn fingerprint(outputs: &[f64]) -> u64 {
    let mut text = String::with_capacity(outputs.len() * 16);
    for &x in outputs {
        let rounded = if x.is_nan() {
            "nan".to_string()
        } else if x.is_infinite() {
            format!("{x}")
        } else if x.abs() < 1e-8 {
            "0".to_string()
        } else {
            format!("{x:.7e}")
        };
        text.push_str(&rounded);
        text.push(' ');
    }
    crate::output::fnv1a(text.as_bytes())
}

/// The known mistake of exercise `name` whose fingerprint is `print`, if one is.
pub fn matching(name: &str, print: u64) -> Option<&'static Known> {
    known::KNOWN
        .iter()
        .find(|k| k.exercise == name && k.fingerprint == print)
}

/// The mistake the crate's own function of exercise `name` behaves like, if any: its probe
/// run (a panic there means no match), fingerprinted and looked up in [`known::KNOWN`].
pub fn recognise(name: &str) -> Option<&'static Known> {
    let probe = probes::of(name)?;
    let outputs = std::panic::catch_unwind(probe).ok()?;
    matching(name, fingerprint(&outputs))
}
