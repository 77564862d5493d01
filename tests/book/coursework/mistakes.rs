//! The card's power, measured as the renderer's is: every typical mistake of every
//! exercise ([`raylemma::exercise::mistakes`]) is rejected by the exercise's own checks,
//! every correct alternative passes them, and each mistake's outputs on the probe inputs
//! tell it apart from the right answer and from the exercise's other mistakes, so the card
//! can name it.

use raylemma::check::Verdict;
use raylemma::exercise::mistakes::{self, same_outputs};

fn passes(verdicts: &[Verdict]) -> bool {
    !verdicts.is_empty() && verdicts.iter().all(Verdict::passed)
}

#[test]
fn every_mistake_is_rejected() {
    let missed: Vec<String> = mistakes::tables()
        .flat_map(|t| t.mistakes.iter().map(move |m| (t.exercise, m)))
        .filter(|(_, m)| passes(&(m.check)()))
        .map(|(e, m)| format!("{e}: {}", m.words))
        .collect();
    assert!(missed.is_empty(), "the card passes: {missed:#?}");
}

#[test]
fn every_alternative_passes() {
    let refused: Vec<String> = mistakes::tables()
        .flat_map(|t| t.alternatives.iter().map(move |a| (t.exercise, a)))
        .filter(|(_, a)| !passes(&(a.check)()))
        .map(|(e, a)| format!("{e}: {}", a.words))
        .collect();
    assert!(refused.is_empty(), "the card refuses: {refused:#?}");
}

#[test]
fn every_mistake_is_told_apart_and_named() {
    for t in mistakes::tables() {
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
        let right = (t.probe)();
        // The right answer is no mistake (the card names nothing for it).
        assert!(mistakes::recognise(t.exercise).is_none(), "{}", t.exercise);
        for (i, m) in t.mistakes.iter().enumerate() {
            let outputs = (m.probe)();
            assert!(
                !same_outputs(&outputs, &right),
                "{}: `{}` gives the right answer's outputs on every probe input",
                t.exercise,
                m.words
            );
            // The first mistake matching a twin's outputs is that twin.
            let named = mistakes::matching(t.exercise, &outputs).map(|n| n.words);
            assert_eq!(named, Some(m.words), "{}: mistake {i}", t.exercise);
        }
    }
}
