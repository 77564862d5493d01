//! The estimator of each lamp's colour.

use super::*;

/// `n` luminance estimates of lamp `t`, `λ` drawn by `s`, weighted by `weight(λ, pdf)`.
fn y_estimates(seed: u64, n: usize, draw: impl Fn(f64) -> (f64, f64), t: &Table) -> Summary {
    Summary::of(uniforms(seed, n).into_iter().map(|u| {
        let (nm, pdf) = draw(u);
        xyz_estimate(t, nm, pdf).y
    }))
}

/// The t-test's p-value for `mean = mu`, and a message. Callers assert `p >= test_alpha()`
/// to accept and `p < test_alpha()` to reject, so a NaN p-value fails either way.
fn t_p(s: &Summary, mu: f64) -> (f64, String) {
    let p = ttest::one_sample(s, mu).unwrap().p_value;
    (p, format!("mean {} vs {mu}, p = {p:.3e}", s.mean))
}

#[test]
fn luminance_estimator_is_unbiased_for_every_lamp() {
    for (k, l) in lamps().iter().enumerate() {
        let s = sampler(&l.spectrum);
        let est = y_estimates(
            150 + k as u64,
            N,
            |u| {
                let w = s.sample(u);
                (w.nm, w.pdf)
            },
            &l.spectrum,
        );
        let (p, msg) = t_p(&est, y_of(&l.spectrum));
        assert!(p >= test_alpha(), "{}: {msg}", l.name);
    }
}

/// Planted bugs: the pdf left unnormalised (`L(λ)` instead of `L(λ)/∫L`), and the
/// spectrum counted twice (sampled from `L` *and* multiplied by `L(λ)` again).
#[test]
fn planted_weights_are_rejected() {
    let t = lamp("incandescent").spectrum;
    let s = sampler(&t);
    let y = y_of(&t);
    let unnormalised = y_estimates(160, N, |u| (s.sample(u).nm, t.eval(s.sample(u).nm)), &t);
    let (p, msg) = t_p(&unnormalised, y);
    assert!(p < test_alpha(), "unnormalised pdf not rejected: {msg}");
    let twice = Summary::of(uniforms(161, N).into_iter().map(|u| {
        let w = s.sample(u);
        t.eval(w.nm) * xyz_estimate(&t, w.nm, w.pdf).y
    }));
    let (p, msg) = t_p(&twice, y);
    assert!(
        p < test_alpha(),
        "spectrum counted twice not rejected: {msg}"
    );
}

/// The variance gain of importance sampling over uniform sampling on 380-830 nm, for the
/// luminance estimator: measured on 100 000 samples each, it matches the quadrature
/// prediction within 10 %, and is at least 2 for the peaky lamps (amber LED and both
/// sodium lamps; `figures/emission_gain.md` has the values). For the incandescent lamp
/// there is nothing to gain on Y (between 0.9 and 1.1, and by quadrature below 1: uniform
/// sampling is no worse) and a loss on Z (below 1): the lamp's spectrum is a poor proposal
/// for the blue, where it emits little. High-pressure sodium loses on Z too (below 1): it
/// has little light below 500 nm. The proposal `L (x̄ + ȳ + z̄)` gains on Y (above 2).
#[test]
fn variance_gain_over_uniform_sampling() {
    for (k, l) in lamps().iter().enumerate() {
        let s = sampler(&l.spectrum);
        let is = y_estimates(
            170 + k as u64,
            N,
            |u| {
                let w = s.sample(u);
                (w.nm, w.pdf)
            },
            &l.spectrum,
        );
        let un = y_estimates(
            180 + k as u64,
            N,
            |u| {
                let w = uniform_wavelength(u);
                (w.nm, w.pdf)
            },
            &l.spectrum,
        );
        let measured = un.variance() / is.variance();
        let predicted = predicted_variance(&l.spectrum, |_| 1.0 / 450.0).y
            / predicted_variance(&l.spectrum, |nm| s.pdf(nm)).y;
        assert!(
            (measured / predicted - 1.0).abs() <= 0.1,
            "{}: gain measured {measured}, predicted {predicted}",
            l.name
        );
        if ["amber", "low-pressure", "high-pressure"]
            .iter()
            .any(|n| l.name.starts_with(n))
        {
            assert!(measured >= 2.0, "{}: gain {measured}", l.name);
        }
    }
    let t = lamp("incandescent").spectrum;
    let s = sampler(&t);
    let uniform = predicted_variance(&t, |_| 1.0 / 450.0);
    let gain = uniform / predicted_variance(&t, |nm| s.pdf(nm));
    assert!(
        0.9 < gain.y && gain.y < 1.0 && gain.z < 1.0,
        "incandescent gains {gain}"
    );
    let hps = lamp("high-pressure").spectrum;
    let s_hps = sampler(&hps);
    let gain_hps =
        predicted_variance(&hps, |_| 1.0 / 450.0) / predicted_variance(&hps, |nm| s_hps.pdf(nm));
    assert!(gain_hps.z < 1.0, "high-pressure sodium gains {gain_hps}");
    let c = sampler(&colour_proposal(&t));
    let gain = uniform / predicted_variance(&t, |nm| c.pdf(nm));
    assert!(gain.y > 2.0, "incandescent gains with L (x + y + z) {gain}");
}

/// What the colour proposal `L (x̄ + ȳ + z̄)` gains, channel by channel, by quadrature: on Y
/// it beats `p ∝ L` for every lamp; on X it loses to `p ∝ L` for exactly the two narrowest
/// lamps (amber LED, low-pressure sodium); on Z it is still worse than uniform sampling for
/// the incandescent and high-pressure sodium lamps, whose blue is a small share of their
/// `X + Y + Z`. Only Y improves everywhere (`figures/emission_gain.md` has the values), and
/// for Y alone `L ȳ` does better still.
#[test]
fn colour_proposal_improves_only_luminance_everywhere() {
    for l in lamps() {
        let own = sampler(&l.spectrum);
        let colour = sampler(&colour_proposal(&l.spectrum));
        let uniform = predicted_variance(&l.spectrum, |_| 1.0 / 450.0);
        let g_own = uniform / predicted_variance(&l.spectrum, |nm| own.pdf(nm));
        let g_colour = uniform / predicted_variance(&l.spectrum, |nm| colour.pdf(nm));
        eprintln!("{}: gains p ∝ L {g_own}, colour {g_colour}", l.name);
        assert!(
            g_colour.y > g_own.y && g_colour.y > 1.0,
            "{}: Y {g_colour} vs {g_own}",
            l.name
        );
        let narrow = l.name.starts_with("amber") || l.name.starts_with("low-pressure");
        assert_eq!(
            g_colour.x < g_own.x,
            narrow,
            "{}: X gains {} (colour) and {} (p ∝ L)",
            l.name,
            g_colour.x,
            g_own.x
        );
        let warm = l.name.starts_with("incandescent") || l.name.starts_with("high-pressure");
        assert_eq!(g_colour.z < 1.0, warm, "{}: Z gain {}", l.name, g_colour.z);
        // For luminance alone, L ȳ (tabulated the same way) does better still.
        let nm = image_wavelengths();
        let values = nm
            .iter()
            .map(|&x| l.spectrum.eval(x) * cie::cmf(x).y)
            .collect();
        let luminance = sampler(&Table::new(nm, values).unwrap());
        let g_lum = uniform / predicted_variance(&l.spectrum, |nm| luminance.pdf(nm));
        assert!(g_lum.y > g_colour.y, "{}: Y with L ȳ {g_lum}", l.name);
    }
}

/// The channel-balanced proposal `L (x̄/X + ȳ/Y + z̄/Z)` gains over uniform sampling on every
/// channel of every lamp (by quadrature), where the colour proposal loses on Z for the warm
/// lamps; and it is positive wherever the integrand is.
#[test]
fn balanced_proposal_gains_on_every_channel() {
    for l in lamps() {
        let b = sampler(&balanced_proposal(&l.spectrum));
        let gain = predicted_variance(&l.spectrum, |_| 1.0 / 450.0)
            / predicted_variance(&l.spectrum, |nm| b.pdf(nm));
        eprintln!("{}: gains with the balanced proposal {gain}", l.name);
        assert!(gain.min_element() > 1.0, "{}: {gain}", l.name);
        for i in 0..45_000 {
            let nm = 380.0 + (f64::from(i) + 0.5) * 0.01;
            let f = l.spectrum.eval(nm) * cie::cmf(nm).element_sum();
            assert!(f == 0.0 || b.pdf(nm) > 0.0, "{} at {nm}: f = {f}", l.name);
        }
    }
}

/// The colour proposal is positive wherever a lamp's `L (x̄ + ȳ + z̄)` is (0.01 nm
/// grid): the condition for the estimator to stay unbiased with it.
#[test]
fn colour_proposal_covers_the_integrand() {
    for l in lamps() {
        let c = sampler(&colour_proposal(&l.spectrum));
        for i in 0..45_000 {
            let nm = 380.0 + (f64::from(i) + 0.5) * 0.01;
            let f = l.spectrum.eval(nm) * cie::cmf(nm).element_sum();
            assert!(f == 0.0 || c.pdf(nm) > 0.0, "{} at {nm}: f = {f}", l.name);
        }
    }
}
