//! Waiting for a save of any of a run's files. Directories are watched, not files: editors
//! often replace a file by renaming a new one over it. Used by `watch` and `serve`.

use std::path::{Path, PathBuf};
use std::sync::mpsc;
use std::time::{Duration, SystemTime};

use notify::{RecommendedWatcher, RecursiveMode, Watcher};

/// A run's inputs known before it starts: the script, and the drawing every run starts from
/// (`--open`), whose save re-runs too.
pub fn inputs(script: &Path, open: Option<&PathBuf>) -> Vec<PathBuf> {
    std::iter::once(script.to_path_buf())
        .chain(open.cloned())
        .collect()
}

/// How far a file's time may lag the fine clock and still count as a save during the run:
/// the kernel's coarse clock lags by milliseconds, FAT's times are rounded to 2 s.
const SLACK: Duration = Duration::from_secs(2);

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

    /// Watches the directories of `files` from now on; returns them canonical. Called before
    /// the first run with the files known then (the script, the drawing it opens): a save
    /// made while that run is going, or just after it, is then an event. The file's time alone
    /// can miss it, as it comes from the kernel's coarse clock, which can be a few
    /// milliseconds behind the run's start taken from the fine one.
    pub fn watch(&mut self, files: &[PathBuf]) -> Vec<PathBuf> {
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
        files
    }

    /// Blocks until one of `files` changes after `since` (when the run that read them
    /// started), then lets a burst of events settle (an editor's save is several). False when
    /// the watcher has stopped. `settle`: how long the events must pause.
    pub fn wait(&mut self, files: &[PathBuf], since: SystemTime, settle: Duration) -> bool {
        let watched = self.dirs.len();
        let files = self.watch(files);
        // A directory first seen in this run (one a loaded file is in) is only watched from
        // here on: a save in it during the run, or before the watch was added, shows in the
        // file's time alone. That time comes from the kernel's coarse clock (or a coarse file
        // system's), which can lag `since`, so a time up to `SLACK` before it counts: at worst
        // one extra run, once per new directory. A time ahead of the clock (a file from an
        // archive) is not a save, or it would re-run forever. Files in directories watched
        // before the run are covered by its events.
        let fresh = &self.dirs[watched..];
        let now = SystemTime::now();
        let since = since.checked_sub(SLACK).unwrap_or(since);
        let saved_meanwhile = files.iter().any(|f| {
            f.parent().is_some_and(|d| fresh.iter().any(|x| x == d))
                && std::fs::metadata(f)
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

#[cfg(test)]
mod tests {
    use super::*;

    /// Writes `text` to `file` (when given) and stamps it 3 ms before `since`, as the kernel's
    /// coarse clock may.
    fn save_stamped_before(file: &Path, text: Option<&str>, since: SystemTime) {
        if let Some(text) = text {
            std::fs::write(file, text).unwrap();
        }
        let f = std::fs::File::options().write(true).open(file).unwrap();
        f.set_modified(since - Duration::from_millis(3)).unwrap();
    }

    /// A file `name` holding `text` in a new directory, watched (the directory kept alive by
    /// the first).
    fn watched(name: &str, text: &str) -> (tempfile::TempDir, PathBuf, Changes) {
        let dir = tempfile::tempdir().unwrap();
        let file = dir.path().join(name);
        std::fs::write(&file, text).unwrap();
        let mut c = Changes::new().unwrap();
        c.watch(std::slice::from_ref(&file));
        (dir, file, c)
    }

    /// `c.wait(files, since)` on another thread: what it returns, when it returns.
    fn wait_apart(mut c: Changes, files: Vec<PathBuf>, since: SystemTime) -> mpsc::Receiver<bool> {
        let (tx, rx) = mpsc::channel();
        std::thread::spawn(move || {
            let _ = tx.send(c.wait(&files, since, Duration::from_millis(20)));
        });
        rx
    }

    /// A save timed before the run's start (the kernel's coarse clock lagging the fine one)
    /// made after the script's directory is watched is still seen. Without the watch before
    /// the run, the event is lost and the file's time says nothing changed: `wait` blocks.
    #[test]
    fn a_save_stamped_before_the_runs_start_is_seen_once_the_directory_is_watched() {
        let (_dir, lib, c) = watched("lib.lsp", "(setq r 4)\n");
        let since = SystemTime::now();
        save_stamped_before(&lib, Some("(setq r 7)\n"), since);
        let rx = wait_apart(c, vec![lib], since);
        assert_eq!(rx.recv_timeout(Duration::from_secs(20)), Ok(true));
    }

    /// A file the run loaded from a directory not watched before it, saved during the run and
    /// stamped by the coarse clock 3 ms before the run's start, is seen by its time: no event
    /// can come, as the save predates the watch. Before, only a time after the start counted,
    /// and `wait` blocked.
    #[test]
    fn a_loaded_file_in_a_new_directory_saved_during_the_run_is_seen_by_its_time() {
        let (_dir, script, c) = watched("main.lsp", "(load \"lib\")\n");
        let other = tempfile::tempdir().unwrap();
        let lib = other.path().join("lib.lsp");
        let since = SystemTime::now();
        save_stamped_before(&lib, Some("(setq r 7)\n"), since);
        let rx = wait_apart(c, vec![script, lib], since);
        assert_eq!(rx.recv_timeout(Duration::from_secs(20)), Ok(true));
    }

    /// A loaded file whose directory was already watched and that did not change does not
    /// re-run by its time, however recent: the watch's events cover it.
    #[test]
    fn an_unchanged_file_in_a_watched_directory_does_not_rerun_by_its_time() {
        let (_dir, lib, c) = watched("lib.lsp", "(setq r 4)\n");
        let since = SystemTime::now();
        save_stamped_before(&lib, None, since);
        // Setting the time is an event of its own; it is not a save, so it is let go.
        std::thread::sleep(Duration::from_millis(100));
        while c.rx.try_recv().is_ok() {}
        let rx = wait_apart(c, vec![lib], since);
        assert!(rx.recv_timeout(Duration::from_millis(500)).is_err());
    }
}
