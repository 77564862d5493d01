//! Error paths: each returns the right error, whose message says what is wrong.

use super::*;

#[test]
fn pearson_errors() {
    let e = pearson(&[1, 2], &[1.5], 5.0).unwrap_err();
    assert!(
        matches!(
            e,
            StatsError::LengthMismatch {
                left: 2,
                right: 1,
                ..
            }
        ),
        "{e:?}"
    );
    assert!(matches!(
        pearson(&[], &[], 5.0),
        Err(StatsError::Empty { .. })
    ));
    assert!(matches!(
        pearson(&[0, 0], &[0.0, 0.0], 5.0),
        Err(StatsError::Empty { .. })
    ));

    let e = pearson(&[10, 10, 10], &[15.0, -1.0, 16.0], 5.0).unwrap_err();
    assert_eq!(
        e,
        StatsError::InvalidExpected {
            cell: 1,
            value: -1.0
        }
    );
    assert!(e.to_string().contains("cell 1"), "{e}");
    for bad in [f64::NAN, f64::INFINITY] {
        let e = pearson(&[10, 10], &[10.0, bad], 5.0).unwrap_err();
        assert!(
            matches!(e, StatsError::InvalidExpected { cell: 1, .. }),
            "{e:?}"
        );
    }

    // Samples in a cell where the pdf integrates to 0: a sampler leaking out of its domain.
    let e = pearson(&[50, 3, 47], &[50.0, 0.0, 50.0], 5.0).unwrap_err();
    assert_eq!(e, StatsError::SamplesWherePdfIsZero { cell: 1, count: 3 });
    assert_eq!(
        e.to_string(),
        "3 samples in cell 1 where the pdf integrates to 0"
    );

    // A pdf integrating to 2: expected counts twice the sample count.
    let e = pearson(&[50, 50], &[100.0, 100.0], 5.0).unwrap_err();
    match e {
        StatsError::NotNormalised { integral, .. } => assert_rel(integral, 2.0, 1e-15),
        _ => panic!("{e:?}"),
    }
    assert!(
        e.to_string().contains("integrates to 2.000000, not 1"),
        "{e}"
    );
    // Within 1e-3 N + 1 it is accepted (binning round-off); just outside it is not.
    assert!(pearson(&[500, 500], &[500.9, 500.0], 5.0).is_ok());
    assert!(pearson(&[500, 500], &[501.0, 501.1], 5.0).is_err());

    // Everything pooled into one cell: no degree of freedom left.
    let e = pearson(&[2, 1], &[1.5, 1.5], 5.0).unwrap_err();
    assert_eq!(
        e,
        StatsError::TooFewCells {
            cells: 1,
            min_expected: 5.0
        }
    );
    assert!(matches!(
        pearson(&[5, 5], &[5.0, 5.0], f64::NAN),
        Err(StatsError::InvalidArgument { .. })
    ));
}

#[test]
fn ks_errors() {
    let e = ks::one_sample(&[0.1, f64::NAN, 0.3], |x| x).unwrap_err();
    assert!(
        matches!(e, StatsError::NonFiniteSample { index: 1, .. }),
        "{e:?}"
    );
    assert!(e.to_string().contains("samples[1] is NaN"), "{e}");
    let e = ks::one_sample(&[0.1, 0.2, f64::INFINITY], |x| x).unwrap_err();
    assert!(
        matches!(e, StatsError::NonFiniteSample { index: 2, .. }),
        "{e:?}"
    );
    assert_eq!(
        ks::one_sample(&[], |x| x).unwrap_err(),
        StatsError::Empty { what: "samples" }
    );

    let e = ks::one_sample(&[0.5, 2.0], |x| x).unwrap_err();
    assert_eq!(e, StatsError::CdfOutOfRange { x: 2.0, value: 2.0 });
    let e = ks::one_sample(&[0.5], |_| f64::NAN).unwrap_err();
    assert!(
        matches!(e, StatsError::CdfOutOfRange { x: 0.5, .. }),
        "{e:?}"
    );
    let e = ks::one_sample(&[0.2, 0.1, 0.3], |x| 1.0 - x).unwrap_err();
    let (f0, f1) = (1.0 - 0.1, 1.0 - 0.2);
    assert_eq!(
        e,
        StatsError::CdfNotMonotone {
            x0: 0.1,
            f0,
            x1: 0.2,
            f1
        }
    );
    assert!(e.to_string().contains("decreases"), "{e}");

    let e = ks::two_sample(&[0.1, 0.2], &[0.3, f64::NEG_INFINITY]).unwrap_err();
    assert!(
        matches!(
            e,
            StatsError::NonFiniteSample {
                what: "sample b",
                index: 1,
                ..
            }
        ),
        "{e:?}"
    );
    assert!(matches!(
        ks::two_sample(&[], &[1.0]),
        Err(StatsError::Empty { what: "sample a" })
    ));
}

#[test]
fn t_test_errors() {
    let mut s = Summary::of([1.0, 2.0, 3.0]);
    s.push(f64::NAN);
    s.push(4.0);
    assert_eq!(s.n, 5);
    assert!(s.mean.is_nan() && s.variance().is_nan());
    let e = ttest::one_sample(&s, 2.0).unwrap_err();
    assert!(
        matches!(e, StatsError::NonFiniteSample { index: 3, .. }),
        "{e:?}"
    );
    assert!(e.to_string().contains("summary[3] is NaN"), "{e}");

    let good = Summary::of([1.0, 2.0, 3.0]);
    let e = welch(&good, &s).unwrap_err();
    assert!(
        matches!(
            e,
            StatsError::NonFiniteSample {
                what: "summary b",
                index: 3,
                ..
            }
        ),
        "{e:?}"
    );
    // Merging keeps the index of the first bad value, counted in the merged stream.
    let e = ttest::one_sample(&good.merge(&s), 0.0).unwrap_err();
    assert!(
        matches!(e, StatsError::NonFiniteSample { index: 6, .. }),
        "{e:?}"
    );

    let one = Summary::of([1.0]);
    let e = ttest::one_sample(&one, 0.0).unwrap_err();
    assert_eq!(
        e,
        StatsError::TooFewSamples {
            what: "summary",
            n: 1,
            needed: 2
        }
    );
    assert!(matches!(
        welch(&one, &good),
        Err(StatsError::TooFewSamples {
            what: "summary a",
            ..
        })
    ));
    assert!(matches!(
        ttest::one_sample(&Summary::default(), 0.0),
        Err(StatsError::TooFewSamples { n: 0, .. })
    ));
    assert!(matches!(
        ttest::one_sample(&good, f64::NAN),
        Err(StatsError::InvalidArgument { .. })
    ));
}
