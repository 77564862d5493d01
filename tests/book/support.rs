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

/// A PNG read back as 8-bit RGB, for tests that look at the pixels the project wrote.
pub struct Rgb8 {
    /// Width in pixels.
    pub width: u32,
    /// Height in pixels.
    pub height: u32,
    /// `3 width height` bytes, row-major from the top.
    pub bytes: Vec<u8>,
}

impl Rgb8 {
    /// The pixel at column `x`, row `y` (from the top).
    pub fn pixel(&self, x: u32, y: u32) -> [u8; 3] {
        let i = 3 * (y * self.width + x) as usize;
        [self.bytes[i], self.bytes[i + 1], self.bytes[i + 2]]
    }

    /// Every pixel, row-major.
    pub fn pixels(&self) -> impl Iterator<Item = [u8; 3]> + '_ {
        self.bytes.chunks_exact(3).map(|p| [p[0], p[1], p[2]])
    }
}

/// Reads the PNG at `path` with the `png` crate (palette and grey expanded, 16 bits cut to
/// 8); panics, naming the file, if it is not an RGB or grey PNG.
pub fn read_png(path: &Path) -> Rgb8 {
    let file = std::fs::File::open(path).unwrap_or_else(|e| panic!("{}: {e}", path.display()));
    let mut decoder = png::Decoder::new(std::io::BufReader::new(file));
    decoder.set_transformations(png::Transformations::normalize_to_color8());
    let mut reader = decoder
        .read_info()
        .unwrap_or_else(|e| panic!("{}: {e}", path.display()));
    let mut buf = vec![0; reader.output_buffer_size().expect("a PNG of a sane size")];
    let frame = reader
        .next_frame(&mut buf)
        .unwrap_or_else(|e| panic!("{}: {e}", path.display()));
    let data = &buf[..frame.buffer_size()];
    let bytes = match frame.color_type {
        png::ColorType::Rgb => data.to_vec(),
        png::ColorType::Grayscale => data.iter().flat_map(|&g| [g, g, g]).collect(),
        other => panic!("{}: a {other:?} PNG", path.display()),
    };
    Rgb8 {
        width: frame.width,
        height: frame.height,
        bytes,
    }
}

/// A file the tests write from the code (`path`, from the root): with the environment
/// variable `write` set, writes `want` there; otherwise fails unless the file is `want`,
/// saying how to write it again. One rule for every generated file the tests hold current.
pub fn generated(path: &str, want: &str, write: &str) {
    let full = root().join(path);
    if std::env::var_os(write).is_some() {
        std::fs::write(&full, want).unwrap_or_else(|e| panic!("{path}: {e}"));
        return;
    }
    let have = std::fs::read_to_string(&full).unwrap_or_default();
    assert!(
        have == want,
        "{path} is not what the code makes: write it again with `{write}=1 cargo test --test book`"
    );
}
