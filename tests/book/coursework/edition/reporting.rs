//! The grade written down (`src/exercise/grade/report.rs`): each of its four formats
//! (text, JSON, Gradescope's `results.json`, JUnit XML) for a small hand-made grade,
//! without building or running anything, and `write_all` writing all four.

use super::*;
use raylemma::exercise::card::Entry;
use raylemma::exercise::grade::report;
use raylemma::exercise::grade::{Grade, Graded};

/// Two exercises, one passing (2 points of 2) and one failing (0 of 0.5) with a detail
/// that XML and JSON must escape, and a note.
fn grade() -> Grade {
    let row = |name: &str, chapter: &str, file: &str, status: &str, details: &[&str]| Entry {
        name: name.into(),
        chapter: chapter.into(),
        file: file.into(),
        status: status.into(),
        details: details.iter().map(|d| d.to_string()).collect(),
        section: None,
    };
    Grade {
        rows: vec![
            Graded {
                entry: row(
                    "disc_polar",
                    "sampling/disc",
                    "src/sampling/disc.rs",
                    "passing",
                    &[],
                ),
                score: 2.0,
                max: 2.0,
            },
            Graded {
                entry: row(
                    "Table::lookup",
                    "optics/fresnel",
                    "src/optics/fresnel.rs",
                    "failing",
                    &["claim <R> & \"x\" fails"],
                ),
                score: 0.0,
                max: 0.5,
            },
        ],
        notes: vec!["a note".into()],
    }
}

#[test]
fn the_grade_as_text_has_a_line_per_exercise_its_details_and_the_notes() {
    assert_eq!(
        report::text(&grade(), Path::new("hw")),
        "GRADE of hw: 2 of 2.5 points\n\
         \x20      2 / 2      passing     disc_polar (sampling/disc)\n\
         \x20      0 / 0.5    failing     Table::lookup (optics/fresnel)\n\
         \x20     claim <R> & \"x\" fails\n\
         \x20 note: a note\n"
    );
}

#[test]
fn the_grade_as_json_has_the_scores_the_notes_and_every_exercise() {
    assert_eq!(
        report::json(&grade()),
        r#"{
  "exercises": [
    {
      "chapter": "sampling/disc",
      "details": [],
      "file": "src/sampling/disc.rs",
      "max_score": 2.0,
      "name": "disc_polar",
      "score": 2.0,
      "status": "passing"
    },
    {
      "chapter": "optics/fresnel",
      "details": [
        "claim <R> & \"x\" fails"
      ],
      "file": "src/optics/fresnel.rs",
      "max_score": 0.5,
      "name": "Table::lookup",
      "score": 0.0,
      "status": "failing"
    }
  ],
  "max_score": 2.5,
  "notes": [
    "a note"
  ],
  "score": 2.0
}
"#
    );
}

#[test]
fn the_grade_for_gradescope_has_one_test_per_exercise_and_the_notes_as_output() {
    assert_eq!(
        report::gradescope(&grade()),
        r#"{
  "output": "a note",
  "score": 2.0,
  "tests": [
    {
      "max_score": 2.0,
      "name": "disc_polar",
      "output": "passing (sampling/disc, src/sampling/disc.rs)",
      "score": 2.0,
      "status": "passed"
    },
    {
      "max_score": 0.5,
      "name": "Table::lookup",
      "output": "failing (optics/fresnel, src/optics/fresnel.rs)\n  claim <R> & \"x\" fails",
      "score": 0.0,
      "status": "failed"
    }
  ]
}
"#
    );
}

#[test]
fn the_grade_as_junit_has_a_failure_per_failing_exercise_escaped() {
    assert_eq!(
        report::junit(&grade()),
        "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n\
         <testsuite name=\"raylemma exercises\" tests=\"2\" failures=\"1\">\n\
         \x20 <testcase classname=\"sampling/disc\" name=\"disc_polar\"/>\n\
         \x20 <testcase classname=\"optics/fresnel\" name=\"Table::lookup\">\
         <failure message=\"failing\">failing (optics/fresnel, src/optics/fresnel.rs)\n  \
         claim &lt;R&gt; &amp; &quot;x&quot; fails</failure></testcase>\n\
         \x20 <system-out>a note</system-out>\n\
         </testsuite>\n"
    );
}

#[test]
fn write_all_writes_the_four_files() {
    let dir = scratch("grade-report");
    let out = dir.join("grade");
    let g = grade();
    let text = report::text(&g, Path::new("hw"));
    report::write_all(&out, &g, &text).unwrap();
    let read = |name: &str| fs::read_to_string(out.join(name)).unwrap();
    assert_eq!(read("grade.txt"), text);
    assert_eq!(read("grade.json"), report::json(&g));
    assert_eq!(read("junit.xml"), report::junit(&g));
    assert_eq!(read("results.json"), report::gradescope(&g));
}
