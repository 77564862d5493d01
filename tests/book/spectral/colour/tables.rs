//! Tables: evaluation at the edges, the colour-matching functions and their Wyman fit, and
//! the evenly spaced tables' shortcut against the binary search.

use super::*;

#[test]
fn table_eval_edge_cases() {
    let t = Table::new(vec![400.0, 500.0, 700.0], vec![0.1, 0.7, 0.3]).unwrap();
    // Knots exactly, including both ends.
    assert!(t.eval(400.0) == 0.1 && t.eval(500.0) == 0.7 && t.eval(700.0) == 0.3);
    // Linear in between: the midpoint of each segment.
    assert!((t.eval(450.0) - 0.4).abs() <= 1e-15);
    assert!((t.eval(600.0) - 0.5).abs() <= 1e-15);
    // Zero outside, at NaN and at the infinities; the next float beyond each end too.
    for nm in [
        399.999,
        700.001,
        f64::from_bits(400f64.to_bits() - 1),
        f64::from_bits(700f64.to_bits() + 1),
        f64::NAN,
        f64::INFINITY,
        f64::NEG_INFINITY,
    ] {
        assert!(t.eval(nm) == 0.0, "eval({nm}) = {}", t.eval(nm));
    }
    // A single segment.
    let s = Table::new(vec![500.0, 510.0], vec![2.0, 4.0]).unwrap();
    assert!(s.eval(500.0) == 2.0 && s.eval(510.0) == 4.0 && s.eval(505.0) == 3.0);
    assert!((s.integral() - 30.0).abs() <= 1e-12);
    // The last knot returns its value exactly for any values (the lerp form matters:
    // a + t (b − a) at t = 1 can miss b by an ulp).
    let mut r = rng::seeded(0xc01);
    for _ in 0..10_000 {
        let (a, b) = (
            rng::uniform(&mut r, 0.0, 1e3),
            rng::uniform(&mut r, 0.0, 1e-3),
        );
        let t = Table::new(vec![380.0, 381.0 + a], vec![a, b]).unwrap();
        assert!(t.eval(381.0 + a) == b && t.eval(380.0) == a);
    }
    // Bad tables are refused by the constructor too.
    assert!(Table::new(vec![400.0], vec![1.0]).is_err());
    assert!(Table::new(vec![400.0, 400.0], vec![1.0, 1.0]).is_err());
    assert!(Table::new(vec![400.0, 500.0], vec![1.0, -1.0]).is_err());
    assert!(Table::new(vec![400.0, 500.0], vec![1.0, f64::NAN]).is_err());
    assert!(Table::new(vec![400.0, 500.0], vec![1.0]).is_err());
}

#[test]
fn cmf_edge_cases() {
    assert!(cmf(LAMBDA_MIN) == cmf_row(0));
    assert!(cmf(LAMBDA_MAX) == cmf_row(CMF_ROWS - 1));
    assert!(cmf(555.0) == cmf_row(195));
    let mid = cmf(555.5);
    assert!((mid - 0.5 * (cmf_row(195) + cmf_row(196))).max_abs() <= 1e-15);
    for nm in [
        f64::from_bits(LAMBDA_MIN.to_bits() - 1),
        f64::from_bits(LAMBDA_MAX.to_bits() + 1),
        f64::NAN,
        f64::INFINITY,
        f64::NEG_INFINITY,
        -500.0,
    ] {
        assert!(cmf(nm) == DVec3::ZERO, "cmf({nm}) = {}", cmf(nm));
        assert!(
            cmf_fit(nm) == DVec3::ZERO,
            "cmf_fit({nm}) = {}",
            cmf_fit(nm)
        );
    }
    // A spectrum entirely outside 360-830 nm has no colour (and no chromaticity).
    assert!(xyz(|nm| if nm < 360.0 { 1.0 } else { 0.0 }) == DVec3::ZERO);
    assert!(chromaticity(DVec3::ZERO).is_none());
    assert!(chromaticity(DVec3::splat(f64::NAN)).is_none());
}

/// The Wyman-Sloan-Shirley fit: a few percent of the peak at worst (its paper's figure 2),
/// and a white that stays white to the third decimal. The measured numbers are in
/// `figures/colour_fit.md`.
#[test]
fn wyman_fit_is_close_to_the_table() {
    let mut worst: f64 = 0.0;
    for i in 0..=4700 {
        let nm = LAMBDA_MIN + 0.1 * f64::from(i);
        worst = nan_max_abs([worst, (cmf_fit(nm) - cmf(nm)).max_abs()]);
    }
    // z̄ peaks at 1.78: 0.03 is under 2 % of it.
    assert!(worst <= 0.03, "max |fit − table| = {worst}");
    // Each function within 1.5 % of its own peak (the chapter's sentence).
    for k in 0..3 {
        let (mut peak, mut err) = (0.0_f64, 0.0_f64);
        for i in 0..=4700 {
            let nm = LAMBDA_MIN + 0.1 * f64::from(i);
            peak = peak.max(cmf(nm)[k]);
            err = nan_max_abs([err, cmf_fit(nm)[k] - cmf(nm)[k]]);
        }
        assert!(
            err <= 0.015 * peak,
            "function {k}: {err} against the peak {peak}"
        );
    }
    assert!(
        (cmf_fit(555.0).y - 1.0).abs() <= 0.01,
        "ȳ_fit(555) = {}",
        cmf_fit(555.0).y
    );
    for (file, name, x, y, _) in PUBLISHED {
        let t = builtin(file);
        let c = chromaticity(xyz_with(cmf_fit, |nm| t.eval(nm))).unwrap();
        let err = (c - DVec2::new(x, y)).max_abs();
        assert!(err <= 3e-3, "{name} by the fit: {c}, error {err:.1e}");
    }
}

/// Planted bug: a fit lobe with its two widths swapped (the asymmetry is the point of the
/// paper). The table sees it.
#[test]
fn wyman_fit_rejects_swapped_widths() {
    let mut lobe = cie::FIT_Y[0];
    std::mem::swap(&mut lobe.inv_sigma_below, &mut lobe.inv_sigma_above);
    let mut worst: f64 = 0.0;
    for i in 0..=470 {
        let nm = LAMBDA_MIN + f64::from(i);
        let y = lobe.eval(nm) + cie::FIT_Y[1].eval(nm);
        worst = nan_max_abs([worst, y - cmf(nm).y]);
    }
    assert!(worst > 0.03, "swapped widths went unnoticed: {worst}");
}

#[test]
fn evenly_spaced_tables_find_their_segment_as_the_binary_search_does() {
    // Every built-in table, the two Cornell tables, and an unevenly spaced one: at every
    // knot, half-way between knots, just beside each knot, outside, and at random points,
    // the shortcut and the binary search give the same value to the last bit.
    let mut tables: Vec<Table> = raylemma::spectral::spectrum::BUILTIN
        .iter()
        .map(|(name, _)| builtin(name))
        .collect();
    tables.push(Table::new(vec![400.0, 401.5, 450.0, 700.0], vec![0.1, 0.5, 0.2, 0.9]).unwrap());
    let mut rng = raylemma::rng::seeded(0x7ab1e);
    for t in &tables {
        let nm = t.wavelengths();
        let mut points: Vec<f64> = Vec::new();
        for w in nm.windows(2) {
            points.extend([w[0], (w[0] + w[1]) / 2.0, w[0].next_down(), w[0].next_up()]);
        }
        let last = nm[nm.len() - 1];
        points.extend([
            last,
            last.next_down(),
            last.next_up(),
            nm[0] - 1.0,
            f64::NAN,
        ]);
        points.extend((0..2000).map(|_| raylemma::rng::uniform(&mut rng, 350.0, 850.0)));
        for x in points {
            let (fast, search) = (t.eval(x), t.eval_by_search(x));
            assert!(
                fast.to_bits() == search.to_bits(),
                "at {x} nm: {fast} against the binary search's {search}"
            );
        }
    }
}

#[test]
fn a_dense_table_is_the_same_function_read_by_index() {
    // Tables with whole-nanometre knots (the built-in ones, the Cornell box's): the dense
    // form agrees with the table to rounding everywhere, and is zero outside.
    use raylemma::spectral::spectrum::{Dense, WholeNm};
    let root = crate::support::root();
    let mut tables: Vec<Table> = raylemma::spectral::spectrum::BUILTIN
        .iter()
        .map(|(name, _)| builtin(name))
        .collect();
    for (_, t) in load_csv(&root.join("data/cornell_box_reflectance.csv")).unwrap() {
        tables.push(t);
    }
    let mut rng = raylemma::rng::seeded(0xde5e);
    for t in &tables {
        let d =
            Dense::of_table(t).unwrap_or_else(|| panic!("knots not whole: {:?}", t.wavelengths()));
        let (lo, hi) = (
            t.wavelengths()[0],
            t.wavelengths()[t.wavelengths().len() - 1],
        );
        let mut xs: Vec<f64> = (0..3000)
            .map(|_| raylemma::rng::uniform(&mut rng, 340.0, 850.0))
            .collect();
        xs.extend([
            lo,
            hi,
            lo.next_down(),
            hi.next_up(),
            (lo + hi) / 2.0,
            f64::NAN,
        ]);
        // Every knot, the points on either side of it, and far away.
        for &k in t.wavelengths() {
            xs.extend([k, k.next_down(), k.next_up(), k + 0.5]);
        }
        xs.extend([
            -0.0,
            -1.0,
            -1e300,
            1e300,
            3e9,
            f64::INFINITY,
            -f64::INFINITY,
        ]);
        for x in xs {
            let (a, b) = (d.eval(x), t.eval(x));
            // Rounding: the dense knots are the table's values at whole nanometres (each
            // a rounded interpolation), interpolated again.
            assert!(
                (a - b).abs() <= 8.0 * f64::EPSILON * b.abs().max(1.0),
                "at {x} nm: dense {a}, table {b}"
            );
            // The renderer's read, from the wavelength's split into whole nanometres: the
            // same bits (NaN-safe: to_bits of 0.0 and of a value).
            let w = WholeNm::of(x);
            assert!(x.is_nan() || w.nm - w.frac == w.whole as f64 || w.whole == i64::MIN);
            assert_eq!(
                d.eval_whole(w).to_bits(),
                a.to_bits(),
                "at {x} nm: eval_whole {} against eval {a}",
                d.eval_whole(w)
            );
        }
    }
    // A knot between whole nanometres has no dense form.
    let odd = Table::new(vec![400.0, 400.5, 401.0], vec![1.0, 2.0, 3.0]).unwrap();
    assert!(Dense::of_table(&odd).is_none());
}
