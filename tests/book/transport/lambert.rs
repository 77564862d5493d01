//! Tests of the chapter *Lambertian reflectance* (`src/transport/lambert.rs`).
//! t-tests run at `raylemma::stats::test_alpha()` (Šidák across the suite), fixed seeds;
//! each planted bug is a twin of a passing test that must be rejected.

use raylemma::sampling::sphere::sphere_uniform;
use std::f64::consts::{FRAC_1_PI, PI, TAU};

use glam::{DVec2, DVec3};
use raylemma::rng;
use raylemma::sampling::cosine::{cosine_malley, cosine_pdf};
use raylemma::sampling::sphere::{hemisphere_flip, sphere_inverse_cdf};
use raylemma::stats::ks;
use raylemma::stats::test_alpha;
use raylemma::stats::ttest::{self, Summary};
use raylemma::transport::lambert::*;

const N: usize = 400_000;
const RHO: f64 = 0.7;

fn accepts(s: &Summary, mu: f64) -> bool {
    ttest::one_sample(s, mu).unwrap().p_value >= test_alpha()
}

fn mean_and_p(s: &Summary, mu: f64) -> String {
    format!(
        "mean {} vs {mu} (p = {:.3e})",
        s.mean,
        ttest::one_sample(s, mu).unwrap().p_value
    )
}

/// The albedo int f cos dw of f = rho / pi is rho, for every outgoing direction.
#[test]
fn albedo_of_rho_over_pi_is_rho_by_quadrature() {
    for rho in [0.1, 0.5, 1.0] {
        for wo in [
            DVec3::Z,
            DVec3::new(0.6, 0.0, 0.8),
            DVec3::new(0.0, 0.99, 0.141),
        ] {
            let a = albedo(|wi, wo| lambert_brdf(rho, wi, wo), wo.normalize(), 512);
            assert!((a - rho).abs() < 1e-5 * rho, "rho {rho}: albedo {a}");
        }
    }
}

/// Planted bug: f = rho (no 1/pi) has albedo pi rho, which exceeds 1 for rho > 1/pi.
#[test]
fn planted_brdf_without_one_over_pi_has_albedo_pi_rho() {
    let a = albedo(|wi, _| if wi.z > 0.0 { RHO } else { 0.0 }, DVec3::Z, 512);
    assert!((a - PI * RHO).abs() < 1e-5, "albedo {a}");
    assert!((a - RHO).abs() > 1.0);
}

/// The source notes' chain rho0 int int cos sin = (rho0/2) int int sin 2theta
/// = (rho0/4) int [-cos 2theta]_0^{pi/2} dphi = (rho0/2) int dphi = rho0 pi, line by line.
#[test]
fn seed_normalisation_steps_agree() {
    let n = 4096;
    let dt = PI / 2.0 / n as f64;
    let mid = |g: &dyn Fn(f64) -> f64| (0..n).map(|i| g((i as f64 + 0.5) * dt)).sum::<f64>() * dt;
    let line1 = TAU * mid(&|t| t.cos() * t.sin());
    let line2 = 0.5 * TAU * mid(&|t| (2.0 * t).sin());
    let line3 = 0.25 * TAU * (-(PI).cos() + 0f64.cos());
    let line4 = 0.5 * TAU;
    for (k, v) in [line1, line2, line3, line4].into_iter().enumerate() {
        assert!((v - PI).abs() < 1e-6, "line {}: {v}", k + 1);
    }
    // So the constant BRDF value rho0 conserves energy (albedo <= 1) iff rho0 <= 1/pi.
    for rho0 in [0.9 * FRAC_1_PI, FRAC_1_PI, 1.1 * FRAC_1_PI] {
        let a = albedo(|wi, _| if wi.z > 0.0 { rho0 } else { 0.0 }, DVec3::Z, 256);
        assert_eq!(
            a <= 1.0 + 1e-4,
            rho0 <= FRAC_1_PI,
            "rho0 {rho0}: albedo {a}"
        );
    }
}

/// The albedo of rho / pi is rho by Monte Carlo too (cosine-free uniform estimator of
/// int f cos dw, one-sample t-test).
#[test]
fn albedo_of_rho_over_pi_is_rho_by_monte_carlo() {
    let s = summarize(
        |u| estimate_uniform(RHO, |_| 1.0, u),
        N,
        &mut rng::seeded(11),
    );
    assert!(accepts(&s, RHO), "{}", mean_and_p(&s, RHO));
}

#[test]
fn reciprocity() {
    let mut r = rng::seeded(12);
    for _ in 0..10_000 {
        let (a, b) = (sphere_uniform(&mut r), sphere_uniform(&mut r));
        assert_eq!(lambert_brdf(RHO, a, b), lambert_brdf(RHO, b, a));
    }
}

#[test]
fn the_brdf_is_zero_unless_both_directions_are_above_the_surface() {
    // (Found by mutation testing: `&&` replaced by `||` passed every other test, since the
    // albedo quadrature and the estimators only ever ask for directions above the surface.)
    let (up, down) = (
        DVec3::new(0.3, 0.1, 0.9).normalize(),
        DVec3::new(0.2, -0.4, -0.8).normalize(),
    );
    assert_eq!(lambert_brdf(RHO, up, up), RHO / PI);
    for (wi, wo) in [(up, down), (down, up), (down, down)] {
        assert_eq!(
            lambert_brdf(RHO, wi, wo),
            0.0,
            "f({wi}, {wo}) must be 0: light cannot cross the surface"
        );
    }
    // Exactly in the tangent plane is not above it (a second mutant, `>=` for `>`).
    let tangent = DVec3::X;
    for (wi, wo) in [(tangent, up), (up, tangent)] {
        assert_eq!(
            lambert_brdf(RHO, wi, wo),
            0.0,
            "f({wi}, {wo}): a grazing direction is not above the surface"
        );
    }
}

/// The hand-derived exact answers of both environments agree with quadrature.
#[test]
fn environments_exact_answers_match_quadrature() {
    for env in [GRADIENT, SKY] {
        let q = FRAC_1_PI * hemisphere_quadrature(|w| (env.radiance)(w) * w.z, 512);
        assert!((q - env.reflected_white).abs() < 1e-5, "{}: {q}", env.name);
    }
}

/// The source notes: "an equal chance to scatter light in all directions". Light arriving from
/// one direction leaves in direction `wo` in proportion to `f_r cos(theta_o)`. Outgoing
/// directions drawn that way (uniform on the hemisphere, kept with probability
/// `f_r cos / (rho / pi)`) follow the density `cos / pi`, whose `cos theta` has the CDF
/// `mu^2`, and not the uniform `1 / (2 pi)` the sentence implies, whose `cos theta` is
/// uniform (KS test on `cos theta` for both).
#[test]
fn scattered_light_leaves_with_density_cos_over_pi_not_uniformly() {
    let mut r = rng::seeded(18);
    let wi = DVec3::new(0.6, 0.0, 0.8);
    let mut mus = Vec::new();
    while mus.len() < 100_000 {
        let u = DVec2::new(
            rng::uniform(&mut r, 0.0, 1.0),
            rng::uniform(&mut r, 0.0, 1.0),
        );
        let wo = hemisphere_flip(sphere_inverse_cdf(u), DVec3::Z);
        let keep = lambert_brdf(RHO, wi, wo) * wo.z / (RHO * FRAC_1_PI);
        if rng::uniform(&mut r, 0.0, 1.0) < keep {
            mus.push(wo.z);
        }
    }
    let cosine = ks::one_sample(&mus, |mu| mu * mu).unwrap();
    assert!(
        cosine.p_value > test_alpha(),
        "cos / pi: p = {}",
        cosine.p_value
    );
    let uniform = ks::one_sample(&mus, |mu| mu).unwrap();
    assert!(
        uniform.p_value < test_alpha(),
        "1 / (2 pi): p = {}",
        uniform.p_value
    );
}

/// The source notes take L_i out of the integral, which is only right for a constant L_i. Under
/// the sky max(z,0)^3 the reflected radiance is 2 rho / 5, while rho times any single value
/// of L_i, or rho times its hemispherical average 1/4, is not.
#[test]
fn incoming_radiance_cannot_leave_the_integral() {
    let average = hemisphere_quadrature(SKY.radiance, 512) / TAU;
    assert!((average - 0.25).abs() < 1e-5, "average {average}");
    assert!((SKY.reflected_white - average).abs() > 0.1);
}

/// Both estimators of reflected radiance are unbiased under both environments.
#[test]
fn reflected_radiance_estimators_are_unbiased() {
    for (seed, env) in [(13, GRADIENT), (14, SKY)] {
        let exact = RHO * env.reflected_white;
        let u = summarize(
            |u| estimate_uniform(RHO, env.radiance, u),
            N,
            &mut rng::seeded(seed),
        );
        assert!(
            accepts(&u, exact),
            "uniform, {}: {}",
            env.name,
            mean_and_p(&u, exact)
        );
        let c = summarize(
            |u| estimate_cosine(RHO, env.radiance, u),
            N,
            &mut rng::seeded(seed + 100),
        );
        assert!(
            accepts(&c, exact),
            "cosine, {}: {}",
            env.name,
            mean_and_p(&c, exact)
        );
    }
}

/// The source notes' simplified forms 2 rho L cos and rho L equal the general f L cos / pdf.
#[test]
fn seed_simplified_forms_match_the_general_estimator() {
    let mut r = rng::seeded(15);
    for _ in 0..10_000 {
        let u = DVec2::new(
            rng::uniform(&mut r, 0.0, 1.0),
            rng::uniform(&mut r, 0.0, 1.0),
        );
        let wi = hemisphere_flip(sphere_inverse_cdf(u), DVec3::Z);
        let general = estimate_uniform(RHO, SKY.radiance, u);
        let seed = seed_uniform(RHO, (SKY.radiance)(wi), wi.z);
        assert!((general - seed).abs() <= 1e-14, "{general} vs {seed}");
        let wi = cosine_malley(u);
        let general = estimate_cosine(RHO, SKY.radiance, u);
        let seed = seed_cosine(RHO, (SKY.radiance)(wi));
        assert!((general - seed).abs() <= 1e-14, "{general} vs {seed}");
    }
}

/// Measured variances match the formulas of `sky_variances` (sky, k = 3) within 3 %, and
/// cosine sampling has less than a third of uniform sampling's variance there.
#[test]
fn sky_variances_match_the_formula() {
    let (vu, vc) = sky_variances(RHO, 3);
    let u = summarize(
        |u| estimate_uniform(RHO, SKY.radiance, u),
        N,
        &mut rng::seeded(16),
    );
    let c = summarize(
        |u| estimate_cosine(RHO, SKY.radiance, u),
        N,
        &mut rng::seeded(17),
    );
    assert!(
        (u.variance() / vu - 1.0).abs() < 0.03,
        "uniform {} vs {vu}",
        u.variance()
    );
    assert!(
        (c.variance() / vc - 1.0).abs() < 0.03,
        "cosine {} vs {vc}",
        c.variance()
    );
    assert!(3.0 * vc < vu);
}

// Planted bugs: each estimator with one mistake, rejected by the same t-test.

fn bug_rho_not_over_pi(u: DVec2) -> f64 {
    let wi = cosine_malley(u);
    RHO * (SKY.radiance)(wi) * wi.z / cosine_pdf(wi)
}

fn bug_cosine_extra_cos(u: DVec2) -> f64 {
    let wi = cosine_malley(u);
    RHO * (SKY.radiance)(wi) * wi.z
}

fn bug_uniform_missing_2(u: DVec2) -> f64 {
    let wi = hemisphere_flip(sphere_inverse_cdf(u), DVec3::Z);
    RHO * (SKY.radiance)(wi) * wi.z
}

#[test]
fn planted_bugs_are_rejected() {
    let exact = RHO * SKY.reflected_white;
    type Estimator = fn(DVec2) -> f64;
    let bugs: [(&str, Estimator); 3] = [
        ("f = rho", bug_rho_not_over_pi),
        ("cosine with extra cos", bug_cosine_extra_cos),
        ("uniform missing 2", bug_uniform_missing_2),
    ];
    for (k, (name, bug)) in bugs.into_iter().enumerate() {
        let s = summarize(bug, N, &mut rng::seeded(20 + k as u64));
        assert!(!accepts(&s, exact), "{name}: {}", mean_and_p(&s, exact));
    }
}

/// White furnace: L = L_e / (1 - a), with cosine-weighted bounces (the walk that continues
/// with probability a) and uniform bounces (throughput 2 a cos, roulette on it).
#[test]
fn white_furnace() {
    for (seed, a) in [(30, 0.5), (31, 0.8)] {
        let exact = 1.0 / (1.0 - a);
        let c = Summary::of((0..N).scan(rng::seeded(seed), |r, _| {
            Some(furnace_walk(1.0, |u| furnace_bounce_cosine(a, u), r).0)
        }));
        assert!(
            accepts(&c, exact),
            "cosine walk, a = {a}: {}",
            mean_and_p(&c, exact)
        );
        let u = Summary::of((0..N).scan(rng::seeded(seed + 100), |r, _| {
            Some(furnace_walk(1.0, |u| furnace_bounce_uniform(a, u), r).0)
        }));
        assert!(
            accepts(&u, exact),
            "uniform walk, a = {a}: {}",
            mean_and_p(&u, exact)
        );
    }
}

/// Planted bug in the furnace: f = rho makes every bounce weigh pi a; for a = 0.2 the walk
/// converges to 1 / (1 - 0.2 pi) = 2.69 instead of 1.25.
#[test]
fn planted_furnace_with_f_equal_rho_is_rejected() {
    let a = 0.2;
    let s = Summary::of((0..N).scan(rng::seeded(32), |r, _| {
        Some(furnace_walk(1.0, |u| PI * furnace_bounce_cosine(a, u), r).0)
    }));
    assert!(!accepts(&s, 1.0 / (1.0 - a)), "{}", mean_and_p(&s, 1.25));
    let wrong = 1.0 / (1.0 - PI * a);
    assert!(accepts(&s, wrong), "{}", mean_and_p(&s, wrong));
}

/// The uniform furnace walk's tail index is the root of `(2a)^kappa = kappa + 1`: exactly 2
/// where `E[w^2] = 4a^2/3 = 1` (`a = sqrt(3)/2`), infinite where `2a cos` never exceeds 1,
/// above 2 at the table's `a = 0.8` and below it at `a = 0.95`; and the variance is finite
/// exactly where the tail index is above 2.
#[test]
fn furnace_tail_index_solves_its_equation() {
    let threshold = 3f64.sqrt() / 2.0;
    let k = furnace_tail_index(threshold);
    assert!((k - 2.0).abs() < 1e-10, "kappa at sqrt(3)/2: {k}");
    for a in [0.55, 0.6, 0.8, 0.95, 0.99] {
        let k = furnace_tail_index(a);
        let m = (2.0 * a).powf(k) / (k + 1.0);
        assert!(
            k > 1.0 && (m - 1.0).abs() < 1e-12,
            "a = {a}: kappa {k}, E[w^kappa] {m}"
        );
        // E[w^s] < 1 just below the root and > 1 just above it: the positive root.
        assert!(
            uniform_weight_moment(a, 0.99 * k) < 1.0 && uniform_weight_moment(a, 1.01 * k) > 1.0
        );
    }
    assert!(furnace_tail_index(0.8) > 2.0 && furnace_tail_index(0.95) < 2.0);
    for a in [0.2, 0.5] {
        assert!(furnace_tail_index(a).is_infinite(), "a = {a}");
    }
    for a in [0.2, 0.5, 0.6, 0.8, 0.86, 0.87, 0.95] {
        assert_eq!(
            furnace_uniform_variance(a).is_finite(),
            furnace_tail_index(a) > 2.0,
            "a = {a}"
        );
    }
}

/// The second moment `m(t) = alpha (t^2 + 1/3)` of the uniform walk solves its integral
/// equation `m(t) = t^2 (1+a)/(1-a) + (1/2at) int_1^{2at} m + m(1)/(4at)` (midpoint rule),
/// and the variance formula is `m(1) - 1/(1-a)^2`.
#[test]
fn uniform_furnace_second_moment_solves_its_integral_equation() {
    for a in [0.6, 0.7, 0.8] {
        let alpha = (1.0 + a) / (1.0 - a) / (1.0 - 4.0 * a * a / 3.0);
        let m = |t: f64| alpha * (t * t + 1.0 / 3.0);
        for t in [1.0, 1.7, 4.0] {
            let (lo, hi, n) = (1.0, 2.0 * a * t, 100_000);
            let h = (hi - lo) / f64::from(n);
            let integral = (0..n)
                .map(|i| m(lo + (f64::from(i) + 0.5) * h))
                .sum::<f64>()
                * h;
            let rhs =
                t * t * (1.0 + a) / (1.0 - a) + integral / (2.0 * a * t) + m(1.0) / (4.0 * a * t);
            assert!(
                (rhs / m(t) - 1.0).abs() < 1e-8,
                "a = {a}, t = {t}: {rhs} vs {}",
                m(t)
            );
        }
        let v = m(1.0) - 1.0 / ((1.0 - a) * (1.0 - a));
        assert!((furnace_uniform_variance(a) / v - 1.0).abs() < 1e-12);
    }
}

/// The uniform walk's variance, measured over 400 000 walks, matches
/// `furnace_uniform_variance` within 3 % where its tail index is above 4 (a = 0.6, 0.7:
/// the sample variance's own relative error is then below 0.5 %); at a = 1/2 both walks
/// have the cosine walk's variance a / (1 - a)^2 = 2.
#[test]
fn uniform_furnace_variance_matches_the_formula() {
    let walks = |seed: u64, bounce: &dyn Fn(DVec2) -> f64| {
        Summary::of((0..N).scan(rng::seeded(seed), |r, _| {
            Some(furnace_walk(1.0, bounce, r).0)
        }))
    };
    for (seed, a) in [(33, 0.6), (34, 0.7), (35, 0.5)] {
        assert!(furnace_tail_index(a) > 4.0);
        let s = walks(seed, &|u| furnace_bounce_uniform(a, u));
        let v = furnace_uniform_variance(a);
        assert!(
            (s.variance() / v - 1.0).abs() < 0.03,
            "a = {a}: {} vs {v}",
            s.variance()
        );
    }
    let c = walks(36, &|u| furnace_bounce_cosine(0.5, u));
    assert!(
        (c.variance() / 2.0 - 1.0).abs() < 0.03,
        "cosine: {}",
        c.variance()
    );
    assert!((furnace_uniform_variance(0.5) - 2.0).abs() < 1e-12);
}

/// At a = 0.95 the uniform walk is unbiased but has infinite variance (tail index below 2),
/// so its standard error and t-test mean nothing: over 40 seeds of 25 000 walks the
/// t-test at the 1 % level rejects this correct walk at least 5 times (at its nominal
/// level, 5 or more rejections of 40 has probability 5e-5), and most sample means
/// fall below 20. The cosine walk, same albedo and seeds, rejects at most 3 times.
#[test]
fn the_infinite_variance_walk_fails_its_own_t_test() {
    let a = 0.95;
    assert!(furnace_tail_index(a) < 2.0 && furnace_uniform_variance(a).is_infinite());
    let exact = 1.0 / (1.0 - a);
    // The 40 seeds are independent (each its own generator): counted in parallel, the same
    // counts (this test is one of the last of the run, where one thread would work alone).
    let run = |bounce: &(dyn Fn(DVec2) -> f64 + Sync)| {
        use rayon::prelude::*;
        (0..40u64)
            .into_par_iter()
            .map(|seed| {
                let s = Summary::of((0..25_000).scan(rng::seeded(400 + seed), |r, _| {
                    Some(furnace_walk(1.0, bounce, r).0)
                }));
                (
                    usize::from(ttest::one_sample(&s, exact).unwrap().p_value < 0.01),
                    usize::from(s.mean < exact),
                )
            })
            .reduce(|| (0, 0), |a, b| (a.0 + b.0, a.1 + b.1))
    };
    let (rejected, below) = run(&|u| furnace_bounce_uniform(a, u));
    assert!(rejected >= 5, "uniform: {rejected} of 40 rejected at 1 %");
    assert!(below >= 24, "uniform: {below} of 40 means below {exact}");
    let (rejected, _) = run(&|u| furnace_bounce_cosine(a, u));
    assert!(rejected <= 3, "cosine: {rejected} of 40 rejected at 1 %");
}

// Exercises. Each scaffold is yours to fill in; its test is ignored until you do:
// `cargo test --test book transport::lambert::exercise_ -- --ignored`.

/// Incident radiance from a direction.
type Radiance = dyn Fn(DVec3) -> f64;

/// Exercise 1 of *Lambertian reflectance*: the estimator with directions uniform on the
/// hemisphere about the unit normal `n` (not `+z`). Hint: `Frame::from_normal`.
fn your_estimate_uniform_about(
    n: DVec3,
    rho: f64,
    radiance: &dyn Fn(DVec3) -> f64,
    u: DVec2,
) -> f64 {
    let _ = (n, rho, radiance, u); // delete this line
    unimplemented!("exercise 1 of Lambertian reflectance: the uniform estimator about the normal n")
}

/// Exercise 1 of *Lambertian reflectance*: the estimator with cosine-weighted directions
/// about the unit normal `n`.
fn your_estimate_cosine_about(
    n: DVec3,
    rho: f64,
    radiance: &dyn Fn(DVec3) -> f64,
    u: DVec2,
) -> f64 {
    let _ = (n, rho, radiance, u); // delete this line
    unimplemented!(
        "exercise 1 of Lambertian reflectance: the cosine-weighted estimator about the normal n"
    )
}

/// Both of your estimators, under the chapter's two environments rotated with the normal
/// (`1 + n.w` and `max(n.w, 0)^3`), for three normals, pass the one-sample t-test against
/// the untilted exact answers (rotation changes nothing). An estimator that forgets to
/// tilt is rejected: under `1 + n.w` about `+z` it finds `rho (1 + 2 n_z / 3)`, not
/// `5 rho / 3`.
#[test]
#[ignore = "exercise 1 of Lambertian reflectance: fill in your_estimate_uniform_about and your_estimate_cosine_about, then run it"]
fn exercise_1_tilted_normal() {
    let normals = [
        DVec3::new(0.6, 0.0, 0.8),
        DVec3::new(-0.3, 0.9, 0.1).normalize(),
        DVec3::new(0.0, 0.0, -1.0),
    ];
    for (k, n) in normals.into_iter().enumerate() {
        let gradient = move |w: DVec3| 1.0 + n.dot(w);
        let sky = move |w: DVec3| n.dot(w).max(0.0).powi(3);
        let envs: [(&str, &Radiance, f64); 2] = [
            ("1 + n.w", &gradient, GRADIENT.reflected_white),
            ("max(n.w, 0)^3", &sky, SKY.reflected_white),
        ];
        for (j, (name, env, white)) in envs.into_iter().enumerate() {
            let exact = RHO * white;
            let seed = 200 + 10 * k as u64 + 2 * j as u64;
            let s = summarize(
                |u| your_estimate_uniform_about(n, RHO, env, u),
                N,
                &mut rng::seeded(seed),
            );
            assert!(
                accepts(&s, exact),
                "uniform, n = {n}, {name}: {}",
                mean_and_p(&s, exact)
            );
            let s = summarize(
                |u| your_estimate_cosine_about(n, RHO, env, u),
                N,
                &mut rng::seeded(seed + 1),
            );
            assert!(
                accepts(&s, exact),
                "cosine, n = {n}, {name}: {}",
                mean_and_p(&s, exact)
            );
        }
    }
}

/// Exercise 2 of *Lambertian reflectance*: your reflected radiance under `L = 1 + x`, for
/// the albedo `RHO` = 0.7.
const YOUR_ANSWER_2: Option<f64> = None;

/// Your answer is within 1e-4 of the quadrature of `(rho/pi) int (1 + x) cos dw`, and both
/// of the chapter's estimators pass the one-sample t-test against it.
#[test]
#[ignore = "exercise 2 of Lambertian reflectance: set YOUR_ANSWER_2, then run it"]
fn exercise_2_another_environment() {
    let env = |w: DVec3| 1.0 + w.x;
    let exact = RHO * FRAC_1_PI * hemisphere_quadrature(|w| env(w) * w.z, 512);
    let yours = YOUR_ANSWER_2.expect("exercise 2 of Lambertian reflectance: set YOUR_ANSWER_2");
    assert!(
        (yours - exact).abs() < 1e-4,
        "your {yours} vs {exact} by quadrature"
    );
    let s = summarize(|u| estimate_uniform(RHO, env, u), N, &mut rng::seeded(220));
    assert!(accepts(&s, yours), "uniform: {}", mean_and_p(&s, yours));
    let s = summarize(|u| estimate_cosine(RHO, env, u), N, &mut rng::seeded(221));
    assert!(accepts(&s, yours), "cosine: {}", mean_and_p(&s, yours));
}

/// Exercise 3 of *Lambertian reflectance*: an environment (radiance from the direction `w`
/// above the surface, finite and not negative) under which uniform directions give a lower
/// variance than cosine-weighted ones.
fn your_horizon_environment(w: DVec3) -> f64 {
    let _ = w; // delete this line
    unimplemented!("exercise 3 of Lambertian reflectance: an environment bright near the horizon")
}

/// Under your environment the uniform estimator's sample variance (400 000 samples) is
/// below the cosine-weighted one's.
#[test]
#[ignore = "exercise 3 of Lambertian reflectance: fill in your_horizon_environment, then run it"]
fn exercise_3_when_uniform_wins() {
    let mut r = rng::seeded(230);
    for _ in 0..1000 {
        let w = hemisphere_flip(sphere_uniform(&mut r), DVec3::Z);
        let l = your_horizon_environment(w);
        assert!(l.is_finite() && l >= 0.0, "L({w}) = {l}");
    }
    let u = summarize(
        |u| estimate_uniform(RHO, your_horizon_environment, u),
        N,
        &mut rng::seeded(231),
    );
    let c = summarize(
        |u| estimate_cosine(RHO, your_horizon_environment, u),
        N,
        &mut rng::seeded(232),
    );
    assert!(
        u.variance() < c.variance(),
        "uniform variance {} is not below cosine's {}",
        u.variance(),
        c.variance()
    );
}
