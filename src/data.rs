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

/// The 1-based line of `text` on which the byte `offset` is (a parser's span, for a
/// [`DataError`]'s line): the workspace's one, in the shared crate.
pub use raylemma_output::line_of;

/// The largest text file read (a scene, a table, a file of samples or answers): 32 MiB.
pub const MAX_TEXT: u64 = 32 << 20;

/// Reads the text file at `path`, at most [`MAX_TEXT`] bytes of it (a device such as
/// `/dev/zero` or a runaway file is refused once that much is read); an unreadable file is
/// a [`DataError`] on line 0.
///
/// # Errors
/// If the file cannot be read, is larger than [`MAX_TEXT`] or is not UTF-8.
pub fn read_text(path: &Path) -> Result<(String, String), DataError> {
    use std::io::Read as _;
    let name = path.display().to_string();
    let cannot = |e: std::io::Error| DataError::new(&name, 0, format!("cannot read the file: {e}"));
    let mut bytes = Vec::new();
    std::fs::File::open(path)
        .and_then(|f| f.take(MAX_TEXT + 1).read_to_end(&mut bytes))
        .map_err(cannot)?;
    if bytes.len() as u64 > MAX_TEXT {
        return Err(DataError::new(
            &name,
            0,
            format!(
                "larger than {} MiB, the most read of a text file",
                MAX_TEXT >> 20
            ),
        ));
    }
    let text = String::from_utf8(bytes).map_err(|e| {
        let line = 1 + e.as_bytes()[..e.utf8_error().valid_up_to()]
            .iter()
            .filter(|&&b| b == b'\n')
            .count();
        DataError::new(&name, line, "not UTF-8 text")
    })?;
    Ok((text, name))
}
