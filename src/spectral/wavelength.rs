//! Wavelength sampling: uniform, a visible-range importance pdf, hero wavelengths (Wilkie et
//! al. 2014) rotated in sample space and in wavelength space, the termination of secondary
//! wavelengths at a dispersive delta event, Wilkie et al.'s multiple importance sampling
//! over which lane was the hero (for a path whose sampling depends on wavelength without
//! being a delta), and the source notes' "random wavelength and a small band of nearby
//! ones" for comparison.
//! Chapter: *Wavelength sampling and hero wavelengths* (`chapters/spectral/wavelength.md`).
//!
//! A path carries [`N`] wavelengths ("lanes") at once. Every strategy fills a
//! [`Wavelengths`] so that one estimator serves them all: for a spectral integrand `f`,
//!
//! `⟨∫ f dλ⟩ = (1/N) Σ_j f(λ_j) / pdf_j`, summed over the lanes with `pdf_j > 0`,
//!
//! where `pdf_j` is the *weighting* density the strategy assigns to lane `j` (the lane's own
//! density for per-lane estimators, the lanes' mean density for the balance heuristic over
//! the rotations of a wavelength-space hero).

use std::sync::LazyLock;

use glam::DVec3;

use super::{LAMBDA_MAX, LAMBDA_MIN, cie};

/// The number of wavelengths a path carries (as in pbrt-v4 and in Wilkie et al. 2014).
pub const N: usize = 4;

/// The width of the sampled range, 830 − 360 = 470 nm.
pub const RANGE: f64 = LAMBDA_MAX - LAMBDA_MIN;

// ANCHOR: wavelengths
/// The wavelengths of one path, nm, with the density each lane is weighted by.
///
/// The estimate of `∫ f dλ` is `(1/N) Σ_j f(λ_j) / pdf_j` over the lanes with
/// `pdf_j > 0` ([`Wavelengths::estimate`]); a lane with `pdf_j = 0` is terminated.
/// `hero_pdf` is the density of lane 0's wavelength on its own: the weight lane 0 needs
/// once it is the only one left ([`Wavelengths::terminate_secondary`]).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Wavelengths {
    /// The wavelengths, nm; lane 0 is the hero.
    pub lambda: [f64; N],
    /// The weighting density of each lane, per nm; 0 for a terminated lane.
    pub pdf: [f64; N],
    /// The density of the hero wavelength `lambda[0]` alone, per nm.
    pub hero_pdf: f64,
}
// ANCHOR_END: wavelengths

impl Wavelengths {
    // ANCHOR: estimate
    /// The estimate `(1/N) Σ_j f(λ_j) / pdf_j` over the live lanes (`pdf_j > 0`) of the
    /// integral of `f` over wavelength. A NaN wavelength or density gives a NaN estimate
    /// (a NaN `pdf_j` is not `> 0`, so it is caught explicitly), never a silent zero.
    pub fn estimate(&self, f: impl Fn(f64) -> DVec3) -> DVec3 {
        let mut sum = DVec3::ZERO;
        for (&l, &p) in self.lambda.iter().zip(&self.pdf) {
            if p.is_nan() || l.is_nan() {
                return DVec3::NAN;
            }
            if p > 0.0 {
                sum += f(l) / p;
            }
        }
        sum / N as f64
    }
    // ANCHOR_END: estimate

    /// The estimate of the CIE XYZ of spectrum `s` ([`cie::xyz`]'s normalisation:
    /// `s = 1` has `Y = 1`): [`Wavelengths::estimate`] of `s(λ) (x̄, ȳ, z̄)(λ) / ∫ ȳ dλ`.
    pub fn xyz(&self, s: impl Fn(f64) -> f64) -> DVec3 {
        let k = 1.0 / cie::y_integral();
        self.estimate(|l| s(l) * k * cie::cmf(l))
    }

    // ANCHOR: terminate
    /// Keeps only the hero lane, for a path that met a wavelength-dependent delta event
    /// (refraction through dispersive glass): the secondary lanes get `pdf = 0`, and the
    /// hero's weighting density becomes `hero_pdf / N`, so that the estimate is
    /// `(1/N) f(λ_0) / (p(λ_0)/N) = f(λ_0) / p(λ_0)`: a one-wavelength estimator, unbiased
    /// because `λ_0` alone has density `p`. Calling it twice changes nothing.
    pub fn terminate_secondary(&mut self) {
        if self.is_terminated() {
            return;
        }
        self.pdf = [0.0; N];
        self.pdf[0] = self.hero_pdf / N as f64;
    }
    // ANCHOR_END: terminate

    // ANCHOR: balance_path
    /// Wilkie et al.'s multiple importance sampling over which lane was the hero, for a path
    /// `X̄` whose sampling depends on wavelength without being a delta (a rough dispersive
    /// interface, a chromatic medium). `path_pdf[k]` is `p(X̄ | λ_k)`, the density with which
    /// the path's sampling would have produced `X̄` had lane `k` been the hero: `path_pdf[0]`
    /// is the one actually used, and the caller's throughput of lane `j` is
    /// `f(X̄, λ_j) / p(X̄ | λ_0)`. Every live lane's weighting density is multiplied by
    /// `(1/N) Σ_k p(X̄ | λ_k) / p(X̄ | λ_0)`, so that the estimate becomes the balance heuristic
    /// `Σ_j f(X̄, λ_j) / (p(λ_j) Σ_k p(X̄ | λ_k))`.
    ///
    /// The densities are those of the whole path (products over its vertices), applied once:
    /// the mean of products is not the product of means. Right for lanes that carry their
    /// own density ([`hero_uniform`], Wilkie et al.'s, and [`hero_visible`]): there every
    /// lane is equally likely to have been the hero. Not for [`hero_balance`]'s lanes, whose
    /// weight would be `(1/N) Σ_k p(λ_k) p(X̄ | λ_k) / p(X̄ | λ_0)`. A terminated path is left
    /// as it is (its estimator is already the hero's alone). At a delta event only the hero
    /// has `p(X̄ | λ_k) > 0`, and the rule gives lane 0 the density `p(λ_0) / N`:
    /// [`Wavelengths::terminate_secondary`] is its limit. A `path_pdf[0]` that is not positive
    /// makes every density NaN, so the estimate is NaN, never a silent zero.
    pub fn balance_path_pdfs(&mut self, path_pdf: [f64; N]) {
        if self.is_terminated() {
            return;
        }
        if path_pdf[0].is_nan() || path_pdf[0] <= 0.0 {
            self.pdf = [f64::NAN; N];
            return;
        }
        let mean = path_pdf.iter().map(|&p| p / path_pdf[0]).sum::<f64>() / N as f64;
        for p in &mut self.pdf {
            *p *= mean;
        }
    }
    // ANCHOR_END: balance_path

    /// Whether the secondary lanes are terminated (all have `pdf = 0`).
    pub fn is_terminated(&self) -> bool {
        self.pdf[1..].iter().all(|&p| p == 0.0)
    }

    /// A single wavelength `nm` with density `pdf`, stored as a hero whose secondary
    /// lanes are terminated.
    pub fn single(nm: f64, pdf: f64) -> Self {
        let mut w = Wavelengths {
            lambda: [nm; N],
            pdf: [pdf; N],
            hero_pdf: pdf,
        };
        w.terminate_secondary();
        w
    }
}

/// The fractional part, in `[0, 1)`: the wrap "mod 1" of sample space.
#[inline]
pub fn wrap01(x: f64) -> f64 {
    let f = x - x.floor();
    // x - floor(x) rounds up to 1.0 for tiny negative x.
    if f >= 1.0 { 0.0 } else { f }
}

/// `(u + offset) mod 1` for `u` and `offset` in `[0, 1)` with `1 − offset` a double (the
/// rotations `j/N`), the wrap decided exactly: `u ≥ 1 − offset` wraps to `u − (1 − offset)`,
/// which is exact; otherwise `u + offset`, one rounding, which may round up to 1.0 but
/// never wraps to 0. [`wrap01`] of the rounded sum sends `u + offset` just below 1 (when it
/// rounds to 1.0: `u` = 1/4 − 2⁻⁵⁵ with offset 3/4) to 0, a whole range away.
#[inline]
pub fn rotate01(u: f64, offset: f64) -> f64 {
    let rest = 1.0 - offset;
    if u >= rest { u - rest } else { u + offset }
}

// ---------------------------------------------------------------------------------------
// Uniform.

// ANCHOR: uniform
/// The uniform density on 360–830 nm: `1 / 470` per nm inside, 0 outside (and for NaN).
pub fn uniform_pdf(nm: f64) -> f64 {
    if (LAMBDA_MIN..=LAMBDA_MAX).contains(&nm) {
        1.0 / RANGE
    } else {
        0.0
    }
}

/// The uniform wavelength for `u` in `[0, 1)`: `λ = 360 + 470 u`.
pub fn sample_uniform(u: f64) -> f64 {
    LAMBDA_MIN + u * RANGE
}
// ANCHOR_END: uniform

// ---------------------------------------------------------------------------------------
// The visible-range importance pdf.

/// The rate `a` of the visible pdf `p(λ) ∝ 1 / cosh²(a (λ − c))`, per nm (pbrt-v4).
pub const VISIBLE_A: f64 = 0.0072;
/// The centre `c` of the visible pdf, nm (pbrt-v4).
pub const VISIBLE_C: f64 = 538.0;

// ANCHOR: visible
/// `(t₀, t₁) = (tanh(a (λ_min − c)), tanh(a (λ_max − c)))`: the CDF's anchors, computed once.
fn visible_ends() -> (f64, f64) {
    static ENDS: LazyLock<(f64, f64)> = LazyLock::new(|| {
        (
            (VISIBLE_A * (LAMBDA_MIN - VISIBLE_C)).tanh(),
            (VISIBLE_A * (LAMBDA_MAX - VISIBLE_C)).tanh(),
        )
    });
    *ENDS
}

/// The visible-range importance density `p(λ) = a / (t₁ − t₀) / cosh²(a (λ − c))` on
/// 360–830 nm: normalised over this range because `∫ sech²(a x) dx = tanh(a x) / a`.
/// 0 outside the range and for NaN.
pub fn visible_pdf(nm: f64) -> f64 {
    if !(LAMBDA_MIN..=LAMBDA_MAX).contains(&nm) {
        return 0.0;
    }
    let (t0, t1) = visible_ends();
    let c = (VISIBLE_A * (nm - VISIBLE_C)).cosh();
    VISIBLE_A / (t1 - t0) / (c * c)
}

/// Its CDF, `P(λ) = (tanh(a (λ − c)) − t₀) / (t₁ − t₀)`, clamped to `[0, 1]`.
pub fn visible_cdf(nm: f64) -> f64 {
    let (t0, t1) = visible_ends();
    let l = nm.clamp(LAMBDA_MIN, LAMBDA_MAX);
    (((VISIBLE_A * (l - VISIBLE_C)).tanh() - t0) / (t1 - t0)).clamp(0.0, 1.0)
}

/// The inverse CDF and the density there, for `u` in `[0, 1)`: with
/// `t = t₀ + u (t₁ − t₀) = tanh(a (λ − c))`, `λ = c + atanh(t) / a`, and since
/// `1 / cosh² = 1 − tanh²`, `p(λ) = a (1 − t²) / (t₁ − t₀)`: no `cosh`, and one logarithm,
/// since `atanh t = ½ ln((1 + t) / (1 − t))` (`|t| < 1` here: `t₀ ≈ −0.86`, `t₁ ≈ 0.97`).
/// Near `t = 0` this form loses relative accuracy, but not absolute: `λ` agrees with
/// `c + atanh(t) / a` to `1e-9` nm (a test checks it), and `ln` is cheaper than the
/// `log1p` that `f64::atanh` calls (the renderer draws four of these per path).
/// `λ` is clamped to the range against rounding (u = 0 gives 360 nm, u → 1 gives 830 nm).
#[inline]
pub fn sample_visible_pdf(u: f64) -> (f64, f64) {
    let (t0, t1) = visible_ends();
    let t = t0 + u * (t1 - t0);
    let l = VISIBLE_C + ((1.0 + t) / (1.0 - t)).ln() * (0.5 / VISIBLE_A);
    (
        l.clamp(LAMBDA_MIN, LAMBDA_MAX),
        (1.0 - t * t) * (VISIBLE_A / (t1 - t0)),
    )
}

/// The inverse CDF alone (see [`sample_visible_pdf`]).
pub fn sample_visible(u: f64) -> f64 {
    sample_visible_pdf(u).0
}
// ANCHOR_END: visible

// ---------------------------------------------------------------------------------------
// Strategies.

// ANCHOR: hero_uniform
// EXERCISE spectral/wavelength hero_uniform: N hero wavelengths rotated by 1/N of the range, each with the uniform density
/// Hero wavelengths, uniform: lane `j` at `λ_j = λ_min + ((u + j/N) mod 1)(λ_max − λ_min)`,
/// each with the uniform density (each `λ_j` alone is uniform, since `(u + j/N) mod 1` is).
pub fn hero_uniform(u: f64) -> Wavelengths {
    let lambda = std::array::from_fn(|j| sample_uniform(rotate01(u, j as f64 / N as f64)));
    Wavelengths {
        lambda,
        pdf: [1.0 / RANGE; N],
        hero_pdf: 1.0 / RANGE,
    }
}
// END EXERCISE
// ANCHOR_END: hero_uniform

// ANCHOR: hero_visible
/// Hero wavelengths rotated in *sample space*: `u_j = (u + j/N) mod 1`, `λ_j = P⁻¹(u_j)`
/// through the visible pdf's inverse CDF. Each `u_j` is uniform, so each `λ_j` alone has
/// density `p`: every lane is weighted by its own `p(λ_j)`.
#[inline]
pub fn hero_visible(u: f64) -> Wavelengths {
    let lanes: [(f64, f64); N] =
        std::array::from_fn(|j| sample_visible_pdf(rotate01(u, j as f64 / N as f64)));
    Wavelengths {
        lambda: lanes.map(|l| l.0),
        pdf: lanes.map(|l| l.1),
        hero_pdf: lanes[0].1,
    }
}
// ANCHOR_END: hero_visible

// ANCHOR: hero_balance
/// Hero wavelengths rotated in *wavelength space* from a non-uniform hero: the hero
/// `λ_0 = P⁻¹(u)` from the visible pdf, the others
/// `λ_j = λ_min + ((λ_0 − λ_min)/R + j/N mod 1) R`, and every lane weighted by the balance
/// heuristic over the N rotations of `p`: `f(λ_j) / Σ_k p(λ_k)`, stored as the weighting
/// density `pdf_j = (1/N) Σ_k p(λ_k)`.
///
/// This is not Wilkie et al.'s method: their hero is uniform (then this is [`hero_uniform`]),
/// and their balance heuristic is over the wavelength-dependent *path* densities
/// ([`Wavelengths::balance_path_pdfs`]). Here the lanes are always an equally spaced rule whose
/// offset has the folded density `R Σ_k p(λ_k)`, within 7 % of uniform for the visible pdf:
/// [`hero_uniform`] with slightly reshuffled weights.
pub fn hero_balance(u: f64) -> Wavelengths {
    let (hero, hero_pdf) = sample_visible_pdf(u);
    let s = (hero - LAMBDA_MIN) / RANGE;
    let lambda: [f64; N] = std::array::from_fn(|j| {
        if j == 0 {
            hero
        } else {
            sample_uniform(rotate01(s, j as f64 / N as f64))
        }
    });
    let mean = (hero_pdf + lambda[1..].iter().map(|&l| visible_pdf(l)).sum::<f64>()) / N as f64;
    Wavelengths {
        lambda,
        pdf: [mean; N],
        hero_pdf,
    }
}
// ANCHOR_END: hero_balance

// ANCHOR: seed_band
/// The source notes' strategy (project page 003, `sample_lambda`): "a random wavelength
/// within the visible range and then a small band of nearby wavelengths", the contributions
/// averaged. `lo`, `hi`: the range the random wavelength is drawn from; `spacing`: the
/// distance between the band's wavelengths. The source gives neither number.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct SeedBand {
    /// Start of the source's "visible range", nm.
    pub lo: f64,
    /// End of the source's "visible range", nm.
    pub hi: f64,
    /// Spacing of the band, nm.
    pub spacing: f64,
}

/// The reading of the source notes used in the chapter: the CIE's conventional visible range
/// 380–780 nm, and a band of 5 nm steps.
pub const SEED_BAND: SeedBand = SeedBand {
    lo: 380.0,
    hi: 780.0,
    spacing: 5.0,
};

/// The source's lanes: `λ_0 = lo + u (hi − lo)` and `λ_j = λ_0 + j · spacing`, each weighted
/// by the density of the random wavelength, `1 / (hi − lo)`, and averaged.
pub fn seed_band(u: f64, band: &SeedBand) -> Wavelengths {
    let hero = band.lo + u * (band.hi - band.lo);
    let pdf = 1.0 / (band.hi - band.lo);
    Wavelengths {
        lambda: std::array::from_fn(|j| hero + j as f64 * band.spacing),
        pdf: [pdf; N],
        hero_pdf: pdf,
    }
}

/// What the source's estimator converges to: lane `j` is uniform on
/// `[lo + j·spacing, hi + j·spacing]`, so the average over lanes integrates `f` with the
/// weight `w(λ) = (1/N) · #{j : lo + j·spacing ≤ λ ≤ hi + j·spacing}` instead of 1 on
/// 360–830 nm: a staircase, 0 below `lo`, up by `1/N` at each of `lo + j·spacing`
/// (`j = 0 … N−1`), 1 from `lo + (N−1)·spacing` to `hi`, and down by `1/N` past each of
/// `hi + j·spacing`.
pub fn seed_band_weight(nm: f64, band: &SeedBand) -> f64 {
    (0..N)
        .filter(|&j| {
            let o = j as f64 * band.spacing;
            nm >= band.lo + o && nm <= band.hi + o
        })
        .count() as f64
        / N as f64
}
// ANCHOR_END: seed_band

/// The wavelength-sampling strategies the chapter compares.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum WavelengthStrategy {
    /// One uniform wavelength.
    Uniform,
    /// One wavelength from the visible pdf.
    Visible,
    /// N hero lanes, uniform ([`hero_uniform`]).
    HeroUniform,
    /// N hero lanes from the visible pdf, rotated in sample space ([`hero_visible`]).
    HeroVisible,
    /// N hero lanes from the visible pdf rotated in wavelength space, balance heuristic over
    /// the rotations ([`hero_balance`]; not Wilkie et al.'s method, whose hero is uniform).
    HeroBalance,
    /// The source notes' band ([`seed_band`] with [`SEED_BAND`]).
    SeedBand,
}

impl WavelengthStrategy {
    /// Every strategy, in the chapter's order.
    pub const ALL: [WavelengthStrategy; 6] = [
        WavelengthStrategy::Uniform,
        WavelengthStrategy::Visible,
        WavelengthStrategy::HeroUniform,
        WavelengthStrategy::HeroVisible,
        WavelengthStrategy::HeroBalance,
        WavelengthStrategy::SeedBand,
    ];

    /// A short name for tables and legends.
    pub fn name(self) -> &'static str {
        match self {
            WavelengthStrategy::Uniform => "uniform, 1 λ",
            WavelengthStrategy::Visible => "visible pdf, 1 λ",
            WavelengthStrategy::HeroUniform => "hero, uniform",
            WavelengthStrategy::HeroVisible => "hero, visible pdf (sample space)",
            WavelengthStrategy::HeroBalance => "hero, visible pdf (wavelength space, balance)",
            WavelengthStrategy::SeedBand => "seed's band",
        }
    }

    /// The wavelengths of one path for the uniform number `u` in `[0, 1)`.
    #[inline]
    pub fn sample(self, u: f64) -> Wavelengths {
        match self {
            WavelengthStrategy::Uniform => Wavelengths::single(sample_uniform(u), 1.0 / RANGE),
            WavelengthStrategy::Visible => {
                let (l, p) = sample_visible_pdf(u);
                Wavelengths::single(l, p)
            }
            WavelengthStrategy::HeroUniform => hero_uniform(u),
            WavelengthStrategy::HeroVisible => hero_visible(u),
            WavelengthStrategy::HeroBalance => hero_balance(u),
            WavelengthStrategy::SeedBand => seed_band(u, &SEED_BAND),
        }
    }
}
