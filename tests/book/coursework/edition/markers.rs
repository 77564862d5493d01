//! The markers and their errors, named with the file and line (both places for a duplicate
//! name).

use super::*;

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
