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
