//! Grading (`src/exercise/grade.rs`); `raylemma grade` itself is run by CI on five
//! submissions (`.ci/editions`), since each builds a crate.

use super::*;

/// The fixture with its solution of `disc_polar` replaced and a helper outside the
/// markers changed: what a student might submit.
const SUBMITTED: &str = "\
use super::V2;
use super::Helper; // a `use` outside the markers: not graded

// ANCHOR: polar
// EXERCISE sampling/disc disc_polar: map the square to the disc
/// The polar map: `r = sqrt(u1)`.
#[allow(unused_variables)]
pub fn disc_polar(u: V2) -> V2 {
    let r = u.x.powf(0.5); // the student's
    V2::new(r, 0.0)
}
// END EXERCISE
// ANCHOR_END: polar

fn helper() -> f64 { 42.0 } // outside the markers: not graded
";

#[test]
fn the_grader_takes_only_the_bodies_of_a_submission() {
    let dir = scratch("grade-bodies");
    fs::create_dir_all(dir.join("src")).unwrap();
    fs::write(dir.join("src/fixture.rs"), SUBMITTED).unwrap();
    let sources = crate_with("// tests\n");
    let exercises = edition::markers(&sources).unwrap();
    let (files, notes) = grade::splice(sources, &exercises, &chapters(), &dir);
    let text = String::from_utf8(
        files
            .iter()
            .find(|f| f.path == "src/fixture.rs")
            .unwrap()
            .bytes
            .clone(),
    )
    .unwrap();
    // disc_polar has the submission's body; nothing else of the submission is there.
    assert!(
        text.contains("    let r = u.x.powf(0.5); // the student's\n    V2::new(r, 0.0)\n}"),
        "{text}"
    );
    assert!(
        !text.contains("cbrt") && !text.contains("Helper") && !text.contains("42.0"),
        "{text}"
    );
    // The submission lost Table::lookup's markers: graded as its stub, with a note.
    assert!(
        text.contains("crate::exercise::todo(\"Table::lookup\")"),
        "{text}"
    );
    assert_eq!(notes.len(), 1, "{notes:?}");
    assert!(
        notes[0].contains("`Table::lookup`") && notes[0].contains("not started"),
        "{notes:?}"
    );
    // The rest of the file is the edition's, line for line.
    let m = marker::parse("src/fixture.rs", &text, &chapters()).unwrap();
    assert_eq!(m.len(), 2);
    assert!(
        text.starts_with("use super::V2;\n\n// ANCHOR: polar\n"),
        "{text}"
    );

    // A missing file grades every exercise in it as its stub, and says so.
    let empty = scratch("grade-missing");
    let sources = crate_with("// tests\n");
    let (files, notes) = grade::splice(sources, &exercises, &chapters(), &empty);
    let text = String::from_utf8_lossy(
        &files
            .iter()
            .find(|f| f.path == "src/fixture.rs")
            .unwrap()
            .bytes,
    )
    .into_owned();
    assert!(
        text.contains("todo(\"disc_polar\")") && text.contains("todo(\"Table::lookup\")"),
        "{text}"
    );
    assert!(
        notes.len() == 1
            && notes[0].contains("src/fixture.rs")
            && notes[0].contains("disc_polar, Table::lookup"),
        "{notes:?}"
    );
    let _ = fs::remove_dir_all(&dir);
    let _ = fs::remove_dir_all(&empty);
}

#[test]
fn a_weights_file_is_read_or_refused_with_its_line() {
    let exercises = edition::markers(&crate_with("")).unwrap();
    let w = grade::parse_weights(
        "default = 2\n[points]\ndisc_polar = 3.5\n",
        "w.toml",
        &exercises,
    )
    .unwrap();
    assert_eq!((w.of("disc_polar"), w.of("Table::lookup")), (3.5, 2.0));
    let w = grade::parse_weights("", "w.toml", &exercises).unwrap();
    assert_eq!(w, grade::Weights::default());
    for (text, line, words) in [
        (
            "[points]\n\ndisc_polr = 1\n",
            3,
            "no exercise is called `disc_polr`",
        ),
        (
            "[points]\ndisc_polar = -1\n",
            2,
            "must be a number of points >= 0",
        ),
        ("default = nan\n", 1, "not NaN"),
        ("default = 1\npoints = 3\n", 2, "invalid type"),
        ("defualt = 1\n", 1, "unknown field `defualt`"),
        ("[points\n", 1, "unclosed table"),
    ] {
        let e = grade::parse_weights(text, "w.toml", &exercises).unwrap_err();
        assert!(
            e.file == "w.toml" && e.line == line && e.problem.contains(words),
            "{text:?}: {e}"
        );
    }
}
