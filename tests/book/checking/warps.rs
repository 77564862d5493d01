//! Tests of the warp checker itself (chapter *Checking a sampler*): it must reject every
//! planted bug, and say why. Every chi-squared test here runs at the suite's Šidák-corrected
//! level `raylemma::stats::test_alpha()`, with a fixed seed.

use glam::{DVec2, DVec3};
use raylemma::check::warp::{self, Domain, RngWarp, SquareWarp, WarpOptions, planted};
use raylemma::check::{Options, Verdict};
use raylemma::sampling::cosine::cosine_pdf;
use raylemma::sampling::disc::{disc_pdf, disc_polar, disc_polar_invert};
use raylemma::sampling::sphere::sphere_pdf;
use raylemma::sampling::sphere::{SPHERE_PDF, hemisphere_pdf};

/// 200 000 samples (21 rows by the rule) and 2 000 Jacobian points.
fn opts() -> WarpOptions {
    WarpOptions {
        points: 2_000,
        ..WarpOptions::from(Options::default().cases(200_000))
    }
}

fn square(
    name: &str,
    domain: Domain,
    sample: fn(DVec2) -> DVec3,
    pdf: fn(DVec3) -> f64,
) -> Verdict {
    warp::check(&SquareWarp::new(name, domain, sample, pdf), &opts())
}

fn chi2_message(v: &Verdict) -> String {
    v.finding("chi_squared").example.clone().unwrap_or_default()
}

#[test]
fn a_correct_sampler_passes() {
    square("polar disc", Domain::Disc, disc_polar, disc_pdf).assert_pass();
}

#[test]
fn rejects_r_equals_u_on_the_disc() {
    // The classic mistake: r = u instead of sqrt(u) crowds samples at the centre.
    let v = square("disc r=u", Domain::Disc, planted::disc_r_equals_u, disc_pdf);
    assert!(v.failed("chi_squared") && v.failed("jacobian"), "{v}");
}

#[test]
fn rejects_a_cos_1_1_lobe_claimed_as_cosine() {
    // Samples from cos^1.1 (exponent n: z = u^(1/(n+1))), claimed to follow cos/pi.
    let v = square(
        "cos^1.1 lobe",
        Domain::Sphere,
        planted::cosine_power_lobe,
        cosine_pdf,
    );
    assert!(v.failed("chi_squared") && v.failed("jacobian"), "{v}");
}

#[test]
fn rejects_a_missing_sin_theta() {
    // theta uniform in [0, pi]: forgets the sin(theta) of the solid-angle element.
    let v = square(
        "theta uniform",
        Domain::Sphere,
        planted::sphere_theta_uniform,
        sphere_pdf,
    );
    assert!(v.failed("chi_squared") && v.failed("jacobian"), "{v}");
}

#[test]
fn rejects_a_pdf_that_does_not_integrate_to_one() {
    let v = square(
        "disc pdf x2",
        Domain::Disc,
        disc_polar,
        planted::disc_pdf_doubled,
    );
    assert!(chi2_message(&v).contains("integrates"), "{v}");
}

#[test]
fn rejects_samples_outside_the_domain() {
    let v = square(
        "disc radius 1.01",
        Domain::Disc,
        planted::disc_outside,
        disc_pdf,
    );
    assert!(
        chi2_message(&v).contains("outside the disc: x^2 + y^2 = "),
        "{v}"
    );
}

#[test]
fn rejects_nan_samples() {
    let v = square("nan", Domain::Disc, planted::disc_nan, disc_pdf);
    assert!(chi2_message(&v).contains("not finite"), "{v}");
}

#[test]
fn rejects_a_negative_pdf() {
    let v = square(
        "negative pdf",
        Domain::Disc,
        disc_polar,
        planted::disc_pdf_negative,
    );
    assert!(chi2_message(&v).contains("negative"), "{v}");
}

#[test]
fn rejects_samples_where_the_pdf_is_zero() {
    // Claims the upper half disc only, samples the whole disc.
    let v = square(
        "half",
        Domain::Disc,
        disc_polar,
        planted::disc_pdf_upper_half,
    );
    assert!(
        chi2_message(&v).contains("the claimed pdf is 0 there"),
        "{v}"
    );
}

/// A few samples leaked just below the horizon, into the row of cells that straddles it:
/// the cells' integrals are positive and chi-squared misses them, so the checker must ask
/// the pdf at every sample.
#[test]
fn rejects_samples_leaked_below_the_horizon() {
    let leak = SquareWarp::new(
        "cosine leaking below the horizon",
        Domain::Sphere,
        planted::cosine_leaking_below_horizon,
        cosine_pdf,
    );
    let v = warp::check(&leak, &Options::default().cases(warp::TEST_SAMPLES));
    let message = chi2_message(&v);
    assert!(
        v.failed("chi_squared") && message.contains("the claimed pdf is 0 there"),
        "{v}"
    );
    // The Jacobian's points stay 1e-3 away from the edges of the square: it cannot see it.
    assert!(!v.failed("jacobian"), "{v}");
}

#[test]
fn writes_images_on_failure() {
    let v = square(
        "images demo",
        Domain::Disc,
        planted::disc_r_equals_u,
        disc_pdf,
    );
    let message = chi2_message(&v);
    assert!(message.contains("images in"), "{message}");
    // The folder the message names: warp-failures/ of the working directory (the crate's
    // root under cargo test), never a folder fixed when the binary was built.
    let named = message
        .rsplit("images in ")
        .next()
        .unwrap_or_default()
        .trim();
    let dir = std::path::Path::new(named);
    assert_eq!(
        dir,
        raylemma::check::pictures::failure_dir().join("images_demo"),
        "{message}"
    );
    assert!(dir.is_relative(), "{message}");
    for f in ["observed.png", "expected.png", "difference.png"] {
        assert!(dir.join(f).is_file(), "{f} missing");
        let png = crate::support::read_png(&dir.join(f));
        let (w, h) = (png.width, png.height);
        assert!(w.min(h) >= 256, "{f} is {w} x {h}: too small to read");
    }
    let legend = std::fs::read_to_string(dir.join("README.txt")).unwrap();
    assert!(
        legend.contains("r^2 from 0 (bottom") && legend.contains("red where there are more"),
        "{legend}"
    );
    // Fixed, the same sampler's images go: they would say that it still fails.
    square(
        "images demo",
        Domain::Disc,
        raylemma::sampling::disc::disc_polar,
        disc_pdf,
    )
    .assert_pass();
    assert!(!dir.exists(), "stale images left after the sampler passed");
}

/// A cosine sampler written with y up (its samples have y >= 0, z on both sides) fails on
/// its first sample below the horizon, and the message says the checker's axes and how
/// many samples are below; the same sampler with z up passes.
#[test]
fn a_sampler_with_y_up_is_told_that_z_is_up() {
    let z_up = |u: DVec2| raylemma::sampling::cosine::cosine_malley(u);
    square("cosine, z up", Domain::Sphere, z_up, cosine_pdf).assert_pass();
    let y_up = |u: DVec2| {
        let w = raylemma::sampling::cosine::cosine_malley(u);
        DVec3::new(w.x, w.z, w.y)
    };
    let v = square("cosine, y up", Domain::Sphere, y_up, cosine_pdf);
    let message = chi2_message(&v);
    assert!(
        v.failed("chi_squared")
            && message.contains("+z is up")
            && message.contains("must map its up axis to z"),
        "{message}"
    );
    // About half of the samples are below the horizon (binomial: 0.5 +- 0.002 at 5 sd).
    let (below, total): (f64, f64) = message
        .split("; ")
        .find_map(|part| {
            let (b, rest) = part.split_once(" of the ")?;
            let (t, _) = rest.split_once(' ')?;
            Some((b.rsplit(' ').next()?.parse().ok()?, t.parse().ok()?))
        })
        .unwrap_or((f64::NAN, f64::NAN));
    assert!(
        (below / total - 0.5).abs() < 0.01,
        "{below} / {total}: {message}"
    );
}

#[test]
fn round_trip_rejects_an_inverse_returning_nan() {
    // A correct inverse passes; one that loses the first coordinate to NaN must fail
    // (glam's `max_element` would drop that NaN and pass it).
    let check = |invert: fn(DVec3) -> DVec2| {
        let w = SquareWarp::new("polar disc", Domain::Disc, disc_polar, disc_pdf).inverse(invert);
        warp::round_trip(&w, &opts()).expect("an invertible warp gets a round trip")
    };
    assert!(check(disc_polar_invert).passed());
    let nan_first = check(planted::disc_polar_invert_nan);
    assert!(!nan_first.passed(), "{nan_first:?}");
    assert!(nan_first.worst.is_some_and(|(w, _)| w.is_nan()));
}

#[test]
fn rng_samplers_get_the_chi_squared_test_only() {
    let w = RngWarp {
        name: "rejection disc".into(),
        domain: Domain::Disc,
        sample: |rng: &mut raylemma::rng::Rng| loop {
            let p = DVec3::new(
                raylemma::rng::uniform(rng, -1.0, 1.0),
                raylemma::rng::uniform(rng, -1.0, 1.0),
                0.0,
            );
            if p.length_squared() <= 1.0 {
                return p;
            }
        },
        pdf: disc_pdf,
    };
    let v = warp::check(&w, &opts());
    v.assert_pass();
    assert_eq!(v.findings.len(), 1);
}

#[test]
fn interval_domain_checks_a_linear_density() {
    // x = sqrt(u1) has density 2x on [0, 1].
    let ok = square(
        "linear on [0,1]",
        Domain::Interval { lo: 0.0, hi: 1.0 },
        |u| DVec3::new(u.x.sqrt(), 0.0, 0.0),
        |p| 2.0 * p.x,
    );
    ok.assert_pass();
    // Planted bug: x = u1 (uniform) claimed as 2x.
    let bad = square(
        "uniform as linear",
        Domain::Interval { lo: 0.0, hi: 1.0 },
        planted::linear_without_sqrt,
        |p| 2.0 * p.x,
    );
    assert!(bad.failed("chi_squared") && bad.failed("jacobian"), "{bad}");
}

#[test]
fn square_domain_checks_a_product_density() {
    // (sqrt(u1), u2) has density 2x on the unit square.
    let ok = square(
        "2x on the square",
        Domain::Square,
        |u| DVec3::new(u.x.sqrt(), u.y, 0.0),
        |p| 2.0 * p.x,
    );
    ok.assert_pass();
    // Planted bug: the density claimed along the wrong axis.
    let bad = square(
        "2y claimed",
        Domain::Square,
        |u| DVec3::new(u.x.sqrt(), u.y, 0.0),
        planted::square_linear_pdf_wrong_axis,
    );
    assert!(bad.failed("chi_squared") && bad.failed("jacobian"), "{bad}");
}

/// Uniform directions in a cone of half-angle `acos(cos_max)` around a tilted axis
/// (`planted::Cone` claiming its own pdf): a pdf with a jump (the cone's rim) that cuts the
/// checker's cells obliquely, as a light's silhouette does. The expected counts of the cut
/// cells must still be exact.
#[test]
fn expected_counts_are_exact_where_a_jump_cuts_cells() {
    // 2 000 000 samples in a cone of 0.1 sr: about 40 cells meet the rim. Integrating each
    // cut cell with one fixed Gauss rule errs by a few percent of its count, which this many
    // samples detect; adaptive subdivision of the cut cells makes the test pass.
    let cone = planted::Cone {
        axis: DVec3::new(0.3, -0.5, 0.8).normalize(),
        cos_max: 0.985,
        claimed_cos_max: 0.985,
    };
    // 2 000 000 samples: 51 rows and 10 000 points by the rule.
    let options = Options::default().cases(2_000_000);
    let v = warp::check(&cone, &options);
    v.assert_pass();
    // Its planted twin: a cone 2 % wider than the pdf claims puts samples where the pdf is 0.
    let wrong = planted::Cone {
        cos_max: 0.9847,
        ..cone
    };
    assert!(warp::check(&wrong, &options).failed("chi_squared"));
}

/// The warp checker's own knobs follow from the samples: the sampler tests' 400 000 give
/// 21 rows and 5 000 points, the default's 1 000 000 give 51 rows and 10 000 points.
#[test]
fn the_grid_follows_the_samples() {
    let grid = |o: WarpOptions| (o.samples, o.resolution, o.points);
    let tests = WarpOptions::from(Options::default().cases(warp::TEST_SAMPLES));
    assert_eq!(grid(tests), (400_000, 21, 5_000));
    assert_eq!(grid(WarpOptions::default()), (1_000_000, 51, 10_000));
    assert_eq!(
        grid(WarpOptions::from(Options::default())),
        (1_000_000, 51, 10_000)
    );
    assert_eq!(
        grid(WarpOptions::from(Options::default().cases(999_999))).1,
        21
    );
    assert_eq!(
        grid(WarpOptions::from(Options::default().cases(2_000_000))).1,
        51
    );
    let o = WarpOptions::from(Options::default().seed(7).alpha(0.01));
    assert_eq!((o.seed, o.alpha), (7, 0.01));
    assert_eq!(WarpOptions::default().seed, warp::SEED);
    assert_eq!(WarpOptions::default().alpha, raylemma::stats::test_alpha());
}

/// An even number of rows on the sphere is rounded up: a row always straddles the equator.
#[test]
fn sphere_rows_are_always_odd() {
    let even = WarpOptions {
        resolution: 20,
        ..opts()
    };
    let w = SquareWarp::new(
        "cosine",
        Domain::Sphere,
        raylemma::sampling::cosine::cosine_seed_cartesian,
        cosine_pdf,
    );
    let (_, observed, _) = warp::chi_squared(&w, &even).unwrap();
    assert_eq!(observed.len(), 21 * 42);
}

// ---------------------------------------------------------------------------------------
// The answers of the derivation exercises, and the exercises' own checks.

/// Exercise 2's answer. In the cells' own coordinates, `(z, phi)` on the sphere, the pdfs of
/// the uniform sphere and hemisphere are constant and the cosine lobe is linear in `z`, so
/// the midpoint rule is exact on every whole cell; what it gets wrong is the row that
/// straddles the horizon, whose centre is on the jump: it gives the cosine lobe nothing
/// there and the uniform hemisphere twice its share or nothing, at any number of samples.
#[test]
fn midpoint_cell_integrals_fail_only_across_the_horizon() {
    use std::f64::consts::{PI, TAU};
    for rows in [21usize, 51] {
        let cols = 2 * rows;
        let dz = 2.0 / rows as f64;
        let dphi = TAU / cols as f64;
        for i in 0..rows {
            let (z0, z1) = (-1.0 + dz * i as f64, -1.0 + dz * (i + 1) as f64);
            let mid = 0.5 * (z0 + z1);
            let point = DVec3::new((1.0 - mid * mid).sqrt(), 0.0, mid);
            let up = |z: f64| z.clamp(0.0, 1.0);
            // Exact probabilities of one cell of the row, from the antiderivatives in z.
            let cosine = (up(z1).powi(2) - up(z0).powi(2)) / 2.0 / PI * dphi;
            let hemisphere = (up(z1) - up(z0)) / TAU * dphi;
            let sphere = (z1 - z0) * SPHERE_PDF * dphi;
            let midpoint = |pdf: f64| pdf * dz * dphi;
            let cases = [
                ("cosine", midpoint(cosine_pdf(point)), cosine),
                (
                    "hemisphere",
                    midpoint(hemisphere_pdf(point, DVec3::Z)),
                    hemisphere,
                ),
                ("sphere", midpoint(SPHERE_PDF), sphere),
            ];
            let straddles = z0 < 0.0 && z1 > 0.0;
            for (name, mid, exact) in cases {
                if straddles && name != "sphere" {
                    // The centre is z = 0 up to rounding: the cosine lobe is 0 there, and the
                    // hemisphere's density is its full value or 0, as the rounding falls.
                    let ratio = mid / exact;
                    assert!(
                        ratio == 0.0 || (name == "hemisphere" && (ratio - 2.0).abs() <= 1e-9),
                        "{rows} rows, {name}: the midpoint gives {ratio} times the cell's share"
                    );
                } else {
                    assert!(
                        (mid - exact).abs() <= 1e-12 * exact.max(1e-300) + 1e-300,
                        "{rows} rows, row {i}, {name}: midpoint {mid:e}, exact {exact:e}"
                    );
                }
            }
        }
    }
}

/// Exercise 3's answer: the polar disc's `r = sqrt(u1)` has an infinite derivative at
/// `u1 = 0`. Central differences with the checker's step `1e-6` are off by percents at
/// `u1 = 2e-6`, undefined below `1e-6` (they evaluate `sqrt` of a negative number), and
/// right to about `1e-7` at the checker's margin `1e-3`.
#[test]
fn the_polar_disc_is_singular_at_the_edge_of_the_square() {
    let h = 1e-6;
    let area = |u1: f64| {
        let u = DVec2::new(u1, 0.3);
        let du =
            (disc_polar(u + DVec2::new(h, 0.0)) - disc_polar(u - DVec2::new(h, 0.0))) / (2.0 * h);
        let dv =
            (disc_polar(u + DVec2::new(0.0, h)) - disc_polar(u - DVec2::new(0.0, h))) / (2.0 * h);
        (du.x * dv.y - du.y * dv.x).abs()
    };
    // The exact area element is pi everywhere.
    let error = |u1: f64| (area(u1) / std::f64::consts::PI - 1.0).abs();
    assert!(error(2e-6) > 1e-2, "{}", error(2e-6));
    assert!(area(0.5e-6).is_nan());
    assert!(error(1e-3) < 5e-7, "{}", error(1e-3));
    assert!(error(0.5) < 1e-8, "{}", error(0.5));
}

/// Exercise 1 of *Checking a sampler*: a uniform point of the triangle `x, y >= 0`,
/// `x + y <= 1` of the unit square (density 2 there), from a point `u` of the square, by a
/// one-to-one warp.
fn your_triangle(u: DVec2) -> DVec3 {
    let _ = u;
    unimplemented!("exercise 1 of Checking a sampler: a uniform point of the triangle")
}

/// The triangle's density, 2 on it and 0 elsewhere.
fn triangle_pdf(p: DVec3) -> f64 {
    if p.x + p.y <= 1.0 { 2.0 } else { 0.0 }
}

#[test]
#[ignore = "exercise 1 of Checking a sampler: fill in your_triangle, then run it"]
fn exercise_1_your_triangle_sampler_passes() {
    let options = Options::default().cases(warp::TEST_SAMPLES);
    let yours = SquareWarp::new("your triangle", Domain::Square, your_triangle, triangle_pdf);
    warp::check(&yours, &options).assert_pass();
    // Its planted twin: the point of the square itself, half of it outside the triangle.
    let twin = SquareWarp::new(
        "the square as a triangle",
        Domain::Square,
        |u: DVec2| DVec3::new(u.x, u.y, 0.0),
        triangle_pdf,
    );
    let v = warp::check(&twin, &options);
    assert!(v.failed("chi_squared") && v.failed("jacobian"), "{v}");
    // The fold u -> 1 - u of the other half is a correct sampler that is two-to-one: its
    // samples pass chi-squared, and the local Jacobian claim, which holds for one-to-one
    // warps, fails it with the product 2.
    let fold = SquareWarp::new(
        "triangle by folding",
        Domain::Square,
        |u: DVec2| {
            if u.x + u.y > 1.0 {
                DVec3::new(1.0 - u.x, 1.0 - u.y, 0.0)
            } else {
                DVec3::new(u.x, u.y, 0.0)
            }
        },
        triangle_pdf,
    );
    let v = warp::check(&fold, &options);
    assert!(!v.failed("chi_squared") && v.failed("jacobian"), "{v}");
}
