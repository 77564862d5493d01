//! Numbers: every `{{#value}}` and `{{#claim}}` reads a table the figure job recorded, and
//! every claim holds.

use std::path::Path;

use super::{Checker, Problem};
use crate::values;

impl Checker {
    /// Every `{{#value}}` and `{{#claim}}` reads a table that exists, and every claim holds
    /// (a claim that fails on a quick-mode table is left to the preprocessor's warning).
    pub(super) fn check_numbers(&mut self, file: &Path, text: &str, problems: &mut Vec<Problem>) {
        let values = match &self.values {
            Ok(v) => v,
            Err(e) => {
                problems.push(Problem {
                    file: self.display_path(file),
                    line: 1,
                    message: e.clone(),
                });
                return;
            }
        };
        let (_, findings) = values::expand(values, text);
        for f in findings.into_iter().filter(|f| !f.warning) {
            problems.push(Problem {
                file: self.display_path(file),
                line: f.line,
                message: f.message,
            });
        }
    }
}
