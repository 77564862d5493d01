//! What `raylemma exercises` writes: the edition's manifest (a workspace without the
//! benches and the figure job), and the command refusing a folder in use, leaving nothing half-written.

use super::*;

#[test]
fn the_edition_manifest_drops_the_benches_and_the_figure_job() {
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
        !manifest.contains("benches\"") && !manifest.contains("figures"),
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
        "raylemma student edition: solutions\ncommit: unknown\n",
        "the fixture is not a git clone: its commit is unknown"
    );
    assert_eq!(names(&base), ["crate", "out"]);
    // The crate itself, or a folder inside it, is never a destination.
    let inside = root.join("handout");
    let (code, err) = exercises(&root, &[inside.to_str().unwrap()]);
    assert_eq!(code, Some(2), "{err}");
    assert!(err.contains("inside it"), "{err}");
    let _ = fs::remove_dir_all(&base);
}

/// The edition's stamp records the commit it was made from, and the grader's note says
/// when its own code is another (the bodies are judged by the grader's checks).
#[test]
fn the_stamp_records_the_commit_and_the_grader_compares_it() {
    use raylemma::exercise::edition::{commit_of, stamped_commit};
    use raylemma::exercise::grade::commit_note;
    assert_eq!(
        stamped_commit("raylemma student edition: hand-out\ncommit: 4dc02fa\n"),
        Some("4dc02fa")
    );
    assert_eq!(
        stamped_commit("raylemma student edition: hand-out\ncommit: unknown\n"),
        None
    );
    assert_eq!(stamped_commit("raylemma student edition: hand-out\n"), None);
    assert_eq!(commit_note(Some("abc"), Some("abc")), None);
    for (stamped, ours, words) in [
        (
            Some("abc"),
            Some("def"),
            "made from commit abc; this grader's code is def",
        ),
        (Some("abc"), Some("abc-modified"), "git checkout abc"),
        (None, Some("def"), "records no commit"),
        (Some("abc"), None, "not a git clone"),
    ] {
        let note = commit_note(stamped, ours).unwrap_or_default();
        assert!(note.contains(words), "{stamped:?} {ours:?}: {note}");
    }
    // This repository is a clone (where git runs): its commit is a full hash.
    let root = crate::support::root();
    if let Some(c) = commit_of(root) {
        assert!(
            c.len() >= 40 && c[..40].chars().all(|x| x.is_ascii_hexdigit()),
            "{c}"
        );
    }
    let not_a_clone = std::env::temp_dir();
    assert_eq!(commit_of(&not_a_clone), None);
}

/// The hand-out's README tells the student where the renderer is once `cargo test` ran.
#[test]
fn the_readme_says_the_renderer_is_built_by_the_first_test() {
    let text = edition::readme(&[], Kind::HandOut);
    assert!(
        text.contains(
            "after your first `cargo test`, it is already built, as\n`target/debug/raylemma`"
        ),
        "{text}"
    );
}
