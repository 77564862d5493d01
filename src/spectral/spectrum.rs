//! Spectra: what the scenes need and nothing more. Chapter: *Spectra and CIE colour*
//! (`chapters/spectral/colour.md`).
//!
//! A spectrum is a function of wavelength λ in nanometres. Three kinds cover every scene:
//!
//! * a [`Table`]: values at increasing wavelengths, linear between them and zero outside
//!   (measured reflectances, lamp and illuminant spectra, read from CSV files in `data/`);
//! * a blackbody, by Planck's law
//!   `B(λ, T) = 2hc² / λ⁵ / (exp(hc / (λ k T)) − 1)`;
//! * a constant.

use std::path::Path;

use crate::data::DataError;

/// Planck's constant, J s (exact in the SI since 2019).
pub const PLANCK_H: f64 = 6.626_070_15e-34;
/// The speed of light in vacuum, m/s (exact).
pub const LIGHT_C: f64 = 299_792_458.0;
/// Boltzmann's constant, J/K (exact).
pub const BOLTZMANN_K: f64 = 1.380_649e-23;
/// Wien's displacement constant b, m K: the peak of `B(λ, T)` is at `λ = b / T`.
pub const WIEN_B: f64 = 2.897_771_955e-3;

// ANCHOR: table
/// A piecewise-linear spectrum: `values[i]` at `nm[i]` (strictly increasing), linear in
/// between and zero outside `[nm[0], nm[n-1]]`.
#[derive(Clone, Debug, PartialEq)]
pub struct Table {
    nm: Vec<f64>,
    values: Vec<f64>,
    /// `1 / step` when the wavelengths are evenly spaced (as most measured tables are),
    /// so that [`Table::eval`] finds a segment by one multiplication instead of a binary
    /// search.
    inv_step: Option<f64>,
}

/// `1 / step` if the knots `nm` are evenly spaced (every step within `1e-9` of the first),
/// else `None`.
fn even_spacing(nm: &[f64]) -> Option<f64> {
    let step = nm[1] - nm[0];
    nm.windows(2)
        .all(|w| ((w[1] - w[0]) - step).abs() <= 1e-9 * step)
        .then_some(1.0 / step)
}

impl Table {
    /// A table from its wavelengths (nm) and values.
    ///
    /// # Errors
    /// If there are fewer than two points, the lengths differ, a number is not finite, a
    /// value is negative, or the wavelengths do not strictly increase. The message names
    /// the offending index.
    pub fn new(nm: Vec<f64>, values: Vec<f64>) -> Result<Self, String> {
        if nm.len() != values.len() {
            return Err(format!(
                "{} wavelengths but {} values",
                nm.len(),
                values.len()
            ));
        }
        if nm.len() < 2 {
            return Err(format!("{} points; a table needs at least 2", nm.len()));
        }
        for (i, (&l, &v)) in nm.iter().zip(&values).enumerate() {
            if !l.is_finite() || !v.is_finite() {
                return Err(format!("point {i}: ({l}, {v}) is not finite"));
            }
            if v < 0.0 {
                return Err(format!("point {i}: value {v} at {l} nm is negative"));
            }
            if i > 0 && l <= nm[i - 1] {
                return Err(format!(
                    "point {i}: wavelength {l} nm is not greater than the previous {} nm",
                    nm[i - 1]
                ));
            }
        }
        let inv_step = even_spacing(&nm);
        Ok(Table {
            nm,
            values,
            inv_step,
        })
    }

    /// The value at `nm`: linear interpolation, zero outside the table.
    pub fn eval(&self, nm: f64) -> f64 {
        let (first, last) = (self.nm[0], self.nm[self.nm.len() - 1]);
        // NaN fails both comparisons and is mapped to 0 like any wavelength outside.
        if !(nm >= first && nm <= last) {
            return 0.0;
        }
        // The first knot strictly above nm; nm == last lands in the final segment.
        let hi = self.segment_end(nm);
        let lo = hi - 1;
        let t = (nm - self.nm[lo]) / (self.nm[hi] - self.nm[lo]);
        // This form returns the knot values exactly at t = 0 and t = 1 (the last knot).
        (1.0 - t) * self.values[lo] + t * self.values[hi]
    }
    // ANCHOR_END: table

    /// The index of the first knot strictly above `nm` (at most the last one), for `nm`
    /// inside the table: the binary search's answer, `partition_point(|x| x <= nm)`. On
    /// evenly spaced knots it is computed from `(nm - nm[0]) / step` and then moved by one
    /// where rounding put it on the wrong side of a knot, so that both ways pick the same
    /// segment and give the same value to the last bit (a test checks it).
    fn segment_end(&self, nm: f64) -> usize {
        let n = self.nm.len();
        let Some(inv) = self.inv_step else {
            return self.nm.partition_point(|&x| x <= nm).min(n - 1);
        };
        let mut hi = (((nm - self.nm[0]) * inv) as usize + 1).min(n - 1);
        // Rounding can only put it one knot off.
        if hi > 1 && self.nm[hi - 1] > nm {
            hi -= 1;
        } else if hi < n - 1 && self.nm[hi] <= nm {
            hi += 1;
        }
        hi
    }

    /// [`Table::eval`] by the binary search alone, whatever the spacing (the form the
    /// even-spacing shortcut must agree with).
    pub fn eval_by_search(&self, nm: f64) -> f64 {
        let (first, last) = (self.nm[0], self.nm[self.nm.len() - 1]);
        if !(nm >= first && nm <= last) {
            return 0.0;
        }
        let hi = self.nm.partition_point(|&x| x <= nm).min(self.nm.len() - 1);
        let lo = hi - 1;
        let t = (nm - self.nm[lo]) / (self.nm[hi] - self.nm[lo]);
        (1.0 - t) * self.values[lo] + t * self.values[hi]
    }

    /// The wavelengths, nm.
    pub fn wavelengths(&self) -> &[f64] {
        &self.nm
    }

    /// The values.
    pub fn values(&self) -> &[f64] {
        &self.values
    }

    /// The same table with every value multiplied by `k ≥ 0`.
    pub fn scaled(&self, k: f64) -> Table {
        Table {
            nm: self.nm.clone(),
            inv_step: self.inv_step,
            values: self.values.iter().map(|v| v * k).collect(),
        }
    }

    /// The exact integral of the piecewise-linear function over its range (trapezoids).
    pub fn integral(&self) -> f64 {
        self.nm
            .windows(2)
            .zip(self.values.windows(2))
            .map(|(l, v)| 0.5 * (v[0] + v[1]) * (l[1] - l[0]))
            .sum()
    }
}

// ANCHOR: planck
/// Planck's law: the spectral radiance of a blackbody at `kelvin`, at wavelength `nm`, in
/// W sr⁻¹ m⁻² nm⁻¹. `exp_m1` keeps the denominator accurate far into the red, where
/// `hc / (λ k T)` is small.
/// A blackbody at `kelvin ≤ 0` emits nothing, and so does any wavelength `nm ≤ 0`; both
/// (and NaN) give 0.
///
/// Far into the blue (`x = hc/(λkT) > 700`) `e^x` is near its overflow at 709.78, past
/// which the quotient would be 0 while the radiance is still a double (down to 1e-308 at
/// `x ≈ 1490`): there `1/(e^x − 1) = e^{−x}/(1 − e^{−x})`, with `e^{−x}` applied as two
/// factors `e^{−x/2}` so that neither is subnormal before the last product.
pub fn planck(nm: f64, kelvin: f64) -> f64 {
    if !(nm > 0.0 && kelvin > 0.0) {
        return 0.0;
    }
    let l = nm * 1e-9;
    let x = PLANCK_H * LIGHT_C / (l * BOLTZMANN_K * kelvin);
    let a = 2.0 * PLANCK_H * LIGHT_C * LIGHT_C / l.powi(5);
    if x <= 700.0 {
        return a / x.exp_m1() * 1e-9;
    }
    let half = (-0.5 * x).exp();
    if half == 0.0 {
        // e^{−x} < 1e-647: below every double, whatever a (∞ once λ⁵ underflows).
        return 0.0;
    }
    a * half * 1e-9 * half / -(-x).exp_m1()
}
// ANCHOR_END: planck

/// Planck's law divided by its own maximum (at Wien's `λ = b / T`), so that the peak is 1.
/// Zero when there is no peak (`kelvin ≤ 0` or NaN).
pub fn planck_normalised(nm: f64, kelvin: f64) -> f64 {
    let peak = planck_peak(kelvin);
    if peak > 0.0 {
        planck(nm, kelvin) / peak
    } else {
        0.0
    }
}

/// The maximum of Planck's law at `kelvin`, `B(b / T, T)` (Wien's `λ = b / T`).
///
/// A renderer asks for it at every wavelength of every path, always at the same few
/// temperatures, so each thread keeps the last temperature's peak: the same value
/// [`planck`] returns, computed once instead of at every call.
fn planck_peak(kelvin: f64) -> f64 {
    thread_local! {
        static LAST: std::cell::Cell<(u64, f64)> = const { std::cell::Cell::new((u64::MAX, f64::NAN)) };
    }
    LAST.with(|last| {
        let (bits, peak) = last.get();
        if bits == kelvin.to_bits() {
            return peak;
        }
        let peak = planck(WIEN_B / kelvin * 1e9, kelvin);
        last.set((kelvin.to_bits(), peak));
        peak
    })
}

// ANCHOR: dense
/// A spectrum read by index: its values on every whole nanometre of `[lo, lo + n - 1]`,
/// linear in between and zero outside. A [`Table`] whose knots are all whole nanometres is
/// the same piecewise-linear function ([`Dense::of_table`]), read without a search: the
/// renderer keeps its materials' and lights' tables this way, and a test checks that the
/// two agree to rounding.
#[derive(Clone, Debug, PartialEq)]
pub struct Dense {
    /// The first knot, a whole number of nanometres.
    lo: i64,
    values: Vec<f64>,
}

impl Dense {
    /// The dense form of `t` if its knots are whole nanometres below [`WholeNm::LIMIT`]
    /// (else `None`).
    pub fn of_table(t: &Table) -> Option<Dense> {
        if t.nm
            .iter()
            .any(|x| x.fract() != 0.0 || x.abs() >= WholeNm::LIMIT)
        {
            return None;
        }
        let (lo, hi) = (t.nm[0], t.nm[t.nm.len() - 1]);
        let values = (0..=(hi - lo) as usize)
            .map(|i| t.eval(lo + i as f64))
            .collect();
        Some(Dense {
            lo: lo as i64,
            values,
        })
    }

    /// The value at `nm`: linear between the whole nanometres, zero outside.
    #[inline]
    pub fn eval(&self, nm: f64) -> f64 {
        // `lo` is a whole number below 2^31: converted exactly.
        let s = nm - self.lo as f64;
        let last = self.values.len() - 1;
        // NaN fails the comparison, as any wavelength outside.
        if !(s >= 0.0 && s <= last as f64) {
            return 0.0;
        }
        let i = (s as usize).min(last.saturating_sub(1));
        let t = s - i as f64;
        match self.values.get(i + 1) {
            Some(&next) => (1.0 - t) * self.values[i] + t * next,
            None => self.values[i],
        }
    }

    /// [`Dense::eval`] at `w.nm`, from its split into whole nanometres and the fraction
    /// beyond: the same value, bit for bit (a test checks it), with the wavelength's
    /// rounding down and its conversion to an index done once for every table it is
    /// read in. With `k = whole - lo`, the knot below is `k` and the weight of the one
    /// above is `frac`; `k = n - 1` (the last knot) counts only with `frac = 0`, where
    /// [`Dense::eval`] weights the last interval's upper end by `t = 1`.
    #[inline]
    pub fn eval_whole(&self, w: WholeNm) -> f64 {
        let last = self.values.len() as i64 - 1;
        let k = w.whole.saturating_sub(self.lo);
        if k < 0 || k > last || (k == last && w.frac > 0.0) {
            return 0.0;
        }
        // A table has two knots or more, so `last >= 1` and `0 <= i < last`. `k - i` is 1
        // only at the last knot (where `frac = 0`): `t` as `eval` has it.
        let i = k.min(last - 1);
        let t = (k - i) as f64 + w.frac;
        let i = i as usize;
        (1.0 - t) * self.values[i] + t * self.values[i + 1]
    }
}
// ANCHOR_END: dense

/// A wavelength, nm, with its split `nm = whole + frac` into whole nanometres and the
/// fraction beyond (`0 <= frac < 1`), both exact in `f64`: what reading a table on whole
/// nanometres by index needs ([`Dense::eval_whole`]), worked out once per wavelength
/// instead of once per table. A NaN or a wavelength
/// beyond `±2^31` nm gets a `whole` below every table (`i64::MIN`), so reads there are 0
/// as [`Dense::eval`]'s are.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct WholeNm {
    /// The wavelength itself.
    pub nm: f64,
    /// `floor(nm)`.
    pub whole: i64,
    /// `nm - floor(nm)`.
    pub frac: f64,
}

impl WholeNm {
    /// `2^31` nm: wavelengths split exactly (and dense tables' knots) lie below it.
    pub const LIMIT: f64 = 2_147_483_648.0;

    /// The split of `nm`.
    #[inline]
    pub fn of(nm: f64) -> Self {
        // NaN is not below the limit either.
        if nm.is_nan() || nm.abs() >= Self::LIMIT {
            return WholeNm {
                nm,
                whole: i64::MIN,
                frac: 0.0,
            };
        }
        let floor = nm.floor();
        WholeNm {
            nm,
            whole: floor as i64,
            frac: nm - floor,
        }
    }
}

/// A spectrum of a scene.
#[derive(Clone, Debug, PartialEq)]
pub enum Spectrum {
    /// The same value at every wavelength.
    Constant(f64),
    /// A measured table.
    Table(Table),
    /// A blackbody at `kelvin`, scaled so that its peak value is `peak`.
    Blackbody {
        /// Temperature, K.
        kelvin: f64,
        /// The value at the peak wavelength.
        peak: f64,
    },
}

impl Spectrum {
    /// The value at wavelength `nm`.
    pub fn eval(&self, nm: f64) -> f64 {
        match self {
            Spectrum::Constant(c) => *c,
            Spectrum::Table(t) => t.eval(nm),
            Spectrum::Blackbody { kelvin, peak } => peak * planck_normalised(nm, *kelvin),
        }
    }
}

// ---------------------------------------------------------------------------------------
// CSV tables.

/// The name of the wavelength column every spectrum CSV starts with.
pub(crate) const WAVELENGTH_COLUMN: &str = "wavelength_nm";

/// Parses a spectrum CSV: a header `wavelength_nm,<name>,<name>...`, then one row per
/// wavelength. Lines that are blank or start with `#` are skipped. Returns one named
/// [`Table`] per value column, in file order. `file` names the file in errors.
///
/// # Errors
/// With the line and reason: no header, a first column not called `wavelength_nm`, no
/// value column, a repeated column name, a row with a missing or extra field, an empty
/// field, a field that is not a number, a NaN or infinite number, a negative value, a
/// wavelength that is not positive, wavelengths that repeat or decrease, fewer than two
/// rows, or a range with no overlap with 360-830 nm (the colour-matching range; the
/// error points at the row nearest to it). Every case is a test in
/// `tests/book/spectral/colour/bad_input.rs`.
pub fn parse_csv(text: &str, file: &str) -> Result<Vec<(String, Table)>, DataError> {
    let err = |line: usize, problem: String| DataError::new(file, line, problem);
    let mut rows = text
        .lines()
        .enumerate()
        .map(|(k, l)| (k + 1, l.trim()))
        .filter(|(_, l)| !l.is_empty() && !l.starts_with('#'));
    let (header_line, header) = rows
        .next()
        .ok_or_else(|| err(0, "the file is empty: no header".into()))?;
    // A byte-order mark (left by some spreadsheet exports) is not part of the first name.
    let header = header.strip_prefix('\u{feff}').unwrap_or(header);
    let names: Vec<&str> = header.split(',').map(str::trim).collect();
    if names[0] != WAVELENGTH_COLUMN {
        let hint = if names[0].parse::<f64>().is_ok() {
            " (the header line is missing)"
        } else {
            ""
        };
        return Err(err(
            header_line,
            format!(
                "the first column is {:?}; it must be {WAVELENGTH_COLUMN:?}{hint}",
                names[0]
            ),
        ));
    }
    if names.len() < 2 {
        return Err(err(
            header_line,
            "no value column after wavelength_nm".into(),
        ));
    }
    for (i, n) in names.iter().enumerate() {
        if n.is_empty() {
            return Err(err(header_line, format!("column {} has no name", i + 1)));
        }
        if names[..i].contains(n) {
            return Err(err(header_line, format!("column {n:?} appears twice")));
        }
    }
    let columns = names.len() - 1;
    let mut nm: Vec<f64> = Vec::new();
    let mut values: Vec<Vec<f64>> = vec![Vec::new(); columns];
    let (mut first_line, mut last_line) = (0, header_line);
    for (line, row) in rows {
        if first_line == 0 {
            first_line = line;
        }
        last_line = line;
        let fields: Vec<&str> = row.split(',').map(str::trim).collect();
        if fields.len() != names.len() {
            let what = if fields.len() < names.len() {
                "missing field"
            } else {
                "extra field"
            };
            return Err(err(
                line,
                format!(
                    "{what}: {} fields; the header ({}) has {}",
                    fields.len(),
                    names.join(","),
                    names.len()
                ),
            ));
        }
        for (c, field) in fields.iter().enumerate() {
            if field.is_empty() {
                return Err(err(
                    line,
                    format!("{}: missing value (empty field)", names[c]),
                ));
            }
            let x: f64 = field
                .parse()
                .map_err(|_| err(line, format!("{}: {field:?} is not a number", names[c])))?;
            if x.is_nan() {
                return Err(err(line, format!("{}: NaN is not a value", names[c])));
            }
            if x.is_infinite() {
                return Err(err(line, format!("{}: {x} is infinite", names[c])));
            }
            if c == 0 {
                if x <= 0.0 {
                    return Err(err(line, format!("wavelength {x} nm is not positive")));
                }
                if let Some(&prev) = nm.last()
                    && x <= prev
                {
                    let how = if x == prev { "repeats" } else { "is below" };
                    return Err(err(
                        line,
                        format!(
                            "wavelength {x} nm {how} the previous {prev} nm; wavelengths must increase"
                        ),
                    ));
                }
                nm.push(x);
            } else {
                if x < 0.0 {
                    return Err(err(line, format!("{}: {x} is negative", names[c])));
                }
                values[c - 1].push(x);
            }
        }
    }
    if nm.len() < 2 {
        return Err(err(
            last_line,
            format!("{} data rows; a spectrum needs at least 2", nm.len()),
        ));
    }
    let (lo, hi) = (nm[0], nm[nm.len() - 1]);
    if lo.max(super::LAMBDA_MIN) >= hi.min(super::LAMBDA_MAX) {
        // Point at the row nearest to the colour-matching range.
        let line = if hi <= super::LAMBDA_MIN {
            last_line
        } else {
            first_line
        };
        return Err(err(
            line,
            format!(
                "the wavelengths {lo}-{hi} nm do not overlap {}-{} nm",
                super::LAMBDA_MIN,
                super::LAMBDA_MAX
            ),
        ));
    }
    Ok(names[1..]
        .iter()
        .zip(values)
        .map(|(n, v)| {
            let t = Table::new(nm.clone(), v).expect("rows were checked one by one");
            (n.to_string(), t)
        })
        .collect())
}

/// Reads and parses the spectrum CSV at `path` (see [`parse_csv`]).
///
/// # Errors
/// If the file cannot be read (line 0), or as [`parse_csv`].
pub fn load_csv(path: &Path) -> Result<Vec<(String, Table)>, DataError> {
    let (text, name) = crate::data::read_text(path)?;
    parse_csv(&text, &name)
}

/// The column `column` of a parsed file, or an error naming the columns there are.
///
/// # Errors
/// If there is no such column.
pub fn column(tables: &[(String, Table)], column: &str, file: &str) -> Result<Table, DataError> {
    tables
        .iter()
        .find(|(n, _)| n == column)
        .map(|(_, t)| t.clone())
        .ok_or_else(|| {
            let names: Vec<&str> = tables.iter().map(|(n, _)| n.as_str()).collect();
            DataError::new(
                file,
                0,
                format!("no column {column:?}; the file has {}", names.join(", ")),
            )
        })
}

// ANCHOR: builtin
/// The spectrum tables shipped in `data/`, embedded in the binary so that tests and
/// figures need no files at run time: `(file name, contents)`.
pub const BUILTIN: &[(&str, &str)] = &[
    (
        "cie_illuminant_A.csv",
        include_str!("../../data/cie_illuminant_A.csv"),
    ),
    (
        "cie_illuminant_D65.csv",
        include_str!("../../data/cie_illuminant_D65.csv"),
    ),
    (
        "cie_illuminant_F2.csv",
        include_str!("../../data/cie_illuminant_F2.csv"),
    ),
    (
        "cie_illuminant_F11.csv",
        include_str!("../../data/cie_illuminant_F11.csv"),
    ),
    (
        "cie_illuminant_HP1_high_pressure_sodium.csv",
        include_str!("../../data/cie_illuminant_HP1_high_pressure_sodium.csv"),
    ),
    (
        "cie_illuminant_LED_B3.csv",
        include_str!("../../data/cie_illuminant_LED_B3.csv"),
    ),
    (
        "lamp_cool_white_fluorescent.csv",
        include_str!("../../data/lamp_cool_white_fluorescent.csv"),
    ),
    (
        "lamp_high_pressure_sodium.csv",
        include_str!("../../data/lamp_high_pressure_sodium.csv"),
    ),
    (
        "lamp_incandescent.csv",
        include_str!("../../data/lamp_incandescent.csv"),
    ),
    (
        "lamp_low_pressure_sodium.csv",
        include_str!("../../data/lamp_low_pressure_sodium.csv"),
    ),
    (
        "lamp_phosphor_led_yag.csv",
        include_str!("../../data/lamp_phosphor_led_yag.csv"),
    ),
];
// ANCHOR_END: builtin

/// The first value column of the built-in table `file` (a name in [`BUILTIN`]).
///
/// # Panics
/// If there is no such file, or it is malformed (a defect of the build, caught by the tests).
pub fn builtin(file: &str) -> Table {
    let (_, text) = BUILTIN
        .iter()
        .find(|(n, _)| *n == file)
        .unwrap_or_else(|| panic!("no built-in spectrum {file:?}"));
    let mut tables = parse_csv(text, file).unwrap_or_else(|e| panic!("{e}"));
    tables.swap_remove(0).1
}
