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

/// The source's two forms are the same map, not only the same distribution.
#[test]
fn seed_angles_and_cartesian_agree_pointwise() {
    let mut rng = raylemma::rng::seeded(3);
    for _ in 0..10_000 {
        let u = warp::square_point(&mut rng);
        let d = max_abs((cosine_seed_angles(u) - cosine_seed_cartesian(u)).to_array());
        assert!(d <= 1e-12, "u = {u:?}: differ by {d}");
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
    // u1 = 1e-17: 2 u1 - 1 rounds to -1, the rim; the true z is about 6.3e-9.
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

/// In f32 every construction gives unit vectors to within one ε. The source's Cartesian form
/// and Malley's method also keep `cos θ` (hence the pdf) accurate to one ε, up to u → 1
/// at the horizon; the source's angle form does not: `θ = acos(1 − 2u₁)/2` near π/2 leaves
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
        assert!(n <= 1.0, "{name}: worst norm error {n} ε");
        if name == "seed angles" {
            assert!(z >= 100.0, "{name}: cos θ error only {z} ε");
        } else {
            assert!(z <= 1.0, "{name}: worst cos θ error {z} ε");
        }
    }
    let z = z_error(planted::malley_naive_lift, cosine_malley, &points);
    assert!(z.is_nan() || z >= 1000.0, "the naive lift passed: {z} ε");
}

// ---------------------------------------------------------------------------------------
// Exercises: each test is ignored until the exercise is done; run one with
// `cargo test --test book sampling::cosine::exercise_1 -- --ignored`.

/// Exercise 1 of *Cosine-weighted hemisphere*: a direction of the `cos^n` lobe around `z`,
/// by inverting the CDF of `z = cos(theta)`.
fn your_cos_n_sample(u: DVec2, n: f64) -> DVec3 {
    let _ = (u, n);
    unimplemented!("exercise 1 of Cosine-weighted hemisphere: sample the cos^n lobe")
}

/// Exercise 1 of *Cosine-weighted hemisphere*: the `cos^n` lobe's density per steradian
/// (0 below the horizon).
fn your_cos_n_pdf(w: DVec3, n: f64) -> f64 {
    let _ = (w, n);
    unimplemented!("exercise 1 of Cosine-weighted hemisphere: the density of the cos^n lobe")
}

#[test]
#[ignore = "exercise 1 of Cosine-weighted hemisphere: fill in your_cos_n_sample and your_cos_n_pdf, then run it"]
fn exercise_1_cos_n_lobe() {
    let options = Options::default().cases(warp::TEST_SAMPLES);
    for n in [1.0, 10.0, 100.0] {
        let w = SquareWarp::new(
            format!("your cos^{n} lobe"),
            Domain::Sphere,
            move |u| your_cos_n_sample(u, n),
            move |w| your_cos_n_pdf(w, n),
        );
        let v = warp::check(&w, &options);
        v.assert_pass();
        assert!(!v.finding("jacobian").name.is_empty(), "{v}");
    }
    // n = 1 is the cosine density of this chapter.
    let mut rng = raylemma::rng::seeded(0xC05);
    for _ in 0..1000 {
        let w = raylemma::sampling::sphere::sphere_uniform(&mut rng);
        let (yours, ours) = (your_cos_n_pdf(w, 1.0), cosine_pdf(w));
        assert!(
            (yours - ours).abs() <= 1e-12 * ours.max(1.0),
            "at {w}: your cos^1 pdf {yours}, the cosine pdf {ours}"
        );
    }
    // And the checker tells the lobes apart: the n = 1 sampler against the n = 10 pdf.
    let mixed = SquareWarp::new(
        "your cos^1 samples, cos^10 pdf",
        Domain::Sphere,
        |u| your_cos_n_sample(u, 1.0),
        |w| your_cos_n_pdf(w, 10.0),
    );
    let v = warp::check(&mixed, &options);
    assert!(v.failed("chi_squared"), "{v}");
}

/// Exercise 2 of *Cosine-weighted hemisphere*: the smallest number of samples at which
/// chi-squared rejects the `cos^1.05` lobe claimed as a cosine lobe for 90 % of the seeds.
const YOUR_SAMPLES: Option<usize> = None;

#[test]
#[ignore = "exercise 2 of Cosine-weighted hemisphere: set YOUR_SAMPLES, then run it"]
fn exercise_2_power_against_cos_1_05() {
    use raylemma::check::warp::WarpOptions;
    use raylemma::stats::test_alpha;
    // The cos^1.05 lobe: P(Z <= z) = z^2.05, so z = (1 - u1)^(1/2.05).
    let lobe = SquareWarp::new(
        "cos^1.05 lobe claimed as cosine",
        Domain::Sphere,
        |u: DVec2| {
            let z = (1.0 - u.x).powf(1.0 / 2.05);
            let r = ((1.0 - z) * (1.0 + z)).max(0.0).sqrt();
            let phi = std::f64::consts::TAU * u.y;
            DVec3::new(r * phi.cos(), r * phi.sin(), z)
        },
        cosine_pdf,
    );
    // The power table's method: the share of seeds 1000, 1001, ... for which chi-squared
    // on 21 rows of cells rejects at the suite's level.
    let share = |samples: usize| {
        let seeds = 20;
        let rejected = (0..seeds)
            .filter(|&s| {
                let options = WarpOptions {
                    resolution: 21,
                    points: 0,
                    ..WarpOptions::from(Options::default().cases(samples).seed(1000 + s))
                };
                warp::chi_squared(&lobe, &options).is_ok_and(|(c, _, _)| c.p_value < test_alpha())
            })
            .count();
        rejected as f64 / seeds as f64
    };
    let n = YOUR_SAMPLES.expect("set YOUR_SAMPLES");
    let (above, below) = (share(2 * n), share(n / 2));
    assert!(
        above >= 0.9 && below < 0.9,
        "rejected for {:.0} % of the seeds at {} samples and {:.0} % at {}",
        100.0 * above,
        2 * n,
        100.0 * below,
        n / 2
    );
}
