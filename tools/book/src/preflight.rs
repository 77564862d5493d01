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

use std::collections::{HashMap, HashSet};
use std::fmt;
use std::fs;
use std::io;
use std::path::{Component, Path, PathBuf};
use std::sync::LazyLock;

use pulldown_cmark::{Event, Options, Parser, Tag, TagEnd};
use regex::Regex;

use crate::values;

/// Same pattern as mdBook's `links` preprocessor (mdbook-driver 0.5, `find_links`).
static LINK: LazyLock<Regex> = LazyLock::new(|| {
    Regex::new(r"(?x)\\\{\{\#.*\}\}|\{\{\s*\#([a-zA-Z0-9_]+)\s+([^}]+)\}\}").expect("valid regex")
});
/// Same anchor patterns as mdBook (`take_lines.rs`).
static ANCHOR_START: LazyLock<Regex> =
    LazyLock::new(|| Regex::new(r"ANCHOR:\s*(?P<name>[\w_-]+)").expect("valid regex"));
static ANCHOR_END: LazyLock<Regex> =
    LazyLock::new(|| Regex::new(r"ANCHOR_END:\s*(?P<name>[\w_-]+)").expect("valid regex"));
static IMG_SRC: LazyLock<Regex> = LazyLock::new(|| {
    Regex::new(r#"(?is)<img\b[^>]*?\bsrc\s*=\s*(?:"([^"]*)"|'([^']*)'|([^\s>]+))"#)
        .expect("valid regex")
});
static IMG_TAG: LazyLock<Regex> =
    LazyLock::new(|| Regex::new(r"(?is)<img\b[^>]*>").expect("valid regex"));
static IMG_ALT: LazyLock<Regex> = LazyLock::new(|| {
    Regex::new(r#"(?is)\balt\s*=\s*(?:"([^"]*)"|'([^']*)'|([^\s>]+))"#).expect("valid regex")
});
static SCHEME: LazyLock<Regex> =
    LazyLock::new(|| Regex::new(r"^[a-zA-Z][a-zA-Z0-9+.-]*:").expect("valid regex"));

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
    let mut files = Vec::new();
    collect_markdown(src_dir, &mut files)?;
    files.sort();
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

fn collect_markdown(dir: &Path, out: &mut Vec<PathBuf>) -> io::Result<()> {
    for entry in fs::read_dir(dir)? {
        let entry = entry?;
        let path = entry.path();
        if entry.file_type()?.is_dir() {
            collect_markdown(&path, out)?;
        } else if path.extension().is_some_and(|e| e == "md") {
            out.push(path);
        }
    }
    Ok(())
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
        problems.sort_by_key(|p| p.line);
        problems
    }

    fn check_includes(&mut self, file: &Path, text: &str, problems: &mut Vec<Problem>) {
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

    /// Every `{{#value}}` and `{{#claim}}` reads a table that exists, and every claim holds
    /// (a claim that fails on a quick-mode table is left to the preprocessor's warning).
    fn check_numbers(&mut self, file: &Path, text: &str, problems: &mut Vec<Problem>) {
        let values = match &self.values {
            Ok(v) => v,
            Err(e) => {
                problems.push(Problem {
                    file: self.display_path(file),
                    line: 1,
                    message: e.clone(),
                });
                return;
            }
        };
        let (_, findings) = values::expand(values, text);
        for f in findings.into_iter().filter(|f| !f.warning) {
            problems.push(Problem {
                file: self.display_path(file),
                line: f.line,
                message: f.message,
            });
        }
    }

    /// Math is written `$…$` or `$$…$$`, the only delimiters the book's KaTeX pass reads:
    /// `\\(…\\)` and a display `\\[` on its own reach the page as raw TeX. Fenced code and
    /// code spans are skipped; `\\[2pt]` inside an aligned formula is not a delimiter.
    fn check_math_delimiters(&self, file: &Path, text: &str, problems: &mut Vec<Problem>) {
        let mut fenced = false;
        for (i, line) in text.lines().enumerate() {
            let trimmed = line.trim_start();
            if trimmed.starts_with("```") || trimmed.starts_with("~~~") {
                fenced = !fenced;
                continue;
            }
            if fenced {
                continue;
            }
            let outside_code: String = line.split('`').step_by(2).collect::<Vec<_>>().join(" ");
            let display = trimmed
                .strip_prefix("\\\\[")
                .is_some_and(|rest| rest.trim().is_empty() || rest.starts_with(' '));
            if outside_code.contains("\\\\(") || display {
                problems.push(Problem {
                    file: self.display_path(file),
                    line: i + 1,
                    message: "math delimited by \\\\( \\\\) or \\\\[ \\\\]: write $…$ or $$…$$ \
                              (the only delimiters the KaTeX pass renders)"
                        .into(),
                });
            }
        }
    }

    /// Every `rust` code block only includes code, and only from files that a crate of the
    /// project compiles: Rust pasted into a chapter is compiled by nothing, so it is refused.
    fn check_rust_blocks(&mut self, file: &Path, text: &str, problems: &mut Vec<Problem>) {
        let dir = file.parent().unwrap_or(Path::new("")).to_path_buf();
        let mut block: Option<(usize, bool)> = None; // (line, is rust)
        for (i, line) in text.lines().enumerate() {
            let t = line.trim_start();
            if let Some(info) = t.strip_prefix("```") {
                block = match block {
                    None => Some((i + 1, info.trim_start().starts_with("rust"))),
                    Some(_) => None,
                };
                continue;
            }
            let Some((start, true)) = block else {
                continue;
            };
            if t.trim().is_empty() {
                continue;
            }
            let include = LINK.captures(t).filter(|c| {
                c.get(0)
                    .is_some_and(|m| m.start() == 0 && m.end() == t.trim_end().len())
                    && c.get(1)
                        .is_some_and(|k| matches!(k.as_str(), "include" | "rustdoc_include"))
            });
            let Some(cap) = include else {
                problems.push(Problem {
                    file: self.display_path(file),
                    line: i + 1,
                    message: format!(
                        "the rust block of line {start} holds pasted code, which nothing compiles: \
                         include it by anchor from a file of src/ or tests/"
                    ),
                });
                block = Some((start, false)); // once per block
                continue;
            };
            let arg = cap[2].split_whitespace().next().unwrap_or("");
            let path = arg.split_once(':').map_or(arg, |(p, _)| p);
            let target = normalize(&dir.join(path));
            if target.extension().is_some_and(|e| e == "rs") {
                let root = self.root.clone();
                let compiled = self.compiled.get_or_insert_with(|| compiled_files(&root));
                if !compiled.contains(&target) {
                    problems.push(Problem {
                        file: self.display_path(file),
                        line: i + 1,
                        message: format!(
                            "{} is shown as Rust but no crate of the project compiles it (no `mod` \
                             of a crate root reaches it)",
                            self.display_path(&target).display()
                        ),
                    });
                }
            }
        }
    }

    fn check_images(&self, file: &Path, text: &str, problems: &mut Vec<Problem>) {
        let mut opts = Options::empty();
        opts.insert(Options::ENABLE_TABLES);
        opts.insert(Options::ENABLE_FOOTNOTES);
        opts.insert(Options::ENABLE_STRIKETHROUGH);
        opts.insert(Options::ENABLE_TASKLISTS);
        opts.insert(Options::ENABLE_HEADING_ATTRIBUTES);
        // The image being read: its URL, where it starts, and its alt text so far.
        let mut image: Option<(String, usize, String)> = None;
        for (event, range) in Parser::new_ext(text, opts).into_offset_iter() {
            match event {
                Event::Start(Tag::Image { dest_url, .. }) => {
                    if let Some(message) = self.check_image(file, &dest_url) {
                        problems.push(Problem {
                            file: self.display_path(file),
                            line: line_of(text, range.start),
                            message: format!("image {dest_url}: {message}"),
                        });
                    }
                    image = Some((dest_url.to_string(), range.start, String::new()));
                }
                Event::Text(t) | Event::Code(t) if image.is_some() => {
                    if let Some((_, _, alt)) = image.as_mut() {
                        alt.push_str(&t);
                    }
                }
                Event::End(TagEnd::Image) => {
                    if let Some((url, start, alt)) = image.take()
                        && alt.trim().is_empty()
                    {
                        problems.push(Problem {
                            file: self.display_path(file),
                            line: line_of(text, start),
                            message: format!(
                                "image {url}: no alt text (write ![what it shows]({url}))"
                            ),
                        });
                    }
                }
                Event::Html(html) | Event::InlineHtml(html) => {
                    for tag in IMG_TAG.find_iter(&html) {
                        let alt = IMG_ALT
                            .captures(tag.as_str())
                            .and_then(|c| c.get(1).or(c.get(2)).or(c.get(3)))
                            .map_or("", |m| m.as_str());
                        if alt.trim().is_empty() {
                            let offset = range.start + tag.start();
                            problems.push(Problem {
                                file: self.display_path(file),
                                line: line_of(text, offset.min(text.len())),
                                message: "<img> without alt text (add alt=\"what it shows\")"
                                    .into(),
                            });
                        }
                    }
                    for cap in IMG_SRC.captures_iter(&html) {
                        let Some(src) = cap.get(1).or(cap.get(2)).or(cap.get(3)) else {
                            continue;
                        };
                        if let Some(message) = self.check_image(file, src.as_str()) {
                            let offset = range.start + html[..src.start()].len();
                            problems.push(Problem {
                                file: self.display_path(file),
                                line: line_of(text, offset.min(text.len())),
                                message: format!("image {}: {message}", src.as_str()),
                            });
                        }
                    }
                }
                _ => {}
            }
        }
    }

    /// Resolves an image link of the chapter `file` in the built book; `None` if it will load.
    fn check_image(&self, file: &Path, url: &str) -> Option<String> {
        if url.is_empty() || url.starts_with('#') || url.starts_with("//") || SCHEME.is_match(url) {
            return None; // remote (or not a file): not checked here
        }
        let path = percent_decode(url.split(['?', '#']).next().unwrap_or(""));
        if path.starts_with('/') {
            return Some("absolute path; use a path relative to the chapter page".into());
        }
        let chapter_dir = file
            .parent()
            .and_then(|d| d.strip_prefix(&self.src_dir).ok())
            .unwrap_or(Path::new(""));
        let depth = chapter_dir.components().count();
        let Some(in_book) = normalize_within(&chapter_dir.join(&path)) else {
            // Points above the book's root: a path valid on disk (e.g. ../../figures/x.png)
            // does not exist in the output. Suggest the right one if it is a figure.
            let on_disk = normalize(&file.parent().unwrap_or(Path::new("")).join(&path));
            let hint = on_disk
                .strip_prefix(self.root.join("figures"))
                .ok()
                .map(|rest| {
                    format!(
                        "; figures are copied to the book's root, so from this chapter write \
                         '{}figures/{}'",
                        "../".repeat(depth),
                        to_url(rest)
                    )
                })
                .unwrap_or_default();
            return Some(format!("points outside the built book{hint}"));
        };
        if self.src_dir.join(&in_book).is_file() {
            return None;
        }
        if let Ok(rest) = in_book.strip_prefix("figures")
            && self.root.join("figures").join(rest).is_file()
        {
            return None;
        }
        let looked = match in_book.strip_prefix("figures") {
            Ok(rest) => self.display_path(&self.root.join("figures").join(rest)),
            Err(_) => self.display_path(&self.src_dir.join(&in_book)),
        };
        Some(format!("not found: {}", looked.display()))
    }

    /// `path` relative to the project root if it lies inside it, else unchanged.
    fn display_path(&self, path: &Path) -> PathBuf {
        path.strip_prefix(&self.root)
            .map(Path::to_path_buf)
            .unwrap_or_else(|_| path.to_path_buf())
    }
}

/// The `.rs` files reached by `mod` declarations from the crate roots of the project under
/// `root`: the library and binaries (`src/lib.rs`, `src/main.rs`, `src/bin/`), the test,
/// bench and example targets, and the tools' crates (`tools/*/src/`). `#[path]` attributes
/// and inline modules (`mod a { mod b; }`) are followed; a module behind `cfg` counts.
fn compiled_files(root: &Path) -> HashSet<PathBuf> {
    let mut roots: Vec<PathBuf> = ["src/lib.rs", "src/main.rs"]
        .iter()
        .map(|r| root.join(r))
        .collect();
    let list = |dir: PathBuf| -> Vec<PathBuf> {
        fs::read_dir(dir)
            .map(|d| d.filter_map(|e| e.ok().map(|e| e.path())).collect())
            .unwrap_or_default()
    };
    for dir in ["src/bin", "tests", "benches", "examples"] {
        for p in list(root.join(dir)) {
            if p.extension().is_some_and(|e| e == "rs") {
                roots.push(p);
            } else if p.join("main.rs").is_file() {
                roots.push(p.join("main.rs"));
            }
        }
    }
    for tool in list(root.join("tools")) {
        for r in ["src/main.rs", "src/lib.rs"] {
            roots.push(tool.join(r));
        }
    }
    let mut seen = HashSet::new();
    let mut stack: Vec<(PathBuf, bool)> = roots
        .into_iter()
        .filter(|r| r.is_file())
        .map(|r| (normalize(&r), true))
        .collect();
    while let Some((file, owns_dir)) = stack.pop() {
        if !seen.insert(file.clone()) {
            continue;
        }
        let Ok(text) = fs::read_to_string(&file) else {
            continue;
        };
        let dir = file.parent().unwrap_or(Path::new("")).to_path_buf();
        // The directory of this file's child modules: its own for a root or mod.rs, else
        // the folder named after it.
        let children = if owns_dir || file.file_name().is_some_and(|n| n == "mod.rs") {
            dir.clone()
        } else {
            dir.join(file.file_stem().unwrap_or_default())
        };
        for (path, inline_dirs, name) in module_declarations(&text) {
            let target = match path {
                Some(p) if inline_dirs.is_empty() => dir.join(p),
                Some(p) => children.join(inline_dirs.join("/")).join(p),
                None => {
                    let base = children.join(inline_dirs.join("/"));
                    let flat = base.join(format!("{name}.rs"));
                    if flat.is_file() {
                        flat
                    } else {
                        base.join(&name).join("mod.rs")
                    }
                }
            };
            let owns = target.file_name().is_some_and(|n| n == "mod.rs");
            stack.push((normalize(&target), owns));
        }
    }
    seen
}

/// The out-of-line `mod name;` declarations of a Rust file: each with its `#[path]`, the
/// inline modules it sits in, and its name. Comments are skipped; strings are not parsed,
/// so a brace inside one could mislead it (none of the project's files has one that does).
fn module_declarations(text: &str) -> Vec<(Option<String>, Vec<String>, String)> {
    static MOD: LazyLock<Regex> = LazyLock::new(|| {
        Regex::new(r"^\s*(?:pub(?:\([^)]*\))?\s+)?mod\s+([A-Za-z_][A-Za-z0-9_]*)\s*([;{])")
            .expect("valid regex")
    });
    static PATH_ATTR: LazyLock<Regex> =
        LazyLock::new(|| Regex::new(r#"#\[path\s*=\s*"([^"]+)"\s*\]"#).expect("valid regex"));
    let mut out = Vec::new();
    let mut inline: Vec<(String, i64)> = Vec::new(); // (name, depth at which it opened)
    let mut depth: i64 = 0;
    let mut path: Option<String> = None;
    for raw in text.lines() {
        let line = raw.split("//").next().unwrap_or("");
        if let Some(c) = PATH_ATTR.captures(line) {
            path = Some(c[1].to_string());
        }
        if let Some(c) = MOD.captures(line) {
            let name = c[1].to_string();
            if &c[2] == ";" {
                let dirs = inline.iter().map(|(n, _)| n.clone()).collect();
                out.push((path.take(), dirs, name));
            } else {
                inline.push((name, depth));
                path = None;
            }
        } else if !line.trim().is_empty() && !line.trim_start().starts_with("#[") {
            path = None;
        }
        for ch in line.chars() {
            match ch {
                '{' => depth += 1,
                '}' => {
                    depth -= 1;
                    if inline.last().is_some_and(|(_, d)| *d == depth) {
                        inline.pop();
                    }
                }
                _ => {}
            }
        }
    }
    out
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

/// 1-based line number of byte `offset` in `text`.
fn line_of(text: &str, offset: usize) -> usize {
    text.as_bytes()[..offset.min(text.len())]
        .iter()
        .filter(|&&b| b == b'\n')
        .count()
        + 1
}

/// Lexically resolves `.` and `..` (no file system access, symlinks not followed).
fn normalize(path: &Path) -> PathBuf {
    let mut out = PathBuf::new();
    for c in path.components() {
        match c {
            Component::CurDir => {}
            Component::ParentDir => {
                if !out.pop() {
                    out.push("..");
                }
            }
            other => out.push(other),
        }
    }
    out
}

/// Like [`normalize`] for a relative path, but `None` if it climbs above its starting point.
fn normalize_within(path: &Path) -> Option<PathBuf> {
    let mut out = PathBuf::new();
    for c in path.components() {
        match c {
            Component::CurDir => {}
            Component::ParentDir => {
                if !out.pop() {
                    return None;
                }
            }
            Component::Normal(n) => out.push(n),
            Component::RootDir | Component::Prefix(_) => return None,
        }
    }
    Some(out)
}

fn to_url(path: &Path) -> String {
    path.components()
        .map(|c| c.as_os_str().to_string_lossy())
        .collect::<Vec<_>>()
        .join("/")
}

/// Decodes `%XX` escapes (invalid escapes are kept as they are).
fn percent_decode(s: &str) -> String {
    let bytes = s.as_bytes();
    let mut out = Vec::with_capacity(bytes.len());
    let mut i = 0;
    while i < bytes.len() {
        if bytes[i] == b'%'
            && let Some(Ok(b)) = s.get(i + 1..i + 3).map(|h| u8::from_str_radix(h, 16))
        {
            out.push(b);
            i += 3;
            continue;
        }
        out.push(bytes[i]);
        i += 1;
    }
    String::from_utf8_lossy(&out).into_owned()
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A throw-away project tree under the system temp dir, removed on drop.
    struct Tree(PathBuf);

    impl Tree {
        fn new(name: &str) -> Tree {
            let dir = std::env::temp_dir()
                .join(format!("raylemma-book-test-{}-{name}", std::process::id()));
            let _ = fs::remove_dir_all(&dir);
            fs::create_dir_all(&dir).unwrap();
            Tree(dir)
        }
        fn write(&self, rel: &str, contents: &str) {
            let p = self.0.join(rel);
            fs::create_dir_all(p.parent().unwrap()).unwrap();
            fs::write(p, contents).unwrap();
        }
        fn check(&self) -> Vec<String> {
            check_chapters(&self.0, &self.0.join("chapters"))
                .unwrap()
                .iter()
                .map(ToString::to_string)
                .collect()
        }
    }

    impl Drop for Tree {
        fn drop(&mut self) {
            let _ = fs::remove_dir_all(&self.0);
        }
    }

    const CODE: &str = "fn a() {}\n// ANCHOR: foo\nfn foo() {}\n// ANCHOR_END: foo\n\
                        // ANCHOR: open\nfn open() {}\n";

    #[test]
    fn valid_includes_and_images_pass() {
        let t = Tree::new("valid");
        t.write("src/lib.rs", "mod x;\n");
        t.write("src/x.rs", CODE);
        t.write("figures/plot.png", "png");
        t.write("chapters/local.png", "png");
        t.write(
            "chapters/geometry/sphere.md",
            "# Sphere\n\n```rust\n{{#include ../../src/x.rs:foo}}\n```\n\
             {{#rustdoc_include ../../src/x.rs:2:3}}\n{{#include ../../src/x.rs}}\n\
             ![plot](../figures/plot.png \"title\")\n![l](../local.png)\n\
             ![remote](https://example.com/x.png)\n<img alt=\"a plot\" src=\"../figures/plot.png\">\n\
             \\{{#include missing.rs}} is escaped\n",
        );
        t.write(
            "chapters/intro.md",
            "![p](figures/plot.png) {{ #include ../src/x.rs:foo }}",
        );
        assert_eq!(t.check(), Vec::<String>::new());
    }

    #[test]
    fn images_without_alt_text_are_reported() {
        let t = Tree::new("alt");
        t.write("figures/plot.svg", "<svg/>");
        t.write(
            "chapters/a.md",
            "![](figures/plot.svg)\n\n![ ](figures/plot.svg)\n\n![`code` alt](figures/plot.svg)\n\n\
             <img src=\"figures/plot.svg\">\n\n<img alt='' src=\"figures/plot.svg\">\n",
        );
        assert_eq!(
            t.check(),
            [
                "chapters/a.md:1: image figures/plot.svg: no alt text (write ![what it shows](figures/plot.svg))",
                "chapters/a.md:3: image figures/plot.svg: no alt text (write ![what it shows](figures/plot.svg))",
                "chapters/a.md:7: <img> without alt text (add alt=\"what it shows\")",
                "chapters/a.md:9: <img> without alt text (add alt=\"what it shows\")",
            ]
        );
    }

    #[test]
    fn missing_anchor_is_reported_with_file_and_line() {
        let t = Tree::new("anchor");
        t.write("src/x.rs", CODE);
        t.write(
            "chapters/geometry/sphere.md",
            "a\nb\n{{#include ../../src/x.rs:bar}}\n{{#rustdoc_include ../../src/x.rs:open}}\n",
        );
        assert_eq!(
            t.check(),
            vec![
                "chapters/geometry/sphere.md:3: include ../../src/x.rs:bar: \
                 anchor 'bar' not found in src/x.rs",
                "chapters/geometry/sphere.md:4: rustdoc_include ../../src/x.rs:open: \
                 anchor 'open' (line 5) has no 'ANCHOR_END: open' after it in src/x.rs",
            ]
        );
    }

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

    #[test]
    fn missing_files_and_images_are_all_collected() {
        let t = Tree::new("missing");
        t.write("figures/plot.png", "png");
        t.write(
            "chapters/geometry/sphere.md",
            "{{#include ../../src/nope.rs}}\n\n![a](../figures/none.png)\n\n\
             ![b](../../figures/plot.png)\n\n![c](/figures/plot.png)\n\n\
             {{#playground ../../examples/missing.rs editable}}\n",
        );
        t.write("chapters/a.md", "![x](y%20z.png)\n");
        assert_eq!(
            t.check(),
            vec![
                "chapters/a.md:1: image y%20z.png: not found: chapters/y z.png",
                "chapters/geometry/sphere.md:1: include ../../src/nope.rs: \
                 file not found: src/nope.rs",
                "chapters/geometry/sphere.md:3: image ../figures/none.png: \
                 not found: figures/none.png",
                "chapters/geometry/sphere.md:5: image ../../figures/plot.png: \
                 points outside the built book; figures are copied to the book's root, \
                 so from this chapter write '../figures/plot.png'",
                "chapters/geometry/sphere.md:7: image /figures/plot.png: \
                 absolute path; use a path relative to the chapter page",
                "chapters/geometry/sphere.md:9: playground ../../examples/missing.rs: \
                 file not found: examples/missing.rs",
            ]
        );
    }

    #[test]
    fn pasted_or_uncompiled_rust_is_refused() {
        let t = Tree::new("rust");
        t.write(
            "src/lib.rs",
            "pub mod a;\n#[cfg(test)]\nmod inline {\n    mod b;\n}\n",
        );
        t.write("src/a/mod.rs", "#[path = \"odd_name.rs\"]\nmod c;\n");
        t.write("src/a/odd_name.rs", CODE);
        t.write("src/inline/b.rs", CODE);
        t.write("src/orphan.rs", CODE);
        t.write("tests/book/main.rs", "mod part;\n");
        t.write("tests/book/part/mod.rs", "mod t;\n");
        t.write("tests/book/part/t.rs", CODE);
        t.write(
            "chapters/a.md",
            "```rust\n{{#include ../src/a/odd_name.rs:foo}}\n```\n\
             ```rust,ignore\n{{#include ../src/inline/b.rs:foo}}\n\n{{#include ../tests/book/part/t.rs}}\n```\n\
             ```rust\n{{#include ../src/orphan.rs:foo}}\n```\n\
             ```rust\nfn pasted() {}\nfn more() {}\n```\n\
             ```text\nfn not_rust() {}\n```\n",
        );
        assert_eq!(
            t.check(),
            vec![
                "chapters/a.md:10: src/orphan.rs is shown as Rust but no crate of the project \
                 compiles it (no `mod` of a crate root reaches it)",
                "chapters/a.md:13: the rust block of line 12 holds pasted code, which nothing \
                 compiles: include it by anchor from a file of src/ or tests/",
            ]
        );
    }

    #[test]
    fn math_in_other_delimiters_is_refused() {
        let t = Tree::new("math");
        t.write(
            "chapters/a.md",
            "An answer \\\\(y\\\\) is fine as $y$.\n\\\\[ e = 1 \\\\]\n\
             $$\n\\begin{aligned} a \\\\[2pt] b \\end{aligned}\n$$\n\
             `\\\\(` in code\n```text\n\\\\(x\\\\)\n```\n",
        );
        let found = t.check();
        assert_eq!(found.len(), 2, "{found:?}");
        assert!(
            found[0].starts_with("chapters/a.md:1: math delimited"),
            "{found:?}"
        );
        assert!(
            found[1].starts_with("chapters/a.md:2: math delimited"),
            "{found:?}"
        );
    }

    #[test]
    fn numbers_are_checked_against_what_the_figure_job_recorded() {
        let t = Tree::new("numbers");
        t.write(
            "figures/values.json",
            r#"{"t": {"file": "t.md", "values": {"x.b": {"shown": "1", "number": 1.0}},
                "claims": {"x_above_2": {"holds": false, "read": "1 > 2"}}}}"#,
        );
        t.write(
            "chapters/a.md",
            "x is {{#value t.x.b}}.\n\nIt is above 2{{#claim t.x_above_2}}.\n\n\
             {{#value t.y.b}}\n",
        );
        let problems = t.check();
        assert_eq!(problems.len(), 2, "{problems:?}");
        assert!(
            problems[0].starts_with("chapters/a.md:3: claim does not hold: t.x_above_2")
                && problems[0].contains("read: 1 > 2"),
            "{problems:?}"
        );
        assert!(
            problems[1].starts_with("chapters/a.md:5: {{#value t.y.b}}: no such name")
                && problems[1].contains("t.x.b"),
            "{problems:?}"
        );
    }

    #[test]
    fn line_numbers_are_one_based() {
        assert_eq!(line_of("abc", 0), 1);
        assert_eq!(line_of("a\nb\nc", 4), 3);
        assert_eq!(line_of("a\n", 99), 2);
    }

    #[test]
    fn paths_normalize_lexically() {
        assert_eq!(
            normalize(Path::new("/a/b/../c/./d")),
            PathBuf::from("/a/c/d")
        );
        assert_eq!(
            normalize_within(Path::new("geometry/../figures/x.png")),
            Some("figures/x.png".into())
        );
        assert_eq!(normalize_within(Path::new("geometry/../../x.png")), None);
        assert_eq!(percent_decode("a%20b%zz%2"), "a b%zz%2");
    }
}
