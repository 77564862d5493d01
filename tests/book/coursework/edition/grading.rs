//! Grading (`src/exercise/grade/`); `raylemma grade` itself is run by CI on eight
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

/// The fixture with the bodies of its two exercises replaced by `disc_polar_body` and
/// `lookup_body` (each a list of lines, at the function's indentation or not).
fn submitted_with(disc_polar_body: &str, lookup_body: &str) -> String {
    let text = FIXTURE
        .replace(
            "    let s = u.y.cbrt();\n    V2::new(s, 2.0 * s)\n",
            disc_polar_body,
        )
        .replace(
            "        self.entries.iter().find(|e| e.0 == key).map(|e| e.1)\n",
            lookup_body,
        );
    assert!(
        !text.contains("cbrt") && !text.contains("self.entries"),
        "{text}"
    );
    text
}

/// `submitted` (the fixture's file in a submission) spliced into the fixture crate: the
/// spliced file and the grader's notes.
fn graded(name: &str, submitted: &str) -> (String, Vec<String>) {
    let dir = scratch(name);
    fs::create_dir_all(dir.join("src")).unwrap();
    fs::write(dir.join("src/fixture.rs"), submitted).unwrap();
    let sources = crate_with("// tests\n");
    let exercises = edition::markers(&sources).unwrap();
    let (files, notes) = grade::splice(sources, &exercises, &chapters(), &dir);
    let _ = fs::remove_dir_all(&dir);
    let file = files.iter().find(|f| f.path == "src/fixture.rs").unwrap();
    (String::from_utf8(file.bytes.clone()).unwrap(), notes)
}

/// The escape of issue 40 (item 3), and two more: bodies that end outside their function
/// (a brace closed early, a comment opened) so that the code between two exercises, which
/// judges them, is hidden and replaced. Each is graded as its stub, with a note naming the
/// file, the line and the problem; the spliced file is the edition's, which tokenizes.
#[test]
fn a_body_that_ends_outside_its_function_is_graded_as_its_stub() {
    let cases = [
        (
            "escape-cfg",
            // The issue's: a brace closes disc_polar, a module compiled out swallows the
            // edition's code up to the next body, which closes it and redefines that code.
            "    V2::new(u.x, 0.0)\n}\n#[cfg(any())]\nmod hidden {\n    fn h() {\n",
            "        None\n    }\n    }\n}\nimpl Table {\n    pub fn helper() {}\n    fn f(&self) -> Option<f64> {\n",
            (8, 23),
        ),
        (
            "escape-comment",
            // A block comment opened in one body and closed in the next hides the code
            // between them.
            "    V2::new(u.x, 0.0) /*\n",
            "        */ None\n",
            (7, 0),
        ),
        (
            "escape-quote",
            // A quote in a character literal: a scanner that counts quotes thinks the
            // braces after it are in a string; the tokenizer does not.
            "    let _q = '\"';\n    V2::new(u.x, 0.0) } fn disc_pdf() { let _r = '\"';\n",
            "        Some(key)\n",
            (8, 0),
        ),
    ];
    for (name, polar, lookup, (polar_line, lookup_line)) in cases {
        let submitted = submitted_with(polar, lookup);
        let (text, notes) = graded(name, &submitted);
        assert!(
            text.contains("crate::exercise::todo(\"disc_polar\")"),
            "{name}: {text}"
        );
        assert_eq!(
            text.contains("crate::exercise::todo(\"Table::lookup\")"),
            lookup_line != 0,
            "{name}: {text}"
        );
        assert_eq!(
            notes.len(),
            1 + usize::from(lookup_line != 0),
            "{name}: {notes:?}"
        );
        assert!(
            notes[0].starts_with(&format!(
                "src/fixture.rs:{polar_line}: the body of `disc_polar` is refused"
            )) && notes[0].contains("do not balance")
                && notes[0].contains("not started"),
            "{name}: {notes:?}"
        );
        if lookup_line != 0 {
            assert!(
                notes[1].starts_with(&format!(
                    "src/fixture.rs:{lookup_line}: the body of `Table::lookup` is refused"
                )),
                "{name}: {notes:?}"
            );
        }
        assert!(
            text.parse::<proc_macro2::TokenStream>().is_ok(),
            "{name}: {text}"
        );
        assert_eq!(
            marker::parse("src/fixture.rs", &text, &chapters())
                .unwrap()
                .len(),
            2
        );
    }
}

/// A body whose brackets balance but that reaches outside the language's function body
/// (a file read in, a module, a macro, `unsafe`, `extern`, a marker line) is refused with
/// its line; one that only looks like it (the words in strings, comments, names) is not.
#[test]
fn a_body_that_reads_files_or_defines_modules_or_macros_is_refused() {
    let body = |lines: &[&str]| lines.iter().map(|l| l.to_string()).collect::<Vec<_>>();
    for (lines, line, words) in [
        (
            &[
                "    let x = 1;",
                "    include!(\"/solutions/src/optics/fresnel.rs\")",
            ][..],
            2,
            "reads a file",
        ),
        (
            &["    include_str!(\"../../src/exercise/registry.rs\").len()"][..],
            1,
            "reads a file",
        ),
        (
            &["    #[path = \"../x.rs\"]", "    mod x;", "    x::f()"][..],
            2,
            "declares a module",
        ),
        (
            &[
                "    #[macro_export]",
                "    macro_rules! disc_pdf { () => { 1.0 } }",
                "    0.0",
            ][..],
            2,
            "defines a macro",
        ),
        (
            &["    let p = &1.0 as *const f64;", "    unsafe { *p }"][..],
            2,
            "`unsafe`",
        ),
        (
            &["    unsafe extern \"C\" { fn exit(c: i32); }", "    0.0"][..],
            1,
            "`unsafe`",
        ),
        (
            &["    0.0", "    // END EXERCISE"][..],
            2,
            "an exercise marker",
        ),
    ] {
        let (at, why) = grade::refused(&body(lines)).unwrap_or_else(|| panic!("{lines:?}"));
        assert!(
            at == line && why.contains(words),
            "{lines:?}: line {at}: {why}"
        );
    }
    for lines in [
        &[
            "    let include = 1; // include!(\"x\") and mod y;",
            "    include + 1",
        ][..],
        &[
            "    let s = \"unsafe { } } {\";",
            "    let r = r#\"\"}\"#;",
            "    s.len() + r.len()",
        ][..],
        &[
            "    /* a comment with a } and /* a nested one */ */",
            "    let c = '}';",
            "    c",
        ][..],
        &[
            "    fn helper(x: f64) -> f64 {",
            "        x * x",
            "    }",
            "    helper(2.0)",
        ][..],
    ] {
        assert_eq!(grade::refused(&body(lines)), None, "{lines:?}");
    }
}

/// A body that names, as a path, a module reaching outside the computation is refused:
/// without this, a `disc_polar` that writes a card of its own with every exercise passing
/// to the file after the card's `--json` and calls `std::process::exit(0)` scores every
/// exercise (`tools/grade/cases.py`'s `exit`, graded in CI). The same words as a local
/// name, a field or in a string are not paths and stay allowed, and so does the stub.
#[test]
fn a_body_that_reaches_the_process_files_or_the_grader_is_refused() {
    let body = |lines: &[&str]| lines.iter().map(|l| l.to_string()).collect::<Vec<_>>();
    for (lines, line, word) in [
        (
            &[
                "    let args: Vec<String> = std::env::args().collect();",
                "    std::process::exit(0)",
            ][..],
            1,
            "`env`",
        ),
        (&["    std::process::exit(0)"][..], 1, "`process`"),
        (&["    ::std::process::abort()"][..], 1, "`process`"),
        (
            &[
                "    use std::fs;",
                "    fs::write(\"../card.json\", \"{}\").ok();",
                "    0.0",
            ][..],
            1,
            "`fs`",
        ),
        (
            &["    use std::{io, fs as files};", "    0.0"][..],
            1,
            "`fs`",
        ),
        (
            &["    let w = crate::output::write_file;", "    0.0"][..],
            1,
            "`output`",
        ),
        (
            &["    raylemma_output::write_file(p, b).ok();", "    0.0"][..],
            1,
            "`raylemma_output`",
        ),
        (
            &["    let t = std::thread::spawn(|| ());", "    0.0"][..],
            1,
            "`thread`",
        ),
        (
            &[
                "    if true {",
                "        let m = crate::exercise::edition::markers_under(\".\".as_ref());",
                "    }",
                "    0.0",
            ][..],
            2,
            "`exercise`",
        ),
    ] {
        let (at, why) = grade::refused(&body(lines)).unwrap_or_else(|| panic!("{lines:?}"));
        assert!(
            at == line && why.contains("it reaches") && why.contains(word),
            "{lines:?}: line {at}: {why}"
        );
    }
    for lines in [
        &[
            "    let output = 2.0 * x;",
            "    let env = output + 1.0;",
            "    env",
        ][..],
        &[
            "    let s = \"std::process::exit(0)\"; // std::fs::write",
            "    s.len()",
        ][..],
        &["    let p = Point { os: 1.0, fs: 2.0 };", "    p.os + p.fs"][..],
        &["    crate::exercise::todo(\"disc_polar\")"][..],
    ] {
        assert_eq!(grade::refused(&body(lines)), None, "{lines:?}");
    }
}
