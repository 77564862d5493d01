//! What a differing image looks like: the conformance card's diagnosis. Chapter:
//! *Reference scenes and interop* (`chapters/renderer/scenes.md`, *Reading the card*).
//!
//! A comparison says *that* a candidate differs from the reference and where the worst
//! block is. The common mistakes of a renderer leave recognisable marks on the whole
//! image, and each is a hypothesis that can be tested: the candidate with the mistake
//! undone is compared with the reference again, by the same test
//! ([`crate::conformance::compare::compare`]) at the same level. A hypothesis *explains* the
//! difference when the undone candidate agrees; it *explains most of it* when it leaves at
//! most 20 % of the failing tests of blocks and of the whole image, and of the excess of
//! the blocks' `Σ z²` over its expectation (one per block and channel).
//!
//! * a uniform factor `k = Σ c / Σ r` (all three channels alike: a light's power, the `1/π`
//!   of a BRDF, a normalisation), or one factor per channel (the colour conversion);
//! * a gamma-encoded image: the candidate through the sRGB decoding is compared;
//! * a field of view: the reference magnified about the image's centre by `m`
//!   (bilinear), the best `m` from 0.9 to 1.1 to 0.001, is compared; the candidate's
//!   vertical field of view is then `2 atan(tan(fov/2) / m)`;
//! * a shift: the reference moved by whole pixels, `(dx, dy)` in `{-2, ..., 2}²`, the best
//!   of them compared (pixel centres off by one, or the raster's y range flipped);
//! * CIE XYZ saved as R, G, B ([`xyz_swapped`]): the candidate through the XYZ-to-sRGB
//!   matrix is compared;
//! * another maximum depth: the candidate against the rung's references at its other
//!   depths;
//! * and, as a pointer rather than a test, the factor `Σ c / Σ r` over the pixels where
//!   the camera sees each material directly, with its standard error, for the materials
//!   that differ by more than four of them.

use glam::{DMat3, DVec2, DVec3};

use crate::conformance::compare::{Comparison, Estimate, Region, compare, compare_blocks};
use crate::image::{Image, ImageError};
use crate::render::camera::Camera;
use crate::render::scene::{Scene, Surface};
use crate::spectral::cie::xyz_to_linear_srgb_matrix;

/// The fraction of the failing tests, and of the excess of the blocks' `Σ z²`, a
/// hypothesis must remove to be reported as explaining most of a difference.
pub(crate) const MOST: f64 = 0.8;

/// What the card is given besides the two images.
pub struct Context<'a> {
    /// The rung's number on the ladder (`conformance::ladder::LADDER`), 0 for a scene of
    /// no rung.
    pub rung: u32,
    /// The rung's scene at the compared depth (its camera, its materials' names).
    pub scene: &'a Scene,
    /// The materials' names, in the order of [`Scene::materials`].
    pub materials: &'a [String],
    /// The rung's references at its other depths: `(depth, reference)`, `None` unbounded.
    pub other_depths: Vec<(Option<u32>, Estimate)>,
}

/// The diagnosis of a candidate that differs from `reference` at the test level `level`:
/// one sentence per finding, the most telling first. Empty when nothing fits.
pub fn diagnose(
    reference: &Estimate,
    candidate: &Estimate,
    level: f64,
    context: &Context,
) -> Vec<String> {
    let Ok(base) = compare(reference, candidate, level) else {
        return Vec::new();
    };
    let (fail0, excess0) = (failures(&base), excess(&base.regions));
    // (rank, sentence): a full explanation ranks above every partial one, and partial
    // ones by how few failing tests they leave.
    let mut found: Vec<(f64, String)> = Vec::new();
    let (k, se) = factor(reference, candidate, |_| true);
    let channel = [0, 1, 2].map(|c| channel_factor(reference, candidate, c));
    if k < 0.05 {
        found.push((
            3.0,
            format!(
                "the candidate has {:.1} % of the reference's light: it misses what every path of this rung carries (light sampling, or a maximum depth counted one bounce short: raylemma's max_depth counts bounces, so max_depth = 1 is paths of two segments)",
                100.0 * k
            ),
        ));
    }
    let mut judge = |undone: Result<Comparison, ImageError>, what: String| {
        if let Ok(c) = undone {
            let (fail, left) = (failures(&c), excess(&c.regions) / excess0);
            if c.agree() {
                found.push((2.0, format!("{what}: undoing it, the candidate AGREES")));
            } else if fail as f64 <= (1.0 - MOST) * fail0 as f64 && left <= 1.0 - MOST {
                found.push((
                    1.0 - fail as f64 / fail0 as f64,
                    format!(
                        "{what}: undoing it leaves {fail} of the {fail0} failing tests of blocks and of the whole image"
                    ),
                ));
            }
        }
    };

    judge(
        compare(reference, &scaled(candidate, DVec3::splat(1.0 / k)), level),
        format!(
            "a uniform factor: the candidate is {k:.4} ± {se:.4} times the reference in all channels (a light's power, the 1/π of a BRDF, a normalisation)"
        ),
    );
    // XYZ saved as R, G, B: fixed by the matrix, no factor fitted; when it explains the
    // difference, the three fitted factors per channel are not tried (on a grey image they
    // fit it too).
    let mut xyz_agrees = false;
    if xyz_swapped(&reference.image, &candidate.image, false).is_some() {
        let undone = compare(
            reference,
            &transformed(candidate, xyz_to_linear_srgb_matrix()),
            level,
        );
        xyz_agrees = undone.as_ref().is_ok_and(Comparison::agree);
        judge(
            undone,
            "CIE XYZ saved as R, G, B: the candidate's channels, taken as X, Y, Z and converted to linear sRGB (write linear sRGB, or name the channels X, Y, Z)".to_string(),
        );
    }
    let per = DVec3::new(channel[0], channel[1], channel[2]);
    if !xyz_agrees && (per - DVec3::splat(k)).abs().max_element() > 3.0 * se {
        judge(
            compare(reference, &scaled(candidate, DVec3::ONE / per), level),
            format!(
                "one factor per channel: R {:.4}, G {:.4}, B {:.4} times the reference (the colour conversion: the XYZ-to-sRGB matrix or the CIE normalisation, or a spectrum's values)",
                per.x, per.y, per.z
            ),
        );
    }
    judge(
        compare(reference, &decoded(candidate), level),
        "the image is gamma-encoded: its values went through the sRGB encoding (save linear values, as an EXR holds them)".to_string(),
    );
    if let Some((m, c)) = best_magnification(reference, candidate, level) {
        let fov = context.scene.camera.fov_y_deg;
        let fov_c = 2.0 * ((fov.to_radians() / 2.0).tan() / m).atan().to_degrees();
        judge(
            Ok(c),
            format!(
                "the camera: the candidate is the reference magnified {m:.3} times about the centre, as if seen with a vertical field of view of {fov_c:.1}° instead of {fov}° (the field of view, its axis, or the camera's position)"
            ),
        );
    }
    if let Some(((dx, dy), c)) = best_shift(reference, candidate, level) {
        judge(
            Ok(c),
            format!(
                "{}: the pixel centres (half a pixel, or a pixel, off) or the raster's {} range",
                shift_words(dx, dy),
                if dx != 0 && dy != 0 {
                    "x and y"
                } else if dx != 0 {
                    "x"
                } else {
                    "y"
                }
            ),
        );
    }
    for (d, r) in &context.other_depths {
        let name = d.map_or("unbounded depth".to_string(), |d| format!("depth {d}"));
        judge(
            compare(r, candidate, level),
            format!(
                "the maximum depth: the candidate is this rung's reference at {name} (a depth counted differently: raylemma's max_depth counts bounces, no light sampled at the last)"
            ),
        );
    }
    found.sort_by(|a, b| b.0.total_cmp(&a.0));
    let explained = !found.is_empty();
    let uniform = found.iter().any(|f| f.1.starts_with("a uniform factor"));
    let mut lines: Vec<String> = found.into_iter().map(|(_, s)| s).collect();
    if uniform && context.rung == 1 {
        lines.push(UNIFORM_ON_DIRECT_LIGHT.to_string());
    }
    if !explained {
        let materials = by_material(reference, candidate, context, k, se);
        let fit = index_fit(reference, candidate, level, context, &materials);
        lines.extend(materials);
        lines.extend(fit);
    }
    lines
}

/// What a uniform factor leaves open on rung 1 (one quad light over a Lambertian floor,
/// direct light only), and the rungs that tell the causes apart.
pub const UNIFORM_ON_DIRECT_LIGHT: &str = "this rung cannot tell these causes of a uniform factor apart: the light's power, the BRDF's 1/π and the light's pdf scale its image alike. Rung 2 (a sphere light) keeps a factor of the power or of the 1/π, not one of the quad light's pdf; rung 3 (two lights of different power) adds the choice of a light; rung 6, where the light is seen in a mirror with no BRDF and no light sampling, keeps only a factor of the power";

/// The excess of the blocks' `Σ z²` over its expectation (one per block and channel), at
/// least one.
fn excess(regions: &[Region]) -> f64 {
    let sum: f64 = regions.iter().map(|r| r.zs.length_squared()).sum();
    (sum - 3.0 * regions.len() as f64).max(1.0)
}

/// The failing tests of a comparison that a smooth mistake shows in: the blocks and the
/// whole image's channels (a pixel's test, on a few runs' spread, is too noisy to weigh
/// hypotheses by).
fn failures(c: &Comparison) -> usize {
    c.block_failure_count + c.image_failure_count()
}

/// `Σ c / Σ r` over the pixels `keep` selects and all channels, with its standard error
/// from both images' variances.
fn factor(reference: &Estimate, candidate: &Estimate, keep: impl Fn(usize) -> bool) -> (f64, f64) {
    let (r, c) = (&reference.image, &candidate.image);
    let (mut sr, mut sc, mut vr, mut vc) = (0.0, 0.0, 0.0, 0.0);
    for i in (0..r.mean.len()).filter(|&i| keep(i)) {
        sr += r.mean[i].element_sum();
        sc += c.mean[i].element_sum();
        vr += finite(r.var[i]).element_sum();
        vc += finite(c.var[i]).element_sum();
    }
    let k = sc / sr;
    (k, (vc + k * k * vr).sqrt() / sr.abs())
}

fn channel_factor(reference: &Estimate, candidate: &Estimate, ch: usize) -> f64 {
    let sr: f64 = reference.image.mean.iter().map(|m| m[ch]).sum();
    let sc: f64 = candidate.image.mean.iter().map(|m| m[ch]).sum();
    sc / sr
}

fn finite(v: DVec3) -> DVec3 {
    DVec3::new(
        if v.x.is_finite() { v.x } else { 0.0 },
        if v.y.is_finite() { v.y } else { 0.0 },
        if v.z.is_finite() { v.z } else { 0.0 },
    )
}

/// A candidate that differs from the reference in colour the way one does whose CIE XYZ
/// values are written as R, G, B (a spectral film's output under the wrong names), or, if
/// it was read from X, Y, Z (`from_xyz`), whose channels were sRGB all along: the whole
/// image's mean colour, put through the XYZ-to-sRGB matrix (or its inverse), lands within
/// 5 % of the reference's and at least four times closer than as read. The sentence says
/// so; `raylemma compare` prints it as a hint, the card as a finding.
pub fn xyz_swapped(reference: &Image, candidate: &Image, from_xyz: bool) -> Option<String> {
    let mean = |i: &Image| i.mean.iter().copied().sum::<DVec3>() / i.mean.len() as f64;
    let (r, c) = (mean(reference), mean(candidate));
    let m = xyz_to_linear_srgb_matrix();
    let (swapped, question) = if from_xyz {
        (
            m.inverse() * c,
            "once its X, Y, Z are taken as linear sRGB: are they sRGB under the names X, Y, Z?",
        )
    } else {
        (
            m * c,
            "once its R, G, B are taken as CIE XYZ and converted to linear sRGB: are they XYZ \
             under the names R, G, B? compare reads R, G, B as linear sRGB, as raylemma writes \
             them, and X, Y, Z as CIE XYZ, as Mitsuba's spectral films write them",
        )
    };
    let off = |x: DVec3| (x - r).length() / r.length();
    let (as_read, if_swapped) = (off(c), off(swapped));
    (if_swapped < 0.05 && if_swapped * 4.0 < as_read).then(|| {
        format!(
            "the candidate's mean colour is {:.1} % from the reference's, but {:.1} % {question}",
            100.0 * as_read,
            100.0 * if_swapped,
        )
    })
}

/// The estimate with every mean put through the matrix `m`, its variance through the
/// matrix of `m`'s squared entries (the channels taken as independent).
fn transformed(e: &Estimate, m: DMat3) -> Estimate {
    let sq = DMat3::from_cols(
        m.x_axis * m.x_axis,
        m.y_axis * m.y_axis,
        m.z_axis * m.z_axis,
    );
    let mut out = e.clone();
    for (mean, v) in out.image.mean.iter_mut().zip(out.image.var.iter_mut()) {
        *mean = m * *mean;
        *v = sq * *v;
    }
    out
}

/// The estimate with every mean multiplied by `s` (its variance by `s²`).
fn scaled(e: &Estimate, s: DVec3) -> Estimate {
    let mut out = e.clone();
    for (m, v) in out.image.mean.iter_mut().zip(out.image.var.iter_mut()) {
        *m *= s;
        *v *= s * s;
    }
    out
}

/// The sRGB decoding of a value (odd in its sign) and its derivative. Not
/// `spectral::display::srgb_decode`: that is an exercise, a stub in the student edition,
/// and the card must diagnose whatever the student has left unfinished; the derivative is
/// needed here too.
fn srgb_decode(x: f64) -> (f64, f64) {
    let a = x.abs();
    let (y, dy) = if a <= 0.04045 {
        (a / 12.92, 1.0 / 12.92)
    } else {
        let b = (a + 0.055) / 1.055;
        (b.powf(2.4), 2.4 / 1.055 * b.powf(1.4))
    };
    (y.copysign(x), dy)
}

/// The estimate through the sRGB decoding, its variance by the delta method.
fn decoded(e: &Estimate) -> Estimate {
    let mut out = e.clone();
    for (m, v) in out.image.mean.iter_mut().zip(out.image.var.iter_mut()) {
        for c in 0..3 {
            let (y, dy) = srgb_decode(m[c]);
            m[c] = y;
            v[c] *= dy * dy;
        }
    }
    out
}

/// The image magnified `m` times about its centre: the value at pixel centre `p` is the
/// original's at `centre + (p - centre) / m`, bilinear between pixel centres (edge pixels
/// repeated beyond the border).
pub(crate) fn magnified(image: &Image, m: f64) -> Image {
    let (w, h) = (image.width as usize, image.height as usize);
    let centre = DVec2::new(w as f64 / 2.0, h as f64 / 2.0);
    let at = |v: &[DVec3], x: isize, y: isize| {
        let x = x.clamp(0, w as isize - 1) as usize;
        let y = y.clamp(0, h as isize - 1) as usize;
        v[y * w + x]
    };
    let sample = |v: &[DVec3], p: DVec2, square: bool| {
        let q = centre + (p - centre) / m - DVec2::splat(0.5);
        let (x0, y0) = (q.x.floor(), q.y.floor());
        let (fx, fy) = (q.x - x0, q.y - y0);
        let (x0, y0) = (x0 as isize, y0 as isize);
        // Means interpolate linearly; the variance of a weighted sum of independent
        // pixels has the squared weights.
        let wt = |f: f64| if square { f * f } else { f };
        at(v, x0, y0) * wt((1.0 - fx) * (1.0 - fy))
            + at(v, x0 + 1, y0) * wt(fx * (1.0 - fy))
            + at(v, x0, y0 + 1) * wt((1.0 - fx) * fy)
            + at(v, x0 + 1, y0 + 1) * wt(fx * fy)
    };
    let mut out = image.clone();
    for y in 0..h {
        for x in 0..w {
            let p = DVec2::new(x as f64 + 0.5, y as f64 + 0.5);
            out.mean[y * w + x] = sample(&image.mean, p, false);
            out.var[y * w + x] = sample(&image.var, p, true);
        }
    }
    out
}

/// The magnification of the reference, from 0.9 to 1.1 (steps of 0.005, then of 0.001
/// about the best), that leaves the least excess of the blocks' `Σ z²` against the
/// candidate away from the border (a twentieth of the image and a pixel: there the
/// candidate's own values stand in), with that comparison; `None` when 1 is best. On rung 1 (40°) that range is a field of view from about
/// 37° to 43.6°.
fn best_magnification(
    reference: &Estimate,
    candidate: &Estimate,
    level: f64,
) -> Option<(f64, Comparison)> {
    // Judged away from the border, where a reference made smaller (a candidate's wider
    // view) would need what lies beyond its frame.
    let border =
        (0.05 * f64::from(reference.image.width.min(reference.image.height))).ceil() as u32 + 1;
    let best_of = |ms: &mut dyn Iterator<Item = f64>| {
        let mut best: Option<(f64, f64)> = None;
        for m in ms {
            let mut r = Estimate {
                image: magnified(&reference.image, m),
                ..reference.clone()
            };
            interior(&mut r.image, &candidate.image, border);
            if let Ok(blocks) = compare_blocks(&r, candidate, level) {
                let e = excess(&blocks);
                if best.is_none_or(|b| e < b.1) {
                    best = Some((m, e));
                }
            }
        }
        best
    };
    // Steps of 0.005, then steps of 0.001 about the best of them.
    let coarse = best_of(&mut (-20..=20).map(|i| 1.0 + f64::from(i) * 5e-3))?.0;
    let (m, _) = best_of(&mut (-4..=4).map(|i| coarse + f64::from(i) * 1e-3))?;
    if m == 1.0 {
        return None;
    }
    let mut r = Estimate {
        image: magnified(&reference.image, m),
        ..reference.clone()
    };
    interior(&mut r.image, &candidate.image, border);
    compare(&r, candidate, level).ok().map(|c| (m, c))
}

/// `r` with the means of the pixels within `border` of the edge taken from `c`: they
/// agree there, whatever lies beyond `r`'s frame.
fn interior(r: &mut Image, c: &Image, border: u32) {
    let (w, h) = (r.width, r.height);
    for y in 0..h {
        for x in 0..w {
            if x < border || y < border || x + border >= w || y + border >= h {
                let i = (y * w + x) as usize;
                r.mean[i] = c.mean[i];
            }
        }
    }
}

/// The image moved by `(dx, dy)` pixels (`y` down): the value at pixel `(x, y)` is the
/// original's at `(x - dx, y - dy)`, edge pixels repeated beyond the border.
pub(crate) fn shifted(image: &Image, dx: i32, dy: i32) -> Image {
    let (w, h) = (image.width as i32, image.height as i32);
    let at = |x: i32, y: i32| ((y - dy).clamp(0, h - 1) * w + (x - dx).clamp(0, w - 1)) as usize;
    let mut out = image.clone();
    for y in 0..h {
        for x in 0..w {
            out.mean[(y * w + x) as usize] = image.mean[at(x, y)];
            out.var[(y * w + x) as usize] = image.var[at(x, y)];
        }
    }
    out
}

/// The shifts tried: every `(dx, dy)` in `{-2, ..., 2}²` but `(0, 0)`.
const SHIFTS: i32 = 2;

/// The shift of the reference by whole pixels, `(dx, dy)` in `{-2, ..., 2}²` but
/// `(0, 0)`, that leaves the least excess of the blocks' `Σ z²` against the candidate,
/// with that comparison; `None` when it leaves more than no shift does.
fn best_shift(
    reference: &Estimate,
    candidate: &Estimate,
    level: f64,
) -> Option<((i32, i32), Comparison)> {
    let base = excess(&compare_blocks(reference, candidate, level).ok()?);
    let mut best: Option<((i32, i32), f64)> = None;
    for dy in -SHIFTS..=SHIFTS {
        for dx in -SHIFTS..=SHIFTS {
            if (dx, dy) == (0, 0) {
                continue;
            }
            let r = Estimate {
                image: shifted(&reference.image, dx, dy),
                ..reference.clone()
            };
            if let Ok(blocks) = compare_blocks(&r, candidate, level) {
                let e = excess(&blocks);
                if best.is_none_or(|b| e < b.1) {
                    best = Some(((dx, dy), e));
                }
            }
        }
    }
    let ((dx, dy), _) = best.filter(|b| b.1 < base)?;
    let r = Estimate {
        image: shifted(&reference.image, dx, dy),
        ..reference.clone()
    };
    compare(&r, candidate, level).ok().map(|c| ((dx, dy), c))
}

/// "the image is shifted by one pixel down", and the like (`y` down).
fn shift_words(dx: i32, dy: i32) -> String {
    let part = |d: i32, neg: &str, pos: &str| {
        let n = ["", "one pixel", "two pixels"][d.unsigned_abs().min(2) as usize];
        format!("{n} {}", if d < 0 { neg } else { pos })
    };
    let parts: Vec<String> = [(dx, "left", "right"), (dy, "up", "down")]
        .into_iter()
        .filter(|p| p.0 != 0)
        .map(|(d, neg, pos)| part(d, neg, pos))
        .collect();
    format!("the image is shifted by {}", parts.join(" and "))
}

/// When the per-material step names a dielectric of one index: the index, of the scene's
/// and four near it (±0.05, ±0.1), at which raylemma's own render (256 samples a pixel)
/// leaves the least excess of the blocks' `Σ z²` against the candidate, if not the
/// scene's.
fn index_fit(
    reference: &Estimate,
    candidate: &Estimate,
    level: f64,
    context: &Context,
    materials: &[String],
) -> Option<String> {
    use crate::render::scene::{Ior, Material};
    let scene = context.scene;
    let (m, n0) = scene
        .materials
        .iter()
        .enumerate()
        .find_map(|(i, m)| match m {
            Material::Dielectric {
                ior: Ior::Constant(n),
            } => {
                let name = format!("material {:?}", context.materials.get(i)?);
                materials
                    .iter()
                    .any(|l| l.starts_with(&format!("where the camera sees {name}")))
                    .then_some((i, *n))
            }
            _ => None,
        })?;
    let size = (reference.image.width, reference.image.height);
    let mut best: Option<(f64, f64)> = None;
    for dn in [-0.1, -0.05, 0.0, 0.05, 0.1] {
        let mut s = scene.clone();
        s.materials[m] = Material::Dielectric {
            ior: Ior::Constant(n0 + dn),
        };
        let image = crate::render::render(&s, 256, crate::render::Progress::Silent);
        if (image.width, image.height) != size {
            return None;
        }
        if let Ok(blocks) = compare_blocks(&Estimate::from_variance(image), candidate, level) {
            let e = excess(&blocks);
            if best.is_none_or(|b| e < b.1) {
                best = Some((n0 + dn, e));
            }
        }
    }
    let (n, _) = best.filter(|b| b.0 != n0)?;
    Some(format!(
        "the material {:?} behaves as if its index were {n:.2}, not {n0} (raylemma's render at indices {:.2} to {:.2} nearest the candidate)",
        context.materials.get(m).map_or("?", String::as_str),
        n0 - 0.1,
        n0 + 0.1
    ))
}

/// The material, light or background the camera sees through each pixel's centre.
pub fn labels(scene: &Scene, materials: &[String]) -> Vec<String> {
    let camera = Camera::new(&scene.camera);
    let (w, h) = (scene.camera.width, scene.camera.height);
    let mut out = Vec::with_capacity((w * h) as usize);
    for y in 0..h {
        for x in 0..w {
            let ray = camera.ray(x, y, DVec2::splat(0.5));
            out.push(match scene.intersect(ray.origin, ray.dir) {
                None => "the background".to_string(),
                Some(hit) => match hit.surface {
                    Surface::Shape(i) => {
                        let m = scene.shapes[i].material;
                        format!(
                            "material {:?}",
                            materials.get(m).map_or("?", String::as_str)
                        )
                    }
                    Surface::Light(i) => format!("light {}", i + 1),
                },
            });
        }
    }
    out
}

/// The factor per material seen directly, for those that differ from 1 by more than four
/// standard errors, the furthest first, and the ones that agree (a pointer to which
/// surface is wrong).
fn by_material(
    reference: &Estimate,
    candidate: &Estimate,
    context: &Context,
    k: f64,
    se: f64,
) -> Vec<String> {
    let labels = labels(context.scene, context.materials);
    if labels.len() != reference.image.mean.len() {
        return Vec::new();
    }
    let mut names: Vec<&String> = labels.iter().collect();
    names.sort();
    names.dedup();
    let mut off: Vec<(f64, String)> = Vec::new();
    let mut fine = Vec::new();
    for name in names {
        let n = labels.iter().filter(|l| *l == name).count();
        if n < 8 {
            continue;
        }
        let (kl, sel) = factor(reference, candidate, |i| labels[i] == *name);
        if !kl.is_finite() {
            continue;
        }
        if (kl - 1.0).abs() > 4.0 * sel {
            off.push((
                (kl - 1.0).abs() / sel,
                format!(
                    "where the camera sees {name} ({n} pixels) the candidate is {:+.2} % ± {:.2} %",
                    100.0 * (kl - 1.0),
                    100.0 * sel
                ),
            ));
        } else {
            fine.push(name.clone());
        }
    }
    if off.is_empty() {
        return Vec::new();
    }
    off.sort_by(|a, b| b.0.total_cmp(&a.0));
    let mut lines: Vec<String> = off.into_iter().map(|(_, s)| s).collect();
    if !fine.is_empty() {
        lines.push(format!(
            "it agrees where the camera sees {}",
            fine.join(", ")
        ));
    }
    lines.push(format!(
        "over the whole image it is {:+.2} % ± {:.2} %",
        100.0 * (k - 1.0),
        100.0 * se
    ));
    lines
}
