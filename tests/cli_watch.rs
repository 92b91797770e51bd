//! `lispcad watch`: a change to the script (or a file it loads) rewrites the outputs; a
//! failing run keeps the last good output.

use std::path::Path;
use std::process::{Command, Stdio};
use std::time::{Duration, Instant};

fn wait_for(what: &str, mut ok: impl FnMut() -> bool) {
    let start = Instant::now();
    while !ok() {
        assert!(
            start.elapsed() < Duration::from_secs(30),
            "timed out waiting for {what}"
        );
        std::thread::sleep(Duration::from_millis(50));
    }
}

fn read(p: &Path) -> String {
    std::fs::read_to_string(p).unwrap_or_default()
}

#[test]
fn watch_reruns_on_change_and_keeps_the_last_good_output() {
    let dir = tempfile::tempdir().unwrap();
    let script = dir.path().join("w.lsp");
    let part = dir.path().join("part.lsp");
    let out = dir.path().join("w.svg");
    std::fs::write(&part, "(setq r 5.0)").unwrap();
    std::fs::write(&script, "(load \"part\") (draw (circle '(0 0) r))").unwrap();
    let mut child = Command::new(env!("CARGO_BIN_EXE_lispcad"))
        .arg("watch")
        .arg(&script)
        .arg("-o")
        .arg(&out)
        .stderr(Stdio::null())
        .stdout(Stdio::null())
        .spawn()
        .unwrap();
    wait_for("the first run", || read(&out).contains("</svg>"));
    let first = read(&out);
    // The watcher is set up after the first run; give it a moment before editing.
    std::thread::sleep(Duration::from_millis(300));

    // A change to the loaded file re-runs the script.
    std::fs::write(&part, "(setq r 9.0)").unwrap();
    wait_for("a re-run after the loaded file changed", || {
        let now = read(&out);
        now.contains("</svg>") && now != first
    });
    let second = read(&out);

    // A broken script leaves the last good output in place.
    std::fs::write(&script, "(load \"part\") (draw (circle '(0 0) r)").unwrap();
    std::thread::sleep(Duration::from_millis(1500));
    assert_eq!(read(&out), second);

    // Fixing it writes again.
    std::fs::write(&script, "(load \"part\") (draw (line '(0 0) (list r r)))").unwrap();
    wait_for("a re-run after the fix", || {
        let now = read(&out);
        now.contains("</svg>") && now != second
    });
    let _ = child.kill();
    let _ = child.wait();
}
