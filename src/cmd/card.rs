//! `raylemma card [EXERCISE...]`: the report card of the exercises of this crate
//! (`src/exercise/card.rs`), without building the test binary: in the hand-out, the
//! quickest way to see where each exercise stands after an edit. With exercises named, only
//! those are judged, and each failing one's verdicts are printed in full after the card
//! (every claim in words, its first and worst failing inputs) with the chapter to reread.
//! `--json FILE` writes the card as data too (what `raylemma grade` reads).
//!
//! The card judges the code compiled into this binary, so it refuses (exit status 2) to
//! run outside the crate that binary was built from ([`edition::check_judged_crate`]):
//! the repository's binary run inside a hand-out would judge the solved code.

use std::path::PathBuf;

use clap::Args;
use raylemma::exercise::{card, edition};

use super::{CmdResult, Failure, Outcome, root};

/// `raylemma card`.
#[derive(Args, Debug)]
pub struct CardArgs {
    /// Judge only these exercises (names as in the card: `disc_polar`,
    /// `Sellmeier::index`); the others are left out of the card.
    #[arg(value_name = "EXERCISE")]
    pub only: Vec<String>,
    /// Also write the card as JSON to this file.
    #[arg(long, value_name = "FILE")]
    pub json: Option<PathBuf>,
}

/// Runs `raylemma card`: 0 if every exercise judged passes, 1 if one does not, 2 for an
/// unknown exercise, a working directory outside the crate this binary judges, markers that
/// cannot be read or JSON that cannot be written.
pub fn run(args: &CardArgs) -> CmdResult {
    let root = root();
    let cwd = std::env::current_dir()
        .map_err(|e| Failure::BadInput(format!("cannot read the working directory: {e}")))?;
    edition::check_judged_crate(&root, &cwd).map_err(Failure::BadInput)?;
    let mut markers = edition::markers_under(&root)?;
    if let Some(unknown) = args
        .only
        .iter()
        .find(|n| !markers.iter().any(|m| m.name == **n))
    {
        let names: Vec<&str> = markers.iter().map(|m| m.name.as_str()).collect();
        return Err(Failure::BadInput(format!(
            "no exercise is called `{unknown}`; the exercises are: {}",
            names.join(", ")
        )));
    }
    let card = if args.only.is_empty() {
        card::run(&markers)
    } else {
        markers.retain(|m| args.only.contains(&m.name));
        card::run_some(&markers)
    }
    .with_sections(&root, &markers);
    println!("{card}");
    for row in card.rows.iter().filter(|_| !args.only.is_empty()) {
        // A loop is waited for once: the card's line is its whole verdict.
        let stuck = card::stuck(&row.status);
        let verdicts = card::failed_verdicts(&row.name, &row.status);
        if verdicts.is_empty() && !stuck {
            continue;
        }
        let section = row.section.as_ref().map_or_else(String::new, |s| {
            format!(", section {} ({})", s.title, s.link)
        });
        println!(
            "\n--- {} is {}: reread chapter {}{section} (chapters/{}.md; in the built book, book/{}.html)",
            row.name,
            row.status.label(),
            row.chapter,
            row.chapter,
            row.chapter
        );
        if stuck {
            println!(
                "its checks did not return within {} s above, so they are not run again for a full verdict: look for a loop that never ends",
                card::LIMIT.as_secs()
            );
        }
        for v in verdicts {
            print!("{v}");
        }
    }
    if let Some(path) = &args.json {
        let text = serde_json::to_string_pretty(&card.report())
            .map_err(|e| Failure::Failed(format!("cannot write the card as JSON: {e}")))?;
        raylemma::output::write_file(path, (text + "\n").as_bytes())?;
    }
    Ok(if card.passed() {
        Outcome::Done
    } else {
        Outcome::Negative
    })
}
