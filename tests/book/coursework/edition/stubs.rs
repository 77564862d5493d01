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
