//! Tests of the student edition (chapter *Coursework*, `src/exercise/`): the markers and
//! their errors (file and line), the stub writer, the scrubber's rule and its refusal of a
//! leaked solution line, the edition's manifest, `raylemma exercises` refusing a non-empty
//! folder and leaving nothing half-written, and this crate's own markers against the
//! report card's registry. The editions themselves are built and tested by CI
//! (`.ci/run`), not here.

use std::fs;
use std::path::Path;
use std::process::Command;

use raylemma::exercise::edition::{self, EditionError, File, Kind};
use raylemma::exercise::{grade, marker, not_started, registry, scrub, stub};

const SUMMARY: &str =
    "# Summary\n\n- [The disc](sampling/disc.md)\n- [Fresnel](optics/fresnel.md)\n";

fn chapters() -> Vec<String> {
    marker::chapters(SUMMARY)
}

/// A small source file with two exercises: a free function and a method.
const FIXTURE: &str = "\
use super::V2;

// ANCHOR: polar
// EXERCISE sampling/disc disc_polar: map the square to the disc
/// The polar map: `r = sqrt(u1)`.
pub fn disc_polar(u: V2) -> V2 {
    let s = u.y.cbrt();
    V2::new(s, 2.0 * s)
}
// END EXERCISE
// ANCHOR_END: polar

impl Table {
    // EXERCISE optics/fresnel Table::lookup: find the entry
    pub fn lookup(
        &self,
        key: f64,
    ) -> Option<f64> {
        self.entries.iter().find(|e| e.0 == key).map(|e| e.1)
    }
    // END EXERCISE
}
";

#[test]
fn markers_give_name_chapter_task_and_the_body_lines() {
    assert_eq!(chapters(), ["sampling/disc", "optics/fresnel"]);
    let m = marker::parse("src/fixture.rs", FIXTURE, &chapters()).unwrap();
    assert_eq!(m.len(), 2);
    assert_eq!(
        (
            m[0].name.as_str(),
            m[0].chapter.as_str(),
            m[0].task.as_str()
        ),
        ("disc_polar", "sampling/disc", "map the square to the disc")
    );
    assert_eq!(
        (
            m[0].line,
            m[0].fn_line,
            m[0].signature_end,
            m[0].close,
            m[0].end
        ),
        (4, 6, 6, 9, 10)
    );
    assert_eq!(
        (m[1].name.as_str(), m[1].function()),
        ("Table::lookup", "lookup")
    );
    assert_eq!((m[1].fn_line, m[1].signature_end, m[1].close), (15, 18, 20));
    assert_eq!(m[1].indent, "    ");
    assert!(
        marker::is_marker_line("    // EXERCISE a b: c")
            && marker::is_marker_line("// END EXERCISE")
    );
    assert!(!marker::is_marker_line("/// // EXERCISE in a doc comment"));
}

/// The error of parsing `text` (one file, `src/bad.rs`): its line and words.
fn error(text: &str) -> (usize, String) {
    let e = marker::parse("src/bad.rs", text, &chapters()).unwrap_err();
    assert_eq!(e.file, "src/bad.rs");
    (e.line, e.problem)
}

#[test]
fn malformed_markers_are_named_with_file_and_line() {
    let (line, why) = error("\n// EXERCISE sampling/disc f: task\npub fn f() {\n    1\n}\n");
    assert_eq!(line, 2);
    assert!(why.contains("`f` is not closed"), "{why}");
    let (line, why) =
        error("// EXERCISE sampling/disc f: task\nfn f() {\n}\n// EXERCISE sampling/disc g: t\n");
    assert_eq!(line, 1);
    assert!(
        why.contains("not closed") && why.contains("line 4"),
        "{why}"
    );
    let (line, why) =
        error("fn f() {}\n\n// EXERCISE sampling/disk f: task\nfn f() {\n}\n// END EXERCISE\n");
    assert_eq!(line, 3);
    assert!(
        why.contains("unknown chapter `sampling/disk`") && why.contains("SUMMARY.md"),
        "{why}"
    );
    let (line, why) = error("// END EXERCISE\n");
    assert_eq!(line, 1);
    assert!(why.contains("no exercise open"), "{why}");
    let (_, why) = error("// EXERCISE sampling/disc f task\n");
    assert!(why.contains("CHAPTER NAME: TASK"), "{why}");
    let (_, why) = error("// EXERCISE sampling/disc f:  \n");
    assert!(why.contains("no task"), "{why}");
    let (_, why) = error("// EXERCISE sampling/disc 2f: t\nfn f() {\n}\n// END EXERCISE\n");
    assert!(why.contains("not an exercise name"), "{why}");
    let (line, why) = error("// EXERCISE sampling/disc g: t\nfn f() {\n}\n// END EXERCISE\n");
    assert_eq!(line, 1);
    assert!(why.contains("no `fn g`"), "{why}");
    let (line, why) = error(
        "// EXERCISE sampling/disc f: t\nfn f() {\n    1\n}\nconst X: u8 = 1;\n// END EXERCISE\n",
    );
    assert_eq!(line, 6);
    assert!(why.contains("must close the body"), "{why}");
}

#[test]
fn a_duplicate_name_is_named_with_both_places() {
    let one = "// EXERCISE sampling/disc f: t\nfn f() {\n    1\n}\n// END EXERCISE\n";
    let files = vec![
        File {
            path: "chapters/SUMMARY.md".into(),
            bytes: SUMMARY.into(),
        },
        File {
            path: "src/a.rs".into(),
            bytes: one.into(),
        },
        File {
            path: "src/b.rs".into(),
            bytes: format!("\n\n{one}").into_bytes(),
        },
    ];
    let e = edition::markers(&files).unwrap_err();
    assert_eq!((e.file.as_str(), e.line), ("src/b.rs", 3));
    assert!(
        e.problem.contains("duplicate exercise name `f`") && e.problem.contains("src/a.rs:1"),
        "{e}"
    );
}

#[test]
fn the_stub_keeps_markers_docs_and_signature_and_returns_the_body() {
    let m = marker::parse("src/fixture.rs", FIXTURE, &chapters()).unwrap();
    let (stubbed, removed) = stub::stub_file(FIXTURE, &m);
    let want = "\
use super::V2;

// ANCHOR: polar
// EXERCISE sampling/disc disc_polar: map the square to the disc
/// The polar map: `r = sqrt(u1)`.
#[allow(unused_variables)]
pub fn disc_polar(u: V2) -> V2 {
    crate::exercise::todo(\"disc_polar\")
}
// END EXERCISE
// ANCHOR_END: polar

impl Table {
    // EXERCISE optics/fresnel Table::lookup: find the entry
    #[allow(unused_variables)]
    pub fn lookup(
        &self,
        key: f64,
    ) -> Option<f64> {
        crate::exercise::todo(\"Table::lookup\")
    }
    // END EXERCISE
}
";
    assert_eq!(stubbed, want);
    let lines: Vec<(&str, usize, &str)> = removed
        .iter()
        .map(|r| (r.exercise.as_str(), r.line, r.text.as_str()))
        .collect();
    assert_eq!(
        lines,
        [
            ("disc_polar", 7, "    let s = u.y.cbrt();"),
            ("disc_polar", 8, "    V2::new(s, 2.0 * s)"),
            (
                "Table::lookup",
                19,
                "        self.entries.iter().find(|e| e.0 == key).map(|e| e.1)"
            ),
        ]
    );
}

#[test]
fn a_stub_panics_with_a_message_the_card_recognises() {
    let payload = std::panic::catch_unwind(|| raylemma::exercise::todo("disc_polar")).unwrap_err();
    let message = raylemma::exercise::panic_message(payload.as_ref());
    assert!(
        message.starts_with("exercise `disc_polar` is not started"),
        "{message}"
    );
    assert!(
        message.contains("edition.rs:"),
        "the stub's place: {message}"
    );
    assert_eq!(not_started(&message), Some("disc_polar"));
    assert_eq!(not_started("index out of bounds"), None);
}

#[test]
fn the_trivial_rule_exempts_lines_that_name_less_than_two_things() {
    for line in [
        "}",
        "} else {",
        "None",
        "Some(t)",
        "0.0",
        "return V3::ZERO;",
        "Wavelengths {",
        "if cos2_t < 0.0 {",
        "return Refraction::TotalInternalReflection;",
        "Ok(())",
    ] {
        assert!(scrub::is_trivial(line), "{line}");
    }
    for line in [
        "let s = u.y.cbrt();",
        "let w = n.cross(t);",
        "self.entries.iter().find(|e| e.0 == key)",
    ] {
        assert!(!scrub::is_trivial(line), "{line}");
    }
    assert_eq!(
        scrub::fragments("    let x = \"a // b\"; // the comment"),
        ["let x = \"a // b\";", "the comment"]
    );
    assert_eq!(
        scrub::names("1.5e-3 * std::f64::consts::PI + x.y"),
        ["std::consts::PI", "x", "y"]
    );
}

/// A whole crate in memory: the fixture's source, a summary, a manifest and `test`.
fn crate_with(test: &str) -> Vec<File> {
    let manifest = "[package]\nname = \"raylemma\"\n\n[lib]\ntest = false\n\n[workspace]\nmembers = [\".\", \"tools/book\", \"tools/figures\"]\nexclude = [\"fuzz\"]\n\n[dev-dependencies]\napprox = \"0.5\"\ncriterion = \"0.8\"\n\n[[bench]]\nname = \"sphere\"\nharness = false\n\n[profile.test]\nopt-level = 2\n";
    vec![
        File {
            path: "Cargo.toml".into(),
            bytes: manifest.into(),
        },
        File {
            path: "chapters/SUMMARY.md".into(),
            bytes: SUMMARY.into(),
        },
        File {
            path: "src/fixture.rs".into(),
            bytes: FIXTURE.into(),
        },
        File {
            path: "tests/book/main.rs".into(),
            bytes: test.into(),
        },
    ]
}

#[test]
fn the_hand_out_is_refused_while_a_solution_line_is_anywhere_in_it() {
    let leak = "//! fixture\nfn independent() {\n    let s = u.y.cbrt();   // copied\n}\n";
    let Err(EditionError::Leaks(leaks)) = edition::make(crate_with(leak), Kind::HandOut) else {
        panic!("a leaked line was not refused");
    };
    assert_eq!(leaks.len(), 1);
    let text = leaks[0].to_string();
    assert!(
        text.starts_with("tests/book/main.rs:3: `let s = u.y.cbrt();`"),
        "{text}"
    );
    assert!(
        text.contains("exercise `disc_polar`, at src/fixture.rs:7"),
        "{text}"
    );
    // The solutions edition keeps the solutions, so it has nothing to refuse.
    assert!(edition::make(crate_with(leak), Kind::Solutions).is_ok());
    // Without the copy, the hand-out is made, and holds no line of either body.
    let e = edition::make(crate_with("//! fixture\n"), Kind::HandOut).unwrap();
    let fixture = e.files.iter().find(|f| f.path == "src/fixture.rs").unwrap();
    let text = String::from_utf8_lossy(&fixture.bytes);
    assert!(
        text.contains("crate::exercise::todo(\"disc_polar\")") && !text.contains("cbrt()"),
        "{text}"
    );
    assert_eq!(e.removed.len(), 3);
}

#[test]
fn the_edition_manifest_drops_the_benches_criterion_and_the_figure_job() {
    let e = edition::make(crate_with("//! fixture\n"), Kind::HandOut).unwrap();
    let names: Vec<&str> = e.files.iter().map(|f| f.path.as_str()).collect();
    assert_eq!(
        names,
        [
            ".gitignore",
            ".raylemma-edition",
            "Cargo.toml",
            "README.md",
            "chapters/SUMMARY.md",
            "src/fixture.rs",
            "tests/book/main.rs"
        ]
    );
    let manifest = String::from_utf8_lossy(&e.files[2].bytes).into_owned();
    assert!(
        !manifest.contains("[[bench]]")
            && !manifest.contains("criterion")
            && !manifest.contains("figures"),
        "{manifest}"
    );
    assert!(
        manifest.contains("members = [\".\"]")
            && manifest.contains("approx = \"0.5\"")
            && manifest.contains("opt-level = 2"),
        "{manifest}"
    );
    // A package name of its own (see `edition::manifest`), the library still `raylemma`.
    assert!(
        manifest.contains("[package]\nname = \"raylemma-hand-out\"")
            && manifest.contains("[lib]\nname = \"raylemma\"\ntest = false"),
        "{manifest}"
    );
    let readme = String::from_utf8_lossy(&e.files[3].bytes).into_owned();
    assert!(
        readme.contains("cargo test")
            && readme.contains(
                "| `Table::lookup` | optics/fresnel | `src/fixture.rs` | find the entry |"
            ),
        "{readme}"
    );
    assert!(readme.contains("the **hand-out**"), "{readme}");
}

fn scratch(name: &str) -> crate::support::Scratch {
    crate::support::scratch(&format!("exercises-{name}"))
}

/// Writes the fixture crate (with `test` as its test file) under `root`.
fn write_crate(root: &Path, test: &str) {
    for f in crate_with(test) {
        let path = root.join(&f.path);
        fs::create_dir_all(path.parent().unwrap()).unwrap();
        fs::write(path, f.bytes).unwrap();
    }
}

fn exercises(root: &Path, args: &[&str]) -> (Option<i32>, String) {
    let out = Command::new(env!("CARGO_BIN_EXE_raylemma"))
        .arg("exercises")
        .args(args)
        .arg("--root")
        .arg(root)
        .output()
        .expect("the binary runs");
    (
        out.status.code(),
        String::from_utf8_lossy(&out.stderr).into_owned(),
    )
}

/// The names in `dir`, sorted (hidden ones included).
fn names(dir: &Path) -> Vec<String> {
    let mut names: Vec<String> = fs::read_dir(dir)
        .unwrap()
        .map(|e| e.unwrap().file_name().into_string().unwrap())
        .collect();
    names.sort();
    names
}

#[test]
fn the_command_refuses_a_folder_in_use_and_leaves_nothing_half_written() {
    let base = scratch("cli");
    let root = base.join("crate");
    write_crate(&root, "//! fixture\n");
    let out = base.join("out");
    let out_s = out.to_str().unwrap();
    // A folder with something in it is refused, and left as it was.
    fs::create_dir_all(&out).unwrap();
    fs::write(out.join("notes.txt"), "mine").unwrap();
    let (code, err) = exercises(&root, &[out_s]);
    assert_eq!(code, Some(2), "{err}");
    assert!(
        err.contains("out") && err.contains("not empty") && err.contains("--overwrite"),
        "{err}"
    );
    assert_eq!(names(&out), ["notes.txt"]);
    // --overwrite does not replace a folder that is not an edition either.
    let (code, err) = exercises(&root, &[out_s, "--overwrite"]);
    assert_eq!(code, Some(2), "{err}");
    assert!(err.contains("not a raylemma edition"), "{err}");
    assert_eq!(names(&out), ["notes.txt"]);
    fs::remove_dir_all(&out).unwrap();
    // A malformed marker: named with its file and line, and nothing is written.
    let bad = FIXTURE.replace("// END EXERCISE\n}", "}");
    fs::write(root.join("src/fixture.rs"), &bad).unwrap();
    let (code, err) = exercises(&root, &[out_s]);
    assert_eq!(code, Some(2), "{err}");
    assert!(
        err.contains("src/fixture.rs:14: exercise `Table::lookup` is not closed"),
        "{err}"
    );
    assert_eq!(
        names(&base),
        ["crate"],
        "nothing beside the destination either"
    );
    // A leaked line: named, and nothing is written.
    fs::write(root.join("src/fixture.rs"), FIXTURE).unwrap();
    fs::write(root.join("tests/book/main.rs"), "// let s = u.y.cbrt();\n").unwrap();
    let (code, err) = exercises(&root, &[out_s]);
    assert_eq!(code, Some(1), "{err}");
    assert!(
        err.contains("tests/book/main.rs:1: `let s = u.y.cbrt();`")
            && err.contains("nothing was written"),
        "{err}"
    );
    assert_eq!(names(&base), ["crate"]);
    // A good crate: the whole edition lands, and --overwrite replaces it with the other.
    fs::write(root.join("tests/book/main.rs"), "//! fixture\n").unwrap();
    let (code, err) = exercises(&root, &[out_s]);
    assert_eq!(code, Some(0), "{err}");
    assert_eq!(
        names(&out),
        [
            ".gitignore",
            ".raylemma-edition",
            "Cargo.toml",
            "README.md",
            "chapters",
            "src",
            "tests"
        ]
    );
    assert!(
        fs::read_to_string(out.join("src/fixture.rs"))
            .unwrap()
            .contains("todo(\"disc_polar\")")
    );
    let (code, err) = exercises(&root, &[out_s, "--solutions"]);
    assert_eq!(
        code,
        Some(2),
        "an edition is not replaced without --overwrite: {err}"
    );
    let (code, err) = exercises(&root, &[out_s, "--solutions", "--overwrite"]);
    assert_eq!(code, Some(0), "{err}");
    assert!(
        fs::read_to_string(out.join("src/fixture.rs"))
            .unwrap()
            .contains("u.y.cbrt()")
    );
    assert_eq!(
        fs::read_to_string(out.join(".raylemma-edition")).unwrap(),
        "raylemma student edition: solutions\n"
    );
    assert_eq!(names(&base), ["crate", "out"]);
    // The crate itself, or a folder inside it, is never a destination.
    let inside = root.join("handout");
    let (code, err) = exercises(&root, &[inside.to_str().unwrap()]);
    assert_eq!(code, Some(2), "{err}");
    assert!(err.contains("inside it"), "{err}");
    let _ = fs::remove_dir_all(&base);
}

#[test]
fn every_marker_of_this_crate_is_well_formed_and_has_its_checks() {
    let root = crate::support::root();
    let markers = edition::markers_under(root).unwrap_or_else(|e| panic!("{e}"));
    let names: Vec<&str> = markers.iter().map(|m| m.name.as_str()).collect();
    for m in &markers {
        assert!(
            registry::find(&m.name).is_some(),
            "{}:{}: `{}` has no checks in src/exercise/registry.rs",
            m.file,
            m.line,
            m.name
        );
    }
    for e in registry::EXERCISES {
        assert!(
            names.contains(&e.name),
            "the registry checks `{}`, which no marker names",
            e.name
        );
        for n in e.needs {
            assert!(
                names.contains(n),
                "`{}` needs `{n}`, which is not an exercise",
                e.name
            );
        }
    }
    for later in registry::LATER {
        for n in later.needs {
            assert!(
                names.contains(n),
                "{} needs `{n}`, which is not an exercise",
                later.name
            );
        }
    }
    // At least one exercise in each chapter of a seed section.
    for chapter in [
        "geometry/sphere",
        "sampling/importance",
        "transport/lambert",
        "sampling/sphere",
        "sampling/disc",
        "sampling/cosine",
        "optics/specular",
        "transport/roulette",
        "optics/reflect",
        "optics/fresnel",
        "spectral/display",
        "transport/shadow",
        "sampling/tabulated",
        "optics/dispersion",
        "spectral/wavelength",
        "optics/thinfilm",
    ] {
        assert!(
            markers.iter().any(|m| m.chapter == chapter),
            "no exercise in {chapter}"
        );
    }
    assert_eq!(
        registry::unlocks("disc_concentric"),
        ["cosine_malley", "renderer", "cosine chapter"]
    );
    // Roulette's tests draw their bounces with hemisphere_flip (issue: the card did not say).
    assert!(registry::unlocks("hemisphere_flip").contains(&"roulette chapter"));
}

/// Every chapter ends with exercises, and every exercise of the hand-out is checked by a
/// command its chapter names.
#[test]
fn every_chapter_ends_with_exercises_that_name_their_command() {
    let root = crate::support::root();
    let summary = fs::read_to_string(root.join("chapters/SUMMARY.md")).unwrap();
    let markers = edition::markers_under(root).unwrap();
    for chapter in marker::chapters(&summary) {
        if ["introduction", "coursework"].contains(&chapter.as_str())
            || chapter.starts_with("appendix/")
        {
            continue;
        }
        let text = fs::read_to_string(root.join("chapters").join(format!("{chapter}.md"))).unwrap();
        let Some(at) = text.rfind("\n## Exercises\n") else {
            panic!("chapters/{chapter}.md has no `## Exercises` section");
        };
        let section = &text[at..];
        assert!(
            !section[14..].contains("\n## "),
            "chapters/{chapter}.md: the exercises are not its last section"
        );
        assert!(
            section.contains("cargo test --test book "),
            "chapters/{chapter}.md: its exercises name no command"
        );
        for m in markers.iter().filter(|m| m.chapter == chapter) {
            assert!(
                section.contains(&format!("`{}`", m.name)),
                "chapters/{chapter}.md: its exercises do not name `{}`",
                m.name
            );
        }
    }
}

/// The card judges an exercise whose checks do not return within the limit as failing,
/// naming the loop, and goes on: checks that sleep 5 s against a limit of 0.2 s fail
/// within 2 s. The twin returns at once with no verdicts: failing too, but not for time.
#[test]
fn an_exercise_that_does_not_return_fails_and_the_card_goes_on() {
    use raylemma::exercise::card::{Status, judge_within};
    use std::time::{Duration, Instant};
    fn sleeps() -> Vec<raylemma::check::Verdict> {
        std::thread::sleep(Duration::from_secs(5));
        Vec::new()
    }
    fn returns() -> Vec<raylemma::check::Verdict> {
        Vec::new()
    }
    let start = Instant::now();
    let status = judge_within("sleeps", sleeps, Duration::from_millis(200));
    assert!(
        start.elapsed() < Duration::from_secs(2),
        "{:?}",
        start.elapsed()
    );
    match status {
        Status::Failing(lines) => assert!(
            lines.len() == 1 && lines[0].contains("did not return within"),
            "{lines:?}"
        ),
        other => panic!("{other:?}"),
    }
    match judge_within("returns", returns, Duration::from_millis(200)) {
        Status::Failing(lines) => {
            assert!(
                lines.iter().all(|l| !l.contains("did not return")),
                "{lines:?}"
            )
        }
        other => panic!("{other:?}"),
    }
}

// ---------------------------------------------------------------------------------------
// Grading (`src/exercise/grade.rs`); `raylemma grade` itself is run by CI on five
// submissions (`.ci/editions`), since each builds a crate.

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
