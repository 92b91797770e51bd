//! Waiting for a save of any of a run's files. Directories are watched, not files: editors
//! often replace a file by renaming a new one over it.
// `watch` has the same loop inline; the lead may fold it onto this at merge.

use std::path::PathBuf;
use std::sync::mpsc;
use std::time::Duration;

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

    /// Blocks until one of `files` changes, then lets a burst of events settle (an editor's
    /// save is several). False when the watcher has stopped.
    pub fn wait(&mut self, files: &[PathBuf]) -> bool {
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
        // A short settle: the page's latency budget is 100 ms from save to update.
        while self.rx.recv_timeout(Duration::from_millis(20)).is_ok() {}
        true
    }
}
