//! Tests of the chapter *Uniform sphere and hemisphere* (`src/sampling/sphere.rs`).
//! Chi-squared tests run at `raylemma::stats::test_alpha()` with fixed seeds.

use std::f64::consts::{PI, TAU};

use glam::{DVec2, DVec3};
use raylemma::check::warp::{self, Domain, RngWarp, SquareWarp, planted};
use raylemma::check::{Options, max_abs};
use raylemma::rng::{self, Rng};
use raylemma::sampling::sphere::*;
use raylemma::stats::{chi2, test_alpha};

/// The sampler tests' settings: 400 000 samples, and by the warp checker's rule 21 rows of
/// cells and 5 000 Jacobian and round-trip points.
fn opts() -> Options {
    Options::default().cases(warp::TEST_SAMPLES)
}

#[test]
fn inverse_cdf_passes_chi_squared_jacobian_and_round_trip() {
    let w = SquareWarp::new(
        "sphere inverse cdf",
        Domain::Sphere,
        sphere_inverse_cdf,
        sphere_pdf,
    )
    .inverse(sphere_inverse_cdf_invert);
    let v = warp::check(&w, &opts());
    v.assert_pass();
    assert_eq!(v.findings.len(), 3);
}

#[test]
fn gaussian_passes_chi_squared() {
    let w = RngWarp {
        name: "sphere gaussian".into(),
        domain: Domain::Sphere,
        sample: sphere_gaussian,
        pdf: sphere_pdf,
    };
    warp::check(&w, &opts()).assert_pass();
}

#[test]
fn rejection_passes_chi_squared() {
    let w = RngWarp {
        name: "sphere rejection".into(),
        domain: Domain::Sphere,
        sample: |rng: &mut Rng| sphere_rejection(rng).0,
        pdf: sphere_pdf,
    };
    warp::check(&w, &opts()).assert_pass();
}

/// The Gaussian and rejection methods are not warps of the square, so their Jacobian
/// check is the radial change of variables: integrating the 3D density along a ray,
/// `p(w) = int_0^inf rho(t w) t^2 dt`, must give `1 / (4 pi)` in every direction.
#[test]
fn radial_densities_integrate_to_the_uniform_sphere_pdf() {
    let gauss = |t: f64| (-t * t / 2.0).exp() / (TAU).powf(1.5);
    let ball = |t: f64| if t <= 1.0 { 3.0 / (4.0 * PI) } else { 0.0 };
    // Midpoint rule, fine enough for 1e-6 relative accuracy on these smooth integrands.
    let radial = |rho: &dyn Fn(f64) -> f64, upper: f64| {
        let n = 200_000;
        let h = upper / n as f64;
        (0..n)
            .map(|k| (k as f64 + 0.5) * h)
            .map(|t| rho(t) * t * t * h)
            .sum::<f64>()
    };
    for (name, value) in [
        ("gaussian", radial(&gauss, 12.0)),
        ("ball", radial(&ball, 1.0)),
    ] {
        let err = (value / SPHERE_PDF - 1.0).abs();
        assert!(err <= 1e-6, "{name}: {value} vs {SPHERE_PDF}");
    }
}

#[test]
fn rejection_acceptance_rate_is_pi_over_6() {
    let mut rng = rng::seeded(0xACC);
    let n = 200_000u64;
    let draws: u64 = (0..n)
        .map(|_| u64::from(sphere_rejection(&mut rng).1))
        .sum();
    // n acceptances in `draws` trials: test against a binomial with p = pi/6.
    let p = PI / 6.0;
    let observed = [n, draws - n];
    let expected = [draws as f64 * p, draws as f64 * (1.0 - p)];
    let test = chi2::pearson(&observed, &expected, 5.0).unwrap();
    assert!(
        test.p_value >= test_alpha(),
        "acceptance {} (p = {})",
        n as f64 / draws as f64,
        test.p_value
    );
    // Planted twin: the same counts tested against the rate 1/2 must be rejected.
    let wrong = [draws as f64 * 0.5, draws as f64 * 0.5];
    assert!(chi2::pearson(&observed, &wrong, 5.0).unwrap().p_value < test_alpha());
}

#[test]
fn hemisphere_by_flipping_passes() {
    let n = DVec3::new(0.3, -0.4, 0.866).normalize();
    let w = RngWarp {
        name: "hemisphere flip".into(),
        domain: Domain::Sphere,
        sample: move |rng: &mut Rng| hemisphere_flip(sphere_gaussian(rng), n),
        pdf: move |w| hemisphere_pdf(w, n),
    };
    warp::check(&w, &opts()).assert_pass();
}

#[test]
fn hemisphere_claimed_at_the_sphere_density_is_rejected() {
    // Planted bug: flipping without doubling the pdf (the pdf then integrates to 1/2).
    let w = RngWarp {
        name: "hemisphere, sphere pdf".into(),
        domain: Domain::Sphere,
        sample: |rng: &mut Rng| hemisphere_flip(sphere_gaussian(rng), DVec3::Z),
        pdf: planted::hemisphere_pdf_not_doubled,
    };
    let v = warp::check(&w, &opts());
    assert!(v.failed("chi_squared"), "{v}");
    // Refused by name, as the chapter says: the pdf integrates to 1/2.
    let message = v.finding("chi_squared").example.clone().unwrap_or_default();
    assert!(message.contains("integrates to 0.500000"), "{message}");
}

#[test]
fn near_zero_vectors_normalise_or_are_refused() {
    use raylemma::single::sampling::sphere as single;
    assert_eq!(normalize_robust(DVec3::ZERO), None);
    assert_eq!(normalize_robust(DVec3::new(f64::NAN, 0.0, 0.0)), None);
    assert_eq!(normalize_robust(DVec3::new(f64::INFINITY, 0.0, 0.0)), None);
    // A NaN or infinity beside a finite component: glam's `max_element` drops a NaN in
    // all but the last component, so the largest component alone would let these through.
    for bad in [
        DVec3::new(f64::NAN, 1.0, 0.0),
        DVec3::new(1.0, f64::NAN, 0.0),
        DVec3::new(0.0, 1.0, f64::NAN),
        DVec3::new(f64::NEG_INFINITY, 1.0, 0.0),
    ] {
        assert_eq!(normalize_robust(bad), None, "{bad:?}");
        assert_eq!(single::normalize_robust(bad.as_vec3()), None, "{bad:?}");
    }
    for v in [
        DVec3::new(1e-300, -2e-300, 2e-300),
        DVec3::new(5e-324, 0.0, 0.0),
        DVec3::new(3e-170, 4e-170, 0.0),
    ] {
        let w = normalize_robust(v).expect("a tiny non-zero vector normalises");
        assert!(
            (w.length() - 1.0).abs() <= 4.0 * f64::EPSILON,
            "{v:?} -> {w:?}"
        );
        assert!(w.dot(v.signum()) > 0.0);
    }
    // glam's plain normalize fails on the same inputs: the reason normalize_robust exists.
    assert!(!DVec3::new(1e-300, -2e-300, 2e-300).normalize().is_finite());
    // Its |v|^2 is 0: infinite in the non-zero components, NaN in a zero one.
    let all = DVec3::new(1e-300, -2e-300, 2e-300).normalize();
    assert!(all.to_array().iter().all(|c| c.is_infinite()), "{all:?}");
    let one = DVec3::new(5e-324, 0.0, 0.0).normalize();
    assert!(
        one.x.is_infinite() && one.y.is_nan() && one.z.is_nan(),
        "{one:?}"
    );
}

#[test]
fn inverse_cdf_is_accurate_at_the_poles() {
    for u in [0.0, 1e-300, 1e-17, 0.5, 1.0 - f64::EPSILON / 2.0] {
        let w = sphere_inverse_cdf(DVec2::new(u, 0.3));
        assert!(
            (w.length() - 1.0).abs() <= 4.0 * f64::EPSILON,
            "u = {u}: {w:?}"
        );
    }
    // At inputs the project's generator produces (multiples of 2^-53), near the pole: with
    // u = k 2^-53, z = 1 - 2u is exact and z^2 rounds to 1 - 4u (the 4u^2 it drops is below
    // half an ulp), so the source's sqrt(1 - z^2) is 2 sqrt(u), wrong by u/2 relative:
    // about 2.3e5 eps at u = 1e-10. The exact radius 2 sqrt(u (1 - u)) is
    // 2^-52 sqrt(k (2^53 - k)), computed here in integers: r 2^72 = sqrt(k (2^53 - k) 2^40).
    for (target, source_at_least) in [(1e-10, 1e5), (1e-8, 1e6)] {
        let k = (target * 2f64.powi(53)).round() as u128;
        let u = k as f64 * 2f64.powi(-53);
        let exact = ((k * ((1u128 << 53) - k)) << 40).isqrt(); // r 2^72, to 1 part in 1e17
        let rel = |r: f64| ((r * 2f64.powi(72)) as i128 - exact as i128) as f64 / exact as f64;
        let w = sphere_inverse_cdf(DVec2::new(u, 0.0));
        let z: f64 = 1.0 - 2.0 * u;
        let (code, source) = (
            rel(w.x) / f64::EPSILON,
            rel((1.0 - z * z).sqrt()) / f64::EPSILON,
        );
        assert!(
            code.abs() <= 2.0,
            "u = {u:e}: the code's radius is off by {code} eps"
        );
        assert!(
            source.abs() >= source_at_least,
            "u = {u:e}: the source's radius is off by only {source} eps"
        );
    }
    // Smaller u still, as other generators (low-discrepancy points) produce: at u = 1e-20
    // the source's sqrt(1 - z^2) returns 0, and the code's radius keeps its precision.
    let u = 1e-20;
    let w = sphere_inverse_cdf(DVec2::new(u, 0.0));
    assert!((w.x / (2.0 * u.sqrt()) - 1.0).abs() <= 1e-12);
    let z: f64 = 1.0 - 2.0 * u;
    assert_eq!((1.0 - z * z).sqrt(), 0.0);
}

/// The inverse maps azimuth 0 to u2 = 0, not 1: the seam of the square is closed on one
/// side only.
#[test]
fn inverse_at_the_azimuth_seam() {
    let u = DVec2::new(0.3, 0.0);
    let back = sphere_inverse_cdf_invert(sphere_inverse_cdf(u));
    assert!(max_abs((back - u).to_array()) <= 1e-15, "{back:?}");
}

/// In f32 the inverse CDF gives unit vectors to within an ε and `z = 1 − 2u₁` exactly
/// rounded, up to u → 1 (the hard cases of `check::single::square_points`); the robust
/// normalisation of the Gaussian and rejection methods leaves at most an ε too.
#[test]
fn single_precision_directions_are_unit() {
    use raylemma::check::single::{norm_error, square_points, z_error};
    use raylemma::single::sampling::sphere as single;
    let points = square_points(&Options::default());
    let n = norm_error(single::sphere_inverse_cdf, &points);
    assert!(n <= 2.0, "inverse CDF: worst norm error {n} ε");
    let z = z_error(single::sphere_inverse_cdf, sphere_inverse_cdf, &points);
    assert!(z <= 1.0, "inverse CDF: worst z error {z} ε");
    // Normalising f32 vectors of every length from 1e-30 to 1e30.
    let mut r = raylemma::rng::seeded(0x5F33);
    let worst = max_abs((0..100_000).map(|_| {
        let v = raylemma::sampling::sphere::sphere_uniform(&mut r).as_vec3()
            * 10f32.powf(raylemma::rng::uniform(&mut r, -30.0, 30.0) as f32);
        let w = single::normalize_robust(v).expect("non-zero finite vector");
        (w.as_dvec3().length() - 1.0) / f64::from(f32::EPSILON)
    }));
    assert!(worst <= 2.0, "normalize_robust: worst norm error {worst} ε");
}

// ---------------------------------------------------------------------------------------
// Exercises: each test is ignored until the exercise is done; run one with
// `cargo test --test book sampling::sphere::exercise_1 -- --ignored`.

/// Exercise 1 of *Uniform sphere and hemisphere*: a uniform direction on the hemisphere
/// around `z` by inverting its CDF, `z = u1`, `phi = 2 pi u2`, with the radius of the
/// circle at height `z` computed without cancellation near the pole.
fn your_hemisphere_inverse_cdf(u: DVec2) -> DVec3 {
    let _ = u;
    unimplemented!("exercise 1 of Uniform sphere and hemisphere: invert the hemisphere's CDF")
}

#[test]
#[ignore = "exercise 1 of Uniform sphere and hemisphere: fill in your_hemisphere_inverse_cdf, then run it"]
fn exercise_1_hemisphere_inverse_cdf() {
    let w = SquareWarp::new(
        "hemisphere, your inverse CDF",
        Domain::Sphere,
        your_hemisphere_inverse_cdf,
        |w: DVec3| hemisphere_pdf(w, DVec3::Z),
    );
    let v = warp::check(&w, &opts());
    v.assert_pass();
    assert_eq!(v.findings.len(), 2, "chi-squared and the Jacobian: {v}");
    // Near the pole, z -> 1: the radius sqrt((1 - z)(1 + z)), where 1 - z is exact.
    for k in (1..=1000)
        .map(f64::from)
        .chain([2f64.powi(20), 2f64.powi(40)])
    {
        let u1 = 1.0 - k * f64::EPSILON / 2.0;
        let w = your_hemisphere_inverse_cdf(DVec2::new(u1, 0.1));
        let radius = w.x.hypot(w.y);
        let exact = ((1.0 - w.z) * (1.0 + w.z)).sqrt();
        assert!(
            w.z == u1 && (radius / exact - 1.0).abs() <= 4.0 * f64::EPSILON,
            "u1 = {u1}: z = {}, radius {radius:e}, want {exact:e}",
            w.z
        );
    }
}

/// Exercise 2 of *Uniform sphere and hemisphere*: the first dimension `d` in which
/// rejection from the cube `[-1, 1]^d` accepts fewer than 1 % of its draws.
const YOUR_DIMENSION: Option<u32> = None;

#[test]
#[ignore = "exercise 2 of Uniform sphere and hemisphere: set YOUR_DIMENSION, then run it"]
fn exercise_2_rejection_in_d_dimensions() {
    let d = YOUR_DIMENSION.expect("set YOUR_DIMENSION");
    assert!(d >= 2, "d = {d}");
    // The acceptance rate, counted: 400 000 draws in d and in d - 1 dimensions. At a rate
    // near 1 % the count's relative standard deviation is about 1.6 %.
    let mut rng = rng::seeded(0xD1);
    let mut rate = |d: u32| {
        let draws = 400_000;
        let inside = (0..draws)
            .filter(|_| {
                (0..d)
                    .map(|_| raylemma::rng::uniform(&mut rng, -1.0, 1.0).powi(2))
                    .sum::<f64>()
                    <= 1.0
            })
            .count();
        inside as f64 / f64::from(draws)
    };
    let (here, before) = (rate(d), rate(d - 1));
    assert!(
        here < 0.01 * 0.9 && before > 0.01 * 1.1,
        "accepted: {:.3} % in {d} dimensions, {:.3} % in {}",
        100.0 * here,
        100.0 * before,
        d - 1
    );
}

/// Exercise 3 of *Uniform sphere and hemisphere*: the length of the shortest non-zero
/// vector `sphere_rejection` can draw from the cube.
const YOUR_SHORTEST_CUBE_DRAW: Option<f64> = None;

#[test]
#[ignore = "exercise 3 of Uniform sphere and hemisphere: set YOUR_SHORTEST_CUBE_DRAW, then run it"]
fn exercise_3_the_shortest_cube_draw() {
    // rand's uniform f64 is (64 random bits >> 11) 2^-53, a multiple of 2^-53 in [0, 1):
    // check it on the generator itself, then take the coordinate -1 + 2x nearest to zero
    // (but not zero) over that grid, at x = 1/2 plus one step.
    let mut rng = rng::seeded(0x5407);
    for _ in 0..100_000 {
        let x: f64 = rand::RngExt::random(&mut rng);
        assert_eq!((x * 2f64.powi(53)).fract(), 0.0, "{x} is not on the grid");
    }
    let step = 2f64.powi(-53);
    let shortest = (-1.0 + 2.0 * (0.5 + step)).abs();
    let answer = YOUR_SHORTEST_CUBE_DRAW.expect("set YOUR_SHORTEST_CUBE_DRAW");
    assert!(
        (answer / shortest - 1.0).abs() <= 1e-3,
        "your shortest draw {answer:e}; the grid's is {shortest:e}"
    );
    // So glam's plain normalize is exact on every vector the cube can give: the shortest,
    // along an axis or a diagonal, normalise as well as normalize_robust does.
    for v in [
        DVec3::new(shortest, 0.0, 0.0),
        DVec3::new(-shortest, shortest, shortest),
    ] {
        let (plain, robust) = (v.normalize(), normalize_robust(v).unwrap());
        assert!(
            max_abs((plain - robust).to_array()) <= 2.0 * f64::EPSILON,
            "{v:?}: {plain:?} against {robust:?}"
        );
    }
}
