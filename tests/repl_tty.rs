//! The interactive REPL on a real terminal (a pty from util-linux `script`): rustyline's
//! multi-line entry, get* functions prompting on the terminal, and the persistent history file.

#![cfg(target_os = "linux")]

use std::io::{Read, Write};
use std::process::{Command, Stdio};
use std::sync::{Arc, Mutex};
use std::time::{Duration, Instant};

/// Waits until the terminal output contains `want`; the output so far on timeout.
fn wait_for(buf: &Arc<Mutex<Vec<u8>>>, want: &str) -> Result<(), String> {
    let end = Instant::now() + Duration::from_secs(20);
    loop {
        let text = String::from_utf8_lossy(&buf.lock().unwrap()).into_owned();
        if text.contains(want) {
            return Ok(());
        }
        if Instant::now() > end {
            return Err(text);
        }
        std::thread::sleep(Duration::from_millis(20));
    }
}

#[test]
fn interactive_session_on_a_pty() {
    assert!(
        Command::new("script").arg("--version").output().is_ok(),
        "util-linux `script` is needed to give the REPL a terminal"
    );
    let dir = tempfile::tempdir().unwrap();
    let hist = dir.path().join("history");
    let cmd = format!("{} repl", env!("CARGO_BIN_EXE_lispcad"));
    let mut child = Command::new("script")
        .args(["-qefc", &cmd, "/dev/null"])
        .current_dir(dir.path())
        .env("LISPCAD_HISTORY", &hist)
        .env("NO_COLOR", "1")
        .env("TERM", "xterm")
        .stdin(Stdio::piped())
        .stdout(Stdio::piped())
        .stderr(Stdio::null())
        .spawn()
        .unwrap();
    let buf = Arc::new(Mutex::new(Vec::new()));
    let mut out = child.stdout.take().unwrap();
    let sink = buf.clone();
    let reader = std::thread::spawn(move || {
        let mut chunk = [0u8; 4096];
        while let Ok(n) = out.read(&mut chunk) {
            if n == 0 {
                break;
            }
            sink.lock().unwrap().extend_from_slice(&chunk[..n]);
        }
    });
    let mut stdin = child.stdin.take().unwrap();
    let mut send = |s: &str| {
        stdin.write_all(s.as_bytes()).unwrap();
        stdin.flush().unwrap();
    };
    wait_for(&buf, "AutoLISP REPL").unwrap();
    wait_for(&buf, "_$ ").unwrap();
    // An open list continues on the next line: no result until it is closed.
    send("(+ 1 \"(\" ; )\r");
    std::thread::sleep(Duration::from_millis(300));
    send("2)\r");
    wait_for(&buf, "bad argument type: numberp: \"(\"").unwrap();
    send("(* 6 7)\r");
    wait_for(&buf, "42").unwrap();
    // getreal asks on the terminal.
    send("(setq r (getreal \"Radius: \"))\r");
    wait_for(&buf, "Radius: ").unwrap();
    send("2.5\r");
    wait_for(&buf, "\r\n2.5\r\n").unwrap();
    send("(* r 2)\r");
    wait_for(&buf, "5.0").unwrap();
    send(":quit\r");
    drop(stdin);
    let status = child.wait().unwrap();
    reader.join().unwrap();
    assert!(status.success(), "{status:?}");
    let h = std::fs::read_to_string(&hist).expect("history file written");
    assert!(h.contains("(* 6 7)"), "{h}");
    assert!(
        h.contains("(+ 1 \"(\" ; )\\n2)") || h.contains("(+ 1 \"(\" ; )\n2)"),
        "{h:?}"
    );
}
