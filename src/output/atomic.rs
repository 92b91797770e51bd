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

#[cfg(test)]
mod tests {
    use super::*;

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
