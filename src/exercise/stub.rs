//! The stub writer: a marked function's body replaced by a call that says which exercise
//! it is. Chapter: *Coursework* (`chapters/coursework.md`).
//!
//! ```text
//! // EXERCISE sampling/disc disc_polar: map the unit square to the disc with r = sqrt(u1)
//! /// The polar map: ...
//! #[allow(unused_variables)]
//! pub fn disc_polar(u: V2) -> V3 {
//!     crate::exercise::todo("disc_polar")
//! }
//! // END EXERCISE
//! ```
//!
//! The markers, doc comments, attributes and signature stay as they were; the body's lines
//! are returned as [`Removed`] lines, which the scrubber ([`super::scrub`]) then looks for
//! in every file of the hand-out. [`super::todo`] returns `!`, so the stub compiles
//! whatever the function returns, in both precisions of the dual files; the attribute
//! silences the warnings about the parameters the stub does not use.

use super::marker::Marker;

/// A line of a solution taken out of the hand-out.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Removed {
    /// The exercise it belongs to.
    pub exercise: String,
    /// The file it was in, relative to the crate's root.
    pub file: String,
    /// Its line in that file (1-based).
    pub line: usize,
    /// The line as written.
    pub text: String,
}

/// The stub's body line for the exercise `name` at the function's indentation `indent`.
pub(crate) fn stub_line(indent: &str, name: &str) -> String {
    format!("{indent}    crate::exercise::todo(\"{name}\")")
}

/// Whether `text` is a file compiled twice, for `f64` and for `f32` (its twin in
/// `src/single.rs`): it takes its types from the precision its parent module chose.
pub fn is_twin(text: &str) -> bool {
    text.contains("use super::precision::")
}

/// The first lines of a stub in a file compiled twice ([`is_twin`]): a body written with
/// `f64` types compiles for the first precision and fails for the second, in an error that
/// does not say why.
pub fn twin_note(indent: &str) -> Vec<String> {
    [
        "// This file is compiled twice: for f64, and for f32 as its twin in src/single.rs.",
        "// Write the body with Float, V2, V3 and consts::, not f64, DVec3 or std::f64: an",
        "// error that expects f32 (or names `single::`) is the f32 twin's.",
    ]
    .iter()
    .map(|line| format!("{indent}    {line}"))
    .collect()
}

/// `text` (the file of `markers`, which must all be in it) with every marked body
/// replaced by its stub, and the lines removed; in a file compiled twice, each stub starts
/// with [`twin_note`]. Line endings are kept as they were.
pub fn stub_file(text: &str, markers: &[Marker]) -> (String, Vec<Removed>) {
    let twin = is_twin(text);
    replace_bodies(text, markers, |m| {
        let stub = stub_line(&m.indent, &m.name);
        if twin {
            let mut lines = twin_note(&m.indent);
            lines.push(stub);
            lines
        } else {
            vec![stub]
        }
    })
}

/// `text` (the file of `markers`, which must all be in it) with every marked body
/// replaced by the lines `body` gives for its marker (the stub for the hand-out, a
/// submission's body for the grader, `super::grade`), and the lines removed. Everything
/// outside the bodies is kept as it was, line endings included; the `fn` line gets
/// `#[allow(unused_variables)]` (a stub uses none of its parameters).
pub(crate) fn replace_bodies(
    text: &str,
    markers: &[Marker],
    body: impl Fn(&Marker) -> Vec<String>,
) -> (String, Vec<Removed>) {
    let mut out = String::with_capacity(text.len());
    let mut removed = Vec::new();
    let put = |out: &mut String, m: &Marker, ending: &str| {
        for line in body(m) {
            out.push_str(&line);
            out.push_str(if ending.is_empty() { "\n" } else { ending });
        }
    };
    for (i, line) in text.split_inclusive('\n').enumerate() {
        let number = i + 1;
        let ending = if line.ends_with("\r\n") {
            "\r\n"
        } else if line.ends_with('\n') {
            "\n"
        } else {
            ""
        };
        let Some(m) = markers.iter().find(|m| m.line <= number && number <= m.end) else {
            out.push_str(line);
            continue;
        };
        if number == m.fn_line {
            out.push_str(&format!("{}#[allow(unused_variables)]{ending}", m.indent));
        }
        if number == m.close && m.close == m.signature_end + 1 {
            // An empty body: the new one still goes in.
            put(&mut out, m, ending);
        }
        if number <= m.signature_end || number >= m.close {
            out.push_str(line);
            continue;
        }
        if number == m.signature_end + 1 {
            put(&mut out, m, ending);
        }
        removed.push(Removed {
            exercise: m.name.clone(),
            file: m.file.clone(),
            line: number,
            text: line.trim_end_matches(['\n', '\r']).to_string(),
        });
    }
    (out, removed)
}
