//! Tests of the chapter *Dispersion* (`chapters/optics/dispersion.md`).
//!
//! Deterministic checks: catalogue values, closed forms against numerical minimisation,
//! an independent water formula (IAPWS R9-97, written out here), the parser's error paths
//! on small inline tables, and the hard cases (the ends of the render range, grazing and
//! totally reflected rays in a prism). No statistics are involved.

use raylemma::check::max_abs;
use std::f64::consts::{FRAC_PI_2, PI};
use std::path::Path;

use raylemma::optics::dispersion::{
    self as disp, Catalogue, DataError, FUSED_SILICA, Face, LINE_C_NM, LINE_D_NM, LINE_F_NM, N_BK7,
    PrismPath, RENDER_RANGE_NM, SELLMEIER_CSV, Sellmeier, WATER,
};

fn deg(x: f64) -> f64 {
    x.to_radians()
}

/// Wavelengths 360..=830 nm in steps of 1 nm.
fn render_range() -> impl Iterator<Item = f64> {
    (360..=830).map(f64::from)
}

// ---------------------------------------------------------------------------------------
// The table and its catalogue values.

/// SCHOTT optical glass datasheet N-BK7 (517642.251): n_d = 1.51680, n_F = 1.52238,
/// n_C = 1.51432, n_F − n_C = 0.008054, ν_d = 64.17. The datasheet prints five decimals of
/// n (two of ν_d), so the fit must reproduce each to half a unit of its last digit.
#[test]
fn n_bk7_matches_the_schott_datasheet() {
    let g = disp::material(N_BK7);
    let checks = [
        ("n_d", g.index(LINE_D_NM), 1.51680, 5e-6),
        ("n_F", g.index(LINE_F_NM), 1.52238, 5e-6),
        ("n_C", g.index(LINE_C_NM), 1.51432, 5e-6),
        (
            "n_F - n_C",
            g.index(LINE_F_NM) - g.index(LINE_C_NM),
            0.008054,
            5e-7,
        ),
        ("V_d", g.abbe(), 64.17, 0.005),
    ];
    for (what, got, want, tol) in checks {
        assert!(
            (got - want).abs() <= tol,
            "N-BK7 {what}: {got} vs datasheet {want} (tolerance {tol})"
        );
    }
}

/// Fused silica: Malitson (1965) tabulates n = 1.45846 at the d line (587.56 nm); the
/// catalogues of fused silica (e.g. Corning HPFS 7980, Heraeus Suprasil) print
/// n_d = 1.4585 and ν_d = 67.8. Tolerances: half a unit of the last printed digit.
#[test]
fn fused_silica_matches_malitson_and_the_catalogues() {
    let g = disp::material(FUSED_SILICA);
    let n_d = g.index(LINE_D_NM);
    assert!(
        (n_d - 1.45846).abs() <= 5e-6,
        "n_d {n_d} vs Malitson 1.45846"
    );
    assert!(
        (n_d - 1.4585).abs() <= 5e-5,
        "n_d {n_d} vs catalogue 1.4585"
    );
    let v = g.abbe();
    assert!((v - 67.8).abs() <= 0.05, "V_d {v} vs catalogue 67.8");
}

/// Malitson prints resonance wavelengths; the table stores their squares, exactly.
#[test]
fn malitson_c_are_the_squares_of_his_resonance_wavelengths() {
    let g = disp::material(FUSED_SILICA);
    let published = [0.0684043, 0.1162414, 9.896161];
    for (&(_, c), lambda) in g.terms.iter().zip(published) {
        let rel = (c - lambda * lambda).abs() / c;
        assert!(rel <= 1e-15, "C = {c} vs {lambda}^2: relative error {rel}");
    }
}

/// IAPWS R9-97 (Harvey, Gallagher & Levelt Sengers, J. Phys. Chem. Ref. Data 27, 761
/// (1998)): the refractive index of water from density, temperature and wavelength,
/// written out here independently of the table.
fn iapws_water(temperature_k: f64, density_kg_m3: f64, wavelength_nm: f64) -> f64 {
    let a = [
        0.244257733,
        9.74634476e-3,
        -3.73234996e-3,
        2.68678472e-4,
        1.58920570e-3,
        2.45934259e-3,
        0.900704920,
        -1.66626219e-2,
    ];
    let (uv, ir) = (0.2292020f64, 5.432937f64);
    let rho = density_kg_m3 / 1000.0;
    let t = temperature_k / 273.15;
    let l2 = (wavelength_nm / 589.0).powi(2);
    let rhs = rho
        * (a[0]
            + a[1] * rho
            + a[2] * t
            + a[3] * l2 * t
            + a[4] / l2
            + a[5] / (l2 - uv * uv)
            + a[6] / (l2 - ir * ir)
            + a[7] * rho * rho);
    ((2.0 * rhs + 1.0) / (1.0 - rhs)).sqrt()
}

/// The IAPWS formula reproduces its own check value (T = 298.15 K, ρ = 997.047435 kg/m³,
/// λ = 589.3 nm: n = 1.33285819), so the transcription above is right.
#[test]
fn iapws_transcription_reproduces_its_check_value() {
    let n = iapws_water(298.15, 997.047435, 589.3);
    assert!((n - 1.332_858_19).abs() < 1e-8, "{n}");
}

/// Daimon & Masumura's fit for water at 20 °C agrees with IAPWS R9-97 at 20 °C
/// (ρ = 998.2067 kg/m³) to 2e-5 over the whole render range.
#[test]
fn daimon_water_agrees_with_iapws() {
    let water = disp::material(WATER);
    let worst = max_abs(render_range().map(|l| water.index(l) - iapws_water(293.15, 998.2067, l)));
    assert!(worst <= 2e-5, "worst |Δn| = {worst}");
}

/// Handbooks print n_D(20 °C) = 1.33299 for water: an index relative to air. Times the
/// index of air at 589 nm and 20 °C (1.00027, Edlén) it is the vacuum-referenced 1.3333
/// of the fit, to 2e-5.
#[test]
fn handbook_water_index_is_relative_to_air() {
    let n = disp::material(WATER).index(589.29);
    assert!((1.33299 * 1.00027 - n).abs() <= 2e-5, "{n}");
    assert!((1.33299 - n).abs() > 3e-4, "{n}");
}

/// The seed: "Because I'm using the Sellmeier equations, everything should be able to
/// faithfully represent the wavelength dependent refraction behavior well into this range"
/// (380–830 nm). True of these fits: each fitted range covers the whole render range,
/// every pole lies outside it, and n is finite, above 1 and falls with wavelength (normal
/// dispersion) everywhere in 360–830 nm, ends included.
#[test]
fn seed_claim_sellmeier_holds_over_360_to_830_nm() {
    let (lo, hi) = RENDER_RANGE_NM;
    for g in &disp::catalogue().materials {
        assert!(
            g.covers(lo) && g.covers(hi),
            "{} range {:?}",
            g.name,
            g.range_um
        );
        for pole in g.poles_nm() {
            // NaN-safe: a NaN pole fails both comparisons.
            assert!(
                pole < lo || pole > hi,
                "{}: a pole of the Sellmeier sum at {pole} nm lies inside the rendered range",
                g.name
            );
        }
        // Finite, above 1 and falling (normal dispersion) at every nanometre, 360 and 830
        // included; finite and above 1 just inside the ends too.
        let mut previous = f64::INFINITY;
        for l in render_range() {
            let n = g.index(l);
            assert!(n.is_finite() && n > 1.0, "{} n({l}) = {n}", g.name);
            assert!(n < previous, "{} not normal at {l} nm", g.name);
            previous = n;
        }
        for l in [lo + 1e-9, hi - 1e-9] {
            let n = g.index(l);
            assert!(n.is_finite() && n > 1.0, "{} n({l}) = {n}", g.name);
        }
    }
}

/// Outside its range a fit is an extrapolation, and below the poles a meaningless one:
/// N-BK7's formula gives n = 1.84 at 100 nm (between the poles at 77 and 141 nm, a value
/// that looks plausible and is not) and NaN at 140 nm, where n² < 0. `covers` says so.
#[test]
fn below_the_poles_the_formula_is_meaningless() {
    let g = disp::material(N_BK7);
    let poles = g.poles_nm();
    assert!(
        (poles[0] - 77.5).abs() < 0.5 && (poles[1] - 141.5).abs() < 0.5,
        "{poles:?}"
    );
    assert!(!g.covers(100.0) && !g.covers(140.0));
    assert!((g.index(100.0) - 1.84).abs() < 0.005, "{}", g.index(100.0));
    assert!(g.index(140.0).is_nan());
}

/// The embedded table and the file on disk are the same table.
#[test]
fn embedded_table_equals_the_file() {
    let path = crate::support::root().join("data/sellmeier.csv");
    let from_file = disp::load(&path).unwrap_or_else(|e| panic!("{e}"));
    assert_eq!(&from_file, disp::catalogue());
    assert_eq!(
        std::fs::read_to_string(&path).ok().as_deref(),
        Some(SELLMEIER_CSV)
    );
    let names: Vec<_> = from_file
        .materials
        .iter()
        .map(|m| m.name.as_str())
        .collect();
    assert_eq!(names, [N_BK7, FUSED_SILICA, WATER]);
    assert!(from_file.materials.iter().all(|m| !m.source.is_empty()));
    assert_eq!(disp::material(WATER).terms.len(), 4);
}

// ---------------------------------------------------------------------------------------
// The parser's error paths: each names the file, the line and the problem.

const HEADER: &str =
    "material,lambda_min_um,lambda_max_um,B1,C1_um2,B2,C2_um2,B3,C3_um2,B4,C4_um2,source";
const GOOD_ROW: &str = "glass,0.3,2.5,1.0,0.006,0.2,0.02,1.0,100,,,a source, with a comma";

fn parse_err(rows: &str) -> DataError {
    let text = format!("# a comment\n{HEADER}\n{rows}\n");
    match disp::parse(&text, "inline.csv") {
        Ok(c) => panic!("parsed {c:?} from {text:?}"),
        Err(e) => e,
    }
}

#[track_caller]
fn assert_error(e: &DataError, line: usize, words: &str) {
    let text = e.to_string();
    assert_eq!(e.file, "inline.csv", "{text}");
    assert_eq!(e.line, line, "{text}");
    assert!(
        text.starts_with(&format!("inline.csv:{line}: ")) && text.contains(words),
        "{text:?} should name line {line} and say {words:?}"
    );
}

#[test]
fn parser_accepts_a_good_row_with_commas_in_the_source() {
    let text = format!("{HEADER}\n\n{GOOD_ROW}\n");
    let c: Catalogue = disp::parse(&text, "inline.csv").unwrap_or_else(|e| panic!("{e}"));
    let g: &Sellmeier = c.material("glass");
    assert_eq!(g.source, "a source, with a comma");
    assert_eq!(g.terms, vec![(1.0, 0.006), (0.2, 0.02), (1.0, 100.0)]);
    assert_eq!(g.range_um, (0.3, 2.5));
}

#[test]
fn parser_rejects_a_missing_column() {
    let e = parse_err("glass,0.3,2.5,1.0,0.006,0.2");
    assert_error(&e, 3, "missing column `C2_um2` (found 6 of 12 columns)");
}

#[test]
fn parser_rejects_a_field_that_is_not_a_number() {
    let e = parse_err(&GOOD_ROW.replace("0.006", "0.0O6"));
    assert_error(&e, 3, "column `C1_um2`: `0.0O6` is not a number");
}

#[test]
fn parser_rejects_nan_and_infinity() {
    let e = parse_err(&GOOD_ROW.replace(",0.2,", ",NaN,"));
    assert_error(&e, 3, "column `B2`: `NaN` is not a finite number");
    let e = parse_err(&GOOD_ROW.replace(",2.5,", ",inf,"));
    assert_error(&e, 3, "`lambda_max_um`: `inf` is not a finite number");
}

#[test]
fn parser_rejects_a_non_positive_wavelength_range() {
    let e = parse_err(&GOOD_ROW.replace("glass,0.3,", "glass,0,"));
    assert_error(&e, 3, "lambda_min_um must be positive, found 0");
    let e = parse_err(&GOOD_ROW.replace("glass,0.3,", "glass,-0.3,"));
    assert_error(&e, 3, "lambda_min_um must be positive");
    let e = parse_err(&GOOD_ROW.replace("glass,0.3,2.5,", "glass,2.5,0.3,"));
    assert_error(&e, 3, "empty wavelength range");
}

#[test]
fn parser_rejects_half_a_term_and_a_pole_inside_the_range() {
    let e = parse_err(&GOOD_ROW.replace(",100,", ",,"));
    assert_error(&e, 3, "column `C3_um2` is empty but `B3` is not");
    // C = 1 µm² puts a pole at 1 µm, inside 0.3..2.5 µm.
    let e = parse_err(&GOOD_ROW.replace(",0.02,", ",1,"));
    assert_error(&e, 3, "pole at 1 um lies inside");
    let e = parse_err(&GOOD_ROW.replace(",0.02,", ",-0.02,"));
    assert_error(&e, 3, "C must be >= 0");
}

#[test]
fn parser_rejects_a_wrong_header_a_duplicate_and_an_empty_table() {
    let e =
        disp::parse("# only comments\nmaterial,B1,C1\n", "inline.csv").expect_err("wrong header");
    assert_error(&e, 2, "expected the header");
    let e = parse_err(&format!("{GOOD_ROW}\n{GOOD_ROW}"));
    assert_error(&e, 4, "material `glass` appears twice");
    let e = disp::parse(&format!("{HEADER}\n# nothing\n"), "inline.csv").expect_err("empty");
    assert_error(&e, 2, "no materials");
    let e = disp::parse("", "inline.csv").expect_err("empty file");
    assert_eq!(
        e.to_string(),
        "inline.csv: no header line (the file is empty)"
    );
    let e = parse_err(&GOOD_ROW.replace("a source, with a comma", ""));
    assert_error(&e, 3, "column `source` is empty");
}

#[test]
fn loading_a_missing_file_names_it() {
    let e = disp::load(Path::new("/nonexistent/sellmeier.csv")).expect_err("missing file");
    let text = e.to_string();
    assert!(
        text.starts_with("/nonexistent/sellmeier.csv: cannot read the file"),
        "{text}"
    );
}

// ---------------------------------------------------------------------------------------
// The prism.

/// The numerical minimum of the deviation over the incidence angle equals the symmetric
/// path's closed form, and inverting it recovers n, to 1e-12 rad (and 1e-12 in n), for
/// N-BK7's indices and three apex angles.
#[test]
fn prism_minimum_deviation_matches_the_closed_form() {
    let g = disp::material(N_BK7);
    for apex in [deg(30.0), deg(45.0), deg(60.0)] {
        for l in [400.0, LINE_F_NM, LINE_D_NM, LINE_C_NM, 780.0] {
            let n = g.index(l);
            let (i_min, d_num) = disp::minimum_deviation_numeric(n, apex).expect("passes");
            let d_exact = disp::minimum_deviation_analytic(n, apex).expect("passes");
            assert!(
                (d_num - d_exact).abs() <= 1e-12,
                "A = {apex}, λ = {l}: numeric {d_num}, closed form {d_exact}"
            );
            // At the minimum the path is symmetric: exit angle = incidence.
            let PrismPath::Through { exit, .. } = disp::prism(n, apex, i_min) else {
                panic!("minimum-deviation ray reflected")
            };
            assert!(
                (exit - i_min).abs() <= 1e-6,
                "exit {exit} vs incidence {i_min}"
            );
            let n_back = disp::index_from_minimum_deviation(apex, d_exact);
            assert!((n_back - n).abs() <= 1e-12, "{n_back} vs {n}");
        }
    }
}

/// Blue is deviated more than red: at the d line's minimum-deviation incidence, the
/// deviation of a 60° N-BK7 prism falls monotonically from 400 to 780 nm.
#[test]
fn prism_deviation_falls_with_wavelength() {
    let g = disp::material(N_BK7);
    let apex = deg(60.0);
    let (i0, _) = disp::minimum_deviation_numeric(g.index(LINE_D_NM), apex).expect("passes");
    let devs: Vec<f64> = (400..=780)
        .step_by(5)
        .map(|l| {
            disp::prism(g.index(f64::from(l)), apex, i0)
                .deviation()
                .expect("passes")
        })
        .collect();
    assert!(devs.windows(2).all(|w| w[1] < w[0]), "{devs:?}");
}

/// The hard cases of the prism: grazing incidence (±90°) and every incidence in between,
/// at the ends of the render range. Each ray either gets through with a finite deviation
/// or is reported as totally reflected, with an angle beyond the critical one, or (entered
/// steeply from the apex side of a wide prism) as missing the second face — never NaN.
#[test]
fn prism_grazing_and_total_internal_reflection_are_reported_not_nan() {
    let mut misses = 0;
    for name in [N_BK7, FUSED_SILICA, WATER] {
        let g = disp::material(name);
        for l in [RENDER_RANGE_NM.0, RENDER_RANGE_NM.1] {
            let n = g.index(l);
            for apex in [deg(10.0), deg(60.0), deg(89.0)] {
                let limit = disp::prism_limiting_incidence(n, apex);
                for k in -1000..=1000 {
                    let incidence = FRAC_PI_2 * f64::from(k) / 1000.0;
                    match disp::prism(n, apex, incidence) {
                        PrismPath::Through { deviation, exit } => {
                            assert!(deviation.is_finite() && exit.is_finite());
                            assert!(
                                limit.is_some_and(|lim| incidence >= lim - 1e-12),
                                "{name} {l} nm, A = {apex}: {incidence} passes, limit {limit:?}"
                            );
                        }
                        PrismPath::TotalInternalReflection {
                            face,
                            angle,
                            critical,
                        } => {
                            assert_eq!(face, Face::Exit);
                            assert!(angle > critical && critical.is_finite());
                            assert!(limit.is_none_or(|lim| incidence <= lim + 1e-12));
                        }
                        PrismPath::MissesExitFace => {
                            // Only entered steeply from the apex side, when A ≥ 90° − θc.
                            assert!(incidence < 0.0 && apex >= FRAC_PI_2 - (1.0 / n).asin());
                            misses += 1;
                        }
                    }
                }
            }
        }
    }
    assert!(
        misses > 0,
        "the sweep should meet rays that miss the exit face"
    );
    // Exactly grazing incidence passes a 60° N-BK7 prism; normal incidence does not.
    let n = disp::material(N_BK7).index(LINE_D_NM);
    assert!(disp::prism(n, deg(60.0), FRAC_PI_2).deviation().is_some());
    assert!(matches!(
        disp::prism(n, deg(60.0), 0.0),
        PrismPath::TotalInternalReflection {
            face: Face::Exit,
            ..
        }
    ));
    // A prism less dense than its surroundings can reflect at the entry face.
    assert!(matches!(
        disp::prism(0.75, deg(30.0), deg(80.0)),
        PrismPath::TotalInternalReflection {
            face: Face::Entry,
            ..
        }
    ));
    // No ray gets through when n sin(A/2) > 1.
    assert!(disp::minimum_deviation_analytic(1.5, deg(89.0)).is_none());
    assert!(disp::minimum_deviation_numeric(1.5, deg(89.0)).is_none());
}

/// At the limiting incidence the ray leaves grazing the second face (exit = 90°), and
/// the deviation approaches that value continuously from the passing side.
#[test]
fn prism_limiting_incidence_leaves_grazing() {
    let n = disp::material(N_BK7).index(LINE_D_NM);
    let apex = deg(60.0);
    let lim = disp::prism_limiting_incidence(n, apex).expect("exists");
    let PrismPath::Through { exit, deviation } = disp::prism(n, apex, lim + 1e-12) else {
        panic!("just above the limit the ray should pass")
    };
    assert!((exit - FRAC_PI_2).abs() < 1e-5, "exit {exit}");
    assert!((deviation - (lim + FRAC_PI_2 - apex)).abs() < 1e-5);
}

// ---------------------------------------------------------------------------------------
// The rainbow.

/// Minimising D(i) = 180° + 2i − 4r numerically finds the incidence of the closed form
/// cos² i = (n² − 1)/3 (to 1e-7 rad, the accuracy of a minimiser), and the same minimum
/// deviation to 1e-13 rad, for indices across water's range and beyond.
#[test]
fn rainbow_minimum_matches_the_closed_form() {
    for k in 0..=40 {
        let n = 1.2 + 0.015 * f64::from(k);
        let (i_num, d_num) = disp::rainbow_minimum_numeric(n);
        let i_exact = disp::rainbow_incidence_analytic(n);
        let d_exact = disp::drop_deviation(n, i_exact);
        assert!(
            (i_num - i_exact).abs() <= 1e-7,
            "n {n}: i {i_num} vs {i_exact}"
        );
        assert!(
            (d_num - d_exact).abs() <= 1e-13,
            "n {n}: D {d_num} vs {d_exact}"
        );
        assert!(((PI - d_exact) - disp::rainbow_angle(n)).abs() <= 1e-15);
    }
}

/// The primary bow for n = 1.333 lies at 42.0°–42.1° from the antisolar point.
#[test]
fn rainbow_for_n_1_333_is_at_about_42_degrees() {
    let bow = disp::rainbow_angle(1.333).to_degrees();
    assert!((42.0..42.1).contains(&bow), "{bow}");
}

/// With water's dispersion (Daimon & Masumura, 20 °C), red is outside and violet inside:
/// 42.44° at 700 nm, 41.83° at 550 nm, 40.57° at 400 nm (to 0.01°), and the radius grows
/// monotonically with wavelength over the render range.
#[test]
fn rainbow_red_outside_violet_inside() {
    let water = disp::material(WATER);
    let bow = |l: f64| disp::rainbow_angle(water.index(l)).to_degrees();
    for (l, want) in [(700.0, 42.44), (550.0, 41.83), (400.0, 40.57)] {
        assert!(
            (bow(l) - want).abs() <= 0.01,
            "{l} nm: {} vs {want}",
            bow(l)
        );
    }
    let bows: Vec<f64> = render_range().map(bow).collect();
    assert!(bows.windows(2).all(|w| w[1] > w[0]));
    assert!(bows.iter().all(|b| b.is_finite()));
    // The band from 400 to 700 nm is 1.87° wide: almost four solar diameters (0.53°).
    let width = bow(700.0) - bow(400.0);
    assert!((width - 1.87).abs() <= 0.01, "{width}");
    // The round "42.3 degrees for red" of the textbooks is the bow at about 650 nm.
    assert!((bow(650.0) - 42.3).abs() <= 0.05, "650 nm: {}", bow(650.0));
}

// ---------------------------------------------------------------------------------------
// Exercises. Each scaffold is the student's to fill in; each ignored test checks it, and
// fails until it is done: `cargo test --test book optics::dispersion::exercise_ -- --ignored`.

/// Golden-section search for the minimum of a unimodal `f` on `[a, b]`, written here
/// independently of the library's: `(x, f(x))`.
fn golden_min(f: impl Fn(f64) -> f64, mut a: f64, mut b: f64) -> (f64, f64) {
    let g = (5f64.sqrt() - 1.0) / 2.0;
    for _ in 0..300 {
        let (c, d) = (b - g * (b - a), a + g * (b - a));
        if f(c) < f(d) {
            b = d;
        } else {
            a = c;
        }
    }
    let x = 0.5 * (a + b);
    (x, f(x))
}

/// The secondary bow's radius around the antisolar point, `D_min - 180°` (rad), from the
/// closed form `cos^2 i = (n^2 - 1)/8` and `D = 360° + 2i - 6r`, written here.
fn secondary_bow(n: f64) -> f64 {
    let i = ((n * n - 1.0) / 8.0).sqrt().acos();
    let r = (i.sin() / n).asin();
    2.0 * PI + 2.0 * i - 6.0 * r - PI
}

/// Exercise 1 of *Dispersion*: the deviation of a ray through a spherical drop of index
/// `n` with `k` internal reflections, entering at `incidence` (rad).
#[allow(unused_variables)]
fn your_drop_deviation_k(n: f64, incidence: f64, k: u32) -> f64 {
    unimplemented!("exercise 1 of Dispersion: the deviation with k internal reflections")
}

/// Exercise 1 of *Dispersion*: the secondary bow's radius around the antisolar point at
/// 550 nm (degrees), for water at 20 °C.
const YOUR_SECONDARY_BOW_AT_550_DEG: Option<f64> = None;

#[test]
#[ignore = "exercise 1 of Dispersion: fill in your_drop_deviation_k and YOUR_SECONDARY_BOW_AT_550_DEG, then run it"]
fn exercise_1_secondary_bow() {
    for k in 0..=40 {
        let n = 1.2 + 0.015 * f64::from(k);
        for i in [0.0, 0.3, 1.0, 1.5] {
            let (yours, primary) = (your_drop_deviation_k(n, i, 1), disp::drop_deviation(n, i));
            assert!(
                (yours - primary).abs() <= 1e-13,
                "n {n}, i {i}, k = 1: {yours} vs {primary}"
            );
        }
        let (i_num, d_num) = golden_min(|i| your_drop_deviation_k(n, i, 2), 0.0, FRAC_PI_2);
        let i_exact = ((n * n - 1.0) / 8.0).sqrt().acos();
        assert!(
            (i_num - i_exact).abs() <= 1e-7,
            "n {n}: minimum at {i_num}, closed form {i_exact}"
        );
        assert!(
            (d_num - PI - secondary_bow(n)).abs() <= 1e-13,
            "n {n}: D_min {d_num}"
        );
    }
    let water = disp::material(WATER);
    let bow = |l: f64| {
        let n = water.index(l);
        golden_min(|i| your_drop_deviation_k(n, i, 2), 0.0, FRAC_PI_2).1 - PI
    };
    // Colours the other way round: red inside, violet outside.
    assert!(bow(700.0) < bow(550.0) && bow(550.0) < bow(400.0));
    let expected = secondary_bow(water.index(550.0)).to_degrees();
    let yours =
        YOUR_SECONDARY_BOW_AT_550_DEG.expect("exercise 1: set YOUR_SECONDARY_BOW_AT_550_DEG");
    assert!(
        (yours - expected).abs() <= 0.01,
        "{yours}°, but the bow is at {expected}°"
    );
}

/// Exercise 2 of *Dispersion*: Cauchy's `n = a + b / lambda^2` fitted to N-BK7 at the F
/// and C lines, minus the Sellmeier fit, at 360 nm and at 830 nm.
const YOUR_CAUCHY_MINUS_SELLMEIER_AT_360_AND_830: Option<(f64, f64)> = None;

#[test]
#[ignore = "exercise 2 of Dispersion: set YOUR_CAUCHY_MINUS_SELLMEIER_AT_360_AND_830, then run it"]
fn exercise_2_cauchy() {
    let g = disp::material(N_BK7);
    let (f, c) = (LINE_F_NM * 1e-3, LINE_C_NM * 1e-3);
    let b = (g.index(LINE_F_NM) - g.index(LINE_C_NM)) / (1.0 / (f * f) - 1.0 / (c * c));
    let a = g.index(LINE_F_NM) - b / (f * f);
    let cauchy = |nm: f64| a + b / (nm * 1e-3).powi(2);
    let expected = (
        cauchy(360.0) - g.index(360.0),
        cauchy(830.0) - g.index(830.0),
    );
    let yours = YOUR_CAUCHY_MINUS_SELLMEIER_AT_360_AND_830
        .expect("exercise 2: set YOUR_CAUCHY_MINUS_SELLMEIER_AT_360_AND_830");
    assert!(
        (yours.0 - expected.0).abs() <= 1e-6 && (yours.1 - expected.1).abs() <= 1e-6,
        "{yours:?}, but Cauchy minus Sellmeier is {expected:?}"
    );
}

/// Exercise 3 of *Dispersion*: a row of `data/sellmeier.csv` for SCHOTT N-SF11, with the
/// coefficients and range of its datasheet, named `N-SF11`.
const YOUR_N_SF11_ROW: &str = "";

/// Exercise 3 of *Dispersion*: how many times wider N-SF11 spreads the F and C lines than
/// N-BK7, through 60° prisms at minimum deviation.
const YOUR_SPREAD_RATIO: Option<f64> = None;

#[test]
#[ignore = "exercise 3 of Dispersion: fill in YOUR_N_SF11_ROW and YOUR_SPREAD_RATIO, then run it"]
fn exercise_3_another_glass() {
    let text = format!("{HEADER}\n{YOUR_N_SF11_ROW}\n");
    let table = disp::parse(&text, "exercise.csv").unwrap_or_else(|e| panic!("{e}"));
    let g = table.material("N-SF11");
    // SCHOTT optical glass datasheet N-SF11 (785257.322): n_d = 1.78472, nu_d = 25.68.
    assert!(
        (g.index(LINE_D_NM) - 1.78472).abs() <= 5e-6,
        "n_d = {}",
        g.index(LINE_D_NM)
    );
    assert!((g.abbe() - 25.68).abs() <= 0.005, "V_d = {}", g.abbe());
    let spread = |m: &Sellmeier| {
        let d = |nm: f64| disp::minimum_deviation_analytic(m.index(nm), deg(60.0)).unwrap();
        d(LINE_F_NM) - d(LINE_C_NM)
    };
    let ratio = spread(g) / spread(disp::material(N_BK7));
    let yours = YOUR_SPREAD_RATIO.expect("exercise 3: set YOUR_SPREAD_RATIO");
    assert!(
        (yours - ratio).abs() <= 0.01,
        "{yours}, but the ratio is {ratio}"
    );
}

/// Exercise 4 of *Dispersion*: the width of Alexander's dark band at 550 nm (degrees),
/// between the primary and the secondary bow, for water at 20 °C.
const YOUR_DARK_BAND_AT_550_DEG: Option<f64> = None;

#[test]
#[ignore = "exercise 4 of Dispersion: set YOUR_DARK_BAND_AT_550_DEG, then run it"]
fn exercise_4_alexanders_dark_band() {
    let n = disp::material(WATER).index(550.0);
    let band = (secondary_bow(n) - disp::rainbow_angle(n)).to_degrees();
    let yours = YOUR_DARK_BAND_AT_550_DEG.expect("exercise 4: set YOUR_DARK_BAND_AT_550_DEG");
    assert!(
        (yours - band).abs() <= 0.01,
        "{yours}°, but the band is {band}° wide"
    );
}

/// Exercise 5 of *Dispersion*: the line of `data/sellmeier.csv` that the parser's error
/// names, and the column it blames, when N-BK7's `B1` is written `1,0` (a decimal comma).
const YOUR_ERROR_LINE_AND_COLUMN: Option<(usize, &str)> = None;

#[test]
#[ignore = "exercise 5 of Dispersion: set YOUR_ERROR_LINE_AND_COLUMN, then run it"]
fn exercise_5_a_broken_row() {
    let broken = SELLMEIER_CSV.replacen("N-BK7,0.3,2.5,1.03961212,", "N-BK7,0.3,2.5,1,0,", 1);
    assert_ne!(
        broken, SELLMEIER_CSV,
        "the embedded table has changed: update this test"
    );
    let e =
        disp::parse(&broken, disp::SELLMEIER_CSV_NAME).expect_err("a decimal comma must not parse");
    let (line, column) =
        YOUR_ERROR_LINE_AND_COLUMN.expect("exercise 5: set YOUR_ERROR_LINE_AND_COLUMN");
    let text = e.to_string();
    assert_eq!(e.line, line, "{text}");
    assert!(
        text.starts_with(&format!("{}:{line}: ", disp::SELLMEIER_CSV_NAME))
            && text.contains(&format!("`{column}`")),
        "{text}"
    );
}

// ---------------------------------------------------------------------------------------
// Accuracy against exact arithmetic (data/corpus/dispersion.txt, tools/exact).

/// The exact answer (as the double nearest it) of the corpus case asking `question`.
fn corpus_exact(question: &str) -> f64 {
    let root = crate::support::root();
    let corpus = raylemma::check::accuracy::corpus::load(&root.join("data/corpus/dispersion.txt"))
        .expect("the corpus reads");
    let case = corpus
        .cases
        .iter()
        .find(|c| c.question == question)
        .unwrap_or_else(|| panic!("no case `{question}` in the corpus"));
    case.exact.as_ref().expect("an answer")[0].double
}

/// The Abbe number used to subtract two rounded indices, `n_F − n_C`, which agree to two
/// or three digits: 183 ulps off for water at the catalogue's lines, where the problem's
/// condition number is 6.97 (26 times the claim's bound per unit of κ). `abbe_at` sums the
/// difference term by term and is within 2 ulps.
#[test]
fn abbe_number_keeps_the_digits_of_n_f_minus_n_c() {
    for (name, question) in [
        (WATER, "abbe_water 587.5618 486.1327 656.2725"),
        (N_BK7, "abbe_bk7 587.5618 486.1327 656.2725"),
        (FUSED_SILICA, "abbe_silica 587.5618 486.1327 656.2725"),
    ] {
        let exact = corpus_exact(question);
        let v = disp::material(name).abbe();
        let ulps = (v - exact).abs() / (exact.abs() * f64::EPSILON / 2.0);
        assert!(ulps <= 4.0, "{name}: V_d = {v}, exact {exact}: {ulps} ulps");
    }
}

/// Each Sellmeier term used to be `B λ²/(λ² − C)`, ∞/∞ = NaN once λ² overflows (λ above
/// about 1.3e157 nm); as `B/(1 − C/λ²)` it tends to `B`, and `n` to `sqrt(1 + Σ B_i)`.
#[test]
fn index_survives_an_overflowing_wavelength_square() {
    for (name, question) in [
        (N_BK7, "n_bk7 1e+160"),
        (FUSED_SILICA, "n_silica 1.7e+308"),
        (WATER, "n_water 1e+160"),
    ] {
        let nm: f64 = question.split(' ').nth(1).unwrap().parse().unwrap();
        let exact = corpus_exact(question);
        let n = disp::material(name).index(nm);
        assert!(
            (n - exact).abs() <= 2.0 * f64::EPSILON * exact,
            "{name}: n = {n}, exact {exact}"
        );
    }
}
