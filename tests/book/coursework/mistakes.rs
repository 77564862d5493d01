//! The card's power, measured as the renderer's is: every typical mistake of every
//! exercise ([`raylemma::exercise::mistakes::twins`]) is rejected by the exercise's own
//! checks, every correct alternative passes them, each mistake's probe tells it apart from
//! the right answer and from the exercise's other mistakes, and what the hand-out keeps of
//! them (`src/exercise/mistakes/known.rs`) is what the twins give.

use raylemma::check::Verdict;
use raylemma::exercise::mistakes::{self, fingerprint, probes, twins};
use raylemma::exercise::registry;

use crate::support::generated;

fn passes(verdicts: &[Verdict]) -> bool {
    !verdicts.is_empty() && verdicts.iter().all(Verdict::passed)
}

#[test]
fn every_mistake_is_rejected() {
    let missed: Vec<String> = twins::tables()
        .flat_map(|t| t.mistakes.iter().map(move |m| (t.exercise, m)))
        .filter(|(_, m)| passes(&(m.check)()))
        .map(|(e, m)| format!("{e}: {}", m.words))
        .collect();
    assert!(missed.is_empty(), "the card passes: {missed:#?}");
}

#[test]
fn every_alternative_passes() {
    let refused: Vec<String> = twins::tables()
        .flat_map(|t| t.alternatives.iter().map(move |a| (t.exercise, a)))
        .filter(|(_, a)| !passes(&(a.check)()))
        .map(|(e, a)| format!("{e}: {}", a.words))
        .collect();
    assert!(refused.is_empty(), "the card refuses: {refused:#?}");
}

#[test]
fn every_mistake_is_told_apart_and_named() {
    for t in twins::tables() {
        assert!(
            t.mistakes.len() >= 5,
            "{}: only {} mistakes",
            t.exercise,
            t.mistakes.len()
        );
        assert!(
            !t.alternatives.is_empty(),
            "{}: no correct alternative",
            t.exercise
        );
        let probe = probes::of(t.exercise).expect("every table's exercise has a probe");
        let right = fingerprint(&probe());
        // The right answer is no mistake (the card names nothing for it).
        assert!(mistakes::recognise(t.exercise).is_none(), "{}", t.exercise);
        for m in t.mistakes {
            let print = fingerprint(&(m.probe)());
            assert_ne!(
                print, right,
                "{}: `{}` gives the right answer's probe",
                t.exercise, m.words
            );
            // The mistake the card would name for this probe is this one.
            let named = mistakes::matching(t.exercise, print).map(|k| k.words);
            assert_eq!(named, Some(m.words), "{}", t.exercise);
        }
    }
}

#[test]
fn the_hand_out_knows_every_mistake_the_twins_make() {
    generated(
        "src/exercise/mistakes/known.rs",
        &twins::known_rs(),
        "RAYLEMMA_WRITE_KNOWN",
    );
}

#[test]
fn every_exercise_has_its_mistakes() {
    let missing: Vec<&str> = registry::EXERCISES
        .iter()
        .map(|e| e.name)
        .filter(|n| !twins::tables().any(|t| t.exercise == *n))
        .collect();
    assert!(missing.is_empty(), "no table of mistakes: {missing:?}");
}
