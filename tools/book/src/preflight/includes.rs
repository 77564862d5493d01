//! Includes: every `{{#include}}` / `{{#rustdoc_include}}` / `{{#playground}}` target exists,
//! with its anchors (matched as mdBook matches them).

use std::fs;
use std::io;
use std::path::Path;
use std::sync::LazyLock;

use regex::Regex;

use super::paths::normalize;
use super::{Checker, LINK, Problem, line_of};

/// Same anchor patterns as mdBook (`take_lines.rs`).
static ANCHOR_START: LazyLock<Regex> =
    LazyLock::new(|| Regex::new(r"ANCHOR:\s*(?P<name>[\w_-]+)").expect("valid regex"));
static ANCHOR_END: LazyLock<Regex> =
    LazyLock::new(|| Regex::new(r"ANCHOR_END:\s*(?P<name>[\w_-]+)").expect("valid regex"));

impl Checker {
    pub(super) fn check_includes(&mut self, file: &Path, text: &str, problems: &mut Vec<Problem>) {
        let dir = file.parent().unwrap_or(Path::new("")).to_path_buf();
        let shown_file = self.display_path(file);
        for cap in LINK.captures_iter(text) {
            let (Some(kind), Some(rest)) = (cap.get(1), cap.get(2)) else {
                continue; // escaped `\{{#...}}`
            };
            let kind = kind.as_str();
            if !matches!(
                kind,
                "include" | "rustdoc_include" | "playground" | "playpen"
            ) {
                continue;
            }
            let Some(arg) = rest.as_str().split_whitespace().next() else {
                continue;
            };
            let line = line_of(text, cap.get(0).map_or(0, |m| m.start()));
            let (path, selector) = match arg.split_once(':') {
                Some((p, s)) if kind != "playground" && kind != "playpen" => (p, Some(s)),
                _ => (arg, None),
            };
            let mut report = |message: String| {
                problems.push(Problem {
                    file: shown_file.clone(),
                    line,
                    message: format!("{kind} {arg}: {message}"),
                })
            };
            let target = normalize(&dir.join(path));
            let shown = self.display_path(&target);
            let contents = self.cache.entry(target.clone()).or_insert_with(|| {
                match fs::read_to_string(&target) {
                    Ok(s) => Ok(s),
                    Err(e) if e.kind() == io::ErrorKind::NotFound => Err("file not found".into()),
                    Err(e) => Err(format!("cannot read: {e}")),
                }
            });
            let contents = match contents {
                Ok(s) => s,
                Err(e) => {
                    report(format!("{e}: {}", shown.display()));
                    continue;
                }
            };
            if let Some(anchor) = selector.and_then(anchor_of)
                && let Err(e) = check_anchor(contents, anchor)
            {
                report(format!("{e} in {}", shown.display()));
            }
        }
    }
}

/// The anchor named by an include selector, or `None` for a line range (`10`, `3:7`, `:5`, ``).
/// Mirrors mdBook's `parse_range_or_anchor`.
fn anchor_of(selector: &str) -> Option<&str> {
    let first = selector.split(':').next().unwrap_or("");
    if first.is_empty() || first.parse::<usize>().is_ok() {
        None
    } else {
        Some(first)
    }
}

/// Checks that `contents` has a line with `ANCHOR: anchor` and, after it, `ANCHOR_END: anchor`
/// (matched the way mdBook matches them: first marker on each line, whole name).
fn check_anchor(contents: &str, anchor: &str) -> Result<(), String> {
    let mut start_line = None;
    for (i, line) in contents.lines().enumerate() {
        match start_line {
            None => {
                if ANCHOR_START
                    .captures(line)
                    .is_some_and(|c| &c["name"] == anchor)
                {
                    start_line = Some(i + 1);
                }
            }
            Some(_) => {
                if ANCHOR_END
                    .captures(line)
                    .is_some_and(|c| &c["name"] == anchor)
                {
                    return Ok(());
                }
            }
        }
    }
    match start_line {
        None => Err(format!("anchor '{anchor}' not found")),
        Some(l) => Err(format!(
            "anchor '{anchor}' (line {l}) has no 'ANCHOR_END: {anchor}' after it"
        )),
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn anchor_names_must_match_whole() {
        assert!(check_anchor("// ANCHOR: foobar\n// ANCHOR_END: foobar\n", "foo").is_err());
        assert!(check_anchor("// ANCHOR_END: foo\n// ANCHOR: foo\n", "foo").is_err());
        assert!(check_anchor("//ANCHOR:foo\n//ANCHOR_END:foo\n", "foo").is_ok());
    }

    #[test]
    fn selectors_distinguish_ranges_from_anchors() {
        assert_eq!(anchor_of("foo"), Some("foo"));
        assert_eq!(anchor_of("10"), None);
        assert_eq!(anchor_of("3:7"), None);
        assert_eq!(anchor_of(":5"), None);
        assert_eq!(anchor_of(""), None);
    }
}
