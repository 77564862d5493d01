//! A scene as fully resolved JSON: every default filled in, every spectrum sampled on the
//! 1 nm grid, every transform explicit, and the conventions (colour, camera, quads, lights)
//! stated in the file, so that an implementer in any language can render it without
//! re-implementing raylemma's TOML parser. Written with `serde_json`. Chapter: *Reference
//! scenes and interop* (`chapters/renderer/scenes.md`, *Exporting a scene*).
//!
//! Nothing is refused: Sellmeier glass is its coefficients and its index at every
//! nanometre, a thin film its index, thickness and heights, a gradient sky its axis and
//! two spectra.

use glam::DVec3;
use serde::Serialize;

use super::{SceneFile, sampled};
use crate::render::scene::{Environment, Geometry, Ior, LightShape, Material, Scene};
use crate::spectral::cie;
use crate::spectral::spectrum::Spectrum;

/// The format's name and version, the first keys of every file.
pub(crate) const FORMAT: &str = "raylemma-scene";
/// The version of the layout below; it changes whenever a key is renamed, removed or changes
/// meaning. A key added beside the others (as `render.max_depth_counts` was) leaves it, so
/// that readers of version 1 keep working.
pub(crate) const VERSION: u32 = 1;

#[derive(Serialize)]
struct File<'a> {
    format: &'static str,
    version: u32,
    source: &'a str,
    scene_hash: String,
    conventions: Conventions,
    render: Render,
    camera: Camera,
    materials: Vec<MaterialJson>,
    shapes: Vec<ShapeJson>,
    lights: Vec<LightJson>,
    environment: Option<EnvironmentJson>,
}

#[derive(Serialize)]
struct Conventions {
    spectra: &'static str,
    colour: &'static str,
    wavelength_range_nm: [f64; 2],
    y_integral: f64,
    /// Rows.
    xyz_to_linear_srgb: [[f64; 3]; 3],
    camera: &'static str,
    quad: &'static str,
    lights: &'static str,
    dielectric: &'static str,
}

#[derive(Serialize)]
struct Render {
    spp: u32,
    seed: u64,
    wavelengths: &'static str,
    direct: &'static str,
    roulette_depth: u32,
    /// The scene's `max_depth`, counted in bounces as raylemma counts it.
    max_depth: u32,
    /// What `max_depth` counts, in words, for an implementer whose renderer counts segments.
    max_depth_counts: &'static str,
}

/// What the export's `max_depth` counts. raylemma counts bounces (surface hits after the
/// camera's ray that scatter), Mitsuba path segments: the two differ by one, which is the
/// first thing a renderer built from the JSON gets wrong (chapter *The path tracer*, *The
/// maximum depth*; `tools/mitsuba/NOTES.md`, section 5).
pub(crate) const MAX_DEPTH_COUNTS: &str = "bounces: a path has at most max_depth + 1 segments; 0 is only the lights the camera sees, 1 is direct light only (paths of two segments, camera to surface to light); a light is sampled only at the vertices before the last, where the next segment is traced too; a renderer counting segments (Mitsuba's max_depth) uses max_depth + 1";

#[derive(Serialize)]
struct Camera {
    position: [f64; 3],
    look_at: [f64; 3],
    up: [f64; 3],
    fov_y_deg: f64,
    width: u32,
    height: u32,
    /// The unit view direction.
    forward: [f64; 3],
    /// The image's right, unit: `forward x up`, normalised.
    right: [f64; 3],
    /// The image's up, unit: `right x forward`.
    image_up: [f64; 3],
    /// `tan(fov_y / 2)`: half the image plane's height at unit distance.
    half_height: f64,
    /// `half_height * width / height`.
    half_width: f64,
}

/// A spectrum: its kind, its exact parameters, its samples on the 1 nm grid.
#[derive(Serialize)]
struct SpectrumJson {
    kind: &'static str,
    #[serde(skip_serializing_if = "Option::is_none")]
    value: Option<f64>,
    #[serde(skip_serializing_if = "Option::is_none")]
    kelvin: Option<f64>,
    #[serde(skip_serializing_if = "Option::is_none")]
    peak: Option<f64>,
    /// Whether `nm` and `values` are the spectrum exactly over 360-830 nm.
    exact: bool,
    nm: Vec<f64>,
    values: Vec<f64>,
    /// The table's own knots, when the 1 nm samples are not exact.
    #[serde(skip_serializing_if = "Option::is_none")]
    knots: Option<Knots>,
}

#[derive(Serialize)]
struct Knots {
    nm: Vec<f64>,
    values: Vec<f64>,
}

#[derive(Serialize)]
struct MaterialJson {
    name: String,
    #[serde(rename = "type")]
    kind: &'static str,
    #[serde(skip_serializing_if = "Option::is_none")]
    reflectance: Option<SpectrumJson>,
    #[serde(skip_serializing_if = "Option::is_none")]
    ior: Option<f64>,
    #[serde(skip_serializing_if = "Option::is_none")]
    sellmeier: Option<SellmeierJson>,
    #[serde(skip_serializing_if = "Option::is_none")]
    thickness_nm: Option<ThicknessJson>,
}

#[derive(Serialize)]
struct SellmeierJson {
    name: String,
    formula: &'static str,
    /// `[B_i, C_i]`, `C_i` in µm².
    terms: Vec<[f64; 2]>,
    /// The index on the 1 nm grid.
    nm: Vec<f64>,
    index: Vec<f64>,
}

#[derive(Serialize)]
struct ThicknessJson {
    bottom: f64,
    top: f64,
    /// The heights (world y) between which it varies linearly; constant beyond.
    y_range: [f64; 2],
    model: &'static str,
}

#[derive(Serialize)]
struct ShapeJson {
    #[serde(rename = "type")]
    kind: &'static str,
    #[serde(flatten)]
    geometry: GeometryJson,
    material: usize,
    material_name: String,
}

#[derive(Serialize)]
#[serde(untagged)]
enum GeometryJson {
    Quad {
        corner: [f64; 3],
        edge1: [f64; 3],
        edge2: [f64; 3],
        /// `normalize(edge1 x edge2)`.
        normal: [f64; 3],
        area: f64,
        /// The rectangle [-1, 1]² (normal +z) mapped onto the quad: columns
        /// `edge1/2, edge2/2, normal, centre`; 16 numbers, row by row.
        to_world: [f64; 16],
    },
    Sphere {
        center: [f64; 3],
        radius: f64,
    },
}

#[derive(Serialize)]
struct LightJson {
    #[serde(rename = "type")]
    kind: &'static str,
    #[serde(flatten)]
    geometry: GeometryJson,
    emits: &'static str,
    emission: SpectrumJson,
}

#[derive(Serialize)]
#[serde(tag = "type", rename_all = "lowercase")]
enum EnvironmentJson {
    Constant {
        radiance: SpectrumJson,
    },
    Gradient {
        axis: [f64; 3],
        above: Box<SpectrumJson>,
        below: Box<SpectrumJson>,
        rule: &'static str,
    },
}

fn spectrum(s: &Spectrum) -> SpectrumJson {
    let (nm, values, exact) = sampled(s);
    let (kind, value, kelvin, peak, knots) = match s {
        Spectrum::Constant(c) => ("constant", Some(*c), None, None, None),
        Spectrum::Blackbody { kelvin, peak } => {
            ("blackbody", None, Some(*kelvin), Some(*peak), None)
        }
        Spectrum::Table(t) => (
            "table",
            None,
            None,
            None,
            (!exact).then(|| Knots {
                nm: t.wavelengths().to_vec(),
                values: t.values().to_vec(),
            }),
        ),
    };
    SpectrumJson {
        kind,
        value,
        kelvin,
        peak,
        exact,
        nm,
        values,
        knots,
    }
}

/// A vector as an array, with `-0` written as `0`.
fn arr(v: DVec3) -> [f64; 3] {
    v.to_array().map(|x| x + 0.0)
}

fn quad(corner: DVec3, e1: DVec3, e2: DVec3) -> GeometryJson {
    let cross = e1.cross(e2);
    GeometryJson::Quad {
        corner: arr(corner),
        edge1: arr(e1),
        edge2: arr(e2),
        normal: arr(cross.normalize()),
        area: cross.length(),
        to_world: super::mitsuba::rectangle_matrix(corner, e1, e2),
    }
}

fn material(m: &Material, name: &str) -> MaterialJson {
    let mut out = MaterialJson {
        name: name.to_string(),
        kind: "lambert",
        reflectance: None,
        ior: None,
        sellmeier: None,
        thickness_nm: None,
    };
    match m {
        Material::Lambert { reflectance } => out.reflectance = Some(spectrum(reflectance)),
        Material::Mirror => out.kind = "mirror",
        Material::Dielectric { ior } => {
            out.kind = "dielectric";
            match ior {
                Ior::Constant(n) => out.ior = Some(*n),
                Ior::Sellmeier(fit) => {
                    let nm: Vec<f64> = super::grid().collect();
                    out.sellmeier = Some(SellmeierJson {
                        name: fit.name.clone(),
                        formula: "n^2 = 1 + sum_i B_i l^2 / (l^2 - C_i), l in micrometres",
                        terms: fit.terms.iter().map(|&(b, c)| [b, c]).collect(),
                        index: nm.iter().map(|&l| fit.index(l)).collect(),
                        nm,
                    });
                }
            }
        }
        Material::ThinFilm { ior, thickness } => {
            out.kind = "thin-film";
            out.ior = Some(*ior);
            out.thickness_nm = Some(ThicknessJson {
                bottom: thickness.bottom_nm,
                top: thickness.top_nm,
                y_range: thickness.y,
                model: "a film of index ior in air on both sides: reflectance and transmittance of the Airy sum (coherent, both polarisations averaged) at the thickness of the hit point's height; transmitted light goes straight on",
            });
        }
    }
    out
}

fn camera(s: &Scene) -> Camera {
    let c = &s.camera;
    let forward = (c.look_at - c.position).normalize();
    let right = forward.cross(c.up).normalize();
    let half_height = (c.fov_y_deg.to_radians() / 2.0).tan();
    Camera {
        position: arr(c.position),
        look_at: arr(c.look_at),
        up: arr(c.up),
        fov_y_deg: c.fov_y_deg,
        width: c.width,
        height: c.height,
        forward: arr(forward),
        right: arr(right),
        image_up: arr(right.cross(forward)),
        half_height,
        half_width: half_height * f64::from(c.width) / f64::from(c.height),
    }
}

// ANCHOR: to_json
/// The scene as fully resolved JSON (see the module's documentation), pretty-printed,
/// ending with a newline.
pub fn to_json(f: &SceneFile) -> String {
    let s = &f.scene;
    let m = cie::xyz_to_linear_srgb_matrix();
    let names: Vec<&str> = f.materials.iter().map(|(n, _)| n.as_str()).collect();
    let file = File {
        format: FORMAT,
        version: VERSION,
        source: &f.file,
        scene_hash: format!("{:016x}", s.hash),
        conventions: Conventions {
            spectra: "nm and values: the spectrum at every whole nanometre of 360-830 nm where it can be non-zero, linear in between and zero outside the first and last; exact says whether that is the spectrum itself over 360-830 nm (knots gives a table's own knots when it is not)",
            colour: "a pixel is linear sRGB: xyz_to_linear_srgb times XYZ = the integral over 360-830 nm of L(nm) times the CIE 1931 2-degree colour-matching functions (the 1 nm table, linear in between), divided by y_integral, so that a constant radiance 1 has Y = 1",
            wavelength_range_nm: [crate::spectral::LAMBDA_MIN, crate::spectral::LAMBDA_MAX],
            y_integral: cie::y_integral(),
            xyz_to_linear_srgb: [0, 1, 2].map(|i| m.row(i).to_array()),
            camera: "a pinhole at position; the ray through the image point (x, y), in pixels from the top-left corner, has the direction forward + sx half_width right + sy half_height image_up with sx = 2 x / width - 1, sy = 1 - 2 y / height; each sample uniform in its pixel (a box filter); a pixel is the mean of its samples",
            quad: "the parallelogram corner + a edge1 + b edge2, a and b in [0, 1]; seen from both sides",
            lights: "emitters reflect nothing and block rays; a quad light emits on the side of its normal only, a sphere light outwards only (nothing inside it is lit by it); emission is radiance per nm",
            dielectric: "a smooth boundary between the outside (index 1) and the inside (against the normal of a quad, inside a sphere): exact Fresnel reflectance and Snell refraction, no radiance scaling on refraction",
        },
        render: Render {
            spp: s.settings.spp,
            seed: s.settings.seed,
            wavelengths: s.settings.wavelengths.name(),
            direct: super::direct_name(s.settings.direct),
            roulette_depth: s.settings.roulette_depth,
            max_depth: s.settings.max_depth,
            max_depth_counts: MAX_DEPTH_COUNTS,
        },
        camera: camera(s),
        materials: s
            .materials
            .iter()
            .zip(&names)
            .map(|(m, n)| material(m, n))
            .collect(),
        shapes: s
            .shapes
            .iter()
            .map(|sh| {
                let (kind, geometry) = match sh.geometry {
                    Geometry::Quad(q) => {
                        let [e1, e2] = q.edges();
                        ("quad", quad(q.corner(), e1, e2))
                    }
                    Geometry::Sphere(sp) => (
                        "sphere",
                        GeometryJson::Sphere {
                            center: arr(sp.center),
                            radius: sp.radius,
                        },
                    ),
                };
                ShapeJson {
                    kind,
                    geometry,
                    material: sh.material,
                    material_name: names[sh.material].to_string(),
                }
            })
            .collect(),
        lights: s
            .lights
            .iter()
            .map(|l| {
                let (kind, geometry, emits) = match &l.shape {
                    LightShape::Quad(q) => {
                        let [e1, e2] = q.shape().edges();
                        (
                            "quad",
                            quad(q.shape().corner(), e1, e2),
                            "towards its normal",
                        )
                    }
                    LightShape::Sphere(sp) => (
                        "sphere",
                        GeometryJson::Sphere {
                            center: arr(sp.center()),
                            radius: sp.radius(),
                        },
                        "outwards only",
                    ),
                };
                LightJson {
                    kind,
                    geometry,
                    emits,
                    emission: spectrum(&l.emission),
                }
            })
            .collect(),
        environment: s.environment.as_ref().map(|e| match e {
            Environment::Constant(r) => EnvironmentJson::Constant {
                radiance: spectrum(r),
            },
            Environment::Gradient { axis, above, below } => EnvironmentJson::Gradient {
                axis: arr(*axis),
                above: Box::new(spectrum(above)),
                below: Box::new(spectrum(below)),
                rule: "L(w) = above (1 + c) / 2 + below (1 - c) / 2 with c = axis . w, w the unit direction away from the scene",
            },
        }),
    };
    // Plain numbers, strings and arrays: serialising them cannot fail.
    let mut text = inline_scalar_arrays(&serde_json::to_string_pretty(&file).unwrap_or_default());
    text.push('\n');
    text
}
// ANCHOR_END: to_json

/// serde_json's pretty JSON with every array of scalars on one line (a spectrum's 471
/// samples are one line, not 471): inside such an array, the line breaks and indents
/// between elements become single spaces. Strings are copied as they are.
fn inline_scalar_arrays(pretty: &str) -> String {
    let b = pretty.as_bytes();
    let mut out = String::with_capacity(pretty.len());
    let mut i = 0;
    // Copies the string starting at b[i] (a quote) and returns the index after it.
    let string_end = |mut j: usize| {
        j += 1;
        while j < b.len() && b[j] != b'"' {
            j += if b[j] == b'\\' { 2 } else { 1 };
        }
        j + 1
    };
    while i < b.len() {
        match b[i] {
            b'"' => {
                let j = string_end(i).min(b.len());
                out.push_str(&pretty[i..j]);
                i = j;
            }
            b'[' => {
                // Scan to the closing bracket; give up at a nested array or object.
                let (mut j, mut flat) = (i + 1, true);
                while j < b.len() && b[j] != b']' {
                    match b[j] {
                        b'"' => j = string_end(j),
                        b'[' | b'{' => {
                            flat = false;
                            break;
                        }
                        _ => j += 1,
                    }
                }
                if flat && j < b.len() {
                    let mut k = i + 1;
                    out.push('[');
                    let mut first = true;
                    while k < j {
                        if b[k].is_ascii_whitespace() {
                            k += 1;
                            continue;
                        }
                        let start = k;
                        while k < j && b[k] != b',' {
                            k = if b[k] == b'"' { string_end(k) } else { k + 1 };
                        }
                        if !first {
                            out.push_str(", ");
                        }
                        out.push_str(pretty[start..k].trim_end());
                        first = false;
                        k += 1;
                    }
                    out.push(']');
                    i = j + 1;
                } else {
                    out.push('[');
                    i += 1;
                }
            }
            _ => {
                // Copy up to the next quote or bracket (ASCII, so always a char boundary).
                let j = (i + 1..b.len())
                    .find(|&j| b[j] == b'"' || b[j] == b'[')
                    .unwrap_or(b.len());
                out.push_str(&pretty[i..j]);
                i = j;
            }
        }
    }
    out
}
