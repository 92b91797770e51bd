//! Waiting for a save of any of a run's files. Directories are watched, not files: editors
//! often replace a file by renaming a new one over it. Used by `watch` and `serve`.

use std::path::PathBuf;
use std::sync::mpsc;
use std::time::{Duration, SystemTime};

use notify::{RecommendedWatcher, RecursiveMode, Watcher};

pub struct Changes {
    watcher: RecommendedWatcher,
    rx: mpsc::Receiver<Vec<PathBuf>>,
    dirs: Vec<PathBuf>,
}

impl Changes {
    pub fn new() -> notify::Result<Changes> {
        let (tx, rx) = mpsc::channel();
        let watcher = notify::recommended_watcher(move |ev: notify::Result<notify::Event>| {
            if let Ok(ev) = ev {
                if ev.kind.is_modify() || ev.kind.is_create() || ev.kind.is_remove() {
                    let _ = tx.send(ev.paths);
                }
            }
        })?;
        Ok(Changes {
            watcher,
            rx,
            dirs: Vec::new(),
        })
    }

    /// Blocks until one of `files` changes after `since` (when the run that read them
    /// started), then lets a burst of events settle (an editor's save is several). False when
    /// the watcher has stopped. `settle`: how long the events must pause.
    pub fn wait(&mut self, files: &[PathBuf], since: SystemTime, settle: Duration) -> bool {
        let files: Vec<PathBuf> = files.iter().filter_map(|f| f.canonicalize().ok()).collect();
        for f in &files {
            if let Some(d) = f.parent() {
                if !self.dirs.iter().any(|x| x == d) {
                    if let Err(e) = self.watcher.watch(d, RecursiveMode::NonRecursive) {
                        eprintln!("warning: cannot watch {}: {e}", d.display());
                    }
                    self.dirs.push(d.to_path_buf());
                }
            }
        }
        // A directory is only watched from here on: a save during the run, or before the
        // watch was added, shows in the file's time alone. A time ahead of the clock (a file
        // from an archive) is not a save, or it would re-run forever.
        let now = SystemTime::now();
        let saved_meanwhile = files.iter().any(|f| {
            std::fs::metadata(f)
                .and_then(|m| m.modified())
                .is_ok_and(|t| t > since && t <= now)
        });
        if !saved_meanwhile {
            loop {
                let Ok(paths) = self.rx.recv() else {
                    return false;
                };
                let hit = paths.iter().any(|p| {
                    let p = p.canonicalize().unwrap_or_else(|_| p.clone());
                    files.contains(&p)
                });
                if hit {
                    break;
                }
            }
        }
        while self.rx.recv_timeout(settle).is_ok() {}
        true
    }
}
