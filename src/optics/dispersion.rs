//! Dispersion: the Sellmeier equation, a prism, and the rainbow.
//!
//! Chapter: *Dispersion* (`chapters/optics/dispersion.md`); tests: `tests/book/optics/dispersion.rs`.
//!
//! The Sellmeier coefficients live in `data/sellmeier.csv`, with their sources. They are
//! embedded in the library ([`catalogue`]) so that nothing depends on the working
//! directory, and can also be read from any file ([`load`]); both go through [`parse`],
//! which names the file, the line and the problem of any malformed row.
//!
//! Units: wavelengths are in nanometres at the interface (the renderer's unit), in
//! micrometres inside the Sellmeier formula (the catalogues' unit). Angles are in radians.

use std::f64::consts::PI;
use std::path::Path;
use std::sync::OnceLock;

/// The Sellmeier table, embedded at compile time.
pub const SELLMEIER_CSV: &str = include_str!("../../data/sellmeier.csv");

/// The name [`catalogue`] reports in errors about the embedded table.
pub const SELLMEIER_CSV_NAME: &str = "data/sellmeier.csv";

/// Material names of the embedded table.
pub const N_BK7: &str = "N-BK7";
/// Fused silica (Malitson 1965).
pub const FUSED_SILICA: &str = "fused silica";
/// Distilled water at 20 °C (Daimon & Masumura 2007).
pub const WATER: &str = "water";

/// The helium d line (nm), where catalogues quote `n_d`.
pub const LINE_D_NM: f64 = 587.5618;
/// The hydrogen F line (nm).
pub const LINE_F_NM: f64 = 486.1327;
/// The hydrogen C line (nm).
pub const LINE_C_NM: f64 = 656.2725;

/// The wavelength range the renderer samples (nm): 360–830 nm, where the CIE
/// colour-matching functions are tabulated (the source notes trace 380–830 nm).
pub const RENDER_RANGE_NM: (f64, f64) = (360.0, 830.0);

// ---------------------------------------------------------------------------------------
// The Sellmeier equation.

/// One material's Sellmeier fit.
#[derive(Clone, Debug, PartialEq)]
pub struct Sellmeier {
    /// The material's name, as in the table.
    pub name: String,
    /// The terms `(B_i, C_i)`, `C_i` in µm².
    pub terms: Vec<(f64, f64)>,
    /// The wavelength range of the fit (µm), `0 < min < max`.
    pub range_um: (f64, f64),
    /// Where the coefficients come from.
    pub source: String,
}

impl Sellmeier {
    // ANCHOR: sellmeier
    // EXERCISE optics/dispersion Sellmeier::index: the refractive index by the Sellmeier equation
    /// The refractive index at `wavelength_nm`:
    /// `n² = 1 + Σ B_i λ² / (λ² − C_i)`, λ in µm.
    ///
    /// Outside [`Self::range_um`] the formula is an extrapolation; below the shortest
    /// pole `n²` can turn negative and the result is NaN.
    ///
    /// Each term is evaluated as `B_i / (1 − C_i/λ²)`, the same quotient with λ² divided
    /// out: as accurate (chapter *Dispersion*, *Accuracy against exact arithmetic*), and
    /// still `B_i` where λ² overflows (λ above about 1.3e157 nm), where `B λ² / (λ² − C)`
    /// is ∞/∞ = NaN.
    pub fn index(&self, wavelength_nm: f64) -> f64 {
        let l2 = (wavelength_nm * 1e-3).powi(2);
        let n2 = 1.0
            + self
                .terms
                .iter()
                .map(|&(b, c)| b / (1.0 - c / l2))
                .sum::<f64>();
        n2.sqrt()
    }
    // END EXERCISE
    // ANCHOR_END: sellmeier

    /// True iff `wavelength_nm` lies in the range of the fit.
    pub fn covers(&self, wavelength_nm: f64) -> bool {
        let um = wavelength_nm * 1e-3;
        (self.range_um.0..=self.range_um.1).contains(&um)
    }

    /// The poles of the formula, `sqrt(C_i)`, in nm (resonance wavelengths).
    pub fn poles_nm(&self) -> Vec<f64> {
        self.terms.iter().map(|&(_, c)| 1e3 * c.sqrt()).collect()
    }

    // ANCHOR: abbe
    /// The Abbe number `V_d = (n_d − 1) / (n_F − n_C)`: large means little dispersion.
    pub fn abbe(&self) -> f64 {
        self.abbe_at(LINE_D_NM, LINE_F_NM, LINE_C_NM)
    }

    /// `(n(d) − 1) / (n(f) − n(c))` at any three wavelengths (nm), with neither
    /// difference taken of rounded indices: `n_F` and `n_C` agree to two or three digits,
    /// and subtracting them would lose those digits (up to 26 κ ulps at the catalogue's
    /// lines, water's, chapter *Dispersion*). Instead `n − 1 = (n² − 1)/(n + 1)` and
    /// `n_F − n_C = (n_F² − n_C²)/(n_F + n_C)`, whose numerator is summed term by term,
    /// `B_i λF²/(λF² − C_i) − B_i λC²/(λC² − C_i) = B_i C_i (λC² − λF²) / ((λF² − C_i)(λC² − C_i))`,
    /// with `λC² − λF² = (λC − λF)(λC + λF)` (exact difference when the two are within a
    /// factor 2).
    pub fn abbe_at(&self, d_nm: f64, f_nm: f64, c_nm: f64) -> f64 {
        let squared = |nm: f64| (nm * 1e-3).powi(2);
        let (ld, lf, lc) = (squared(d_nm), squared(f_nm), squared(c_nm));
        let excess: f64 = self.terms.iter().map(|&(b, k)| b / (1.0 - k / ld)).sum();
        let gap = (c_nm - f_nm) * (c_nm + f_nm) * 1e-6;
        let spread: f64 = self
            .terms
            .iter()
            .map(|&(b, k)| b * k * gap / ((lf - k) * (lc - k)))
            .sum();
        let n_d = (1.0 + excess).sqrt();
        let sum_fc = self.index(f_nm) + self.index(c_nm);
        excess / (n_d + 1.0) * sum_fc / spread
    }
    // ANCHOR_END: abbe
}

// ---------------------------------------------------------------------------------------
// The table and its parser.

pub use crate::data::DataError;

/// A set of Sellmeier fits, in file order.
#[derive(Clone, Debug, PartialEq)]
pub struct Catalogue {
    /// The materials.
    pub materials: Vec<Sellmeier>,
}

impl Catalogue {
    /// The material called `name`, if any.
    pub fn get(&self, name: &str) -> Option<&Sellmeier> {
        self.materials.iter().find(|m| m.name == name)
    }

    /// The material called `name`.
    ///
    /// # Panics
    /// If there is none (the message lists the names there are).
    pub fn material(&self, name: &str) -> &Sellmeier {
        self.get(name).unwrap_or_else(|| {
            let names: Vec<_> = self.materials.iter().map(|m| m.name.as_str()).collect();
            panic!("no material {name:?}; the table has {}", names.join(", "))
        })
    }
}

/// The columns of a Sellmeier table, in order.
pub const COLUMNS: [&str; 12] = [
    "material",
    "lambda_min_um",
    "lambda_max_um",
    "B1",
    "C1_um2",
    "B2",
    "C2_um2",
    "B3",
    "C3_um2",
    "B4",
    "C4_um2",
    "source",
];

/// Parses a Sellmeier table; `name` is the file name used in errors.
///
/// The format: `#` starts a comment line; blank lines are skipped; the first other line is
/// the header [`COLUMNS`]; each further line is one material. The source runs to the end
/// of the line (it may contain commas; one pair of surrounding double quotes is removed).
///
/// # Errors
/// The first problem found, with its line: a wrong header, a missing column, a field that
/// is not a number or not finite, a non-positive or empty wavelength range, a `B_i` without
/// its `C_i` (or the reverse), a negative `C_i`, a pole inside the fitted range, `n² ≤ 0`
/// inside the range, a repeated material, or no materials at all.
pub fn parse(text: &str, name: &str) -> Result<Catalogue, DataError> {
    let err = |line: usize, problem: String| DataError {
        file: name.to_string(),
        line,
        problem,
    };
    let mut materials: Vec<Sellmeier> = Vec::new();
    let mut header_seen = false;
    let mut last_line = 0;
    for (k, raw) in text.lines().enumerate() {
        let line = k + 1;
        last_line = line;
        let row = raw.trim();
        if row.is_empty() || row.starts_with('#') {
            continue;
        }
        if !header_seen {
            let got: Vec<&str> = row.split(',').map(str::trim).collect();
            if got != COLUMNS {
                return Err(err(
                    line,
                    format!("expected the header `{}`, found `{row}`", COLUMNS.join(",")),
                ));
            }
            header_seen = true;
            continue;
        }
        let fields: Vec<&str> = row.splitn(COLUMNS.len(), ',').map(str::trim).collect();
        if fields.len() < COLUMNS.len() {
            return Err(err(
                line,
                format!(
                    "missing column `{}` (found {} of {} columns)",
                    COLUMNS[fields.len()],
                    fields.len(),
                    COLUMNS.len()
                ),
            ));
        }
        let material = parse_row(&fields).map_err(|problem| err(line, problem))?;
        if materials.iter().any(|m| m.name == material.name) {
            return Err(err(
                line,
                format!("material `{}` appears twice", material.name),
            ));
        }
        materials.push(material);
    }
    if !header_seen {
        return Err(err(0, "no header line (the file is empty)".into()));
    }
    if materials.is_empty() {
        return Err(err(last_line, "no materials after the header".into()));
    }
    Ok(Catalogue { materials })
}

/// One row, already split into [`COLUMNS`]; the error is the problem in words.
fn parse_row(fields: &[&str]) -> Result<Sellmeier, String> {
    let name = fields[0];
    if name.is_empty() {
        return Err("column `material` is empty".into());
    }
    let number = |col: usize| -> Result<Option<f64>, String> {
        let text = fields[col];
        if text.is_empty() {
            return Ok(None);
        }
        let value: f64 = text
            .parse()
            .map_err(|_| format!("column `{}`: `{text}` is not a number", COLUMNS[col]))?;
        if !value.is_finite() {
            return Err(format!(
                "column `{}`: `{text}` is not a finite number",
                COLUMNS[col]
            ));
        }
        Ok(Some(value))
    };
    let required = |col: usize| -> Result<f64, String> {
        number(col)?.ok_or_else(|| format!("column `{}` is empty", COLUMNS[col]))
    };
    let (lo, hi) = (required(1)?, required(2)?);
    if lo <= 0.0 {
        return Err(format!("lambda_min_um must be positive, found {lo}"));
    }
    if hi <= lo {
        return Err(format!(
            "empty wavelength range: lambda_max_um {hi} is not above lambda_min_um {lo}"
        ));
    }
    let mut terms = Vec::new();
    for i in 0..4 {
        let (bc, cc) = (3 + 2 * i, 4 + 2 * i);
        match (number(bc)?, number(cc)?) {
            (None, None) => {}
            (Some(b), Some(c)) => {
                if c < 0.0 {
                    return Err(format!(
                        "column `{}`: C must be >= 0 (it is a squared wavelength), found {c}",
                        COLUMNS[cc]
                    ));
                }
                let pole = c.sqrt();
                if (lo..=hi).contains(&pole) {
                    return Err(format!(
                        "column `{}`: the pole at {pole} um lies inside the range {lo}..{hi} um",
                        COLUMNS[cc]
                    ));
                }
                terms.push((b, c));
            }
            (Some(_), None) => {
                return Err(format!(
                    "column `{}` is empty but `{}` is not",
                    COLUMNS[cc], COLUMNS[bc]
                ));
            }
            (None, Some(_)) => {
                return Err(format!(
                    "column `{}` is empty but `{}` is not",
                    COLUMNS[bc], COLUMNS[cc]
                ));
            }
        }
    }
    if terms.is_empty() {
        return Err("no Sellmeier term (B1 and C1 are empty)".into());
    }
    let source = fields[11];
    let source = source
        .strip_prefix('"')
        .and_then(|s| s.strip_suffix('"'))
        .unwrap_or(source);
    if source.is_empty() {
        return Err("column `source` is empty: every table names its source".into());
    }
    let material = Sellmeier {
        name: name.to_string(),
        terms,
        range_um: (lo, hi),
        source: source.to_string(),
    };
    // n² must stay positive over the fitted range (between poles it is continuous, so a
    // fine geometric grid finds any sign change a fit could plausibly have).
    for k in 0..=256 {
        let um = lo * (hi / lo).powf(f64::from(k) / 256.0);
        let n = material.index(um * 1e3);
        if !(n.is_finite() && n > 0.0) {
            return Err(format!(
                "n^2 is not positive at {um:.4} um, inside the fitted range"
            ));
        }
    }
    Ok(material)
}

/// Reads and parses the Sellmeier table at `path`.
///
/// # Errors
/// If the file cannot be read (line 0), or as [`parse`].
pub fn load(path: &Path) -> Result<Catalogue, DataError> {
    let (text, name) = crate::data::read_text(path)?;
    parse(&text, &name)
}

/// The embedded table ([`SELLMEIER_CSV`]), parsed once.
///
/// # Panics
/// If the embedded file is malformed: a defect of the build, caught by the tests.
pub fn catalogue() -> &'static Catalogue {
    static CATALOGUE: OnceLock<Catalogue> = OnceLock::new();
    CATALOGUE
        .get_or_init(|| parse(SELLMEIER_CSV, SELLMEIER_CSV_NAME).unwrap_or_else(|e| panic!("{e}")))
}

/// The embedded material called `name` (see [`N_BK7`], [`FUSED_SILICA`], [`WATER`]).
///
/// # Panics
/// If there is no such material.
pub fn material(name: &str) -> &'static Sellmeier {
    catalogue().material(name)
}

// ---------------------------------------------------------------------------------------
// A prism.

/// Which face of a prism a ray is totally reflected at.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Face {
    /// The face the ray enters by (possible only when the prism is less dense, `n < 1`).
    Entry,
    /// The face the ray should leave by.
    Exit,
}

/// What happens to a ray sent through a prism.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum PrismPath {
    /// The ray leaves by the second face.
    Through {
        /// The angle between the incoming and outgoing rays (rad).
        deviation: f64,
        /// The angle of the outgoing ray to the second face's normal (rad).
        exit: f64,
    },
    /// The ray is totally reflected inside (at the entry face only if `n < 1`).
    TotalInternalReflection {
        /// The face.
        face: Face,
        /// The angle of incidence on that face, from the denser side (rad).
        angle: f64,
        /// The critical angle of that face (rad); `angle` exceeds it.
        critical: f64,
    },
    /// Inside, the ray runs parallel to or away from the second face (`|A − θ2| ≥ π/2`): it
    /// never reaches it. Since `θ2 ≥ −asin(1/n)`, possible when `apex ≥ π/2 − asin(1/n)`
    /// (about 49° for N-BK7, so already for a 60° prism), for rays entering steeply from
    /// the apex side.
    MissesExitFace,
}

impl PrismPath {
    /// The deviation, if the ray gets through.
    pub fn deviation(&self) -> Option<f64> {
        match *self {
            Self::Through { deviation, .. } => Some(deviation),
            Self::TotalInternalReflection { .. } | Self::MissesExitFace => None,
        }
    }
}

// ANCHOR: prism
/// Traces a ray through a prism of apex angle `apex` and relative index `n` (prism over
/// surroundings), entering at `incidence` from the first face's normal, positive on the
/// side away from the apex (the usual drawing: the ray comes up from below the normal).
///
/// # Panics
/// If `n` is not positive, `apex` is not in `(0, π)`, or `|incidence| > π/2`.
pub fn prism(n: f64, apex: f64, incidence: f64) -> PrismPath {
    assert!(
        n > 0.0 && n.is_finite(),
        "prism index must be positive, got {n}"
    );
    assert!(
        apex > 0.0 && apex < PI,
        "apex angle must lie in (0, π), got {apex}"
    );
    assert!(
        incidence.abs() <= PI / 2.0,
        "incidence must lie in [-π/2, π/2], got {incidence}"
    );
    // First face: sin θ1 = n sin θ2.
    let s2 = incidence.sin() / n;
    if s2.abs() > 1.0 {
        return PrismPath::TotalInternalReflection {
            face: Face::Entry,
            angle: incidence.abs(),
            critical: n.asin(),
        };
    }
    let theta2 = s2.asin();
    // Inside, the two normals meet at the apex angle: θ2 + θ3 = A.
    let theta3 = apex - theta2;
    if theta3.abs() >= PI / 2.0 {
        return PrismPath::MissesExitFace;
    }
    // Second face: n sin θ3 = sin θ4.
    let s4 = n * theta3.sin();
    if s4.abs() > 1.0 {
        return PrismPath::TotalInternalReflection {
            face: Face::Exit,
            angle: theta3.abs(),
            critical: (1.0 / n).asin(),
        };
    }
    let exit = s4.asin();
    PrismPath::Through {
        deviation: incidence + exit - apex,
        exit,
    }
}
// ANCHOR_END: prism

// ANCHOR: min_deviation
/// The minimum deviation of a prism, from the symmetric path `θ2 = θ3 = A/2`:
/// `D_min = 2 asin(n sin(A/2)) − A`. `None` when no ray gets through (`n sin(A/2) > 1`).
pub fn minimum_deviation_analytic(n: f64, apex: f64) -> Option<f64> {
    let s = n * (apex / 2.0).sin();
    (s <= 1.0).then(|| 2.0 * s.asin() - apex)
}

/// The index a measured minimum deviation implies: `n = sin((A + D_min)/2) / sin(A/2)`.
pub fn index_from_minimum_deviation(apex: f64, d_min: f64) -> f64 {
    ((apex + d_min) / 2.0).sin() / (apex / 2.0).sin()
}
// ANCHOR_END: min_deviation

/// The smallest incidence at which a ray still gets through (it then leaves grazing the
/// second face), for `n > 1`; `None` if no ray gets through at all.
pub fn prism_limiting_incidence(n: f64, apex: f64) -> Option<f64> {
    let critical = (1.0 / n).asin();
    let s1 = n * (apex - critical).sin();
    (s1 <= 1.0).then(|| s1.asin())
}

/// The minimum deviation found numerically: golden-section search of [`prism`] over the
/// incidences that get through. Returns `(incidence, deviation)`; `None` if none does.
pub fn minimum_deviation_numeric(n: f64, apex: f64) -> Option<(f64, f64)> {
    let lo = prism_limiting_incidence(n, apex)?;
    let deviation = |i: f64| prism(n, apex, i).deviation().unwrap_or(f64::INFINITY);
    Some(golden_section_min(deviation, lo, PI / 2.0))
}

// ---------------------------------------------------------------------------------------
// The rainbow.

// ANCHOR: drop
/// The deviation of a ray through a spherical drop of relative index `n > 1` with one
/// internal reflection, entering at `incidence` to the surface normal:
/// `D = π + 2i − 4r` with `sin i = n sin r` (two refractions turn the ray by `i − r`
/// each, the reflection by `π − 2r`).
pub fn drop_deviation(n: f64, incidence: f64) -> f64 {
    let r = (incidence.sin() / n).asin();
    PI + 2.0 * incidence - 4.0 * r
}

/// The incidence of least deviation, from `dD/di = 0`: `cos² i = (n² − 1) / 3`.
/// Defined for `1 < n < 2`.
pub fn rainbow_incidence_analytic(n: f64) -> f64 {
    ((n * n - 1.0) / 3.0).sqrt().acos()
}

/// The primary bow's angular radius around the antisolar point, `π − D_min` (rad).
pub fn rainbow_angle(n: f64) -> f64 {
    PI - drop_deviation(n, rainbow_incidence_analytic(n))
}
// ANCHOR_END: drop

/// The least deviation found numerically (golden section over `[0, π/2]`), as
/// `(incidence, deviation)`, independent of the analytic condition.
pub fn rainbow_minimum_numeric(n: f64) -> (f64, f64) {
    golden_section_min(|i| drop_deviation(n, i), 0.0, PI / 2.0)
}

/// Golden-section search for the minimum of a unimodal `f` on `[a, b]`: returns
/// `(x, f(x))`. The bracket shrinks until it no longer changes in floating point; `x`
/// is then accurate to about `sqrt(ε)` of the scale, `f(x)` to about `ε`.
fn golden_section_min(f: impl Fn(f64) -> f64, mut a: f64, mut b: f64) -> (f64, f64) {
    let g = (5f64.sqrt() - 1.0) / 2.0;
    let mut c = b - g * (b - a);
    let mut d = a + g * (b - a);
    let (mut fc, mut fd) = (f(c), f(d));
    for _ in 0..200 {
        if fc < fd {
            b = d;
            d = c;
            fd = fc;
            c = b - g * (b - a);
            fc = f(c);
        } else {
            a = c;
            c = d;
            fc = fd;
            d = a + g * (b - a);
            fd = f(d);
        }
        if b - a <= 1e-15 * (a.abs() + b.abs()) {
            break;
        }
    }
    let x = 0.5 * (a + b);
    let fx = f(x);
    [(c, fc), (d, fd), (x, fx)]
        .into_iter()
        .min_by(|p, q| p.1.total_cmp(&q.1))
        .unwrap_or((x, fx))
}
