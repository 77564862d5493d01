//! The book's named values: every number the prose quotes and every comparison it claims,
//! recorded under a stable name by the figure code that computes it.
//!
//! The figure job (`tools/figures`) makes each output with a [`Record`]: as it formats a
//! table's cell it records the cell's number under a name (`r.number("exact.entering_ns",
//! ns, ".1")` returns the text the table prints, so the table and the book cannot disagree),
//! and beside the data it states each comparison a chapter makes as a named boolean with the
//! inputs it read (`r.claim("exact_slower_leaving", leaving > entering, read)`). The job
//! writes every output's record into one file, `figures/values.json` ([`Values`]), keyed by
//! the output's name without its extension (`fresnel_speed`).
//!
//! The book builder (`tools/book`) replaces `{{#value fresnel_speed.exact.entering_ns}}` by
//! the recorded text and fails the build on an unknown name or a `{{#claim NAME}}` that does
//! not hold, naming chapter, line and sentence. A renamed row or a changed comparison thus
//! breaks the figure job's compile or run, not a sentence at book-build time.
//!
//! Two rules carry over from the tables the values come from: a record of a timing output
//! names its machine (the fingerprint of its caption, [`fingerprint`]), and the book refuses
//! a sentence that quotes timings of two machines; a record made in `--quick` mode says so,
//! and the book only warns about its false claims.

use std::collections::BTreeMap;
use std::fmt::Write as _;
use std::path::Path;

use serde::{Deserialize, Serialize};

/// The name of the file, in `figures/`, that holds every record.
pub const FILE: &str = "values.json";

/// Every output's record, by the output's name without its extension.
pub type Values = BTreeMap<String, Entry>;

/// What one output recorded.
#[derive(Clone, Debug, Default, PartialEq, Serialize, Deserialize)]
pub struct Entry {
    /// The output file the values belong to, e.g. `fresnel_speed.md`.
    pub file: String,
    /// For a timing output, the fingerprint of the machine its caption names.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub machine: Option<String>,
    /// Made by a `--quick` run: noisy, not for quoting.
    #[serde(default, skip_serializing_if = "std::ops::Not::not")]
    pub quick: bool,
    /// The numbers and texts the book may quote.
    #[serde(default, skip_serializing_if = "BTreeMap::is_empty")]
    pub values: BTreeMap<String, Value>,
    /// The comparisons the book may claim.
    #[serde(default, skip_serializing_if = "BTreeMap::is_empty")]
    pub claims: BTreeMap<String, Claim>,
}

/// A quoted value: the text the book prints and, for a number, the number.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub struct Value {
    pub shown: String,
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub number: Option<f64>,
}

/// A claimed comparison: whether it holds, and what it read.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub struct Claim {
    pub holds: bool,
    pub read: String,
}

/// A name is lowercase words of `a-z`, `0-9` and `_`, joined by dots: `exact.entering_ns`.
pub fn valid_name(name: &str) -> bool {
    !name.is_empty()
        && name.split('.').all(|part| {
            !part.is_empty()
                && part
                    .bytes()
                    .all(|b| b.is_ascii_lowercase() || b.is_ascii_digit() || b == b'_')
        })
}

/// A label as one word of a value name: lowercase, every run of other characters one `_`
/// (`"floor under a quad light"` -> `floor_under_a_quad_light`, `"cornell-diffuse"` ->
/// `cornell_diffuse`).
pub fn slug(label: &str) -> String {
    let mut out = String::new();
    for c in label.chars() {
        if c.is_ascii_alphanumeric() {
            out.push(c.to_ascii_lowercase());
        } else if !out.is_empty() && !out.ends_with('_') {
            out.push('_');
        }
    }
    while out.ends_with('_') {
        out.pop();
    }
    out
}

/// The values of one output as its figure code makes it.
pub struct Record {
    entry: Entry,
    errors: Vec<String>,
}

impl Record {
    /// An empty record for the output `file`.
    pub fn new(file: &str) -> Record {
        Record {
            entry: Entry {
                file: file.to_string(),
                ..Entry::default()
            },
            errors: Vec::new(),
        }
    }

    /// The output this record is for.
    pub fn file(&self) -> &str {
        &self.entry.file
    }

    fn name_ok(&mut self, name: &str) -> bool {
        if !valid_name(name) {
            self.errors.push(format!(
                "{name:?} is not a value name (lowercase words of a-z, 0-9 and _, joined by dots)"
            ));
            return false;
        }
        if self.entry.values.contains_key(name) || self.entry.claims.contains_key(name) {
            self.errors.push(format!("{name:?} is recorded twice"));
            return false;
        }
        true
    }

    /// Records `x` under `name`, shown with `format` ([`format_number`]), and returns the
    /// shown text (for the table to print, so that table and book agree).
    pub fn number(&mut self, name: &str, x: f64, format: &str) -> String {
        let shown = match format_number(x, format) {
            Ok(s) => s,
            Err(e) => {
                self.errors.push(format!("{name}: {e}"));
                return format!("{x}");
            }
        };
        if self.name_ok(name) {
            self.entry.values.insert(
                name.to_string(),
                Value {
                    shown: shown.clone(),
                    number: x.is_finite().then_some(x),
                },
            );
        }
        shown
    }

    /// Records a text (a name, a verdict, a cell that is not a number) under `name`.
    pub fn text(&mut self, name: &str, shown: impl Into<String>) -> String {
        let shown = shown.into();
        if self.name_ok(name) {
            self.entry.values.insert(
                name.to_string(),
                Value {
                    shown: shown.clone(),
                    number: None,
                },
            );
        }
        shown
    }

    /// States the comparison `name`: whether it holds, and what it read (the inputs with
    /// their values, e.g. `"exact leaving 12.3 ns > exact entering 10.1 ns"`).
    pub fn claim(&mut self, name: &str, holds: bool, read: impl Into<String>) {
        if self.name_ok(name) {
            self.entry.claims.insert(
                name.to_string(),
                Claim {
                    holds,
                    read: read.into(),
                },
            );
        }
    }

    /// The finished entry (with the machine of a timing output's caption and the quick
    /// mark), or every mistake the figure code made in recording it.
    ///
    /// # Errors
    /// The names that were invalid or recorded twice, and formats that were unknown.
    pub fn finish(self, bytes: &[u8], quick: bool) -> Result<Entry, String> {
        if !self.errors.is_empty() {
            return Err(self.errors.join("; "));
        }
        let mut entry = self.entry;
        entry.machine = fingerprint(&String::from_utf8_lossy(bytes));
        entry.quick = quick;
        Ok(entry)
    }
}

/// The machine fingerprint a timing table's caption names (`fingerprint 1a2b3c4d`, from
/// `tools/figures/src/timing.rs`), if any.
pub fn fingerprint(text: &str) -> Option<String> {
    let at = text.find("fingerprint ")? + "fingerprint ".len();
    let hex: String = text[at..]
        .trim_start_matches('`')
        .chars()
        .take_while(char::is_ascii_hexdigit)
        .collect();
    (hex.len() == 8).then_some(hex)
}

/// `x` as text: `int` (no decimals), `.N` (N decimals), `sN` (N significant digits) or
/// `xN` (TeX scientific notation with N decimals, for use inside `$…$`).
///
/// # Errors
/// For another format.
pub fn format_number(x: f64, format: &str) -> Result<String, String> {
    let bad = || format!("unknown format {format:?} (int, .N, sN or xN)");
    let digits = |n: &str| n.parse::<usize>().map_err(|_| bad());
    if !x.is_finite() {
        return Ok(format!("{x}"));
    }
    let out = if format == "int" {
        format!("{x:.0}")
    } else if let Some(n) = format.strip_prefix('.') {
        format!("{x:.*}", digits(n)?)
    } else if let Some(n) = format.strip_prefix('s') {
        let n = digits(n)?.max(1);
        if x == 0.0 {
            "0".into()
        } else {
            let mut e = x.abs().log10().floor() as i32;
            let round = |e: i32| {
                let scale = 10f64.powi(e - n as i32 + 1);
                (x / scale).round() * scale
            };
            let mut rounded = round(e);
            // Rounding may carry into the next power of ten (0.99998 to 2 digits is 1.0).
            if rounded.abs() >= 10f64.powi(e + 1) {
                e += 1;
                rounded = round(e);
            }
            let decimals = (n as i32 - 1 - e).max(0) as usize;
            format!("{rounded:.decimals$}")
        }
    } else if let Some(n) = format.strip_prefix('x') {
        let s = format!("{x:.*e}", digits(n)?);
        let (m, e) = s.split_once('e').ok_or_else(bad)?;
        let e: i32 = e.parse().map_err(|_| bad())?;
        if e == 0 {
            m.to_string()
        } else {
            format!("{m}\\times10^{{{e}}}")
        }
    } else {
        return Err(bad());
    };
    Ok(out)
}

/// Reads `figures/values.json` from the figures folder `dir` (an empty set if there is none).
///
/// # Errors
/// If the file exists but cannot be read or is not a values file.
pub fn read(dir: &Path) -> Result<Values, String> {
    let path = dir.join(FILE);
    match std::fs::read_to_string(&path) {
        Ok(text) => serde_json::from_str(&text).map_err(|e| format!("{}: {e}", path.display())),
        Err(e) if e.kind() == std::io::ErrorKind::NotFound => Ok(Values::new()),
        Err(e) => Err(format!("{}: {e}", path.display())),
    }
}

/// The values file's text: pretty JSON, sorted by name, so that a change reviews as a diff.
pub fn to_json(values: &Values) -> String {
    let mut s = serde_json::to_string_pretty(values).unwrap_or_else(|_| "{}".into());
    let _ = writeln!(s);
    s
}

/// Looks up `key` (`OUTPUT.NAME`): its entry and its value or claim.
pub fn lookup<'v>(values: &'v Values, key: &str) -> Option<(&'v Entry, Found<'v>)> {
    let (output, name) = key.split_once('.')?;
    let entry = values.get(output)?;
    if let Some(v) = entry.values.get(name) {
        return Some((entry, Found::Value(v)));
    }
    entry.claims.get(name).map(|c| (entry, Found::Claim(c)))
}

/// What a name found.
#[derive(Debug)]
pub enum Found<'v> {
    Value(&'v Value),
    Claim(&'v Claim),
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn numbers_are_formatted() {
        assert_eq!(format_number(0.000050250, "s3").unwrap(), "0.0000503");
        assert_eq!(format_number(46.97, "s2").unwrap(), "47");
        assert_eq!(format_number(1234.5, "s2").unwrap(), "1200");
        assert_eq!(format_number(0.99998, "s2").unwrap(), "1.0");
        assert_eq!(format_number(-9.96, "s2").unwrap(), "-10");
        assert_eq!(format_number(-0.5, ".2").unwrap(), "-0.50");
        assert_eq!(format_number(45.4, "int").unwrap(), "45");
        assert_eq!(format_number(6.034e14, "x1").unwrap(), "6.0\\times10^{14}");
        assert_eq!(format_number(3.0, "x1").unwrap(), "3.0");
        assert_eq!(format_number(f64::NAN, ".2").unwrap(), "NaN");
        assert!(format_number(1.0, "q").is_err());
    }

    #[test]
    fn labels_become_name_words() {
        assert_eq!(slug("floor under a quad light"), "floor_under_a_quad_light");
        assert_eq!(slug("cornell-diffuse"), "cornell_diffuse");
        assert_eq!(slug("MIS, balance heuristic"), "mis_balance_heuristic");
        assert_eq!(slug("`lamps/amber-led` (2x)"), "lamps_amber_led_2x");
        assert!(valid_name(&slug("Ünïcode ok?")));
    }

    #[test]
    fn names_are_dotted_lowercase_words() {
        assert!(valid_name("exact.entering_ns"));
        assert!(valid_name("n2"));
        for bad in ["", "A", "a..b", ".a", "a.", "a-b", "a b"] {
            assert!(!valid_name(bad), "{bad:?}");
        }
    }

    #[test]
    fn a_record_keeps_what_the_table_prints_and_refuses_mistakes() {
        let mut r = Record::new("s.md");
        assert_eq!(r.number("exact.ns", 45.44, ".1"), "45.4");
        assert_eq!(r.text("winner", "`exact`"), "`exact`");
        r.claim("exact_faster", true, "45.4 < 50");
        let entry = r
            .finish(b"| a |\n*AMD EPYC (fingerprint `0a1b2c3d`).*", true)
            .unwrap();
        assert_eq!(entry.machine.as_deref(), Some("0a1b2c3d"));
        assert!(entry.quick);
        assert_eq!(entry.values["exact.ns"].number, Some(45.44));
        assert!(entry.claims["exact_faster"].holds);
        let mut r = Record::new("s.md");
        r.number("x", 1.0, ".1");
        r.number("x", 2.0, ".1");
        r.claim("Bad name", true, "");
        r.number("y", 1.0, "q");
        let err = r.finish(b"", false).unwrap_err();
        assert!(
            err.contains("\"x\" is recorded twice")
                && err.contains("\"Bad name\"")
                && err.contains("unknown format"),
            "{err}"
        );
    }

    #[test]
    fn the_file_reads_back_and_keys_find_values_and_claims() {
        let mut r = Record::new("s.md");
        r.number("a.b", 2.5, ".2");
        r.claim("c", false, "2.5 > 3");
        let mut values = Values::new();
        values.insert("s".into(), r.finish(b"", false).unwrap());
        let back: Values = serde_json::from_str(&to_json(&values)).unwrap();
        assert_eq!(back, values);
        // Every digit survives a read and a write (a values file rewritten by a run that
        // did not remake an output must not change that output's numbers).
        let mut r = Record::new("x.md");
        r.number("x", 3.8378906249999996, ".2");
        let mut odd = Values::new();
        odd.insert("x".into(), r.finish(b"", false).unwrap());
        let text = to_json(&odd);
        let again: Values = serde_json::from_str(&text).unwrap();
        assert_eq!(to_json(&again), text);
        assert_eq!(again["x"].values["x"].number, Some(3.8378906249999996));
        assert!(matches!(lookup(&back, "s.a.b"), Some((_, Found::Value(v))) if v.shown == "2.50"));
        assert!(matches!(lookup(&back, "s.c"), Some((_, Found::Claim(c))) if !c.holds));
        assert!(lookup(&back, "s.d").is_none() && lookup(&back, "t.a.b").is_none());
    }
}
