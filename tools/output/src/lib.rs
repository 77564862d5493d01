//! Every file the library writes, written so that a reader never sees half of it and a
//! failure never destroys what was there: the one writer of the project, with one error
//! type ([`FileError`]: the path and the problem).
//!
//! * [`write_file`] (and [`write_file_with`], for an encoder that streams into a file):
//!   one file, written in full under a hidden temporary name beside its destination
//!   ([`temporary_beside`]), flushed to disk, and renamed over it. A rename within a folder
//!   is atomic: the destination is the old file or the new one, never a mixture.
//! * [`FileSet`]: several files that land together or not at all (a render's EXR, PNG and
//!   JSON). Every file is staged first; only when all are written does [`FileSet::commit`]
//!   rename them into place, keeping a hard link to each earlier file until the last one
//!   has landed, so that a failure midway puts every earlier file back, byte for byte.
//!   Nothing is left behind either way: a failed or dropped set removes its temporary
//!   files.
//! * [`StagedDir`]: a whole folder of outputs made beside its destination, then either
//!   merged into it file by file as one [`FileSet`] ([`StagedDir::commit_files`], the
//!   figures job) or swapped in for it whole ([`StagedDir::replace`], the book).
//!
//! Hand-written on `std` alone (no crate: build time matters). A crate of its own
//! (`tools/output`), so that the library (as `raylemma::output`) and the book tool, which
//! does not link the library, share it.
//!
//! A set is atomic against failures of this process's writes (a full disk, a missing
//! permission, a destination that is a folder), not against a crash between two renames:
//! a crash then may leave some files of the new set beside some of the old one, and the
//! hidden `.NAME.old-*` links of the old ones. No reader ever sees a partial file.

use std::ffi::OsString;
use std::fmt;
use std::fs::{self, File};
use std::io::Write as _;
use std::path::{Path, PathBuf};
use std::sync::atomic::{AtomicU64, Ordering};

/// A file or folder that could not be written (or read): its path and what went wrong.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct FileError {
    /// The file or folder the caller asked for (never a temporary name).
    pub path: PathBuf,
    /// What went wrong, in words.
    pub problem: String,
}

impl FileError {
    /// A problem with `path`.
    pub fn new(path: impl Into<PathBuf>, problem: impl Into<String>) -> Self {
        FileError {
            path: path.into(),
            problem: problem.into(),
        }
    }
}

impl fmt::Display for FileError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(f, "{}: {}", self.path.display(), self.problem)
    }
}

impl std::error::Error for FileError {}

/// A fresh hidden name beside `path`: `.NAME.KIND-PID-N`, `N` counting every name this
/// process has asked for, so that two threads writing the same file never share one.
fn hidden_beside(path: &Path, kind: &str) -> PathBuf {
    static NEXT: AtomicU64 = AtomicU64::new(0);
    let n = NEXT.fetch_add(1, Ordering::Relaxed);
    let mut name = OsString::from(".");
    name.push(path.file_name().unwrap_or_default());
    name.push(format!(".{kind}-{}-{n}", std::process::id()));
    path.with_file_name(name)
}

/// A hidden temporary name beside `path` (`.NAME.tmp-PID-N`) in the same folder, hence on
/// the same file system, so that renaming it over `path` is atomic.
pub fn temporary_beside(path: &Path) -> PathBuf {
    hidden_beside(path, "tmp")
}

/// Creates the folder `dir` and its parents if they do not exist.
///
/// # Errors
/// A [`FileError`] naming `dir`.
pub fn create_dir_all(dir: &Path) -> Result<(), FileError> {
    fs::create_dir_all(dir)
        .map_err(|e| FileError::new(dir, format!("cannot create the folder: {e}")))
}

/// Writes `bytes` to `path` atomically: in full beside it, then renamed over it.
///
/// # Errors
/// A [`FileError`] naming `path` (its folder does not exist or cannot be written, `path`
/// is a folder, the disk is full...); `path` is then as it was.
pub fn write_file(path: &Path, bytes: &[u8]) -> Result<(), FileError> {
    write_file_with(path, |f| f.write_all(bytes))
}

/// Writes to `path` atomically whatever `fill` writes into the open file (an encoder that
/// streams, such as OpenEXR's).
///
/// # Errors
/// As [`write_file`], and `fill`'s error, named by `path`.
pub fn write_file_with<E: fmt::Display>(
    path: &Path,
    fill: impl FnOnce(&mut File) -> Result<(), E>,
) -> Result<(), FileError> {
    let mut set = FileSet::new();
    set.write_with(path, fill)?;
    set.commit().map(drop)
}

/// A file written in full under its temporary name, waiting for its destination.
#[derive(Debug)]
struct Staged {
    temp: PathBuf,
    target: PathBuf,
}

/// Files that land together or not at all: each is staged with [`FileSet::write`] (or
/// [`FileSet::write_with`]) and none replaces its destination before [`FileSet::commit`].
/// A set dropped without committing removes what it staged.
#[derive(Debug, Default)]
pub struct FileSet {
    staged: Vec<Staged>,
}

impl FileSet {
    /// An empty set.
    pub fn new() -> Self {
        Self::default()
    }

    /// Stages `bytes` for `path`.
    ///
    /// # Errors
    /// As [`FileSet::write_with`].
    pub fn write(&mut self, path: &Path, bytes: &[u8]) -> Result<(), FileError> {
        self.write_with(path, |f| f.write_all(bytes))
    }

    /// Stages for `path` whatever `fill` writes into the open temporary file, which is then
    /// flushed to disk.
    ///
    /// # Errors
    /// A [`FileError`] naming `path`: it has no file name or is already in the set, its
    /// folder does not exist or cannot be written, or `fill` failed (the temporary file is
    /// then removed; what the set staged before stays staged).
    pub fn write_with<E: fmt::Display>(
        &mut self,
        path: &Path,
        fill: impl FnOnce(&mut File) -> Result<(), E>,
    ) -> Result<(), FileError> {
        let err = |problem: String| FileError::new(path, problem);
        if path.file_name().is_none() {
            return Err(err("the path has no file name".into()));
        }
        if self.staged.iter().any(|s| s.target == path) {
            return Err(err("the file is already part of this set".into()));
        }
        let temp = temporary_beside(path);
        let mut file =
            File::create_new(&temp).map_err(|e| err(format!("cannot write the file: {e}")))?;
        let filled = fill(&mut file)
            .map_err(|e| e.to_string())
            .and_then(|()| file.sync_all().map_err(|e| e.to_string()));
        drop(file);
        if let Err(problem) = filled {
            let _ = fs::remove_file(&temp);
            return Err(err(format!("cannot write the file: {problem}")));
        }
        self.staged.push(Staged {
            temp,
            target: path.to_path_buf(),
        });
        Ok(())
    }

    /// The destinations staged so far, in order.
    pub fn paths(&self) -> impl Iterator<Item = &Path> {
        self.staged.iter().map(|s| s.target.as_path())
    }

    /// Renames every staged file over its destination, in the order they were staged.
    /// While a set of several files lands, each earlier file is kept as a hidden hard link
    /// (a copy where the file system has no links); if one rename fails, the files already
    /// moved are put back (or removed, where there was none) and the links are removed.
    ///
    /// # Errors
    /// A [`FileError`] naming the destination that could not be replaced; every
    /// destination is then as it was before the set, and no temporary file is left.
    pub fn commit(mut self) -> Result<Vec<PathBuf>, FileError> {
        let staged = std::mem::take(&mut self.staged);
        let keep = staged.len() > 1;
        let mut landed: Vec<(&Path, Option<PathBuf>)> = Vec::new();
        for (i, s) in staged.iter().enumerate() {
            match land(s, keep) {
                Ok(earlier) => landed.push((&s.target, earlier)),
                Err(mut e) => {
                    for rest in &staged[i..] {
                        let _ = fs::remove_file(&rest.temp);
                    }
                    for (target, earlier) in landed.iter().rev() {
                        let restored = match earlier {
                            Some(old) => fs::rename(old, target),
                            None => fs::remove_file(target),
                        };
                        if let Err(r) = restored {
                            e.problem.push_str(&format!(
                                "; and {} could not be restored: {r}",
                                target.display()
                            ));
                        }
                    }
                    return Err(e);
                }
            }
        }
        for (_, earlier) in &landed {
            if let Some(old) = earlier {
                let _ = fs::remove_file(old);
            }
        }
        Ok(staged.into_iter().map(|s| s.target).collect())
    }
}

/// Moves one staged file over its destination; with `keep`, first links the earlier file
/// (if any, and not a folder) to a hidden name beside it, which is returned.
fn land(s: &Staged, keep: bool) -> Result<Option<PathBuf>, FileError> {
    let earlier = match fs::symlink_metadata(&s.target) {
        Ok(m) if keep && !m.is_dir() => {
            let old = hidden_beside(&s.target, "old");
            fs::hard_link(&s.target, &old)
                .or_else(|_| fs::copy(&s.target, &old).map(drop))
                .map_err(|e| {
                    let _ = fs::remove_file(&old);
                    FileError::new(
                        &s.target,
                        format!("cannot keep the earlier file while replacing it: {e}"),
                    )
                })?;
            Some(old)
        }
        _ => None,
    };
    match fs::rename(&s.temp, &s.target) {
        Ok(()) => Ok(earlier),
        Err(e) => {
            if let Some(old) = &earlier {
                let _ = fs::remove_file(old);
            }
            Err(FileError::new(
                &s.target,
                format!("cannot move the file into place: {e}"),
            ))
        }
    }
}

impl Drop for FileSet {
    fn drop(&mut self) {
        for s in &self.staged {
            let _ = fs::remove_file(&s.temp);
        }
    }
}

/// A folder of outputs made beside its destination `target` (a hidden `.NAME.tmp-PID-N`
/// on the same file system) and moved into place only when all of it was made: merged into
/// `target` ([`StagedDir::commit_files`]) or swapped in for it ([`StagedDir::replace`]).
/// Dropped without either, it is removed with everything in it.
#[derive(Debug)]
pub struct StagedDir {
    staging: PathBuf,
    target: PathBuf,
}

impl StagedDir {
    /// A new, empty staging folder beside `target` (whose parent is created if needed).
    ///
    /// # Errors
    /// A [`FileError`] naming `target` when it has no name or its parent cannot be
    /// written.
    pub fn beside(target: &Path) -> Result<Self, FileError> {
        if target.file_name().is_none() {
            return Err(FileError::new(target, "the path has no folder name"));
        }
        if let Some(parent) = target.parent() {
            create_dir_all(parent)?;
        }
        let staging = temporary_beside(target);
        fs::create_dir(&staging).map_err(|e| {
            FileError::new(
                target,
                format!("cannot create a staging folder beside it: {e}"),
            )
        })?;
        Ok(StagedDir {
            staging,
            target: target.to_path_buf(),
        })
    }

    /// The staging folder, to write the outputs into.
    pub fn path(&self) -> &Path {
        &self.staging
    }

    /// The destination.
    pub fn target(&self) -> &Path {
        &self.target
    }

    /// Moves every file of the staging folder (in subfolders too) to the same place under
    /// `target`, creating the folders it needs, as one [`FileSet`]: all land or none does.
    /// Files of `target` that the staging folder does not have are left alone. Returns the
    /// destinations, sorted.
    ///
    /// # Errors
    /// A [`FileError`] naming the file or folder that failed; `target` is then as it was
    /// (folders this call created are removed again), and the staging folder is removed.
    pub fn commit_files(self) -> Result<Vec<PathBuf>, FileError> {
        let relative: Vec<PathBuf> = files_under(&self.staging, &[""])?
            .into_iter()
            .map(|p| {
                p.strip_prefix(&self.staging)
                    .map(Path::to_path_buf)
                    .unwrap_or(p)
            })
            .collect();
        let mut created = Vec::new();
        let result = self.make_folders(&relative, &mut created).and_then(|()| {
            let set = FileSet {
                staged: relative
                    .iter()
                    .map(|rel| Staged {
                        temp: self.staging.join(rel),
                        target: self.target.join(rel),
                    })
                    .collect(),
            };
            set.commit()
        });
        if result.is_err() {
            for dir in created.iter().rev() {
                let _ = fs::remove_dir(dir);
            }
        }
        result
    }

    /// Creates `target` and the folders under it that the files `relative` need, recording
    /// those that did not exist in `created` (parents first).
    fn make_folders(
        &self,
        relative: &[PathBuf],
        created: &mut Vec<PathBuf>,
    ) -> Result<(), FileError> {
        let mut folders = vec![self.target.clone()];
        for rel in relative {
            for dir in rel.ancestors().skip(1) {
                if !dir.as_os_str().is_empty() {
                    folders.push(self.target.join(dir));
                }
            }
        }
        folders.sort();
        folders.dedup();
        // Sorted paths put every folder after its parent.
        for dir in folders {
            if fs::symlink_metadata(&dir).is_err() {
                fs::create_dir(&dir)
                    .map_err(|e| FileError::new(&dir, format!("cannot create the folder: {e}")))?;
                created.push(dir);
            }
        }
        Ok(())
    }

    /// Replaces the folder `target` (if there is one) by the staging folder: the old one is
    /// renamed aside, the new one renamed into place, then the old one deleted. A reader
    /// sees the old folder or the new one, except for the instant between the two renames,
    /// when there is none. Returns `target`.
    ///
    /// # Errors
    /// A [`FileError`] naming `target` if either rename fails; the old folder is then put
    /// back and the staging folder removed. (Failing to delete the old folder afterwards is
    /// not an error: the new one is in place; the old one stays as `.NAME.old-PID-N`.)
    pub fn replace(self) -> Result<PathBuf, FileError> {
        let old = hidden_beside(&self.target, "old");
        let had_old = fs::symlink_metadata(&self.target).is_ok();
        if had_old {
            fs::rename(&self.target, &old).map_err(|e| {
                FileError::new(
                    &self.target,
                    format!("cannot move the earlier folder aside: {e}"),
                )
            })?;
        }
        if let Err(e) = fs::rename(&self.staging, &self.target) {
            let mut problem = format!("cannot move the new folder into place: {e}");
            if had_old && let Err(r) = fs::rename(&old, &self.target) {
                problem.push_str(&format!(
                    "; and the earlier folder, now {}, could not be put back: {r}",
                    old.display()
                ));
            }
            return Err(FileError::new(&self.target, problem));
        }
        if had_old {
            let _ = fs::remove_dir_all(&old);
        }
        Ok(self.target.clone())
    }
}

impl Drop for StagedDir {
    fn drop(&mut self) {
        if fs::symlink_metadata(&self.staging).is_ok() {
            let _ = fs::remove_dir_all(&self.staging);
        }
    }
}

/// Every file under the folders `dirs` of `root` (each `root.join(dir)`, its subfolders
/// too; an empty `dir` is `root` itself), as paths that begin with `root`, sorted: the one
/// walker of the project, for "which files make X" (the renderer's source closure, the
/// figure job's code version, the book's chapters) and for the files a [`StagedDir`]
/// holds. A folder is entered; anything else, a link too, is a file. A file under two of
/// `dirs` is listed twice.
///
/// # Errors
/// A [`FileError`] naming a folder that cannot be listed.
pub fn files_under<P: AsRef<Path>>(root: &Path, dirs: &[P]) -> Result<Vec<PathBuf>, FileError> {
    let mut files = Vec::new();
    let mut stack: Vec<PathBuf> = dirs
        .iter()
        .map(|d| {
            let d = d.as_ref();
            if d.as_os_str().is_empty() {
                root.to_path_buf()
            } else {
                root.join(d)
            }
        })
        .collect();
    while let Some(dir) = stack.pop() {
        let cannot_list = |e: std::io::Error| FileError::new(&dir, format!("cannot list: {e}"));
        for entry in fs::read_dir(&dir).map_err(cannot_list)? {
            let entry = entry.map_err(cannot_list)?;
            let path = entry.path();
            let kind = entry
                .file_type()
                .map_err(|e| FileError::new(&path, e.to_string()))?;
            if kind.is_dir() {
                stack.push(path);
            } else {
                files.push(path);
            }
        }
    }
    files.sort();
    Ok(files)
}

/// The 1-based line of `text` on which the byte `offset` is (a parser's span, for an
/// error that names its line); an offset past the end is on the last line.
pub fn line_of(text: &str, offset: usize) -> usize {
    let end = offset.min(text.len());
    text.as_bytes()[..end]
        .iter()
        .filter(|&&b| b == b'\n')
        .count()
        + 1
}

/// The 64-bit FNV-1a hash of `bytes`: fixed, the same on every platform and Rust version
/// (a scene file's hash in a render's sidecar, the code version of kept figures, a
/// machine's fingerprint).
pub fn fnv1a(bytes: &[u8]) -> u64 {
    bytes.iter().fold(0xcbf2_9ce4_8422_2325, |h, &b| {
        (h ^ u64::from(b)).wrapping_mul(0x0100_0000_01b3)
    })
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn lines_and_hashes() {
        assert_eq!(line_of("a\nb\nc", 0), 1);
        assert_eq!(line_of("a\nb\nc", 2), 2);
        assert_eq!(line_of("a\nb\nc", 99), 3);
        // The published FNV-1a 64 test vectors.
        assert_eq!(fnv1a(b""), 0xcbf2_9ce4_8422_2325);
        assert_eq!(fnv1a(b"a"), 0xaf63_dc4c_8601_ec8c);
        assert_eq!(fnv1a(b"foobar"), 0x8594_4171_f739_67e8);
    }

    #[test]
    fn files_under_lists_every_file_of_the_folders_sorted() {
        let root =
            std::env::temp_dir().join(format!("raylemma-files-under-{}", std::process::id()));
        let _ = fs::remove_dir_all(&root);
        for f in [
            "a/z.txt",
            "a/b/y.rs",
            "a/b/c/x.md",
            "a/b.txt",
            "d/w.txt",
            "top.txt",
        ] {
            let p = root.join(f);
            fs::create_dir_all(p.parent().unwrap()).unwrap();
            fs::write(&p, f).unwrap();
        }
        fs::create_dir_all(root.join("a/empty")).unwrap();
        let at = |fs: &[&str]| fs.iter().map(|f| root.join(f)).collect::<Vec<_>>();
        assert_eq!(
            files_under(&root, &["a"]).unwrap(),
            at(&["a/b/c/x.md", "a/b/y.rs", "a/b.txt", "a/z.txt"])
        );
        assert_eq!(
            files_under(&root, &["d", "a/b"]).unwrap(),
            at(&["a/b/c/x.md", "a/b/y.rs", "d/w.txt"])
        );
        assert_eq!(files_under(&root, &[""]).unwrap().len(), 6);
        assert!(files_under::<&str>(&root, &[]).unwrap().is_empty());
        let missing = files_under(&root, &["nowhere"]).unwrap_err();
        assert!(missing.to_string().contains("cannot list"), "{missing}");
        fs::remove_dir_all(&root).unwrap();
    }
}
