//! Atomic file replacement: write a temporary file in the target's directory, then rename it
//! over the target. A reader never sees a half-written file, and a failed write leaves nothing
//! behind (the temporary file is removed when dropped).
//!
//! No fsync: the guarantee is atomicity (whole file or none), not durability across a power
//! cut. Batch runs write thousands of files, and an fsync per file made them wait on the disk
//! for most of their wall time.

use std::io::Write;
use std::path::Path;

/// Write `bytes` to `path` atomically (same-directory temporary file, then rename).
pub fn write_atomic(path: &Path, bytes: &[u8]) -> std::io::Result<()> {
    let dir = match path.parent() {
        Some(d) if !d.as_os_str().is_empty() => d,
        _ => Path::new("."),
    };
    let mut b = tempfile::Builder::new();
    b.prefix(".lispcad-").suffix(".tmp");
    // tempfile creates 0600 files; an output is an ordinary file (0644 before the umask),
    // given its mode when it is created rather than by a chmod after (one call per file).
    #[cfg(unix)]
    {
        use std::os::unix::fs::PermissionsExt;
        b.permissions(std::fs::Permissions::from_mode(0o644));
    }
    let mut tmp = b.tempfile_in(dir)?;
    tmp.write_all(bytes)?;
    tmp.persist(path).map_err(|e| e.error)?;
    Ok(())
}

/// `write_atomic` of `name` in the open directory `dir`: the temporary file is created,
/// renamed over `name` and (on failure) removed relative to the handle (cap-std, as the
/// confinement that opened it), never through a symlink in its place. The same four system
/// calls as a plain write (open, write, rename, close), where a path through
/// `/proc/self/fd/N/` made the kernel walk it for each.
pub fn write_atomic_at(
    dir: &cap_std::fs::Dir,
    name: &std::ffi::OsStr,
    bytes: &[u8],
) -> std::io::Result<()> {
    use std::sync::atomic::{AtomicU64, Ordering};
    static NEXT: AtomicU64 = AtomicU64::new(0);
    // The process id names this run's temporaries; asked once (each getpid is a system call).
    static PID: std::sync::OnceLock<u32> = std::sync::OnceLock::new();
    let pid = *PID.get_or_init(std::process::id);
    let mut options = cap_std::fs::OpenOptions::new();
    // create_new: O_EXCL, which neither follows nor reuses a symlink or file in its place.
    options.write(true).create_new(true);
    #[cfg(unix)]
    {
        use cap_std::fs::OpenOptionsExt;
        options.mode(0o644);
    }
    // A name taken (by a file left over from a killed run) only moves on to the next.
    for _ in 0..64 {
        let n = NEXT.fetch_add(1, Ordering::Relaxed);
        let tmp = format!(".lispcad-{pid:x}-{n:x}.tmp");
        let mut file = match dir.open_with(&tmp, &options) {
            Ok(f) => f,
            Err(e) if e.kind() == std::io::ErrorKind::AlreadyExists => continue,
            Err(e) => return Err(e),
        };
        let r = file
            .write_all(bytes)
            .and_then(|()| dir.rename(&tmp, dir, name));
        drop(file);
        if r.is_err() {
            let _ = dir.remove_file(&tmp);
        }
        return r;
    }
    Err(std::io::Error::new(
        std::io::ErrorKind::AlreadyExists,
        "no free temporary file name",
    ))
}

#[cfg(test)]
mod tests {
    use super::*;

    #[cfg(unix)]
    #[test]
    fn at_a_directory_handle_replaces_content_and_leaves_no_temporary() {
        let dir = tempfile::tempdir().unwrap();
        let handle =
            cap_std::fs::Dir::open_ambient_dir(dir.path(), cap_std::ambient_authority()).unwrap();
        let handle = &handle;
        let name = std::ffi::OsStr::new("a.txt");
        write_atomic_at(handle, name, b"one").unwrap();
        write_atomic_at(handle, name, b"two!").unwrap();
        let p = dir.path().join("a.txt");
        assert_eq!(std::fs::read(&p).unwrap(), b"two!");
        use std::os::unix::fs::PermissionsExt;
        let mode = std::fs::metadata(&p).unwrap().permissions().mode() & 0o777;
        assert_eq!(mode & 0o600, 0o600, "{mode:o}");
        assert_eq!(mode & 0o111, 0, "{mode:o}");
        let names: Vec<_> = std::fs::read_dir(dir.path()).unwrap().collect();
        assert_eq!(names.len(), 1);
        // A symlink in the target's place is replaced, not followed.
        let outside = tempfile::tempdir().unwrap();
        let victim = outside.path().join("v.txt");
        std::fs::write(&victim, b"keep").unwrap();
        std::os::unix::fs::symlink(&victim, dir.path().join("l.txt")).unwrap();
        write_atomic_at(handle, std::ffi::OsStr::new("l.txt"), b"new").unwrap();
        assert_eq!(std::fs::read(&victim).unwrap(), b"keep");
        assert!(!std::fs::symlink_metadata(dir.path().join("l.txt"))
            .unwrap()
            .file_type()
            .is_symlink());
        // A failed rename (the name is a non-empty directory) leaves no temporary behind.
        std::fs::create_dir(dir.path().join("d")).unwrap();
        std::fs::write(dir.path().join("d/x"), b"x").unwrap();
        assert!(write_atomic_at(handle, std::ffi::OsStr::new("d"), b"x").is_err());
        let mut left: Vec<_> = std::fs::read_dir(dir.path())
            .unwrap()
            .map(|e| e.unwrap().file_name().into_string().unwrap())
            .collect();
        left.sort();
        assert_eq!(left, ["a.txt", "d", "l.txt"]);
    }

    #[test]
    fn replaces_content_and_leaves_no_temporary() {
        let dir = tempfile::tempdir().unwrap();
        let p = dir.path().join("a.txt");
        write_atomic(&p, b"one").unwrap();
        write_atomic(&p, b"two").unwrap();
        assert_eq!(std::fs::read(&p).unwrap(), b"two");
        let names: Vec<_> = std::fs::read_dir(dir.path()).unwrap().collect();
        assert_eq!(names.len(), 1);
    }

    #[test]
    fn missing_directory_is_an_error_and_writes_nothing() {
        let dir = tempfile::tempdir().unwrap();
        let p = dir.path().join("no/such/dir/a.txt");
        assert!(write_atomic(&p, b"x").is_err());
        assert_eq!(std::fs::read_dir(dir.path()).unwrap().count(), 0);
    }
}
