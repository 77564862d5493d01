//! Šidák's correction.

use super::*;

#[test]
fn sidak_levels() {
    // One test: no correction.
    assert_rel(sidak(0.05, 1), 0.05, 1e-15);
    // 1 - 0.99^(1/100) = 1.004983e-4 (not the first-order -ln(0.99)/100 = 1.005034e-4).
    // References: 1 - exp(ln(0.99) / m) in 50-digit decimal arithmetic.
    assert_rel(sidak(0.01, 100), 1.004_983_082_416_679e-4, 1e-15);
    assert_rel(-(-0.01f64).ln_1p() / 100.0, 1.005_03e-4, 1e-5);
    // The suite's budget of 200: 1 - 0.99^(1/200) = 5.025042e-5, first-order 5.025168e-5.
    assert_rel(sidak(0.01, 200), 5.025_041_667_302_186e-5, 1e-15);
    assert_rel(-(-0.01f64).ln_1p() / 200.0, 5.025_168e-5, 1e-6);
    // The naive form 1 - (1 - alpha)^(1/m) subtracts from 1 a number within 1e-4 of it
    // and loses three to four of its sixteen digits.
    for (m, reference, lost) in [
        (100.0, 1.004_983_082_416_679e-4, 3e-14),
        (200.0, 5.025_041_667_302_186e-5, 3e-13),
    ] {
        let naive = 1.0 - 0.99f64.powf(1.0 / m);
        assert!(
            (naive / reference - 1.0).abs() > lost,
            "m = {m}: naive {naive:e}"
        );
    }
    assert_eq!(test_alpha(), sidak(SUITE_ALPHA, SUITE_TESTS));
    // Šidák lies between Bonferroni's alpha/m and -ln(1 - alpha)/m, for every m.
    for m in [1, 2, 10, 100, 1000, 1_000_000] {
        let a = sidak(SUITE_ALPHA, m);
        let mf = f64::from(m);
        assert!(
            SUITE_ALPHA / mf <= a && a <= -(-SUITE_ALPHA).ln_1p() / mf,
            "m = {m}: {a}"
        );
        // and it does what it claims: m tests at level a have family-wise level alpha.
        assert_rel(-(mf * (-a).ln_1p()).exp_m1(), SUITE_ALPHA, 1e-12);
    }
}
