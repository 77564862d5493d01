//! Leaves the exercise markers out of the code the book shows.
//!
//! A function a student writes in the student edition is wrapped in
//! `// EXERCISE CHAPTER NAME: TASK` and `// END EXERCISE` (the library's
//! `src/exercise/marker.rs`); the chapters include that code by anchor, markers and all.
//! The markers are for the edition's tools and the student's editor, not for the reader:
//! this step removes those lines from every `rust` code block, and nothing else.

/// The opening marker's prefix and the closing marker, after the line's indentation (as
/// `src/exercise/marker.rs` defines them).
const OPEN: &str = "// EXERCISE ";
const CLOSE: &str = "// END EXERCISE";

/// True iff `line` is an exercise marker.
fn is_marker(line: &str) -> bool {
    let t = line.trim_start();
    t.starts_with(OPEN) || t.trim_end() == CLOSE
}

/// `text` with the marker lines removed from its fenced code blocks whose info string
/// starts with `rust`; prose and other blocks (a `text` block showing the syntax) are
/// left alone.
pub fn drop_exercise_markers(text: &str) -> String {
    let mut out = String::with_capacity(text.len());
    let mut in_rust: Option<bool> = None; // inside a block: is it rust?
    for line in text.split_inclusive('\n') {
        let t = line.trim_start();
        if let Some(info) = t.strip_prefix("```") {
            in_rust = match in_rust {
                None => Some(info.trim_start().starts_with("rust")),
                Some(_) => None,
            };
        } else if in_rust == Some(true) && is_marker(line) {
            continue;
        }
        out.push_str(line);
    }
    out
}

#[cfg(test)]
mod tests {
    use super::drop_exercise_markers;

    #[test]
    fn drops_markers_from_rust_blocks_only() {
        let text = "Prose // EXERCISE a b: c\n```rust,ignore\n    // EXERCISE sampling/disc disc_polar: map\n    /// Doc.\n    pub fn f() {\n        1\n    }\n    // END EXERCISE\n```\n```text\n// EXERCISE x y: shown as syntax\n// END EXERCISE\n```\n";
        let want = "Prose // EXERCISE a b: c\n```rust,ignore\n    /// Doc.\n    pub fn f() {\n        1\n    }\n```\n```text\n// EXERCISE x y: shown as syntax\n// END EXERCISE\n```\n";
        assert_eq!(drop_exercise_markers(text), want);
    }

    #[test]
    fn keeps_comments_that_only_mention_exercises() {
        let text = "```rust\n// EXERCISES are below\n/// // EXERCISE in a doc comment\nlet x = 1; // END EXERCISE\n```\n";
        assert_eq!(drop_exercise_markers(text), text);
    }
}
