//! Found by mutation testing.

use super::*;

/// The sampler's `integral` is the table's (trapezoids over the knots, computed here
/// independently of `Table::integral`).
#[test]
fn sampler_integral_is_the_tables() {
    for lamp in lamps() {
        let (nm, v) = (lamp.spectrum.wavelengths(), lamp.spectrum.values());
        let trapezoids: f64 = (1..nm.len())
            .map(|i| 0.5 * (v[i] + v[i - 1]) * (nm[i] - nm[i - 1]))
            .sum();
        let got = sampler(&lamp.spectrum).integral();
        assert!(
            (got / trapezoids - 1.0).abs() <= 1e-12,
            "{}: {got} vs {trapezoids}",
            lamp.name
        );
    }
}

/// Sampling `L (x̄ + ȳ + z̄)` makes the estimate of `X + Y + Z` nearly constant: the
/// weight `L (x̄+ȳ+z̄) / p` is the proposal's integral wherever the product is linear, and
/// only interpolation between the 1 nm knots makes it vary. A proposal that is not that
/// product (the planted `L + (x̄+ȳ+z̄)`) leaves it varying by tens of percent.
#[test]
fn colour_proposal_flattens_the_sum_of_x_y_z() {
    let spread = |proposal: &Table, lamp: &Table| {
        let s = sampler(proposal);
        let est: Vec<f64> = (0..10_000)
            .map(|i| {
                let w = s.sample((f64::from(i) + 0.5) / 10_000.0);
                xyz_estimate(lamp, w.nm, w.pdf).element_sum()
            })
            .collect();
        let mean = est.iter().sum::<f64>() / est.len() as f64;
        raylemma::check::max_abs(est.iter().map(|e| e / mean - 1.0))
    };
    for lamp in lamps() {
        let good = spread(&colour_proposal(&lamp.spectrum), &lamp.spectrum);
        assert!(good <= 0.05, "{}: X+Y+Z varies by {good}", lamp.name);
    }
    // The planted twin, on the incandescent lamp: the sum instead of the product.
    let lamp = &lamps()[1].spectrum;
    let nm = colour_proposal(lamp).wavelengths().to_vec();
    let values = nm
        .iter()
        .map(|&l| lamp.eval(l) + cie::cmf(l).element_sum())
        .collect();
    let sum = Table::new(nm, values).unwrap();
    let bad = spread(&sum, lamp);
    assert!(bad >= 0.2, "the sum proposal varies by only {bad}");
}

/// `write_lamp_images` writes one decodable drawing per lamp and returns its path.
#[test]
fn lamp_images_are_written_and_decode() {
    let dir = crate::support::scratch("lamps");
    let paths = write_lamp_images(&dir).unwrap();
    assert_eq!(paths.len(), lamps().len());
    for (path, lamp) in paths.iter().zip(lamps()) {
        assert_eq!(path, &dir.join(format!("{}.png", lamp.stem)));
        load_image(path).unwrap_or_else(|e| panic!("{e}"));
    }
    std::fs::remove_dir_all(&dir).unwrap();
}
