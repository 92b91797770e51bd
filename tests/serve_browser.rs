//! `lispcad serve` in a real browser: Debian's chromium, headless, driven by playwright-core
//! (tests/browser/preview.mjs; `bash .ci/setup` installs both). The page draws the drawing,
//! updates without a reload after a save, keeps the drawing and shows the error when the
//! script breaks. The screenshot of that last state is left in target/serve-preview.png.

use std::io::{BufRead, BufReader};
use std::path::Path;
use std::process::{Command, Stdio};

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
    std::fs::write(
        &script,
        "(layer \"CUT\" 1)\n(draw (circle '(0 0) 10))\n(layer \"AUX\" 3)\n(draw (line '(0 0) '(20 5)))\n",
    )
    .unwrap();
    let mut srv = Command::new(env!("CARGO_BIN_EXE_lispcad"))
        .args(["serve", "s.lsp", "--port", "0"])
        .current_dir(dir.path())
        .env("NO_COLOR", "1")
        .stdin(Stdio::null())
        .stdout(Stdio::null())
        .stderr(Stdio::piped())
        .spawn()
        .unwrap();
    let mut err = BufReader::new(srv.stderr.take().unwrap());
    let mut url = None;
    let mut line = String::new();
    while url.is_none() && err.read_line(&mut line).unwrap_or(0) > 0 {
        url = line
            .trim()
            .strip_prefix("serving ")
            .and_then(|r| r.split(' ').next())
            .map(str::to_string);
        line.clear();
    }
    std::thread::spawn(move || std::io::copy(&mut err, &mut std::io::sink()));
    let shot = root.join("target/serve-preview.png");
    let out = url.map(|url| {
        Command::new("node")
            .arg(browser.join("preview.mjs"))
            .arg(&url)
            .arg(&script)
            .arg(&shot)
            .current_dir(&browser)
            .output()
            .expect("node runs")
    });
    let _ = srv.kill();
    let _ = srv.wait();
    let out = out.expect("serve printed its address");
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
