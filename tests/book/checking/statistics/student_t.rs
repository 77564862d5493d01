//! Student t: published values.

use super::*;

#[test]
fn student_t_matches_nist_critical_values() {
    // NIST/SEMATECH e-Handbook, section 1.3.6.7.2, "Critical Values of the Student's t
    // Distribution" (upper-tail 0.025 and 0.005, i.e. two-sided 0.05 and 0.01).
    for (dof, alpha, critical) in [
        (10.0, 0.05, 2.228),
        (10.0, 0.01, 3.169),
        (30.0, 0.05, 2.042),
        (30.0, 0.01, 2.750),
        (100.0, 0.05, 1.984),
    ] {
        assert_rel(two_sided_p(critical, dof), alpha, 2e-3);
        assert_rel(two_sided_p(-critical, dof), alpha, 2e-3);
    }
}

#[test]
fn student_t_closed_forms_in_the_far_tail() {
    // dof 1 (Cauchy): p = (2/pi) atan(1/|t|); dof 2: p = 1 - |t| / sqrt(t² + 2).
    for t in [0.5f64, 3.0, 1e3, 1e6] {
        assert_rel(
            two_sided_p(t, 1.0),
            2.0 / std::f64::consts::PI * (1.0 / t).atan(),
            1e-10,
        );
        let s = (t * t + 2.0).sqrt();
        assert_rel(two_sided_p(t, 2.0), 2.0 / (s * (s + t)), 1e-10);
    }
    assert_eq!(two_sided_p(0.0, 5.0), 1.0);
    assert_eq!(two_sided_p(f64::INFINITY, 5.0), 0.0);
}

#[test]
fn one_sample_t_test_at_a_critical_value() {
    // Eleven values; choose mu0 so that t = 2.228 exactly with 10 dof.
    let xs: Vec<f64> = (0..11).map(|i| f64::from(i * i) / 7.0).collect();
    let s = Summary::of(xs.iter().copied());
    let mu0 = s.mean - 2.228 * s.std_error();
    let r = ttest::one_sample(&s, mu0).unwrap();
    assert_rel(r.t, 2.228, 1e-12);
    assert_eq!(r.dof, 10.0);
    assert_rel(r.p_value, 0.05, 2e-3);
}

#[test]
fn welch_by_hand() {
    // a = 1..=5 (mean 3, var 2.5), b = 2, 4, 6, 8 (mean 5, var 20/3).
    let a = Summary::of((1..=5).map(f64::from));
    let b = Summary::of([2.0, 4.0, 6.0, 8.0]);
    let r = welch(&a, &b).unwrap();
    let (va, vb): (f64, f64) = (2.5 / 5.0, 20.0 / 3.0 / 4.0);
    let dof = (va + vb) * (va + vb) / (va * va / 4.0 + vb * vb / 3.0);
    assert_rel(r.difference, -2.0, 1e-14);
    assert_rel(r.std_error, (va + vb).sqrt(), 1e-14);
    assert_rel(r.dof, dof, 1e-14);
    assert_rel(r.p_value, two_sided_p(-2.0 / (va + vb).sqrt(), dof), 1e-14);
}

#[test]
fn summary_is_welford_and_merges() {
    // Values near 1e9 with spread 1: the naive sum of squares would lose every digit.
    let xs: Vec<f64> = (0..1000).map(|i| 1e9 + f64::from(i % 10)).collect();
    let s = Summary::of(xs.iter().copied());
    assert_eq!(s.n, 1000);
    assert_rel(s.mean, 1e9 + 4.5, 1e-15);
    assert_rel(s.variance(), 8.25 * 1000.0 / 999.0, 1e-7);
    // The textbook one-pass formula (sum x² - n mean²) / (n - 1) is off by orders of magnitude.
    let naive = (xs.iter().map(|x| x * x).sum::<f64>() - 1000.0 * s.mean * s.mean) / 999.0;
    assert!(
        (naive / s.variance() - 1.0).abs() > 1.0,
        "naive variance {naive}"
    );
    // Merging two halves gives the summary of the whole.
    let (left, right) = xs.split_at(377);
    let merged = Summary::of(left.iter().copied()).merge(&Summary::of(right.iter().copied()));
    assert_eq!(merged.n, s.n);
    assert_rel(merged.mean, s.mean, 1e-15);
    assert_rel(merged.variance(), s.variance(), 1e-7);
    assert_eq!(Summary::default().merge(&s).n, s.n);
}

#[test]
fn zero_variance_is_decided_not_an_error() {
    let s = Summary::of([2.0; 5]);
    let same = ttest::one_sample(&s, 2.0).unwrap();
    assert_eq!((same.t, same.p_value), (0.0, 1.0));
    let other = ttest::one_sample(&s, 1.0).unwrap();
    assert_eq!((other.t, other.p_value), (f64::INFINITY, 0.0));
    let r = welch(&s, &Summary::of([3.0; 4])).unwrap();
    assert_eq!((r.t, r.p_value, r.dof), (f64::NEG_INFINITY, 0.0, 7.0));
    assert_eq!(welch(&s, &s).unwrap().p_value, 1.0);
}
