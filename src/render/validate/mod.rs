//! The checker that turns the raw tables of a scene file ([`super::raw`]) into the
//! model ([`super::scene`]): every number, name and combination is checked before a single
//! ray is traced, and every problem is a [`DataError`] naming the file, the line and what
//! is wrong (an unknown key or material, a negative radius, an index of refraction `<= 0`,
//! a NaN, a degenerate quad, a missing spectrum file, zero samples per pixel, a camera or a
//! light inside glass). Chapter: *Reference scenes and interop*
//! (`chapters/renderer/scenes.md`, *Bad input*).
//!
//! One file per part of the scene: [`settings`] (`[render]`, `[camera]`, the emission
//! wavelength strategy), [`spectra`], [`materials`], [`shapes`] (`[[shape]]` and
//! `[[light]]`); here, the checker's common rules and the order in which a scene is
//! checked.

mod materials;
mod settings;
mod shapes;
mod spectra;

use std::collections::BTreeMap;
use std::ops::Range;
use std::path::{Path, PathBuf};

use glam::DVec3;
use toml::Spanned;

use super::raw::{RawScene, fnv1a, line_of};
use super::scene::Scene;
use crate::data::DataError;

/// Checks the tables of one file, `file`, whose text is `text`; relative spectrum files
/// are found in `dir`.
struct Checker<'a> {
    file: &'a str,
    text: &'a str,
    dir: PathBuf,
    /// The data files read so far, in order (the scene's provenance).
    read: std::cell::RefCell<Vec<PathBuf>>,
}

/// Checks the raw tables `raw` of the scene file `file` (text `text`, folder `dir`), table
/// by table in the order the model needs them: settings, camera, spectra (which may refer
/// to earlier ones), materials, shapes, lights (and the camera and lights outside every
/// dielectric sphere), environment, then the wavelength strategy that depends on the
/// lights. The scene carries the [`fnv1a`] hash of `text`.
///
/// # Errors
/// The first problem, as a [`DataError`] with its line.
pub(super) fn scene(
    raw: &RawScene,
    text: &str,
    file: &str,
    dir: &Path,
) -> Result<Scene, DataError> {
    let ck = Checker {
        file,
        text,
        dir: dir.to_path_buf(),
        read: std::cell::RefCell::new(Vec::new()),
    };
    let mut settings = ck.render(&raw.render)?;
    let camera = ck.camera(&raw.camera)?;
    let mut spectra = BTreeMap::new();
    for (name, v) in &raw.spectra {
        let s = ck.spectrum(v, &spectra, &format!("spectrum {name:?}"))?;
        spectra.insert(name.clone(), s);
    }
    let mut names = Vec::new();
    let mut materials = Vec::new();
    for (name, m) in &raw.materials {
        materials.push(ck.material(name, m, &spectra)?);
        names.push(name.clone());
    }
    let shapes = ck.shapes(&raw.shape, &names)?;
    let lights = ck.lights(&raw.light, &spectra)?;
    ck.outside_dielectrics(
        (&raw.camera, camera.position),
        (&raw.light, &lights),
        &materials,
        &shapes,
    )?;
    let environment = match &raw.environment {
        Some(env) => Some(ck.environment(env, &spectra)?),
        None => None,
    };
    if let Some(w) = &raw.render.get_ref().wavelengths
        && w.get_ref() == "emission"
    {
        settings.wavelengths = ck.emission_sampling(w.span(), &lights, environment.is_some())?;
    }
    if shapes.is_empty() && lights.is_empty() {
        return Err(DataError::new(
            file,
            0,
            "the scene has no shape and no light",
        ));
    }
    Ok(Scene {
        camera,
        settings,
        materials,
        shapes,
        lights,
        environment,
        hash: fnv1a(text.as_bytes()),
        files: ck.read.into_inner(),
    })
}

/// The rules every table follows.
impl Checker<'_> {
    /// A problem at `span`: an `Err` with the file and the span's line.
    fn err<T>(&self, span: Range<usize>, problem: impl Into<String>) -> Result<T, DataError> {
        Err(DataError::new(self.file, line_of(self.text, span), problem))
    }

    fn finite(&self, x: &Spanned<f64>, what: &str) -> Result<f64, DataError> {
        let v = *x.get_ref();
        if v.is_finite() {
            Ok(v)
        } else {
            self.err(x.span(), format!("{what} is {v}, not a finite number"))
        }
    }

    fn vec3(&self, x: &Spanned<[f64; 3]>, what: &str) -> Result<DVec3, DataError> {
        let v = DVec3::from_array(*x.get_ref());
        if v.is_finite() {
            Ok(v)
        } else {
            self.err(
                x.span(),
                format!("{what} {v} has a component that is not finite"),
            )
        }
    }

    /// Refuses the first of `keys` that is given: `(name, its span if present)`.
    fn refuse_keys<'k>(
        &self,
        keys: impl IntoIterator<Item = &'k (&'k str, Option<Range<usize>>)>,
        what: &str,
        kind: &str,
    ) -> Result<(), DataError> {
        for (key, span) in keys {
            if let Some(span) = span {
                return self.err(span.clone(), format!("{what}: a {kind} has no key `{key}`"));
            }
        }
        Ok(())
    }

    fn required<'b, T>(
        &self,
        x: &'b Option<Spanned<T>>,
        outer: Range<usize>,
        what: &str,
    ) -> Result<&'b Spanned<T>, DataError> {
        match x {
            Some(v) => Ok(v),
            None => self.err(outer, format!("missing key `{what}`")),
        }
    }

    fn non_negative_int(&self, x: &Spanned<i64>, what: &str, min: i64) -> Result<u64, DataError> {
        let v = *x.get_ref();
        if v >= min {
            Ok(v as u64)
        } else {
            self.err(
                x.span(),
                format!("{what} is {v}; it must be at least {min}"),
            )
        }
    }
}
