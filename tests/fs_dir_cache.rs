//! The output directory handles a run keeps open (`fs_policy::DirCache`), as a batch worker
//! uses them: each "row" is a policy of its own sharing one cache. The writes stay where the
//! confinement puts them, a symlink swapped in after the first row leads nowhere, and a
//! directory removed meanwhile is an error naming it, never a file lost.
#![cfg(unix)]

use std::path::{Path, PathBuf};

use lispcad::builtins::fs_policy::DirCache;
use lispcad::builtins::io::FsPolicy;
use lispcad::lang::Interp;

/// A row: a fresh interpreter whose policy allows writes below `root` only, with the
/// worker's cache, and one line drawn.
fn row(root: &Path, dirs: &DirCache) -> Interp {
    let mut it = lispcad::builtins::new_interp();
    *it.ext::<FsPolicy>() = FsPolicy {
        roots: vec![root.to_path_buf()],
        dirs: dirs.clone(),
        ..FsPolicy::default()
    };
    it.base_dir = Some(root.to_path_buf());
    it.eval_source("t", "(entmake '((0 . \"LINE\") (10 0 0 0) (11 3 4 0)))")
        .unwrap();
    it
}

fn save(it: &mut Interp, name: &str) -> Result<(), String> {
    it.eval_source("t", &format!("(save \"{name}\")"))
        .map(drop)
        .map_err(|e| e.message.clone())
}

/// The bytes of the same row saved through a policy of its own (no handle held).
fn reference(dir: &Path) -> Vec<u8> {
    let own = dir.join("reference");
    std::fs::create_dir(&own).unwrap();
    save(&mut row(&own, &DirCache::default()), "r.dxf").unwrap();
    std::fs::read(own.join("r.dxf")).unwrap()
}

fn names(dir: &Path) -> Vec<String> {
    let mut v: Vec<String> = std::fs::read_dir(dir)
        .unwrap()
        .map(|e| e.unwrap().file_name().to_string_lossy().into_owned())
        .collect();
    v.sort();
    v
}

struct Tree {
    _dir: tempfile::TempDir,
    top: PathBuf,
    root: PathBuf,
    outside: PathBuf,
}

fn tree() -> Tree {
    let dir = tempfile::tempdir().unwrap();
    let top = dir.path().to_path_buf();
    let root = top.join("in");
    let outside = top.join("outside");
    std::fs::create_dir_all(root.join("out")).unwrap();
    std::fs::create_dir_all(&outside).unwrap();
    Tree {
        _dir: dir,
        top,
        root,
        outside,
    }
}

#[test]
fn rows_into_one_directory_open_it_once() {
    let t = tree();
    let dirs = DirCache::new();
    let mut r1 = row(&t.root, &dirs);
    save(&mut r1, "out/a.dxf").unwrap();
    save(&mut r1, "out/b.dxf").unwrap();
    // The root's handle and out's.
    assert_eq!(dirs.len(), 2);
    save(&mut row(&t.root, &dirs), "out/c.dxf").unwrap();
    assert_eq!(dirs.len(), 2, "the second row opened its directory again");
    assert_eq!(names(&t.root.join("out")), ["a.dxf", "b.dxf", "c.dxf"]);
    let want = reference(&t.top);
    for n in ["a", "b", "c"] {
        assert_eq!(
            std::fs::read(t.root.join(format!("out/{n}.dxf"))).unwrap(),
            want
        );
    }
}

#[test]
fn rows_into_different_directories_each_get_their_own() {
    let t = tree();
    let dirs = DirCache::new();
    for sub in ["p", "q", "p/deep"] {
        std::fs::create_dir_all(t.root.join("out").join(sub)).unwrap();
    }
    save(&mut row(&t.root, &dirs), "out/p/x.dxf").unwrap();
    save(&mut row(&t.root, &dirs), "out/q/x.dxf").unwrap();
    save(&mut row(&t.root, &dirs), "out/p/deep/x.dxf").unwrap();
    save(&mut row(&t.root, &dirs), "top.dxf").unwrap();
    // The root, out/p, out/q and out/p/deep.
    assert_eq!(dirs.len(), 4);
    let want = reference(&t.top);
    for f in ["out/p/x.dxf", "out/q/x.dxf", "out/p/deep/x.dxf", "top.dxf"] {
        assert_eq!(std::fs::read(t.root.join(f)).unwrap(), want, "{f}");
    }
    assert_eq!(names(&t.root.join("out/p")), ["deep", "x.dxf"]);
    // A directory per row: the handles stay few, and every file is written.
    for i in 0..3 * DirCache::MAX {
        std::fs::create_dir(t.root.join(format!("out/r{i}"))).unwrap();
        save(&mut row(&t.root, &dirs), &format!("out/r{i}/x.dxf")).unwrap();
        assert!(dirs.len() <= DirCache::MAX);
    }
    for i in 0..3 * DirCache::MAX {
        assert_eq!(names(&t.root.join(format!("out/r{i}"))), ["x.dxf"]);
    }
}

#[test]
fn a_symlink_swapped_in_after_the_first_row_does_not_lead_out() {
    let t = tree();
    let dirs = DirCache::new();
    save(&mut row(&t.root, &dirs), "out/a.dxf").unwrap();
    // out moves aside (still below the root) and a symlink to the outside takes its name.
    let moved = t.root.join("out.moved");
    std::fs::rename(t.root.join("out"), &moved).unwrap();
    std::os::unix::fs::symlink(&t.outside, t.root.join("out")).unwrap();
    // The handle held is the directory's, wherever it is now: the symlink is not followed.
    save(&mut row(&t.root, &dirs), "out/b.dxf").unwrap();
    assert!(names(&t.outside).is_empty(), "{:?}", names(&t.outside));
    assert_eq!(names(&moved), ["a.dxf", "b.dxf"]);
    assert!(t.root.join("out").is_symlink());
    // A worker without the handle opens out by its name and is refused.
    let e = save(&mut row(&t.root, &DirCache::default()), "out/c.dxf").unwrap_err();
    assert!(e.starts_with("file access refused:"), "{e}");
    assert!(names(&t.outside).is_empty(), "{:?}", names(&t.outside));
}

#[test]
fn a_directory_removed_during_the_run_is_an_error_then_found_again() {
    let t = tree();
    let dirs = DirCache::new();
    save(&mut row(&t.root, &dirs), "out/a.dxf").unwrap();
    std::fs::remove_dir_all(t.root.join("out")).unwrap();
    let e = save(&mut row(&t.root, &dirs), "out/b.dxf").unwrap_err();
    let out = t.root.join("out");
    assert!(
        e.contains(&format!("save {}", out.join("b.dxf").display()))
            && e.contains("its directory was removed during the run")
            && e.contains("No such file or directory"),
        "{e}"
    );
    assert_eq!(names(&t.root), Vec::<String>::new());
    // Made again by its name: the next row writes there.
    std::fs::create_dir(&out).unwrap();
    save(&mut row(&t.root, &dirs), "out/c.dxf").unwrap();
    assert_eq!(names(&out), ["c.dxf"]);
    // Removed and made again between two rows, with no failure between: the same.
    std::fs::remove_dir_all(&out).unwrap();
    std::fs::create_dir(&out).unwrap();
    save(&mut row(&t.root, &dirs), "out/d.dxf").unwrap();
    assert_eq!(names(&out), ["d.dxf"]);
    assert_eq!(std::fs::read(out.join("d.dxf")).unwrap(), reference(&t.top));
}

#[test]
fn a_root_removed_during_the_run_is_an_error() {
    let t = tree();
    let dirs = DirCache::new();
    let root = t.root.join("out");
    save(&mut row(&root, &dirs), "a.dxf").unwrap();
    std::fs::remove_dir_all(&root).unwrap();
    let e = save(&mut row(&root, &dirs), "b.dxf").unwrap_err();
    assert!(
        e.contains("its directory was removed during the run")
            && e.contains(&root.display().to_string()),
        "{e}"
    );
    assert!(!root.exists());
}

#[test]
fn a_directory_the_script_renames_is_opened_again_by_its_name() {
    let t = tree();
    let dirs = DirCache::new();
    let mut it = row(&t.root, &dirs);
    save(&mut it, "out/a.dxf").unwrap();
    let r = it
        .eval_source(
            "t",
            "(list (vl-file-rename \"out\" \"out2\") (vl-mkdir \"out\"))",
        )
        .unwrap();
    assert_eq!(it.prin1_string(&r), "(T T)");
    save(&mut it, "out/b.dxf").unwrap();
    assert_eq!(names(&t.root.join("out")), ["b.dxf"]);
    assert_eq!(names(&t.root.join("out2")), ["a.dxf"]);
}

#[test]
fn without_a_batch_each_save_opens_its_directory_by_name() {
    let t = tree();
    // The default policy keeps no handle (a REPL or `watch` session).
    let off = DirCache::default();
    let mut it = row(&t.root, &off);
    save(&mut it, "out/a.dxf").unwrap();
    assert_eq!(off.len(), 0);
    std::fs::rename(t.root.join("out"), t.root.join("out.old")).unwrap();
    std::fs::create_dir(t.root.join("out")).unwrap();
    save(&mut it, "out/b.dxf").unwrap();
    assert_eq!(names(&t.root.join("out")), ["b.dxf"]);
    assert_eq!(names(&t.root.join("out.old")), ["a.dxf"]);
}
