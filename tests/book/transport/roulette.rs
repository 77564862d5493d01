//! Tests of the chapter *Russian roulette* (`src/transport/roulette.rs`).
//! t-tests run at `raylemma::stats::test_alpha()` (Šidák across the suite), fixed seeds;
//! each planted bug is a twin of a passing test that must be rejected.

use raylemma::rng::{self, Rng};
use raylemma::stats::test_alpha;
use raylemma::stats::ttest::{self, Summary};
use raylemma::transport::roulette::*;

const FURNACE: Furnace = Furnace {
    emission: 1.0,
    albedo: 0.5,
};

fn accepts(s: &Summary, mu: f64) -> bool {
    ttest::one_sample(s, mu).unwrap().p_value >= test_alpha()
}

fn report(s: &Summary, mu: f64) -> String {
    format!(
        "mean {} vs {mu} (p = {:.3e})",
        s.mean,
        ttest::one_sample(s, mu).unwrap().p_value
    )
}

/// `n` single-step estimates: F = U^2 (E[F] = 1/3, E[F^2] = 1/5) under roulette with `p`.
fn single_step(p: f64, divide: bool, n: usize, seed: u64) -> Summary {
    let mut r = rng::seeded(seed);
    Summary::of((0..n).map(|_| {
        let x = rng::uniform(&mut r, 0.0, 1.0);
        let f = x * x;
        let u = rng::uniform(&mut r, 0.0, 1.0);
        if divide {
            roulette(f, p, u)
        } else if u < p {
            f
        } else {
            0.0
        }
    }))
}

/// `n` furnace paths: (estimates, vertex counts).
fn paths(survival: Survival, divide: bool, n: usize, seed: u64) -> (Summary, Summary) {
    let mut r: Rng = rng::seeded(seed);
    let (mut est, mut verts) = (Summary::default(), Summary::default());
    for _ in 0..n {
        let (l, v) = furnace_path(&FURNACE, survival, divide, &mut r);
        est.push(l);
        verts.push(f64::from(v));
    }
    (est, verts)
}

#[test]
fn single_step_roulette_is_unbiased() {
    for (seed, p) in [(1, 0.1), (2, 0.3), (3, 0.7)] {
        let s = single_step(p, true, 400_000, seed);
        assert!(accepts(&s, 1.0 / 3.0), "p = {p}: {}", report(&s, 1.0 / 3.0));
    }
}

/// Var[F'] = E[F^2]/p - E[F]^2 = 1/(5p) - 1/9, measured within 3 % (the sample variance's
/// relative standard deviation is below 0.6 % at p = 0.1, where the kurtosis is about 31).
#[test]
fn single_step_variance_matches_the_formula() {
    for (seed, p) in [(4, 0.1), (5, 0.3), (6, 0.7), (7, 1.0)] {
        let s = single_step(p, true, 1_000_000, seed);
        let v = roulette_variance(1.0 / 3.0, 0.2, p);
        assert!(
            (s.variance() / v - 1.0).abs() < 0.03,
            "p = {p}: {} vs {v}",
            s.variance()
        );
    }
}

/// Planted bug: no division by p. The estimate converges to p E[F], not E[F].
#[test]
fn planted_single_step_without_division_is_rejected() {
    for (seed, p) in [(8, 0.3), (9, 0.7)] {
        let s = single_step(p, false, 400_000, seed);
        assert!(
            !accepts(&s, 1.0 / 3.0),
            "p = {p}: {}",
            report(&s, 1.0 / 3.0)
        );
        assert!(accepts(&s, p / 3.0), "p = {p}: {}", report(&s, p / 3.0));
    }
}

/// The seed's `u <= p` survives `u = 0` at `p = 0` and divides by zero; `u < p` does not.
#[test]
fn seed_comparison_divides_by_zero_at_p_zero() {
    assert!(!roulette_seed(1.0, 0.0, 0.0).is_finite());
    assert_eq!(roulette(1.0, 0.0, 0.0), 0.0);
    assert_eq!(roulette(1.0, 1.0, 0.999_999), 1.0);
}

/// Without roulette, a path cut after D bounces estimates L_e (1 - a^(D+1)) / (1 - a):
/// at D = 3, 1.875 instead of 2.
#[test]
fn fixed_depth_is_biased_by_the_missing_tail() {
    let (s, _) = paths(Survival::Depth(3), true, 200_000, 10);
    assert!(!accepts(&s, FURNACE.radiance()), "{}", report(&s, 2.0));
    let t = FURNACE.truncated(3);
    assert!((t - 1.875).abs() < 1e-15);
    assert!(accepts(&s, t), "{}", report(&s, t));
}

/// Roulette is unbiased on paths: Welch's test of each roulette estimator against the
/// deep fixed-depth estimator (D = 40, its missing tail a^41 L_e / (1 - a) added back),
/// and a one-sample test against the exact L_e / (1 - a) = 2. Mean vertex counts of the
/// fixed survivals are 1 / (1 - q).
#[test]
fn path_roulette_is_unbiased() {
    let depth = 40;
    let (deep, _) = paths(Survival::Depth(depth), true, 200_000, 11);
    let tail = FURNACE.radiance() - FURNACE.truncated(depth);
    let mut deep_plus_tail = deep;
    deep_plus_tail.mean += tail;
    let cases = [
        (12, Survival::Fixed(0.6)),
        (13, Survival::Fixed(0.8)),
        (14, Survival::Fixed(0.95)),
        (15, Survival::Throughput),
    ];
    for (seed, survival) in cases {
        let (s, v) = paths(survival, true, 200_000, seed);
        let w = ttest::welch(&s, &deep_plus_tail).unwrap();
        assert!(
            w.p_value >= test_alpha(),
            "{survival:?}: {} vs {} (Welch p = {:.3e})",
            s.mean,
            deep_plus_tail.mean,
            w.p_value
        );
        assert!(
            accepts(&s, FURNACE.radiance()),
            "{survival:?}: {}",
            report(&s, 2.0)
        );
        if let Survival::Fixed(q) = survival {
            let ev = expected_vertices(q);
            assert!(accepts(&v, ev), "{survival:?} vertices: {}", report(&v, ev));
        }
    }
}

/// Planted bug: no division by p on paths. With fixed q = 0.6 the estimate converges to
/// L_e / (1 - a q) = 1 / 0.7; Welch's test against the deep estimator rejects it, as it
/// rejects the throughput-based roulette without division.
#[test]
fn planted_path_without_division_is_rejected() {
    let (deep, _) = paths(Survival::Depth(40), true, 200_000, 16);
    for (seed, survival) in [(17, Survival::Fixed(0.6)), (18, Survival::Throughput)] {
        let (s, _) = paths(survival, false, 200_000, seed);
        let w = ttest::welch(&s, &deep).unwrap();
        assert!(
            w.p_value < test_alpha(),
            "{survival:?}: {} (p = {:.3e})",
            s.mean,
            w.p_value
        );
    }
    let (s, _) = paths(Survival::Fixed(0.6), false, 200_000, 19);
    let wrong = 1.0 / (1.0 - 0.5 * 0.6);
    assert!(accepts(&s, wrong), "{}", report(&s, wrong));
}

/// The path variance formula (L_e = 1, a = 1/2, E[w^2] = 1/3):
/// Var = (1/3 - q/4) / ((1/4)(q - 1/3)), measured within 5 % for q = 0.8 and 0.95.
#[test]
fn path_variance_matches_the_formula() {
    for (seed, q) in [(20, 0.8), (21, 0.95)] {
        let (s, _) = paths(Survival::Fixed(q), true, 400_000, seed);
        let v = path_variance(&FURNACE, q);
        let by_hand = (1.0 / 3.0 - q / 4.0) / (0.25 * (q - 1.0 / 3.0));
        assert!((v / by_hand - 1.0).abs() < 1e-12);
        assert!(
            (s.variance() / v - 1.0).abs() < 0.05,
            "q = {q}: {} vs {v}",
            s.variance()
        );
    }
    assert!(path_variance(&FURNACE, 1.0 / 3.0).is_infinite());
}
