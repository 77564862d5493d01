//! A scene file for other renderers: as a Mitsuba 3 scene ([`mitsuba::to_xml`]) that
//! `mitsuba.load_file` renders unchanged, as a pbrt-v4 scene ([`pbrt::to_pbrt`]), and as
//! fully resolved JSON ([`json::to_json`]: every default filled in, every spectrum on the
//! 1 nm grid, every transform explicit), which an implementer in any language reads
//! without re-implementing the TOML parser.
//! Part of the tools for other renderers ([`crate::conformance`]). Chapter: *Reference scenes and interop* (`chapters/renderer/scenes.md`, *Exporting a
//! scene*).
//!
//! All three start from a [`SceneFile`] (the renderer's reading of a scene file,
//! `crate::render::format`): the checked [`Scene`] and, for every material,
//! shape and light, the camera and the environment, the line of the file where it is
//! written, so that what Mitsuba or pbrt cannot express (thin films, a gradient sky; for
//! Mitsuba also Sellmeier dispersion) is refused as `file:line: reason`, like every other
//! problem of a scene file.

pub mod json;
pub mod mitsuba;
pub mod pbrt;

use glam::DVec3;

pub use crate::render::format::SceneFile;
use crate::render::scene::Scene;
use crate::spectral::spectrum::{Spectrum, Table};
use crate::spectral::{LAMBDA_MAX, LAMBDA_MIN};

/// The whole nanometres from 360 to 830 nm, the grid of the colour-matching functions.
pub fn grid() -> impl Iterator<Item = f64> + Clone {
    (LAMBDA_MIN as u32..=LAMBDA_MAX as u32).map(f64::from)
}

// ANCHOR: sampled
/// A spectrum on the 1 nm grid: `(wavelengths, values)` at every whole nanometre of
/// 360-830 nm where it can be non-zero, and whether that is exact. A table keeps its own
/// range (clipped to 360-830): linear between whole nanometres and zero outside its first
/// and last, the samples are the table itself over 360-830 nm (the only wavelengths a
/// render uses: the colour-matching functions are zero outside) when its knots are whole
/// nanometres, as every table in `data/` is. A constant is exact; a blackbody is Planck's
/// law at every nanometre, linear in between (its XYZ within 7e-5 of the exact curve's at
/// 1500 K, 3e-6 at 6500 K).
pub fn sampled(s: &Spectrum) -> (Vec<f64>, Vec<f64>, bool) {
    let (nm, exact): (Vec<f64>, bool) = match s {
        Spectrum::Table(t) => {
            let knots = t.wavelengths();
            let (first, last) = (knots[0], knots[knots.len() - 1]);
            let nm: Vec<f64> = grid().filter(|&l| l >= first && l <= last).collect();
            (nm, on_grid(t))
        }
        Spectrum::Constant(_) => (grid().collect(), true),
        Spectrum::Blackbody { .. } => (grid().collect(), false),
    };
    let values = nm.iter().map(|&l| s.eval(l)).collect();
    (nm, values, exact)
}
// ANCHOR_END: sampled

/// Whether resampling `t` at whole nanometres within its range keeps it exact over
/// 360-830 nm: every knot inside that range is a whole nanometre, and the first and last
/// knots are whole nanometres or outside it.
fn on_grid(t: &Table) -> bool {
    let knots = t.wavelengths();
    let (first, last) = (knots[0], knots[knots.len() - 1]);
    let inside = |l: f64| (LAMBDA_MIN..=LAMBDA_MAX).contains(&l);
    knots.iter().all(|&l| !inside(l) || l.fract() == 0.0)
        && (first.fract() == 0.0 || first < LAMBDA_MIN)
        && (last.fract() == 0.0 || last > LAMBDA_MAX)
        && first <= LAMBDA_MAX
        && last >= LAMBDA_MIN
}

/// The distance from `p` to the farthest point of the scene's geometry (for clipping
/// planes).
pub(crate) fn extent(scene: &Scene, p: DVec3) -> f64 {
    use crate::render::scene::{Geometry, LightShape};
    let mut far: f64 = 0.0;
    let mut sphere = |c: DVec3, r: f64| far = far.max((c - p).length() + r);
    for s in &scene.shapes {
        match &s.geometry {
            Geometry::Sphere(sp) => sphere(sp.center, sp.radius),
            Geometry::Quad(q) => {
                for v in q.vertices() {
                    sphere(v, 0.0);
                }
            }
        }
    }
    for l in &scene.lights {
        match &l.shape {
            LightShape::Sphere(sp) => sphere(sp.center(), sp.radius()),
            LightShape::Quad(q) => {
                for v in q.vertices() {
                    sphere(v, 0.0);
                }
            }
        }
    }
    far
}

/// The name of a direct-lighting strategy in the scene format.
pub(crate) fn direct_name(d: crate::render::scene::DirectLight) -> &'static str {
    crate::render::scene::DIRECT_STRATEGIES
        .iter()
        .find(|(_, s)| *s == d)
        .map_or("other", |(n, _)| n)
}
