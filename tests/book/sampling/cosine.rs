//! Tests of the chapter *Cosine-weighted hemisphere* (`src/sampling/cosine.rs`).
//! Chi-squared tests run at `raylemma::stats::test_alpha()` with fixed seeds.

use std::f64::consts::FRAC_1_PI;

use glam::{DVec2, DVec3};
use raylemma::check::warp::{self, Domain, SquareWarp, planted};
use raylemma::check::{Options, max_abs};
use raylemma::sampling::cosine::*;
use raylemma::sampling::disc::disc_concentric;

/// The warp checker at the sampler tests' settings (400 000 samples, 21 rows and 5 000
/// points by its rule).
fn check(
    name: &str,
    sample: fn(DVec2) -> DVec3,
    pdf: fn(DVec3) -> f64,
) -> raylemma::check::Verdict {
    let w = SquareWarp::new(name, Domain::Sphere, sample, pdf);
    warp::check(&w, &Options::default().cases(warp::TEST_SAMPLES))
}

#[test]
fn seed_inverse_cdf_in_angles_passes() {
    check("cosine, seed angles", cosine_seed_angles, cosine_pdf).assert_pass();
}

#[test]
fn seed_cartesian_form_passes() {
    check("cosine, seed cartesian", cosine_seed_cartesian, cosine_pdf).assert_pass();
}

#[test]
fn malley_with_the_concentric_disc_passes() {
    check("cosine, malley", cosine_malley, cosine_pdf).assert_pass();
}

/// The seed's two forms are the same map, not only the same distribution.
#[test]
fn seed_angles_and_cartesian_agree_pointwise() {
    let mut rng = raylemma::rng::seeded(3);
    for _ in 0..10_000 {
        let u = warp::square_point(&mut rng);
        let d = max_abs((cosine_seed_angles(u) - cosine_seed_cartesian(u)).to_array());
        assert!(d <= 1e-7, "u = {u:?}: differ by {d}");
    }
}

#[test]
fn a_uniform_hemisphere_claimed_as_cosine_is_rejected() {
    let v = check("uniform as cosine", planted::hemisphere_uniform, cosine_pdf);
    assert!(v.failed("chi_squared") && v.failed("jacobian"), "{v}");
}

#[test]
fn a_cos_1_1_lobe_is_rejected() {
    let v = check("cos^1.1", planted::cosine_power_lobe, cosine_pdf);
    assert!(v.failed("chi_squared"), "{v}");
}

#[test]
fn the_pdf_without_1_over_pi_is_rejected() {
    let v = check(
        "cosine, pdf cos",
        cosine_malley,
        planted::cosine_pdf_without_1_over_pi,
    );
    // Refused by name (the pdf integrates to pi), and the Jacobian check sees it too.
    let message = v.finding("chi_squared").example.clone().unwrap_or_default();
    assert!(message.contains("integrates to 3.14159"), "{v}");
    assert!(v.failed("jacobian"), "{v}");
}

/// u -> 1 and the rim: directions stay unit length with z > 0 (pdf > 0), so an estimator
/// dividing by the pdf stays finite. The naive lift sqrt(1 - x^2 - y^2) does not.
#[test]
fn grazing_samples_keep_a_positive_pdf() {
    let below_one = f64::from_bits(1.0f64.to_bits() - 1);
    let edges = [1e-300, 0.5, 1.0 - 1e-12, below_one];
    for &a in &edges {
        for &b in &edges {
            let u = DVec2::new(a, b);
            for (name, w) in [
                ("angles", cosine_seed_angles(u)),
                ("cartesian", cosine_seed_cartesian(u)),
                ("malley", cosine_malley(u)),
            ] {
                assert!(
                    w.is_finite() && (w.length() - 1.0).abs() <= 1e-12,
                    "{name} {u:?}: {w:?}"
                );
                assert!(cosine_pdf(w) > 0.0, "{name} {u:?}: pdf 0 at {w:?}");
                let weight = w.z / cosine_pdf(w);
                assert!(
                    (weight - 1.0 / FRAC_1_PI).abs() <= 1e-9,
                    "{name}: cos(theta) / pdf = {weight} at {w:?}; with pdf = cos(theta)/pi it must be pi"
                );
            }
        }
    }
}

#[test]
fn naive_malley_loses_the_rim() {
    // The planted bug: z from 1 - x^2 - y^2 rounds to <= 0 for some u near the rim.
    let naive = |u: DVec2| {
        let p = disc_concentric(u);
        (1.0 - p.x * p.x - p.y * p.y).sqrt()
    };
    // u1 = 1e-17: 2 u1 - 1 rounds to -1, the rim; the true z is about 9e-9.
    let bad = (0..1000)
        .map(|k| DVec2::new(1e-17, k as f64 / 1000.0))
        .skip(1)
        .filter(|&u| {
            let z = naive(u);
            z.is_nan() || z <= 0.0
        })
        .count();
    assert!(bad > 0, "the naive lift never failed");
    assert!((1..1000).all(|k| cosine_malley(DVec2::new(1e-17, k as f64 / 1000.0)).z > 0.0));
}

// ---------------------------------------------------------------------------------------
// Single precision.

/// In f32 every construction gives unit vectors to within an ε. The seed's Cartesian form
/// and Malley's method also keep `cos θ` (hence the pdf) accurate to an ε, up to u → 1
/// at the horizon; the seed's angle form does not: `θ = acos(1 − 2u₁)/2` near π/2 leaves
/// `cos θ` with an absolute error of about ε, hundreds of ε relative to a small `cos θ`.
/// The planted twin, Malley's lift written `z = sqrt(1 − x² − y²)`, cancels at the rim.
#[test]
fn single_precision_directions_are_unit_and_keep_cos_theta() {
    use raylemma::check::single::{norm_error, planted, square_points, z_error};
    use raylemma::single::sampling::cosine as single;
    type F32 = fn(glam::Vec2) -> glam::Vec3;
    type F64 = fn(glam::DVec2) -> DVec3;
    let points = square_points(&Options::default());
    let forms = [
        (
            "seed angles",
            single::cosine_seed_angles as F32,
            cosine_seed_angles as F64,
        ),
        (
            "seed Cartesian",
            single::cosine_seed_cartesian,
            cosine_seed_cartesian,
        ),
        ("Malley", single::cosine_malley, cosine_malley),
    ];
    for (name, f, exact) in forms {
        let (n, z) = (norm_error(f, &points), z_error(f, exact, &points));
        assert!(n <= 2.0, "{name}: worst norm error {n} ε");
        if name == "seed angles" {
            assert!(z >= 100.0, "{name}: cos θ error only {z} ε");
        } else {
            assert!(z <= 2.0, "{name}: worst cos θ error {z} ε");
        }
    }
    let z = z_error(planted::malley_naive_lift, cosine_malley, &points);
    assert!(z.is_nan() || z >= 1000.0, "the naive lift passed: {z} ε");
}
