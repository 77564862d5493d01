//! The checker of the importance-sampling estimator: any routine with the signature of
//! [`crate::sampling::importance::estimate`] can be checked against the claims of the
//! chapter *Importance sampling* (`chapters/sampling/importance.md`).
//!
//! * `count`: `n` draws give `n` terms;
//! * `unbiased`: the mean of `f(X)/q(X)` is `∫ f` for proposals positive wherever `f` is
//!   (t-tests at the options' level);
//! * `zero_variance`: a proposal proportional to `f` gives every term equal to `∫ f`;
//! * `zero_density`: a draw where `q(X) = 0` adds a term of 0: counted (a draw skipped
//!   leaves fewer than `n` terms, a biased mean), never NaN or ∞.
//!
//! Planted bugs that it must reject are in [`planted`].

pub mod planted;

use super::{Finding, Options, Verdict};
use crate::rng::{self, Rng};
use crate::sampling::importance::{HALF_SUPPORT, LINEAR, MATCHED, Proposal, UNIFORM, square};
use crate::stats::ttest::{self, Summary};

/// The estimator's signature: the terms `f(X)/q(X)` of `n` draws `X ~ q`, summarised.
pub type Estimator = dyn Fn(&dyn Fn(f64) -> f64, &Proposal, usize, &mut Rng) -> Summary;

/// Default number of draws per estimate.
pub const SAMPLES: usize = 200_000;
/// Default seed.
pub const SEED: u64 = 0x1a5;
/// Bound of the matched proposal's spread and error, in units of `eps I`.
pub(crate) const MATCHED_BOUND: f64 = 16.0;

/// The error of `estimate` against the draws it is given, as a picture: the root mean
/// square of `mean - exact` over 16 estimates at each of 16, 64, ..., 65 536 draws, on
/// log-log axes beside the slope -1/2 an unbiased estimator of finite variance follows. A
/// bias shows as the points levelling off. Written as `importance_convergence.svg` into
/// [`crate::check::pictures::failure_dir`]; `None` if it cannot be.
fn convergence(
    estimate: &Estimator,
    f: &dyn Fn(f64) -> f64,
    q: &Proposal,
    exact: f64,
    name: &str,
    rng: &mut Rng,
) -> Option<std::path::PathBuf> {
    let points: Vec<(f64, f64)> = (0..7)
        .map(|k| {
            let n = 16usize << (2 * k);
            let sum: f64 = (0..16)
                .map(|_| (estimate(f, q, n, rng).mean - exact).powi(2))
                .sum();
            (n as f64, (sum / 16.0).sqrt())
        })
        .collect();
    let title = format!("f = {name}, q: {}: the error of the estimate", q.name);
    let svg = crate::check::pictures::loglog_svg(
        &points,
        -0.5,
        [
            &title,
            "draws n",
            "root mean square of (estimate - integral), 16 estimates",
            "slope -1/2: an unbiased estimator",
        ],
    );
    crate::check::pictures::write("importance_convergence.svg", &svg)
}

/// Runs the chapter's claims on `estimate`; `options` sets the draws per estimate (default
/// [`SAMPLES`]), the seed (default [`SEED`]) and the t-tests' level.
pub fn estimator(estimate: &Estimator, options: &Options) -> Verdict {
    let n = options.cases_or(SAMPLES);
    let mut rng = rng::seeded(options.seed_or(SEED));
    let mut verdict = Verdict::new("importance-sampling estimator");

    let mut count = Finding::new("count", "n draws give a summary of n terms");
    for k in [1, 17, n.max(1)] {
        let s = estimate(&square, &UNIFORM, k, &mut rng);
        count.record(s.n == k as u64, || {
            format!("n = {k} draws gave {} terms", s.n)
        });
    }

    let mut unbiased = Finding::new(
        "unbiased",
        "mean of f(X)/q(X) = int f for q > 0 wherever f != 0 (one-sample t-test)",
    );
    let linear_plus_one = |x: f64| 1.0 + x;
    type Integrand<'a> = (&'a str, &'a dyn Fn(f64) -> f64, f64); // name, f, its integral
    let integrands: [Integrand; 2] = [
        ("x^2", &square, 1.0 / 3.0),
        ("1 + x", &linear_plus_one, 1.5),
    ];
    for (name, f, exact) in integrands {
        for q in [UNIFORM, LINEAR] {
            let s = estimate(f, &q, n, &mut rng);
            let p = ttest::one_sample(&s, exact).map_or(0.0, |t| t.p_value);
            if p < options.level() && unbiased.picture.is_none() {
                unbiased.picture = convergence(estimate, f, &q, exact, name, &mut rng)
                    .map(|path| path.display().to_string());
            }
            unbiased.record(p >= options.level(), || {
                format!(
                    "f = {name}, q: {}: mean {:.6} over {} terms where int f = {exact:.6} (p = {p:.3e})",
                    q.name, s.mean, s.n
                )
            });
        }
    }

    let mut matched = Finding::new(
        "zero_variance",
        "q proportional to f (q = 3x^2 for f = x^2): every term is I = 1/3",
    )
    .in_unit("multiples of eps / 3");
    let s = estimate(&square, &MATCHED, n.min(20_000), &mut rng);
    let unit = f64::EPSILON / 3.0;
    let error = (s.mean - 1.0 / 3.0).abs().max(s.variance().max(0.0).sqrt()) / unit;
    matched.measure(error, MATCHED_BOUND, || {
        format!(
            "mean {:e}, standard deviation {:e} of the terms (want 1/3 and 0)",
            s.mean,
            s.variance().max(0.0).sqrt()
        )
    });

    let mut zero = Finding::new(
        "zero_density",
        "a draw where q(X) = 0 adds a term of 0: counted, never skipped, never NaN or infinity",
    );
    let wrong_half = Proposal {
        name: "uniform draws, density 2 on [0, 1/2] and 0 above",
        sample: |u| u,
        pdf: HALF_SUPPORT.pdf,
    };
    let draws = n.min(20_000);
    let s = estimate(&square, &wrong_half, draws, &mut rng);
    let counted = s.n == draws as u64;
    zero.record(
        counted && s.first_non_finite().is_none() && s.mean.is_finite(),
        || {
            format!(
                "{}: {draws} draws gave {} terms; the summary holds {:?} (mean {})",
                wrong_half.name,
                s.n,
                s.first_non_finite(),
                s.mean
            )
        },
    );

    verdict.findings.extend([count, unbiased, matched, zero]);
    verdict
}
