//! Bad input.

use super::*;

/// Parses `text` as `bad.csv` and returns the error, which must name that file.
fn refuse(text: &str) -> raylemma::data::DataError {
    let e = parse_csv(text, "bad.csv").expect_err(&format!("accepted:\n{text}"));
    assert_eq!(e.file, "bad.csv");
    e
}

fn assert_refused(text: &str, line: usize, words: &str) {
    let e = refuse(text);
    assert!(
        e.line == line && e.problem.contains(words),
        "expected line {line} with {words:?}, got {e}\nfor:\n{text}"
    );
}

#[test]
fn csv_rows_with_bad_fields_are_refused_with_file_line_and_reason() {
    let h = "wavelength_nm,a,b\n";
    assert_refused(&format!("{h}400,1,2\n410,1\n"), 3, "missing field");
    assert_refused(&format!("{h}400,1,2\n410,1,2,3\n"), 3, "extra field");
    assert_refused(&format!("{h}400,1,2\n410,1,2,\n"), 3, "extra field");
    assert_refused(&format!("{h}400,1,2\n410,,2\n"), 3, "a: missing value");
    assert_refused(
        &format!("{h}400,1,2\n410,1,-0.5\n"),
        3,
        "b: -0.5 is negative",
    );
    assert_refused(&format!("{h}400,1,2\n410,NaN,2\n"), 3, "a: NaN");
    assert_refused(&format!("{h}400,1,2\n410,1,inf\n"), 3, "b: inf is infinite");
    assert_refused(&format!("{h}400,1,2\n-inf,1,2\n"), 3, "infinite");
    assert_refused(
        &format!("{h}400,1,2\n410,one,2\n"),
        3,
        "\"one\" is not a number",
    );
    assert_refused(&format!("{h}400,1,2\n410,1;2,2\n"), 3, "not a number");
    // Comments and blank lines are skipped but still counted.
    assert_refused(
        &format!("# a comment\n\n{h}400,1,2\n\n410,x,2\n"),
        6,
        "not a number",
    );
    // Windows line ends and a byte-order mark are fine.
    let ok = parse_csv("\u{feff}wavelength_nm,a\r\n400,1\r\n500,2\r\n", "ok.csv").unwrap();
    assert_eq!(ok[0].0, "a");
    assert!(ok[0].1.eval(450.0) == 1.5);
}

#[test]
fn csv_wavelength_problems_are_refused_with_file_line_and_reason() {
    let h = "wavelength_nm,v\n";
    assert_refused(&format!("{h}400,1\n410,1\n405,1\n"), 4, "405 nm is below");
    assert_refused(&format!("{h}400,1\n410,1\n410,2\n"), 4, "410 nm repeats");
    assert_refused(&format!("{h}0,1\n410,1\n"), 2, "not positive");
    assert_refused(&format!("{h}-10,1\n410,1\n"), 2, "not positive");
    // No overlap with 360-830 nm: the row nearest to the range is named.
    assert_refused(
        &format!("{h}200,1\n300,1\n360,1\n"),
        4,
        "do not overlap 360-830",
    );
    assert_refused(&format!("{h}830,1\n900,1\n"), 2, "do not overlap 360-830");
    assert_refused(&format!("{h}1000,1\n1100,1\n"), 2, "do not overlap");
    // Touching the range at one point is no overlap; one nanometre inside is.
    assert!(parse_csv(&format!("{h}300,1\n361,1\n"), "ok.csv").is_ok());
    // Too few rows.
    assert_refused(&format!("{h}400,1\n"), 2, "1 data rows");
    assert_refused(h, 1, "0 data rows");
}

#[test]
fn csv_header_problems_are_refused_with_file_line_and_reason() {
    assert_refused("", 0, "empty");
    assert_refused("\n# only a comment\n\n", 0, "empty");
    assert_refused("nm,v\n400,1\n500,1\n", 1, "must be \"wavelength_nm\"");
    assert_refused("400,1\n500,1\n", 1, "header line is missing");
    assert_refused("wavelength_nm\n400\n500\n", 1, "no value column");
    assert_refused(
        "wavelength_nm,v,v\n400,1,1\n500,1,1\n",
        1,
        "\"v\" appears twice",
    );
    assert_refused(
        "wavelength_nm,,v\n400,1,1\n500,1,1\n",
        1,
        "column 2 has no name",
    );
    assert_refused(
        "# x\nwavelength_nm;v\n400;1\n",
        2,
        "must be \"wavelength_nm\"",
    );
}

#[test]
fn missing_files_and_columns_are_refused() {
    let e = load_csv(std::path::Path::new("data/no_such_spectrum.csv")).unwrap_err();
    assert!(
        e.file.contains("no_such_spectrum.csv") && e.problem.contains("cannot read"),
        "{e}"
    );
    let tables = parse_csv("wavelength_nm,a,b\n400,1,2\n500,1,2\n", "two.csv").unwrap();
    let e = column(&tables, "c", "two.csv").unwrap_err();
    assert!(
        e.file == "two.csv" && e.problem.contains("no column \"c\"") && e.problem.contains("a, b"),
        "{e}"
    );
    // Every shipped file parses, and every built-in table is positive somewhere in range.
    for (file, text) in BUILTIN {
        let tables = parse_csv(text, file).unwrap_or_else(|e| panic!("{e}"));
        for (name, t) in tables {
            assert!(xyz(|nm| t.eval(nm)).y > 0.0, "{file}:{name} is black");
        }
    }
    let path = crate::support::root().join("data/cie_illuminant_A.csv");
    assert!(load_csv(&path).is_ok());
}
