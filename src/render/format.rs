//! The scene file as written: a small TOML file, deserialised by serde into raw tables
//! whose values keep their byte spans (`raw`), so that the checker (`validate`)
//! can name the line of every mistake. The entry points [`parse`] and [`load`] return a
//! checked [`Scene`] or a [`DataError`]; [`SceneFile`] keeps the line of each part beside
//! the scene, for the exporters (`crate::conformance::export`) to refuse with a line. Chapter: *Reference scenes and
//! interop* (`chapters/renderer/scenes.md`), which documents every key so that another
//! implementation can read the same files.

use std::path::{Path, PathBuf};

use super::raw::{line_of, raw_tables};
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

/// A checked scene with the names and lines of its parts.
#[derive(Clone, Debug)]
pub struct SceneFile {
    /// The scene.
    pub scene: Scene,
    /// The file's name as given.
    pub file: String,
    /// The line of `[camera]`.
    pub camera_line: usize,
    /// The line of `[environment]`, if there is one.
    pub environment_line: usize,
    /// The name and line of every material, in the order of [`Scene::materials`].
    pub materials: Vec<(String, usize)>,
    /// The line of every `[[shape]]`, in order.
    pub shape_lines: Vec<usize>,
    /// The line of every `[[light]]`, in the order of [`Scene::lights`].
    pub light_lines: Vec<usize>,
}

impl SceneFile {
    /// Reads the scene text `text` of the file `file`, whose relative spectrum files are in
    /// `dir`: the checked scene, as [`parse`] gives it, with its lines.
    ///
    /// # Errors
    /// As [`parse`].
    pub fn parse(text: &str, file: &str, dir: &Path) -> Result<SceneFile, DataError> {
        let raw = raw_tables(text, file)?;
        let scene = validate::scene(&raw, text, file, dir)?;
        let line = |span| line_of(text, span);
        Ok(SceneFile {
            scene,
            file: file.to_string(),
            camera_line: line(raw.camera.span()),
            environment_line: raw.environment.as_ref().map_or(0, |e| line(e.span())),
            // Checked in the same (sorted) order as the model holds them.
            materials: raw
                .materials
                .iter()
                .map(|(name, m)| (name.clone(), line(m.span())))
                .collect(),
            shape_lines: raw.shape.iter().map(|s| line(s.span())).collect(),
            light_lines: raw.light.iter().map(|l| line(l.span())).collect(),
        })
    }

    /// Reads the scene file at `path`.
    ///
    /// # Errors
    /// If the file cannot be read, or as [`SceneFile::parse`].
    pub fn load(path: &Path) -> Result<SceneFile, DataError> {
        let (text, name) = crate::data::read_text(path)?;
        let dir = path
            .parent()
            .map_or_else(|| PathBuf::from("."), Path::to_path_buf);
        Self::parse(&text, &name, &dir)
    }

    /// A problem on `line` of the file.
    pub fn error(&self, line: usize, problem: impl Into<String>) -> DataError {
        DataError::new(&self.file, line, problem)
    }
}
