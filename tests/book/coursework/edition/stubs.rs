//! The stub writer: markers, docs and signature kept, the body returned.

use super::*;

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

/// In a file compiled twice (its types from `super::precision`, as the disc's), each stub
/// starts with the note that it is, so that a body written in `f64` types, which the
/// second build refuses with an error about `f32`, is explained where it is written; in
/// other files the stub is the one line. This crate's twin files are those of
/// `src/single.rs`.
#[test]
fn a_stub_in_a_file_compiled_twice_says_so() {
    let twin = FIXTURE.replace("use super::V2;", "use super::precision::{Float, V2};");
    let m = marker::parse("src/fixture.rs", &twin, &chapters()).unwrap();
    let (stubbed, _) = stub::stub_file(&twin, &m);
    let note = stub::twin_note("").join("\n");
    // Once per stub (the second is indented with its impl).
    assert_eq!(
        stubbed.matches("// This file is compiled twice").count(),
        2,
        "{stubbed}"
    );
    assert!(
        stubbed.contains(&format!(
            "{note}\n    crate::exercise::todo(\"disc_polar\")"
        )),
        "{stubbed}"
    );
    let plain_markers = marker::parse("src/fixture.rs", FIXTURE, &chapters()).unwrap();
    let (plain, _) = stub::stub_file(FIXTURE, &plain_markers);
    assert!(!plain.contains("compiled twice"), "{plain}");
    for file in [
        "src/geometry/ray.rs",
        "src/geometry/sphere.rs",
        "src/sampling/disc.rs",
        "src/sampling/trig.rs",
    ] {
        let text = std::fs::read_to_string(crate::support::root().join(file)).unwrap_or_default();
        assert!(
            stub::is_twin(&text),
            "{file} is compiled twice but not seen as a twin"
        );
    }
    let text = std::fs::read_to_string(crate::support::root().join("src/optics/fresnel.rs"))
        .unwrap_or_default();
    assert!(
        !stub::is_twin(&text) && !text.is_empty(),
        "fresnel.rs is compiled once"
    );
}
