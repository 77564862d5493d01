//! Which checkers judge each exercise, and what each exercise unlocks. Chapter:
//! *Coursework* (`chapters/coursework.md`).
//!
//! Every exercise marked in the source ([`super::marker`]) has one entry in [`EXERCISES`],
//! under the same name: the checkers of its chapter run on the crate's own function, the
//! one the student writes, at the settings of the chapter's tests. `needs` lists the other
//! exercises whose functions the checks call (a stub there makes this one *waiting*);
//! [`LATER`] lists the chapter tests that need exercises (the renderer uses nearly all of
//! them). The card ([`super::card`]) reads both to say what each exercise unlocks.

use glam::{DVec2, DVec3};
use num_complex::Complex64;

use crate::check::warp::{self, Domain, RngWarp, SquareWarp};
use crate::check::{self, Options, Verdict};
use crate::geometry::sphere as sphere64;
use crate::optics::fresnel::Polarized;
use crate::optics::reflect::Refraction;
use crate::optics::{dispersion, fresnel, reflect, specular, thinfilm};
use crate::sampling::{cosine, disc, importance, sphere, tabulated};
use crate::single;
use crate::spectral::{display, wavelength};
use crate::transport::{lambert, roulette, shadow};

/// One exercise's checks.
#[derive(Clone, Copy)]
pub struct Exercise {
    /// The name of its marker.
    pub name: &'static str,
    /// The exercises whose functions its checks call.
    pub needs: &'static [&'static str],
    /// Runs its checkers on the crate's function; every verdict must pass.
    pub check: fn() -> Vec<Verdict>,
}

/// A later check that needs exercises: what to run, and which exercises it needs.
#[derive(Clone, Copy)]
pub struct Later {
    /// A short name for the card (`renderer`).
    pub name: &'static str,
    /// The command that runs it.
    pub command: &'static str,
    /// The exercises its code calls.
    pub needs: &'static [&'static str],
}

/// The exercises the renderer calls (`raylemma render`, the renderer's tests).
const RENDERER: &[&str] = &[
    "intersect_stable",
    "disc_concentric",
    "cosine_malley",
    "reflect",
    "refract",
    "amplitudes",
    "roulette",
    "area_to_solid_angle",
    "Sellmeier::index",
    "Piecewise1D::sample",
    "hero_uniform",
    "srgb_encode",
];

/// The command line's tests: the renderer's exercises, and the hemisphere's.
const COMMAND_LINE: [&str; 13] = joined(RENDERER, &["hemisphere_flip"]);

/// `a` then `b`, as one array of `N` names (`N` must be their total: checked at compile
/// time).
const fn joined<const N: usize>(a: &[&'static str], b: &[&'static str]) -> [&'static str; N] {
    assert!(a.len() + b.len() == N, "N must be the two lists' total");
    let mut out = [""; N];
    let mut i = 0;
    while i < a.len() {
        out[i] = a[i];
        i += 1;
    }
    let mut j = 0;
    while j < b.len() {
        out[i + j] = b[j];
        j += 1;
    }
    out
}

/// The chapters' tests that call exercises of other chapters.
pub const LATER: &[Later] = &[
    Later {
        name: "renderer",
        command: "cargo test --test book renderer",
        needs: RENDERER,
    },
    Later {
        name: "specular furnace",
        command: "cargo test --test book optics::specular",
        needs: &["intersect_stable", "reflect", "refract", "amplitudes"],
    },
    Later {
        name: "white furnace",
        command: "cargo test --test book transport::lambert",
        needs: &["lambert_brdf", "cosine_malley", "hemisphere_flip"],
    },
    // The other chapters' tests that call an exercise of another chapter, as the hand-out's
    // run shows them (`.ci/editions` fails if a test there reaches a stub not listed).
    Later {
        name: "cosine chapter",
        command: "cargo test --test book sampling::cosine",
        needs: &["disc_concentric", "hemisphere_flip"],
    },
    Later {
        name: "roulette chapter",
        command: "cargo test --test book transport::roulette",
        needs: &["hemisphere_flip"],
    },
    Later {
        name: "shadow chapter",
        command: "cargo test --test book transport::shadow",
        needs: &["intersect_stable"],
    },
    Later {
        name: "rectangle chapter",
        command: "cargo test --test book transport::rectangle",
        needs: &["area_to_solid_angle"],
    },
    Later {
        name: "wavelength chapter",
        command: "cargo test --test book spectral::wavelength",
        needs: &["Sellmeier::index"],
    },
    Later {
        name: "emission chapter",
        command: "cargo test --test book spectral::emission",
        needs: &["Piecewise1D::sample", "PiecewiseLinear1D::sample"],
    },
    Later {
        name: "sampler checks",
        command: "cargo test --test book checking::warps",
        needs: &["disc_polar", "cosine_malley", "cosine_pdf"],
    },
    Later {
        name: "accuracy tables",
        command: "cargo test --test book checking::accuracy",
        needs: &["intersect_stable", "amplitudes"],
    },
    Later {
        name: "checks from any language",
        command: "cargo test --test book checking::external",
        needs: &["cosine_pdf", "refract", "amplitudes"],
    },
    // The command line's tests run `raylemma render` (the conformance card renders the
    // ladder), so they need the renderer's exercises too.
    Later {
        name: "command line",
        command: "cargo test --test book cli",
        needs: &COMMAND_LINE,
    },
    Later {
        name: "coursework chapter",
        command: "cargo test --test book coursework",
        needs: &[
            "intersect_stable",
            "estimate",
            "disc_polar",
            "Piecewise1D::sample",
            "reflect",
            "amplitudes",
            "schlick",
            "narrow_lobe_brdf",
            "Sellmeier::index",
            "airy_r",
            "lambert_brdf",
            "roulette",
            "area_to_solid_angle",
            "hero_uniform",
            "srgb_encode",
        ],
    },
];

/// The claim on rejection's cost: the mean number of draws per direction that the sampler
/// `f` reports is the cube's volume over the ball's, `6 / pi` (one-sample t-test at the
/// suite's level).
fn acceptance(f: fn(&mut crate::rng::Rng) -> (DVec3, u32)) -> Verdict {
    let mut rng = crate::rng::seeded(warp::SEED);
    let tries = crate::stats::ttest::Summary::of((0..200_000).map(|_| f64::from(f(&mut rng).1)));
    let want = 6.0 / std::f64::consts::PI;
    let p = crate::stats::ttest::one_sample(&tries, want).map_or(0.0, |t| t.p_value);
    let mut finding = check::Finding::new("draws", "the mean number of draws is 6 / pi");
    finding.record(p >= crate::stats::test_alpha(), || {
        format!(
            "{} draws per direction on average over {} directions (p = {p:.3e})",
            tries.mean, tries.n
        )
    });
    let mut verdict = Verdict::new("sphere by rejection: its cost");
    verdict.findings.push(finding);
    verdict
}

/// The sampler tests' options: 400 000 samples, the warp checker's seed.
fn warp_options() -> Options {
    Options::default().cases(warp::TEST_SAMPLES)
}

/// The claims of the reflectance checker that an approximation such as Schlick's must
/// keep (it cannot keep `energy` or `matched`: it approximates).
pub const SCHLICK_KEEPS: [&str; 5] = ["range", "normal", "grazing", "tir", "reciprocity"];

/// The card's judgement of a Schlick routine `f` (the chapter *Fresnel and Schlick*): the
/// claims of the reflectance checker an approximation keeps ([`SCHLICK_KEEPS`]), which
/// hold for any power of `1 - cos`, and [`check::fresnel::schlick`]'s `formula` and
/// `exponent`, which hold only for Schlick's fifth power: one verdict.
pub fn schlick_verdict(f: &dyn Fn(f64, f64, f64) -> f64) -> Verdict {
    let o = Options::default();
    let mut v = only(
        check::fresnel::reflectance(f, &o),
        &SCHLICK_KEEPS,
        "the claims an approximation keeps, and its formula",
    );
    v.findings.extend(check::fresnel::schlick(f, &o).findings);
    v
}

/// `verdict` with only the findings named `keep`, its subject saying so.
pub fn only(mut verdict: Verdict, keep: &[&str], why: &str) -> Verdict {
    verdict.findings.retain(|f| keep.contains(&f.name.as_str()));
    verdict.subject = format!("{} ({why})", verdict.subject);
    verdict
}

/// The checks of `intersect_stable`, run on the `f64` intersector `f` (the crate's, or a
/// twin of [`super::mistakes`]). The `f32` routine they also judge
/// (`single::geometry::sphere::intersect_stable`) is always the crate's: a twin replaces
/// only the `f64` one.
pub fn intersect_stable_checks(
    f: fn(&crate::geometry::Ray, &crate::geometry::Sphere, f64) -> Option<f64>,
) -> Vec<Verdict> {
    let o = Options::default();
    vec![
        check::sphere::intersection(&f, &o),
        check::sphere::intersection(&single::geometry::sphere::intersect_stable, &o),
        check::sphere::far(&single::geometry::sphere::intersect_stable, &o),
    ]
}

/// An importance-sampling estimator with the signature of `estimate`, its integrand taken
/// as a trait object.
pub type EstimateFn = fn(
    &dyn Fn(f64) -> f64,
    &importance::Proposal,
    usize,
    &mut crate::rng::Rng,
) -> crate::stats::ttest::Summary;

/// The checks of `estimate`, run on the estimator `f` (the crate's, or a twin of
/// [`super::mistakes`]).
pub fn estimate_checks(f: EstimateFn) -> Vec<Verdict> {
    vec![check::importance::estimator(&f, &Options::default())]
}

/// The checks of `sphere_rejection`, run on the sampler `f` (the crate's, or a twin of
/// [`super::mistakes`]): its directions, and the number of draws it reports.
pub fn sphere_rejection_checks(f: fn(&mut crate::rng::Rng) -> (DVec3, u32)) -> Vec<Verdict> {
    let w = RngWarp {
        name: "sphere by rejection".to_string(),
        domain: Domain::Sphere,
        sample: move |rng: &mut _| f(rng).0,
        pdf: sphere::sphere_pdf,
    };
    vec![warp::check(&w, &warp_options()), acceptance(f)]
}

/// The checks of `hemisphere_flip`, run on the flip `f` (the crate's, or a twin of
/// [`super::mistakes`]): Gaussian sphere samples flipped around `+z` and a tilted normal.
pub fn hemisphere_flip_checks(f: fn(DVec3, DVec3) -> DVec3) -> Vec<Verdict> {
    let tilted = DVec3::new(0.3, -0.5, 0.8).normalize();
    [DVec3::Z, tilted]
        .into_iter()
        .map(|n| {
            let w = RngWarp {
                name: format!("hemisphere around {n:.3}"),
                domain: Domain::Sphere,
                sample: move |rng: &mut _| f(sphere::sphere_gaussian(rng), n),
                pdf: move |w| sphere::hemisphere_pdf(w, n),
            };
            warp::check(&w, &warp_options())
        })
        .collect()
}

/// The checks of `disc_concentric`, run on the map `f` (the crate's, or a twin of
/// [`super::mistakes`]), with the crate's inverse for the round trip, and the square's
/// special points (`square_special_points`).
pub fn disc_concentric_checks(f: fn(DVec2) -> DVec3) -> Vec<Verdict> {
    let w = SquareWarp::new("disc concentric", Domain::Disc, f, disc::disc_pdf)
        .inverse(disc::disc_concentric_invert);
    vec![
        warp::check(&w, &warp_options()),
        square_special_points("disc concentric", f),
    ]
}

/// The points of the unit square that random draws never hit but a map of it to the disc
/// must take in: its centre, the midpoints of its sides and its corners (`1 - eps/2` for
/// 1), each mapped to a finite point of the closed unit disc. The two-wedge concentric map
/// divides 0 by 0 at the centre without its guard.
fn square_special_points(name: &str, f: fn(DVec2) -> DVec3) -> Verdict {
    let mut finding = check::Finding::new(
        "special_points",
        "the centre, the sides' midpoints and the corners map to finite points of the disc",
    );
    let coordinates = [0.0, 0.5, 1.0 - f64::EPSILON / 2.0];
    for x in coordinates {
        for y in coordinates {
            let u = DVec2::new(x, y);
            let p = f(u);
            let inside = p.is_finite() && p.z == 0.0 && p.x.hypot(p.y) <= 1.0 + 1e-12;
            finding.record(inside, || format!("u = {u}: f(u) = {p}"));
        }
    }
    let mut verdict = Verdict::new(format!("{name}: the square's special points"));
    verdict.findings.push(finding);
    verdict
}

/// The checks of `cosine_malley`, run on the sampler `f` (the crate's, or a twin of
/// [`super::mistakes`]) with the crate's cosine density.
pub fn cosine_malley_checks(f: fn(DVec2) -> DVec3) -> Vec<Verdict> {
    let w = SquareWarp::new("cosine Malley", Domain::Sphere, f, cosine::cosine_pdf);
    vec![warp::check(&w, &warp_options())]
}

/// The checks of `cosine_pdf`, run on the density `f` (the crate's, or a twin of
/// [`super::mistakes`]) as the claimed density of the seed's Cartesian sampler.
pub fn cosine_pdf_checks(f: fn(DVec3) -> f64) -> Vec<Verdict> {
    let w = SquareWarp::new(
        "cosine pdf (the seed's Cartesian sampler)",
        Domain::Sphere,
        cosine::cosine_seed_cartesian,
        f,
    );
    vec![warp::check(&w, &warp_options())]
}

/// The checks of `Piecewise1D::sample`, run on the sampler `f` (the crate's, or a twin of
/// [`super::mistakes`]).
pub fn piecewise1d_sample_checks(
    f: fn(&tabulated::Piecewise1D, f64) -> tabulated::Sample,
) -> Vec<Verdict> {
    vec![check::tabulated::sampler(&f, &Options::default())]
}

/// The checks of `PiecewiseLinear1D::sample`, run on the sampler `f` (the crate's, or a
/// twin of [`super::mistakes`]).
pub fn piecewise_linear1d_sample_checks(
    f: fn(&tabulated::PiecewiseLinear1D, f64) -> tabulated::Sample,
) -> Vec<Verdict> {
    vec![check::tabulated::linear_sampler(&f, &Options::default())]
}

/// The checks of `disc_polar`, run on the map `f` (the crate's, or a twin of
/// [`super::mistakes`]).
pub fn disc_polar_checks(f: fn(DVec2) -> DVec3) -> Vec<Verdict> {
    let w = SquareWarp::new("disc polar", Domain::Disc, f, disc::disc_pdf)
        .inverse(disc::disc_polar_invert);
    vec![warp::check(&w, &warp_options())]
}

/// Every exercise, by name (the card orders them as the markers are, in the book's order).
pub const EXERCISES: &[Exercise] = &[
    Exercise {
        name: "intersect_stable",
        needs: &[],
        check: || intersect_stable_checks(sphere64::intersect_stable),
    },
    Exercise {
        name: "estimate",
        needs: &[],
        check: || estimate_checks(|f, q, n, rng| importance::estimate(f, q, n, rng)),
    },
    Exercise {
        name: "sphere_rejection",
        needs: &[],
        check: || sphere_rejection_checks(sphere::sphere_rejection),
    },
    Exercise {
        name: "hemisphere_flip",
        needs: &[],
        check: || hemisphere_flip_checks(sphere::hemisphere_flip),
    },
    Exercise {
        name: "disc_polar",
        needs: &[],
        check: || disc_polar_checks(disc::disc_polar),
    },
    Exercise {
        name: "disc_concentric",
        needs: &[],
        check: || disc_concentric_checks(disc::disc_concentric),
    },
    Exercise {
        name: "cosine_malley",
        needs: &["disc_concentric", "cosine_pdf"],
        check: || cosine_malley_checks(cosine::cosine_malley),
    },
    Exercise {
        name: "cosine_pdf",
        needs: &[],
        check: || cosine_pdf_checks(cosine::cosine_pdf),
    },
    Exercise {
        name: "Piecewise1D::sample",
        needs: &[],
        check: || piecewise1d_sample_checks(tabulated::Piecewise1D::sample),
    },
    Exercise {
        name: "PiecewiseLinear1D::sample",
        needs: &[],
        check: || piecewise_linear1d_sample_checks(tabulated::PiecewiseLinear1D::sample),
    },
    Exercise {
        name: "reflect",
        needs: &[],
        check: || reflect_checks(reflect::reflect),
    },
    Exercise {
        name: "refract",
        needs: &[],
        check: || refract_checks(reflect::refract),
    },
    Exercise {
        name: "amplitudes",
        needs: &[],
        check: || amplitudes_checks(fresnel::fresnel_dielectric),
    },
    Exercise {
        name: "fresnel_transmittance",
        needs: &[],
        check: || fresnel_transmittance_checks(fresnel::fresnel_transmittance),
    },
    Exercise {
        name: "schlick",
        needs: &[],
        check: || vec![schlick_verdict(&fresnel::schlick)],
    },
    Exercise {
        name: "narrow_lobe_brdf",
        needs: &[],
        check: || narrow_lobe_brdf_checks(specular::narrow_lobe_brdf),
    },
    Exercise {
        name: "Sellmeier::index",
        needs: &[],
        check: || sellmeier_index_checks(dispersion::Sellmeier::index),
    },
    Exercise {
        name: "airy_r",
        needs: &[],
        check: || airy_r_checks(thinfilm::airy_r),
    },
    Exercise {
        name: "lambert_brdf",
        needs: &[],
        check: || lambert_brdf_checks(lambert::lambert_brdf),
    },
    Exercise {
        name: "roulette",
        needs: &[],
        check: || roulette_checks(roulette::roulette),
    },
    Exercise {
        name: "area_to_solid_angle",
        needs: &[],
        check: || area_to_solid_angle_checks(shadow::area_to_solid_angle),
    },
    Exercise {
        name: "hero_uniform",
        needs: &[],
        check: || hero_uniform_checks(wavelength::hero_uniform),
    },
    Exercise {
        name: "srgb_encode",
        needs: &[],
        check: || srgb_encode_checks(display::srgb_encode),
    },
    Exercise {
        name: "srgb_decode",
        needs: &[],
        check: || srgb_decode_checks(display::srgb_decode),
    },
];

/// The entry of the exercise `name`.
pub fn find(name: &str) -> Option<&'static Exercise> {
    EXERCISES.iter().find(|e| e.name == name)
}

/// The checks of `reflect`, run on the reflection `f` (the crate's, or a twin of
/// [`super::mistakes`]).
pub fn reflect_checks(f: fn(DVec3, DVec3) -> DVec3) -> Vec<Verdict> {
    vec![check::reflect::reflection(&f, &Options::default())]
}

/// The checks of `refract`, run on the refraction `f` (the crate's, or a twin of
/// [`super::mistakes`]).
pub fn refract_checks(f: fn(DVec3, DVec3, f64, f64) -> Refraction) -> Vec<Verdict> {
    vec![check::reflect::refraction(&f, &Options::default())]
}

/// The checks of `amplitudes`, run on the reflectance `r` built from them as
/// [`fresnel::fresnel_dielectric`] builds it, `R = (r_s^2 + r_p^2) / 2` and `1` for
/// `None` (the crate's `fresnel_dielectric` itself, or [`super::mistakes`]' reflectance of
/// a twin). The card judges `amplitudes` through the edition's own `fresnel_dielectric`,
/// not through [`check::fresnel::amplitudes`] on the function itself: the grader's escape
/// case (chapter *Coursework*) needs it so, and the chapter *Fresnel and Schlick* says so.
/// So a mistake that keeps every `r^2` (the other sign of `r_p`, wrong transmission
/// amplitudes) passes here; the chapter's tests catch it.
pub fn amplitudes_checks(r: fn(f64, f64, f64) -> f64) -> Vec<Verdict> {
    vec![check::fresnel::reflectance(&r, &Options::default())]
}

/// The checks of `fresnel_transmittance`, run on the transmittance `f` (the crate's, or a
/// twin of [`super::mistakes`]): judged as a reflectance, `R = 1 - T`; the energy claim
/// compares `T` with the checker's own transmittance, and the others hold `R` to its exact
/// values.
pub fn fresnel_transmittance_checks(f: fn(f64, f64, f64) -> Polarized) -> Vec<Verdict> {
    let r = |c, n1, n2| 1.0 - f(c, n1, n2).unpolarized();
    let mut v = check::fresnel::reflectance(&r, &Options::default());
    v.subject = "transmittance, as R = 1 - T".to_string();
    vec![v]
}

/// The checks of `narrow_lobe_brdf`, run on the BRDF `f` with its `divide_by_cos` set (the
/// crate's, or a twin of [`super::mistakes`]).
pub fn narrow_lobe_brdf_checks(f: fn(f64, f64, DVec3, bool) -> f64) -> Vec<Verdict> {
    let g = |rho, pdf, w_i: DVec3| f(rho, pdf, w_i, true);
    vec![check::specular::delta(&g, &Options::default())]
}

/// The checks of `Sellmeier::index`, run on the index `f` (the crate's, or a twin of
/// [`super::mistakes`]).
pub fn sellmeier_index_checks(f: fn(&dispersion::Sellmeier, f64) -> f64) -> Vec<Verdict> {
    vec![check::dispersion::sellmeier(&f, &Options::default())]
}

/// The checks of `airy_r`, run on the Airy sum `f` (the crate's, or a twin of
/// [`super::mistakes`]).
pub fn airy_r_checks(f: fn(Complex64, Complex64, Complex64) -> Complex64) -> Vec<Verdict> {
    vec![check::thinfilm::airy(&f, &Options::default())]
}

/// What finishing `name` unlocks: the exercises that need it, then the later checks.
pub fn unlocks(name: &str) -> Vec<&'static str> {
    let exercises = EXERCISES
        .iter()
        .filter(|e| e.needs.contains(&name))
        .map(|e| e.name);
    let later = LATER
        .iter()
        .filter(|l| l.needs.contains(&name))
        .map(|l| l.name);
    exercises.chain(later).collect()
}

/// The checks of `lambert_brdf`, run on the BRDF `f` (the crate's, or a twin of
/// [`super::mistakes`]).
pub fn lambert_brdf_checks(f: fn(f64, DVec3, DVec3) -> f64) -> Vec<Verdict> {
    vec![check::lambert::brdf(&f, &Options::default())]
}

/// The checks of `roulette`, run on the rule `f` (the crate's, or a twin of
/// [`super::mistakes`]).
pub fn roulette_checks(f: fn(f64, f64, f64) -> f64) -> Vec<Verdict> {
    vec![check::roulette::roulette(&f, &Options::default())]
}

/// The checks of `area_to_solid_angle`, run on the conversion `f` (the crate's, or a twin
/// of [`super::mistakes`]).
pub fn area_to_solid_angle_checks(f: fn(f64, f64, f64) -> f64) -> Vec<Verdict> {
    vec![check::shadow::area_to_solid_angle(&f, &Options::default())]
}

/// The checks of `hero_uniform`, run on the sampler `f` (the crate's, or a twin of
/// [`super::mistakes`]).
pub fn hero_uniform_checks(f: fn(f64) -> wavelength::Wavelengths) -> Vec<Verdict> {
    vec![check::wavelength::hero(&f, &Options::default())]
}

/// The checks of `srgb_encode`, run on the encoding `f` (the crate's, or a twin of
/// [`super::mistakes`]).
pub fn srgb_encode_checks(f: fn(f64) -> f64) -> Vec<Verdict> {
    vec![check::display::srgb_encode(&f, &Options::default())]
}

/// The checks of `srgb_decode`, run on the decoding `f` (the crate's, or a twin of
/// [`super::mistakes`]).
pub fn srgb_decode_checks(f: fn(f64) -> f64) -> Vec<Verdict> {
    vec![check::display::srgb_decode(&f, &Options::default())]
}
