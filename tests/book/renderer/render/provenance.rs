//! Provenance: the renderer's source closure, a code version that does not depend on where
//! the project lies, and a reference record that names what changed.

use super::*;

#[test]
fn the_renderer_source_closure_holds_what_makes_pixels_and_nothing_of_the_checks() {
    let root = crate::support::root();
    let files: Vec<String> = raylemma::render::provenance::source_closure(root)
        .unwrap_or_else(|e| panic!("{e}"))
        .iter()
        .map(|f| f.display().to_string())
        .collect();
    for needed in [
        "src/render/integrator.rs",
        "src/render/pixel.rs",
        "src/geometry/ray.rs",
        "src/optics/fresnel.rs",
        "src/sampling/cosine.rs",
        "src/sampling/disc.rs",
        "src/spectral/cie.rs",
        "src/transport/shadow.rs",
        "data/cie1931_2deg_cmf_1nm.csv",
        "data/sellmeier.csv",
        "Cargo.lock",
    ] {
        assert!(
            files.iter().any(|f| f == needed),
            "{needed} missing from {files:?}"
        );
    }
    for unrelated in [
        "src/check/",
        "src/conformance/",
        "src/spectral/upsample.rs",
        "src/stats/ks.rs",
    ] {
        assert!(
            !files.iter().any(|f| f.starts_with(unrelated)),
            "{unrelated} in {files:?}"
        );
    }
}

#[test]
fn the_code_version_is_the_same_wherever_the_project_lies() {
    // A fresh clone elsewhere must find the committed references current: the version
    // hashes the closure's files by their paths relative to the root, never absolute ones
    // (the test runs in the project folder either way; the version reads no other path).
    use raylemma::render::provenance::{code_version, source_closure};
    let root = crate::support::root();
    let here = code_version(root).unwrap_or_else(|e| panic!("{e}"));
    let elsewhere = crate::support::scratch("clone");
    for f in source_closure(root).unwrap_or_else(|e| panic!("{e}")) {
        let to = elsewhere.join(&f);
        std::fs::create_dir_all(to.parent().expect("a file has a folder"))
            .unwrap_or_else(|e| panic!("{e}"));
        std::fs::copy(root.join(&f), &to).unwrap_or_else(|e| panic!("{}: {e}", f.display()));
    }
    let there = code_version(&elsewhere).unwrap_or_else(|e| panic!("{e}"));
    let _ = std::fs::remove_dir_all(&elsewhere);
    assert_eq!(here, there);
}

/// Copies every file of `src/` and `data/` and `Cargo.lock` under `to`: all that
/// `code_version` may read.
fn copy_sources(root: &std::path::Path, to: &std::path::Path) {
    let files =
        raylemma::output::files_under(root, &["src", "data"]).unwrap_or_else(|e| panic!("{e}"));
    for f in files.iter().chain([&root.join("Cargo.lock")]) {
        let rel = f.strip_prefix(root).unwrap_or(f);
        let dest = to.join(rel);
        std::fs::create_dir_all(dest.parent().expect("a file has a folder"))
            .unwrap_or_else(|e| panic!("{e}"));
        std::fs::copy(f, &dest).unwrap_or_else(|e| panic!("{}: {e}", f.display()));
    }
}

/// Appends a line of code (not a comment: comments are not code) to `file` under `root`.
fn append_code(root: &std::path::Path, file: &str) {
    use std::io::Write as _;
    let mut f = std::fs::OpenOptions::new()
        .append(true)
        .open(root.join(file))
        .unwrap_or_else(|e| panic!("{file}: {e}"));
    writeln!(f, "pub const EDITED: u8 = 1;").unwrap_or_else(|e| panic!("{e}"));
}

#[test]
fn editing_the_tools_for_other_renderers_leaves_the_references_current() {
    // The references record the renderer's code version; the exporters, compare and the
    // conformance card (`src/conformance/`) read the renderer but make no pixel of it, so an
    // edit there must not make every reference stale. An edit of the renderer must.
    use raylemma::render::provenance::code_version;
    let root = crate::support::root();
    let copy = crate::support::scratch("tools-edit");
    copy_sources(root, &copy);
    let before = code_version(&copy).unwrap_or_else(|e| panic!("{e}"));
    assert_eq!(before, code_version(root).unwrap_or_else(|e| panic!("{e}")));
    for file in [
        "src/conformance/export/mitsuba.rs",
        "src/conformance/export/json.rs",
        "src/conformance/compare.rs",
        "src/conformance/mod.rs",
    ] {
        append_code(&copy, file);
        assert_eq!(
            code_version(&copy).unwrap_or_else(|e| panic!("{e}")),
            before,
            "an edit of {file} made the references stale"
        );
    }
    append_code(&copy, "src/render/camera.rs");
    assert_ne!(
        code_version(&copy).unwrap_or_else(|e| panic!("{e}")),
        before
    );
}

#[test]
fn a_reference_record_names_what_changed() {
    use raylemma::render::provenance::{MadeFrom, code_text, code_version};
    let root = crate::support::root();
    let file = root.join("scenes/cornell.toml");
    let scene = load("cornell.toml");
    let code = code_version(root).unwrap_or_else(|e| panic!("{e}"));
    let now = MadeFrom::of(root, &file, &scene, &code).unwrap_or_else(|e| panic!("{e}"));
    assert!(now.differences(&now).is_empty());
    assert!(
        now.data
            .iter()
            .any(|d| d.file == "data/cornell_box_reflectance.csv"),
        "{now:?}"
    );
    let mut old = now.clone();
    old.code = "0".into();
    old.settings.spp += 1;
    old.data[0].fnv1a = "0".into();
    let why = now.differences(&old).join("; ");
    assert!(
        why.contains("code") && why.contains("settings") && why.contains(&now.data[0].file),
        "{why}"
    );
    // Comments and blank lines are not code: documentation edits keep references current.
    assert_eq!(
        code_text("let a = 1; // one\n\n// note\nlet b = 2;  "),
        "let a = 1; // one\nlet b = 2;"
    );
}
