//! The exercise markers of the source. Chapter: *Coursework* (`chapters/coursework.md`).
//!
//! A function a student is meant to write is wrapped in two comments:
//!
//! ```text
//! // EXERCISE sampling/disc disc_polar: map the unit square to the disc with r = sqrt(u1)
//! /// The polar map: ... (the doc comment states the task's math and stays in the hand-out)
//! pub fn disc_polar(u: V2) -> V3 {
//!     ... the solution: every line of the body is removed from the hand-out ...
//! }
//! // END EXERCISE
//! ```
//!
//! The opening line is `// EXERCISE CHAPTER NAME: TASK`: `CHAPTER` is a chapter of
//! `chapters/SUMMARY.md` without its `.md` (`sampling/disc`), `NAME` the exercise's name,
//! unique in the crate, whose last `::` segment is the function's name (`disc_polar`,
//! `Sellmeier::index`), and `TASK` one line saying what to write. Between the two markers
//! come doc comments and attributes, the signature (its last line ends with `{`, at the
//! indentation of the `fn` line) and the body, which ends with a `}` alone at that
//! indentation just before `// END EXERCISE`. That is rustfmt's layout of a function.

use crate::data::DataError;

/// The opening marker's prefix, after the line's indentation.
pub const OPEN: &str = "// EXERCISE ";
/// The closing marker, after the line's indentation.
pub const CLOSE: &str = "// END EXERCISE";

/// One marked exercise: where it is, what it asks, and the lines of its body.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Marker {
    /// The exercise's name, e.g. `disc_polar` or `Sellmeier::index`.
    pub name: String,
    /// The chapter, as in `chapters/SUMMARY.md` without `.md`: `sampling/disc`.
    pub chapter: String,
    /// The one-line statement of the task.
    pub task: String,
    /// The file, relative to the crate's root (`src/sampling/disc.rs`).
    pub file: String,
    /// The line of the `// EXERCISE` comment (1-based).
    pub line: usize,
    /// The line of the `fn` keyword.
    pub fn_line: usize,
    /// The last line of the signature (the one ending with `{`).
    pub signature_end: usize,
    /// The line of the body's closing `}`; the body is the lines strictly between
    /// `signature_end` and `close`.
    pub close: usize,
    /// The line of `// END EXERCISE`.
    pub end: usize,
    /// The indentation of the `fn` line.
    pub indent: String,
}

impl Marker {
    /// The function's name: the last `::` segment of the exercise's name.
    pub fn function(&self) -> &str {
        self.name.rsplit("::").next().unwrap_or(&self.name)
    }
}

/// True iff `line` is an exercise marker (opening or closing): the book builder leaves
/// these lines out of the code it shows.
pub fn is_marker_line(line: &str) -> bool {
    let t = line.trim_start();
    t.starts_with(OPEN) || t.trim_end() == CLOSE
}

/// The chapters of the book: every `(PATH.md)` link target of `chapters/SUMMARY.md`,
/// without `.md`, in the book's order.
pub fn chapters(summary: &str) -> Vec<String> {
    let mut out = Vec::new();
    for line in summary.lines() {
        let mut rest = line;
        while let Some(start) = rest.find("](") {
            let after = &rest[start + 2..];
            let Some(close) = after.find(')') else { break };
            if let Some(path) = after[..close].strip_suffix(".md") {
                out.push(path.to_string());
            }
            rest = &after[close..];
        }
    }
    out
}

/// A valid exercise name: one or more Rust identifiers joined by `::`.
fn valid_name(name: &str) -> bool {
    !name.is_empty()
        && name.split("::").all(|seg| {
            let mut chars = seg.chars();
            chars
                .next()
                .is_some_and(|c| c.is_ascii_alphabetic() || c == '_')
                && chars.all(|c| c.is_ascii_alphanumeric() || c == '_')
        })
}

/// `rest` split at its first `:` that is not part of a `::`.
fn split_task(rest: &str) -> Option<(&str, &str)> {
    let bytes = rest.as_bytes();
    let mut i = 0;
    while i < bytes.len() {
        if bytes[i] == b':' {
            if bytes.get(i + 1) == Some(&b':') {
                i += 2;
                continue;
            }
            return Some((&rest[..i], &rest[i + 1..]));
        }
        i += 1;
    }
    None
}

/// The leading spaces of `line`.
fn indentation(line: &str) -> &str {
    &line[..line.len() - line.trim_start_matches(' ').len()]
}

/// True iff `line` declares the function `name`: `fn name(` or `fn name<` outside a
/// comment.
fn declares(line: &str, name: &str) -> bool {
    let t = line.trim_start();
    if t.starts_with("//") {
        return false;
    }
    [format!("fn {name}("), format!("fn {name}<")]
        .iter()
        .any(|pattern| t.contains(pattern.as_str()))
}

/// The exercises marked in one source file `file` (its path relative to the crate's
/// root) with the text `text`, each chapter checked against `chapters`.
///
/// # Errors
/// A [`DataError`] naming the file and the line of the first malformed marker: an
/// opening line without `CHAPTER NAME: TASK`, an unknown chapter, a name that is not an
/// identifier, an exercise never closed (or closed after another opens), an
/// `END EXERCISE` with no exercise open, no `fn NAME` before the end, or a body that does
/// not end with `}` at the function's indentation.
pub fn parse(file: &str, text: &str, chapters: &[String]) -> Result<Vec<Marker>, DataError> {
    let lines: Vec<&str> = text.lines().collect();
    let mut out = Vec::new();
    let mut open: Option<(usize, String, String, String)> = None; // line, chapter, name, task
    for (i, raw) in lines.iter().enumerate() {
        let number = i + 1;
        let t = raw.trim();
        if let Some(rest) = raw.trim_start().strip_prefix(OPEN) {
            if let Some((line, _, name, _)) = &open {
                return Err(DataError::new(
                    file,
                    *line,
                    format!(
                        "exercise `{name}` is not closed: a new exercise opens on line {number} before its `{CLOSE}`"
                    ),
                ));
            }
            let form = "expected `// EXERCISE CHAPTER NAME: TASK`";
            let Some((head, task)) = split_task(rest) else {
                return Err(DataError::new(file, number, format!("{form}: no `:`")));
            };
            let mut words = head.split_whitespace();
            let (Some(chapter), Some(name), None) = (words.next(), words.next(), words.next())
            else {
                return Err(DataError::new(
                    file,
                    number,
                    format!("{form}: `{}` is not a chapter and a name", head.trim()),
                ));
            };
            let task = task.trim();
            if task.is_empty() {
                return Err(DataError::new(file, number, format!("{form}: no task")));
            }
            if !chapters.iter().any(|c| c == chapter) {
                return Err(DataError::new(
                    file,
                    number,
                    format!(
                        "unknown chapter `{chapter}` in the marker of `{name}`: not in chapters/SUMMARY.md"
                    ),
                ));
            }
            if !valid_name(name) {
                return Err(DataError::new(
                    file,
                    number,
                    format!("`{name}` is not an exercise name (identifiers joined by `::`)"),
                ));
            }
            open = Some((
                number,
                chapter.to_string(),
                name.to_string(),
                task.to_string(),
            ));
        } else if t == CLOSE {
            let Some((line, chapter, name, task)) = open.take() else {
                return Err(DataError::new(
                    file,
                    number,
                    format!("`{CLOSE}` with no exercise open"),
                ));
            };
            out.push(region(file, &lines, line, number, chapter, name, task)?);
        }
    }
    if let Some((line, _, name, _)) = open {
        return Err(DataError::new(
            file,
            line,
            format!("exercise `{name}` is not closed: no `{CLOSE}` before the end of the file"),
        ));
    }
    Ok(out)
}

/// The marker of the region from the opening line `line` to the closing line `end`.
fn region(
    file: &str,
    lines: &[&str],
    line: usize,
    end: usize,
    chapter: String,
    name: String,
    task: String,
) -> Result<Marker, DataError> {
    let function = name.rsplit("::").next().unwrap_or(&name).to_string();
    // Lines are 1-based: lines[k - 1] is line k.
    let Some(fn_line) = (line + 1..end).find(|&k| declares(lines[k - 1], &function)) else {
        return Err(DataError::new(
            file,
            line,
            format!("exercise `{name}`: no `fn {function}` between its marker and line {end}"),
        ));
    };
    let indent = indentation(lines[fn_line - 1]).to_string();
    let signature_end = (fn_line..end).find(|&k| {
        let l = lines[k - 1].trim_end();
        l.ends_with('{') && (k == fn_line || indentation(l) == indent)
    });
    let Some(signature_end) = signature_end else {
        return Err(DataError::new(
            file,
            fn_line,
            format!(
                "exercise `{name}`: the signature of `{function}` never opens its body with `{{`"
            ),
        ));
    };
    let close = (signature_end + 1..end)
        .rev()
        .find(|&k| !lines[k - 1].trim().is_empty());
    let closing = format!("{indent}}}");
    match close {
        Some(close) if lines[close - 1].trim_end() == closing => Ok(Marker {
            name,
            chapter,
            task,
            file: file.to_string(),
            line,
            fn_line,
            signature_end,
            close,
            end,
            indent,
        }),
        _ => Err(DataError::new(
            file,
            end,
            format!(
                "exercise `{name}`: the line before `{CLOSE}` must close the body of `{function}` with `}}` at its indentation"
            ),
        )),
    }
}

/// Checks that no two markers share a name.
///
/// # Errors
/// A [`DataError`] at the second marker of a name, naming the first.
pub(crate) fn check_unique(markers: &[Marker]) -> Result<(), DataError> {
    for (i, m) in markers.iter().enumerate() {
        if let Some(first) = markers[..i].iter().find(|f| f.name == m.name) {
            return Err(DataError::new(
                &m.file,
                m.line,
                format!(
                    "duplicate exercise name `{}`: already marked at {}:{}",
                    m.name, first.file, first.line
                ),
            ));
        }
    }
    Ok(())
}
