//! The report card (chapter *Coursework*, `src/exercise/card.rs`): every exercise's
//! checkers on this crate's own functions. In the student edition this is what says
//! which exercises are not started, waiting, failing or passing.
//!
//! The card is printed at the very end of the test binary's output, after libtest's
//! summary (from a C `atexit` handler, which runs when libtest exits), so that it is the
//! last thing `cargo test` shows; the test itself fails, with the total, unless every
//! exercise passes. `cargo test --test book report_card` runs it alone.
//!
//! A test that never returns (a loop in an exercise) would keep libtest waiting for ever,
//! and the card would never be printed. So the first test of the binary in libtest's order
//! (`a_watchdog_for_tests_that_never_return`, in `main.rs`) starts [`watchdog`]: once the
//! card has been printed-to-be for [`GRACE`] seconds, or [`WAIT`] seconds after the start if
//! the card's own test never got a thread, it prints the card (making it first if need
//! be), says that a test did not return, and ends the run with exit status 101, as a
//! failing `cargo test` does. libtest has already named the test that hangs ("has been
//! running for over 60 seconds") when the wait is longer than that.

use std::io::Write as _;
use std::sync::OnceLock;
use std::time::{Duration, Instant};

use raylemma::exercise::{card, edition};

static CARD: OnceLock<String> = OnceLock::new();

unsafe extern "C" {
    /// The C library's `atexit`: `callback` runs when the process exits normally.
    fn atexit(callback: extern "C" fn()) -> std::ffi::c_int;
}

/// Prints the card (called once, at exit; never unwinds).
extern "C" fn print_card() {
    if PRINTED.get().is_some() {
        return;
    }
    if let Some(text) = CARD.get() {
        let mut out = std::io::stdout();
        let _ = writeln!(out, "\n{text}");
        let passed = PASSED.load(std::sync::atomic::Ordering::Relaxed);
        let n = STUB_PANICS.load(std::sync::atomic::Ordering::Relaxed);
        if let Some(note) = stub_note(n, passed) {
            let _ = writeln!(out, "{note}");
        }
        let _ = out.flush();
    }
}

/// Seconds the run may go on after the card is made (every other test of the solutions
/// ends within about 30 s of the start on 2 cores), unless `RAYLEMMA_TEST_GRACE` says.
pub const GRACE: u64 = 120;
/// Seconds after the start at which the card is made by the watchdog if its own test has
/// not run, unless `RAYLEMMA_TEST_WAIT` says.
pub const WAIT: u64 = 300;

fn seconds(var: &str, default: u64) -> Duration {
    let s = std::env::var(var)
        .ok()
        .and_then(|v| v.parse().ok())
        .unwrap_or(default);
    Duration::from_secs(s)
}

fn make_card() -> card::Card {
    let root = crate::support::root();
    let markers = edition::markers_under(root).unwrap_or_else(|e| panic!("{e}"));
    card::run(&markers).with_sections(root, &markers)
}

/// Starts the watchdog thread (see the module's documentation); it ends the process only
/// if the run is still going when its time is up.
pub fn watchdog() {
    let (grace, wait) = (
        seconds("RAYLEMMA_TEST_GRACE", GRACE),
        seconds("RAYLEMMA_TEST_WAIT", WAIT),
    );
    let start = Instant::now();
    std::thread::spawn(move || {
        let mut carded: Option<Instant> = None;
        loop {
            std::thread::sleep(Duration::from_millis(250));
            if carded.is_none() && CARD.get().is_some() {
                carded = Some(Instant::now());
            }
            let late = match carded {
                Some(t) => t.elapsed() >= grace,
                None => start.elapsed() >= wait,
            };
            if late {
                break;
            }
        }
        let text = CARD
            .get()
            .cloned()
            .unwrap_or_else(|| make_card().to_string());
        let mut out = std::io::stdout();
        let _ = writeln!(
            out,
            "\nraylemma: a test has not returned {} s after the start: a loop that never ends (libtest names the test that has been running for over 60 seconds). The run is stopped here.\n\n{text}",
            start.elapsed().as_secs()
        );
        let _ = out.flush();
        // The card is printed: the atexit handler must not print it again.
        PRINTED.set(()).ok();
        std::process::exit(101);
    });
}

/// Silences the panic of a stub (`raylemma::exercise::todo`) in a whole run, counting it
/// instead: in the hand-out's first run most tests fail on a stub, and the card, last,
/// lists each exercise not started on one line, where a message per test would bury it
/// (libtest prints a failing test's section only when the test printed something). Every
/// other panic is left to the hook that was there (libtest's capture takes it into the
/// failing test's output). The card's footer says how many panics were stubs'. With
/// `RAYLEMMA_STUB_MESSAGES` set, each stub's message is one line in its test's output (CI's
/// check of cross-chapter dependencies reads them).
pub fn silent_stubs() {
    let previous = std::panic::take_hook();
    std::panic::set_hook(Box::new(move |info| {
        if DELIBERATE.get() {
            return; // a test's own stub, caught by that test: no failure, nothing to count
        }
        let message = raylemma::exercise::panic_message(info.payload());
        if raylemma::exercise::not_started(&message).is_some() {
            STUB_PANICS.fetch_add(1, std::sync::atomic::Ordering::Relaxed);
            if std::env::var_os("RAYLEMMA_STUB_MESSAGES").is_some() {
                eprintln!("{message}");
            }
        } else {
            previous(info);
        }
    }));
}

thread_local! {
    /// Set while [`deliberate`] runs its closure on this thread.
    static DELIBERATE: std::cell::Cell<bool> = const { std::cell::Cell::new(false) };
}

/// Runs `f`, which a test expects to panic, catching the panic; the hook of
/// [`silent_stubs`] neither prints nor counts it (a test of the stubs themselves would
/// otherwise add a stub "not started" to the card's footer of every edition).
pub fn deliberate<R>(f: impl FnOnce() -> R + std::panic::UnwindSafe) -> std::thread::Result<R> {
    DELIBERATE.set(true);
    let result = std::panic::catch_unwind(f);
    DELIBERATE.set(false);
    result
}

/// How many panics [`silent_stubs`] kept quiet.
static STUB_PANICS: std::sync::atomic::AtomicUsize = std::sync::atomic::AtomicUsize::new(0);

/// True once the card's test found every exercise passing.
static PASSED: std::sync::atomic::AtomicBool = std::sync::atomic::AtomicBool::new(false);

/// The line the card ends with when `n` stubs panicked: what the silent failures were.
/// None when the card `passed`: no exercise is then a stub, and a stub's panic was a test
/// of the stubs themselves (the solutions' card does not blame exercises not started).
fn stub_note(n: usize, passed: bool) -> Option<String> {
    (n > 0 && !passed).then(|| {
        format!(
            "{n} panics in the tests above were stubs of exercises not started, kept quiet: a \
             test that failed with nothing printed reached one, and passes once the exercises \
             it needs are written (each row's `unlocks`); `cargo test --test book CHAPTER` \
             shows their messages"
        )
    })
}

#[test]
fn the_stub_note_is_left_out_when_every_exercise_passes() {
    assert_eq!(stub_note(0, false), None);
    assert_eq!(stub_note(3, true), None);
    assert!(stub_note(3, false).is_some_and(|n| n.starts_with("3 panics")));
}

/// Set once the watchdog has printed the card.
static PRINTED: OnceLock<()> = OnceLock::new();

#[test]
fn report_card() {
    let card = make_card();
    PASSED.store(card.passed(), std::sync::atomic::Ordering::Relaxed);
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
