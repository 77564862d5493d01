//! The scene file as parsed, before any check: serde's raw tables, each value with its
//! byte span, and the small helpers that read them (the line of a span, the file's hash).
//! [`super::format`] reads a file into these, `validate` turns them into the model, and the
//! export (`super::export`) reads them for the lines of a scene's parts; this module
//! depends on none of them.

use std::collections::BTreeMap;
use std::ops::Range;

use serde::Deserialize;
use toml::Spanned;

use crate::data::DataError;

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
    pub(super) light_sampling: Option<Spanned<String>>,
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
    raylemma_output::line_of(text, span.start)
}

/// The 64-bit FNV-1a hash of `bytes` (a scene file's, for the render's sidecar).
pub use raylemma_output::fnv1a;

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
