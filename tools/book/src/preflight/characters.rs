//! Characters: no control character but the line feed in a chapter. A tab, a backspace or a
//! carriage return in prose is nearly always a TeX macro whose backslash an escape ate
//! (`\t` of `\times`, `\b` of `\bar`, `\r` of `\rho`), which the page then shows as
//! "imes", "ar" or "ho" with the math delimiters still balanced.

use std::path::Path;

use super::{Checker, Problem};

impl Checker {
    /// Every control character but `\n` is reported with its line and what it most likely
    /// was.
    pub(super) fn check_control_characters(
        &self,
        file: &Path,
        text: &str,
        problems: &mut Vec<Problem>,
    ) {
        for (i, line) in text.split('\n').enumerate() {
            if let Some(c) = line.chars().find(|c| c.is_control()) {
                let was = match c {
                    '\t' => " (a TeX macro's `\\t`: \\times, \\text, \\tfrac?)",
                    '\u{8}' => " (a TeX macro's `\\b`: \\bar, \\beta?)",
                    '\r' => " (a TeX macro's `\\r`: \\rho, \\right? or a CRLF line ending)",
                    '\u{c}' => " (a TeX macro's `\\f`: \\frac?)",
                    _ => "",
                };
                problems.push(Problem {
                    file: self.display_path(file),
                    line: i + 1,
                    message: format!("control character U+{:04X} in the text{was}", u32::from(c)),
                });
            }
        }
    }
}
