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
//! one hard link is not written in place (it could be a link to a file outside).

use std::fs::File;
use std::path::{Component, Path, PathBuf};

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
    _dir: Option<cap_std::fs::Dir>,
    pub path: PathBuf,
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

/// `path` made absolute against the current directory, `.` dropped; None if it has `..`.
fn absolute(path: &Path) -> Option<PathBuf> {
    let abs = if path.is_absolute() {
        path.to_path_buf()
    } else {
        std::env::current_dir().ok()?.join(path)
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
        !self.sandbox || self.allow_all || self.confine(path, Access::Read).is_ok()
    }

    /// The path to use for `access` to `path`, or the refusal message.
    pub fn confine(&self, path: &Path, access: Access) -> Result<Confined, String> {
        let free = self.allow_all || (access == Access::Read && !self.sandbox);
        if free {
            return Ok(Confined {
                _dir: None,
                path: path.to_path_buf(),
            });
        }
        let abs = absolute(path).ok_or_else(|| refused(path, access, "contains `..`"))?;
        if access == Access::Read {
            for f in &self.read_files {
                if absolute(f).as_deref() == Some(&abs) {
                    return Ok(Confined {
                        _dir: None,
                        path: path.to_path_buf(),
                    });
                }
            }
        }
        let mut roots = self.write_roots();
        if access == Access::Read {
            roots.extend(self.read_roots.iter().cloned());
        }
        for root in &roots {
            // The root as given and as the kernel resolves it: the path may use either.
            let forms = [absolute(root), root.canonicalize().ok()];
            for r in forms.iter().flatten() {
                if let Ok(rel) = abs.strip_prefix(r) {
                    return open_beneath(r, rel).map_err(|e| {
                        refused(
                            path,
                            access,
                            &format!("cannot be reached below {}: {e}", root.display()),
                        )
                    });
                }
            }
        }
        Err(refused(
            path,
            access,
            "is outside the script and output directories",
        ))
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

    /// Opens `path` for reading (confined under --sandbox).
    pub fn open_read(&self, path: &Path) -> Result<File, String> {
        use std::os::unix::fs::OpenOptionsExt;
        let c = self.confine(path, Access::Read)?;
        let mut o = std::fs::OpenOptions::new();
        o.read(true);
        if self.sandbox && !self.allow_all && c._dir.is_some() {
            // A symlink named below a root could lead anywhere: sandboxed reads do not follow.
            o.custom_flags(libc::O_NOFOLLOW);
        }
        o.open(&c.path)
            .map_err(|e| format!("cannot open {}: {e}", path.display()))
    }
}

/// Opens the parent of `rel` below `root` and names the file through that handle.
fn open_beneath(root: &Path, rel: &Path) -> std::io::Result<Confined> {
    let name = match rel.file_name() {
        Some(n) => n.to_owned(),
        // The root itself (e.g. `vl-directory-files` of the script directory).
        None => {
            let dir = cap_std::fs::Dir::open_ambient_dir(root, cap_std::ambient_authority())?;
            return Ok(through(dir, None));
        }
    };
    let root_dir = cap_std::fs::Dir::open_ambient_dir(root, cap_std::ambient_authority())?;
    let parent = rel.parent().filter(|p| !p.as_os_str().is_empty());
    let dir = match parent {
        Some(p) => root_dir.open_dir(p)?,
        None => root_dir,
    };
    Ok(through(dir, Some(&name)))
}

fn through(dir: cap_std::fs::Dir, name: Option<&std::ffi::OsStr>) -> Confined {
    use std::os::fd::AsRawFd;
    let base = PathBuf::from(format!("/proc/self/fd/{}", dir.as_raw_fd()));
    let path = match name {
        Some(n) => base.join(n),
        None => base,
    };
    Confined {
        _dir: Some(dir),
        path,
    }
}
