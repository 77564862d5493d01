//! `raylemma`: renders and compares scenes; runs the checkers on implementations outside
//! Rust; regenerates the book's figures and builds the
//! book. One file per subcommand under `src/cmd/`.
//!
//! `cargo run --release` with no subcommand regenerates the figures and reference images
//! and builds the book; see `--help`. The figures and the book are made by two tools of
//! this workspace (`tools/figures/`, `tools/book/`), which this program runs with cargo,
//! so that the library never compiles their dependencies.

mod cmd;

use std::process::ExitCode;

use clap::{Parser, Subcommand};

/// Render and compare scenes; regenerate raylemma's figures and build its book.
///
/// With no subcommand: `figures`, `references`, then `book`.
#[derive(Parser, Debug)]
#[command(name = "raylemma", version, about, long_about = None)]
struct Cli {
    /// With no subcommand: fewer samples and shorter timings (for CI); figures keep their
    /// shape. (`figures` and `references` take it too.)
    #[arg(long)]
    quick: bool,
    #[command(subcommand)]
    command: Option<Cmd>,
}

#[derive(Subcommand, Debug)]
enum Cmd {
    /// Regenerate every figure and generated table into figures/.
    ///
    /// The figure job (tools/figures/) writes every output together or not at all, with a
    /// progress bar and each output's time. The outputs that take seconds to minutes and
    /// depend only on the code (the calibrations and power tables) are kept while the code
    /// is what they record (a hash of src/, data/, scenes/, tools/examples/,
    /// tools/figures/src/ and Cargo.lock, in a comment at their end): delete one to remake
    /// it. The timing tables are kept as committed, each naming the machine it was
    /// measured on; --timings measures them on this one.
    #[command(after_help = "Example:\n  raylemma figures --only sphere_speed")]
    Figures(cmd::figures::FiguresArgs),
    /// Render the canonical scenes whose references in figures/reference/ are out of date
    /// (each records what it was made from), with the noise-level table and the cornell
    /// scene's RMSE against time.
    #[command(after_help = "Example:\n  raylemma references --check")]
    References(cmd::figures::ReferencesArgs),
    /// Build the HTML book from chapters/ into book/ (mdBook as a library, math as MathML).
    #[command(after_help = "Example:\n  raylemma book   (then open book/index.html)")]
    Book,
    /// Render a scene file: SCENE.exr (linear sRGB and the variance of each pixel's mean),
    /// SCENE.png (display) and SCENE.json (scene hash, spp, seed, time, version) in --out.
    #[command(
        after_help = "Example:\n  raylemma render scenes/cornell.toml --spp 64 --seed 1 --out renders"
    )]
    Render(cmd::render::RenderArgs),
    /// Pool independent renders of one scene (different seeds) into one render, exactly:
    /// means, variances and samples per pixel. Exit status 2 for renders of different
    /// scenes, settings or builds, or two with one seed.
    #[command(
        after_help = "Example:\n  raylemma merge a/cornell.exr b/cornell.exr --out merged/cornell.exr"
    )]
    Merge(cmd::merge::MergeArgs),
    /// Check another renderer on the conformance ladder (scenes/conformance/): each rung
    /// written in its format, rendered several times with different seeds and compared
    /// with its reference; a card per rung and depth (text, JSON, JUnit XML). Exit status
    /// 0 if every rung agrees, 1 if one differs or the renderer failed on it, 2 for usage.
    #[command(
        after_help = "Example:\n  raylemma conformance --format mitsuba --renderer \"python3 render.py {scene} {out} {spp} {seed}\""
    )]
    Conformance(cmd::conformance::ConformanceArgs),
    /// Does a candidate agree with a reference render within their noise? The candidate is
    /// one EXR with variance channels or several independent plain RGB EXRs. Exit status 0
    /// if they agree, 1 if they differ, 2 for bad input.
    #[command(
        after_help = "Example:\n  raylemma compare figures/reference/cornell.exr mine-1.exr mine-2.exr mine-3.exr mine-4.exr --spp 64"
    )]
    Compare(cmd::compare::CompareArgs),
    /// Run the book's checkers on an implementation outside Rust: a program that answers
    /// questions on stdin/stdout, or a file of values. Prints the verdict; exit status 0
    /// if it passes, 1 if it fails, 2 for bad input.
    Check {
        #[command(subcommand)]
        command: cmd::check::CheckCmd,
    },
    /// Write the student edition into DIR: a crate in which every exercise's body is a
    /// stub, whose `cargo test` ends with a report card (--solutions: the solutions in
    /// place).
    #[command(
        after_help = "Example:\n  raylemma exercises ~/handout   (then: cd ~/handout && cargo test)"
    )]
    Exercises(cmd::exercises::ExercisesArgs),
    /// Print the report card of this crate's exercises (in the hand-out: where each one
    /// stands), without building the tests. Exit status 0 if every exercise passes, 1 if
    /// one does not.
    #[command(after_help = "Example:\n  cargo run -- card disc_polar   (inside a hand-out)")]
    Card(cmd::card::CardArgs),
    /// Grade a worked hand-out: its exercise bodies in the edition's own code, judged by the
    /// card, scored with the teacher's weights; writes grade.txt, grade.json, junit.xml and
    /// Gradescope's results.json. Exit status 0 full marks, 1 less, 2 bad input.
    #[command(
        after_help = "Example:\n  raylemma grade submissions/alice --weights tools/grade/weights.toml --out grades/alice"
    )]
    Grade(cmd::grade::GradeArgs),
    /// Write a scene for other renderers: a Mitsuba 3 XML file, a pbrt-v4 scene file, or
    /// fully resolved JSON (defaults filled in, spectra on the 1 nm grid, transforms
    /// explicit).
    #[command(
        after_help = "Example:\n  raylemma export scenes/cornell.toml --to mitsuba --out cornell.xml"
    )]
    Export(cmd::export::ExportArgs),
}

/// Parses the command line and runs the subcommand; its result becomes the exit status by
/// the one rule of [`cmd::exit`] (0 success, 1 a negative verdict, 2 bad input or usage).
fn main() -> ExitCode {
    one_message_per_unfinished_exercise();
    let cli = Cli::parse();
    if cli.quick && cli.command.is_some() {
        return cmd::exit(Err(cmd::Failure::BadInput(
            "--quick goes after `figures` or `references` (raylemma figures --quick), or alone for everything".into(),
        )));
    }
    cmd::exit(match &cli.command {
        None => cmd::figures::everything(cli.quick),
        Some(Cmd::Figures(args)) => cmd::figures::figures(args),
        Some(Cmd::References(args)) => cmd::figures::references(args),
        Some(Cmd::Book) => cmd::book::build(),
        Some(Cmd::Render(args)) => cmd::render::run(args),
        Some(Cmd::Compare(args)) => cmd::compare::run(args),
        Some(Cmd::Merge(args)) => cmd::merge::run(args),
        Some(Cmd::Conformance(args)) => cmd::conformance::run(args),
        Some(Cmd::Check { command }) => cmd::check::run(command),
        Some(Cmd::Exercises(args)) => cmd::exercises::run(args),
        Some(Cmd::Card(args)) => cmd::card::run(args),
        Some(Cmd::Grade(args)) => cmd::grade::run(args),
        Some(Cmd::Export(args)) => cmd::export::run(args),
    })
}

/// Whether a panic is `print!`'s on a closed pipe: standard output or error written after
/// the program reading them has exited (Rust ignores `SIGPIPE`, so the write fails, and
/// `print!` panics with the error).
fn closed_pipe(message: &str) -> bool {
    message.starts_with("failed printing to std") && message.contains("Broken pipe")
}

/// In the student edition, a function whose exercise is not started panics on every thread
/// that calls it (a render calls it once per worker, and then again on the main thread):
/// print that message once, with what to do; end quietly on a closed pipe
/// ([`closed_pipe`]); and leave every other panic to the default hook.
fn one_message_per_unfinished_exercise() {
    use std::sync::atomic::{AtomicBool, Ordering};
    static SAID: AtomicBool = AtomicBool::new(false);
    let default = std::panic::take_hook();
    std::panic::set_hook(Box::new(move |info| {
        let message = raylemma::exercise::panic_message(info.payload());
        if closed_pipe(&message) {
            // The reader went away (`raylemma check corpus | head -1`): what it wanted, it
            // has; nothing is wrong, so end quietly with status 0, as `cat` would.
            std::process::exit(0);
        }
        if raylemma::exercise::not_started(&message).is_none() {
            return default(info);
        }
        if !SAID.swap(true, Ordering::SeqCst) {
            eprintln!(
                "raylemma: {message}\nraylemma: this command calls that exercise; the report card (cargo test --test book report_card) lists what each command needs"
            );
        }
    }));
}
