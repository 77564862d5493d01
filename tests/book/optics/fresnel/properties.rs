//! Properties over random inputs (quickcheck, fixed seeds).

use super::*;

#[derive(Clone, Debug)]
struct Interface {
    cos_i: f64,
    n1: f64,
    n2: f64,
}

impl Arbitrary for Interface {
    fn arbitrary(g: &mut Gen) -> Self {
        let index = |g: &mut Gen| 1.0 + f64::from(u16::arbitrary(g) % 30_000) / 10_000.0;
        Interface {
            cos_i: f64::from(u32::arbitrary(g) % 1_000_001) / 1_000_000.0,
            n1: index(g),
            n2: index(g),
        }
    }
}

fn quickcheck(seed: u64) -> QuickCheck {
    QuickCheck::new()
        .rng(Gen::from_size_and_seed(100, seed))
        .tests(5_000)
        .max_tests(50_000)
}

fn prop_energy_and_range(x: Interface) -> TestResult {
    let r = fresnel_polarized(x.cos_i, x.n1, x.n2);
    let t = fresnel_transmittance(x.cos_i, x.n1, x.n2);
    let cos_t = cos_transmitted(x.cos_i, x.n1, x.n2).unwrap_or(1.0);
    let unit = EPS * (1.0 + 1.0 / cos_t);
    let in_range = [r.s, r.p, t.s, t.p].iter().all(|v| (0.0..=1.0).contains(v));
    TestResult::from_bool(
        in_range
            && (r.s + t.s - 1.0).abs() <= 64.0 * unit
            && (r.p + t.p - 1.0).abs() <= 64.0 * unit,
    )
}

#[test]
fn quickcheck_energy_and_range() {
    quickcheck(21).quickcheck(prop_energy_and_range as fn(Interface) -> TestResult);
}

fn prop_approximations_in_range_and_exact_at_normal(x: Interface) -> bool {
    let fit = FresnelFit::new(x.n1, x.n2);
    let (s, f) = (schlick(x.cos_i, x.n1, x.n2), fit.eval(x.cos_i));
    (0.0..=1.0).contains(&s)
        && (0.0..=1.0).contains(&f)
        && (schlick(1.0, x.n1, x.n2) - r0(x.n1, x.n2)).abs() < 1e-15
        && (fit.eval(1.0) - r0(x.n1, x.n2)).abs() < 1e-14
}

#[test]
fn quickcheck_approximations() {
    quickcheck(22)
        .quickcheck(prop_approximations_in_range_and_exact_at_normal as fn(Interface) -> bool);
}
