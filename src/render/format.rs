//! The scene file as written: a small TOML file, deserialised by serde into raw tables
//! whose values keep their byte spans, so that the checker (`validate`) can name
//! the line of every mistake. The entry points [`parse`] and [`load`] return a checked
//! [`Scene`] or a [`DataError`]. Chapter: *Reference scenes and
//! interop* (`chapters/renderer/scenes.md`), which documents every key so that another
//! implementation can read the same files.

use std::collections::BTreeMap;
use std::ops::Range;
use std::path::{Path, PathBuf};

use serde::Deserialize;
use toml::Spanned;

use super::scene::{DirectLight, Scene};
use super::validate;
use crate::data::DataError;
use crate::spectral::wavelength::WavelengthStrategy;
use crate::transport::shadow::Heuristic;

/// The names the `wavelengths` key accepts, with their strategies (and `"emission"`,
/// [`super::scene::Wavelength::Emission`]).
pub const WAVELENGTH_STRATEGIES: [(&str, WavelengthStrategy); 5] = [
    ("uniform", WavelengthStrategy::Uniform),
    ("visible", WavelengthStrategy::Visible),
    ("hero-uniform", WavelengthStrategy::HeroUniform),
    ("hero-visible", WavelengthStrategy::HeroVisible),
    ("hero-balance", WavelengthStrategy::HeroBalance),
];

/// The names the `direct` key accepts, with their strategies of direct lighting.
pub const DIRECT_STRATEGIES: [(&str, DirectLight); 4] = [
    ("mis-power", DirectLight::Mis(Heuristic::Power)),
    ("mis-balance", DirectLight::Mis(Heuristic::Balance)),
    ("light", DirectLight::Light),
    ("bsdf", DirectLight::Bsdf),
];

/// The largest accepted image side, in pixels.
pub const MAX_RESOLUTION: i64 = 16_384;

/// The whole file: its tables, each with its span.
#[derive(Deserialize)]
#[serde(deny_unknown_fields)]
pub(super) struct RawScene {
    pub(super) render: Spanned<RawRender>,
    pub(super) camera: Spanned<RawCamera>,
    #[serde(default)]
    pub(super) spectra: BTreeMap<String, Spanned<toml::Value>>,
    #[serde(default)]
    pub(super) materials: BTreeMap<String, Spanned<RawMaterial>>,
    #[serde(default)]
    pub(super) shape: Vec<Spanned<RawShape>>,
    #[serde(default)]
    pub(super) light: Vec<Spanned<RawShape>>,
    pub(super) environment: Option<Spanned<RawEnvironment>>,
}

/// `[render]`.
#[derive(Deserialize)]
#[serde(deny_unknown_fields)]
pub(super) struct RawRender {
    pub(super) spp: Spanned<i64>,
    pub(super) seed: Option<Spanned<i64>>,
    pub(super) wavelengths: Option<Spanned<String>>,
    pub(super) roulette_depth: Option<Spanned<i64>>,
    pub(super) max_depth: Option<Spanned<i64>>,
    pub(super) direct: Option<Spanned<String>>,
}

/// `[camera]`.
#[derive(Deserialize)]
#[serde(deny_unknown_fields)]
pub(super) struct RawCamera {
    pub(super) position: Spanned<[f64; 3]>,
    pub(super) look_at: Spanned<[f64; 3]>,
    pub(super) up: Spanned<[f64; 3]>,
    pub(super) fov_y: Spanned<f64>,
    pub(super) resolution: Spanned<[i64; 2]>,
}

/// An entry of `[materials]`: the keys any material type can have.
#[derive(Deserialize)]
#[serde(deny_unknown_fields)]
pub(super) struct RawMaterial {
    #[serde(rename = "type")]
    pub(super) kind: Spanned<String>,
    pub(super) reflectance: Option<Spanned<toml::Value>>,
    pub(super) ior: Option<Spanned<f64>>,
    pub(super) sellmeier: Option<Spanned<String>>,
    pub(super) thickness_nm: Option<Spanned<toml::Value>>,
    pub(super) y_range: Option<Spanned<[f64; 2]>>,
}

/// A `[[shape]]` or a `[[light]]`: the keys a sphere or a quad can have.
#[derive(Deserialize)]
#[serde(deny_unknown_fields)]
pub(super) struct RawShape {
    #[serde(rename = "type")]
    pub(super) kind: Spanned<String>,
    pub(super) center: Option<Spanned<[f64; 3]>>,
    pub(super) radius: Option<Spanned<f64>>,
    pub(super) corner: Option<Spanned<[f64; 3]>>,
    pub(super) edge1: Option<Spanned<[f64; 3]>>,
    pub(super) edge2: Option<Spanned<[f64; 3]>>,
    pub(super) material: Option<Spanned<String>>,
    pub(super) emission: Option<Spanned<toml::Value>>,
}

/// `[environment]`: `emission` (constant), or `above`, `below` and `axis` (a gradient).
#[derive(Deserialize)]
#[serde(deny_unknown_fields)]
pub(super) struct RawEnvironment {
    pub(super) emission: Option<Spanned<toml::Value>>,
    pub(super) above: Option<Spanned<toml::Value>>,
    pub(super) below: Option<Spanned<toml::Value>>,
    pub(super) axis: Option<Spanned<[f64; 3]>>,
}

/// An inline or named spectrum definition: exactly one of the kinds.
#[derive(Deserialize)]
#[serde(deny_unknown_fields)]
pub(super) struct RawSpectrum {
    pub(super) constant: Option<f64>,
    pub(super) file: Option<String>,
    pub(super) column: Option<String>,
    pub(super) blackbody: Option<f64>,
    pub(super) peak: Option<f64>,
    pub(super) lamp: Option<String>,
    pub(super) scale: Option<f64>,
    pub(super) luminance: Option<f64>,
}

/// The 1-based line of `text` on which the byte span `span` starts.
pub(super) fn line_of(text: &str, span: Range<usize>) -> usize {
    let end = span.start.min(text.len());
    text.as_bytes()[..end]
        .iter()
        .filter(|&&b| b == b'\n')
        .count()
        + 1
}

/// The 64-bit FNV-1a hash of `bytes` (a scene file's, for the render's sidecar).
pub fn fnv1a(bytes: &[u8]) -> u64 {
    bytes.iter().fold(0xcbf2_9ce4_8422_2325, |h, &b| {
        (h ^ u64::from(b)).wrapping_mul(0x0100_0000_01b3)
    })
}

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

/// The raw tables of the TOML text `text` of the file `file`, with their spans.
///
/// # Errors
/// A TOML syntax error, an unknown key or a value of the wrong type, with its line.
pub(super) fn raw_tables(text: &str, file: &str) -> Result<RawScene, DataError> {
    toml::from_str(text).map_err(|e: toml::de::Error| {
        let line = e.span().map_or(0, |s| line_of(text, s));
        DataError::new(file, line, e.message().to_string())
    })
}

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
