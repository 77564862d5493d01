//! Math: written `$…$` or `$$…$$`, the only delimiters the book's KaTeX pass reads.

use std::path::Path;

use super::{Checker, Problem};

impl Checker {
    /// Math is written `$…$` or `$$…$$`, the only delimiters the book's KaTeX pass reads:
    /// `\\(…\\)` and a display `\\[` on its own reach the page as raw TeX. Fenced code and
    /// code spans are skipped; `\\[2pt]` inside an aligned formula is not a delimiter.
    pub(super) fn check_math_delimiters(
        &self,
        file: &Path,
        text: &str,
        problems: &mut Vec<Problem>,
    ) {
        let mut fenced = false;
        for (i, line) in text.lines().enumerate() {
            let trimmed = line.trim_start();
            if trimmed.starts_with("```") || trimmed.starts_with("~~~") {
                fenced = !fenced;
                continue;
            }
            if fenced {
                continue;
            }
            let outside_code: String = line.split('`').step_by(2).collect::<Vec<_>>().join(" ");
            let display = trimmed
                .strip_prefix("\\\\[")
                .is_some_and(|rest| rest.trim().is_empty() || rest.starts_with(' '));
            if outside_code.contains("\\\\(") || display {
                problems.push(Problem {
                    file: self.display_path(file),
                    line: i + 1,
                    message: "math delimited by \\\\( \\\\) or \\\\[ \\\\]: write $…$ or $$…$$ \
                              (the only delimiters the KaTeX pass renders)"
                        .into(),
                });
            }
        }
    }
}
