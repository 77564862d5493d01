//! Tests of the warp checker itself (chapter *Checking a sampler*): it must reject every
//! planted bug, and say why. Every chi-squared test here runs at the suite's Šidák-corrected
//! level `raylemma::stats::test_alpha()`, with a fixed seed.

use glam::{DVec2, DVec3};
use raylemma::check::warp::{self, Domain, RngWarp, SquareWarp, WarpOptions, planted};
use raylemma::check::{Options, Verdict};
use raylemma::sampling::cosine::cosine_pdf;
use raylemma::sampling::disc::{disc_pdf, disc_polar, disc_polar_invert};
use raylemma::sampling::sphere::sphere_pdf;

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
    assert!(chi2_message(&v).contains("outside the domain"), "{v}");
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
    assert!(chi2_message(&v).contains("integrates to 0"), "{v}");
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
    // The folder the message names: under CARGO_TARGET_DIR if set, else target/.
    let named = message
        .rsplit("images in ")
        .next()
        .unwrap_or_default()
        .trim();
    let dir = std::path::Path::new(named);
    assert!(dir.ends_with("warp-failures/images_demo"), "{message}");
    let expected = std::env::var_os("CARGO_TARGET_DIR").map_or_else(
        || std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("target"),
        std::path::PathBuf::from,
    );
    assert!(
        dir.starts_with(&expected),
        "{} is not under {}",
        dir.display(),
        expected.display()
    );
    for f in ["observed.png", "expected.png", "difference.png"] {
        assert!(dir.join(f).is_file(), "{f} missing");
    }
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
