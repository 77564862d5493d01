//! What the chapters' tests share: the project's root and scratch folders. One helper for
//! each small job, so that no test file writes its own.

use std::path::{Path, PathBuf};

/// The project's root (where `Cargo.toml`, `scenes/`, `data/` and `figures/` are).
pub fn root() -> &'static Path {
    Path::new(env!("CARGO_MANIFEST_DIR"))
}

/// A new, empty scratch folder for one test, `NAME-PID` under cargo's `CARGO_TARGET_TMPDIR`
/// (inside the target folder, so `cargo clean` removes what is left). It is removed when
/// the value is dropped, unless the test is failing: then it stays, to be looked at.
pub struct Scratch(PathBuf);

impl Scratch {
    /// The folder.
    pub fn as_path(&self) -> &Path {
        &self.0
    }
}

impl std::ops::Deref for Scratch {
    type Target = Path;
    fn deref(&self) -> &Path {
        &self.0
    }
}

impl AsRef<Path> for Scratch {
    fn as_ref(&self) -> &Path {
        &self.0
    }
}

impl AsRef<std::ffi::OsStr> for Scratch {
    fn as_ref(&self) -> &std::ffi::OsStr {
        self.0.as_os_str()
    }
}

impl Drop for Scratch {
    fn drop(&mut self) {
        if !std::thread::panicking() {
            let _ = std::fs::remove_dir_all(&self.0);
        }
    }
}

/// A scratch folder for the test `name` (see [`Scratch`]); any earlier one of that name and
/// process is replaced.
pub fn scratch(name: &str) -> Scratch {
    let dir = Path::new(env!("CARGO_TARGET_TMPDIR"))
        .join(format!("raylemma-{name}-{}", std::process::id()));
    let _ = std::fs::remove_dir_all(&dir);
    std::fs::create_dir_all(&dir)
        .unwrap_or_else(|e| panic!("cannot make the scratch folder {}: {e}", dir.display()));
    Scratch(dir)
}

/// The path of a scratch file `name` in one folder shared by the tests of this run
/// (`files-PID` under `CARGO_TARGET_TMPDIR`), for helpers that write many small files;
/// the name must be unique to its test.
pub fn scratch_file(name: &str) -> PathBuf {
    let dir = Path::new(env!("CARGO_TARGET_TMPDIR"))
        .join(format!("raylemma-files-{}", std::process::id()));
    std::fs::create_dir_all(&dir)
        .unwrap_or_else(|e| panic!("cannot make the scratch folder {}: {e}", dir.display()));
    dir.join(name)
}
