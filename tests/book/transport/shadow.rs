//! Tests of the chapter *Shadow-ray pdfs* (`src/transport/shadow.rs`).
//!
//! Every statistical test has a fixed seed, runs at `raylemma::stats::test_alpha()` and has
//! a planted-bug twin it must reject. The planted bugs are the source notes' and the classic ones:
//! a missing `r^2`, a missing cosine, the cosine's sign not handled, an area pdf not
//! normalised by the area (and, for the sphere, normalised by the whole sphere instead of
//! the visible cap).

use raylemma::sampling::sphere::sphere_uniform;
use std::f64::consts::{PI, TAU};

use glam::{DVec2, DVec3};
use raylemma::check::warp::planted::{self, AreaToSolidAngle as Convert, LIGHT_PDFS as PLANTED};
use raylemma::check::warp::{self, Domain, RngWarp, WarpOptions, square_point};
use raylemma::check::{Options, max_abs};
use raylemma::rng::{self, Rng};
use raylemma::stats::test_alpha;
use raylemma::stats::ttest::{Summary, one_sample};
use raylemma::transport::shadow::*;

const N: usize = 200_000;

fn quad() -> QuadLight {
    // A 1.5 x 0.8 rectangle at height 1.2 facing down (-z), off the axis of p = 0.
    QuadLight::new(
        DVec3::new(-0.4, -0.3, 1.2),
        DVec3::new(0.0, 0.8, 0.0),
        DVec3::new(1.5, 0.0, 0.0),
    )
    .unwrap()
}

fn tilted_quad() -> QuadLight {
    // A parallelogram tilted towards p = 0 (not a rectangle).
    QuadLight::new(
        DVec3::new(-0.6, 0.5, 0.9),
        DVec3::new(0.3, 0.9, 0.4),
        DVec3::new(1.1, 0.2, -0.3),
    )
    .unwrap()
}

fn sphere() -> SphereLight {
    SphereLight::new(DVec3::new(0.6, -0.3, 2.5), 0.9).unwrap()
}

/// The mean of `f(u)` over `n` uniform points of the square, seeded.
fn mean_of(seed: u64, n: usize, mut f: impl FnMut(DVec2, DVec2) -> f64) -> Summary {
    let mut rng = rng::seeded(seed);
    let mut s = Summary::default();
    for _ in 0..n {
        let (a, b) = (square_point(&mut rng), square_point(&mut rng));
        s.push(f(a, b));
    }
    s
}

fn p_value(s: &Summary, mu: f64) -> f64 {
    one_sample(s, mu).map_or(0.0, |t| t.p_value)
}

fn accepts(s: &Summary, mu: f64) -> bool {
    p_value(s, mu) >= test_alpha()
}

const STRATEGIES: [IrradianceStrategy; 4] = [
    IrradianceStrategy::Light,
    IrradianceStrategy::Bsdf,
    IrradianceStrategy::Mis(Heuristic::Balance),
    IrradianceStrategy::Mis(Heuristic::Power),
];

/// Integral of `pdf` over the cone of a sphere light seen from `p`, in `s` with
/// `1 - cos(theta) = (1 - cos(theta_max)) (1 - s^2)`: the substitution turns the
/// cap pdf's `1 / sqrt` singularity at the silhouette (`s = 0`) into a smooth integrand.
/// Composite 8-point Gauss-Legendre, 200 panels in `s` and 64 in `phi`.
fn cone_integral(light: &SphereLight, p: DVec3, pdf: impl Fn(DVec3) -> f64) -> f64 {
    const G: [(f64, f64); 4] = [
        (0.183_434_642_495_649_8, 0.362_683_783_378_362),
        (0.525_532_409_916_329, 0.313_706_645_877_887_3),
        (0.796_666_477_413_626_7, 0.222_381_034_453_374_47),
        (0.960_289_856_497_536_2, 0.101_228_536_290_376_26),
    ];
    let nodes: Vec<(f64, f64)> = G.iter().flat_map(|&(x, w)| [(-x, w), (x, w)]).collect();
    let h = light.one_minus_cos_max(p).unwrap();
    let axis = (light.center() - p).normalize();
    let (t, b) = (
        rng::perpendicular(axis),
        axis.cross(rng::perpendicular(axis)),
    );
    let (ns, nphi) = (200, 64);
    let mut sum = 0.0;
    for i in 0..ns {
        for &(x, w) in &nodes {
            let s = (i as f64 + 0.5 + 0.5 * x) / ns as f64;
            let one_minus_cos = h * (1.0 - s * s);
            let sin = (one_minus_cos * (2.0 - one_minus_cos)).sqrt();
            for j in 0..nphi {
                for &(y, v) in &nodes {
                    let phi = TAU * (j as f64 + 0.5 + 0.5 * y) / nphi as f64;
                    let dir = (1.0 - one_minus_cos) * axis + sin * (phi.cos() * t + phi.sin() * b);
                    // d(cos theta) = 2 h s ds; weights w/2 per panel of width 1/ns.
                    sum += pdf(dir)
                        * 2.0
                        * h
                        * s
                        * (w / 2.0 / ns as f64)
                        * (TAU * v / 2.0 / nphi as f64);
                }
            }
        }
    }
    sum
}

// The planted bugs, as wrong conversions of a correct sample to a solid-angle pdf:
// `raylemma::check::warp::planted::LIGHT_PDFS` (a missing r^2, a missing cosine, the source notes'
// signed cosine, an area pdf of 1).

mod hard_cases;
mod irradiance;
mod pdf_integrates;
mod sample_pdf;
mod solid_angle;

// ---------------------------------------------------------------------------------------
// Exercises. Each scaffold is yours to fill in; its test is ignored until you do:
// `cargo test --test book transport::shadow::exercise_ -- --ignored`.

/// Exercise 1 of *Shadow-ray pdfs*: a point uniform in area on the triangle `a b c`, from
/// `u` in the unit square, seen from `p`: `LightSample::seen_from` with the triangle's unit
/// normal and its area density.
fn your_triangle_sample(a: DVec3, b: DVec3, c: DVec3, p: DVec3, u: DVec2) -> Option<LightSample> {
    let _ = (a, b, c, p, u); // delete this line
    unimplemented!("exercise 1 of Shadow-ray pdfs: sample the triangle uniformly by area")
}

/// For two triangles seen from the origin: the mean of `1 / pdf` over your samples passes
/// the t-test against `triangle_solid_angle`, each planted conversion of your points is
/// rejected, the points' mean is the centroid (t-test per coordinate), and a quarter of them
/// lie in the corner triangle where the barycentric coordinate of `a` exceeds 1/2.
#[test]
#[ignore = "exercise 1 of Shadow-ray pdfs: fill in your_triangle_sample, then run it"]
fn exercise_1_triangle_solid_angle_is_the_mean_of_one_over_pdf() {
    let p = DVec3::ZERO;
    let triangles = [
        (
            DVec3::new(-0.4, -0.3, 1.2),
            DVec3::new(1.1, -0.3, 1.2),
            DVec3::new(-0.4, 0.5, 1.2),
        ),
        (
            DVec3::new(-0.6, 0.5, 0.9),
            DVec3::new(0.5, 0.7, 0.6),
            DVec3::new(-0.3, 1.4, 1.3),
        ),
    ];
    for (k, (a, b, c)) in triangles.into_iter().enumerate() {
        let seed = 500 + 10 * k as u64;
        let exact = triangle_solid_angle(a - p, b - p, c - p);
        let s = mean_of(seed, N, |u, _| {
            your_triangle_sample(a, b, c, p, u).map_or(0.0, |s| 1.0 / s.pdf)
        });
        assert!(
            accepts(&s, exact),
            "triangle {k}: mean {} vs {exact}, p = {:e}",
            s.mean,
            p_value(&s, exact)
        );
        let area = 0.5 * (b - a).cross(c - a).length();
        for (bug, convert) in PLANTED {
            let s = mean_of(seed + 1, N, |u, _| {
                let s = your_triangle_sample(a, b, c, p, u).unwrap();
                // As a light facing p (n . w < 0), whichever way your normal points.
                1.0 / convert(1.0 / area, s.dist, -s.cos_light.abs())
            });
            assert!(
                !accepts(&s, exact),
                "triangle {k}, planted bug {bug} passed: mean {}",
                s.mean
            );
        }
        let centroid = (a + b + c) / 3.0;
        for axis in 0..3 {
            let s = mean_of(seed + 2, N, |u, _| {
                your_triangle_sample(a, b, c, p, u).unwrap().point[axis]
            });
            assert!(
                accepts(&s, centroid[axis]),
                "triangle {k}, coordinate {axis}: mean {} vs {}",
                s.mean,
                centroid[axis]
            );
        }
        let corner = mean_of(seed + 3, N, |u, _| {
            let q = your_triangle_sample(a, b, c, p, u).unwrap().point;
            let lambda_a = 0.5 * (b - q).cross(c - q).length() / area;
            f64::from(u8::from(lambda_a > 0.5))
        });
        assert!(
            accepts(&corner, 0.25),
            "triangle {k}: {} of the points near a, not 1/4",
            corner.mean
        );
    }
}

/// Exercise 2 of *Shadow-ray pdfs*: a point uniform in area on the *whole* sphere light
/// (far side included), from `u` in the unit square, seen from `p`:
/// `LightSample::seen_from` with the area density `1 / (4 pi R^2)`.
fn your_whole_sphere_sample(light: &SphereLight, p: DVec3, u: DVec2) -> Option<LightSample> {
    let _ = (light, p, u); // delete this line
    unimplemented!("exercise 2 of Shadow-ray pdfs: sample the whole sphere uniformly by area")
}

/// Exercise 2 of *Shadow-ray pdfs*: the total mass the sampler checker finds in the pdf
/// of your whole-sphere sampler, evaluated as every light's pdf is, by casting the ray and
/// converting at its first hit, for the light `sphere()` seen from `(0.1, 0.2, -0.4)`.
const YOUR_ANSWER_2: Option<f64> = None;

/// Your samples, a blocked one (not the ray's first hit) counting 0, give an irradiance
/// that passes the t-test against the closed form; the share of them that are visible is
/// the visible cap's share of the area, `(1 - R/d)/2` (t-test); and your answer is within
/// 1e-4 of the first-hit pdf's integral over the cone (the quadrature of
/// `sphere_cap_pdf_integrates_to_one`).
#[test]
#[ignore = "exercise 2 of Shadow-ray pdfs: fill in your_whole_sphere_sample and YOUR_ANSWER_2, then run it"]
fn exercise_2_the_whole_sphere() {
    let light = sphere();
    let p = DVec3::new(0.1, 0.2, -0.4);
    let n = (light.center() - p).normalize();
    let exact = sphere_irradiance(p, n, &light, 1.0);
    let visible = |s: &LightSample| {
        light
            .hit(p, s.dir)
            .is_some_and(|h| (h.dist - s.dist).abs() <= 1e-9 * s.dist)
    };
    let e = mean_of(520, N, |u, _| {
        your_whole_sphere_sample(&light, p, u)
            .filter(visible)
            .map_or(0.0, |s| n.dot(s.dir).max(0.0) / s.pdf)
    });
    assert!(
        accepts(&e, exact),
        "irradiance {} vs {exact}, p = {:e}",
        e.mean,
        p_value(&e, exact)
    );
    let d = (light.center() - p).length();
    let share = 0.5 * (1.0 - light.radius() / d);
    let v = mean_of(521, N, |u, _| {
        let s = your_whole_sphere_sample(&light, p, u).unwrap();
        f64::from(u8::from(visible(&s)))
    });
    assert!(accepts(&v, share), "visible share {} vs {share}", v.mean);
    let pa = 1.0 / (4.0 * PI * light.radius() * light.radius());
    let total = cone_integral(&light, p, |w| {
        light
            .hit(p, w)
            .map_or(0.0, |h| area_to_solid_angle(pa, h.dist, h.cos_light))
    });
    let yours = YOUR_ANSWER_2.expect("exercise 2 of Shadow-ray pdfs: set YOUR_ANSWER_2");
    assert!(
        (yours - total).abs() < 1e-4,
        "your {yours} vs {total} by quadrature"
    );
}

/// Exercise 4 of *Shadow-ray pdfs*: the variance per sample over `E^2` of sampling the
/// table's large light (6 x 6, centred 0.3 off the normal at height 1, shading point at the
/// origin, normal `+z`) uniformly in solid angle, to three decimals.
const YOUR_ANSWER_4: Option<f64> = None;

/// Your answer is within 1e-3 of `Omega int cos^2 dw / (int cos dw)^2 - 1`, each integral
/// over the light by the midpoint rule in area (`dw = |cos_l| dA / r^2`).
#[test]
#[ignore = "exercise 4 of Shadow-ray pdfs: set YOUR_ANSWER_4, then run it"]
fn exercise_4_spherical_rectangles() {
    let (side, m) = (6.0, 1000);
    let light = QuadLight::new(
        DVec3::new(0.3 - side / 2.0, -side / 2.0, 1.0),
        DVec3::new(0.0, side, 0.0),
        DVec3::new(side, 0.0, 0.0),
    )
    .unwrap();
    let (mut omega, mut first, mut second) = (0.0, 0.0, 0.0);
    let h = 1.0 / f64::from(m);
    for i in 0..m {
        for j in 0..m {
            let q = light
                .shape()
                .point((f64::from(i) + 0.5) * h, (f64::from(j) + 0.5) * h);
            let (r, w) = (q.length(), q.normalize());
            let d_omega = light.normal().dot(w).abs() / (r * r) * light.area() * h * h;
            omega += d_omega;
            first += w.z * d_omega;
            second += w.z * w.z * d_omega;
        }
    }
    let exact_e = light.irradiance(DVec3::ZERO, DVec3::Z, 1.0);
    assert!(
        (first / exact_e - 1.0).abs() < 1e-5,
        "{first} vs Lambert's {exact_e}"
    );
    let relative = omega * second / (first * first) - 1.0;
    let yours = YOUR_ANSWER_4.expect("exercise 4 of Shadow-ray pdfs: set YOUR_ANSWER_4");
    assert!(
        (yours - relative).abs() < 1e-3,
        "your {yours} vs {relative} by quadrature"
    );
}
