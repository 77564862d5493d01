//! Specular reflection and refraction as delta distributions, and why no cosine appears.
//! Chapter: *The missing cosine in specular reflection* (`chapters/optics/specular.md`).
//!
//! A perfect mirror's BRDF is a delta distribution on the sphere of directions,
//! `f_r(w_i, w_o) = rho delta(w_i - R(w_o)) / |cos theta_i|`: the `1 / |cos theta_i|`
//! cancels the cosine of the rendering equation, so the reflected radiance is
//! `rho L(R(w_o))`, with no cosine. Two numerical checks live here:
//!
//! * a narrow lobe (von Mises-Fisher, concentration `kappa`) standing in for the delta,
//!   whose reflected radiance tends to `rho L` with the `1/cos` and to `rho L cos` without;
//! * a white furnace: a mirror or glass sphere inside a constant environment must return
//!   exactly the environment's radiance, for every path.

use crate::sampling::sphere::sphere_uniform;
use std::f64::consts::TAU;

use glam::{DVec2, DVec3};

use crate::geometry::sphere::intersect_stable;
use crate::geometry::{Ray, Sphere};
use crate::optics::fresnel::fresnel_dielectric;
use crate::optics::reflect::{Refraction, reflect, refract};
use crate::rng::{self, Rng};

// ANCHOR: lobe
/// A direction from the von Mises-Fisher lobe of concentration `kappa` around the unit
/// `axis`, and its pdf per steradian,
/// `p(w) = kappa exp(kappa (cos - 1)) / (2 pi (1 - exp(-2 kappa)))`, `cos = w . axis`.
/// As `kappa` grows the lobe tends to the delta distribution around `axis`.
pub fn sample_lobe(axis: DVec3, kappa: f64, u: DVec2) -> (DVec3, f64) {
    // Inverse CDF of cos: 1 + ln(u + (1 - u) e^(-2 kappa)) / kappa, in [-1, 1].
    let cos = (1.0 + (u.x + (1.0 - u.x) * (-2.0 * kappa).exp()).ln() / kappa).clamp(-1.0, 1.0);
    let sin = (1.0 - cos * cos).max(0.0).sqrt();
    let phi = TAU * u.y;
    let (t, b) = axis.any_orthonormal_pair();
    let w = (t * phi.cos() + b * phi.sin()) * sin + axis * cos;
    let pdf = kappa * (kappa * (cos - 1.0)).exp() / (TAU * (1.0 - (-2.0 * kappa).exp()));
    (w, pdf)
}
// ANCHOR_END: lobe

// ANCHOR: narrow_lobe_brdf
// EXERCISE optics/specular narrow_lobe_brdf: the narrow lobe's BRDF, with (or, for the planted bug, without) its 1 / |cos theta_i|
/// A glossy BRDF approaching the mirror: `f = rho lobe_kappa(w_i; R(w_o)) / |cos theta_i|`
/// above the surface (normal `+z`), zero below. With `divide_by_cos = false` it is the
/// planted bug: the same lobe without the `1 / |cos theta_i|`.
pub fn narrow_lobe_brdf(rho: f64, lobe_pdf: f64, w_i: DVec3, divide_by_cos: bool) -> f64 {
    if w_i.z <= 0.0 {
        return 0.0;
    }
    if divide_by_cos {
        rho * lobe_pdf / w_i.z
    } else {
        rho * lobe_pdf
    }
}
// END EXERCISE

/// One sample of the reflected radiance `int f L |cos theta_i| dw_i` in a constant
/// environment `L = 1`, for the outgoing direction `w_o` (unit, `z > 0`), drawing `w_i`
/// from the lobe itself: the estimate `f |cos| / pdf`.
pub fn reflected_radiance_sample(
    rho: f64,
    kappa: f64,
    w_o: DVec3,
    divide_by_cos: bool,
    u: DVec2,
) -> f64 {
    let mirror = DVec3::new(-w_o.x, -w_o.y, w_o.z);
    let (w_i, pdf) = sample_lobe(mirror, kappa, u);
    narrow_lobe_brdf(rho, pdf, w_i, divide_by_cos) * w_i.z.max(0.0) / pdf
}
// ANCHOR_END: narrow_lobe_brdf

/// What a furnace sphere is made of.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum FurnaceMaterial {
    /// A perfect mirror of reflectance `rho` (1 for energy conservation).
    Mirror {
        /// Reflectance.
        rho: f64,
    },
    /// A smooth dielectric of index `ior` in vacuum.
    Glass {
        /// Index of refraction.
        ior: f64,
    },
}

/// How a specular bounce is weighted: the correct delta (no cosine) or the planted bug
/// that multiplies the throughput by `|cos theta|` as a diffuse bounce would.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum CosineTerm {
    /// The delta BSDF's `1/|cos|` cancels the rendering equation's cosine (correct).
    Cancelled,
    /// The cosine is kept (the planted bug).
    Kept,
}

/// The result of tracing one path in the furnace.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct FurnacePath {
    /// Radiance carried back to the camera (the environment's radiance is 1).
    pub radiance: f64,
    /// Specular bounces on the sphere before escaping.
    pub bounces: u32,
}

// ANCHOR: furnace
/// Traces one path from `ray` through a unit sphere at the origin of `material`, inside a
/// constant environment of radiance 1. At glass, reflection is chosen with probability
/// `F` (Fresnel) and refraction with `1 - F`, so the weight `F / F` is 1. A correct
/// specular BSDF returns radiance exactly 1 for every path that hits the sphere.
pub fn furnace_path(
    ray: Ray,
    material: FurnaceMaterial,
    cosine: CosineTerm,
    rng: &mut Rng,
) -> FurnacePath {
    let sphere = Sphere::new(DVec3::ZERO, 1.0);
    let (mut ray, mut throughput, mut bounces) = (ray, 1.0, 0);
    while let Some(t) = intersect_stable(&ray, &sphere, 1e-9) {
        bounces += 1;
        if bounces > 10_000 {
            return FurnacePath {
                radiance: f64::NAN,
                bounces,
            }; // a trapped path: a bug
        }
        let p = ray.at(t);
        let n = p.normalize(); // outward normal
        let w = ray.dir.normalize();
        let cos_i = w.dot(n).abs();
        let next = match material {
            FurnaceMaterial::Mirror { rho } => {
                throughput *= rho;
                reflect(w, n)
            }
            FurnaceMaterial::Glass { ior } => {
                let (n1, n2) = if w.dot(n) < 0.0 {
                    (1.0, ior)
                } else {
                    (ior, 1.0)
                };
                let f = fresnel_dielectric(cos_i, n1, n2);
                match refract(w, n, n1, n2) {
                    Refraction::Transmitted(w_t) if rng::uniform(rng, 0.0, 1.0) >= f => w_t,
                    _ => reflect(w, n),
                }
            }
        };
        if cosine == CosineTerm::Kept {
            throughput *= cos_i;
        }
        ray = Ray::new(p, next);
    }
    FurnacePath {
        radiance: throughput,
        bounces,
    }
}
// ANCHOR_END: furnace

/// A ray from 3 radii away aimed at a uniformly random point of the sphere's silhouette,
/// so that it hits. The silhouette is drawn in the plane through the centre perpendicular
/// to the line of sight: seen from 3 radii, the tangent cone meets that plane in the circle
/// of radius `3 / sqrt(8)`, not 1 (a ray aimed at radius `r` passes the centre at
/// `3 r / sqrt(9 + r^2)`). The radius is shrunk by 0.999 so that every ray hits, at angles
/// of incidence up to about 87.6°.
pub fn furnace_camera_ray(rng: &mut Rng) -> Ray {
    let origin = sphere_uniform(rng) * 3.0;
    let (t, b) = (-origin.normalize()).any_orthonormal_pair();
    let silhouette = 3.0 / 8f64.sqrt();
    let r = rng::uniform(rng, 0.0, 1.0).sqrt() * 0.999 * silhouette;
    let phi = rng::uniform(rng, 0.0, TAU);
    let target = (t * phi.cos() + b * phi.sin()) * r;
    Ray::new(origin, (target - origin).normalize())
}
