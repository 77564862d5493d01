//! The text of the protocol: numbers written so that they read back exactly, answers and
//! table rows split into fields, and CSV files read into numbered rows. Chapter: *Checks
//! from any language*.

use std::path::Path;

use crate::data::{DataError, read_text};

/// `x` written so that any language's `strtod`, `float()` or `parse` reads back the same
/// `f64`: the shortest decimal that round-trips, with an exponent for very small or large
/// magnitudes (`0.1`, `1.0`, `-0.0`, `1e-300`, `5e-324`).
pub(super) fn number_text(x: f64) -> String {
    format!("{x:?}")
}

/// The fields of an answer or a table row: separated by spaces, tabs or commas.
pub(crate) fn fields(line: &str) -> Vec<&str> {
    line.split(|c: char| c.is_whitespace() || c == ',')
        .filter(|s| !s.is_empty())
        .collect()
}

/// One field as a finite number; why not, otherwise (phrased to follow "the answer" or
/// "the row").
pub(crate) fn number(field: &str) -> Result<f64, String> {
    match field.parse::<f64>() {
        Ok(x) if x.is_finite() => Ok(x),
        Ok(_) => Err(format!("has `{field}`, which is not a finite number")),
        Err(_) => Err(format!("has `{field}`, which is not a number")),
    }
}

/// Exactly `N` finite numbers, or why not (`what` names them, e.g. "`x y z`").
pub(super) fn numbers<const N: usize>(fields: &[&str], what: &str) -> Result<[f64; N], String> {
    if fields.len() != N {
        return Err(format!(
            "should be {N} numbers {what}, but has {} field{}",
            fields.len(),
            if fields.len() == 1 { "" } else { "s" }
        ));
    }
    let mut out = [0.0; N];
    for (x, field) in out.iter_mut().zip(fields) {
        *x = number(field)?;
    }
    Ok(out)
}

/// A row of a CSV file: its line (from 1) and its fields.
pub(super) type Row = (usize, Vec<String>);

/// The rows of a CSV file: `(line, fields)` for every line that is not blank, not a
/// comment (starting with `#`), and not the header (a first row none of whose fields is a
/// number, such as `x,y,z`). Returns the file's name for messages too.
///
/// # Errors
/// A [`DataError`] if the file cannot be read, or has no row.
pub(super) fn csv_rows(path: &Path) -> Result<(String, Vec<Row>), DataError> {
    let (text, name) = read_text(path)?;
    let mut rows = Vec::new();
    let mut first = true;
    for (k, line) in text.lines().enumerate() {
        let line = line.trim();
        if line.is_empty() || line.starts_with('#') {
            continue;
        }
        let row: Vec<String> = fields(line).into_iter().map(String::from).collect();
        let header = first && row.iter().all(|f| f.parse::<f64>().is_err());
        first = false;
        if !header {
            rows.push((k + 1, row));
        }
    }
    if rows.is_empty() {
        return Err(DataError::new(&name, 0, "the file has no rows of numbers"));
    }
    Ok((name, rows))
}

/// `rows` as `&str` fields, for [`numbers`].
pub(super) fn as_strs(row: &[String]) -> Vec<&str> {
    row.iter().map(String::as_str).collect()
}
