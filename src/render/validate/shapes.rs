//! The checks of `[[shape]]` and `[[light]]`: a sphere (centre, radius > 0) or a quad
//! (corner and two edges that span a parallelogram), each with only its own keys, and a
//! known material (shapes) or an emission spectrum (lights); and the camera and the lights
//! outside every dielectric sphere. Chapter: *Reference scenes and interop*
//! (`chapters/renderer/scenes.md`, *Bad input*).

use std::collections::BTreeMap;
use std::ops::Range;

use glam::DVec3;
use toml::Spanned;

use super::Checker;
use crate::data::DataError;
use crate::geometry::parallelogram::{Degenerate, Parallelogram};
use crate::geometry::sphere::Sphere;
use crate::render::raw::{RawCamera, RawShape};
use crate::render::scene::{Emitter, Geometry, LightShape, Material, Shape};
use crate::spectral::spectrum::Spectrum;
use crate::transport::shadow::{QuadLight, SphereLight};

impl Checker<'_> {
    /// The scattering shapes; `materials` are the names of `[materials]`, in the order of
    /// [`crate::render::scene::Scene::materials`].
    pub(super) fn shapes(
        &self,
        raw: &[Spanned<RawShape>],
        materials: &[String],
    ) -> Result<Vec<Shape>, DataError> {
        let mut shapes = Vec::new();
        for (i, s) in raw.iter().enumerate() {
            let span = s.span();
            let s = s.get_ref();
            let what = format!("shape {} ({})", i + 1, s.kind.get_ref());
            self.keys_for(s, s.kind.get_ref(), &what, "material")?;
            let geometry = match s.kind.get_ref().as_str() {
                "sphere" => {
                    let (c, r) = self.sphere(s, span.clone(), &what)?;
                    Geometry::Sphere(Sphere::new(c, r))
                }
                // keys_for has refused any other type.
                _ => Geometry::Quad(self.quad(s, span.clone(), &what)?),
            };
            let m = self.required(&s.material, span, "material")?;
            let Some(material) = materials.iter().position(|n| n == m.get_ref()) else {
                return self.err(
                    m.span(),
                    format!(
                        "{what}: unknown material {:?} (there are: {})",
                        m.get_ref(),
                        if materials.is_empty() {
                            "none".into()
                        } else {
                            materials.join(", ")
                        }
                    ),
                );
            };
            shapes.push(Shape { geometry, material });
        }
        Ok(shapes)
    }

    /// The emitters; their spectra may name entries of `spectra`.
    pub(super) fn lights(
        &self,
        raw: &[Spanned<RawShape>],
        spectra: &BTreeMap<String, Spectrum>,
    ) -> Result<Vec<Emitter>, DataError> {
        let mut lights = Vec::new();
        for (i, l) in raw.iter().enumerate() {
            let span = l.span();
            let l = l.get_ref();
            let what = format!("light {} ({})", i + 1, l.kind.get_ref());
            self.keys_for(l, l.kind.get_ref(), &what, "emission")?;
            let shape = match l.kind.get_ref().as_str() {
                "sphere" => {
                    let (c, r) = self.sphere(l, span.clone(), &what)?;
                    LightShape::Sphere(
                        SphereLight::new(c, r)
                            .or_else(|e| self.err(span.clone(), format!("{what}: {e}")))?,
                    )
                }
                _ => LightShape::Quad(QuadLight::from(self.quad(l, span.clone(), &what)?)),
            };
            let e = self.required(&l.emission, span, "emission")?;
            let emission = self.spectrum(e, spectra, &format!("{what} emission"))?;
            lights.push(Emitter::new(shape, emission));
        }
        Ok(lights)
    }

    /// Refuses a camera or a light inside a dielectric sphere. The path tracer leaves out the
    /// radiance factor `η²` of a refraction, which cancels only for paths that leave every
    /// dielectric they enter: a path that starts inside one (the camera) or ends inside one
    /// (a light) would be wrong by that factor (chapter *The path tracer*,
    /// `chapters/renderer/path-tracer.md`). A light is inside when its centre (a sphere) or
    /// a corner (a quad) is; the error is on the line of the camera's `position`, or of the
    /// light's `center` or `corner`. A dielectric made of quads has no inside to test.
    pub(super) fn outside_dielectrics(
        &self,
        camera: (&Spanned<RawCamera>, DVec3),
        lights: (&[Spanned<RawShape>], &[Emitter]),
        materials: &[Material],
        shapes: &[Shape],
    ) -> Result<(), DataError> {
        let spheres: Vec<(usize, Sphere)> = shapes
            .iter()
            .enumerate()
            .filter_map(|(i, s)| match s.geometry {
                Geometry::Sphere(sp)
                    if matches!(materials[s.material], Material::Dielectric { .. }) =>
                {
                    Some((i, sp))
                }
                _ => None,
            })
            .collect();
        let inside = |p: DVec3| {
            spheres
                .iter()
                .find(|(_, sp)| (p - sp.center).length() < sp.radius)
                .map(|(i, _)| i + 1)
        };
        let why = "the renderer leaves out the radiance factor η² of refraction, which cancels only \
                   when the camera and every light are outside every dielectric";
        if let Some(i) = inside(camera.1) {
            return self.err(
                camera.0.get_ref().position.span(),
                format!("the camera is inside shape {i}, a dielectric sphere: {why}"),
            );
        }
        for (k, (raw, light)) in lights.0.iter().zip(lights.1).enumerate() {
            let (points, at) = match &light.shape {
                LightShape::Quad(q) => (q.vertices().to_vec(), raw.get_ref().corner.as_ref()),
                LightShape::Sphere(sp) => (vec![sp.center()], raw.get_ref().center.as_ref()),
            };
            if let Some(i) = points.iter().find_map(|&p| inside(p)) {
                return self.err(
                    at.map_or(raw.span(), Spanned::span),
                    format!(
                        "light {} is inside shape {i}, a dielectric sphere: {why}",
                        k + 1
                    ),
                );
            }
        }
        Ok(())
    }

    /// The centre and radius (> 0) of a sphere.
    fn sphere(
        &self,
        s: &RawShape,
        span: Range<usize>,
        what: &str,
    ) -> Result<(DVec3, f64), DataError> {
        let c = self.vec3(
            self.required(&s.center, span.clone(), "center")?,
            &format!("{what} center"),
        )?;
        let r = self.required(&s.radius, span, "radius")?;
        let radius = self.finite(r, &format!("{what} radius"))?;
        if radius <= 0.0 {
            return self.err(
                r.span(),
                format!("{what} radius is {radius}; it must be > 0"),
            );
        }
        Ok((c, radius))
    }

    /// A quad's corner and edges, as a parallelogram; a degenerate one is refused on the
    /// line of the edge at fault.
    fn quad(
        &self,
        s: &RawShape,
        span: Range<usize>,
        what: &str,
    ) -> Result<Parallelogram, DataError> {
        let corner = self.vec3(
            self.required(&s.corner, span.clone(), "corner")?,
            &format!("{what} corner"),
        )?;
        let e1 = self.vec3(
            self.required(&s.edge1, span.clone(), "edge1")?,
            &format!("{what} edge1"),
        )?;
        let e2 = self.vec3(
            self.required(&s.edge2, span.clone(), "edge2")?,
            &format!("{what} edge2"),
        )?;
        Parallelogram::new(corner, e1, e2).or_else(|e| {
            // Point at the edge that makes the quad degenerate.
            let at = match e {
                Degenerate::ZeroLengthEdge("e1") => s.edge1.as_ref(),
                Degenerate::ZeroLengthEdge(_) | Degenerate::ParallelEdges => s.edge2.as_ref(),
                // `vec3` has refused non-finite vectors.
                Degenerate::NonFinite(_) => None,
            };
            self.err(
                at.map_or(span, Spanned::span),
                format!("{what} is degenerate: {e}"),
            )
        })
    }

    /// Refuses an unknown `type`, and keys that belong to the other kind of shape (or
    /// `emission` on a shape, `material` on a light: `extra` is the one allowed).
    fn keys_for(&self, s: &RawShape, kind: &str, what: &str, extra: &str) -> Result<(), DataError> {
        if kind != "sphere" && kind != "quad" {
            let noun = if extra == "material" {
                "shape"
            } else {
                "light"
            };
            return self.err(
                s.kind.span(),
                format!("unknown {noun} type {kind:?} (there are: sphere, quad)"),
            );
        }
        let sphere = [
            ("center", s.center.as_ref().map(Spanned::span)),
            ("radius", s.radius.as_ref().map(Spanned::span)),
        ];
        let quad = [
            ("corner", s.corner.as_ref().map(Spanned::span)),
            ("edge1", s.edge1.as_ref().map(Spanned::span)),
            ("edge2", s.edge2.as_ref().map(Spanned::span)),
        ];
        let other = [
            ("material", s.material.as_ref().map(Spanned::span)),
            ("emission", s.emission.as_ref().map(Spanned::span)),
        ];
        let wrong = if kind == "sphere" {
            &quad[..]
        } else {
            &sphere[..]
        };
        self.refuse_keys(
            wrong
                .iter()
                .chain(other.iter().filter(|(k, _)| *k != extra)),
            what,
            kind,
        )
    }
}
