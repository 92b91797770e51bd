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

/// `write_atomic` of `name` in the open directory `dir`: the file is created, given its name
/// and (on failure) removed relative to the handle (as the confinement that opened it), never
/// through a symlink in its place. Four system calls (open, write, link or rename, close),
/// where a path through `/proc/self/fd/N/` made the kernel walk it for each.
///
/// On Linux the file is made unnamed (O_TMPFILE) and then linked in under `name`: the kernel
/// allocates its inode without holding the directory's lock (a named temporary is created
/// under it), so two workers writing into one directory do not wait on each other, and no
/// temporary name ever appears. Where `name` exists already, the file is linked under a
/// temporary name and renamed over it; where the file system has no unnamed files, it is
/// created under the temporary name.
pub fn write_atomic_at(
    dir: &cap_std::fs::Dir,
    name: &std::ffi::OsStr,
    bytes: &[u8],
) -> std::io::Result<()> {
    // Once a name was found taken, this run is most likely rewriting earlier outputs (a batch
    // run again): the named way then takes the four calls, where the unnamed one would take
    // six (a failed link, a link under the temporary name, the rename).
    #[cfg(target_os = "linux")]
    {
        use std::sync::atomic::{AtomicBool, Ordering};
        static REPLACING: AtomicBool = AtomicBool::new(false);
        if !REPLACING.load(Ordering::Relaxed) {
            let mut taken = false;
            if let Some(r) = write_unnamed_at(dir, name, bytes, &mut taken) {
                if taken {
                    REPLACING.store(true, Ordering::Relaxed);
                }
                return r;
            }
        }
    }
    write_named_at(dir, name, bytes)
}

/// `write_atomic_at` through an unnamed file; None where one cannot be made. `taken` is set
/// when `name` existed (the file is then linked under a temporary name and renamed over it).
#[cfg(target_os = "linux")]
fn write_unnamed_at(
    dir: &cap_std::fs::Dir,
    name: &std::ffi::OsStr,
    bytes: &[u8],
    taken: &mut bool,
) -> Option<std::io::Result<()>> {
    let mut file = unnamed::create(dir)?;
    if let Err(e) = file.write_all(bytes) {
        return Some(Err(e));
    }
    Some(match unnamed::link(&file, dir, name) {
        Err(e) if e.kind() == std::io::ErrorKind::AlreadyExists => {
            *taken = true;
            replace_through_temporary(dir, name, |tmp| unnamed::link(&file, dir, tmp))
        }
        r => r,
    })
}

/// `write_atomic_at` through a named temporary file (where there are no unnamed files).
fn write_named_at(
    dir: &cap_std::fs::Dir,
    name: &std::ffi::OsStr,
    bytes: &[u8],
) -> std::io::Result<()> {
    let mut options = cap_std::fs::OpenOptions::new();
    // create_new: O_EXCL, which neither follows nor reuses a symlink or file in its place.
    options.write(true).create_new(true);
    #[cfg(unix)]
    {
        use cap_std::fs::OpenOptionsExt;
        options.mode(0o644);
    }
    replace_through_temporary(dir, name, |tmp| {
        let mut file = dir.open_with(tmp, &options)?;
        file.write_all(bytes)
    })
}

/// Makes the file under a fresh temporary name with `make` (which fails with
/// `AlreadyExists` if the name is taken), then renames it over `name`; removes it on failure.
fn replace_through_temporary(
    dir: &cap_std::fs::Dir,
    name: &std::ffi::OsStr,
    mut make: impl FnMut(&std::ffi::OsStr) -> std::io::Result<()>,
) -> std::io::Result<()> {
    use std::sync::atomic::{AtomicU64, Ordering};
    static NEXT: AtomicU64 = AtomicU64::new(0);
    // The process id names this run's temporaries; asked once (each getpid is a system call).
    static PID: std::sync::OnceLock<u32> = std::sync::OnceLock::new();
    let pid = *PID.get_or_init(std::process::id);
    // A name taken (by a file left over from a killed run) only moves on to the next.
    for _ in 0..64 {
        let n = NEXT.fetch_add(1, Ordering::Relaxed);
        let mut buf = [0u8; 48];
        let tmp = temporary_name(&mut buf, pid, n);
        match make(tmp) {
            Ok(()) => {}
            Err(e) if e.kind() == std::io::ErrorKind::AlreadyExists => continue,
            Err(e) => {
                let _ = dir.remove_file(tmp);
                return Err(e);
            }
        }
        let r = dir.rename(tmp, dir, name);
        if r.is_err() {
            let _ = dir.remove_file(tmp);
        }
        return r;
    }
    Err(std::io::Error::new(
        std::io::ErrorKind::AlreadyExists,
        "no free temporary file name",
    ))
}

/// `.lispcad-PID-N.tmp` (hexadecimal), written into `buf` without allocating.
fn temporary_name(buf: &mut [u8; 48], pid: u32, n: u64) -> &std::ffi::OsStr {
    use std::os::unix::ffi::OsStrExt;
    let mut w = &mut buf[..];
    write!(w, ".lispcad-{pid:x}-{n:x}.tmp").expect("48 bytes hold the longest name");
    let len = 48 - w.len();
    std::ffi::OsStr::from_bytes(&buf[..len])
}

/// Unnamed files (O_TMPFILE) and linking one in by its descriptor.
#[cfg(target_os = "linux")]
mod unnamed {
    use std::fs::File;
    use std::os::fd::{AsRawFd, FromRawFd};

    /// An unnamed regular file in `dir` (mode 0644 before the umask), or None if it cannot
    /// be made: the file system has none (EOPNOTSUPP; EISDIR from kernels older than
    /// O_TMPFILE), or any other failure (EPERM in a removed directory, EACCES...), which the
    /// named way then meets and reports as it always has.
    pub fn create(dir: &cap_std::fs::Dir) -> Option<File> {
        let flags = libc::O_TMPFILE | libc::O_WRONLY | libc::O_CLOEXEC;
        // SAFETY: a valid descriptor and a NUL-terminated path; the descriptor returned is
        // owned by the File made of it.
        let fd = unsafe { libc::openat(dir.as_raw_fd(), c".".as_ptr(), flags, 0o644) };
        // SAFETY: fd was just opened and nothing else owns it.
        (fd >= 0).then(|| unsafe { File::from_raw_fd(fd) })
    }

    /// Gives `file` the name `name` in `dir` (`AlreadyExists` if it is taken, by anything,
    /// a symlink included: the new name is never followed). Through `/proc/self/fd/N`, as
    /// open(2) documents for O_TMPFILE (linking by the descriptor itself needs a privilege).
    pub fn link(
        file: &File,
        dir: &cap_std::fs::Dir,
        name: &std::ffi::OsStr,
    ) -> std::io::Result<()> {
        use std::io::Write;
        use std::os::unix::ffi::OsStrExt;
        let mut from = [0u8; 32];
        let mut w = &mut from[..];
        write!(w, "/proc/self/fd/{}\0", file.as_raw_fd()).expect("32 bytes hold the path");
        // A file name is at most 255 bytes (NAME_MAX).
        let mut to = [0u8; 256];
        let n = name.as_bytes();
        if n.len() >= to.len() || n.contains(&0) {
            return Err(std::io::ErrorKind::InvalidFilename.into());
        }
        to[..n.len()].copy_from_slice(n);
        // SAFETY: both paths are NUL-terminated and outlive the call.
        let r = unsafe {
            libc::linkat(
                libc::AT_FDCWD,
                from.as_ptr().cast(),
                dir.as_raw_fd(),
                to.as_ptr().cast(),
                libc::AT_SYMLINK_FOLLOW,
            )
        };
        if r == 0 {
            Ok(())
        } else {
            Err(std::io::Error::last_os_error())
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn temporary_names_are_the_formatted_ones() {
        let mut buf = [0u8; 48];
        assert_eq!(temporary_name(&mut buf, 0x1f, 255), ".lispcad-1f-ff.tmp");
        let want = format!(".lispcad-{:x}-{:x}.tmp", u32::MAX, u64::MAX);
        assert_eq!(temporary_name(&mut buf, u32::MAX, u64::MAX), want.as_str());
    }

    #[cfg(unix)]
    #[test]
    fn at_a_directory_handle_replaces_content_and_leaves_no_temporary() {
        // The unnamed way (where the file system has it), the named one, and the choice.
        #[cfg(target_os = "linux")]
        at_a_directory_handle(|dir, name, bytes| {
            // Where the file system has no unnamed files, the named way stands in.
            write_unnamed_at(dir, name, bytes, &mut false)
                .unwrap_or_else(|| write_named_at(dir, name, bytes))
        });
        at_a_directory_handle(write_named_at);
        at_a_directory_handle(write_atomic_at);
    }

    #[cfg(unix)]
    fn at_a_directory_handle(
        write_atomic_at: fn(&cap_std::fs::Dir, &std::ffi::OsStr, &[u8]) -> std::io::Result<()>,
    ) {
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
