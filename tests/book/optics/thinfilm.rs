//! Tests of the chapter *Thin-film interference* (`chapters/optics/thinfilm.md`).
//!
//! The reference is a transfer-matrix computation written here, independently of the
//! library: Macleod's characteristic matrix of a film (*Thin-Film Optical Filters*, ch. 2)
//! with tilted admittances, in Macleod's own conventions (time dependence `exp(+iωt)`,
//! evanescent cosines `−i·sqrt(sin²θ − 1)`, `r_p` with the opposite sign to Born & Wolf's).
//! The library uses the Airy sum in Born & Wolf's conventions; only the measurable powers
//! R and T must agree. Planted bugs (and the seed's formula) must be rejected.
//! Everything is deterministic (fixed seeds); no statistics are involved.

use std::f64::consts::{FRAC_PI_2, PI};

use num_complex::Complex64;
use raylemma::optics::thinfilm::{
    Film, airy_r, cos_theta, incoherent_reflectance, interface, phase, quarter_wave_reflectance,
    seed_reflectance,
};
use raylemma::rng;

// ---------------------------------------------------------------------------------------
// The independent reference: Macleod's characteristic matrix.

/// `cos θ` in a medium of index `n` for light arriving from index `n1` at `cos θ1`, in
/// Macleod's convention: real, or `−i·sqrt(sin²θ − 1)` (fourth quadrant). From
/// `cos²θ = 1 − ρ² sin²θ1 = (1 − ρ²) + ρ² cos²θ1`, `ρ = n1/n`, so that a medium of the
/// ambient's index gets the ambient's cosine even at grazing incidence.
fn macleod_cos(n1: f64, cos1: f64, n: f64) -> Complex64 {
    let rho2 = (n1 / n).powi(2);
    let c2 = (1.0 - rho2) + rho2 * cos1 * cos1;
    if c2 >= 0.0 {
        Complex64::new(c2.sqrt(), 0.0)
    } else {
        Complex64::new(0.0, -(-c2).sqrt())
    }
}

/// `(cos δ, sin δ / δ)` times `e^{−|Im δ|}`, and `|Im δ|`: the matrix of a thick
/// evanescent layer overflows otherwise. `sin δ / δ` is taken by its series near 0, so
/// that a film exactly at its critical angle (`δ = 0`) needs no special case.
fn scaled_cos_sinc(delta: Complex64) -> (Complex64, Complex64, f64) {
    let y = delta.im.abs();
    let e = (-2.0 * y).exp();
    let (sx, cx) = delta.re.sin_cos();
    let (cosh, sinh) = (0.5 * (1.0 + e), 0.5 * (1.0 - e) * delta.im.signum());
    let cos = Complex64::new(cx * cosh, -sx * sinh);
    let sin = Complex64::new(sx * cosh, cx * sinh);
    let sinc = if delta.norm() < 1e-6 {
        (1.0 - delta * delta / 6.0) * (-y).exp()
    } else {
        sin / delta
    };
    (cos, sinc, y)
}

/// `(R_s, R_p, T_s, T_p)` by the transfer matrix.
fn tmm(film: &Film, wavelength_nm: f64, theta1: f64) -> [f64; 4] {
    tmm_cos(film, wavelength_nm, theta1.cos())
}

fn tmm_cos(film: &Film, wavelength_nm: f64, cos1: f64) -> [f64; 4] {
    let (n1, n2, n3, d) = (film.n1, film.n2, film.n3, film.thickness_nm);
    let c1 = Complex64::new(cos1, 0.0);
    let c2 = macleod_cos(n1, cos1, n2);
    let c3 = macleod_cos(n1, cos1, n3);
    let k = 2.0 * PI / wavelength_nm;
    let delta = c2 * (k * n2 * d);
    let (cos, sinc, y) = scaled_cos_sinc(delta);
    let i = Complex64::i();
    let mut out = [0.0; 4];
    // s: tilted admittances (in units of the free-space admittance) η = n cos θ; the
    // film's matrix entries i sin δ / η2 and i η2 sin δ are written with sin δ = δ·sinc δ,
    // so that no cosine is divided by. [B, C] = M [1, η3], scaled by e^{−|Im δ|}.
    {
        let (eta1, eta3) = (c1 * n1, c3 * n3);
        let (m12, m21) = (i * k * d * sinc, i * k * d * (c2 * n2) * (c2 * n2) * sinc);
        let b = cos + m12 * eta3;
        let c = m21 + cos * eta3;
        let den = eta1 * b + c;
        out[0] = ((eta1 * b - c) / den).norm_sqr();
        out[2] = 4.0 * eta1.re * eta3.re * (-2.0 * y).exp() / den.norm_sqr();
    }
    // p: η = n / cos θ. Multiplying B and C by cos θ3, and r's numerator and denominator
    // by cos θ1, keeps grazing and critical cosines (0) out of every denominator:
    // B' = c3 B, C' = c3 C, r = (n1 B' − c1 C') / (n1 B' + c1 C'),
    // T = 4 n1 c1 Re(n3 c3*) / |n1 B' + c1 C'|².
    {
        let (m12, m21) = (i * k * d * c2 * c2 * sinc, i * k * n2 * n2 * d * sinc);
        let b = cos * c3 + m12 * n3;
        let c = m21 * c3 + cos * n3;
        let den = b * n1 + c * c1;
        out[1] = ((b * n1 - c * c1) / den).norm_sqr();
        out[3] = 4.0 * n1 * c1.re * (c3.conj() * n3).re * (-2.0 * y).exp() / den.norm_sqr();
    }
    out
}

/// The bare interface `n1 | n3`, from the Fresnel equations written out here (the test's
/// own, in Macleod's admittance form).
fn bare(n1: f64, n3: f64, theta1: f64) -> [f64; 2] {
    let c1 = Complex64::new(theta1.cos(), 0.0);
    let c3 = macleod_cos(n1, theta1.cos(), n3);
    let rs = (c1 * n1 - c3 * n3) / (c1 * n1 + c3 * n3);
    let rp = (n1 / c1 - n3 / c3) / (n1 / c1 + n3 / c3);
    [rs.norm_sqr(), rp.norm_sqr()]
}

fn library(film: &Film, wavelength_nm: f64, theta1: f64) -> [f64; 4] {
    let r = film.response(wavelength_nm, theta1);
    [
        r.reflectance_s,
        r.reflectance_p,
        r.transmittance_s,
        r.transmittance_p,
    ]
}

// ---------------------------------------------------------------------------------------
// The sweep: random films over the whole domain, including the awkward corners.

#[derive(Clone, Copy, Debug)]
struct Case {
    film: Film,
    wavelength_nm: f64,
    theta1: f64,
}

/// `count` random cases: indices 1–2.5 in every order (so films and substrates both
/// denser and rarer than the ambient, total internal reflection at either interface and
/// evanescent films), one in ten with two equal indices, thicknesses 0 or 0.01 nm to
/// 100 µm, wavelengths 360–830 nm, angles 0 to exactly 90°.
fn sweep(count: usize, seed: u64) -> Vec<Case> {
    let mut g = rng::seeded(seed);
    (0..count)
        .map(|_| {
            let mut n = [0.0; 3];
            for x in &mut n {
                *x = rng::uniform(&mut g, 1.0, 2.5);
            }
            match (rng::uniform(&mut g, 0.0, 1.0) * 30.0) as u32 {
                0 => n[1] = n[0],
                1 => n[2] = n[1],
                2 => n[2] = n[0],
                _ => {}
            }
            let thickness_nm = if rng::uniform(&mut g, 0.0, 1.0) < 0.1 {
                0.0
            } else {
                rng::log_uniform(&mut g, 1e-2, 1e5)
            };
            let u = rng::uniform(&mut g, 0.0, 1.0);
            let theta1 = if u < 0.03 {
                0.0
            } else if u < 0.06 {
                FRAC_PI_2
            } else {
                rng::uniform(&mut g, 0.0, FRAC_PI_2)
            };
            Case {
                film: Film::new(n[0], n[1], n[2], thickness_nm),
                wavelength_nm: rng::uniform(&mut g, 360.0, 830.0),
                theta1,
            }
        })
        .collect()
}

/// The worst disagreement of `f` (unpolarised reflectance) with the transfer matrix over
/// `cases`, and the case where it occurs. NaN counts as infinitely wrong.
fn worst_unpolarised(cases: &[Case], f: impl Fn(&Case) -> f64) -> (f64, Option<Case>) {
    let mut worst = (0.0, None);
    for case in cases {
        let [rs, rp, ..] = tmm(&case.film, case.wavelength_nm, case.theta1);
        let got = f(case);
        let err = if got.is_finite() {
            (got - 0.5 * (rs + rp)).abs()
        } else {
            f64::INFINITY
        };
        if err > worst.0 {
            worst = (err, Some(*case));
        }
    }
    worst
}

const SWEEP_SEED: u64 = 0x7f11;
const SWEEP_CASES: usize = 20_000;

// ANCHOR: tmm_test
/// The Airy sum agrees with the transfer matrix to 1e-12 in R_s, R_p, T_s and T_p over
/// 20 000 random films: every order of indices, total internal reflection at either
/// interface, evanescent films, thicknesses from 0 to 100 µm, angles up to exactly 90°.
#[test]
fn airy_sum_agrees_with_the_transfer_matrix() {
    let cases = sweep(SWEEP_CASES, SWEEP_SEED);
    let mut worst = (0.0f64, String::new());
    for case in &cases {
        let want = tmm(&case.film, case.wavelength_nm, case.theta1);
        let got = library(&case.film, case.wavelength_nm, case.theta1);
        for (k, name) in ["R_s", "R_p", "T_s", "T_p"].iter().enumerate() {
            let err = (got[k] - want[k]).abs();
            if (err.is_nan() || err > worst.0) && !worst.0.is_nan() {
                worst = (
                    err,
                    format!("{name}: {} vs {} for {case:?}", got[k], want[k]),
                );
            }
        }
    }
    assert!(worst.0 <= 1e-12, "worst error {:e}: {}", worst.0, worst.1);
}
// ANCHOR_END: tmm_test

/// A reflectance built from the library's pieces, with one piece swapped.
fn assembled(
    case: &Case,
    phase_of: impl Fn(f64, f64, Complex64, f64) -> Complex64,
    flip_r12_p: bool,
) -> f64 {
    let Film { n1, n2, n3, .. } = case.film;
    let cos1 = case.theta1.cos();
    let c1 = Complex64::new(cos1, 0.0);
    let (c2, c3) = (cos_theta(n1, cos1, n2), cos_theta(n1, cos1, n3));
    let (i12, i23) = (interface(n1, c1, n2, c2), interface(n2, c2, n3, c3));
    let delta = phase_of(n2, case.film.thickness_nm, c2, case.wavelength_nm);
    let r12_p = if flip_r12_p { -i12.r_p } else { i12.r_p };
    let rs = airy_r(i12.r_s, i23.r_s, delta).norm_sqr();
    let rp = airy_r(r12_p, i23.r_p, delta).norm_sqr();
    0.5 * (rs + rp)
}

mod limits;
mod planted;
mod regimes;
mod seed;

// ---------------------------------------------------------------------------------------
// Energy, range and the soap film (thin and thick films, grazing and total reflection are
// in `regimes`).

/// R in [0, 1] and R + T = 1 (lossless media) for each polarisation, to 1e-12, over the
/// random sweep.
#[test]
fn energy_is_conserved_and_reflectance_is_in_range() {
    for case in sweep(SWEEP_CASES, SWEEP_SEED + 1) {
        let r = case.film.response(case.wavelength_nm, case.theta1);
        for (rr, tt) in [
            (r.reflectance_s, r.transmittance_s),
            (r.reflectance_p, r.transmittance_p),
        ] {
            assert!(
                (0.0..=1.0 + 1e-12).contains(&rr) && tt >= -1e-12 && (rr + tt - 1.0).abs() <= 1e-12,
                "R = {rr}, T = {tt} for {case:?}"
            );
        }
    }
}

// ANCHOR: soap_test
/// A quarter-wave film at normal incidence (n2 d = λ/4, e^{2iδ} = −1) reflects
/// ((n1 n3 − n2²)/(n1 n3 + n2²))²: for a soap film (n2 = 1.33) in air, ((1 − n2²)/(1 + n2²))²
/// = 0.0771. For a film denser (or rarer) than both neighbours, r12 r23 < 0 and that is the
/// largest R over all thicknesses; for a film between them, as an anti-reflection coating
/// (MgF2, 1.38, on glass, 1.52), the smallest: 0.0126, against 0.0426 for bare glass.
#[test]
fn quarter_wave_soap_film_reflects_most() {
    let lambda = 550.0;
    let soap = quarter_wave_reflectance(1.0, 1.33, 1.0);
    assert!((soap - 0.0771).abs() < 5e-5, "{soap}");
    let coating = quarter_wave_reflectance(1.0, 1.38, 1.52);
    assert!((coating - 0.0126).abs() < 5e-5, "{coating}");
    let glass = Film::new(1.0, 1.52, 1.52, 0.0).reflectance(lambda, 0.0);
    assert!((glass - 0.0426).abs() < 5e-5, "{glass}");
    for (n1, n2, n3) in [
        (1.0, 1.33, 1.0),
        (1.0, 1.5, 1.33),
        (1.0, 1.38, 1.52),
        (1.33, 2.0, 1.5),
    ] {
        let quarter = lambda / (4.0 * n2);
        let r = Film::new(n1, n2, n3, quarter).reflectance(lambda, 0.0);
        let want = quarter_wave_reflectance(n1, n2, n3);
        assert!((r - want).abs() <= 1e-14, "{n1}/{n2}/{n3}: {r} vs {want}");
        // Over one period of thickness (0 to λ/(2 n2)) the quarter wave is the extreme.
        let mut others = (0..=400).map(|k| {
            Film::new(n1, n2, n3, 2.0 * quarter * f64::from(k) / 400.0).reflectance(lambda, 0.0)
        });
        if (n2 - n1) * (n3 - n2) < 0.0 {
            assert!(others.all(|x| x <= r + 1e-15));
        } else {
            assert!(others.all(|x| x >= r - 1e-15));
        }
    }
}
// ANCHOR_END: soap_test

/// The rule for the spectra of *What films look like*: the quarter wave is the brightest
/// thickness when r12 r23 < 0, the film denser (or rarer) than *both* neighbours, as soap in
/// air and oil (1.5) on water (1.33) are. Denser than the ambient side alone does not make a
/// maximum: MgF2 (1.38) on glass (1.52) is denser than air, and its quarter wave is the
/// darkest thickness, darker than bare glass (the film at zero or half-wave thickness).
#[test]
fn quarter_wave_is_the_peak_only_between_denser_or_rarer() {
    let lambda = 550.0;
    let over_a_period = |(n1, n2, n3): (f64, f64, f64)| {
        let quarter = lambda / (4.0 * n2);
        let r = |d: f64| Film::new(n1, n2, n3, d).reflectance(lambda, 0.0);
        let others: Vec<f64> = (0..=400)
            .map(|k| r(2.0 * quarter * f64::from(k) / 400.0))
            .collect();
        let (lo, hi) = others.iter().fold((f64::INFINITY, 0.0f64), |(lo, hi), &x| {
            (lo.min(x), hi.max(x))
        });
        (r(quarter), r(0.0), r(2.0 * quarter), lo, hi)
    };
    for film in [(1.0, 1.33, 1.0), (1.0, 1.5, 1.33)] {
        let (r12, r23) = (
            (film.0 - film.1) / (film.0 + film.1),
            (film.1 - film.2) / (film.1 + film.2),
        );
        assert!(r12 * r23 < 0.0, "{film:?}");
        let (quarter, bare, half, _, hi) = over_a_period(film);
        assert!(
            quarter >= hi - 1e-15 && quarter > bare + 0.01,
            "{film:?}: {quarter}"
        );
        assert!((bare - half).abs() <= 1e-12, "{film:?}: {bare} vs {half}");
    }
    // The lens coating: denser than the ambient air, yet a minimum.
    let coating = (1.0, 1.38, 1.52);
    assert!(coating.1 > coating.0);
    let (quarter, bare, half, lo, _) = over_a_period(coating);
    assert!(quarter <= lo + 1e-15, "{quarter} vs {lo}");
    assert!((quarter - 0.0126).abs() < 5e-5, "{quarter}");
    assert!(
        (bare - 0.0426).abs() < 5e-5 && (half - bare).abs() <= 1e-12,
        "{bare}, {half}"
    );
}
// ---------------------------------------------------------------------------------------
// Exercises. Each scaffold is the student's to fill in; each ignored test checks it, and
// fails until it is done: `cargo test --test book optics::thinfilm::exercise_ -- --ignored`.

/// Two films by Macleod's characteristic matrices (his conventions, as in [`tmm_cos`]),
/// `n = [ambient, upper film, lower film, substrate]`: `[R_s, R_p]`. Unscaled, so for
/// films up to a few micrometres only.
fn tmm_two_layers(n: [f64; 4], d_nm: [f64; 2], wavelength_nm: f64, cos1: f64) -> [f64; 2] {
    let k = 2.0 * PI / wavelength_nm;
    let i = Complex64::i();
    let c: Vec<Complex64> = n.iter().map(|&nj| macleod_cos(n[0], cos1, nj)).collect();
    let mut out = [0.0; 2];
    for (pol, slot) in out.iter_mut().enumerate() {
        // Tilted admittances: n cos θ for s, n / cos θ for p.
        let eta = |j: usize| if pol == 0 { c[j] * n[j] } else { n[j] / c[j] };
        let (mut m11, mut m12, mut m21, mut m22) = (
            Complex64::new(1.0, 0.0),
            Complex64::new(0.0, 0.0),
            Complex64::new(0.0, 0.0),
            Complex64::new(1.0, 0.0),
        );
        for layer in 1..=2 {
            let delta = c[layer] * (k * n[layer] * d_nm[layer - 1]);
            let (cos, sin) = (delta.cos(), delta.sin());
            let (a11, a12, a21, a22) = (cos, i * sin / eta(layer), i * eta(layer) * sin, cos);
            (m11, m12, m21, m22) = (
                m11 * a11 + m12 * a21,
                m11 * a12 + m12 * a22,
                m21 * a11 + m22 * a21,
                m21 * a12 + m22 * a22,
            );
        }
        let b = m11 + m12 * eta(3);
        let cc = m21 + m22 * eta(3);
        *slot = ((eta(0) * b - cc) / (eta(0) * b + cc)).norm_sqr();
    }
    out
}

/// Exercise 1 of *Thin-film interference*: `[R_s, R_p]` of two films on a substrate,
/// `n = [ambient, upper film, lower film, substrate]` with thicknesses `d_nm = [upper,
/// lower]`, by the Airy sum applied twice.
#[allow(unused_variables)]
fn your_two_layer_reflectance(
    n: [f64; 4],
    d_nm: [f64; 2],
    wavelength_nm: f64,
    cos1: f64,
) -> [f64; 2] {
    unimplemented!("exercise 1 of Thin-film interference: apply the Airy sum twice")
}

#[test]
#[ignore = "exercise 1 of Thin-film interference: fill in your_two_layer_reflectance, then run it"]
fn exercise_1_two_layers() {
    let mut g = rng::seeded(0x2f11);
    let mut worst: f64 = 0.0;
    for _ in 0..20_000 {
        let mut n = [0.0; 4];
        for x in &mut n {
            *x = rng::uniform(&mut g, 1.0, 2.5);
        }
        let d = [
            rng::uniform(&mut g, 0.0, 1000.0),
            rng::uniform(&mut g, 0.0, 1000.0),
        ];
        let wavelength = rng::uniform(&mut g, 360.0, 830.0);
        let cos1 = rng::uniform(&mut g, 0.01, 1.0);
        let (yours, reference) = (
            your_two_layer_reflectance(n, d, wavelength, cos1),
            tmm_two_layers(n, d, wavelength, cos1),
        );
        for (y, r) in yours.iter().zip(reference) {
            assert!(
                (y - r).abs() <= 1e-10,
                "{n:?}, {d:?} nm at {wavelength} nm, cos {cos1}: {yours:?}, matrices give {reference:?}"
            );
            worst = worst.max((y - r).abs());
        }
    }
    // One film with the other of zero thickness is the library's one film.
    let one = Film::new(1.0, 1.38, 1.52, 100.0).response_cos(550.0, 0.8);
    let two = your_two_layer_reflectance([1.0, 1.38, 2.0, 1.52], [100.0, 0.0], 550.0, 0.8);
    assert!(
        (two[0] - one.reflectance_s).abs() <= 1e-12 && (two[1] - one.reflectance_p).abs() <= 1e-12
    );
    assert!(worst <= 1e-10);
}

/// The unpolarised reflectance of the film of MgF2 (1.38, no dispersion) on glass (1.52)
/// in air, averaged over 400..=700 nm in steps of 1 nm, at `theta1`.
fn mean_coating_reflectance(thickness_nm: f64, theta1: f64) -> f64 {
    let film = Film::new(1.0, 1.38, 1.52, thickness_nm);
    (400..=700)
        .map(|l| film.reflectance(f64::from(l), theta1))
        .sum::<f64>()
        / 301.0
}

/// Exercise 2 of *Thin-film interference*: the MgF2 thickness (nm) that minimises
/// `mean_coating_reflectance` at normal incidence and at 45°.
const YOUR_COATING_NM_AT_0_AND_45: Option<(f64, f64)> = None;

#[test]
#[ignore = "exercise 2 of Thin-film interference: set YOUR_COATING_NM_AT_0_AND_45, then run it"]
fn exercise_2_broadband_coating() {
    let optimum = |theta1: f64| {
        (500..=2000)
            .map(|k| f64::from(k) * 0.1)
            .min_by(|a, b| {
                mean_coating_reflectance(*a, theta1)
                    .total_cmp(&mean_coating_reflectance(*b, theta1))
            })
            .unwrap()
    };
    let expected = (optimum(0.0), optimum(45f64.to_radians()));
    let yours = YOUR_COATING_NM_AT_0_AND_45.expect("exercise 2: set YOUR_COATING_NM_AT_0_AND_45");
    assert!(
        (yours.0 - expected.0).abs() <= 0.5 && (yours.1 - expected.1).abs() <= 0.5,
        "{yours:?} nm, but the optima are {expected:?} nm"
    );
}

/// Exercise 3 of *Thin-film interference*: the unpolarised reflectance of a film (index
/// `n2`, `d_nm` thick) on a metal of complex index `n3 = n + ik`, for light from the
/// ambient `n1` at `cos θ1 = cos1`.
#[allow(unused_variables)]
fn your_film_on_metal_reflectance(
    n1: f64,
    n2: f64,
    n3: Complex64,
    d_nm: f64,
    wavelength_nm: f64,
    cos1: f64,
) -> f64 {
    unimplemented!("exercise 3 of Thin-film interference: a film on a metal substrate")
}

/// The bare interface from `n1` onto a conductor `n3`, as pbrt-v4 writes it (`FrComplex`).
fn bare_conductor(n1: f64, n3: Complex64, cos1: f64) -> f64 {
    let eta = n3 / n1;
    let sin2_t = (1.0 - cos1 * cos1) / (eta * eta);
    let cos_t = (1.0 - sin2_t).sqrt();
    let r_parl = (eta * cos1 - cos_t) / (eta * cos1 + cos_t);
    let r_perp = (cos1 - eta * cos_t) / (cos1 + eta * cos_t);
    0.5 * (r_parl.norm_sqr() + r_perp.norm_sqr())
}

#[test]
#[ignore = "exercise 3 of Thin-film interference: fill in your_film_on_metal_reflectance, then run it"]
fn exercise_3_metal_substrate() {
    let metals = [
        Complex64::new(0.96, 6.69),
        Complex64::new(0.06, 3.59),
        Complex64::new(0.2, 3.0),
    ];
    for m in metals {
        for k in 0..90 {
            let c = f64::to_radians(f64::from(k)).cos();
            // No film: the bare conductor, from air and from glass.
            for n1 in [1.0, 1.5] {
                let (got, want) = (
                    your_film_on_metal_reflectance(n1, 1.38, m, 0.0, 550.0, c),
                    bare_conductor(n1, m, c),
                );
                assert!(
                    (got - want).abs() <= 1e-12,
                    "{m} from {n1} at {k} deg, no film: {got}, expected {want}"
                );
            }
            let r = your_film_on_metal_reflectance(1.0, 1.38, m, 120.0, 550.0, c);
            assert!(
                (0.0..1.0).contains(&r),
                "{m} at {k} deg: R = {r}, but the metal absorbs"
            );
        }
        // A half-wave film is absent at normal incidence, on a metal too.
        let half = 550.0 / (2.0 * 1.38);
        let (got, want) = (
            your_film_on_metal_reflectance(1.0, 1.38, m, half, 550.0, 1.0),
            bare_conductor(1.0, m, 1.0),
        );
        assert!(
            (got - want).abs() <= 1e-12,
            "{m}, half-wave film: {got}, expected {want}"
        );
    }
    // A real substrate index is the library's dielectric film, total reflection included.
    for case in sweep(2_000, 0x3e7a) {
        let Film {
            n1,
            n2,
            n3,
            thickness_nm,
        } = case.film;
        let c = case.theta1.cos();
        // Where the plain Airy sum keeps its digits (see "Where the plain sum loses digits").
        if c < 1e-3 || cos_theta(n1, c, n2).norm() < 1e-3 || thickness_nm > 5_000.0 {
            continue;
        }
        let got = your_film_on_metal_reflectance(
            n1,
            n2,
            Complex64::new(n3, 0.0),
            thickness_nm,
            case.wavelength_nm,
            c,
        );
        let want = case.film.response_cos(case.wavelength_nm, c).reflectance();
        assert!(
            (got - want).abs() <= 1e-9,
            "{case:?}: {got}, expected {want}"
        );
    }
}

/// Exercise 4 of *Thin-film interference*: for the 300 nm soap film (1.33) in air at
/// 550 nm, the hemispherical means weighted by cos θ, `2 ∫ R(θ) cos θ sin θ dθ` over
/// `[0, π/2]`, of the s-only reflectance `R_s` and of the true unpolarised `R`.
const YOUR_MEANS_S_ONLY_AND_TRUE: Option<(f64, f64)> = None;

#[test]
#[ignore = "exercise 4 of Thin-film interference: set YOUR_MEANS_S_ONLY_AND_TRUE, then run it"]
fn exercise_4_s_only_on_average() {
    let film = Film::new(1.0, 1.33, 1.0, 300.0);
    let steps = 20_000;
    let h = FRAC_PI_2 / f64::from(steps);
    let (mut s_only, mut truth) = (0.0, 0.0);
    for k in 0..steps {
        let theta = (f64::from(k) + 0.5) * h;
        let r = film.response(550.0, theta);
        let w = 2.0 * theta.cos() * theta.sin() * h;
        s_only += w * r.reflectance_s;
        truth += w * r.reflectance();
    }
    let yours = YOUR_MEANS_S_ONLY_AND_TRUE.expect("exercise 4: set YOUR_MEANS_S_ONLY_AND_TRUE");
    assert!(
        (yours.0 / s_only - 1.0).abs() <= 0.01 && (yours.1 / truth - 1.0).abs() <= 0.01,
        "{yours:?}, but the means are ({s_only}, {truth})"
    );
}

/// Exercise 5 of *Thin-film interference*: a film and a wavelength for which the rule
/// "dark when 2 n2 d = m λ" predicts darkness at normal incidence (m a whole number, at
/// least 1), but the reflectance there is a maximum over the thickness.
fn your_counterexample() -> (Film, f64) {
    unimplemented!("exercise 5 of Thin-film interference: a film where the pi rule is wrong")
}

#[test]
#[ignore = "exercise 5 of Thin-film interference: fill in your_counterexample, then run it"]
fn exercise_5_the_pi_rule() {
    let (film, wavelength) = your_counterexample();
    let m = 2.0 * film.n2 * film.thickness_nm / wavelength;
    assert!(
        m >= 0.5 && (m - m.round()).abs() <= 1e-9,
        "2 n2 d / λ = {m}: not a whole number"
    );
    let r = |d: f64| {
        Film {
            thickness_nm: d,
            ..film
        }
        .response(wavelength, 0.0)
        .reflectance()
    };
    let (at, quarter) = (r(film.thickness_nm), wavelength / (4.0 * film.n2));
    for shift in [0.1 * quarter, 0.5 * quarter, quarter] {
        assert!(
            at > r(film.thickness_nm + shift) && at > r(film.thickness_nm - shift),
            "R = {at} at the rule's dark thickness is not a maximum"
        );
    }
}

// ---------------------------------------------------------------------------------------
// Accuracy against exact arithmetic (data/corpus/thinfilm.txt, tools/exact).

/// At a subnormal `cos θ1` the transmittance used to be `(Re(n3 cos θ3)/(n1 cos θ1)) |t|²`
/// = ∞ · 0 = NaN; the exact answer (the corpus's, mpmath at 256 bits) is a few subnormals,
/// and the ratio taken last gives 0, within one unit of the scale 1.
#[test]
fn transmittance_at_a_subnormal_cosine_is_not_nan() {
    let root = crate::support::root();
    let corpus = raylemma::check::accuracy::corpus::load(&root.join("data/corpus/thinfilm.txt"))
        .expect("the corpus reads");
    let question = "film 1.0 1.38 1.52 100.0 550.0 5e-324";
    let case = corpus
        .cases
        .iter()
        .find(|c| c.question == question)
        .expect("the case is in the corpus");
    let exact = case.exact.as_ref().expect("an answer");
    let r = Film::new(1.0, 1.38, 1.52, 100.0).response_cos(550.0, 5e-324);
    let got = [
        r.reflectance_s,
        r.reflectance_p,
        r.transmittance_s,
        r.transmittance_p,
    ];
    for (g, e) in got.iter().zip(exact) {
        assert!(
            (g - e.double).abs() <= f64::EPSILON,
            "{got:?}, exact {}",
            e.text
        );
    }
}
