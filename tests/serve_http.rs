//! `lispcad serve` at the HTTP level: the page, /drawing.svg (also from another view
//! direction), /status, /events delivering one event per re-run after a save, a broken script
//! reported with line:col while the last good drawing stays, and a listener on loopback only.
//! Then in a real browser: Debian's chromium, headless, driven by playwright-core
//! (tests/browser/preview.mjs; `bash .ci/setup` installs both).

use std::io::{BufRead, BufReader, Read, Write};
use std::net::TcpStream;
use std::path::Path;
use std::process::{Child, Command, Stdio};
use std::time::{Duration, Instant};

mod cli_support;

struct Serve {
    child: Child,
    port: u16,
}

impl Drop for Serve {
    fn drop(&mut self) {
        let _ = self.child.kill();
        let _ = self.child.wait();
    }
}

/// Starts `lispcad serve SCRIPT --port 0` in `dir` and reads the address it prints.
fn serve(dir: &Path, script: &str) -> Serve {
    let child = Command::new(env!("CARGO_BIN_EXE_lispcad"))
        .args(["serve", script, "--port", "0"])
        .current_dir(dir)
        .env("NO_COLOR", "1")
        .stdin(Stdio::null())
        .stdout(Stdio::null())
        .stderr(Stdio::piped())
        .spawn()
        .unwrap();
    // Owned by a Serve from here, so it is killed and waited for whatever happens.
    let mut srv = Serve { child, port: 0 };
    let mut err = BufReader::new(srv.child.stderr.take().unwrap());
    let mut line = String::new();
    loop {
        line.clear();
        assert!(err.read_line(&mut line).unwrap() > 0, "serve ended early");
        if let Some(rest) = line.trim().strip_prefix("serving http://127.0.0.1:") {
            let port = rest.trim_end_matches(|c: char| !c.is_ascii_digit());
            let port = port.split('/').next().unwrap().parse().unwrap();
            // Keep draining stderr so the server never blocks on a full pipe.
            std::thread::spawn(move || std::io::copy(&mut err, &mut std::io::sink()));
            srv.port = port;
            return srv;
        }
    }
}

/// GET over a plain socket: (status code, content type, body).
fn get(port: u16, path: &str) -> (u16, String, String) {
    request(port, "GET", path)
}

fn request(port: u16, method: &str, path: &str) -> (u16, String, String) {
    let mut s = TcpStream::connect(("127.0.0.1", port)).unwrap();
    write!(
        s,
        "{method} {path} HTTP/1.1\r\nHost: localhost\r\nConnection: close\r\n\r\n"
    )
    .unwrap();
    let mut raw = Vec::new();
    s.read_to_end(&mut raw).unwrap();
    let raw = String::from_utf8_lossy(&raw).into_owned();
    let (head, body) = raw.split_once("\r\n\r\n").unwrap();
    let code = head.split(' ').nth(1).unwrap().parse().unwrap();
    let ty = head
        .lines()
        .find_map(|l| {
            l.to_ascii_lowercase()
                .strip_prefix("content-type: ")
                .map(str::to_string)
        })
        .unwrap_or_default();
    (code, ty, body.to_string())
}

fn status(port: u16) -> serde_json::Value {
    let (code, ty, body) = get(port, "/status");
    assert_eq!((code, ty.as_str()), (200, "application/json"));
    serde_json::from_str(&body).unwrap()
}

/// The next `run` event of an open /events stream, as JSON.
fn next_event(r: &mut impl BufRead) -> serde_json::Value {
    // The server's keep-alive comments would otherwise let a missed re-run hang the test.
    let end = Instant::now() + Duration::from_secs(60);
    let mut line = String::new();
    loop {
        assert!(Instant::now() < end, "no event within 60 s");
        line.clear();
        assert!(r.read_line(&mut line).unwrap() > 0, "event stream ended");
        if let Some(data) = line.strip_prefix("data: ") {
            return serde_json::from_str(data.trim()).unwrap();
        }
    }
}

const GOOD: &str = "(layer \"CUT\" 1)\n(draw (circle '(0 0) 10))\n(layer \"AUX\" 3)\n(draw (line '(0 0) '(20 5)))\n";

#[test]
fn endpoints_events_and_errors() {
    let dir = tempfile::tempdir().unwrap();
    let d = dir.path();
    std::fs::write(d.join("s.lsp"), GOOD).unwrap();
    let srv = serve(d, "s.lsp");
    let port = srv.port;

    // The page: self-contained (no external script or style), listening for events.
    let (code, ty, page) = get(port, "/");
    assert_eq!((code, ty.as_str()), (200, "text/html; charset=utf-8"));
    assert!(page.contains("new EventSource(\"/events\")"), "{page}");
    assert!(!page.contains("src=\"http") && !page.contains("href=\"http"));

    let st = status(port);
    assert_eq!(st["ok"], true, "{st}");
    assert_eq!(st["error"], serde_json::Value::Null);
    assert_eq!(st["runs"], 1);
    assert_eq!(st["is3d"], false);

    let (code, ty, svg) = get(port, "/drawing.svg");
    assert_eq!((code, ty.as_str()), (200, "image/svg+xml"));
    assert!(svg.contains("inkscape:label=\"CUT\""), "{svg}");
    assert!(svg.contains("inkscape:label=\"AUX\""), "{svg}");
    assert!(svg.contains("<path d=\"M10 0 A10 10 0 0 1 -10 0"), "{svg}");
    // Another view direction projects differently.
    let (code, _, side) = get(port, "/drawing.svg?view=0,-1,0");
    assert_eq!(code, 200);
    assert_ne!(side, svg);
    assert_eq!(get(port, "/drawing.svg?view=0,0,0").0, 400);
    assert_eq!(get(port, "/drawing.svg?view=a,b").0, 400);
    assert_eq!(get(port, "/nothing").0, 404);
    assert_eq!(request(port, "POST", "/status").0, 405);

    // An event per re-run, after the script is saved.
    let mut ev = TcpStream::connect(("127.0.0.1", port)).unwrap();
    ev.set_read_timeout(Some(Duration::from_secs(30))).unwrap();
    write!(ev, "GET /events HTTP/1.1\r\nHost: localhost\r\n\r\n").unwrap();
    let mut ev = BufReader::new(ev);
    let mut line = String::new();
    ev.read_line(&mut line).unwrap();
    assert_eq!(line.trim(), "HTTP/1.1 200 OK");
    loop {
        line.clear();
        ev.read_line(&mut line).unwrap();
        if line.to_ascii_lowercase().starts_with("content-type") {
            assert!(line.contains("text/event-stream"), "{line}");
        }
        if line.trim().is_empty() {
            break;
        }
    }
    std::fs::write(
        d.join("s.lsp"),
        format!("{GOOD}(draw (circle '(0 0) 33))\n"),
    )
    .unwrap();
    let e = next_event(&mut ev);
    assert_eq!(
        (e["runs"].clone(), e["ok"].clone()),
        (2.into(), true.into()),
        "{e}"
    );
    let svg2 = get(port, "/drawing.svg").2;
    assert!(svg2.contains("A33 33"), "{svg2}");

    // A broken script: the error with line:col, the last good drawing still served.
    std::fs::write(
        d.join("s.lsp"),
        format!("{GOOD}\n(draw (circle '(0 0) \"r\"))\n"),
    )
    .unwrap();
    let e = next_event(&mut ev);
    assert_eq!(e["ok"], false, "{e}");
    let st = status(port);
    assert_eq!(st["runs"], 3);
    assert_eq!(st["ok"], false);
    let err = st["error"].as_str().unwrap();
    assert!(err.starts_with("bad argument type"), "{err}");
    assert!(err.ends_with("(s.lsp:6:7)"), "{err}");
    assert_eq!(st["diagnostic"]["line"], 6);
    assert_eq!(st["diagnostic"]["column"], 7);
    assert_eq!(
        st["diagnostic"]["snippet"],
        "(draw (circle '(0 0) \"r\"))\n      ^"
    );
    assert_eq!(get(port, "/drawing.svg").2, svg2);
}

#[test]
fn a_loaded_file_saved_reruns_the_script() {
    let dir = tempfile::tempdir().unwrap();
    let d = dir.path();
    std::fs::write(d.join("lib.lsp"), "(setq r 4)\n").unwrap();
    std::fs::write(
        d.join("s.lsp"),
        "(load \"lib\")\n(draw (circle '(0 0) r))\n",
    )
    .unwrap();
    let srv = serve(d, "s.lsp");
    assert!(get(srv.port, "/drawing.svg").2.contains("A4 4"));
    let mut ev = TcpStream::connect(("127.0.0.1", srv.port)).unwrap();
    ev.set_read_timeout(Some(Duration::from_secs(30))).unwrap();
    write!(ev, "GET /events HTTP/1.1\r\nHost: localhost\r\n\r\n").unwrap();
    let mut ev = BufReader::new(ev);
    // The stream's opening comment: the server has registered this client.
    let mut line = String::new();
    while !line.starts_with(": lispcad") {
        line.clear();
        ev.read_line(&mut line).unwrap();
    }
    std::fs::write(d.join("lib.lsp"), "(setq r 7)\n").unwrap();
    let e = next_event(&mut ev);
    assert_eq!(e["ok"], true, "{e}");
    assert!(get(srv.port, "/drawing.svg").2.contains("A7 7"));
}

/// The listening socket's local address from /proc/net/tcp{,6}: only 127.0.0.1.
#[cfg(target_os = "linux")]
#[test]
fn listens_on_loopback_only() {
    let dir = tempfile::tempdir().unwrap();
    std::fs::write(dir.path().join("s.lsp"), GOOD).unwrap();
    let srv = serve(dir.path(), "s.lsp");
    let port = format!("{:04X}", srv.port);
    let mut listeners = Vec::new();
    for table in ["/proc/net/tcp", "/proc/net/tcp6"] {
        let Ok(text) = std::fs::read_to_string(table) else {
            continue;
        };
        for l in text.lines().skip(1) {
            let f: Vec<&str> = l.split_whitespace().collect();
            // local_address is ADDR:PORT in hex; state 0A is LISTEN.
            let (addr, p) = f[1].split_once(':').unwrap();
            if p == port && f[3] == "0A" {
                listeners.push(addr.to_string());
            }
        }
    }
    assert_eq!(listeners, ["0100007F"], "127.0.0.1 in /proc's byte order");
}

#[test]
fn usage_errors() {
    let dir = tempfile::tempdir().unwrap();
    std::fs::write(dir.path().join("s.lsp"), GOOD).unwrap();
    let o = cli_support::lispcad_in(dir.path(), &["serve", "missing.lsp", "--port", "0"]);
    assert_eq!(o.status.code(), Some(2));
    let o = cli_support::lispcad_in(
        dir.path(),
        &["serve", "s.lsp", "--port", "0", "--open", "in.dxf"],
    );
    assert_eq!(o.status.code(), Some(2));
    assert!(
        String::from_utf8_lossy(&o.stderr).contains("cannot read drawing in.dxf"),
        "{o:?}"
    );
    // A port already taken.
    let srv = serve(dir.path(), "s.lsp");
    let o = cli_support::lispcad_in(
        dir.path(),
        &["serve", "s.lsp", "--port", &srv.port.to_string()],
    );
    assert_eq!(o.status.code(), Some(2));
    assert!(
        String::from_utf8_lossy(&o.stderr).contains("cannot listen on 127.0.0.1"),
        "{o:?}"
    );
}

/// The page draws the drawing, updates without a reload after a save, hides a layer, shows the
/// cursor's coordinates, keeps the drawing and shows the error when the script breaks, and
/// orbits a 3D drawing. The screenshot of the error state is left in target/serve-preview.png.
#[test]
fn page_follows_the_script_in_chromium() {
    let root = Path::new(env!("CARGO_MANIFEST_DIR"));
    let browser = root.join("tests/browser");
    assert!(
        browser.join("node_modules/playwright-core").is_dir()
            && Path::new("/usr/bin/chromium").exists(),
        "run `bash .ci/setup`: it installs chromium and tests/browser's playwright-core"
    );
    let dir = tempfile::tempdir().unwrap();
    let script = dir.path().join("s.lsp");
    std::fs::write(&script, GOOD).unwrap();
    let srv = serve(dir.path(), "s.lsp");
    let shot = root.join("target/serve-preview.png");
    let out = Command::new("node")
        .arg(browser.join("preview.mjs"))
        .arg(format!("http://127.0.0.1:{}/", srv.port))
        .arg(&script)
        .arg(&shot)
        .current_dir(&browser)
        .output()
        .expect("node runs");
    drop(srv);
    let stdout = String::from_utf8_lossy(&out.stdout);
    assert!(
        out.status.success(),
        "{stdout}\n{}",
        String::from_utf8_lossy(&out.stderr)
    );
    let v: serde_json::Value = serde_json::from_str(stdout.trim()).unwrap();
    assert_eq!(v["ok"], true);
    assert_eq!(
        v["coords"], "x 0.000  y 0.000",
        "the view's centre is the circle's"
    );
    let png = std::fs::read(&shot).unwrap();
    assert_eq!(&png[..8], b"\x89PNG\r\n\x1a\n");
}
