//! The checkers of the exercises that had none before the student edition (chapter
//! *Coursework*; each checker's claims are its chapter's): each passes the book's function
//! and rejects its planted bugs and the seeds' mistakes on the claims they break.

use glam::DVec3;
use raylemma::check::{self, Options, Verdict};
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
        &["solid_angle"],
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
