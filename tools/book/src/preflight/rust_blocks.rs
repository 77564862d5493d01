//! Rust blocks: a `rust` code block only includes code, and only from files that a crate of
//! the project compiles, found by following `mod` declarations from the crate roots.

use std::collections::HashSet;
use std::fs;
use std::path::{Path, PathBuf};
use std::sync::LazyLock;

use regex::Regex;

use super::paths::normalize;
use super::{Checker, LINK, Problem};

impl Checker {
    /// Every `rust` code block only includes code, and only from files that a crate of the
    /// project compiles: Rust pasted into a chapter is compiled by nothing, so it is refused.
    pub(super) fn check_rust_blocks(
        &mut self,
        file: &Path,
        text: &str,
        problems: &mut Vec<Problem>,
    ) {
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
