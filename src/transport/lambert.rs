//! Lambertian reflectance. Chapter: *Lambertian reflectance* (`chapters/transport/lambert.md`).
//!
//! A Lambertian surface of albedo `rho` has the constant BRDF `f = rho / pi` above the
//! surface. The factor `1 / pi` is what makes the directional-hemispherical reflectance
//! `int f cos dw` equal `rho`. Reflected radiance `L_o = int f L cos dw` is estimated with
//! one direction drawn uniformly on the hemisphere (`2 rho L cos`) or cosine-weighted
//! (`rho L`). A closed "furnace" of albedo `a` and emission `L_e` has radiance
//! `L_e / (1 - a)`, simulated here by a random walk.
//!
//! The surface normal is `+z` throughout (the chapter *Tangent frames* maps any normal to it).

use std::f64::consts::{FRAC_1_PI, PI, TAU};

use glam::{DVec2, DVec3};

use crate::rng::{self, Rng};
use crate::sampling::cosine::{cosine_malley, cosine_pdf};
use crate::sampling::sphere::{HEMISPHERE_PDF, hemisphere_flip, sphere_inverse_cdf};
use crate::stats::ttest::Summary;

// ANCHOR: brdf
// EXERCISE transport/lambert lambert_brdf: the Lambertian BRDF of albedo rho for the normal +z
/// The Lambertian BRDF of albedo `rho` for the normal `+z`: `rho / pi` when both
/// directions are above the surface, 0 otherwise. Symmetric in its arguments by
/// construction (Helmholtz reciprocity).
pub fn lambert_brdf(rho: f64, wi: DVec3, wo: DVec3) -> f64 {
    if wi.z > 0.0 && wo.z > 0.0 {
        rho * FRAC_1_PI
    } else {
        0.0
    }
}
// END EXERCISE
// ANCHOR_END: brdf

// ANCHOR: quadrature
/// `int g(w) dw` over the hemisphere `z >= 0`, by the midpoint rule in
/// `(theta, phi)` with `n` by `2n` cells and the Jacobian `sin theta`:
/// `int_0^{2 pi} int_0^{pi/2} g sin theta dtheta dphi`. Error `O(1/n^2)` for smooth `g`.
pub fn hemisphere_quadrature(g: impl Fn(DVec3) -> f64, n: usize) -> f64 {
    let (dt, dp) = (PI / 2.0 / n as f64, TAU / (2 * n) as f64);
    // `(cos phi, sin phi)` of the cells' centres, the same on every ring.
    let around: Vec<(f64, f64)> = (0..2 * n)
        .map(|j| {
            let phi = (j as f64 + 0.5) * dp;
            (phi.cos(), phi.sin())
        })
        .collect();
    let mut sum = 0.0;
    for i in 0..n {
        let theta = (i as f64 + 0.5) * dt;
        let (s, c) = theta.sin_cos();
        let mut ring = 0.0;
        for &(cos_phi, sin_phi) in &around {
            ring += g(DVec3::new(s * cos_phi, s * sin_phi, c));
        }
        sum += ring * s;
    }
    sum * dt * dp
}

/// The albedo of a BRDF for the direction `wo`, `int f(wi, wo) cos(theta_i) dwi`, by
/// [`hemisphere_quadrature`]: the share of uniform incident light that leaves towards `wo`
/// (the hemispherical-directional reflectance), which by reciprocity is the share of light
/// arriving from `wo` that is reflected at all (the directional-hemispherical reflectance).
pub fn albedo(brdf: impl Fn(DVec3, DVec3) -> f64, wo: DVec3, n: usize) -> f64 {
    hemisphere_quadrature(|wi| brdf(wi, wo) * wi.z, n)
}
// ANCHOR_END: quadrature

// ANCHOR: environments
/// An environment with a known answer: incident radiance `radiance(w)`, and the exact
/// reflected radiance of a Lambertian surface of albedo 1 under it (`L_o` is linear in `rho`).
#[derive(Clone, Copy)]
pub struct Environment {
    /// Name for tables.
    pub name: &'static str,
    /// Incident radiance from direction `w` (pointing away from the surface).
    pub radiance: fn(DVec3) -> f64,
    /// `(1 / pi) int L(w) cos(theta) dw`, derived by hand.
    pub reflected_white: f64,
}

/// `L = 1 + z`: `(1/pi) int (1 + cos) cos dw = (1/pi)(pi + 2 pi / 3) = 5/3`.
pub const GRADIENT: Environment = Environment {
    name: "L = 1 + z",
    radiance: |w| 1.0 + w.z,
    reflected_white: 5.0 / 3.0,
};

/// A sky `L = max(z, 0)^3`: `(1/pi) 2 pi int_0^1 mu^4 dmu = 2/5`
/// (in general `2 / (k + 2)` for `max(z, 0)^k`).
pub const SKY: Environment = Environment {
    name: "sky L = max(z, 0)^3",
    radiance: |w| w.z.max(0.0).powi(3),
    reflected_white: 2.0 / 5.0,
};
// ANCHOR_END: environments

// ANCHOR: estimators
/// One-sample estimate of `L_o` with a direction uniform on the hemisphere:
/// `f L cos / (1 / (2 pi))`.
pub fn estimate_uniform(rho: f64, radiance: impl Fn(DVec3) -> f64, u: DVec2) -> f64 {
    let wi = hemisphere_flip(sphere_inverse_cdf(u), DVec3::Z);
    lambert_brdf(rho, wi, DVec3::Z) * radiance(wi) * wi.z / HEMISPHERE_PDF
}

/// One-sample estimate of `L_o` with a cosine-weighted direction: `f L cos / (cos / pi)`.
/// A direction exactly on the horizon (pdf 0) contributes 0.
pub fn estimate_cosine(rho: f64, radiance: impl Fn(DVec3) -> f64, u: DVec2) -> f64 {
    let wi = cosine_malley(u);
    let pdf = cosine_pdf(wi);
    if pdf > 0.0 {
        lambert_brdf(rho, wi, DVec3::Z) * radiance(wi) * wi.z / pdf
    } else {
        0.0
    }
}
// ANCHOR_END: estimators

// ANCHOR: seed_forms
/// The source notes' simplification for uniform directions: `2 rho L cos`.
pub fn seed_uniform(rho: f64, radiance: f64, cos: f64) -> f64 {
    2.0 * rho * radiance * cos
}

/// The source notes' simplification for cosine-weighted directions: `rho L`.
pub fn seed_cosine(rho: f64, radiance: f64) -> f64 {
    rho * radiance
}
// ANCHOR_END: seed_forms

/// Summary of `n` one-sample estimates `estimator(u)`, `u` uniform in the unit square.
pub fn summarize(estimator: impl Fn(DVec2) -> f64, n: usize, rng: &mut Rng) -> Summary {
    let mut s = Summary::default();
    for _ in 0..n {
        let u = DVec2::new(rng::uniform(rng, 0.0, 1.0), rng::uniform(rng, 0.0, 1.0));
        s.push(estimator(u));
    }
    s
}

/// Exact variance of one estimate under the sky `max(z, 0)^k` with albedo `rho`.
/// Cosine: `E[(rho L)^2] = rho^2 int z^{2k} z / pi dw = rho^2 / (k + 1)`.
/// Uniform: `E[(2 rho L z)^2] = 4 rho^2 int z^{2k + 2} / (2 pi) dw = 4 rho^2 / (2k + 3)`.
/// Both minus the squared mean `(2 rho / (k + 2))^2`. Returns `(uniform, cosine)`.
pub fn sky_variances(rho: f64, k: i32) -> (f64, f64) {
    let k = f64::from(k);
    let mean2 = (2.0 * rho / (k + 2.0)).powi(2);
    (
        4.0 * rho * rho / (2.0 * k + 3.0) - mean2,
        rho * rho / (k + 1.0) - mean2,
    )
}

// ANCHOR: furnace
/// One random walk in a white furnace: every surface is Lambertian with albedo `a` and
/// emits `emission`, so every direction sees `L = L_e + a L`, i.e. `L = L_e / (1 - a)`.
///
/// `bounce(u)` is one bounce's weight `f cos / pdf` for a direction drawn from `u`. The walk
/// adds `T L_e` at each vertex, multiplies the throughput `T` by the weight, and then
/// plays Russian roulette with survival probability `p = min(1, T)` (dividing `T` by `p`
/// on survival; chapter *Russian roulette*). With cosine-weighted directions the weight
/// is exactly `a`, so this is the walk that continues with probability `a` and counts
/// vertices. With uniform directions the weight `2 a cos` exceeds 1 for `a > 1/2`, and the
/// roulette never reduces a throughput above 1: unbiased still, but with a heavy tail
/// ([`furnace_tail_index`]) and, for `a >= sqrt(3)/2`, infinite variance
/// ([`furnace_uniform_variance`]). Returns the estimate and the number of vertices.
pub fn furnace_walk(emission: f64, bounce: impl Fn(DVec2) -> f64, rng: &mut Rng) -> (f64, u32) {
    let (mut radiance, mut throughput, mut vertices) = (0.0, 1.0, 0);
    loop {
        radiance += throughput * emission;
        vertices += 1;
        let u = DVec2::new(rng::uniform(rng, 0.0, 1.0), rng::uniform(rng, 0.0, 1.0));
        throughput *= bounce(u);
        let p = throughput.min(1.0);
        if rng::uniform(rng, 0.0, 1.0) >= p {
            return (radiance, vertices);
        }
        throughput /= p;
    }
}
// ANCHOR_END: furnace

// ANCHOR: furnace_tail
/// `E[w^s]` of the uniform furnace bounce's weight `w = 2 a cos(theta)`, `cos(theta)`
/// uniform on `[0, 1]` for directions uniform on the hemisphere: `(2a)^s / (s + 1)`.
pub fn uniform_weight_moment(a: f64, s: f64) -> f64 {
    (2.0 * a).powf(s) / (s + 1.0)
}

/// The tail index of a walk whose throughput is multiplied by a weight `w` with moments
/// `moment(s) = E[w^s]` and is never reduced above 1 by the roulette (as in
/// [`furnace_walk`]): the root `kappa > 1` of `E[w^kappa] = 1`. The estimate's moments
/// `E[X^s]` are infinite for every `s >= kappa` (and finite below it), so its variance is
/// finite only if `kappa > 2`. Needs `E[w] < 1` (then `s -> E[w^s]`, log-convex and 1 at
/// `s = 0`, is below 1 on `(0, kappa)` and above it beyond); infinity when `E[w^s]` is still
/// below 1 at `s = 2^19`: a weight that never exceeds 1, or a root beyond that (the furnace's
/// at albedos less than about `1.3e-5` above 1/2). Bisection to `1e-14` relative.
pub fn tail_index(moment: impl Fn(f64) -> f64) -> f64 {
    let (mut lo, mut hi) = (1.0, 2.0);
    while moment(hi) < 1.0 {
        lo = hi;
        hi *= 2.0;
        if hi > 1e6 {
            return f64::INFINITY;
        }
    }
    while hi - lo > 1e-14 * hi {
        let mid = 0.5 * (lo + hi);
        if moment(mid) < 1.0 {
            lo = mid;
        } else {
            hi = mid;
        }
    }
    0.5 * (lo + hi)
}

/// The tail index of [`furnace_walk`] with uniform bounces: the root of
/// `(2a)^kappa / (kappa + 1) = 1`; infinite for `a <= 1/2`, where `2 a cos <= 1`, and where
/// the root is beyond [`tail_index`]'s bound.
pub fn furnace_tail_index(a: f64) -> f64 {
    tail_index(|s| uniform_weight_moment(a, s))
}

/// The exact variance of [`furnace_walk`] with uniform bounces and `L_e = 1`.
///
/// For `a <= 1/2` the weight never exceeds 1, the throughput stays 1 and each bounce
/// survives with probability `E[w] = a`: the cosine walk's `a / (1 - a)^2`. For `a > 1/2`
/// the second moment `m(t)` of a walk carrying throughput `t >= 1` satisfies (with
/// `u = t w` uniform on `[0, 2at]`)
/// `m(t) = t^2 (1 + a)/(1 - a) + (1 / 2at) int_1^{2at} m(s) ds + m(1) / (4at)`,
/// solved by `m(t) = alpha (t^2 + 1/3)`, `alpha (1 - 4a^2/3) = (1 + a)/(1 - a)`; so
/// `Var = 4 (1 + a) / ((1 - a)(3 - 4 a^2)) - 1 / (1 - a)^2`, finite only for
/// `E[w^2] = 4a^2/3 < 1`, i.e. `a < sqrt(3)/2`. Infinity beyond.
pub fn furnace_uniform_variance(a: f64) -> f64 {
    if a <= 0.5 {
        a / ((1.0 - a) * (1.0 - a))
    } else if 4.0 * a * a >= 3.0 {
        f64::INFINITY
    } else {
        4.0 * (1.0 + a) / ((1.0 - a) * (3.0 - 4.0 * a * a)) - 1.0 / ((1.0 - a) * (1.0 - a))
    }
}
// ANCHOR_END: furnace_tail

/// A furnace bounce with cosine-weighted directions: the weight `f cos / pdf` (= `a`).
pub fn furnace_bounce_cosine(a: f64, u: DVec2) -> f64 {
    estimate_cosine(a, |_| 1.0, u)
}

/// A furnace bounce with uniform directions: the weight `2 a cos`.
pub fn furnace_bounce_uniform(a: f64, u: DVec2) -> f64 {
    estimate_uniform(a, |_| 1.0, u)
}
