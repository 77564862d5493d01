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

mod grading;
mod markers;
mod reporting;
mod scrubbing;
mod stubs;
mod this_crate;
mod writing;

/// A whole crate in memory: the fixture's source, a summary, a manifest and `test`.
fn crate_with(test: &str) -> Vec<File> {
    let manifest = "[package]\nname = \"raylemma\"\nautobenches = false\n\n[lib]\ntest = false\n\n[workspace]\nmembers = [\".\", \"benches\", \"tools/book\", \"tools/figures\"]\nexclude = [\"fuzz\"]\n\n[dev-dependencies]\napprox = \"0.5\"\n\n[profile.test]\nopt-level = 2\n";
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

// A stub's panic is one the card recognises. Here, not in `stubs`: it asserts that the
// stub's place is this file (`edition.rs:`).
#[test]
fn a_stub_panics_with_a_message_the_card_recognises() {
    let payload =
        crate::report_card::deliberate(|| raylemma::exercise::todo("disc_polar")).unwrap_err();
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
