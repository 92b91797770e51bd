//! Which files a script may touch, enforced without races.
//!
//! Writes stay below the roots (the script's directory and the output directories); with
//! `sandbox`, reads stay below the roots, the extra read directories and the files named on
//! the command line. A path is first placed lexically below a root (no `..`, no absolute
//! escape); its parent directory is then opened *through the root's directory handle* with
//! cap-std, which refuses any symlink leading out of the root (openat2 RESOLVE_BENEATH where
//! the kernel has it, a component-by-component walk otherwise). The file itself is then
//! reached as `/proc/self/fd/N/NAME` from that open directory, so swapping a directory for a
//! symlink after the check changes nothing, and opened with O_NOFOLLOW. A file with more than
//! one hard link is not written in place (it could be a link to a file outside). Sandboxed
//! reads (open, stat, directory listing) resolve the whole path through the root's handle
//! with cap-std: a symlink is followed only while it stays below the root, atomically with
//! the open, so no swap between a check and the read can lead out.

use std::ffi::{OsStr, OsString};
use std::fs::File;
use std::io::Read;
use std::path::{Component, Path, PathBuf};
use std::rc::Rc;
use std::sync::OnceLock;

/// The policy of one run; `Default` (no roots) confines writes to the current directory.
#[derive(Default, Clone, Debug)]
pub struct FsPolicy {
    /// `--allow-fs`: no confinement at all.
    pub allow_all: bool,
    /// Directories below which the script may write (and, sandboxed, read).
    pub roots: Vec<PathBuf>,
    /// `--sandbox`: reads confined too, `getenv` answers nil.
    pub sandbox: bool,
    /// Sandboxed reads may also go below these (`--allow-read DIR`).
    pub read_roots: Vec<PathBuf>,
    /// Sandboxed reads may also open exactly these (files named on the command line).
    pub read_files: Vec<PathBuf>,
}

/// A path the policy allows, as the caller must use it: through the directory handle kept
/// here when confined. Drop it only after the file operation.
pub struct Confined {
    dir: Option<Rc<cap_std::fs::Dir>>,
    /// The file's name in `dir` (None: the path is `dir` itself, or not confined).
    name: Option<OsString>,
    /// Which directory `dir` is (the root, and the parent below it), for `confine_after`.
    key: Option<(PathBuf, PathBuf)>,
    pub path: PathBuf,
}

impl Confined {
    /// The open directory and the file's name in it, for calls relative to the directory
    /// (`openat`, `renameat`): the same file as `path` without the kernel walking
    /// `/proc/self/fd/N/` again for each call.
    pub fn dir_and_name(&self) -> Option<(&cap_std::fs::Dir, &OsStr)> {
        match (&self.dir, &self.name) {
            (Some(d), Some(n)) => Some((d, n.as_os_str())),
            _ => None,
        }
    }
}

#[derive(Clone, Copy, PartialEq)]
pub enum Access {
    Read,
    Write,
}

fn refused(path: &Path, access: Access, why: &str) -> String {
    match access {
        Access::Write => format!(
            "file access refused: {} {why} (use --allow-fs)",
            path.display()
        ),
        Access::Read => format!(
            "file access refused: {} {why} (--sandbox; use --allow-read DIR)",
            path.display()
        ),
    }
}

/// The current directory, asked of the kernel once per process: nothing in lispcad changes
/// it, and a batch resolves two paths or more per row.
fn current_dir() -> Option<&'static Path> {
    static CWD: OnceLock<Option<PathBuf>> = OnceLock::new();
    CWD.get_or_init(|| std::env::current_dir().ok()).as_deref()
}

/// `path` made absolute against the current directory, `.` dropped; None if it has `..`.
fn absolute_in(path: &Path) -> Option<PathBuf> {
    let abs = if path.is_absolute() {
        path.to_path_buf()
    } else {
        current_dir()?.join(path)
    };
    let mut out = PathBuf::new();
    for c in abs.components() {
        match c {
            Component::ParentDir => return None,
            Component::CurDir => {}
            other => out.push(other),
        }
    }
    Some(out)
}

impl FsPolicy {
    /// The policy for a script and its outputs: both directories are write roots.
    pub fn for_script(script: Option<&Path>, outputs: &[PathBuf]) -> FsPolicy {
        let dir = |p: &Path| match p.parent() {
            Some(d) if !d.as_os_str().is_empty() => d.to_path_buf(),
            _ => PathBuf::from("."),
        };
        FsPolicy {
            roots: script
                .map(dir)
                .into_iter()
                .chain(outputs.iter().map(|o| dir(o)))
                .collect(),
            ..FsPolicy::default()
        }
    }

    fn write_roots(&self) -> Vec<PathBuf> {
        if self.roots.is_empty() {
            vec![PathBuf::from(".")]
        } else {
            self.roots.clone()
        }
    }

    /// Whether writing `path` would be allowed (a lexical check; the write itself goes
    /// through `confine`).
    pub fn may_write(&self, path: &Path) -> bool {
        self.allow_all || self.confine(path, Access::Write).is_ok()
    }

    /// Whether reading `path` is allowed.
    pub fn may_read(&self, path: &Path) -> bool {
        !self.sandbox || self.allow_all || self.stat(path).is_ok_and(|m| m.is_some())
    }

    /// Where `path` lies for `access`: anywhere (not confined), or below a root (the root as
    /// the path names it, and the rest). A lexical check: nothing is opened yet.
    fn locate(&self, path: &Path, access: Access) -> Result<Place, String> {
        let free = self.allow_all || (access == Access::Read && !self.sandbox);
        if free {
            return Ok(Place::Free);
        }
        let abs = absolute_in(path).ok_or_else(|| refused(path, access, "contains `..`"))?;
        if access == Access::Read {
            for f in &self.read_files {
                if absolute_in(f).as_deref() == Some(&abs) {
                    return Ok(Place::Free);
                }
            }
        }
        let mut roots = self.write_roots();
        if access == Access::Read {
            roots.extend(self.read_roots.iter().cloned());
        }
        // The roots as given, then as the kernel resolves them: the path may use either. The
        // resolved forms only when no given form holds the path (resolving walks every
        // component with a system call; a batch writes thousands of files).
        let beneath = |r: &Path, root: &Path| {
            abs.strip_prefix(r).ok().map(|rel| Place::Beneath {
                root: r.to_path_buf(),
                shown: root.to_path_buf(),
                rel: rel.to_path_buf(),
            })
        };
        for root in &roots {
            if let Some(p) = absolute_in(root).and_then(|r| beneath(&r, root)) {
                return Ok(p);
            }
        }
        for root in &roots {
            if let Some(p) = root.canonicalize().ok().and_then(|r| beneath(&r, root)) {
                return Ok(p);
            }
        }
        Err(refused(
            path,
            access,
            "is outside the script and output directories",
        ))
    }

    /// The path to use for `access` to `path`, or the refusal message.
    pub fn confine(&self, path: &Path, access: Access) -> Result<Confined, String> {
        self.confine_after(path, access, None)
    }

    /// `confine`, reusing the directory handle of `prev` (confined just before by this
    /// policy) when `path` lies in the same directory below the same root: a run writing
    /// `a.dxf` and `a.svg` side by side opens their directory once.
    pub fn confine_after(
        &self,
        path: &Path,
        access: Access,
        prev: Option<&Confined>,
    ) -> Result<Confined, String> {
        match self.locate(path, access)? {
            Place::Free => Ok(Confined {
                dir: None,
                name: None,
                key: None,
                path: path.to_path_buf(),
            }),
            Place::Beneath { root, shown, rel } => {
                if let (Some(prev), Some(name)) = (prev, rel.file_name()) {
                    let parent = rel.parent().unwrap_or(Path::new("")).to_path_buf();
                    if let (Some(dir), Some(key)) = (&prev.dir, &prev.key) {
                        if key.0 == root && key.1 == parent && prev.name.is_some() {
                            return Ok(through(dir.clone(), Some(name), (root, parent)));
                        }
                    }
                }
                open_beneath(&root, &rel).map_err(|e| {
                    refused(
                        path,
                        access,
                        &format!("cannot be reached below {}: {e}", shown.display()),
                    )
                })
            }
        }
    }

    /// For a confined read: the root's directory handle and the path below it, which every
    /// read then resolves through cap-std (symlinks followed only while they stay below the
    /// root, atomically with the open). `None`: reads are not confined for this path.
    fn read_place(&self, path: &Path) -> Result<Option<(cap_std::fs::Dir, PathBuf)>, String> {
        match self.locate(path, Access::Read)? {
            Place::Free => Ok(None),
            Place::Beneath { root, shown, rel } => {
                let dir = cap_std::fs::Dir::open_ambient_dir(&root, cap_std::ambient_authority())
                    .map_err(|e| {
                    refused(
                        path,
                        Access::Read,
                        &format!("cannot be reached below {}: {e}", shown.display()),
                    )
                })?;
                let rel = if rel.as_os_str().is_empty() {
                    PathBuf::from(".")
                } else {
                    rel
                };
                Ok(Some((dir, rel)))
            }
        }
    }

    /// A failed confined read: an escape through a symlink is a refusal, anything else the
    /// ordinary I/O error.
    fn read_failed(path: &Path, e: std::io::Error) -> String {
        // cap-std reports an escape as a non-OS PermissionDenied ("a path led outside...").
        if e.kind() == std::io::ErrorKind::PermissionDenied && e.raw_os_error().is_none() {
            refused(path, Access::Read, "leads outside the allowed directories")
        } else {
            format!("cannot open {}: {e}", path.display())
        }
    }

    /// Opens `path` for writing in place ("w" truncates, "a" appends, `new` must not exist):
    /// confined, never through a symlink, and never into a file with other hard links.
    pub fn open_write(&self, path: &Path, append: bool, new: bool) -> Result<File, String> {
        use std::os::unix::fs::{MetadataExt, OpenOptionsExt};
        let c = self.confine(path, Access::Write)?;
        let mut o = std::fs::OpenOptions::new();
        o.write(true).mode(0o644);
        if new {
            o.create_new(true);
        } else {
            o.create(true).append(append);
        }
        if !self.allow_all {
            o.custom_flags(libc::O_NOFOLLOW);
        }
        let f = o
            .open(&c.path)
            .map_err(|e| format!("cannot open {} for writing: {e}", path.display()))?;
        let meta = f
            .metadata()
            .map_err(|e| format!("cannot open {} for writing: {e}", path.display()))?;
        if !self.allow_all && meta.nlink() > 1 {
            return Err(format!(
                "file access refused: {} has {} hard links and may be a file outside (use --allow-fs)",
                path.display(),
                meta.nlink()
            ));
        }
        if !append && !new {
            f.set_len(0)
                .map_err(|e| format!("cannot truncate {}: {e}", path.display()))?;
        }
        Ok(f)
    }

    /// Opens `path` for reading; under --sandbox through the root's directory handle, so no
    /// symlink or swapped directory leads out of it, however the tree changes meanwhile.
    pub fn open_read(&self, path: &Path) -> Result<File, String> {
        match self.read_place(path)? {
            None => File::open(path).map_err(|e| format!("cannot open {}: {e}", path.display())),
            Some((dir, rel)) => dir
                .open(&rel)
                .map(cap_std::fs::File::into_std)
                .map_err(|e| Self::read_failed(path, e)),
        }
    }

    /// Whether `path` exists and is a directory, and its size: `Ok(None)` when it does not
    /// exist (or cannot be examined), a refusal when it lies (or leads) outside under --sandbox.
    pub fn stat(&self, path: &Path) -> Result<Option<(bool, u64)>, String> {
        match self.read_place(path)? {
            None => Ok(std::fs::metadata(path).ok().map(|m| (m.is_dir(), m.len()))),
            Some((dir, rel)) => match dir.metadata(&rel) {
                Ok(m) => Ok(Some((m.is_dir(), m.len()))),
                Err(e) if e.kind() == std::io::ErrorKind::PermissionDenied => {
                    Err(Self::read_failed(path, e))
                }
                Err(_) => Ok(None),
            },
        }
    }

    /// The entries of directory `path` (name, is a directory), `Ok(None)` if it cannot be
    /// listed; confined like `open_read`.
    pub fn list_dir(&self, path: &Path) -> Result<Option<Vec<(String, bool)>>, String> {
        let name = |n: std::ffi::OsString| n.to_string_lossy().into_owned();
        match self.read_place(path)? {
            None => Ok(std::fs::read_dir(path).ok().map(|entries| {
                entries
                    .filter_map(Result::ok)
                    .map(|e| (name(e.file_name()), e.file_type().is_ok_and(|t| t.is_dir())))
                    .collect()
            })),
            Some((dir, rel)) => match dir.read_dir(&rel) {
                Ok(entries) => Ok(Some(
                    entries
                        .filter_map(Result::ok)
                        .map(|e| (name(e.file_name()), e.file_type().is_ok_and(|t| t.is_dir())))
                        .collect(),
                )),
                Err(e) if e.kind() == std::io::ErrorKind::PermissionDenied => {
                    Err(Self::read_failed(path, e))
                }
                Err(_) => Ok(None),
            },
        }
    }

    /// The whole file at `path`, read as `open_read` opens it, within the memory budget.
    pub fn read_bytes(&self, path: &Path) -> Result<Vec<u8>, ReadError> {
        let f = self.open_read(path).map_err(ReadError::Open)?;
        read_all(f).map_err(|e| match e {
            ReadError::Open(m) => ReadError::Open(format!("cannot read {}: {m}", path.display())),
            other => other,
        })
    }
}

/// Why a whole-file read failed: the file could not be opened (or read), or it does not fit
/// in the memory budget.
pub enum ReadError {
    Open(String),
    Memory(crate::lang::Exn),
}

impl From<ReadError> for crate::lang::Exn {
    fn from(e: ReadError) -> Self {
        match e {
            ReadError::Open(m) => crate::lang::error::err(m),
            ReadError::Memory(e) => e,
        }
    }
}

/// Reads `r` to its end in chunks, asking the memory budget before the buffer grows and
/// growing it fallibly, so a huge (or endless) file is an "out of memory" error, never an
/// allocation failure that aborts.
pub fn read_all(mut r: impl std::io::Read) -> Result<Vec<u8>, ReadError> {
    const CHUNK: usize = 1 << 16;
    let mut out: Vec<u8> = Vec::new();
    loop {
        if out.capacity() - out.len() < CHUNK {
            // Doubling, as Vec would, but checked first.
            let more = out.capacity().max(CHUNK);
            crate::lang::memory::reserve(more).map_err(ReadError::Memory)?;
            out.try_reserve_exact(more)
                .map_err(|_| ReadError::Memory(crate::lang::memory::system_refused(more)))?;
        }
        // At most the room there is, so read_to_end never grows the buffer itself.
        let room = out.capacity() - out.len();
        let n = (&mut r)
            .take(room as u64)
            .read_to_end(&mut out)
            .map_err(|e| ReadError::Open(e.to_string()))?;
        if n < room {
            return Ok(out);
        }
    }
}

/// Where a path lies for the policy.
enum Place {
    /// Not confined: used as named.
    Free,
    /// Below `root` (absolute, in the form the path used; `shown` as configured) at `rel`.
    Beneath {
        root: PathBuf,
        shown: PathBuf,
        rel: PathBuf,
    },
}

/// Opens the parent of `rel` below `root` and names the file through that handle.
fn open_beneath(root: &Path, rel: &Path) -> std::io::Result<Confined> {
    let key = (
        root.to_path_buf(),
        rel.parent().unwrap_or(Path::new("")).to_path_buf(),
    );
    let name = match rel.file_name() {
        Some(n) => n.to_owned(),
        // The root itself (e.g. `vl-directory-files` of the script directory).
        None => {
            let dir = cap_std::fs::Dir::open_ambient_dir(root, cap_std::ambient_authority())?;
            return Ok(through(Rc::new(dir), None, key));
        }
    };
    let root_dir = cap_std::fs::Dir::open_ambient_dir(root, cap_std::ambient_authority())?;
    let parent = rel.parent().filter(|p| !p.as_os_str().is_empty());
    let dir = match parent {
        Some(p) => root_dir.open_dir(p)?,
        None => root_dir,
    };
    Ok(through(Rc::new(dir), Some(&name), key))
}

fn through(dir: Rc<cap_std::fs::Dir>, name: Option<&OsStr>, key: (PathBuf, PathBuf)) -> Confined {
    use std::os::fd::AsRawFd;
    let base = PathBuf::from(format!("/proc/self/fd/{}", dir.as_raw_fd()));
    let path = match name {
        Some(n) => base.join(n),
        None => base,
    };
    Confined {
        dir: Some(dir),
        name: name.map(OsStr::to_os_string),
        key: Some(key),
        path,
    }
}
