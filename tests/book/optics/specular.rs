//! Tests of the chapter *The missing cosine in specular reflection*
//! (`src/optics/specular.rs`). t-tests run at `raylemma::stats::test_alpha()`, fixed seeds.

use std::f64::consts::FRAC_PI_3;

use glam::{DVec2, DVec3};
use raylemma::geometry::sphere::intersect_stable;
use raylemma::geometry::{Ray, Sphere};
use raylemma::optics::fresnel::fresnel_dielectric;
use raylemma::optics::reflect::{Refraction, reflect, refract};
use raylemma::optics::specular::*;
use raylemma::rng;
use raylemma::stats::{test_alpha, ttest};

fn w_o(theta: f64) -> DVec3 {
    DVec3::new(theta.sin(), 0.0, theta.cos())
}

fn lobe_terms(kappa: f64, theta: f64, divide_by_cos: bool, n: usize, seed: u64) -> ttest::Summary {
    let mut rng = rng::seeded(seed);
    ttest::Summary::of((0..n).map(|_| {
        let u = DVec2::new(
            rng::uniform(&mut rng, 0.0, 1.0),
            rng::uniform(&mut rng, 0.0, 1.0),
        );
        reflected_radiance_sample(0.8, kappa, w_o(theta), divide_by_cos, u)
    }))
}

/// With the 1/|cos| of the delta BSDF, a narrow lobe (kappa = 1e4, 60 degrees from the
/// normal) reflects exactly rho of a constant environment: every sample equals rho.
#[test]
fn with_the_one_over_cos_the_mirror_reflects_rho() {
    let terms = lobe_terms(1e4, FRAC_PI_3, true, 100_000, 1);
    assert!(
        (terms.mean - 0.8).abs() <= 1e-12 && terms.variance() <= 1e-24,
        "{terms:?}"
    );
}

/// Without it (the planted bug), the estimate tends to rho cos(theta): half of rho at 60
/// degrees. Exactly, E = rho cos(theta_r) (coth kappa - 1/kappa) for the vMF lobe.
#[test]
fn without_the_one_over_cos_the_mirror_loses_energy() {
    let kappa = 1e4;
    let terms = lobe_terms(kappa, FRAC_PI_3, false, 100_000, 2);
    let correct = ttest::one_sample(&terms, 0.8).unwrap();
    assert!(
        correct.p_value < test_alpha(),
        "the bug went unnoticed: mean {}",
        terms.mean
    );
    let expected = 0.8 * FRAC_PI_3.cos() * (1.0 / kappa.tanh() - 1.0 / kappa);
    let exact = ttest::one_sample(&terms, expected).unwrap();
    assert!(
        exact.p_value >= test_alpha(),
        "mean {} vs {expected} (p = {:.3e})",
        terms.mean,
        exact.p_value
    );
}

/// The lobe tends to the delta: the share of it above the horizon grows to 1 with kappa.
#[test]
fn the_lobe_converges_to_the_delta() {
    let means: Vec<f64> = [3.0, 30.0, 300.0, 3000.0]
        .iter()
        .map(|&k| lobe_terms(k, 1.4, true, 200_000, 3).mean)
        .collect();
    assert!(means.windows(2).all(|w| w[0] < w[1]), "{means:?}");
    assert!(
        means[0] < 0.7 && (0.8 - means[3]).abs() <= 1e-3,
        "{means:?}"
    );
}

#[test]
fn lobe_pdf_integrates_to_one() {
    // Midpoint rule over cos in [-1, 1]: int p dOmega = 2 pi int p dcos.
    for kappa in [0.5, 10.0, 1e3] {
        let n = 4_000_000;
        let axis = DVec3::Z;
        let mut total = 0.0;
        for k in 0..n {
            let cos = -1.0 + 2.0 * (k as f64 + 0.5) / n as f64;
            let pdf = kappa * (kappa * (cos - 1.0)).exp()
                / (std::f64::consts::TAU * (1.0 - (-2.0 * kappa).exp()));
            total += pdf * std::f64::consts::TAU * 2.0 / n as f64;
        }
        assert!((total - 1.0).abs() <= 1e-6, "kappa {kappa}: {total}");
        // And the sampler's pdf agrees with the formula at its own samples.
        let (w, pdf) = sample_lobe(axis, kappa, DVec2::new(0.3, 0.7));
        let formula = kappa * (kappa * (w.z - 1.0)).exp()
            / (std::f64::consts::TAU * (1.0 - (-2.0 * kappa).exp()));
        assert!((pdf / formula - 1.0).abs() <= 1e-12);
    }
}

fn furnace(material: Material, cosine: CosineTerm, n: usize, seed: u64) -> (ttest::Summary, u64) {
    let mut rng = rng::seeded(seed);
    let mut bounces = 0u64;
    let s = ttest::Summary::of((0..n).map(|_| {
        let ray = furnace_camera_ray(&mut rng);
        let path = furnace_path(ray, material, cosine, &mut rng);
        bounces += u64::from(path.bounces);
        path.radiance
    }));
    (s, bounces)
}

/// White furnace: a mirror and glass spheres in a constant environment return exactly the
/// environment's radiance on every path (zero variance), however many bounces.
#[test]
fn furnace_returns_the_background_exactly() {
    for (k, material) in [
        Material::Mirror { rho: 1.0 },
        Material::Glass { ior: 1.5 },
        Material::Glass { ior: 2.4 },
    ]
    .into_iter()
    .enumerate()
    {
        let (s, bounces) = furnace(material, CosineTerm::Cancelled, 20_000, 10 + k as u64);
        assert!(s.mean == 1.0 && s.variance() == 0.0, "{material:?}: {s:?}");
        assert!(bounces >= 20_000, "{material:?}: only {bounces} bounces");
    }
}

/// The planted bug: keeping the cosine at specular bounces darkens the furnace.
#[test]
fn furnace_with_the_cosine_kept_is_rejected() {
    for (k, material) in [Material::Mirror { rho: 1.0 }, Material::Glass { ior: 1.5 }]
        .into_iter()
        .enumerate()
    {
        let (s, _) = furnace(material, CosineTerm::Kept, 20_000, 20 + k as u64);
        let t = ttest::one_sample(&s, 1.0).unwrap();
        assert!(
            t.p_value < test_alpha() && s.mean < 0.9,
            "{material:?}: mean {}",
            s.mean
        );
    }
}

/// Deterministic energy bookkeeping: following *both* branches at every glass interface,
/// weighted by F and 1 - F, the weights escaping the sphere add up to 1 (to the weight
/// still inside after 40 interactions).
#[test]
fn both_branches_conserve_energy() {
    fn split(ray: Ray, ior: f64, depth: u32) -> (f64, f64) {
        let sphere = Sphere::new(DVec3::ZERO, 1.0);
        let Some(t) = intersect_stable(&ray, &sphere, 1e-9) else {
            return (1.0, 0.0); // escaped with all its weight
        };
        if depth == 0 {
            return (0.0, 1.0); // still inside: unaccounted
        }
        let p = ray.at(t);
        let (n, w) = (p.normalize(), ray.dir.normalize());
        let (n1, n2) = if w.dot(n) < 0.0 {
            (1.0, ior)
        } else {
            (ior, 1.0)
        };
        let f = fresnel_dielectric(w.dot(n).abs(), n1, n2);
        let (re, rl) = split(Ray::new(p, reflect(w, n)), ior, depth - 1);
        match refract(w, n, n1, n2) {
            Refraction::Transmitted(w_t) => {
                let (te, tl) = split(Ray::new(p, w_t), ior, depth - 1);
                (f * re + (1.0 - f) * te, f * rl + (1.0 - f) * tl)
            }
            Refraction::TotalInternalReflection => (re, rl),
        }
    }
    let mut rng = rng::seeded(30);
    for _ in 0..20 {
        let ray = furnace_camera_ray(&mut rng);
        let (escaped, left) = split(ray, 1.5, 12);
        assert!((escaped + left - 1.0).abs() <= 1e-12, "{escaped} + {left}");
        assert!(left <= 1e-3, "{left} left inside after 12 interfaces");
    }
}

/// The seed writes the mirror's delta as delta(n - (w_i + w_o)/2). For a mirror pair,
/// (w_i + w_o)/2 = cos(theta) n, so that argument vanishes only at normal incidence; the
/// *normalised* half vector (w_i + w_o)/|w_i + w_o| is the one that equals n.
#[test]
fn seeds_delta_argument_vanishes_only_at_normal_incidence() {
    let n = DVec3::Z;
    for deg in [0.0f64, 10.0, 45.0, 80.0] {
        let w_o = w_o(deg.to_radians());
        let w_i = DVec3::new(-w_o.x, -w_o.y, w_o.z); // the mirror direction, pointing away
        let seed = (n - (w_i + w_o) / 2.0).length();
        let half = (n - (w_i + w_o).normalize()).length();
        assert!(
            (seed - (1.0 - deg.to_radians().cos())).abs() <= 1e-15,
            "{deg}: {seed}"
        );
        assert!(half <= 1e-15, "{deg}: {half}");
        if deg > 0.0 {
            assert!(seed > 1e-3);
        }
    }
}

/// A curiosity that checks the Fresnel selection: in a sphere the internal angle of
/// incidence equals the entry angle, so every interface of a path has the same F. A path
/// reflects at entry (1 bounce) with probability F, or enters and then leaves after a
/// geometric number of tries, mean 1/(1 - F): E[bounces] = F + (1 - F)(1 + 1/(1 - F)) = 2
/// for every F. A t-test of the mean bounce count against 2.
#[test]
fn glass_sphere_paths_average_two_bounces() {
    for (k, ior) in [1.5, 2.4].into_iter().enumerate() {
        let mut rng = rng::seeded(40 + k as u64);
        let s = ttest::Summary::of((0..100_000).map(|_| {
            let ray = furnace_camera_ray(&mut rng);
            f64::from(
                furnace_path(
                    ray,
                    Material::Glass { ior },
                    CosineTerm::Cancelled,
                    &mut rng,
                )
                .bounces,
            )
        }));
        let t = ttest::one_sample(&s, 2.0).unwrap();
        assert!(
            t.p_value >= test_alpha(),
            "n = {ior}: mean bounces {} (p = {:.3e})",
            s.mean,
            t.p_value
        );
    }
    // The identity holds for any F shared by all interfaces, so the twin must break that
    // symmetry: Fresnel evaluated as if always entering (indices not swapped inside).
    let mut rng = rng::seeded(50);
    let unswapped = ttest::Summary::of((0..100_000).map(|_| {
        let mut ray = furnace_camera_ray(&mut rng);
        let sphere = Sphere::new(DVec3::ZERO, 1.0);
        let mut bounces = 0.0;
        while let Some(t) = intersect_stable(&ray, &sphere, 1e-9) {
            bounces += 1.0;
            let p = ray.at(t);
            let (n, w) = (p.normalize(), ray.dir.normalize());
            let (n1, n2) = if w.dot(n) < 0.0 {
                (1.0, 1.5)
            } else {
                (1.5, 1.0)
            };
            let f = fresnel_dielectric(w.dot(n).abs(), 1.0, 1.5);
            let next = match refract(w, n, n1, n2) {
                Refraction::Transmitted(w_t) if rng::uniform(&mut rng, 0.0, 1.0) >= f => w_t,
                _ => reflect(w, n),
            };
            ray = Ray::new(p, next);
        }
        bounces
    }));
    assert!(
        ttest::one_sample(&unswapped, 2.0).unwrap().p_value < test_alpha(),
        "mean {}",
        unswapped.mean
    );
}
