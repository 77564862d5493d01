//! Where a chapter teaches an exercise: the section whose text includes the exercise's
//! code. Chapter: *Coursework* (`chapters/coursework.md`).
//!
//! Every exercise's marker sits inside an anchor of its source file (`// ANCHOR: name` …
//! `// ANCHOR_END: name`), and its chapter shows that anchor with
//! `{{#include ../../FILE:name}}`. The section to reread is the heading above that include:
//! found from the files themselves, so it follows the chapter when a heading is renamed
//! or the code moves to another section.

use std::path::Path;

use super::marker::Marker;

/// A chapter's section: its heading and where it is.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Section {
    /// The heading's text, `The polar map`, its math in plain characters ([`readable`]):
    /// `The BRDF and its 1/π`, not `The BRDF and its $1/\pi$`.
    pub title: String,
    /// The chapter's file and the heading's id, `chapters/sampling/disc.md#the-polar-map`.
    pub link: String,
}

/// The TeX commands a heading's math uses, in plain characters.
const TEX: [(&str, &str); 24] = [
    ("pi", "π"),
    ("theta", "θ"),
    ("phi", "φ"),
    ("omega", "ω"),
    ("lambda", "λ"),
    ("rho", "ρ"),
    ("mu", "μ"),
    ("sigma", "σ"),
    ("alpha", "α"),
    ("beta", "β"),
    ("gamma", "γ"),
    ("delta", "δ"),
    ("eta", "η"),
    ("int", "∫"),
    ("sum", "Σ"),
    ("to", "→"),
    ("le", "≤"),
    ("ge", "≥"),
    ("cdot", "·"),
    ("times", "×"),
    ("infty", "∞"),
    ("propto", "∝"),
    ("approx", "≈"),
    ("sqrt", "√"),
];

/// A heading as a terminal shows it: its math (`$…$`) without the dollars and TeX, each
/// command above in its character (`\pi` π, `\to` →), `\bar y` as `ȳ`, other commands
/// as their names, braces and `\,` spacing dropped. `The BRDF and its $1/\pi$` is
/// `The BRDF and its 1/π`.
pub fn readable(heading: &str) -> String {
    let mut out = String::new();
    for (k, part) in heading.split('$').enumerate() {
        if k % 2 == 0 {
            out.push_str(part);
            continue;
        }
        let mut chars = part.chars().peekable();
        let mut bar = false;
        while let Some(c) = chars.next() {
            match c {
                '\\' => {
                    let mut name = String::new();
                    while let Some(&n) = chars.peek().filter(|n| n.is_ascii_alphabetic()) {
                        name.push(n);
                        chars.next();
                    }
                    if name.is_empty() {
                        chars.next(); // `\,`, `\;`: spacing
                    } else if name == "bar" {
                        bar = true;
                        while chars.peek().is_some_and(|n| *n == ' ' || *n == '{') {
                            chars.next();
                        }
                    } else if name != "text" && name != "mathrm" && name != "mathbf" {
                        match TEX.iter().find(|(t, _)| *t == name) {
                            Some((_, sym)) => out.push_str(sym),
                            None => out.push_str(&name),
                        }
                    }
                }
                '{' | '}' => {}
                _ => {
                    out.push(c);
                    if std::mem::take(&mut bar) {
                        out.push('\u{304}');
                    }
                }
            }
        }
    }
    out
}

/// The anchor of `source` that holds line `line` (1-based): the last `// ANCHOR: name`
/// before it whose `// ANCHOR_END: name` does not come before it.
pub fn anchor_at(source: &str, line: usize) -> Option<&str> {
    let mut open: Vec<&str> = Vec::new();
    for text in source.lines().take(line.saturating_sub(1)) {
        let t = text.trim();
        if let Some(name) = t.strip_prefix("// ANCHOR: ") {
            open.push(name.trim());
        } else if let Some(name) = t.strip_prefix("// ANCHOR_END: ") {
            open.retain(|n| *n != name.trim());
        }
    }
    open.last().copied()
}

/// The id mdBook gives a heading: its letters and digits in lower case, `-` and `_` kept,
/// each space a `-`, everything else dropped.
pub fn heading_id(title: &str) -> String {
    title
        .chars()
        .filter_map(|c| {
            if c.is_alphanumeric() || c == '_' || c == '-' {
                Some(c.to_ascii_lowercase())
            } else if c.is_whitespace() {
                Some('-')
            } else {
                None
            }
        })
        .collect()
}

/// The heading above the first line of `chapter` (a chapter's markdown) for which `hit`
/// holds, outside fenced code blocks and outside the chapter's section *Exercises* (which
/// names every exercise and teaches none).
fn heading_above(chapter: &str, hit: impl Fn(&str) -> bool) -> Option<&str> {
    let (mut heading, mut fenced) = (None, false);
    for line in chapter.lines() {
        let t = line.trim_start();
        if t.starts_with("```") {
            fenced = !fenced;
        } else if !fenced && t.starts_with('#') && t.trim_start_matches('#').starts_with(' ') {
            heading = Some(t.trim_start_matches('#').trim());
        }
        if heading != Some("Exercises") && hit(line) {
            return heading;
        }
    }
    None
}

/// The heading above the first line of `chapter` that includes `file:anchor`.
pub fn heading_above_include<'a>(chapter: &'a str, file: &str, anchor: &str) -> Option<&'a str> {
    let needle = format!("{file}:{anchor}}}}}");
    heading_above(chapter, |line| {
        line.contains("{{#include") && line.contains(&needle)
    })
}

/// The section of its chapter that teaches exercise `marker`, with the crate's files under
/// `root`: the one that shows its code, else the first that names it (`` `cosine_pdf` ``,
/// or the method's own name for `Sellmeier::index`), else the chapter's title; `None` only
/// if the files cannot be read.
pub fn of(root: &Path, marker: &Marker) -> Option<Section> {
    let source = std::fs::read_to_string(root.join(&marker.file)).ok()?;
    let chapter_file = format!("chapters/{}.md", marker.chapter);
    let chapter = std::fs::read_to_string(root.join(&chapter_file)).ok()?;
    let names = [
        format!("`{}`", marker.name),
        format!(
            "`{}",
            marker.name.rsplit("::").next().unwrap_or(&marker.name)
        ),
    ];
    let title = anchor_at(&source, marker.line)
        .and_then(|anchor| heading_above_include(&chapter, &marker.file, anchor))
        .or_else(|| heading_above(&chapter, |line| names.iter().any(|n| line.contains(n))))
        .or_else(|| heading_above(&chapter, |_| true))?;
    Some(Section {
        title: readable(title),
        link: format!("{chapter_file}#{}", heading_id(title)),
    })
}
