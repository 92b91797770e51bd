//! The interactive REPL on a real terminal (a pty from util-linux `script`): rustyline's
//! multi-line entry, get* functions prompting on the terminal, the persistent history file; a
//! double Tab listing the candidates, AutoCAD's continuation prompt, and `:serve` publishing
//! every evaluation to the preview's endpoints.

#![cfg(target_os = "linux")]

use std::io::{Read, Write};
use std::net::TcpStream;
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

/// `lispcad repl` on a pty in `dir` (history in `dir/history`): everything it prints is
/// collected in `buf` by the `reader` thread.
struct Pty {
    child: std::process::Child,
    buf: Arc<Mutex<Vec<u8>>>,
    reader: std::thread::JoinHandle<()>,
    stdin: std::process::ChildStdin,
}

impl Pty {
    fn repl(dir: &std::path::Path) -> Pty {
        let cmd = format!("{} repl", env!("CARGO_BIN_EXE_lispcad"));
        let mut child = Command::new("script")
            .args(["-qefc", &cmd, "/dev/null"])
            .current_dir(dir)
            .env("LISPCAD_HISTORY", dir.join("history"))
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
        let stdin = child.stdin.take().unwrap();
        Pty {
            child,
            buf,
            reader,
            stdin,
        }
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
    let Pty {
        mut child,
        buf,
        reader,
        mut stdin,
    } = Pty::repl(dir.path());
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
    // The prompt on its own line, not the echo of the typed form (which also holds the text):
    // input sent while the line editor still owns the terminal can be dropped.
    wait_for(&buf, "\r\nRadius: ").unwrap();
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

/// Waits until the terminal output contains `want` after byte `from`; the text after `from`.
fn wait_until(buf: &Arc<Mutex<Vec<u8>>>, from: usize, want: &str) -> String {
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
    let Pty {
        mut child,
        buf,
        reader,
        mut stdin,
    } = Pty::repl(dir.path());
    let mut send = |s: &str| {
        stdin.write_all(s.as_bytes()).unwrap();
        stdin.flush().unwrap();
    };
    let mark = |b: &Arc<Mutex<Vec<u8>>>| b.lock().unwrap().len();
    wait_until(&buf, 0, "_$ ");

    // Tab completes the common prefix, a second Tab lists every candidate.
    let at = mark(&buf);
    send("(vl-string-t");
    wait_until(&buf, at, "(vl-string-t");
    send("\t");
    wait_until(&buf, at, "vl-string-tr");
    let at = mark(&buf);
    send("\t");
    let shown = wait_until(&buf, at, "vl-string-translate");
    assert!(shown.contains("vl-string-trim"), "{shown:?}");
    send("\x15"); // Ctrl-U clears the line.

    // An open list continues after "(_> ", two after "((_> ".
    let at = mark(&buf);
    send("(+ 1\r");
    wait_until(&buf, at, "(_> ");
    send("(* 2\r");
    wait_until(&buf, at, "((_> ");
    send("3))\r");
    wait_until(&buf, at, "\r\n7\r\n");

    // :serve publishes each evaluation; an error keeps the last good drawing.
    let at = mark(&buf);
    send(":serve 0\r");
    let text = wait_until(&buf, at, "(updated after every evaluation)");
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
