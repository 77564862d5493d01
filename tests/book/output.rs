//! Tests of the one writer of the project (`src/output.rs`): a file is replaced whole or
//! not at all; a set of files lands together or not at all, whether it fails while its
//! files are written or while they are moved into place; nothing temporary is left
//! behind; an unwritable folder is an error that names the path; a staged folder is merged
//! into its destination or swapped in for it, or leaves it as it was.

use std::fs;
use std::path::{Path, PathBuf};

use raylemma::output::{FileError, FileSet, StagedDir, temporary_beside, write_file};

fn scratch(name: &str) -> crate::support::Scratch {
    crate::support::scratch(&format!("output-{name}"))
}

/// The names in `dir`, sorted (hidden temporary files included).
fn names(dir: &Path) -> Vec<String> {
    let mut names: Vec<String> = fs::read_dir(dir)
        .unwrap()
        .map(|e| e.unwrap().file_name().into_string().unwrap())
        .collect();
    names.sort();
    names
}

fn read(path: &Path) -> Vec<u8> {
    fs::read(path).unwrap_or_else(|e| panic!("{}: {e}", path.display()))
}

#[test]
fn a_file_is_replaced_whole_and_nothing_is_left_beside_it() {
    let dir = scratch("file");
    let path = dir.join("a.txt");
    write_file(&path, b"first").unwrap();
    write_file(&path, b"second").unwrap();
    assert_eq!(read(&path), b"second");
    assert_eq!(names(&dir), ["a.txt"]);
    // The temporary name is hidden, beside the file, and new every time.
    let (t1, t2) = (temporary_beside(&path), temporary_beside(&path));
    assert_eq!(t1.parent(), Some(dir.as_path()));
    assert!(
        t1.file_name()
            .unwrap()
            .to_string_lossy()
            .starts_with(".a.txt.tmp-")
    );
    assert_ne!(t1, t2);
    fs::remove_dir_all(&dir).unwrap();
}

/// Three files of an earlier set, and their bytes.
fn earlier_set(dir: &Path) -> Vec<(PathBuf, Vec<u8>)> {
    let files: Vec<(PathBuf, Vec<u8>)> = ["a.exr", "a.png", "a.json"]
        .iter()
        .map(|n| (dir.join(n), format!("earlier {n}").into_bytes()))
        .collect();
    let mut set = FileSet::new();
    for (p, b) in &files {
        set.write(p, b).unwrap();
    }
    assert_eq!(set.paths().count(), 3);
    let landed = set.commit().unwrap();
    assert_eq!(
        landed,
        files.iter().map(|(p, _)| p.clone()).collect::<Vec<_>>()
    );
    files
}

fn assert_intact(files: &[(PathBuf, Vec<u8>)]) {
    for (p, b) in files {
        assert_eq!(&read(p), b, "{} changed", p.display());
    }
}

#[test]
fn a_set_that_fails_while_being_written_leaves_the_earlier_set_intact() {
    let dir = scratch("set-write");
    let earlier = earlier_set(&dir);
    let mut set = FileSet::new();
    set.write(&earlier[0].0, b"new exr").unwrap();
    let e = set
        .write_with(&earlier[1].0, |_| Err("the encoder failed"))
        .unwrap_err();
    assert_eq!(e.path, earlier[1].0);
    assert!(
        e.to_string().contains("a.png") && e.to_string().contains("the encoder failed"),
        "{e}"
    );
    // The caller gives up: the set is dropped without committing.
    drop(set);
    assert_intact(&earlier);
    assert_eq!(names(&dir), ["a.exr", "a.json", "a.png"]);
    // The same file twice in one set is refused.
    let mut set = FileSet::new();
    set.write(&earlier[0].0, b"x").unwrap();
    let e = set.write(&earlier[0].0, b"y").unwrap_err();
    assert!(e.problem.contains("already"), "{e}");
    drop(set);
    assert_intact(&earlier);
    assert_eq!(names(&dir), ["a.exr", "a.json", "a.png"]);
    fs::remove_dir_all(&dir).unwrap();
}

#[test]
fn a_set_that_fails_while_landing_puts_every_earlier_file_back() {
    let dir = scratch("set-land");
    let earlier = earlier_set(&dir);
    // The third destination is a (non-empty) folder: its rename fails after the first two
    // files, one replacing an earlier file and one new, have landed.
    let blocked = dir.join("blocked");
    fs::create_dir(&blocked).unwrap();
    fs::write(blocked.join("keep"), b"keep").unwrap();
    let fresh = dir.join("fresh.txt");
    let mut set = FileSet::new();
    set.write(&earlier[0].0, b"new exr").unwrap();
    set.write(&fresh, b"new file").unwrap();
    set.write(&blocked, b"cannot land").unwrap();
    set.write(&earlier[2].0, b"new json").unwrap();
    let e = set.commit().unwrap_err();
    assert_eq!(e.path, blocked);
    assert!(e.to_string().contains("blocked"), "{e}");
    assert!(!e.problem.contains("restored"), "{e}");
    assert_intact(&earlier);
    assert!(!fresh.exists(), "a file new in the failed set was left");
    assert_eq!(read(&blocked.join("keep")), b"keep");
    // No temporary file and no kept link of an earlier file is left.
    assert_eq!(names(&dir), ["a.exr", "a.json", "a.png", "blocked"]);
    assert_eq!(names(&blocked), ["keep"]);
    // And a set that can land does, replacing all three.
    let mut set = FileSet::new();
    for (p, _) in &earlier {
        set.write(p, b"later").unwrap();
    }
    set.commit().unwrap();
    for (p, _) in &earlier {
        assert_eq!(read(p), b"later");
    }
    assert_eq!(names(&dir), ["a.exr", "a.json", "a.png", "blocked"]);
    fs::remove_dir_all(&dir).unwrap();
}

#[test]
fn an_unwritable_folder_is_an_error_naming_the_path() {
    let dir = scratch("unwritable");
    // A "folder" that is a file: nobody, not even root, can write in it.
    fs::write(dir.join("plain"), b"plain").unwrap();
    let inside = dir.join("plain").join("x.png");
    let e: FileError = write_file(&inside, b"x").unwrap_err();
    assert_eq!(e.path, inside);
    assert!(e.to_string().contains("plain/x.png"), "{e}");
    // A folder that does not exist, in a set.
    let missing = dir.join("no/such/folder/y.json");
    let mut set = FileSet::new();
    let e = set.write(&missing, b"y").unwrap_err();
    assert!(e.to_string().contains("no/such/folder/y.json"), "{e}");
    assert!(set.commit().unwrap().is_empty());
    // A read-only folder (skipped where permissions are not enforced, as for root).
    #[cfg(unix)]
    {
        use std::os::unix::fs::PermissionsExt as _;
        let locked = dir.join("locked");
        fs::create_dir(&locked).unwrap();
        fs::write(locked.join("old.txt"), b"old").unwrap();
        fs::set_permissions(&locked, fs::Permissions::from_mode(0o555)).unwrap();
        if fs::File::create(locked.join("probe")).is_err() {
            let target = locked.join("old.txt");
            let e = write_file(&target, b"new").unwrap_err();
            assert_eq!(e.path, target);
            assert!(e.to_string().contains("locked/old.txt"), "{e}");
            assert_eq!(read(&target), b"old");
            assert_eq!(names(&locked), ["old.txt"]);
        } else {
            eprintln!("permissions are not enforced here (root?): read-only case skipped");
        }
        fs::set_permissions(&locked, fs::Permissions::from_mode(0o755)).unwrap();
    }
    // No temporary file was left anywhere.
    assert!(
        names(&dir).iter().all(|n| !n.starts_with('.')),
        "{:?}",
        names(&dir)
    );
    fs::remove_dir_all(&dir).unwrap();
}

#[test]
fn a_staged_folder_is_merged_file_by_file_or_not_at_all() {
    let root = scratch("staged-merge");
    let target = root.join("figures");
    fs::create_dir_all(target.join("reference")).unwrap();
    fs::write(target.join("other.md"), b"other").unwrap();
    fs::write(target.join("a.md"), b"old a").unwrap();
    fs::write(target.join("reference").join("r.exr"), b"old r").unwrap();
    // A successful job: two files, one in a subfolder, one in a new subfolder.
    let staged = StagedDir::beside(&target).unwrap();
    assert_eq!(staged.path().parent(), Some(root.as_path()));
    fs::write(staged.path().join("a.md"), b"new a").unwrap();
    fs::create_dir_all(staged.path().join("reference")).unwrap();
    fs::write(staged.path().join("reference").join("r.exr"), b"new r").unwrap();
    fs::create_dir_all(staged.path().join("more")).unwrap();
    fs::write(staged.path().join("more").join("m.png"), b"new m").unwrap();
    let written = staged.commit_files().unwrap();
    assert_eq!(
        written,
        [
            target.join("a.md"),
            target.join("more").join("m.png"),
            target.join("reference").join("r.exr")
        ]
    );
    assert_eq!(read(&target.join("a.md")), b"new a");
    assert_eq!(read(&target.join("reference").join("r.exr")), b"new r");
    assert_eq!(read(&target.join("more").join("m.png")), b"new m");
    assert_eq!(read(&target.join("other.md")), b"other");
    assert_eq!(names(&root), ["figures"]);
    // A job that fails midway: it drops its staging folder, and nothing changes.
    let staged = StagedDir::beside(&target).unwrap();
    fs::write(staged.path().join("a.md"), b"newer a").unwrap();
    drop(staged);
    assert_eq!(read(&target.join("a.md")), b"new a");
    assert_eq!(names(&root), ["figures"]);
    // A merge that fails while landing: a destination is a folder. The file that landed
    // first is put back, and the new folder it needed is removed again.
    fs::create_dir_all(target.join("z.md")).unwrap();
    fs::write(target.join("z.md").join("keep"), b"keep").unwrap();
    let staged = StagedDir::beside(&target).unwrap();
    fs::write(staged.path().join("a.md"), b"newest a").unwrap();
    fs::create_dir_all(staged.path().join("brand-new")).unwrap();
    fs::write(staged.path().join("brand-new").join("b.md"), b"b").unwrap();
    fs::write(staged.path().join("z.md"), b"z").unwrap();
    let e = staged.commit_files().unwrap_err();
    assert!(e.to_string().contains("z.md"), "{e}");
    assert_eq!(read(&target.join("a.md")), b"new a");
    assert!(!target.join("brand-new").exists());
    assert_eq!(names(&root), ["figures"]);
    assert_eq!(
        names(&target),
        ["a.md", "more", "other.md", "reference", "z.md"]
    );
    fs::remove_dir_all(&root).unwrap();
}

#[test]
fn a_staged_folder_replaces_its_destination_whole() {
    let root = scratch("staged-replace");
    let target = root.join("book");
    // The first build: no earlier folder.
    let staged = StagedDir::beside(&target).unwrap();
    fs::write(staged.path().join("index.html"), b"one").unwrap();
    assert_eq!(staged.replace().unwrap(), target);
    assert_eq!(names(&target), ["index.html"]);
    // The second replaces it whole: a file the new build lacks is gone.
    fs::write(target.join("stale.html"), b"stale").unwrap();
    let staged = StagedDir::beside(&target).unwrap();
    fs::write(staged.path().join("index.html"), b"two").unwrap();
    staged.replace().unwrap();
    assert_eq!(names(&target), ["index.html"]);
    assert_eq!(read(&target.join("index.html")), b"two");
    assert_eq!(names(&root), ["book"]);
    // A build that fails never touches the book.
    let staged = StagedDir::beside(&target).unwrap();
    fs::write(staged.path().join("index.html"), b"three").unwrap();
    drop(staged);
    assert_eq!(read(&target.join("index.html")), b"two");
    assert_eq!(names(&root), ["book"]);
    // A destination without a name is refused.
    assert!(StagedDir::beside(Path::new("/")).is_err());
    fs::remove_dir_all(&root).unwrap();
}
