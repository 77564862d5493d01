//! The spectral path tracer: the radiance along one path ([`radiance`]), with next-event
//! estimation and multiple importance sampling, Russian roulette and hero wavelengths, and
//! the offset of a ray leaving a surface ([`offset_origin`]). The scene answers the
//! geometric questions ([`super::scene`]); the pixels and tiles are the driver's
//! ([`super::pixel`], [`super::driver`]). Chapter: *The path tracer*
//! (`chapters/renderer/path-tracer.md`), which writes out the estimator this loop computes.
//!
//! Every interaction is one of the book's modules, unchanged: the stable ray-sphere
//! intersection, the parallelogram and sphere lights with their area-to-solid-angle pdfs
//! and the power heuristic (*Shadow-ray pdfs*), Malley's cosine-weighted sampling and the
//! tangent frame (*Sampling*), exact Fresnel and Snell refraction (*Optics*), the Sellmeier
//! index and the Airy sum of a thin film, Russian roulette, and hero wavelengths with the
//! termination of secondary lanes at a dispersive refraction (*Spectral*).

use std::f64::consts::FRAC_1_PI;

use glam::{DVec2, DVec3};
use rand::{Rng, RngExt};

use super::scene::{DirectLight, Ior, Material, Surface};
use super::tracer::Tracer;
use crate::optics::fresnel::fresnel_dielectric;
use crate::optics::reflect::{reflect, refract};
use crate::optics::thinfilm::Film;
use crate::sampling::cosine::cosine_malley;
use crate::sampling::frame::Frame;
use crate::spectral::spectrum::WholeNm;
use crate::spectral::wavelength::{N, Wavelengths};
use crate::transport::roulette::roulette;

/// Radiance (or throughput) at the path's `N` wavelengths.
pub(crate) type Lanes = [f64; N];

// ANCHOR: offset
/// The relative size of the offset that moves a new ray's origin off the surface it
/// leaves: `1e-9 (1 + max |p_i|)` along the normal, on the side the ray goes. Double
/// precision puts the rounding error of a hit point near `1e-16 max |p_i|` (the sphere's
/// hit point is also projected back onto it), so the margin is some seven orders of
/// magnitude, while `1e-9` of the scene's size is far below anything a pixel resolves.
pub const OFFSET: f64 = 1e-9;

/// The origin of a ray leaving the surface point `p` (unit normal `n`, either side) in
/// direction `dir`: `p` pushed by [`OFFSET`] to the side `dir` points to, so that the ray
/// can neither hit the surface it starts on (acne) nor start behind it (light leaking
/// through a wall).
pub fn offset_origin(p: DVec3, n: DVec3, dir: DVec3) -> DVec3 {
    let eps = OFFSET * (1.0 + p.abs().max_element());
    if dir.dot(n) >= 0.0 {
        p + eps * n
    } else {
        p - eps * n
    }
}
// ANCHOR_END: offset

/// The relative margin by which a shadow ray stops short of the point it was sent to: a
/// surface nearer than `(1 - SHADOW_MARGIN) r` blocks it. The light's own hit lies at `r`
/// to within rounding (`1e-16 r`), so the margin leaves it out whatever its orientation,
/// while anything a pixel could resolve in front of the light still blocks.
pub(crate) const SHADOW_MARGIN: f64 = 1e-9;

/// Spectra evaluated at the path's wavelengths once per path: a path's wavelengths never
/// change (a dispersive refraction only ends the secondary lanes), so the reflectance of
/// material `i` and the emission of light `i` are the same at every bounce. The first
/// `K` of each are kept; any beyond are evaluated each time.
struct PerPath<const K: usize>([Option<Lanes>; K]);

impl<const K: usize> PerPath<K> {
    fn new() -> Self {
        PerPath([None; K])
    }

    /// Entry `i`, evaluated by `eval` the first time.
    fn get(&mut self, i: usize, eval: impl FnOnce() -> Lanes) -> Lanes {
        match self.0.get_mut(i) {
            Some(slot) => *slot.get_or_insert_with(eval),
            None => eval(),
        }
    }
}

// ANCHOR: radiance
// ANCHOR: loop_head
/// The radiance arriving at `o` from the direction `-d` (`d` of unit length), at the
/// wavelengths `wl`, estimated along one path. `wl` may be changed: a dispersive
/// refraction terminates the secondary lanes.
#[inline(always)]
pub fn radiance(
    tracer: &Tracer,
    o: DVec3,
    d: DVec3,
    wl: &mut Wavelengths,
    rng: &mut impl Rng,
) -> Lanes {
    let scene = tracer.scene;
    let s = &scene.settings;
    let mut l = [0.0; N];
    let mut beta = [1.0; N];
    let (mut o, mut d) = (o, d);
    // The density with which the last bounce drew `d`; `None` after a delta bounce (or at
    // the camera), where a light that is hit counts in full.
    let mut bsdf_pdf: Option<f64> = None;
    let light_choice = 1.0 / scene.lights.len().max(1) as f64;
    let (mut reflectances, mut emissions) = (PerPath::<8>::new(), PerPath::<4>::new());
    // The wavelengths split into whole nanometres once, for every table read by index.
    let nm = wl.lambda.map(WholeNm::of);
    for depth in 0..=s.max_depth {
        let Some(hit) = tracer.intersect(o, d) else {
            if let Some(env) = &scene.environment {
                for j in 0..N {
                    l[j] += beta[j] * env.eval(d, wl.lambda[j]);
                }
            }
            break;
        };
        let i = match hit.surface {
            // ANCHOR: hit_light
            Surface::Light(k) => {
                if scene.emits_towards(k, o, d) {
                    // A light reached by a delta bounce (or seen from the camera) counts in
                    // full; one reached by BSDF sampling counts with the strategy's weight.
                    let w = match (bsdf_pdf, s.direct) {
                        (None, _) | (Some(_), DirectLight::Bsdf) => 1.0,
                        (Some(_), DirectLight::Light) => 0.0,
                        (Some(pb), DirectLight::Mis(h)) => {
                            let pl = light_choice
                                * scene.lights[k].light_with(s.light_sampling).pdf(o, d);
                            h.weight(pb, pl)
                        }
                    };
                    let le = emissions.get(k, || tracer.emission(k, &nm));
                    for j in 0..N {
                        l[j] += w * beta[j] * le[j];
                    }
                }
                break; // lights reflect nothing
            }
            // ANCHOR_END: hit_light
            Surface::Shape(i) => i,
        };
        let (p, n) = scene.surface_point(i, o, d, hit.t);
        match &scene.materials[scene.shapes[i].material] {
            // ANCHOR_END: loop_head
            // ANCHOR: lambert
            Material::Lambert { .. } => {
                // Shade on the side the ray arrived from (two-sided).
                let n = if n.dot(d) < 0.0 { n } else { -n };
                let material = scene.shapes[i].material;
                let rho = reflectances.get(material, || tracer.reflectance(material, &nm));
                let po = offset_origin(p, n, n);
                let (u_pick, u_light, u_bsdf) = (
                    rng.random::<f64>(),
                    DVec2::new(rng.random(), rng.random()),
                    DVec2::new(rng.random(), rng.random()),
                );
                // The next direction, cosine-weighted (f cos / p = rho), drawn first: it
                // does not depend on the light, so the processor can work on it while the
                // light's sample and shadow ray wait on their square roots and divisions.
                let local = cosine_malley(u_bsdf);
                let next = Frame::from_normal(n).to_world(local).normalize();
                // Next-event estimation: one light, chosen uniformly, one point on it;
                // not at the last vertex, where the BSDF half of the same paths (one
                // bounce longer) is never traced: a path of at most `max_depth` bounces
                // has the same expectation whichever strategy found its light.
                if depth < s.max_depth && s.direct != DirectLight::Bsdf && !scene.lights.is_empty()
                {
                    let k =
                        ((u_pick * scene.lights.len() as f64) as usize).min(scene.lights.len() - 1);
                    let light = &scene.lights[k];
                    if let Some(ls) = light.light_with(s.light_sampling).sample(po, u_light) {
                        let cos = n.dot(ls.dir);
                        // The light's point is seen if nothing lies before it (the
                        // margin keeps the light itself, at `ls.dist` to rounding, out).
                        if cos > 0.0
                            && ls.cos_light < 0.0
                            && !tracer.occluded(po, ls.dir, ls.dist * (1.0 - SHADOW_MARGIN))
                        {
                            let pl = light_choice * ls.pdf;
                            let w = match s.direct {
                                DirectLight::Mis(h) => h.weight(pl, cos * FRAC_1_PI),
                                _ => 1.0,
                            };
                            let le = emissions.get(k, || tracer.emission(k, &nm));
                            // f cos w / p, with f = rho / pi: the scalar part once.
                            let g = FRAC_1_PI * cos * w / pl;
                            for j in 0..N {
                                l[j] += beta[j] * rho[j] * le[j] * g;
                            }
                        }
                    }
                }
                d = next;
                bsdf_pdf = Some(local.z * FRAC_1_PI);
                o = po;
                for j in 0..N {
                    beta[j] *= rho[j];
                }
            }
            // ANCHOR_END: lambert
            // ANCHOR: mirror
            Material::Mirror => {
                d = reflect(d, n);
                o = offset_origin(p, n, d);
                bsdf_pdf = None;
            }
            // ANCHOR_END: mirror
            // ANCHOR: dielectric
            Material::Dielectric { ior } => {
                if matches!(ior, Ior::Sellmeier(_)) {
                    // The direction depends on the wavelength: only the hero can follow it.
                    wl.terminate_secondary();
                }
                let eta = ior.at(wl.lambda[0]);
                let entering = d.dot(n) < 0.0;
                let (n1, n2) = if entering { (1.0, eta) } else { (eta, 1.0) };
                let f = fresnel_dielectric(d.dot(n).abs(), n1, n2);
                // Reflect with probability F, refract with 1 - F: the weight F / F is 1.
                d = match refract(d, n, n1, n2).transmitted() {
                    Some(t) if rng.random::<f64>() >= f => t,
                    _ => reflect(d, n),
                };
                o = offset_origin(p, n, d);
                bsdf_pdf = None;
            }
            // ANCHOR_END: dielectric
            // ANCHOR: thin_film
            Material::ThinFilm { ior, thickness } => {
                let film = Film::new(1.0, *ior, 1.0, thickness.at(p.y));
                let cos1 = d.dot(n).abs().min(1.0);
                let live = wl.pdf.iter().filter(|&&p| p > 0.0).count();
                let resp: [(f64, f64); N] = std::array::from_fn(|j| {
                    if wl.pdf[j] > 0.0 {
                        let r = film.response_cos(wl.lambda[j], cos1);
                        (r.reflectance(), r.transmittance())
                    } else {
                        (0.0, 0.0)
                    }
                });
                // Reflect with the lanes' mean reflectance P; each lane is weighted by its
                // own R / P (or T / (1 - P)), which keeps every lane unbiased.
                // (Terminated lanes have R = 0 here, so the sum runs over the live ones.)
                let p_r = resp.iter().map(|r| r.0).sum::<f64>() / live as f64;
                if rng.random::<f64>() < p_r {
                    d = reflect(d, n);
                    for j in 0..N {
                        beta[j] *= resp[j].0 / p_r;
                    }
                } else {
                    for j in 0..N {
                        beta[j] *= resp[j].1 / (1.0 - p_r);
                    }
                }
                o = offset_origin(p, n, d);
                bsdf_pdf = None;
                // ANCHOR_END: thin_film
                // ANCHOR: loop_tail
            }
        }
        // ANCHOR: roulette
        // Russian roulette on the largest live throughput.
        if depth + 1 >= s.roulette_depth {
            let q = (0..N)
                .filter(|&j| wl.pdf[j] > 0.0)
                .map(|j| beta[j])
                .fold(0.0, f64::max)
                .min(1.0);
            if q.is_nan() || q <= 0.0 {
                break;
            }
            let u = rng.random::<f64>();
            for b in &mut beta {
                *b = roulette(*b, q, u);
            }
            if beta.iter().all(|&b| b == 0.0) {
                break;
            }
        }
        // ANCHOR_END: roulette
    }
    l
}
// ANCHOR_END: loop_tail
// ANCHOR_END: radiance
