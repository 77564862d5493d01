//! The student edition: a self-contained crate made from this one, with the marked
//! solutions taken out (the hand-out) or left in (the solutions, for teachers and CI).
//! Chapter: *Coursework* (`chapters/coursework.md`); written by `raylemma exercises DIR`.
//!
//! What the edition ships ([`SHIPPED`]): the library, its tests, the chapters, the data,
//! scenes and figures the tests and chapters read, the book builder (`tools/book/`, built
//! only on demand), `book.toml` and `Cargo.lock`; and four files of its own: a
//! `Cargo.toml` (this one without the benches, criterion and the figure job), a
//! `README.md` with the two commands and the table of exercises, a `.gitignore` and
//! `.raylemma-edition` (what this folder is, so that `--overwrite` never replaces a folder
//! that is not an edition). It leaves out the figure job, the benches, the fuzzers, the
//! mutation and Mitsuba scripts and CI.
//!
//! The hand-out is refused, naming the file and line, if any line of a removed solution
//! is still in any file it ships ([`super::scrub`]).

use std::fs;
use std::path::{Path, PathBuf};

use super::marker::{self, Marker};
use super::scrub::{self, Leak};
use super::stub::{self, Removed};
use crate::data::DataError;
use crate::output::{FileError, StagedDir};

/// The files and folders of the crate the edition ships, relative to its root.
pub const SHIPPED: &[&str] = &[
    "src",
    "tests",
    "chapters",
    "data",
    "scenes",
    "figures",
    "tools/book",
    // What the chapters include or style themselves with, so that the edition's own book
    // builds: the programs of *Checks from any language*, the grader's example weights,
    // the book's style sheets.
    "tools/examples",
    "tools/grade/weights.toml",
    "assets/book",
    // The small crates the library and its tests depend on by path.
    "tools/output",
    "tools/values",
    "book.toml",
    "Cargo.lock",
    "Cargo.toml", // not shipped as it is: the edition's is made from it by `manifest`
];

/// What the hand-out leaves out of [`SHIPPED`]: the typical mistakes' twins and the
/// correct alternatives (each is an answer, or one with one thing changed) and their tests,
/// all behind the `twins` feature, which the hand-out's manifest turns off
/// ([`manifest`]). The hand-out keeps what the card needs to name a mistake
/// (`src/exercise/mistakes/known.rs`).
pub const TEACHERS_ONLY: &[&str] = &[
    "src/exercise/mistakes/twins/",
    "tests/book/coursework/mistakes.rs",
];

/// The file that says a folder is an edition (and which).
pub const STAMP: &str = ".raylemma-edition";

/// Which edition.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Kind {
    /// Every marked body replaced by its stub.
    HandOut,
    /// The solutions in place.
    Solutions,
    /// A submission's exercise bodies in the edition's own code (`super::grade::splice`).
    Graded,
}

impl Kind {
    /// `hand-out` or `solutions`.
    pub fn name(self) -> &'static str {
        match self {
            Kind::HandOut => "hand-out",
            Kind::Solutions => "solutions",
            Kind::Graded => "graded",
        }
    }
}

/// One file: its path relative to the root (with `/`) and its bytes.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct File {
    /// The path relative to the root, `/`-separated.
    pub path: String,
    /// The contents.
    pub bytes: Vec<u8>,
}

/// A made edition, in memory.
#[derive(Clone, Debug)]
pub struct Edition {
    /// Which edition.
    pub kind: Kind,
    /// Every file, sorted by path.
    pub files: Vec<File>,
    /// The exercises, in the book's order.
    pub exercises: Vec<Marker>,
    /// The lines taken out (none for the solutions).
    pub removed: Vec<Removed>,
}

/// Why an edition could not be made or written.
#[derive(Clone, Debug, PartialEq)]
pub enum EditionError {
    /// A malformed marker: its file, line and problem.
    Marker(DataError),
    /// Lines of removed solutions that the hand-out would still contain.
    Leaks(Vec<Leak>),
    /// A file that could not be read or written.
    File(FileError),
    /// The destination was refused (not empty, not an edition, inside the crate).
    Refused(FileError),
}

impl std::fmt::Display for EditionError {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        match self {
            EditionError::Marker(e) => write!(f, "malformed exercise marker: {e}"),
            EditionError::Leaks(leaks) => {
                write!(
                    f,
                    "{} line(s) of removed solutions would be in the hand-out; nothing was written:",
                    leaks.len()
                )?;
                for leak in leaks {
                    write!(f, "\n  {leak}")?;
                }
                Ok(())
            }
            EditionError::File(e) | EditionError::Refused(e) => write!(f, "{e}"),
        }
    }
}

impl std::error::Error for EditionError {}

impl From<FileError> for EditionError {
    fn from(e: FileError) -> Self {
        EditionError::File(e)
    }
}

impl From<DataError> for EditionError {
    fn from(e: DataError) -> Self {
        EditionError::Marker(e)
    }
}

/// Every file under `root` of [`SHIPPED`], sorted by path. Hidden entries and folders
/// named `target` are skipped; a missing entry of the list is skipped too (a small crate
/// need not have figures).
///
/// # Errors
/// A [`FileError`] for a file or folder that cannot be read.
pub fn read_sources(root: &Path) -> Result<Vec<File>, FileError> {
    let mut out = Vec::new();
    for entry in SHIPPED {
        let path = root.join(entry);
        if fs::symlink_metadata(&path).is_ok() {
            collect(root, &path, &mut out)?;
        }
    }
    out.sort_by(|a, b| a.path.cmp(&b.path));
    Ok(out)
}

fn collect(root: &Path, path: &Path, out: &mut Vec<File>) -> Result<(), FileError> {
    let meta = fs::metadata(path).map_err(|e| FileError::new(path, format!("cannot read: {e}")))?;
    if meta.is_dir() {
        let entries =
            fs::read_dir(path).map_err(|e| FileError::new(path, format!("cannot list: {e}")))?;
        for entry in entries {
            let entry = entry.map_err(|e| FileError::new(path, format!("cannot list: {e}")))?;
            let name = entry.file_name();
            let name = name.to_string_lossy();
            if name.starts_with('.') || name == "target" {
                continue;
            }
            collect(root, &entry.path(), out)?;
        }
        return Ok(());
    }
    let bytes = fs::read(path).map_err(|e| FileError::new(path, format!("cannot read: {e}")))?;
    let relative = path.strip_prefix(root).unwrap_or(path);
    let path = relative
        .components()
        .map(|c| c.as_os_str().to_string_lossy())
        .collect::<Vec<_>>()
        .join("/");
    out.push(File { path, bytes });
    Ok(())
}

/// The text of `path` among `files`, if it is there and UTF-8.
fn text_of<'a>(files: &'a [File], path: &str) -> Option<&'a str> {
    files
        .iter()
        .find(|f| f.path == path)
        .and_then(|f| std::str::from_utf8(&f.bytes).ok())
}

/// Every marker of the `.rs` files under `src/`, in the book's order (the chapters' order
/// in `chapters/SUMMARY.md`, then file and line), with no name twice.
///
/// # Errors
/// A [`DataError`] naming the file and line of the first malformed marker, or
/// `chapters/SUMMARY.md` if it is missing.
pub fn markers(files: &[File]) -> Result<Vec<Marker>, DataError> {
    let summary = text_of(files, "chapters/SUMMARY.md").ok_or_else(|| {
        DataError::new(
            "chapters/SUMMARY.md",
            0,
            "missing: the markers' chapters are checked against it",
        )
    })?;
    let chapters = marker::chapters(summary);
    let mut all = Vec::new();
    for f in files {
        if f.path.starts_with("src/") && f.path.ends_with(".rs") {
            let text = std::str::from_utf8(&f.bytes)
                .map_err(|_| DataError::new(&f.path, 0, "not UTF-8"))?;
            all.extend(marker::parse(&f.path, text, &chapters)?);
        }
    }
    all.sort_by_key(|m| {
        let chapter = chapters.iter().position(|c| *c == m.chapter);
        (chapter, m.file.clone(), m.line)
    });
    marker::check_unique(&all)?;
    Ok(all)
}

/// The markers among `exercises` that are in the file `path`.
pub(crate) fn markers_of(exercises: &[Marker], path: &str) -> Vec<Marker> {
    exercises
        .iter()
        .filter(|m| m.file == path)
        .cloned()
        .collect()
}

/// The markers of the crate at `root`, read from `src/` and `chapters/SUMMARY.md` alone
/// (what the report card needs).
///
/// # Errors
/// A [`DataError`] for a file that cannot be read or a malformed marker.
pub fn markers_under(root: &Path) -> Result<Vec<Marker>, DataError> {
    let mut files = Vec::new();
    for part in ["src", "chapters/SUMMARY.md"] {
        collect(root, &root.join(part), &mut files)
            .map_err(|e| DataError::new(&e.path.display().to_string(), 0, e.problem))?;
    }
    markers(&files)
}

/// Makes the edition `kind` from the crate's files `sources` (as [`read_sources`] reads
/// them).
///
/// # Errors
/// [`EditionError::Marker`] for a malformed marker; [`EditionError::Leaks`] if a line of
/// a removed solution is in a file the hand-out would ship.
pub fn make(sources: Vec<File>, kind: Kind) -> Result<Edition, EditionError> {
    let exercises = markers(&sources)?;
    let mut files = Vec::with_capacity(sources.len() + 4);
    let mut removed = Vec::new();
    let (originals, sources): (Vec<File>, Vec<File>) = sources
        .into_iter()
        .partition(|f| f.path == "Cargo.toml" || f.path == "README.md");
    for mut file in sources {
        if kind == Kind::HandOut && TEACHERS_ONLY.iter().any(|t| file.path.starts_with(t)) {
            continue;
        }
        let mine = markers_of(exercises.as_slice(), &file.path);
        if kind == Kind::HandOut && !mine.is_empty() {
            let text = String::from_utf8_lossy(&file.bytes).into_owned();
            let (stubbed, lines) = stub::stub_file(&text, &mine);
            file.bytes = stubbed.into_bytes();
            removed.extend(lines);
        }
        files.push(file);
    }
    let with_book = text_of(&files, "tools/book/Cargo.toml").is_some();
    let manifest = manifest(
        text_of(&originals, "Cargo.toml").unwrap_or(""),
        with_book,
        kind,
    );
    let generated = [
        ("Cargo.toml", manifest),
        ("README.md", readme(&exercises, kind)),
        (
            ".gitignore",
            "/target\n/warp-failures\n/results\n".to_string(),
        ),
        (
            STAMP,
            format!("raylemma student edition: {}\n", kind.name()),
        ),
    ];
    for (path, text) in generated {
        files.push(File {
            path: path.to_string(),
            bytes: text.into_bytes(),
        });
    }
    files.sort_by(|a, b| a.path.cmp(&b.path));
    if kind == Kind::HandOut {
        let texts: Vec<(String, String)> = files
            .iter()
            .filter_map(|f| {
                let text = std::str::from_utf8(&f.bytes).ok()?;
                Some((f.path.clone(), text.to_string()))
            })
            .collect();
        let leaks = scrub::leaks(&removed, &texts);
        if !leaks.is_empty() {
            return Err(EditionError::Leaks(leaks));
        }
    }
    Ok(Edition {
        kind,
        files,
        exercises,
        removed,
    })
}

/// The edition's `Cargo.toml`, from this crate's (`original`): the same library,
/// binary, dependencies and profiles (the benches are a workspace member of their own,
/// which the edition does not ship), with a workspace
/// of the crate and (if shipped, `with_book`) the book builder, and a package name of its
/// own, `raylemma-hand-out` or `raylemma-solutions` (the library and the binary keep the
/// name `raylemma`).
///
/// The package's own name matters: cargo names a workspace's artifacts by its package's
/// name and version and its path *relative to the workspace*, so two crates called
/// `raylemma` in one target folder (this one and an edition, or the two editions) would
/// take each other's builds for their own.
pub fn manifest(original: &str, with_book: bool, kind: Kind) -> String {
    let members = if with_book {
        r#"[".", "tools/book"]"#
    } else {
        r#"["."]"#
    };
    let mut out = String::from(
        "# The student edition of raylemma, written by `raylemma exercises` (see README.md).\n",
    );
    let mut section = String::new();
    let mut skipping = false;
    for line in original.lines() {
        let t = line.trim();
        if t.starts_with('[') {
            section = t.to_string();
            skipping = false;
            if section == "[workspace]" {
                skipping = true;
                out.push_str(&format!(
                    "[workspace]\n# `cargo test` tests this crate only; the book builder (tools/book: mdBook and\n# KaTeX) is built on demand, by `cargo run --release -p raylemma-book -- --root .`.\nmembers = {members}\ndefault-members = [\".\"]\n\n"
                ));
            }
        }
        if kind == Kind::HandOut && section == "[features]" && t.starts_with("default =") {
            out.push_str("default = [] # the twins are not in the hand-out\n");
        } else if section == "[package]" && t.starts_with("name =") {
            out.push_str(&format!(
                "name = \"raylemma-{}\" # its own name; the library and the binary are `raylemma`\n",
                kind.name()
            ));
        } else if !skipping {
            out.push_str(line);
            out.push('\n');
        }
        if t == "[lib]" {
            out.push_str("name = \"raylemma\"\n");
        }
    }
    while out.ends_with("\n\n") {
        out.pop();
    }
    out
}

/// The commit of the git clone at `root` (`git rev-parse HEAD`), with `-modified` if its
/// tracked files differ from it; `None` if `root` is not a clone or git cannot run.
pub fn commit_of(root: &Path) -> Option<String> {
    let git = |args: &[&str]| {
        std::process::Command::new("git")
            .arg("-C")
            .arg(root)
            .args(args)
            .output()
            .ok()
            .filter(|o| o.status.success())
            .map(|o| String::from_utf8_lossy(&o.stdout).trim().to_string())
    };
    // Only a clone whose top is `root` itself: a crate copied inside another clone is not
    // that clone's commit.
    let top = git(&["rev-parse", "--show-toplevel"])?;
    if fs::canonicalize(&top).ok()? != fs::canonicalize(root).ok()? {
        return None;
    }
    let head = git(&["rev-parse", "HEAD"])?;
    let clean = git(&["status", "--porcelain", "--untracked-files=no"])?.is_empty();
    Some(if clean {
        head
    } else {
        format!("{head}-modified")
    })
}

/// Records in the edition's stamp the commit it was made from (`commit: SHA`, or
/// `commit: unknown` when the crate is not a git clone), which `raylemma grade` compares
/// with its own ([`stamped_commit`]).
pub fn stamp_commit(edition: &mut Edition, commit: Option<&str>) {
    if let Some(f) = edition.files.iter_mut().find(|f| f.path == STAMP) {
        let line = format!("commit: {}\n", commit.unwrap_or("unknown"));
        f.bytes.extend_from_slice(line.as_bytes());
    }
}

/// The commit an edition's stamp `text` records (`None` for a stamp without one, or with
/// `commit: unknown`).
pub fn stamped_commit(text: &str) -> Option<&str> {
    text.lines()
        .find_map(|l| l.strip_prefix("commit: "))
        .map(str::trim)
        .filter(|c| *c != "unknown")
}

/// The edition's `README.md`: what it is, the two commands, and every exercise.
pub fn readme(exercises: &[Marker], kind: Kind) -> String {
    let mut rows = String::new();
    for m in exercises {
        rows.push_str(&format!(
            "| `{}` | {} | `{}` | {} |\n",
            m.name,
            m.chapter,
            m.file,
            m.task.replace('|', "\\|")
        ));
    }
    let what = match kind {
        Kind::HandOut => {
            "the **hand-out**: each function in the table below is a stub that panics with its exercise's name until you write its body"
        }
        Kind::Solutions => {
            "the **solutions**: each function in the table below is written, and `cargo test` passes every exercise (for teachers and for CI)"
        }
        Kind::Graded => {
            "a **graded submission**, written by `raylemma grade`: the edition's own code, with each function in the table below as the submission wrote it"
        }
    };
    README
        .replace("{what}", what)
        .replace("{count}", &exercises.len().to_string())
        .replace("{rows}", &rows)
}

/// The template of the edition's README.
const README: &str = include_str!("readme.md");

/// Checks that `dir` may receive an edition: it does not exist, or is an empty folder, or
/// (with `overwrite`) is an edition written before. It must not be `root` or inside it.
///
/// # Errors
/// [`EditionError::Refused`] naming `dir` and why.
pub fn check_destination(dir: &Path, root: &Path, overwrite: bool) -> Result<(), EditionError> {
    let refuse = |why: &str| Err(EditionError::Refused(FileError::new(dir, why)));
    if let (Ok(d), Ok(r)) = (absolute(dir), fs::canonicalize(root))
        && (d.starts_with(&r) || r.starts_with(&d))
    {
        return refuse("is the crate itself, inside it or above it: choose a folder outside it");
    }
    let Ok(meta) = fs::symlink_metadata(dir) else {
        return Ok(()); // does not exist
    };
    if !meta.is_dir() {
        return refuse("exists and is not a folder");
    }
    let mut entries = fs::read_dir(dir)
        .map_err(|e| EditionError::Refused(FileError::new(dir, format!("cannot list: {e}"))))?;
    if entries.next().is_none() {
        return Ok(());
    }
    if !overwrite {
        return refuse(
            "exists and is not empty; pass --overwrite to replace an edition written before",
        );
    }
    if !dir.join(STAMP).is_file() {
        return refuse(&format!(
            "is not empty and has no {STAMP}: it is not a raylemma edition, so --overwrite does not replace it"
        ));
    }
    Ok(())
}

/// Checks that the crate whose code a `raylemma` binary judges, `built_from` (the
/// `CARGO_MANIFEST_DIR` it was compiled in: its library *is* that crate's code), is the crate
/// of the working directory `cwd`, as `raylemma card` requires (chapter *Coursework*, *The
/// report card*). `cwd` must be `built_from` or inside it, with no edition (a folder with
/// [`STAMP`]) in between. Otherwise the repository's binary, run inside a hand-out, would
/// judge the repository's solved code and print *passing*; and of two hand-outs sharing a
/// `CARGO_TARGET_DIR`, one's binary would judge the other's code.
///
/// # Errors
/// Where the working directory is, which crate the binary judges, and what to run instead.
pub fn check_judged_crate(built_from: &Path, cwd: &Path) -> Result<(), String> {
    let built = fs::canonicalize(built_from).unwrap_or_else(|_| built_from.to_path_buf());
    let here = fs::canonicalize(cwd).unwrap_or_else(|_| cwd.to_path_buf());
    let edition_between = here
        .ancestors()
        .take_while(|d| *d != built)
        .find(|d| d.join(STAMP).is_file());
    if here.starts_with(&built) && edition_between.is_none() {
        return Ok(());
    }
    let crate_here =
        edition_between.or_else(|| here.ancestors().find(|d| d.join("Cargo.toml").is_file()));
    let place = match crate_here {
        Some(c) if c.join(STAMP).is_file() => {
            let kind = fs::read_to_string(c.join(STAMP)).unwrap_or_default();
            let kind = kind
                .lines()
                .next()
                .unwrap_or("")
                .trim()
                .rsplit(": ")
                .next()
                .unwrap_or("edition")
                .to_string();
            format!("is in the {kind} edition at {} ({STAMP})", c.display())
        }
        Some(c) => format!("is in the crate at {} (its Cargo.toml)", c.display()),
        None => "is in no crate (no Cargo.toml in it or above it)".into(),
    };
    Err(format!(
        "the working directory {} {place}, but this raylemma binary was built from {} and \
         judges that crate's code, not the code here: run `cargo run -- card` inside the crate \
         to judge (in a hand-out, its own binary judges its own code), or this binary inside {}",
        here.display(),
        built.display(),
        built.display()
    ))
}

/// `path` made absolute with its existing ancestors resolved (it need not exist).
fn absolute(path: &Path) -> std::io::Result<PathBuf> {
    let path = std::path::absolute(path)?;
    let mut existing = path.as_path();
    let mut tail = Vec::new();
    while fs::symlink_metadata(existing).is_err() {
        tail.push(existing.file_name().unwrap_or_default().to_owned());
        existing = match existing.parent() {
            Some(p) => p,
            None => return Ok(path.clone()),
        };
    }
    let mut out = fs::canonicalize(existing)?;
    for name in tail.iter().rev() {
        out.push(name);
    }
    Ok(out)
}

/// Writes `edition` into `dir`: made whole in a hidden folder beside it, then swapped in
/// ([`StagedDir::replace`]), so that `dir` is the old folder or the new one, never half
/// of either. Returns `dir`.
///
/// # Errors
/// [`EditionError::File`] naming the file that could not be written; `dir` is then as it
/// was and the staging folder is removed.
pub fn write(edition: &Edition, dir: &Path) -> Result<PathBuf, EditionError> {
    let staged = StagedDir::beside(dir)?;
    for file in &edition.files {
        let path = staged.path().join(&file.path);
        if let Some(parent) = path.parent() {
            fs::create_dir_all(parent).map_err(|e| {
                FileError::new(
                    dir.join(&file.path),
                    format!("cannot create its folder: {e}"),
                )
            })?;
        }
        fs::write(&path, &file.bytes)
            .map_err(|e| FileError::new(dir.join(&file.path), format!("cannot write: {e}")))?;
    }
    Ok(staged.replace()?)
}
