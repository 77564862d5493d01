//! The checker of the Sellmeier equation: any routine with the signature of
//! [`crate::optics::dispersion::Sellmeier::index`] (`f(&material, wavelength_nm)`) can be
//! checked against the claims of the chapter *Dispersion* (`chapters/optics/dispersion.md`).
//!
//! * `datasheet`: SCHOTT's N-BK7 (`n_d = 1.51680`, `n_F = 1.52238`, `n_C = 1.51432`) and
//!   Malitson's fused silica (`n_d = 1.45846`), each to half a unit of the last printed
//!   digit, from the published coefficients (built here, not read from `data/`);
//! * `vacuum`: no terms give `n = 1`;
//! * `one_term`: `B = 1, C = 0` gives `n = √2` at every wavelength;
//! * `micrometres`: a pole at 500 nm (`C = 0.25 µm²`) gives `n² = 1 + 4/3` at 1000 nm:
//!   the wavelength is converted to µm before it is squared;
//! * `normal_dispersion`: both glasses' indices fall with wavelength over 400–700 nm.
//!
//! Planted bugs that it must reject are in [`planted`].

pub mod planted;

use super::{Finding, Options, Verdict};
use crate::optics::dispersion::{LINE_C_NM, LINE_D_NM, LINE_F_NM, Sellmeier};

/// A material with the `terms` `(B_i, C_i)` (µm²), fitted over 0.3–2.5 µm.
pub fn material(name: &str, terms: &[(f64, f64)]) -> Sellmeier {
    Sellmeier {
        name: name.to_string(),
        terms: terms.to_vec(),
        range_um: (0.3, 2.5),
        source: "the checker".to_string(),
    }
}

/// SCHOTT N-BK7, the datasheet's B1–B3, C1–C3.
pub fn n_bk7() -> Sellmeier {
    material(
        "N-BK7",
        &[
            (1.039_612_12, 0.006_000_698_67),
            (0.231_792_344, 0.020_017_914_4),
            (1.010_469_45, 103.560_653),
        ],
    )
}

/// Fused silica, Malitson (1965): the squares of his resonance wavelengths 0.0684043,
/// 0.1162414 and 9.896161 µm, written out exactly.
pub fn fused_silica() -> Sellmeier {
    material(
        "fused silica",
        &[
            (0.696_166_3, 0.004_679_148_258_49),
            (0.407_942_6, 0.013_512_063_073_96),
            (0.897_479_4, 97.934_002_537_921),
        ],
    )
}

/// Default number of wavelengths of the dispersion claim.
pub const CASES: usize = 1_000;
/// Bound of the exact claims' errors, in units of `f64::EPSILON`.
pub const BOUND: f64 = 8.0;

/// Runs the chapter's claims on `f`; `options` sets the number of wavelengths of the
/// normal-dispersion claim (default [`CASES`]).
pub fn sellmeier(f: &dyn Fn(&Sellmeier, f64) -> f64, options: &Options) -> Verdict {
    let eps = f64::EPSILON;
    let mut datasheet = Finding::new(
        "datasheet",
        "N-BK7 and fused silica at the Fraunhofer lines, as published",
    )
    .in_unit("absolute error in n");
    let (bk7, silica) = (n_bk7(), fused_silica());
    for (glass, line, nm, want) in [
        (&bk7, "d", LINE_D_NM, 1.516_80),
        (&bk7, "F", LINE_F_NM, 1.522_38),
        (&bk7, "C", LINE_C_NM, 1.514_32),
        (&silica, "d", LINE_D_NM, 1.458_46),
    ] {
        let got = f(glass, nm);
        datasheet.measure((got - want).abs(), 5e-6, || {
            format!(
                "{} n_{line} ({nm} nm) = {got}, published {want}",
                glass.name
            )
        });
    }
    let mut vacuum = Finding::new("vacuum", "no terms: n = 1").in_unit("machine epsilons");
    let empty = material("vacuum", &[]);
    let mut one_term = Finding::new("one_term", "B = 1, C = 0: n = sqrt(2) at every wavelength")
        .in_unit("machine epsilons");
    let flat = material("flat", &[(1.0, 0.0)]);
    for nm in [360.0, 550.0, 830.0, 1500.0] {
        let got = f(&empty, nm);
        vacuum.measure((got - 1.0).abs() / eps, BOUND, || {
            format!("n({nm} nm) = {got}")
        });
        let got = f(&flat, nm);
        one_term.measure((got - 2f64.sqrt()).abs() / eps, BOUND, || {
            format!("n({nm} nm) = {got}")
        });
    }
    let mut micrometres = Finding::new(
        "micrometres",
        "C = 0.25 um^2 (a pole at 500 nm): n(1000 nm)^2 = 1 + 4/3",
    )
    .in_unit("machine epsilons");
    let pole = material("pole at 500 nm", &[(1.0, 0.25)]);
    let got = f(&pole, 1000.0);
    let want = (1.0 + 4.0 / 3.0_f64).sqrt();
    micrometres.measure((got - want).abs() / eps, BOUND, || {
        format!("n(1000 nm) = {got}, want {want}")
    });
    let mut normal = Finding::new(
        "normal_dispersion",
        "n falls with wavelength over 400-700 nm",
    );
    let n = options.cases_or(CASES).max(2);
    for glass in [&bk7, &silica] {
        for k in 0..n {
            let (a, b) = (
                400.0 + 300.0 * k as f64 / n as f64,
                400.0 + 300.0 * (k + 1) as f64 / n as f64,
            );
            let (na, nb) = (f(glass, a), f(glass, b));
            normal.record(nb < na, || {
                format!("{}: n({a} nm) = {na}, n({b} nm) = {nb}", glass.name)
            });
        }
    }
    let mut verdict = Verdict::new("Sellmeier index");
    verdict
        .findings
        .extend([datasheet, vacuum, one_term, micrometres, normal]);
    verdict
}
