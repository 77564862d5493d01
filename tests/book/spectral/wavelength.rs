//! Tests of the chapter *Wavelength sampling and hero wavelengths*
//! (`src/spectral/wavelength.rs`).
//!
//! The t-tests run at `raylemma::stats::test_alpha()` (Šidák across the suite) with fixed
//! seeds. The exact values come from `cie::xyz` (Gauss-Legendre quadrature, a different
//! method from Monte Carlo), the visible pdf's constants from pbrt-v4's source. Every
//! estimator test has planted-bug twins, run on the same samples, that must be rejected.
//! Statistical tests in this file (correct code that must pass): 13.

use glam::DVec3;
use raylemma::check::Options;
use raylemma::check::warp::{self, Domain, SquareWarp, WarpOptions, planted};
use raylemma::rng;
use raylemma::spectral::spectrum::{Table, builtin, planck_normalised};
use raylemma::spectral::wavelength::*;
use raylemma::spectral::{LAMBDA_MAX, LAMBDA_MIN, cie};
use raylemma::stats::ttest::{self, Summary};
use raylemma::stats::{ks, test_alpha};

fn p_value(s: &Summary, mu: f64) -> f64 {
    ttest::one_sample(s, mu).unwrap().p_value
}

/// Asserts that `s` is consistent with `mu` (the correct estimator).
fn assert_unbiased(what: &str, s: &Summary, mu: f64) {
    let p = p_value(s, mu);
    eprintln!(
        "{what}: t = {:.2}, p = {p:.3e}",
        ttest::one_sample(s, mu).unwrap().t
    );
    assert!(
        p >= test_alpha(),
        "{what}: mean {} vs exact {mu} (relative {:+.2e}, p = {p:.3e})",
        s.mean,
        s.mean / mu - 1.0
    );
}

/// Asserts that a planted bug is rejected.
fn assert_rejected(what: &str, s: &Summary, mu: f64) {
    let p = p_value(s, mu);
    eprintln!(
        "planted bug {what}: t = {:.2}, p = {p:.3e}",
        ttest::one_sample(s, mu).unwrap().t
    );
    assert!(
        p < test_alpha(),
        "planted bug {what} was not detected: mean {} vs exact {mu} (p = {p:.3e})",
        s.mean
    );
}

/// `X + Y + Z`: the fixed linear combination each t-test uses (one test per estimator).
fn sum(v: DVec3) -> f64 {
    v.x + v.y + v.z
}

/// `n` estimates of `X + Y + Z` of spectrum `s`, one path per uniform number.
fn estimates(
    n: usize,
    seed: u64,
    lanes: impl Fn(f64) -> Wavelengths,
    s: impl Fn(f64) -> f64,
) -> Summary {
    let mut r = rng::seeded(seed);
    Summary::of((0..n).map(|_| sum(lanes(rng::uniform(&mut r, 0.0, 1.0)).xyz(&s))))
}

fn d65() -> Table {
    builtin("cie_illuminant_D65.csv")
}

fn blackbody(nm: f64) -> f64 {
    planck_normalised(nm, 5000.0)
}

/// The exact relative variances per path of a strategy's X, Y and Z (`Var / exact²` of each):
/// each strategy is a deterministic function of `u`, so the variance is an integral over `u`,
/// here by the midpoint rule on `m` points.
fn exact_relative_variances(
    lanes: &dyn Fn(f64) -> Wavelengths,
    s: &dyn Fn(f64) -> f64,
    m: u32,
) -> DVec3 {
    let exact = cie::xyz(s);
    let (mut first, mut second) = (DVec3::ZERO, DVec3::ZERO);
    for i in 0..m {
        let e = lanes((f64::from(i) + 0.5) / f64::from(m)).xyz(s);
        first += e;
        second += e * e;
    }
    let (first, second) = (first / f64::from(m), second / f64::from(m));
    let mean_err = ((first - exact) / exact).abs().max_element();
    assert!(mean_err <= 1e-4, "the grid's mean is off by {mean_err:.1e}");
    (second - first * first) / (exact * exact)
}

mod edge_cases;
mod lanes;
mod seed_band;
mod unbiased;
mod visible;

// ---------------------------------------------------------------------------------------
// Dispersion: terminating the secondary lanes.

// ANCHOR: prism
/// A toy pixel with a dispersive event: half of it shows a grey wall (albedo 0.8) lit by
/// D65, half a prism. A camera ray through a uniform point of the pixel (`coin`) hits the
/// wall with probability 1/2: no dispersion, all lanes carry on. Otherwise it passes
/// through the prism, which sends towards the D65 light only the wavelengths 480–520 nm (for
/// the others the refracted ray misses it): the refraction angle depends on λ, so only the
/// hero lane can follow it and the secondaries are terminated. `terminate` is the rule.
/// Returns the estimate of `X + Y + Z` of the pixel, `0.5 · 0.8 · D65 + 0.5 · D65 · 1[480, 520]`.
fn prism_path(mut w: Wavelengths, coin: f64, d65: &Table, terminate: fn(&mut Wavelengths)) -> f64 {
    let xyz = if coin < 0.5 {
        w.xyz(|l| 0.8 * d65.eval(l))
    } else {
        terminate(&mut w);
        w.xyz(|l| {
            if (480.0..=520.0).contains(&l) {
                d65.eval(l)
            } else {
                0.0
            }
        })
    };
    sum(xyz)
}
// ANCHOR_END: prism

fn prism_estimates(
    n: usize,
    seed: u64,
    lanes: fn(f64) -> Wavelengths,
    terminate: fn(&mut Wavelengths),
) -> Summary {
    let d = d65();
    let mut r = rng::seeded(seed);
    Summary::of((0..n).map(|_| {
        let u = rng::uniform(&mut r, 0.0, 1.0);
        prism_path(lanes(u), rng::uniform(&mut r, 0.0, 1.0), &d, terminate)
    }))
}

/// The exact pixel, by quadrature: the band's edges are whole nanometres, where
/// `cie::xyz` places its interval ends, so the step is integrated exactly.
fn prism_exact() -> f64 {
    let d = d65();
    0.5 * sum(cie::xyz(|l| 0.8 * d.eval(l)))
        + 0.5
            * sum(cie::xyz(|l| {
                if (480.0..=520.0).contains(&l) {
                    d.eval(l)
                } else {
                    0.0
                }
            }))
}

/// Termination keeps the hero unbiased: with sample-space lanes (statistical test 9) and
/// with Wilkie's balance lanes (statistical test 10). Planted bugs: terminating without
/// reweighting the hero (the prism branch is `N` times too dark), and pbrt-v4's rule
/// `pdf[0] /= N` applied to balance-heuristic lanes (right only when `pdf[0]` is the hero's
/// own density).
#[test]
fn terminating_secondaries_stays_unbiased() {
    let exact = prism_exact();
    let n = 100_000;
    let rule: fn(&mut Wavelengths) = Wavelengths::terminate_secondary;
    assert_unbiased(
        "prism, sample space",
        &prism_estimates(n, 7, hero_visible, rule),
        exact,
    );
    assert_unbiased(
        "prism, balance",
        &prism_estimates(n, 8, hero_balance, rule),
        exact,
    );
    let no_reweight: fn(&mut Wavelengths) = |w| {
        for p in &mut w.pdf[1..] {
            *p = 0.0;
        }
    };
    assert_rejected(
        "no reweighting",
        &prism_estimates(n, 7, hero_visible, no_reweight),
        exact,
    );
    let pbrt_rule: fn(&mut Wavelengths) = |w| {
        for p in &mut w.pdf[1..] {
            *p = 0.0;
        }
        w.pdf[0] /= N as f64;
    };
    // The same rule is right for sample-space lanes, where pdf[0] = p(λ0) ...
    let same = prism_estimates(n, 7, hero_visible, pbrt_rule);
    let ours = prism_estimates(n, 7, hero_visible, rule);
    assert!(same.mean == ours.mean, "{} vs {}", same.mean, ours.mean);
    // ... and wrong for balance lanes, where pdf[0] is the lanes' mean density.
    assert_rejected(
        "pbrt's rule on balance lanes",
        &prism_estimates(n, 8, hero_balance, pbrt_rule),
        exact,
    );
}

// ---------------------------------------------------------------------------------------
// A rough dispersive interface: Wilkie et al.'s weights over which lane was the hero.

/// The refraction angle into N-BK7 of light arriving at 60°, radians: `asin(sin 60° / n(λ))`.
fn refracted(nm: f64) -> f64 {
    let n = raylemma::optics::dispersion::material(raylemma::optics::dispersion::N_BK7).index(nm);
    (60f64.to_radians().sin() / n).asin()
}

/// The spread of the refraction angles over the range, `θ_t(830) − θ_t(360)` (about 0.7°).
fn dispersion_spread() -> f64 {
    refracted(LAMBDA_MAX) - refracted(LAMBDA_MIN)
}

/// The normal density of `x` with mean `m` and standard deviation `s`.
fn gauss(x: f64, m: f64, s: f64) -> f64 {
    (-0.5 * ((x - m) / s).powi(2)).exp() / (s * (2.0 * std::f64::consts::PI).sqrt())
}

/// What a rough dispersive vertex does with the secondary lanes.
#[derive(Clone, Copy, Debug, PartialEq)]
enum Secondaries {
    /// Terminate them, as at a delta event (pbrt-v4 does so at every dispersive dielectric).
    Terminate,
    /// Keep them, each lane's throughput divided by the hero's path density.
    HeroPathPdf,
    /// Keep them, with Wilkie et al.'s balance heuristic over which lane was the hero.
    Wilkie,
    /// Planted bug: each lane divided by its *own* path density, though the path was drawn
    /// with the hero's.
    OwnPathPdf,
}

// ANCHOR: rough
/// A toy rough dispersive interface. Light arriving at 60° refracts into N-BK7 at
/// `θ_t(λ)`, and the rough surface spreads it into a normal lobe of directions
/// `g(θ; θ_t(λ), σ)`. The path draws `θ = θ_t(λ_0) + σ z` from the hero's lobe, `z` standard
/// normal; the light (D65) is seen in the directions `W` refracted for 450–650 nm. So
/// `f(θ, λ) = D65(λ) g(θ; θ_t(λ), σ) 1[θ ∈ W]`, and each lane's throughput is
/// `f(θ, λ_j) / g(θ; θ_t(λ_0), σ)`. Returns the estimate of `X + Y + Z`.
fn rough_path(mut w: Wavelengths, z: f64, sigma: f64, how: Secondaries, d65: &Table) -> f64 {
    let theta = refracted(w.lambda[0]) + sigma * z;
    let seen = (refracted(450.0)..=refracted(650.0)).contains(&theta);
    // p(θ | λ_k) for every lane: the lobe the path would have been drawn from had lane k
    // been the hero.
    let path_pdf = w.lambda.map(|l| gauss(theta, refracted(l), sigma));
    match how {
        Secondaries::Terminate => w.terminate_secondary(),
        Secondaries::Wilkie => w.balance_path_pdfs(path_pdf),
        Secondaries::HeroPathPdf | Secondaries::OwnPathPdf => {}
    }
    let lobe = |l: f64| match how {
        Secondaries::OwnPathPdf => 1.0,
        _ => gauss(theta, refracted(l), sigma) / path_pdf[0],
    };
    sum(w.xyz(|l| if seen { d65.eval(l) * lobe(l) } else { 0.0 }))
}
// ANCHOR_END: rough

/// The exact pixel of the toy, by quadrature over λ of D65 times the lobe's mass in `W`.
fn rough_exact(sigma: f64, d65: &Table) -> f64 {
    use statrs::function::erf::erfc;
    let phi = |x: f64| 0.5 * erfc(-x / std::f64::consts::SQRT_2);
    let (a, b) = (refracted(450.0), refracted(650.0));
    sum(cie::xyz(|l| {
        let t = refracted(l);
        d65.eval(l) * (phi((b - t) / sigma) - phi((a - t) / sigma))
    }))
}

/// `n` estimates of the toy, the same random numbers for every choice (`u` for the lanes,
/// `z` for the direction).
fn rough_estimates(
    n: usize,
    seed: u64,
    lanes: fn(f64) -> Wavelengths,
    sigma: f64,
    how: Secondaries,
    d65: &Table,
) -> Summary {
    let mut r = rng::seeded(seed);
    Summary::of((0..n).map(|_| {
        let u = rng::uniform(&mut r, 0.0, 1.0);
        let z = raylemma::rng::standard_normal(&mut r);
        rough_path(lanes(u), z, sigma, how, d65)
    }))
}

/// Wilkie et al.'s weights keep the estimate unbiased on Wilkie's own uniform lanes
/// (statistical test 12) and on sample-space lanes (statistical test 13), with a lobe 0.3
/// times the spread of the refraction angles. Planted bugs: each lane divided by its own
/// path density, and the same weights on wavelength-space balance lanes (`hero_balance`,
/// whose techniques have the densities `p(λ_k)`, not one common density).
#[test]
fn rough_dispersion_wilkie_weights_are_unbiased() {
    let d = d65();
    let sigma = 0.3 * dispersion_spread();
    let exact = rough_exact(sigma, &d);
    let n = 200_000;
    assert_unbiased(
        "rough interface, uniform lanes, Wilkie",
        &rough_estimates(n, 13, hero_uniform, sigma, Secondaries::Wilkie, &d),
        exact,
    );
    assert_unbiased(
        "rough interface, sample-space lanes, Wilkie",
        &rough_estimates(n, 14, hero_visible, sigma, Secondaries::Wilkie, &d),
        exact,
    );
    assert_rejected(
        "own path pdf per lane",
        &rough_estimates(n, 13, hero_uniform, sigma, Secondaries::OwnPathPdf, &d),
        exact,
    );
    assert_rejected(
        "Wilkie's weights on wavelength-space balance lanes",
        &rough_estimates(n, 15, hero_balance, sigma, Secondaries::Wilkie, &d),
        exact,
    );
}

/// Where Wilkie et al.'s multiple importance sampling helps. With the lobe much narrower
/// than the spread of the refraction angles (σ = 0.01 of it) the other lanes' lobes miss the
/// path and the weights give what termination gives (variance within 2 %); with a lobe ten
/// times wider than the spread the lanes' lobes overlap, the weights tend to 1/N, and
/// Wilkie's weights and the hero's path density agree (within 2 %). In between (σ = 0.1 and
/// 0.3 of the spread) Wilkie's variance is below both: termination wastes the secondaries,
/// and the hero's density for every lane makes fireflies where a lane's lobe is far from the
/// hero's. The same random numbers for every choice; uniform lanes, as in Wilkie et al.
#[test]
fn rough_dispersion_wilkie_weights_beat_termination_and_the_hero_pdf() {
    let d = d65();
    let n = 200_000;
    // The spread of the refraction angles, about 0.7° (the chapter's figure).
    let spread = dispersion_spread().to_degrees();
    assert!((0.65..=0.75).contains(&spread), "spread {spread}°");
    for ratio in [0.01, 0.1, 0.3, 10.0] {
        let sigma = ratio * dispersion_spread();
        let exact = rough_exact(sigma, &d);
        let var =
            |how| rough_estimates(n, 16, hero_uniform, sigma, how, &d).variance() / (exact * exact);
        let (terminate, hero_pdf, wilkie) = (
            var(Secondaries::Terminate),
            var(Secondaries::HeroPathPdf),
            var(Secondaries::Wilkie),
        );
        eprintln!(
            "σ = {ratio} × spread: relative variance, terminate {terminate:.4}, \
             hero pdf {hero_pdf:.4}, Wilkie {wilkie:.4}"
        );
        if ratio < 0.05 {
            assert!(
                (wilkie / terminate - 1.0).abs() <= 0.02,
                "{wilkie} vs {terminate}"
            );
        } else if ratio > 5.0 {
            assert!(
                (wilkie / hero_pdf - 1.0).abs() <= 0.02,
                "{wilkie} vs {hero_pdf}"
            );
        } else {
            assert!(
                wilkie < 0.9 * terminate && wilkie < 0.9 * hero_pdf,
                "σ = {ratio} × spread: Wilkie {wilkie}, terminate {terminate}, hero pdf {hero_pdf}"
            );
        }
    }
    // The delta limit: at a smooth interface only the hero's lobe contains the path, and
    // Wilkie's weights give lane 0 what termination gives it, `p(λ_0) / N`.
    let mut w = hero_visible(0.3);
    let mut t = w;
    w.balance_path_pdfs([2.0, 0.0, 0.0, 0.0]);
    t.terminate_secondary();
    assert!((w.pdf[0] / t.pdf[0] - 1.0).abs() <= 1e-15, "{w:?} vs {t:?}");
    // A path density that is not positive for the hero is a broken sampler: NaN, not 0.
    let mut w = hero_uniform(0.3);
    w.balance_path_pdfs([0.0, 1.0, 1.0, 1.0]);
    assert!(w.estimate(|_| DVec3::ONE).is_nan());
}

// ---------------------------------------------------------------------------------------
// Exercises (ignored until the student fills in the scaffolds; each test fails on the stub).

/// Exercise 1 of *Wavelength sampling*: hero lanes rotated in sample space through the CDF of
/// the lamp's spectrum times ȳ (tabulate `S ȳ` at every whole nanometre of 360–830 nm and draw
/// from it with the piecewise-linear sampler of *Tabulated distributions*,
/// `raylemma::spectral::emission::EmissionSampler`); every lane weighted by its own density.
fn your_light_lanes(spectrum: &Table) -> Box<dyn Fn(f64) -> Wavelengths> {
    let _ = spectrum;
    unimplemented!("exercise 1 of Wavelength sampling: hero lanes through the CDF of S ȳ")
}

/// Checks exercise 1: sampling `S ȳ` makes the low-pressure sodium lamp almost noise-free
/// (exact relative variance per path of its XYZ below 1e-3, against about 8.7 for the
/// visible pdf), and makes the Z of the incandescent lamp worse than the visible pdf does
/// (`S ȳ` starves the blue, where z̄ lives). Exact variances, by quadrature over `u`.
#[test]
#[ignore = "exercise 1 of Wavelength sampling: fill in your_light_lanes, then run it"]
fn exercise_1_light_sampling_lanes() {
    let lps = builtin("lamp_low_pressure_sodium.csv");
    let lanes = your_light_lanes(&lps);
    let v = exact_relative_variances(&*lanes, &|nm| lps.eval(nm), 200_000);
    eprintln!("low-pressure sodium, light sampling: relative variances {v}");
    assert!(v.element_sum() / 3.0 < 1e-3, "low-pressure sodium: {v}");
    let inc = builtin("lamp_incandescent.csv");
    let lanes = your_light_lanes(&inc);
    let v = exact_relative_variances(&*lanes, &|nm| inc.eval(nm), 200_000);
    let visible = exact_relative_variances(&hero_visible, &|nm| inc.eval(nm), 200_000);
    eprintln!("incandescent: light sampling {v}, visible pdf {visible}");
    assert!(
        v.z > visible.z,
        "incandescent Z: light sampling {} vs visible {}",
        v.z,
        visible.z
    );
    assert!(
        v.y < visible.y,
        "incandescent Y: light sampling {} vs visible {}",
        v.y,
        visible.y
    );
}

/// Exercise 2 of *Wavelength sampling*: `n` values of `u` stratified over `[0, 1)`, one
/// uniform point in each of the strata `[i/n, (i + 1)/n)`, in a random order (a shuffled
/// grid), so that the pixels of an image each get one.
fn your_shuffled_grid(n: usize, r: &mut rng::Rng) -> Vec<f64> {
    let _ = (n, r);
    unimplemented!("exercise 2 of Wavelength sampling: a shuffled stratified grid of u")
}

/// Checks exercise 2 on a flat field of 64 pixels lit by D65, 4000 images per case: the
/// grid has one point per stratum; the variance of each pixel is unchanged (each pixel still
/// has one uniform `u`: within 10 %); the variance of the image's mean falls by more than 4
/// times for one uniform wavelength, and by less for uniform hero lanes, whose four lanes are
/// already stratified.
#[test]
#[ignore = "exercise 2 of Wavelength sampling: fill in your_shuffled_grid, then run it"]
fn exercise_2_stratified_hero() {
    let mut r = rng::seeded(0x57A7);
    let g = your_shuffled_grid(64, &mut r);
    let mut strata: Vec<usize> = g.iter().map(|&u| (u * 64.0) as usize).collect();
    strata.sort_unstable();
    assert_eq!(
        strata,
        (0..64).collect::<Vec<_>>(),
        "one u per stratum: {g:?}"
    );
    assert!(
        g.windows(2).any(|w| w[0] > w[1]),
        "the grid is not shuffled"
    );
    let d = d65();
    let images = 4000;
    // (variance of a pixel, variance of the image's mean) for independent or stratified u.
    let measure = |s: WavelengthStrategy, stratified: bool| {
        let mut r = rng::seeded(0xF1A7);
        let (mut pixels, mut means) = (Vec::new(), Vec::new());
        for _ in 0..images {
            let us: Vec<f64> = if stratified {
                your_shuffled_grid(64, &mut r)
            } else {
                (0..64).map(|_| rng::uniform(&mut r, 0.0, 1.0)).collect()
            };
            let image: Vec<f64> = us
                .iter()
                .map(|&u| sum(s.sample(u).xyz(|l| d.eval(l))))
                .collect();
            pixels.push(image[17]);
            means.push(image.iter().sum::<f64>() / 64.0);
        }
        (
            Summary::of(pixels).variance(),
            Summary::of(means).variance(),
        )
    };
    let mut gains = Vec::new();
    for s in [WavelengthStrategy::Uniform, WavelengthStrategy::HeroUniform] {
        let (pixel, mean) = measure(s, false);
        let (pixel_s, mean_s) = measure(s, true);
        eprintln!(
            "{}: pixel variance {pixel:.4e} -> {pixel_s:.4e}, image-mean variance {mean:.4e} -> {mean_s:.4e}",
            s.name()
        );
        assert!(
            (pixel_s / pixel - 1.0).abs() <= 0.1,
            "{}: pixel variance changed",
            s.name()
        );
        gains.push(mean / mean_s);
    }
    assert!(
        gains[0] > 4.0,
        "one uniform wavelength gains only {}",
        gains[0]
    );
    assert!(
        gains[1] < gains[0],
        "hero lanes gain {} against {}",
        gains[1],
        gains[0]
    );
}

/// The prism toy with the prism covering a fraction `q` of the pixel (the chapter's toy has
/// `q = 1/2`): the estimate of `X + Y + Z` of `(1 − q) 0.8 D65 + q D65 1[480, 520]`.
fn prism_path_covering(w: Wavelengths, coin: f64, q: f64, d65: &Table) -> f64 {
    // `prism_path` takes the wall below 0.5 and the prism above.
    let branch = if coin < q { 0.75 } else { 0.25 };
    prism_path(w, branch, d65, Wavelengths::terminate_secondary)
}

/// Exercise 3 of *Wavelength sampling*: the variance per path of the prism toy's estimate
/// when the prism covers a fraction `q` of the pixel, predicted (not measured) from the two
/// branches: `(1 − q) E[w²] + q E[p²] − ((1 − q) W + q P)²`, with `w` the wall's estimate
/// (all lanes live), `p` the prism's (the hero alone), `W`, `P` their means, and the second
/// moments by quadrature over `u` (each branch is a deterministic function of `u`).
fn your_prism_variance(q: f64, lanes: fn(f64) -> Wavelengths) -> f64 {
    let _ = (q, lanes);
    unimplemented!("exercise 3 of Wavelength sampling: the prism toy's variance as a function of q")
}

/// Checks exercise 3: the predicted variance against the measured one (400 000 paths, within
/// four standard errors of the sample variance) at q = 0.25, 0.5, 0.75, for sample-space hero
/// lanes and for one wavelength from the visible pdf; and at q = 1, where both are the
/// one-wavelength estimator, a variance ratio of 1.
#[test]
#[ignore = "exercise 3 of Wavelength sampling: fill in your_prism_variance, then run it"]
fn exercise_3_mixed_terminations() {
    let d = d65();
    let single = |u: f64| WavelengthStrategy::Visible.sample(u);
    for (name, lanes) in [
        ("hero visible", hero_visible as fn(f64) -> Wavelengths),
        ("visible, 1 λ", single),
    ] {
        for q in [0.25, 0.5, 0.75] {
            let mut r = rng::seeded(0x9215);
            let xs: Vec<f64> = (0..400_000)
                .map(|_| {
                    let u = rng::uniform(&mut r, 0.0, 1.0);
                    prism_path_covering(lanes(u), rng::uniform(&mut r, 0.0, 1.0), q, &d)
                })
                .collect();
            let n = xs.len() as f64;
            let mean = xs.iter().sum::<f64>() / n;
            let m2 = xs.iter().map(|x| (x - mean).powi(2)).sum::<f64>() / n;
            let m4 = xs.iter().map(|x| (x - mean).powi(4)).sum::<f64>() / n;
            let se = ((m4 - m2 * m2) / n).sqrt();
            let predicted = your_prism_variance(q, lanes);
            eprintln!("{name}, q = {q}: measured {m2:.5} ± {se:.5}, predicted {predicted:.5}");
            assert!(
                (predicted - m2).abs() <= 4.0 * se,
                "{name}, q = {q}: {predicted} vs {m2} ± {se}"
            );
        }
    }
    let ratio = your_prism_variance(1.0, hero_visible) / your_prism_variance(1.0, single);
    assert!(
        (ratio - 1.0).abs() <= 1e-9,
        "at q = 1 the variance ratio is {ratio}"
    );
}

// ---------------------------------------------------------------------------------------
// Accuracy against exact arithmetic (data/corpus/wavelength.txt, tools/exact).

/// The rotation `(u + j/N) mod 1` used to wrap the *rounded* sum: at `u = 1/4 − 2⁻⁵⁵`,
/// `u + 3/4` rounds to 1.0 and lane 3 went to 360 nm, while the exact lane is
/// 830 − 1.3e-14 nm (the corpus's answer, mpmath at 256 bits). The wrap is now decided
/// exactly ([`rotate01`]).
#[test]
fn hero_rotation_does_not_wrap_a_sum_that_rounds_to_one() {
    let root = crate::support::root();
    let corpus = raylemma::check::accuracy::corpus::load(&root.join("data/corpus/wavelength.txt"))
        .expect("the corpus reads");
    for question in [
        "hero_uniform 0.24999999999999997",
        "hero_uniform 0.49999999999999994",
    ] {
        let case = corpus
            .cases
            .iter()
            .find(|c| c.question == question)
            .expect("the case is in the corpus");
        let got = hero_uniform(case.args[0]).lambda;
        for (g, e) in got.iter().zip(case.exact.as_ref().expect("an answer")) {
            assert!(
                (g - e.double).abs() <= 2.0 * f64::EPSILON * e.double,
                "{question}: {got:?}, exact {}",
                e.text
            );
        }
    }
    assert_eq!(rotate01(0.25 - 2f64.powi(-55), 0.75), 1.0);
    assert_eq!(rotate01(0.75, 0.25), 0.0);
}
