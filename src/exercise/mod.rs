//! Coursework: the exercises marked in the source, the student edition made from them,
//! and the report card. Chapter: *Coursework* (`chapters/coursework.md`).
//!
//! * [`marker`]: the `// EXERCISE CHAPTER NAME: TASK` … `// END EXERCISE` comments around
//!   each function a student writes, parsed and checked (chapter, name, layout);
//! * [`stub`]: a marked body replaced by a call to [`todo()`];
//! * [`scrub`]: no line of a removed solution may survive in the hand-out;
//! * [`edition`]: the student edition, a self-contained crate (`raylemma exercises DIR`,
//!   with `--solutions` for the teachers' copy);
//! * [`registry`]: which checkers judge each exercise, and what each one unlocks;
//! * [`card`]: the report card that the edition's `cargo test` prints at its end;
//! * [`disc_rows`]: the chapter's look inside a failed chi-squared test (the counts of three
//!   rows of the disc's cells), which its tests run and the figure job writes;
//! * [`grade`]: a submission's exercise bodies put into the edition's own code, and its
//!   score from the teacher's weights (`raylemma grade`).

pub mod card;
pub mod disc_rows;
pub mod edition;
pub mod grade;
pub mod marker;
pub mod mistakes;
pub mod registry;
pub mod scrub;
pub mod section;
pub mod stub;

/// The start of the panic message of a stub.
pub(crate) const NOT_STARTED: &str = "exercise `";
/// What follows the exercise's name in that message.
const NOT_STARTED_END: &str = "` is not started";

/// The body of a stub in the hand-out: panics with a message that names the exercise and
/// where the stub is (the caller's file and line), which the report card recognises
/// ([`not_started`]). Returns `!`, so a stub compiles whatever its function returns.
#[track_caller]
pub fn todo(name: &str) -> ! {
    let at = std::panic::Location::caller();
    panic!(
        "{NOT_STARTED}{name}{NOT_STARTED_END}: write the body of its stub at {}:{} (see its // EXERCISE marker)",
        at.file(),
        at.line()
    )
}

/// The exercise named by a stub's panic message, if `message` is one.
pub fn not_started(message: &str) -> Option<&str> {
    let rest = message.strip_prefix(NOT_STARTED)?;
    let end = rest.find(NOT_STARTED_END)?;
    Some(&rest[..end])
}

/// The message of a panic's payload (`panic!` with a string or a format), or a note that
/// it had none.
pub fn panic_message(payload: &(dyn std::any::Any + Send)) -> String {
    if let Some(s) = payload.downcast_ref::<&str>() {
        (*s).to_string()
    } else if let Some(s) = payload.downcast_ref::<String>() {
        s.clone()
    } else {
        "a panic without a message".to_string()
    }
}
