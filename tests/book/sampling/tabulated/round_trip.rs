//! Round trip: invert(sample(u)) = u.

use super::*;

/// `|invert(sample(u)) - u| <= 4 eps (1 + (|x_i| + |x_i+1|) p)`, where `p` is the largest
/// density in the bin: the rounding of `x` (about `eps |x|`) moves `u` by `p` times it.
#[test]
fn round_trip_within_bound() {
    let mut worst: f64 = 0.0;
    // Narrow bins far from 0 make the rounding of x matter.
    let narrow = Table {
        name: "narrow",
        edges: (0..=1000).map(|k| 550.0 + 1e-3 * f64::from(k)).collect(),
        values: (0..1000).map(|k| 1.0 + f64::from(k % 7)).collect(),
    };
    let mut rng = rng::seeded(40);
    for t in [smooth(), spiky(), with_zeros(), single_bin(), narrow] {
        let d = t.constant();
        let us: Vec<f64> = hard_us(d.cdf_table())
            .into_iter()
            .chain((0..20_000).map(|_| rng.random::<f64>()))
            .filter(|&u| u < 1.0)
            .collect();
        for u in us {
            let s = d.sample(u);
            let scale = 1.0 + (t.edges[s.bin].abs() + t.edges[s.bin + 1].abs()) * s.pdf;
            let err = (d.invert(s.x) - u).abs() / (f64::EPSILON * scale);
            worst = max_abs([worst, err]);
            assert!(
                err <= 4.0,
                "{}: u = {u:e}, {s:?}, error {err} units",
                t.name
            );
        }
    }
    for t in linear_tables().into_iter().chain([triangle()]) {
        let d = t.linear();
        for _ in 0..20_000 {
            let u = rng.random::<f64>();
            let s = d.sample(u);
            let p = d
                .pdf(t.edges[s.bin])
                .max(d.pdf(t.edges[s.bin + 1].next_down()));
            let scale = 1.0 + (t.edges[s.bin].abs() + t.edges[s.bin + 1].abs()) * p;
            let err = (d.invert(s.x) - u).abs() / (f64::EPSILON * scale);
            worst = max_abs([worst, err]);
            assert!(
                err <= 8.0,
                "{}: u = {u:e}, {s:?}, error {err} units",
                t.name
            );
        }
    }
    println!("worst round-trip error: {worst:.2} units");
}

#[test]
fn cdf_is_monotone_from_zero_to_one() {
    for t in [smooth(), spiky(), with_zeros(), single_bin()] {
        let d = t.constant();
        let (lo, hi) = (t.edges[0], t.edges[t.edges.len() - 1]);
        assert_eq!(
            (d.cdf(lo - 1.0), d.cdf(lo), d.cdf(hi), d.cdf(hi + 1.0)),
            (0.0, 0.0, 1.0, 1.0)
        );
        let xs: Vec<f64> = (0..=10_000)
            .map(|k| lo + (hi - lo) * f64::from(k) / 1e4)
            .collect();
        assert!(
            xs.windows(2).all(|w| d.cdf(w[0]) <= d.cdf(w[1])),
            "{}",
            t.name
        );
        for &x in &xs {
            assert!(
                (d.cdf(x) - t.cdf(false, x)).abs() <= 1e-13,
                "{} at {x}",
                t.name
            );
        }
    }
}
