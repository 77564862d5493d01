//! What a reference render was made from: the scene file, the data files it read, the
//! renderer's code and the settings. Chapter: *Reference scenes and
//! interop* (`chapters/renderer/scenes.md`, *Reference images*).
//!
//! The renders reproduce bit for bit, so a committed reference whose record matches what the
//! render would be made from now is current, and need not be rendered again: `cargo run
//! --release` renders only the references whose record differs, and says why
//! ([`MadeFrom::differences`]); CI checks that every committed record is current.
//!
//! The renderer's code is the *source closure* of `src/render/` ([`source_closure`]):
//! every library file it refers to (`crate::` and `super::` paths, and the module file of
//! each folder on the way), every data file compiled in (`include_str!`,
//! `include_bytes!`), and `Cargo.lock` (the dependencies' versions). Its version is a hash of those files with comments and blank
//! lines left out, so that editing documentation does not make a reference stale.

use std::collections::{BTreeSet, VecDeque};
use std::path::{Path, PathBuf};

use serde::{Deserialize, Serialize};

use super::raw::fnv1a;
use super::scene::{LightSampling, Scene};
use crate::output::FileError;

/// A file and the FNV-1a hash of its bytes.
#[derive(Clone, Debug, PartialEq, Eq, Serialize, Deserialize)]
pub struct FileHash {
    /// The path, relative to the project root, with `/` separators.
    pub file: String,
    /// FNV-1a (64 bits) of the file's bytes, in hexadecimal.
    pub fnv1a: String,
}

/// The settings of a render that change its pixels.
#[derive(Clone, Debug, PartialEq, Eq, Serialize, Deserialize)]
pub struct Settings {
    /// Samples per pixel.
    pub spp: u32,
    /// The seed.
    pub seed: u64,
    /// Width and height.
    pub resolution: [u32; 2],
    /// The wavelength strategy's name.
    pub wavelengths: String,
    /// The direct-lighting strategy (its debug form).
    pub direct: String,
    /// Russian roulette's first bounce.
    pub roulette_depth: u32,
    /// The bounce limit.
    pub max_depth: u32,
    /// How rectangular lights are sampled, when not by area (the default: absent, so that
    /// the sidecars of renders by area are unchanged).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub light_sampling: Option<String>,
}

/// Everything a render was made from.
#[derive(Clone, Debug, PartialEq, Eq, Serialize, Deserialize)]
pub struct MadeFrom {
    /// The scene file.
    pub scene: FileHash,
    /// The data files the scene read (spectrum tables), in the order read.
    pub data: Vec<FileHash>,
    /// The renderer's code version: the hash of its source closure.
    pub code: String,
    /// How many files the source closure has.
    pub code_files: usize,
    /// The settings.
    pub settings: Settings,
}

fn hex(h: u64) -> String {
    format!("{h:016x}")
}

/// `path` relative to `root`, with `/` separators and no `..` (the path itself if it is
/// not under it).
fn relative(root: &Path, path: &Path) -> String {
    let root = std::fs::canonicalize(root).unwrap_or_else(|_| root.to_path_buf());
    let path = std::fs::canonicalize(path).unwrap_or_else(|_| path.to_path_buf());
    slashed(path.strip_prefix(&root).unwrap_or(&path))
}

/// `p`'s parts joined by `/`, whatever the platform's separator.
fn slashed(p: &Path) -> String {
    p.components()
        .map(|c| c.as_os_str().to_string_lossy().into_owned())
        .collect::<Vec<_>>()
        .join("/")
}

/// `path`'s error `e` while reading it ("PATH: cannot read: ...").
fn cannot_read(path: &Path, e: std::io::Error) -> FileError {
    FileError::new(path, format!("cannot read: {e}"))
}

fn hash_file(root: &Path, path: &Path) -> Result<FileHash, FileError> {
    let bytes = std::fs::read(path).map_err(|e| cannot_read(path, e))?;
    Ok(FileHash {
        file: relative(root, path),
        fnv1a: hex(fnv1a(&bytes)),
    })
}

/// The text of a source file as the code version sees it: without blank lines, without
/// lines that are only a comment, without trailing spaces.
pub fn code_text(text: &str) -> String {
    text.lines()
        .map(str::trim_end)
        .filter(|l| {
            let t = l.trim_start();
            !t.is_empty() && !t.starts_with("//")
        })
        .collect::<Vec<_>>()
        .join("\n")
}

/// The module file of the path `segments` under `src`: the longest prefix that is a file
/// (`a/b.rs` or `a/b/mod.rs`).
fn module_file(src: &Path, segments: &[&str]) -> Option<PathBuf> {
    (1..=segments.len()).rev().find_map(|k| {
        let dir: PathBuf = segments[..k].iter().collect();
        [
            src.join(&dir).with_extension("rs"),
            src.join(&dir).join("mod.rs"),
        ]
        .into_iter()
        .find(|p| p.is_file())
    })
}

/// The module path of the file `file` under `src` (`src/a/b.rs` and `src/a/b/mod.rs` are
/// both `a::b`).
fn module_of(src: &Path, file: &Path) -> Vec<String> {
    let rel = file.strip_prefix(src).unwrap_or(file);
    let mut parts: Vec<String> = rel
        .components()
        .map(|c| c.as_os_str().to_string_lossy().into_owned())
        .collect();
    if let Some(last) = parts.pop() {
        match last.as_str() {
            "mod.rs" | "lib.rs" => {}
            other => parts.push(other.trim_end_matches(".rs").to_string()),
        }
    }
    parts
}

/// The identifiers after `prefix` in `text`, as module paths: for `crate::a::b::C` the
/// segments `[a, b, C]`.
fn paths_after<'t>(text: &'t str, prefix: &str) -> Vec<Vec<&'t str>> {
    let mut out = Vec::new();
    let mut rest = text;
    while let Some(i) = rest.find(prefix) {
        let tail = &rest[i + prefix.len()..];
        let mut segments = Vec::new();
        let mut t = tail;
        loop {
            let end = t
                .find(|c: char| !(c.is_alphanumeric() || c == '_'))
                .unwrap_or(t.len());
            if end == 0 {
                break;
            }
            segments.push(&t[..end]);
            t = &t[end..];
            match t.strip_prefix("::") {
                Some(next) => t = next,
                None => break,
            }
        }
        if !segments.is_empty() {
            out.push(segments);
        }
        rest = tail;
    }
    out
}

/// The string literal arguments of `macro!("...")` in `text`.
fn literal_arguments<'t>(text: &'t str, mac: &str) -> Vec<&'t str> {
    let needle = format!("{mac}!(\"");
    let mut out = Vec::new();
    let mut rest = text;
    while let Some(i) = rest.find(&needle) {
        let tail = &rest[i + needle.len()..];
        if let Some(end) = tail.find('"') {
            out.push(&tail[..end]);
        }
        rest = tail;
    }
    out
}

/// The source closure of the renderer under `root`: every file of `src/render/` that makes
/// a render's files (all but this one; the tools for other renderers are
/// `crate::conformance`, outside it), every library file they refer to, transitively, the
/// module file of every folder on the way,
/// the data files compiled in, and `Cargo.lock`. Sorted, relative to `root`.
///
/// # Errors
/// A [`FileError`] if a file cannot be read or a folder listed.
pub fn source_closure(root: &Path) -> Result<Vec<PathBuf>, FileError> {
    let src = root.join("src");
    let mut seen: BTreeSet<PathBuf> = BTreeSet::new();
    let mut queue: VecDeque<PathBuf> = VecDeque::new();
    let push = |p: PathBuf, seen: &mut BTreeSet<PathBuf>, queue: &mut VecDeque<PathBuf>| {
        if seen.insert(p.clone()) && p.extension().is_some_and(|e| e == "rs") {
            queue.push_back(p);
        }
    };
    for p in crate::output::files_under(&src, &["render"])? {
        let not_pixels = ["provenance.rs"]
            .iter()
            .any(|n| p.file_name().is_some_and(|f| f == *n));
        if p.extension().is_some_and(|x| x == "rs") && !not_pixels {
            push(p, &mut seen, &mut queue);
        }
    }
    while let Some(file) = queue.pop_front() {
        let text = std::fs::read_to_string(&file).map_err(|e| cannot_read(&file, e))?;
        let code = code_text(&text);
        // The folders' module files on the way to this one.
        let mut dir = file.parent().map(Path::to_path_buf);
        while let Some(d) = dir {
            if !d.starts_with(&src) || d == src {
                break;
            }
            let m = d.join("mod.rs");
            if m.is_file() {
                push(m, &mut seen, &mut queue);
            } else if d.with_extension("rs").is_file() {
                push(d.with_extension("rs"), &mut seen, &mut queue);
            }
            dir = d.parent().map(Path::to_path_buf);
        }
        for segments in paths_after(&code, "crate::") {
            if let Some(f) = module_file(&src, &segments) {
                push(f, &mut seen, &mut queue);
            }
        }
        // `super::` is the parent of this file's module.
        let here = module_of(&src, &file);
        let parent = &here[..here.len().saturating_sub(1)];
        for segments in paths_after(&code, "super::") {
            let full: Vec<&str> = parent.iter().map(String::as_str).chain(segments).collect();
            if let Some(f) = module_file(&src, &full) {
                push(f, &mut seen, &mut queue);
            }
        }
        // A folder's own children named by its `use` lines (`pub use ray::Ray;`) or by
        // `self::` paths.
        if file.file_name().is_some_and(|n| n == "mod.rs") {
            let mut names: Vec<&str> = paths_after(&code, "self::")
                .into_iter()
                .filter_map(|p| p.first().copied())
                .collect();
            for line in code.lines() {
                let t = line.trim();
                if let Some(u) = t
                    .strip_prefix("pub use ")
                    .or_else(|| t.strip_prefix("use "))
                {
                    names.extend(u.split(|c: char| !(c.is_alphanumeric() || c == '_')).next());
                }
            }
            for name in names {
                let full: Vec<&str> = here.iter().map(String::as_str).chain([name]).collect();
                if let Some(f) = module_file(&src, &full) {
                    push(f, &mut seen, &mut queue);
                }
            }
        }
        let base = file.parent().unwrap_or(&src).to_path_buf();
        for lit in literal_arguments(&code, "include_str")
            .into_iter()
            .chain(literal_arguments(&code, "include_bytes"))
        {
            let p = base.join(lit);
            let p = std::fs::canonicalize(&p).unwrap_or(p);
            push(p, &mut seen, &mut queue);
        }
    }
    let lock = root.join("Cargo.lock");
    if lock.is_file() {
        seen.insert(lock);
    }
    let root_abs = std::fs::canonicalize(root).unwrap_or_else(|_| root.to_path_buf());
    let mut files: Vec<PathBuf> = seen
        .into_iter()
        .map(|p| {
            let abs = std::fs::canonicalize(&p).unwrap_or(p);
            abs.strip_prefix(&root_abs)
                .map(Path::to_path_buf)
                .unwrap_or(abs)
        })
        .collect();
    files.sort();
    files.dedup();
    Ok(files)
}

/// The renderer's code version: FNV-1a over the source closure's files (path, then text
/// without comments and blank lines for source files, bytes for data), and its file count.
///
/// # Errors
/// A [`FileError`] if a file cannot be read.
pub fn code_version(root: &Path) -> Result<(String, usize), FileError> {
    let files = source_closure(root)?;
    let mut all = Vec::new();
    for f in &files {
        let path = root.join(f);
        // The path as the closure gives it (relative to the root, `/` between parts), so that
        // the version is the same wherever the project is cloned.
        all.extend_from_slice(slashed(f).as_bytes());
        all.push(0);
        if f.extension().is_some_and(|e| e == "rs") {
            let text = std::fs::read_to_string(&path).map_err(|e| cannot_read(&path, e))?;
            all.extend_from_slice(code_text(&text).as_bytes());
        } else {
            all.extend(std::fs::read(&path).map_err(|e| cannot_read(&path, e))?);
        }
        all.push(0);
    }
    Ok((hex(fnv1a(&all)), files.len()))
}

impl MadeFrom {
    /// What the render of `scene` (read from `scene_file`) at its settings is made from
    /// now, under the project root `root`, with the renderer's code version `code`
    /// ([`code_version`]).
    ///
    /// # Errors
    /// A [`FileError`] if the scene file or a data file cannot be read.
    pub fn of(
        root: &Path,
        scene_file: &Path,
        scene: &Scene,
        code: &(String, usize),
    ) -> Result<Self, FileError> {
        let s = &scene.settings;
        Ok(MadeFrom {
            scene: hash_file(root, scene_file)?,
            data: scene
                .files
                .iter()
                .map(|f| hash_file(root, f))
                .collect::<Result<_, _>>()?,
            code: code.0.clone(),
            code_files: code.1,
            settings: Settings {
                spp: s.spp,
                seed: s.seed,
                resolution: [scene.camera.width, scene.camera.height],
                wavelengths: s.wavelengths.name().to_string(),
                direct: format!("{:?}", s.direct),
                roulette_depth: s.roulette_depth,
                max_depth: s.max_depth,
                light_sampling: (s.light_sampling != LightSampling::Area)
                    .then(|| s.light_sampling.name().to_string()),
            },
        })
    }

    /// How `recorded` differs from `self` (what the render would be made from now), in
    /// words; empty when the recorded render is current.
    pub fn differences(&self, recorded: &MadeFrom) -> Vec<String> {
        let mut why = Vec::new();
        if self.scene != recorded.scene {
            why.push(format!("the scene file {} changed", self.scene.file));
        }
        if self.data != recorded.data {
            let changed: Vec<&str> = self
                .data
                .iter()
                .filter(|d| !recorded.data.contains(d))
                .map(|d| d.file.as_str())
                .collect();
            why.push(if changed.is_empty() {
                "the scene reads other data files".to_string()
            } else {
                format!("its data changed ({})", changed.join(", "))
            });
        }
        if self.code != recorded.code {
            why.push("the renderer's code changed".to_string());
        }
        if self.settings != recorded.settings {
            why.push(format!(
                "the settings changed (recorded {:?}, now {:?})",
                recorded.settings, self.settings
            ));
        }
        why
    }
}
