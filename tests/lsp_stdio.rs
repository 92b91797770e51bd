//! `lispcad lsp` driven over pipes with real JSON-RPC framing, as an editor would: initialize,
//! open a broken file and one leaking a global, hover, completion, definition across a `load`,
//! change, symbols, folding, shutdown and exit; then range edits (incremental sync) with hover on
//! variables and definitions following the moved text.

use std::io::{BufRead, BufReader, Write};
use std::path::Path;
use std::process::{Child, ChildStdin, Command, Stdio};
use std::sync::mpsc::{channel, Receiver};
use std::time::Duration;

use serde_json::{json, Value};

struct Client {
    child: Child,
    stdin: ChildStdin,
    rx: Receiver<Value>,
    next_id: i64,
    /// Notifications received while waiting for a response.
    pending: Vec<Value>,
}

fn read_message(r: &mut impl BufRead) -> Option<Value> {
    let mut len = None;
    loop {
        let mut line = String::new();
        if r.read_line(&mut line).ok()? == 0 {
            return None;
        }
        let line = line.trim_end();
        if line.is_empty() {
            break;
        }
        if let Some(v) = line.strip_prefix("Content-Length: ") {
            len = v.parse::<usize>().ok();
        }
    }
    let mut body = vec![0; len?];
    r.read_exact(&mut body).ok()?;
    serde_json::from_slice(&body).ok()
}

impl Client {
    fn start(dir: &Path) -> Client {
        let mut child = Command::new(env!("CARGO_BIN_EXE_lispcad"))
            .arg("lsp")
            .current_dir(dir)
            .stdin(Stdio::piped())
            .stdout(Stdio::piped())
            .stderr(Stdio::inherit())
            .spawn()
            .unwrap();
        let stdin = child.stdin.take().unwrap();
        let mut out = BufReader::new(child.stdout.take().unwrap());
        let (tx, rx) = channel();
        std::thread::spawn(move || {
            while let Some(m) = read_message(&mut out) {
                if tx.send(m).is_err() {
                    break;
                }
            }
        });
        Client {
            child,
            stdin,
            rx,
            next_id: 1,
            pending: Vec::new(),
        }
    }

    fn send(&mut self, v: Value) {
        let body = v.to_string();
        write!(self.stdin, "Content-Length: {}\r\n\r\n{body}", body.len()).unwrap();
        self.stdin.flush().unwrap();
    }

    fn recv(&mut self) -> Value {
        self.rx
            .recv_timeout(Duration::from_secs(30))
            .expect("the server answers")
    }

    fn request(&mut self, method: &str, params: Value) -> Value {
        let id = self.next_id;
        self.next_id += 1;
        self.send(json!({"jsonrpc": "2.0", "id": id, "method": method, "params": params}));
        loop {
            let m = self.recv();
            if m["id"] == id {
                assert!(m.get("error").is_none(), "{method}: {m}");
                return m["result"].clone();
            }
            self.pending.push(m);
        }
    }

    fn notify(&mut self, method: &str, params: Value) {
        self.send(json!({"jsonrpc": "2.0", "method": method, "params": params}));
    }

    /// The next publishDiagnostics for `uri`.
    fn diagnostics(&mut self, uri: &str) -> Vec<Value> {
        loop {
            let m = match self.pending.iter().position(|m| m["params"]["uri"] == uri) {
                Some(i) => self.pending.remove(i),
                None => self.recv(),
            };
            if m["method"] == "textDocument/publishDiagnostics" && m["params"]["uri"] == uri {
                return m["params"]["diagnostics"].as_array().unwrap().clone();
            }
            self.pending.push(m);
        }
    }
}

fn uri(p: &Path) -> String {
    format!("file://{}", p.display())
}

fn open(c: &mut Client, uri: &str, text: &str) {
    c.notify(
        "textDocument/didOpen",
        json!({"textDocument": {"uri": uri, "languageId": "autolisp", "version": 1, "text": text}}),
    );
}

fn at(uri: &str, line: u32, character: u32) -> Value {
    json!({"textDocument": {"uri": uri}, "position": {"line": line, "character": character}})
}

#[test]
fn an_editor_session_over_json_rpc() {
    let dir = tempfile::tempdir().unwrap();
    let d = dir.path().canonicalize().unwrap();
    std::fs::create_dir(d.join("lib")).unwrap();
    let util = "(defun helper-a (x) x)\n\n;; Draws a hole of radius R at P.\n(defun hole (p r)\n  (circle p r))\n";
    std::fs::write(d.join("lib/util.lsp"), util).unwrap();
    let main_text = "(load \"lib/util\")\n(defun area (w h)\n  (setq total (* w h)))\n(hole '(0 0) 2.5)\n(dtr 90)\n";
    std::fs::write(d.join("main.lsp"), main_text).unwrap();
    let main = uri(&d.join("main.lsp"));
    let broken = uri(&d.join("broken.lsp"));

    let mut c = Client::start(&d);
    let init = c.request(
        "initialize",
        json!({"processId": null, "rootUri": uri(&d), "capabilities": {}}),
    );
    let caps = &init["capabilities"];
    assert_eq!(caps["hoverProvider"], true, "{init}");
    assert_eq!(caps["definitionProvider"], true);
    assert_eq!(caps["documentSymbolProvider"], true);
    assert_eq!(caps["foldingRangeProvider"], true);
    // Incremental sync: changes come as range edits.
    assert_eq!(caps["textDocumentSync"], 2);
    assert_eq!(init["serverInfo"]["name"], "lispcad");
    c.notify("initialized", json!({}));

    // A reader error: an unterminated string, reported where it starts.
    open(&mut c, &broken, "(setq a 1)\n(setq b \"open)\n");
    let diags = c.diagnostics(&broken);
    assert_eq!(diags.len(), 1, "{diags:?}");
    assert_eq!(diags[0]["severity"], 1);
    assert_eq!(
        diags[0]["range"]["start"],
        json!({"line": 1, "character": 8})
    );

    // A global leak and an undefined function with a suggestion; the loaded file's HOLE is known.
    open(&mut c, &main, main_text);
    let diags = c.diagnostics(&main);
    let messages: Vec<&str> = diags
        .iter()
        .map(|d| d["message"].as_str().unwrap())
        .collect();
    assert_eq!(messages.len(), 2, "{messages:?}");
    assert!(
        messages[0].starts_with("setq of TOTAL in AREA"),
        "{messages:?}"
    );
    assert_eq!(diags[0]["severity"], 2);
    assert_eq!(
        diags[0]["range"],
        json!({"start": {"line": 2, "character": 2}, "end": {"line": 2, "character": 22}})
    );
    assert!(
        messages[1].contains("undefined function DTR"),
        "{messages:?}"
    );

    // Hover: a builtin's doc, and a loaded defun's parameters with the comment above it.
    let h = c.request("textDocument/hover", at(&main, 2, 15));
    let v = h["contents"]["value"].as_str().unwrap();
    assert!(v.starts_with("```lisp\n(* "), "{v}");
    let h = c.request("textDocument/hover", at(&main, 3, 2));
    let v = h["contents"]["value"].as_str().unwrap();
    assert!(
        v.starts_with("```lisp\n(HOLE P R)\n```\nDraws a hole of radius R at P."),
        "{v}"
    );
    assert!(v.contains("lib/util.lsp:4"), "{v}");

    // Definition across the load: the name in lib/util.lsp.
    let def = c.request("textDocument/definition", at(&main, 3, 2));
    assert_eq!(def["uri"], uri(&d.join("lib/util.lsp")), "{def}");
    assert_eq!(
        def["range"],
        json!({"start": {"line": 3, "character": 7}, "end": {"line": 3, "character": 11}})
    );
    // And within the file.
    let def = c.request("textDocument/definition", at(&main, 1, 8));
    assert_eq!(def["uri"], main.as_str());
    assert_eq!(def["range"]["start"], json!({"line": 1, "character": 7}));

    // Completion: builtins and the file's symbols.
    let items = c.request("textDocument/completion", at(&main, 1, 9));
    let labels: Vec<&str> = items
        .as_array()
        .unwrap()
        .iter()
        .map(|i| i["label"].as_str().unwrap())
        .collect();
    assert!(labels.contains(&"area"), "{labels:?}");
    assert!(labels.contains(&"arc"), "{labels:?}");
    assert!(labels.iter().all(|l| l.starts_with("ar")), "{labels:?}");

    // A change fixing the leak and defining DTR: no diagnostics left.
    let fixed = "(load \"lib/util\")\n(defun area (w h / total)\n  (setq total (* w h)))\n(hole '(0 0) 2.5)\n(defun dtr (a) a)\n(dtr 90)\n";
    c.notify(
        "textDocument/didChange",
        json!({"textDocument": {"uri": main, "version": 2}, "contentChanges": [{"text": fixed}]}),
    );
    assert_eq!(c.diagnostics(&main), Vec::<Value>::new());

    // Symbols and folding ranges.
    let syms = c.request(
        "textDocument/documentSymbol",
        json!({"textDocument": {"uri": main}}),
    );
    let names: Vec<&str> = syms
        .as_array()
        .unwrap()
        .iter()
        .map(|s| s["name"].as_str().unwrap())
        .collect();
    assert_eq!(names, ["AREA", "DTR"]);
    let folds = c.request(
        "textDocument/foldingRange",
        json!({"textDocument": {"uri": main}}),
    );
    assert_eq!(folds[0]["startLine"], 1, "{folds}");
    assert_eq!(folds[0]["endLine"], 2, "{folds}");

    // An unknown method is an error reply, not a crash.
    c.send(json!({"jsonrpc": "2.0", "id": 99, "method": "textDocument/rename", "params": {}}));
    loop {
        let m = c.recv();
        if m["id"] == 99 {
            assert_eq!(m["error"]["code"], -32601, "{m}");
            break;
        }
    }

    let r = c.request("shutdown", Value::Null);
    assert_eq!(r, Value::Null);
    c.notify("exit", Value::Null);
    let status = c.child.wait().unwrap();
    assert!(status.success(), "{status:?}");
}

/// The Markdown of a hover answer (empty when there is none).
fn hover_text(c: &mut Client, uri: &str, line: u32, character: u32) -> String {
    let h = c.request("textDocument/hover", at(uri, line, character));
    h["contents"]["value"]
        .as_str()
        .unwrap_or_default()
        .to_string()
}

fn edit(c: &mut Client, uri: &str, version: i64, range: [u32; 4], text: &str) {
    let [l0, c0, l1, c1] = range;
    c.notify(
        "textDocument/didChange",
        json!({"textDocument": {"uri": uri, "version": version}, "contentChanges": [{
            "range": {"start": {"line": l0, "character": c0}, "end": {"line": l1, "character": c1}},
            "text": text}]}),
    );
}

fn messages(diags: &[Value]) -> Vec<(u64, String)> {
    diags
        .iter()
        .map(|d| {
            let line = d["range"]["start"]["line"].as_u64().unwrap();
            (line, d["message"].as_str().unwrap().to_string())
        })
        .collect()
}

#[test]
fn range_edits_keep_diagnostics_hover_and_definition_right() {
    let dir = tempfile::tempdir().unwrap();
    let d = dir.path().canonicalize().unwrap();
    let text = ";; Area of a rectangle.\n(defun area (w h / total)\n  (setq total (* w h))\n  (setq last-area total))\n(setq count 0)\n(foreach p '(1 2) (area p count))\n";
    let main = uri(&d.join("main.lsp"));
    let mut c = Client::start(&d);
    c.request(
        "initialize",
        json!({"processId": null, "rootUri": uri(&d), "capabilities": {}}),
    );
    c.notify("initialized", json!({}));
    open(&mut c, &main, text);
    let leak = "setq of LAST-AREA in AREA: LAST-AREA is neither a parameter nor a declared local, so it leaks into the global scope (add it after / in the argument list)";
    assert_eq!(messages(&c.diagnostics(&main)), [(3, leak.to_string())]);

    // Variables: a parameter, a declared local, globals set in a defun and at top level, a
    // loop variable.
    assert_eq!(
        hover_text(&mut c, &main, 2, 17),
        "`W`: a parameter of `AREA`\n\n```lisp\n(w h / total)\n```"
    );
    assert_eq!(
        hover_text(&mut c, &main, 2, 9),
        "`TOTAL`: a local variable of `AREA`, declared after `/`\n\n```lisp\n(w h / total)\n```"
    );
    assert_eq!(
        hover_text(&mut c, &main, 3, 10),
        "`LAST-AREA`: a global variable, set by `setq`\n- line 4 in `AREA`"
    );
    assert_eq!(
        hover_text(&mut c, &main, 5, 27),
        "`COUNT`: a global variable, set by `setq`\n- line 5 (top level)"
    );
    assert_eq!(
        hover_text(&mut c, &main, 5, 24),
        "`P`: the variable of a `foreach`"
    );
    // Definition of a parameter: where the argument list names it; of a global: its setq.
    let def = c.request("textDocument/definition", at(&main, 2, 19));
    assert_eq!(
        def["range"],
        json!({"start": {"line": 1, "character": 15}, "end": {"line": 1, "character": 16}})
    );
    let def = c.request("textDocument/definition", at(&main, 5, 27));
    assert_eq!(def["range"]["start"], json!({"line": 4, "character": 6}));

    // Two lines inserted above: diagnostics, hover and definition follow the text.
    edit(
        &mut c,
        &main,
        2,
        [0, 0, 0, 0],
        ";; Squares.\n(defun sq (x) (* x x))\n",
    );
    assert_eq!(messages(&c.diagnostics(&main)), [(5, leak.to_string())]);
    assert!(hover_text(&mut c, &main, 4, 17).starts_with("`W`: a parameter of `AREA`"));
    assert!(hover_text(&mut c, &main, 1, 17).starts_with("`X`: a parameter of `SQ`"));
    // AREA is also a builtin: the file's defun replaces it, so hover and definition show it.
    let def = c.request("textDocument/definition", at(&main, 7, 21));
    assert_eq!(
        def["range"],
        json!({"start": {"line": 3, "character": 7}, "end": {"line": 3, "character": 11}})
    );
    assert!(hover_text(&mut c, &main, 7, 21)
        .starts_with("```lisp\n(AREA W H / TOTAL)\n```\nArea of a rectangle."),);

    // Declaring LAST-AREA local: the leak goes, and hover calls it a local.
    edit(&mut c, &main, 3, [3, 24, 3, 24], " last-area");
    assert_eq!(messages(&c.diagnostics(&main)), []);
    assert!(hover_text(&mut c, &main, 5, 10).starts_with("`LAST-AREA`: a local variable of `AREA`"));

    // A `)` deleted: the reader's error, at the `(` left open; restored: clean again.
    edit(&mut c, &main, 4, [5, 24, 5, 25], "");
    let diags = c.diagnostics(&main);
    assert_eq!(diags.len(), 1, "{diags:?}");
    assert_eq!(
        diags[0]["range"]["start"],
        json!({"line": 3, "character": 0})
    );
    assert_eq!(hover_text(&mut c, &main, 4, 17), "");
    edit(&mut c, &main, 5, [5, 24, 5, 24], ")");
    assert_eq!(messages(&c.diagnostics(&main)), []);
    assert!(hover_text(&mut c, &main, 4, 17).starts_with("`W`: a parameter of `AREA`"));

    c.request("shutdown", Value::Null);
    c.notify("exit", Value::Null);
    assert!(c.child.wait().unwrap().success());
}
