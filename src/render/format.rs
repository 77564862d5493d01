//! The scene file as written: a small TOML file, deserialised by serde into raw tables
//! whose values keep their byte spans (`raw`), so that the checker (`validate`)
//! can name the line of every mistake. The entry points [`parse`] and [`load`] return a
//! checked [`Scene`] or a [`DataError`]. Chapter: *Reference scenes and
//! interop* (`chapters/renderer/scenes.md`), which documents every key so that another
//! implementation can read the same files.

use std::path::{Path, PathBuf};

use super::raw::raw_tables;
use super::scene::Scene;
use super::validate;
use crate::data::DataError;

pub use super::raw::fnv1a;

// ANCHOR: parse
/// Reads a scene from the TOML text `text` of the file `file`; relative spectrum file
/// paths are resolved against `dir` (the scene file's folder).
///
/// # Errors
/// A [`DataError`] with the file, the line and the problem, for anything that is not a
/// valid scene; nothing is rendered or written before this succeeds.
pub fn parse(text: &str, file: &str, dir: &Path) -> Result<Scene, DataError> {
    let raw = raw_tables(text, file)?;
    validate::scene(&raw, text, file, dir)
}
// ANCHOR_END: parse

/// Reads the scene file at `path`.
///
/// # Errors
/// If the file cannot be read, or as [`parse`].
pub fn load(path: &Path) -> Result<Scene, DataError> {
    let (text, name) = crate::data::read_text(path)?;
    let dir = path
        .parent()
        .map_or_else(|| PathBuf::from("."), Path::to_path_buf);
    parse(&text, &name, &dir)
}
