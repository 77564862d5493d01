//! Errors of the project's data files (Sellmeier tables, spectra, scenes): every problem
//! names the file, the line and what is wrong, so that a reader who edits a table sees
//! where the mistake is.

use std::fmt;
use std::path::Path;

/// A problem with a data file: which file, which line (1-based; 0 for the whole file),
/// and what is wrong.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct DataError {
    /// The file's name or path, as given to the parser.
    pub file: String,
    /// The line, counting from 1; 0 when the problem is not on one line.
    pub line: usize,
    /// What is wrong, in words.
    pub problem: String,
}

impl DataError {
    /// A problem on `line` of `file` (0: the whole file).
    pub fn new(file: &str, line: usize, problem: impl Into<String>) -> Self {
        DataError {
            file: file.to_string(),
            line,
            problem: problem.into(),
        }
    }
}

impl fmt::Display for DataError {
    fn fmt(&self, out: &mut fmt::Formatter<'_>) -> fmt::Result {
        if self.line == 0 {
            write!(out, "{}: {}", self.file, self.problem)
        } else {
            write!(out, "{}:{}: {}", self.file, self.line, self.problem)
        }
    }
}

impl std::error::Error for DataError {}

/// Reads the text file at `path`; an unreadable file is a [`DataError`] on line 0.
///
/// # Errors
/// If the file cannot be read or is not UTF-8.
pub fn read_text(path: &Path) -> Result<(String, String), DataError> {
    let name = path.display().to_string();
    let text = std::fs::read_to_string(path)
        .map_err(|e| DataError::new(&name, 0, format!("cannot read the file: {e}")))?;
    Ok((text, name))
}
