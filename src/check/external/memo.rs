//! Answers remembered, and asked for in rounds: how an implementation outside Rust becomes
//! just another implementation of a checker. Chapter: *Checks from any language*.
//!
//! A checker calls the function it checks one case at a time, and some cases depend on
//! earlier answers (the refraction checker sends the transmitted ray back; the warp
//! checker refines a cell where the pdf jumps). A program behind a pipe must instead be
//! asked many questions at once. So the checker is run on a [`Memo`]: a question it has
//! an answer to gets that answer; a new question is written down and gets a *stand-in*
//! (a valid answer of the right kind) so that the run goes on and finds the questions
//! after it. At the end of the run the program answers every question written down, in
//! one run of its own ([`rounds`]), and the checker runs again. A run that asks nothing
//! new used no stand-in: it is the checker run on the program's answers alone, and its
//! result is the verdict.

use std::collections::HashMap;
use std::sync::{Mutex, MutexGuard, PoisonError};

use super::text::number_text;
use super::{Program, text};
use crate::data::DataError;

/// How an answer line is read: the answer, or why the line is not one.
pub(super) type Reader<A> = Box<dyn Fn(&[&str]) -> Result<A, String> + Send + Sync>;

/// The answers to one kind of question (`N` numbers after the verb), and the questions
/// waiting for theirs.
pub(super) struct Memo<const N: usize, A> {
    verb: &'static str,
    read: Reader<A>,
    state: Mutex<State<N, A>>,
}

struct State<const N: usize, A> {
    /// Keyed by the numbers' bits: `0.0` and `-0.0` are different questions.
    answers: HashMap<[u64; N], Option<A>>,
    waiting: Vec<[u64; N]>,
}

impl<const N: usize, A: Copy> Memo<N, A> {
    /// No answers yet to questions `verb x1 ... xN`, whose answer lines `read` reads (from
    /// their fields).
    pub(super) fn new(verb: &'static str, read: Reader<A>) -> Self {
        Self {
            verb,
            read,
            state: Mutex::new(State {
                answers: HashMap::new(),
                waiting: Vec::new(),
            }),
        }
    }

    fn state(&self) -> MutexGuard<'_, State<N, A>> {
        // A checker that panicked mid-run cannot leave a half-written answer behind.
        self.state.lock().unwrap_or_else(PoisonError::into_inner)
    }

    // ANCHOR: get
    /// The answer to `question`; if there is none yet, `stand_in`, and the question waits
    /// for the next round.
    pub(super) fn get(&self, question: [f64; N], stand_in: A) -> A {
        let key = question.map(f64::to_bits);
        let mut state = self.state();
        match state.answers.get(&key) {
            Some(Some(answer)) => *answer,
            Some(None) => stand_in,
            None => {
                state.answers.insert(key, None);
                state.waiting.push(key);
                stand_in
            }
        }
    }
    // ANCHOR_END: get

    /// Records `answer` to `question` (a table's row); `Err` with the other answer if it
    /// had a different one.
    pub(super) fn insert(&self, question: [f64; N], answer: A) -> Result<(), A>
    where
        A: PartialEq,
    {
        let key = question.map(f64::to_bits);
        match self.state().answers.insert(key, Some(answer)) {
            Some(Some(other)) if other != answer => Err(other),
            _ => Ok(()),
        }
    }

    /// Reads one answer line (for tables, whose rows end with an answer).
    pub(super) fn read(&self, fields: &[&str]) -> Result<A, String> {
        (self.read)(fields)
    }
}

/// What [`rounds`] needs of a memo, whatever its kind of question.
pub(super) trait Ask: Sync {
    /// The questions waiting for an answer, as protocol lines (`verb x1 ... xN`), in the
    /// order they were asked.
    fn waiting(&self) -> Vec<String>;
    /// Records `answers` (one line each) to the waiting questions, in order, and clears
    /// them; on a line that is not an answer, its index and why.
    fn answer(&self, answers: &[String]) -> Result<(), (usize, String)>;
}

impl<const N: usize, A: Copy + Send> Ask for Memo<N, A> {
    fn waiting(&self) -> Vec<String> {
        self.state()
            .waiting
            .iter()
            .map(|key| {
                let mut line = self.verb.to_string();
                for &bits in key {
                    line.push(' ');
                    line.push_str(&number_text(f64::from_bits(bits)));
                }
                line
            })
            .collect()
    }

    fn answer(&self, answers: &[String]) -> Result<(), (usize, String)> {
        let mut state = self.state();
        let waiting = std::mem::take(&mut state.waiting);
        for (k, (key, line)) in waiting.iter().zip(answers).enumerate() {
            let answer =
                (self.read)(&text::fields(line)).map_err(|why| (k, format!("{why}: `{line}`")))?;
            state.answers.insert(*key, Some(answer));
        }
        Ok(())
    }
}

/// Where the answers come from.
pub(super) enum Source<'a> {
    /// A program, asked in runs.
    Program(&'a Program),
    /// A table read into the memos already (its file's name): a question it does not
    /// answer is an error.
    Table(&'a str),
}

/// The most rounds a checker may need: each round answers the questions that the answers
/// of the round before led to, and no checker chains more than a few.
const MAX_ROUNDS: usize = 64;

// ANCHOR: rounds
/// Runs `check` on `memos` until a run asks nothing new, asking the program of `source`
/// the questions of each run in between (all kinds in one run of the program, in the
/// order of `memos`), and returns that last run's result.
///
/// # Errors
/// The program's [`DataError`] (it cannot be run, or an answer is not one, with its line
/// and question), or, for a table, the first question it has no row for.
pub(super) fn rounds<T>(
    source: &Source,
    memos: &[&dyn Ask],
    mut check: impl FnMut() -> T,
) -> Result<T, DataError> {
    for round in 1..=MAX_ROUNDS {
        let result = check();
        let asked: Vec<Vec<String>> = memos.iter().map(|m| m.waiting()).collect();
        let questions: Vec<String> = asked.concat();
        if questions.is_empty() {
            return Ok(result);
        }
        let program = match source {
            Source::Program(program) => program,
            Source::Table(name) => {
                return Err(DataError::new(
                    name,
                    0,
                    format!(
                        "no row answers the question `{}` ({} question{} unanswered; \
                         --questions FILE lists them)",
                        questions[0],
                        questions.len(),
                        if questions.len() == 1 { " is" } else { "s are" }
                    ),
                ));
            }
        };
        let answers = program.ask(&questions, round)?;
        let mut first = 0;
        for (memo, asked) in memos.iter().zip(&asked) {
            let these = &answers[first..first + asked.len()];
            memo.answer(these).map_err(|(k, why)| {
                DataError::new(
                    &program.output_name(),
                    first + k + 1,
                    format!("the answer to `{}` {why}", asked[k]),
                )
            })?;
            first += asked.len();
        }
    }
    Err(DataError::new(
        match source {
            Source::Program(p) => p.command.as_str(),
            Source::Table(name) => name,
        },
        0,
        format!("the checker was still asking new questions after {MAX_ROUNDS} rounds"),
    ))
}
// ANCHOR_END: rounds

/// The questions a run of `check` on `memos` leaves unanswered (for a table being
/// written: the rows it still needs).
pub(super) fn unanswered(memos: &[&dyn Ask], check: impl FnOnce()) -> Vec<String> {
    check();
    memos.iter().flat_map(|m| m.waiting()).collect()
}
