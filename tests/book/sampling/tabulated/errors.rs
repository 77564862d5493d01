//! Errors: every malformed table is refused with a message naming the entry.

use super::*;

fn err(edges: &[f64], values: &[f64]) -> TableError {
    Piecewise1D::new(edges, values).expect_err("malformed table accepted")
}

#[test]
fn malformed_tables_are_refused_with_a_named_entry() {
    let cases: Vec<(TableError, &str)> = vec![
        (err(&[0.0, 1.0, 2.0], &[0.0, 0.0]), "all 2 values are zero"),
        (
            err(&[0.0, 1.0, 2.0], &[1.0, -0.5]),
            "values[1] = -0.5 is negative",
        ),
        (
            err(&[0.0, 1.0, 2.0], &[f64::NAN, 1.0]),
            "values[0] = NaN is NaN",
        ),
        (
            err(&[0.0, 1.0, 2.0], &[1.0, f64::INFINITY]),
            "values[1] = inf is infinite",
        ),
        (
            err(&[0.0, 1.0, 1.0], &[1.0, 1.0]),
            "edges[2] = 1 is not greater than edges[1] = 1",
        ),
        (
            err(&[0.0, 2.0, 1.0], &[1.0, 1.0]),
            "edges[2] = 1 is not greater than edges[1] = 2",
        ),
        (
            err(&[0.0, f64::NAN], &[1.0]),
            "edges[1] = NaN is not finite",
        ),
        (err(&[0.0, 1.0, 2.0], &[1.0]), "1 values for 3 edges"),
        (err(&[0.0, 1.0], &[1.0, 1.0]), "2 values for 2 edges"),
        (err(&[0.0], &[]), "1 edges given"),
        (err(&[-1e308, 1e308], &[1.0]), "bin 0 from -1e308 to 1e308"),
        (
            err(&[0.0, 1.0, 2.0], &[1e308, 1e308]),
            "overflows f64 at bin 1",
        ),
    ];
    for (e, want) in cases {
        let message = e.to_string();
        assert!(
            message.contains(want),
            "{message:?} does not contain {want:?}"
        );
    }
    let e = PiecewiseLinear1D::new(&[0.0, 1.0, 2.0], &[1.0, 1.0]).unwrap_err();
    assert!(e.to_string().contains("2 values for 3 knots"), "{e}");
    let e = PiecewiseLinear1D::new(&[0.0, 1.0], &[0.0, -0.0]).unwrap_err();
    assert_eq!(e, TableError::AllZero { values: 2 });
    let boxed: Box<dyn std::error::Error> = Box::new(e);
    assert!(!boxed.to_string().is_empty());
}

/// The source's drawing: a column per integer wavelength from 380 to 830 nm, 450 px wide.
/// As bins `[l, l + 1)` that is 451 edges and 450 values, and fits; as samples at each
/// integer wavelength it is one short (451 knots need 451 values).
#[test]
fn seed_fencepost_450_columns_for_380_to_830_nm() {
    let edges: Vec<f64> = (380..=830).map(f64::from).collect();
    let columns = vec![1.0; 450];
    assert_eq!(edges.len(), 451);
    assert!(Piecewise1D::new(&edges, &columns).is_ok());
    let e = PiecewiseLinear1D::new(&edges, &columns).unwrap_err();
    assert!(e.to_string().contains("450 values for 451 knots"), "{e}");
}

/// "The pertinent quantity is the ratio of black pixels to white pixels": read literally,
/// a column with h black pixels of 256 gives h / (256 - h), not a density proportional
/// to the drawn height h. A sampler built from the ratio is rejected against the drawing.
#[test]
fn seed_black_to_white_ratio_is_not_the_drawn_density() {
    let edges: Vec<f64> = (0..=90).map(|k| 380.0 + 5.0 * f64::from(k)).collect();
    let heights: Vec<f64> = (0..90)
        .map(|k| (250.0 * (-((f64::from(k) - 40.0) / 18.0).powi(2)).exp()).round())
        .collect();
    let drawn = Table {
        name: "drawn heights",
        edges: edges.clone(),
        values: heights.clone(),
    };
    let ratio: Vec<f64> = heights.iter().map(|h| h / (256.0 - h)).collect();
    let d = Piecewise1D::new(&edges, &ratio).unwrap();
    assert_rejected(
        &drawn,
        false,
        &draw(50, N, |u| d.sample(u).x),
        "black/white ratio",
    );
}
