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
//!
//! A batch opens its output directories once per worker, not once per file: [`DirCache`] keeps
//! the handles of the roots and of the directories below them that outputs were written to,
//! and the worker carries it from row to row. Those handles are capabilities. A directory moved
//! (or replaced by a symlink) while the handle is held keeps receiving the outputs at its new
//! place, and a symlink put in its place is never followed; the same as for one file without
//! the cache, held for longer. A directory removed while held cannot take new files (the
//! kernel refuses to create in it); the handle is then dropped and the directory opened
//! afresh by its path, so a directory re-created there receives the output and a missing one
//! is an error naming it, never a silently lost file. A script's own `vl-file-rename` empties
//! the cache, so a script never writes through a handle to a directory it moved. Outside a
//! batch (`run`, the REPL, `watch`) no handle outlives the call that wrote the outputs.

use std::cell::RefCell;
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
    /// The output directories opened so far (shared by clones; see [`DirCache`]).
    pub dirs: DirCache,
}

/// Directory handles opened for outputs, keyed by (root, directory below it): the root's own
/// handle has the empty path below it. A few handles at most (the oldest is closed past
/// [`DirCache::MAX`]), so a batch writing each row into a directory of its own does not run
/// out of descriptors. Off by default (each write opens its directory by path, as a REPL or
/// `watch` session that lives for hours should); a batch worker makes one with
/// [`DirCache::new`] and gives it to each row's policy, and one run's `-o` files share one
/// for their call. A key names a root, and a lookup is made only after the path was placed
/// below one of the current policy's roots, so a handle never serves a policy that does not
/// allow its root.
#[derive(Default, Clone)]
pub struct DirCache(Option<Rc<RefCell<Vec<CachedDir>>>>);

struct CachedDir {
    root: PathBuf,
    below: PathBuf,
    dir: Rc<cap_std::fs::Dir>,
}

impl std::fmt::Debug for DirCache {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        write!(f, "DirCache({} open)", self.len())
    }
}

impl DirCache {
    /// Handles kept at most (roots and directories below them).
    pub const MAX: usize = 16;

    /// A cache that keeps handles (the default keeps none).
    pub fn new() -> DirCache {
        DirCache(Some(Rc::default()))
    }

    /// Whether handles are kept.
    pub fn is_on(&self) -> bool {
        self.0.is_some()
    }

    fn get(&self, root: &Path, below: &Path) -> Option<Rc<cap_std::fs::Dir>> {
        self.0
            .as_ref()?
            .borrow()
            .iter()
            .find(|c| c.root == root && c.below == below)
            .map(|c| c.dir.clone())
    }

    fn put(&self, root: &Path, below: &Path, dir: Rc<cap_std::fs::Dir>) {
        let Some(v) = &self.0 else { return };
        let mut v = v.borrow_mut();
        if v.len() >= Self::MAX {
            v.remove(0);
        }
        v.push(CachedDir {
            root: root.to_path_buf(),
            below: below.to_path_buf(),
            dir,
        });
    }

    /// Closes every handle (a directory may have moved: the next write opens it by path).
    pub fn clear(&self) {
        if let Some(v) = &self.0 {
            v.borrow_mut().clear();
        }
    }

    /// The number of handles held.
    pub fn len(&self) -> usize {
        self.0.as_ref().map_or(0, |v| v.borrow().len())
    }

    pub fn is_empty(&self) -> bool {
        self.len() == 0
    }
}

/// A path the policy allows, as the caller must use it: through the directory handle kept
/// here when confined. Drop it only after the file operation.
pub struct Confined {
    dir: Option<Rc<cap_std::fs::Dir>>,
    /// The file's name in `dir` (None: the path is `dir` itself, or not confined).
    name: Option<OsString>,
    /// Whether `dir` came from the policy's [`DirCache`] (it may since have been removed).
    cached: bool,
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

    /// Whether the directory handle was one already held (see [`FsPolicy::confine_output`]).
    pub fn was_cached(&self) -> bool {
        self.cached
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
        match self.locate(path, access)? {
            Place::Free => Ok(free(path)),
            Place::Beneath { root, shown, rel } => {
                open_beneath(&root, &rel).map_err(|e| unreachable_below(path, access, &shown, &e))
            }
        }
    }

    /// `confine` for writing an output file, through the directory handles of [`DirCache`]:
    /// the outputs of a run (and of a batch worker's rows) open their directory once. A handle
    /// held may belong to a directory removed since; a write through it fails with
    /// `NotFound` (see [`Confined::was_cached`]), and the caller then clears the cache and
    /// confines again.
    pub fn confine_output(&self, path: &Path) -> Result<Confined, String> {
        let (root, shown, rel) = match self.locate(path, Access::Write)? {
            Place::Free => return Ok(free(path)),
            Place::Beneath { root, shown, rel } => (root, shown, rel),
        };
        let Some(name) = rel.file_name() else {
            return self.confine(path, Access::Write);
        };
        let below = rel.parent().unwrap_or(Path::new(""));
        if let Some(dir) = self.dirs.get(&root, below) {
            return Ok(through(dir, Some(name), true));
        }
        let opened = self.open_dir_below(&root, below).or_else(|e| {
            // The root's handle held may be of a removed directory: once more by its path.
            if e.kind() == std::io::ErrorKind::NotFound && !self.dirs.is_empty() {
                self.dirs.clear();
                self.open_dir_below(&root, below)
            } else {
                Err(e)
            }
        });
        match opened {
            Ok(dir) => Ok(through(dir, Some(name), false)),
            Err(e) => Err(unreachable_below(path, Access::Write, &shown, &e)),
        }
    }

    /// The directory `below` the root (both kept in the cache), opened through the root's
    /// handle so that no symlink leads out.
    fn open_dir_below(&self, root: &Path, below: &Path) -> std::io::Result<Rc<cap_std::fs::Dir>> {
        let top = Path::new("");
        let root_dir = match self.dirs.get(root, top) {
            Some(d) => d,
            None => {
                let d = Rc::new(cap_std::fs::Dir::open_ambient_dir(
                    root,
                    cap_std::ambient_authority(),
                )?);
                self.dirs.put(root, top, d.clone());
                d
            }
        };
        if below.as_os_str().is_empty() {
            return Ok(root_dir);
        }
        let d = Rc::new(root_dir.open_dir(below)?);
        self.dirs.put(root, below, d.clone());
        Ok(d)
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

fn free(path: &Path) -> Confined {
    Confined {
        dir: None,
        name: None,
        cached: false,
        path: path.to_path_buf(),
    }
}

fn unreachable_below(path: &Path, access: Access, shown: &Path, e: &std::io::Error) -> String {
    refused(
        path,
        access,
        &format!("cannot be reached below {}: {e}", shown.display()),
    )
}

/// Opens the parent of `rel` below `root` and names the file through that handle.
fn open_beneath(root: &Path, rel: &Path) -> std::io::Result<Confined> {
    let name = match rel.file_name() {
        Some(n) => n.to_owned(),
        // The root itself (e.g. `vl-directory-files` of the script directory).
        None => {
            let dir = cap_std::fs::Dir::open_ambient_dir(root, cap_std::ambient_authority())?;
            return Ok(through(Rc::new(dir), None, false));
        }
    };
    let root_dir = cap_std::fs::Dir::open_ambient_dir(root, cap_std::ambient_authority())?;
    let parent = rel.parent().filter(|p| !p.as_os_str().is_empty());
    let dir = match parent {
        Some(p) => root_dir.open_dir(p)?,
        None => root_dir,
    };
    Ok(through(Rc::new(dir), Some(&name), false))
}

fn through(dir: Rc<cap_std::fs::Dir>, name: Option<&OsStr>, cached: bool) -> Confined {
    use std::os::fd::AsRawFd;
    let base = PathBuf::from(format!("/proc/self/fd/{}", dir.as_raw_fd()));
    let path = match name {
        Some(n) => base.join(n),
        None => base,
    };
    Confined {
        dir: Some(dir),
        name: name.map(OsStr::to_os_string),
        cached,
        path,
    }
}
