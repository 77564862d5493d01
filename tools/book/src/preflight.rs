//! Preflight check of the chapter sources, run before mdBook so that the book cannot drift
//! from the code it quotes: every `{{#include}}` / `{{#rustdoc_include}}` / `{{#playground}}`
//! target must exist (with its anchors), and every local image must exist in the built book
//! and have alt text saying what it shows (`![what it shows](path)`, `<img alt="...">`).
//!
//! Path conventions (mirroring what mdBook does):
//! - include paths are relative to the directory of the chapter file on disk;
//! - image paths are relative to the chapter's *page* in the built book. The book root holds the
//!   non-Markdown files of `chapters/` plus a copy of `<root>/figures/` as `figures/`, so a chapter
//!   at depth `d` below `chapters/` (`chapters/a.md`: 0, `chapters/geometry/b.md`: 1) writes
//!   `"../" * d + "figures/x.png"`.
//!
//! Each check is a module: [`includes`], [`images`], [`numbers`] (`{{#value}}` and
//! `{{#claim}}`), [`math`] (its delimiters), [`characters`] (no control characters) and [`rust_blocks`] (only compiled code is shown
//! as Rust); [`paths`] resolves paths lexically. This module walks the chapters and holds
//! the [`Checker`] they share.

mod characters;
mod images;
mod includes;
mod math;
mod numbers;
mod paths;
mod rust_blocks;
#[cfg(test)]
mod tests;

use std::collections::{HashMap, HashSet};
use std::fmt;
use std::fs;
use std::io;
use std::path::{Path, PathBuf};
use std::sync::LazyLock;

use raylemma_output::line_of;
use regex::Regex;

use crate::values;
use paths::normalize;

/// Same pattern as mdBook's `links` preprocessor (mdbook-driver 0.5, `find_links`).
static LINK: LazyLock<Regex> = LazyLock::new(|| {
    Regex::new(r"(?x)\\\{\{\#.*\}\}|\{\{\s*\#([a-zA-Z0-9_]+)\s+([^}]+)\}\}").expect("valid regex")
});

/// One problem found in a chapter, printed as `file:line: message`.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct Problem {
    /// Chapter file, relative to the project root.
    pub file: PathBuf,
    /// 1-based line number of the directive or image.
    pub line: usize,
    /// What is wrong.
    pub message: String,
}

impl fmt::Display for Problem {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(f, "{}:{}: {}", self.file.display(), self.line, self.message)
    }
}

/// Checks every `.md` file under `src_dir` (the book's `src`, normally `<root>/chapters`).
///
/// `root` is the project root: problems name files relative to it, and `<root>/figures/` is
/// where figures are copied from. Returns all problems found, sorted by file and line; an
/// `Err` only for I/O errors while walking `src_dir` itself.
pub fn check_chapters(root: &Path, src_dir: &Path) -> io::Result<Vec<Problem>> {
    let files: Vec<PathBuf> = raylemma_output::files_under(src_dir, &[""])
        .map_err(io::Error::other)?
        .into_iter()
        .filter(|p| p.extension().is_some_and(|e| e == "md"))
        .collect();
    let mut checker = Checker::new(root, src_dir);
    let mut problems = Vec::new();
    for file in &files {
        match fs::read_to_string(file) {
            Ok(text) => problems.extend(checker.check_chapter(file, &text)),
            Err(e) => problems.push(Problem {
                file: checker.display_path(file),
                line: 1,
                message: format!("cannot read chapter: {e}"),
            }),
        }
    }
    Ok(problems)
}

/// Scanner state: the two directories paths resolve against, and a cache of included files.
pub struct Checker {
    root: PathBuf,
    src_dir: PathBuf,
    /// Included file contents by normalised path; `Err` holds the read error text.
    cache: HashMap<PathBuf, Result<String, String>>,
    /// The named values `{{#value}}` and `{{#claim}}` read (`Err`: why they cannot be).
    values: Result<raylemma_values::Values, String>,
    /// The `.rs` files some crate of the project compiles (found on first use).
    compiled: Option<HashSet<PathBuf>>,
}

impl Checker {
    /// A checker for the book whose project root is `root` and chapter directory `src_dir`.
    pub fn new(root: &Path, src_dir: &Path) -> Self {
        Checker {
            root: normalize(root),
            src_dir: normalize(src_dir),
            cache: HashMap::new(),
            values: values::read(root),
            compiled: None,
        }
    }

    /// Checks one chapter file (`file` is its path on disk, `text` its contents).
    pub fn check_chapter(&mut self, file: &Path, text: &str) -> Vec<Problem> {
        let file = normalize(file);
        let mut problems = Vec::new();
        self.check_includes(&file, text, &mut problems);
        self.check_images(&file, text, &mut problems);
        self.check_numbers(&file, text, &mut problems);
        self.check_rust_blocks(&file, text, &mut problems);
        self.check_math_delimiters(&file, text, &mut problems);
        self.check_control_characters(&file, text, &mut problems);
        problems.sort_by_key(|p| p.line);
        problems
    }

    /// `path` relative to the project root if it lies inside it, else unchanged.
    fn display_path(&self, path: &Path) -> PathBuf {
        path.strip_prefix(&self.root)
            .map(Path::to_path_buf)
            .unwrap_or_else(|_| path.to_path_buf())
    }
}
