//! The pdf: normalised, equal to the exact density, and what `sample` returns.

use super::*;

/// Gauss-Legendre, 3 points per cell: exact for the constant and linear pieces.
fn integrate(edges: &[f64], f: impl Fn(f64) -> f64) -> f64 {
    let (a, w) = ((0.6f64).sqrt(), [5.0 / 9.0, 8.0 / 9.0, 5.0 / 9.0]);
    edges
        .windows(2)
        .map(|e| {
            let (mid, half) = (0.5 * (e[0] + e[1]), 0.5 * (e[1] - e[0]));
            half * (w[0] * f(mid - a * half) + w[1] * f(mid) + w[2] * f(mid + a * half))
        })
        .sum()
}

/// Checks a pdf: integrates to 1 within `64 n epsilon`, and equals the exact density at
/// three points of every cell within `1e-12` relative. Returns the first failure.
fn pdf_problem(t: &Table, linear: bool, pdf: impl Fn(f64) -> f64) -> Option<String> {
    let integral = integrate(&t.edges, &pdf);
    let bound = 64.0 * t.edges.len() as f64 * f64::EPSILON;
    if (integral - 1.0).abs() > bound {
        return Some(format!("{}: the pdf integrates to {integral}", t.name));
    }
    for e in t.edges.windows(2) {
        for x in [e[0], 0.5 * (e[0] + e[1]), 0.9 * e[1] + 0.1 * e[0]] {
            let (got, want) = (pdf(x), t.density(linear, x));
            if (got - want).abs() > 1e-12 * want.max(1e-300) {
                return Some(format!("{}: pdf({x}) = {got}, exact {want}", t.name));
            }
        }
    }
    None
}

#[test]
fn pdf_integrates_to_one_and_matches_the_table() {
    for t in [smooth(), spiky(), with_zeros(), single_bin()] {
        let d = t.constant();
        assert_eq!(pdf_problem(&t, false, |x| d.pdf(x)), None);
    }
    for t in linear_tables().into_iter().chain([triangle()]) {
        let d = t.linear();
        assert_eq!(pdf_problem(&t, true, |x| d.pdf(x)), None);
    }
}

/// Planted bug: the pdf as the bin's probability, not divided by its width.
#[test]
fn pdf_without_bin_width_is_rejected() {
    let t = smooth();
    let d = t.constant();
    let bad = |x: f64| match t.edges.windows(2).position(|e| x >= e[0] && x < e[1]) {
        Some(i) => d.bin_probability(i),
        None => 0.0,
    };
    let problem = pdf_problem(&t, false, bad).expect("pdf without width accepted");
    assert!(problem.contains("integrates"), "{problem}");
}

/// Planted bug: the pdf of the table as given, not divided by its integral.
#[test]
fn unnormalised_pdf_is_rejected() {
    let t = spiky();
    let d = t.constant();
    let bad = |x: f64| d.pdf(x) * d.integral();
    assert!(pdf_problem(&t, false, bad).is_some());
}
