//! Tests of the chapter *Sampling a rectangle by solid angle* (`src/transport/rectangle.rs`).
//!
//! Every statistical test has a fixed seed and runs at `raylemma::stats::test_alpha()`, the
//! suite's Šidák level; this file holds 3 + 3 + 3 = 9 of the suite's budget (three shading
//! points each for the chi-squared test of uniformity, the irradiance t-test, and the
//! solid angle as the mean of `1 / pdf`). Each has planted-bug twins it must reject with a
//! p-value below `1e-6` times the level: a sampler that forgets the height's inversion
//! (`y` uniform along the column), and one that samples uniformly by area while claiming
//! the density `1 / Omega`.

use std::f64::consts::PI;

use glam::{DVec2, DVec3};
use raylemma::check::warp::square_point;
use raylemma::rng;
use raylemma::stats::chi2::pearson;
use raylemma::stats::test_alpha;
use raylemma::stats::ttest::{Summary, one_sample};
use raylemma::transport::rectangle::*;
use raylemma::transport::shadow::{Light, LightError, QuadLight, polygon_irradiance};

/// A 1.5 x 0.8 rectangle at height 1.2 facing down (-z).
fn light() -> RectangleLight {
    RectangleLight::new(
        DVec3::new(-0.4, -0.3, 1.2),
        DVec3::new(0.0, 0.8, 0.0),
        DVec3::new(1.5, 0.0, 0.0),
    )
    .unwrap()
}

/// Shading points below the light: off-axis, close under a corner, and far to the side
/// at a grazing angle.
const POINTS: [[f64; 3]; 3] = [[0.1, -0.2, 0.0], [-0.3, 0.4, 1.1], [3.0, 2.5, 1.1]];

/// The solid angle of `[x0, x1] x [y0, y1]` at height `z` seen from the origin, from the
/// closed form for a rectangle with a corner above the foot of the perpendicular,
/// `F(x, y) = atan(x y / (|z| sqrt(x^2 + y^2 + z^2)))`, odd in `x` and in `y`:
/// `Omega = F(x1, y1) - F(x0, y1) - F(x1, y0) + F(x0, y0)`. Independent of the module's
/// Van Oosterom–Strackee triangles and of Girard's angles.
fn corner_formula(x0: f64, x1: f64, y0: f64, y1: f64, z: f64) -> f64 {
    let f = |x: f64, y: f64| (x * y / (z.abs() * (x * x + y * y + z * z).sqrt())).atan();
    f(x1, y1) - f(x0, y1) - f(x1, y0) + f(x0, y0)
}

/// The light's local frame seen from `p`: `(x0, y0, z0)`, the unit edges and the lengths.
fn local(light: &RectangleLight, p: DVec3) -> (f64, f64, f64, DVec3, DVec3, f64, f64) {
    let [e1, e2] = light.quad().shape().edges();
    let (lx, ly) = (e1.length(), e2.length());
    let (x, y) = (e1 / lx, e2 / ly);
    let d = light.quad().shape().corner() - p;
    (
        d.dot(x),
        d.dot(y),
        d.dot(light.quad().normal()),
        x,
        y,
        lx,
        ly,
    )
}

fn exact_omega(light: &RectangleLight, p: DVec3) -> f64 {
    let (x0, y0, z0, _, _, lx, ly) = local(light, p);
    corner_formula(x0, x0 + lx, y0, y0 + ly, z0)
}

#[test]
fn solid_angle_matches_the_corner_formula() {
    let l = light();
    let mut points: Vec<DVec3> = POINTS.iter().map(|&p| DVec3::from(p)).collect();
    // Nearly in the plane: beside the light, and just below its interior (Omega near 2 pi).
    points.extend([
        DVec3::new(2.0, 0.1, 1.2 - 1e-3),
        DVec3::new(-1.0, -1.0, 1.2 - 1e-5),
        DVec3::new(0.3, 0.1, 1.2 - 1e-9),
        // Far: Omega about 1e-5, and behind the light.
        DVec3::new(100.0, 200.0, -300.0),
        DVec3::new(0.1, 0.2, 2.0),
    ]);
    for p in points {
        let exact = exact_omega(&l, p);
        let view = l.view(p).expect("above MIN_SOLID_ANGLE");
        assert!(
            (view.omega - exact).abs() <= 1e-9 * exact,
            "{p}: {} vs {exact}",
            view.omega
        );
    }
    // Girard's sum of the four angles minus 2 pi agrees where it has digits to spare.
    let p = DVec3::from(POINTS[0]);
    let (x0, y0, z0, _, _, lx, ly) = local(&l, p);
    let z = -z0.abs();
    let angle =
        |x: f64, y: f64, c: f64| (z.abs() * (x * x + y * y + z * z).sqrt()).atan2(c * x * y);
    let (x1, y1) = (x0 + lx, y0 + ly);
    let girard =
        angle(x0, y0, -1.0) + angle(x1, y0, 1.0) + angle(x1, y1, -1.0) + angle(x0, y1, 1.0)
            - 2.0 * PI;
    assert!((girard - exact_omega(&l, p)).abs() < 1e-13, "{girard}");
}

/// Local `(a, b)` in `[0, 1]^2` of a point on the light, and its height off the plane.
fn on_light(light: &RectangleLight, q: DVec3) -> (f64, f64, f64) {
    let [e1, e2] = light.quad().shape().edges();
    let d = q - light.quad().shape().corner();
    (
        d.dot(e1) / e1.length_squared(),
        d.dot(e2) / e2.length_squared(),
        d.dot(light.quad().normal()),
    )
}

#[test]
fn samples_land_on_the_light_with_the_pdf_one_over_omega() {
    let l = light();
    let mut rng = rng::seeded(11);
    let mut misses = 0;
    for i in 0..2000 {
        // Points around the light, on both sides, from 1e-4 to 10 off its plane.
        let h =
            10f64.powf(-4.0 + 5.0 * square_point(&mut rng).x) * if i % 2 == 0 { -1.0 } else { 1.0 };
        let xy = 6.0 * square_point(&mut rng) - DVec2::splat(3.0);
        let p = DVec3::new(xy.x, xy.y, 1.2 + h);
        let omega = exact_omega(&l, p);
        let Some(view) = l.view(p) else {
            assert!(omega < 1.001 * MIN_SOLID_ANGLE, "{p}: {omega}");
            continue;
        };
        for _ in 0..20 {
            let s = l.sample(p, square_point(&mut rng)).expect("a sample");
            let (a, b, off) = on_light(&l, s.point);
            assert!(
                (0.0..=1.0).contains(&a) && (0.0..=1.0).contains(&b) && off.abs() < 1e-14,
                "{p}: ({a}, {b}, {off})"
            );
            assert_eq!(s.pdf, 1.0 / view.omega);
            assert!(
                (s.pdf * omega - 1.0).abs() < 1e-9,
                "{p}: {} vs {omega}",
                1.0 / s.pdf
            );
            assert!((s.dist - (s.point - p).length()).abs() <= 1e-15 * s.dist);
            assert!((s.dir - (s.point - p) / s.dist).length() < 1e-15);
            assert_eq!(s.cos_light, l.quad().normal().dot(s.dir));
            assert_eq!(s.cos_light < 0.0, h < 0.0, "{p}: emitting side");
            let pdf = l.pdf(p, s.dir);
            if pdf == 0.0 {
                // The cast may miss a sample on an edge by rounding.
                misses += 1;
            } else {
                assert_eq!(pdf, s.pdf);
            }
        }
    }
    assert!(misses < 20, "{misses} samples the ray cast missed");
}

/// A sampler of `(x, y)` in the light's frame seen from `p`.
type Sampler = fn(&SphericalRectangle, DVec2) -> DVec2;

fn correct(v: &SphericalRectangle, u: DVec2) -> DVec2 {
    v.sample(u)
}

/// Planted bug: the abscissa inverted, the height not (`y` uniform along the column).
fn no_height_inversion(v: &SphericalRectangle, u: DVec2) -> DVec2 {
    DVec2::new(v.abscissa(u.x), v.y0 + u.y * (v.y1 - v.y0))
}

/// Planted bug: uniform by area (while the light claims `1 / Omega`).
fn uniform_area(v: &SphericalRectangle, u: DVec2) -> DVec2 {
    DVec2::new(v.x0 + u.x * (v.x1 - v.x0), v.y0 + u.y * (v.y1 - v.y0))
}

const PLANTED: [(&str, Sampler); 2] = [
    ("no height inversion", no_height_inversion),
    ("uniform area", uniform_area),
];

/// Pearson's p-value of `n` samples of `sampler` from `p`, binned in a `k x k` grid of the
/// light's `(a, b)`, against the counts `n Omega_cell / Omega` by [`corner_formula`].
fn uniformity_p(light: &RectangleLight, p: DVec3, sampler: Sampler, seed: u64) -> f64 {
    const K: usize = 12;
    const N: usize = 200_000;
    let view = light.view(p).unwrap();
    let (lx, ly) = (view.x1 - view.x0, view.y1 - view.y0);
    let mut observed = vec![0u64; K * K];
    let mut rng = rng::seeded(seed);
    for _ in 0..N {
        let xy = sampler(&view, square_point(&mut rng));
        let a = (((xy.x - view.x0) / lx * K as f64) as usize).min(K - 1);
        let b = (((xy.y - view.y0) / ly * K as f64) as usize).min(K - 1);
        observed[a * K + b] += 1;
    }
    let total = corner_formula(view.x0, view.x1, view.y0, view.y1, view.z0);
    let mut expected = vec![0.0; K * K];
    for i in 0..K {
        for j in 0..K {
            let x = |i: usize| view.x0 + lx * i as f64 / K as f64;
            let y = |j: usize| view.y0 + ly * j as f64 / K as f64;
            let cell = corner_formula(x(i), x(i + 1), y(j), y(j + 1), view.z0);
            expected[i * K + j] = N as f64 * cell / total;
        }
    }
    pearson(&observed, &expected, 5.0).unwrap().p_value
}

#[test]
fn directions_are_uniform_in_solid_angle_chi_squared() {
    let l = light();
    for (i, &p) in POINTS.iter().enumerate() {
        let p = DVec3::from(p);
        let seed = 20 + i as u64;
        let ok = uniformity_p(&l, p, correct, seed);
        assert!(ok >= test_alpha(), "{p}: p = {ok:e}");
        for (bug, sampler) in PLANTED {
            let bad = uniformity_p(&l, p, sampler, seed);
            assert!(
                bad < 1e-6 * test_alpha(),
                "{p}: planted {bug} passed, p = {bad:e}"
            );
        }
    }
}

/// The mean of `f(u)` over `n` seeded points of the unit square.
fn mean_of(seed: u64, n: usize, mut f: impl FnMut(DVec2) -> f64) -> Summary {
    let mut rng = rng::seeded(seed);
    Summary::of((0..n).map(|_| f(square_point(&mut rng))))
}

/// The irradiance estimate `L cos / p_w` at `p` (normal up, +z) with a sample at `(x, y)`
/// from `sampler`, with the density `1 / Omega` the light claims.
fn irradiance_estimate(light: &RectangleLight, p: DVec3, sampler: Sampler, u: DVec2) -> f64 {
    let view = light.view(p).unwrap();
    let xy = sampler(&view, u);
    let (_, _, z0, ex, ey, _, _) = local(light, p);
    let q = p + xy.x * ex + xy.y * ey + z0 * light.quad().normal();
    let w = (q - p).normalize();
    w.z.max(0.0) * view.omega
}

#[test]
fn irradiance_is_unbiased_and_the_planted_bugs_are_not() {
    let l = light();
    for (i, &p) in POINTS.iter().enumerate() {
        let p = DVec3::from(p);
        let exact = polygon_irradiance(p, DVec3::Z, &l.quad().vertices(), 1.0);
        let seed = 30 + i as u64;
        // Through the Light trait, as the renderer calls it.
        let s = mean_of(seed, 100_000, |u| {
            l.sample(p, u).map_or(0.0, |s| {
                s.dir.z.max(0.0) * f64::from(s.cos_light < 0.0) / s.pdf
            })
        });
        let t = one_sample(&s, exact).unwrap();
        assert!(
            t.p_value >= test_alpha(),
            "{p}: {} vs {exact}, p = {:e}",
            s.mean,
            t.p_value
        );
        // And its variance is below area sampling's.
        let area = mean_of(seed, 100_000, |u| {
            l.quad()
                .sample(p, u)
                .map_or(0.0, |s| s.dir.z.max(0.0) / s.pdf)
        });
        assert!(
            s.variance() < area.variance(),
            "{p}: {} vs {}",
            s.variance(),
            area.variance()
        );
        for (bug, sampler) in PLANTED {
            let b = mean_of(seed, 100_000, |u| irradiance_estimate(&l, p, sampler, u));
            let t = one_sample(&b, exact).unwrap();
            assert!(
                t.p_value < 1e-6 * test_alpha(),
                "{p}: planted {bug} passed: {} vs {exact}",
                b.mean
            );
        }
    }
}

#[test]
fn solid_angle_is_the_mean_of_one_over_pdf_of_the_area_sampler() {
    // The pdf the light reports for directions drawn uniformly by area: its mean of
    // p_w(rect) / p_w(area) is 1 (both densities integrate to 1 over the same set).
    let l = light();
    for (i, &p) in POINTS.iter().enumerate() {
        let p = DVec3::from(p);
        let s = mean_of(40 + i as u64, 100_000, |u| {
            l.quad()
                .sample(p, u)
                .map_or(0.0, |s| l.pdf(p, s.dir) / s.pdf)
        });
        let t = one_sample(&s, 1.0).unwrap();
        assert!(
            t.p_value >= test_alpha(),
            "{p}: {}, p = {:e}",
            s.mean,
            t.p_value
        );
    }
}

#[test]
fn hard_cases_are_finite_and_fall_back_consistently() {
    let l = light();
    // In the plane: no sample, pdf 0.
    let p = DVec3::new(3.0, 0.0, 1.2);
    assert!(l.view(p).is_none());
    assert!(l.sample(p, DVec2::splat(0.5)).is_none());
    assert_eq!(l.pdf(p, DVec3::new(-1.0, 0.0, 0.0)), 0.0);
    // Far away: below MIN_SOLID_ANGLE it is the quad light, sample and pdf alike.
    let far = DVec3::new(1e3, 2e3, -3e3);
    assert!(l.view(far).is_none() && exact_omega(&l, far) < MIN_SOLID_ANGLE);
    let u = DVec2::new(0.3, 0.7);
    let s = l.sample(far, u).unwrap();
    assert_eq!(Some(s), l.quad().sample(far, u));
    assert_eq!(l.pdf(far, s.dir), l.quad().pdf(far, s.dir));
    // u at the corners of the square lands at the light's corners, for a point just below
    // the interior (Omega near 2 pi) and one far to the side.
    for p in [
        DVec3::new(0.3, 0.1, 1.2 - 1e-9),
        DVec3::new(30.0, 25.0, 1.0),
    ] {
        for (u, ab) in [
            (DVec2::new(0.0, 0.0), (0.0, 0.0)),
            (DVec2::new(1.0, 0.0), (1.0, 0.0)),
            (DVec2::new(0.0, 1.0), (0.0, 1.0)),
            (DVec2::new(1.0, 1.0), (1.0, 1.0)),
        ] {
            let s = l.sample(p, u).unwrap();
            let (a, b, _) = on_light(&l, s.point);
            assert!(
                (a - ab.0).abs() < 1e-6 && (b - ab.1).abs() < 1e-6,
                "{p}, {u}: ({a}, {b})"
            );
            assert!(s.pdf.is_finite() && s.pdf > 0.0);
        }
        // And u out of range is clamped.
        let s = l.sample(p, DVec2::new(-0.5, 1.5)).unwrap();
        let (a, b, _) = on_light(&l, s.point);
        assert!((0.0..=1.0).contains(&a) && (0.0..=1.0).contains(&b));
    }
    // A parallelogram is refused, naming the problem.
    let e = RectangleLight::new(DVec3::ZERO, DVec3::X, DVec3::new(0.1, 1.0, 0.0)).unwrap_err();
    assert!(matches!(e, LightError::NotRectangle(_)), "{e}");
    assert!(e.to_string().contains("not perpendicular"), "{e}");
    let quad = QuadLight::new(DVec3::ZERO, DVec3::X, DVec3::Y).unwrap();
    assert!(RectangleLight::try_from(quad).is_ok());
}
