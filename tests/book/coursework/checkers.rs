//! The checkers of the exercises that had none before the student edition (chapter
//! *Coursework*; each checker's claims are its chapter's): each passes the book's function
//! and rejects its planted bugs and the seeds' mistakes on the claims they break.

use glam::DVec3;
use raylemma::check::{self, Options, Verdict};
use raylemma::exercise::registry;
use raylemma::optics::fresnel;
use raylemma::optics::{dispersion, specular, thinfilm};
use raylemma::sampling::{importance, tabulated};
use raylemma::spectral::{display, wavelength};
use raylemma::transport::{lambert, roulette, shadow};

fn failed(v: &Verdict, claims: &[&str]) {
    for c in claims {
        assert!(v.failed(c), "{c} passed:\n{v}");
    }
}

#[test]
fn importance_estimator() {
    let o = Options::default();
    let book = |f: &dyn Fn(f64) -> f64, q: &importance::Proposal, n, r: &mut _| {
        importance::estimate(f, q, n, r)
    };
    check::importance::estimator(&book, &o).assert_pass();
    use check::importance::planted;
    failed(
        &check::importance::estimator(&planted::forgets_the_density, &o),
        &["unbiased", "zero_variance"],
    );
    failed(
        &check::importance::estimator(&planted::density_of_u, &o),
        &["unbiased"],
    );
    failed(
        &check::importance::estimator(&planted::skips_zero_density, &o),
        &["zero_density"],
    );
}

/// A biased estimator's failure comes with a picture of its convergence: the error
/// levels off where an unbiased one's keeps falling as n^(-1/2). The book's estimator,
/// which passes, draws nothing.
#[test]
fn a_biased_estimator_is_drawn_levelling_off() {
    use check::importance::planted;
    use check::pictures::with_failure_dir;
    let o = Options::default();
    let dir = crate::support::scratch("importance-picture");
    let v = with_failure_dir(dir.as_path().to_path_buf(), || {
        check::importance::estimator(&planted::forgets_the_density, &o)
    });
    let picture = v.finding("unbiased").picture.clone();
    let path = dir.as_path().join("importance_convergence.svg");
    assert_eq!(picture, Some(path.display().to_string()));
    let svg = std::fs::read_to_string(&path).unwrap();
    assert!(
        svg.starts_with("<svg")
            && svg.contains("slope -1/2")
            && svg.matches("<circle").count() == 7,
        "{svg}"
    );
    let book = |f: &dyn Fn(f64) -> f64, q: &importance::Proposal, n, r: &mut _| {
        importance::estimate(f, q, n, r)
    };
    let clean = crate::support::scratch("importance-no-picture");
    let v = with_failure_dir(clean.as_path().to_path_buf(), || {
        check::importance::estimator(&book, &o)
    });
    assert_eq!(v.finding("unbiased").picture, None);
    assert!(!clean.as_path().join("importance_convergence.svg").exists());
}

/// The log-log plot: points on slope -1/2 lie on the dashed line; the axes span whole
/// decades; points that are not finite and positive are left out.
#[test]
fn the_log_log_plot_draws_the_points_and_the_expected_slope() {
    let points: Vec<(f64, f64)> = [1e1, 1e2, 1e3, 1e4]
        .iter()
        .map(|&n: &f64| (n, 1.0 / n.sqrt()))
        .chain([(1e5, f64::NAN), (0.0, 1.0)])
        .collect();
    let svg = check::pictures::loglog_svg(&points, -0.5, ["t", "x", "y", "slope"]);
    assert_eq!(svg.matches("<circle").count(), 4, "{svg}");
    assert!(
        svg.contains(">1e1<") && svg.contains(">1e4<") && svg.contains(">1e-2<"),
        "{svg}"
    );
    // The dashed line ends at the last point's height.
    let line = svg
        .lines()
        .find(|l| l.contains("stroke-dasharray"))
        .unwrap();
    let last = svg.lines().rfind(|l| l.contains("<circle")).unwrap();
    let y2 = line
        .split("y2=\"")
        .nth(1)
        .and_then(|r| r.split('"').next())
        .unwrap();
    let cy = last
        .split("cy=\"")
        .nth(1)
        .and_then(|r| r.split('"').next())
        .unwrap();
    assert_eq!(y2, cy, "{line}\n{last}");
}

#[test]
fn tabulated_samplers() {
    let o = Options::default();
    check::tabulated::sampler(&|t: &tabulated::Piecewise1D, u| t.sample(u), &o).assert_pass();
    check::tabulated::linear_sampler(&|t: &tabulated::PiecewiseLinear1D, u| t.sample(u), &o)
        .assert_pass();
    use check::tabulated::planted;
    failed(
        &check::tabulated::sampler(&planted::equal_bins, &o),
        &["bins", "zero_bins"],
    );
    failed(
        &check::tabulated::sampler(&planted::first_bin_reaching_u, &o),
        &["zero_bins"],
    );
}

#[test]
fn specular_lobe() {
    let o = Options::default();
    check::specular::delta(
        &|r, p, w: DVec3| specular::narrow_lobe_brdf(r, p, w, true),
        &o,
    )
    .assert_pass();
    // The chapter's planted bug: the lobe without its 1 / cos.
    let v = check::specular::delta(
        &|r, p, w: DVec3| specular::narrow_lobe_brdf(r, p, w, false),
        &o,
    );
    failed(&v, &["reflected_radiance"]);
    assert!(!v.failed("below") && !v.failed("finite"), "{v}");
    // Dividing by a grazing cosine of 0: only the exactly grazing directions see it.
    let v = check::specular::delta(
        &|r, p, w: DVec3| check::specular::planted::horizon_included(r, p, w, true),
        &o,
    );
    failed(&v, &["below"]);
    assert!(
        !v.failed("reflected_radiance") && !v.failed("finite"),
        "{v}"
    );
}

#[test]
fn sellmeier() {
    let o = Options::default();
    check::dispersion::sellmeier(&|m: &dispersion::Sellmeier, nm| m.index(nm), &o).assert_pass();
    use check::dispersion::planted;
    failed(
        &check::dispersion::sellmeier(&planted::nanometres, &o),
        &["datasheet", "micrometres"],
    );
    failed(
        &check::dispersion::sellmeier(&planted::n_squared, &o),
        &["datasheet", "one_term"],
    );
    // The checker's glasses are the table's.
    for (mine, name) in [
        (check::dispersion::n_bk7(), dispersion::N_BK7),
        (check::dispersion::fused_silica(), dispersion::FUSED_SILICA),
    ] {
        assert_eq!(mine.terms, dispersion::material(name).terms, "{name}");
    }
}

#[test]
fn airy_sum() {
    let o = Options::default();
    check::thinfilm::airy(&thinfilm::airy_r, &o).assert_pass();
    use check::thinfilm::planted;
    failed(
        &check::thinfilm::airy(&planted::denominator_minus, &o),
        &["series", "energy"],
    );
    failed(
        &check::thinfilm::airy(&planted::one_way_phase, &o),
        &["series", "bare", "period"],
    );
}

#[test]
fn lambertian_brdf() {
    let o = Options::default();
    check::lambert::brdf(&lambert::lambert_brdf, &o).assert_pass();
    use check::lambert::planted;
    failed(
        &check::lambert::brdf(&planted::without_one_over_pi, &o),
        &["albedo"],
    );
    failed(
        &check::lambert::brdf(&planted::one_sided, &o),
        &["reciprocity", "below"],
    );
}

#[test]
fn russian_roulette() {
    let o = Options::default();
    check::roulette::roulette(&roulette::roulette, &o).assert_pass();
    // The seed's `u <= p` gives 0 / 0 at p = 0, u = 0.
    let v = check::roulette::roulette(&roulette::roulette_seed, &o);
    failed(&v, &["never"]);
    assert!(!v.failed("unbiased"), "{v}");
    use check::roulette::planted;
    failed(
        &check::roulette::roulette(&planted::without_division, &o),
        &["unbiased", "survivors"],
    );
    failed(
        &check::roulette::roulette(&planted::survives_above, &o),
        &["unbiased", "killed"],
    );
}

#[test]
fn area_to_solid_angle() {
    let o = Options::default();
    check::shadow::area_to_solid_angle(&shadow::area_to_solid_angle, &o).assert_pass();
    use check::warp::planted;
    failed(
        &check::shadow::area_to_solid_angle(&planted::missing_r2, &o),
        &["solid_angle", "distance_scale"],
    );
    failed(
        &check::shadow::area_to_solid_angle(&planted::missing_cos, &o),
        &["solid_angle", "cos_scale"],
    );
    failed(
        &check::shadow::area_to_solid_angle(&planted::signed_cos, &o),
        &["solid_angle", "positive"],
    );
    failed(
        &check::shadow::area_to_solid_angle(&planted::unnormalised, &o),
        &["solid_angle", "area_scale"],
    );
}

#[test]
fn hero_wavelengths() {
    let o = Options::default();
    check::wavelength::hero(&wavelength::hero_uniform, &o).assert_pass();
    use check::wavelength::planted;
    failed(
        &check::wavelength::hero(&planted::without_wrap, &o),
        &["range", "lanes_uniform"],
    );
    failed(&check::wavelength::hero(&planted::pdf_shared, &o), &["pdf"]);
    // The seed's band: lanes a few nm apart, not spread over the range.
    let band = |u| wavelength::seed_band(u, &wavelength::SEED_BAND);
    failed(&check::wavelength::hero(&band, &o), &["spacing"]);
}

#[test]
fn srgb_curves() {
    let o = Options::default();
    check::display::srgb_encode(&display::srgb_encode, &o).assert_pass();
    check::display::srgb_decode(&display::srgb_decode, &o).assert_pass();
    use check::display::planted;
    failed(
        &check::display::srgb_encode(&planted::encode_with_the_encoded_breakpoint, &o),
        &["reference", "monotone"],
    );
    failed(
        &check::display::srgb_encode(&planted::encode_without_offset, &o),
        &["reference"],
    );
    // The seed's pure power law, gamma 2.2.
    failed(
        &check::display::srgb_encode(&|x| display::gamma_encode(x, 2.2), &o),
        &["reference"],
    );
    failed(
        &check::display::srgb_decode(&|v| display::gamma_decode(v, 2.2), &o),
        &["reference"],
    );
}

/// A routine with `area_to_solid_angle`'s signature: `(pdf_area, dist, cos_light)`.
type Pdf = dyn Fn(f64, f64, f64) -> f64;

/// The card's claims on `area_to_solid_angle` name the cosine and the distance squared:
/// the answer without the cosine fails `cos_scale` (not only `solid_angle`), the one
/// without the distance `distance_scale`; correct answers written otherwise (another order
/// of operations, `powi`, an explicit `if` for the sign) pass every claim.
#[test]
fn area_to_solid_angle_is_judged_on_its_cosine_and_distance() {
    let o = Options::default();
    // The card's check of the exercise is this checker, with these claims.
    let e = registry::find("area_to_solid_angle").expect("registered");
    let book = (e.check)();
    assert!(
        book.iter()
            .all(|v| v.finding("cos_scale").cases > 0 && v.passed())
    );
    let card = |f: &dyn Fn(f64, f64, f64) -> f64| check::shadow::area_to_solid_angle(f, &o);
    let without_cos = |p: f64, d: f64, _c: f64| p * d * d;
    let v = card(&without_cos);
    assert!(v.failed("cos_scale") && !v.failed("distance_scale"), "{v}");
    let without_r2 = |p: f64, _d: f64, c: f64| p / c.abs();
    let v = card(&without_r2);
    assert!(v.failed("distance_scale") && !v.failed("cos_scale"), "{v}");
    let alternatives: [(&str, &Pdf); 3] = [
        ("p / (|c| / d^2)", &|p, d, c| {
            let s = p / (c.abs() / (d * d));
            if s.is_finite() { s } else { 0.0 }
        }),
        ("p d.powi(2) / |c|", &|p, d, c| match c {
            0.0 => 0.0,
            _ => p * d.powi(2) / c.abs(),
        }),
        ("an explicit if", &|p, d, c| {
            if c == 0.0 {
                0.0
            } else if c < 0.0 {
                d * d * p / -c
            } else {
                d * d * p / c
            }
        }),
    ];
    for (name, f) in alternatives {
        let v = card(f);
        assert!(v.passed(), "{name}:\n{v}");
    }
}

/// The card judges `schlick` by its formula as well as by the reflectance claims an
/// approximation keeps: Schlick with `(1 - cos)^4`, which keeps all five of those, fails
/// `formula` and `exponent` (which says the power it read, 4); correct Schlicks written
/// otherwise (`powi(5)`, an explicit `if` for the side, `cos_t` from `sqrt(1 - sin_t^2)`)
/// pass every claim, as the book's does.
#[test]
fn schlick_is_judged_on_its_formula_and_exponent() {
    let fourth = registry::schlick_verdict(&check::fresnel::planted::schlick_fourth_power);
    for keep in registry::SCHLICK_KEEPS {
        assert!(!fourth.failed(keep), "{keep} failed:\n{fourth}");
    }
    failed(&fourth, &["formula", "exponent"]);
    let said = fourth.to_string();
    assert!(said.contains("to the power 4.000000, not 5"), "{said}");
    registry::schlick_verdict(&fresnel::schlick).assert_pass();
    let powi = |c: f64, n1: f64, n2: f64| {
        let c = c.abs().min(1.0);
        let cos = if n1 > n2 {
            match fresnel::cos_transmitted(c, n1, n2) {
                Some(t) => t,
                None => return 1.0,
            }
        } else {
            c
        };
        let r0 = ((n1 - n2) / (n1 + n2)).powi(2);
        r0 + (1.0 - r0) * (1.0 - cos).powi(5)
    };
    let by_sine = |c: f64, n1: f64, n2: f64| {
        let c = c.abs().min(1.0);
        let r0 = fresnel::r0(n1, n2);
        if n1 <= n2 {
            let x = 1.0 - c;
            return r0 + (1.0 - r0) * x * x * x * x * x;
        }
        let sin_t = n1 / n2 * (1.0 - c * c).sqrt();
        if sin_t >= 1.0 {
            return 1.0;
        }
        let x = 1.0 - (1.0 - sin_t * sin_t).sqrt();
        (1.0 - r0) * x.powf(5.0) + r0
    };
    for (name, f) in [
        ("powi(5)", &powi as &dyn Fn(f64, f64, f64) -> f64),
        ("cos_t from sin_t", &by_sine),
    ] {
        let v = registry::schlick_verdict(f);
        assert!(v.passed(), "{name}:\n{v}");
    }
}
