//! Tests of the chapter *The unit disc* (`src/sampling/disc.rs`).
//! Chi-squared tests run at `raylemma::stats::test_alpha()` with fixed seeds.

use glam::{DVec2, DVec3};
use raylemma::check::warp::{self, Domain, SquareWarp, planted};
use raylemma::check::{Options, max_abs};
use raylemma::sampling::disc::*;

/// The warp checker at the sampler tests' settings (400 000 samples, 21 rows and 5 000
/// points by its rule), with the round trip.
fn check(
    name: &str,
    sample: fn(DVec2) -> DVec3,
    invert: fn(DVec3) -> DVec2,
) -> raylemma::check::Verdict {
    let w = SquareWarp::new(name, Domain::Disc, sample, disc_pdf).inverse(invert);
    warp::check(&w, &Options::default().cases(warp::TEST_SAMPLES))
}

#[test]
fn polar_map_passes_every_check() {
    let v = check("disc polar", disc_polar, disc_polar_invert);
    v.assert_pass();
    assert_eq!(v.findings.len(), 3);
}

#[test]
fn concentric_map_passes_every_check() {
    let v = check("disc concentric", disc_concentric, disc_concentric_invert);
    v.assert_pass();
    assert_eq!(v.findings.len(), 3);
}

#[test]
fn r_equals_u_is_rejected() {
    let v = check("disc r = u", planted::disc_r_equals_u, disc_polar_invert);
    assert!(v.failed("chi_squared") && v.failed("jacobian"), "{v}");
    // The report speaks in the disc's terms: r = u crowds the centre, so the worst cell is
    // the innermost ring, with more samples than the pdf predicts.
    let report = v.to_string();
    let worst = report
        .lines()
        .find(|l| l.contains("r^2 in ["))
        .unwrap_or_default();
    assert!(
        worst.contains("r^2 in [0.000,") && worst.contains(" sd)") && worst.contains('+'),
        "{report}"
    );
}

#[test]
fn concentric_with_a_wrong_wedge_angle_is_rejected() {
    // Planted bug: pi/2 instead of pi/4 in the first wedge folds the disc over itself.
    let v = check(
        "concentric bad wedge",
        planted::concentric_wrong_wedge,
        disc_concentric_invert,
    );
    assert!(v.failed("chi_squared"), "{v}");
}

#[test]
fn concentric_map_distorts_less_than_polar() {
    // Anisotropy (ratio of the Jacobian's singular values) over a grid of the square.
    let grid = || {
        (1..100).flat_map(|i| (1..100).map(move |j| DVec2::new(i as f64 / 100.0, j as f64 / 100.0)))
    };
    let worst = |f: fn(DVec2) -> DVec3| max_abs(grid().map(|u| anisotropy(f, u)));
    let (polar, concentric) = (worst(disc_polar), worst(disc_concentric));
    // Polar: ratio 4 pi u1 or its inverse, 1/(4 pi 0.01) ~ 8 at u1 = 0.01 and 4 pi ~ 12.6 at u1 = 1.
    assert!(polar >= 10.0, "polar {polar}");
    // Concentric: bounded by about 1.9 (wedge corners), well below polar.
    assert!(concentric <= 2.5, "concentric {concentric}");
}

#[test]
fn centre_and_edges_are_exact() {
    assert_eq!(disc_concentric(DVec2::splat(0.5)), DVec3::ZERO);
    assert_eq!(disc_concentric_invert(DVec3::ZERO), DVec2::splat(0.5));
    for u in [
        DVec2::new(0.0, 0.0),
        DVec2::new(1.0, 0.3),
        DVec2::new(0.999_999_999, 0.999_999_999),
    ] {
        for p in [disc_polar(u), disc_concentric(u)] {
            assert!(p.is_finite() && p.length() <= 1.0 + 1e-15, "{u:?} -> {p:?}");
        }
    }
}

/// The polar inverse maps azimuth 0 to u2 = 0, not 1.
#[test]
fn polar_inverse_at_the_azimuth_seam() {
    let u = DVec2::new(0.25, 0.0);
    let back = disc_polar_invert(disc_polar(u));
    assert!(
        max_abs((back - u).to_array()) <= 1e-15,
        "the inverse of the polar map sent u = {u:?} to T(u) and back to {back:?}; at the seam phi = 0 it must return u"
    );
}

/// The sine and cosine the concentric map takes, by their series on `[-pi/4, pi/4]`,
/// against the standard library's on a million angles across the range, both ends, zero,
/// subnormal and tiny angles: within `2 eps` of the value in `f64`, and likewise in the
/// `f32` twin against the `f64` value. The map itself agrees with its libm form (the
/// angle's `cos`, `sin` of the wedge angle, as the chapter first writes it) to `4 eps`.
#[test]
fn the_quarter_range_sine_and_cosine_are_within_two_eps() {
    use std::f64::consts::FRAC_PI_4;
    let mut xs: Vec<f64> = (0..=1_000_000)
        .map(|i| -FRAC_PI_4 + 2.0 * FRAC_PI_4 * f64::from(i) / 1e6)
        .collect();
    xs.extend([
        FRAC_PI_4, -FRAC_PI_4, 0.0, -0.0, 1e-300, 5e-324, 1e-8, -1e-8,
    ]);
    for &x in &xs {
        let ((s, c), (s0, c0)) = (sin_cos_quarter(x), x.sin_cos());
        assert!(
            (s - s0).abs() <= 2.0 * f64::EPSILON * s0.abs()
                && (c - c0).abs() <= 2.0 * f64::EPSILON * c0,
            "at {x}: series ({s}, {c}), std ({s0}, {c0})"
        );
        let (s32, c32) = raylemma::single::sampling::disc::sin_cos_quarter(x as f32);
        let (s1, c1) = (x as f32 as f64).sin_cos();
        assert!(
            (f64::from(s32) - s1).abs() <= 2.0 * f64::from(f32::EPSILON) * s1.abs()
                && (f64::from(c32) - c1).abs() <= 2.0 * f64::from(f32::EPSILON) * c1,
            "f32 at {x}: series ({s32}, {c32}), f64 ({s1}, {c1})"
        );
    }
    let libm = |u: DVec2| {
        let a = 2.0 * u - DVec2::ONE;
        let (r, phi) = if a.x.abs() > a.y.abs() {
            (a.x, FRAC_PI_4 * (a.y / a.x))
        } else {
            (a.y, std::f64::consts::FRAC_PI_2 - FRAC_PI_4 * (a.x / a.y))
        };
        DVec3::new(r * phi.cos(), r * phi.sin(), 0.0)
    };
    let mut rng = raylemma::rng::seeded(0xd15c);
    for _ in 0..200_000 {
        let u = DVec2::new(
            rand::RngExt::random(&mut rng),
            rand::RngExt::random(&mut rng),
        );
        let (p, q) = (disc_concentric(u), libm(u));
        assert!(
            (p - q).abs().max_element() <= 4.0 * f64::EPSILON,
            "at u = {u}: {p} against the libm form's {q}"
        );
    }
}
