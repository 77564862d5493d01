//! Checks from any language: the book's checkers run on an implementation outside Rust, a
//! program that answers questions over a pipe or a file of values. Chapter: *Checks from
//! any language* (`chapters/checking/external.md`); the command line is `raylemma check`.
//!
//! The checkers are not rewritten for this: an external implementation is made into just
//! another implementation of each (a [`Warp`](crate::check::warp::Warp) whose methods,
//! and closures whose calls, look up the program's answers), and the verdict is the
//! checker's own [`Verdict`](crate::check::Verdict), printed as for a Rust user.
//!
//! # The protocol
//!
//! The checker runs the program with `sh -c COMMAND` (so the command may hold arguments
//! and quotes), in the current folder (or the program's `dir`), with its error output passed through. It runs it a
//! few times; each time it writes questions to the program's standard input, one a line,
//! and closes it. The program writes one answer line per question, in order, and exits
//! with status 0. It may answer as it reads or read everything first, and need not flush
//! before it exits. Each run must end within the program's timeout ([`TIMEOUT`] unless
//! set).
//!
//! A question is a verb and numbers, separated by single spaces; every number is written
//! so that it reads back exactly (`0.1`, `1.0`, `-0.0`, `1e-300`). An answer is numbers
//! separated by spaces, tabs or commas; they must be finite (`nan` and `inf` are bad
//! input), and should be printed with every digit (Python's `print`, C's `%.17g`): the
//! Jacobian claim differentiates the answers with a step of `1e-6`.
//!
//! | question | answer | for |
//! |---|---|---|
//! | `warp u1 u2` | `x y z` (`x y` on the disc and the square) | a sampler: the point for `u` in `[0, 1)^2` |
//! | `pdf x y z` | `p` | a sampler that states its own density |
//! | `invert x y z` | `u1 u2` | a sampler with an inverse (the round trip) |
//! | `fresnel cos_i n1 n2` | `R` | an unpolarised dielectric reflectance |
//! | `refract wi_x wi_y wi_z n_x n_y n_z n1 n2` | `t_x t_y t_z`, or `tir` | a refraction |
//!
//! One run may mix verbs. Questions come in rounds (`memo.rs`): the checker runs on the
//! answers it has, and a run of the program answers every question that run could not;
//! the verdict comes from a run of the checker that found an answer to every question.
//!
//! Tables: a file of samples (one `x,y,z` a row, drawn however the sampler likes; the
//! chi-squared claim only), or a table of a function's answers (each row a question's
//! numbers followed by its answer: `cos_i,n1,n2,R`), whose questions
//! [`fresnel_questions`] and [`refraction_questions`] list. CSV rows, with an optional
//! header, blank lines and `#` comments.
//!
//! Every bad input is a [`DataError`](crate::data::DataError): the file or program, the
//! line and what is wrong. A program run whole rather than asked questions (a renderer
//! run by `raylemma conformance`, [`run_logged`]) fails with a [`ProgramError`].
//!
//! `raylemma check` parses its flags and calls one of [`check_sampler`], [`check_fresnel`],
//! [`check_refraction`] and [`check_corpora`] (`command.rs`), which print the verdict.

mod command;
mod memo;
mod optics;
mod run;
mod sampler;
pub(crate) mod text;

use std::path::PathBuf;
use std::time::Duration;

pub use command::{
    CheckError, Checked, FunctionCheck, SamplerCheck, check_corpora, check_fresnel,
    check_refraction, check_sampler,
};
pub use optics::{Function, fresnel, fresnel_questions, refraction, refraction_questions};
pub use run::{ProgramError, ended, run_logged};
pub use sampler::{Density, Sampler, Target, domain_named, sampler};

/// How long one run of a program may take by default: generous, since a run may answer
/// a million questions in an interpreted language.
pub const TIMEOUT: Duration = Duration::from_secs(120);

/// The samples `raylemma check sampler` draws from a program unless told: the book's
/// sampler tests' number ([`crate::check::warp::TEST_SAMPLES`]; fewer than the warp
/// checker's default, since every sample crosses a pipe).
pub const SAMPLES: usize = crate::check::warp::TEST_SAMPLES;

/// A program that answers the protocol's questions: a command run by `sh -c`.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Program {
    /// The command, e.g. `python3 my_sampler.py`.
    pub command: String,
    /// How long one run may take.
    pub timeout: Duration,
    /// The folder it runs in (`None`: the current one).
    pub dir: Option<PathBuf>,
}

impl Program {
    /// The command `command`, with the default [`TIMEOUT`].
    pub fn new(command: impl Into<String>) -> Self {
        Self {
            command: command.into(),
            timeout: TIMEOUT,
            dir: None,
        }
    }

    /// The same program with another timeout per run.
    pub fn timeout(self, timeout: Duration) -> Self {
        Self { timeout, ..self }
    }

    /// The same program, run in the folder `dir`.
    pub fn in_dir(self, dir: impl Into<PathBuf>) -> Self {
        Self {
            dir: Some(dir.into()),
            ..self
        }
    }
}
