//! The REPL on a real terminal (a pty from util-linux `script`): a double Tab lists the
//! candidates, AutoCAD's continuation prompt for an open list, and `:serve` publishing every
//! evaluation to the preview page's endpoints.

#![cfg(target_os = "linux")]

use std::io::{Read, Write};
use std::net::TcpStream;
use std::process::{Command, Stdio};
use std::sync::{Arc, Mutex};
use std::time::{Duration, Instant};

/// Waits until the terminal output contains `want` after byte `from`; the text after `from`.
fn wait_for(buf: &Arc<Mutex<Vec<u8>>>, from: usize, want: &str) -> String {
    let end = Instant::now() + Duration::from_secs(20);
    loop {
        let text = String::from_utf8_lossy(&buf.lock().unwrap()[from..]).into_owned();
        if text.contains(want) {
            return text;
        }
        assert!(Instant::now() < end, "no {want:?} in {text:?}");
        std::thread::sleep(Duration::from_millis(20));
    }
}

fn get(port: u16, path: &str) -> String {
    let mut s = TcpStream::connect(("127.0.0.1", port)).unwrap();
    write!(
        s,
        "GET {path} HTTP/1.1\r\nHost: x\r\nConnection: close\r\n\r\n"
    )
    .unwrap();
    let mut out = String::new();
    s.read_to_string(&mut out).unwrap();
    out.split_once("\r\n\r\n").unwrap().1.to_string()
}

#[test]
fn tab_listing_continuation_prompt_and_serve() {
    let dir = tempfile::tempdir().unwrap();
    let cmd = format!("{} repl", env!("CARGO_BIN_EXE_lispcad"));
    let mut child = Command::new("script")
        .args(["-qefc", &cmd, "/dev/null"])
        .current_dir(dir.path())
        .env("LISPCAD_HISTORY", dir.path().join("history"))
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
    let mark = |b: &Arc<Mutex<Vec<u8>>>| b.lock().unwrap().len();
    wait_for(&buf, 0, "_$ ");

    // Tab completes the common prefix, a second Tab lists every candidate.
    let at = mark(&buf);
    send("(vl-string-t");
    wait_for(&buf, at, "(vl-string-t");
    send("\t");
    wait_for(&buf, at, "vl-string-tr");
    let at = mark(&buf);
    send("\t");
    let shown = wait_for(&buf, at, "vl-string-translate");
    assert!(shown.contains("vl-string-trim"), "{shown:?}");
    send("\x15"); // Ctrl-U clears the line.

    // An open list continues after "(_> ", two after "((_> ".
    let at = mark(&buf);
    send("(+ 1\r");
    wait_for(&buf, at, "(_> ");
    send("(* 2\r");
    wait_for(&buf, at, "((_> ");
    send("3))\r");
    wait_for(&buf, at, "\r\n7\r\n");

    // :serve publishes each evaluation; an error keeps the last good drawing.
    let at = mark(&buf);
    send(":serve 0\r");
    let text = wait_for(&buf, at, "(updated after every evaluation)");
    let port: u16 = text
        .split("http://127.0.0.1:")
        .nth(1)
        .and_then(|r| r.split('/').next())
        .and_then(|p| p.parse().ok())
        .unwrap_or_else(|| panic!("{text:?}"));
    let status = |want: &str| {
        let end = Instant::now() + Duration::from_secs(20);
        loop {
            let s = get(port, "/status");
            if s.contains(want) {
                return s;
            }
            assert!(Instant::now() < end, "{s}");
            std::thread::sleep(Duration::from_millis(20));
        }
    };
    status("\"runs\":1");
    send("(draw (circle '(0 0) 4))\r");
    let s = status("\"runs\":2");
    assert!(s.contains("\"ok\":true"), "{s}");
    assert!(get(port, "/drawing.svg").contains("A4 4"));
    send("(car 1 2)\r");
    let s = status("\"runs\":3");
    assert!(
        s.contains("\"ok\":false") && s.contains("too many arguments"),
        "{s}"
    );
    assert!(get(port, "/drawing.svg").contains("A4 4"));
    send(":quit\r");
    drop(stdin);
    let st = child.wait().unwrap();
    reader.join().unwrap();
    assert!(st.success(), "{st:?}");
}
