//! The conformance suite: `.lsp` files under tests/conformance/, each a sequence of cases.
//! A case is Lisp code followed by expectation lines:
//!   `;=> TEXT`  the prin1 form of the last form's value
//!   `;>> TEXT`  what the code printed (princ/prin1/print), `\n` for newlines
//!   `;!! TEXT`  the error message the code raises
//! Cases in one file share one interpreter, so a file can define functions and use them.

use std::cell::RefCell;
use std::io::Write;
use std::path::Path;
use std::rc::Rc;

#[derive(Clone, Default)]
struct Capture(Rc<RefCell<Vec<u8>>>);

impl Write for Capture {
    fn write(&mut self, b: &[u8]) -> std::io::Result<usize> {
        self.0.borrow_mut().extend_from_slice(b);
        Ok(b.len())
    }
    fn flush(&mut self) -> std::io::Result<()> {
        Ok(())
    }
}

fn run_file(path: &Path) -> (usize, Vec<String>) {
    let text = std::fs::read_to_string(path).unwrap();
    let mut it = lispcad::builtins::new_interp();
    let cap = Capture::default();
    it.out = Box::new(cap.clone());
    let mut failures = Vec::new();
    let mut cases = 0;
    let mut code = String::new();
    let mut code_line = 0;
    for (n, line) in text.lines().enumerate() {
        let lineno = n + 1;
        let expect = |prefix: &str| line.strip_prefix(prefix).map(str::to_string);
        let (kind, want) = if let Some(w) = expect(";=> ") {
            ('=', w)
        } else if let Some(w) = expect(";>> ") {
            ('>', w.replace("\\n", "\n"))
        } else if let Some(w) = expect(";!! ") {
            ('!', w)
        } else {
            if code.trim().is_empty() {
                code_line = lineno;
            }
            code.push_str(line);
            code.push('\n');
            continue;
        };
        cases += 1;
        cap.0.borrow_mut().clear();
        let r = it.eval_source(&format!("{}:{}", path.display(), code_line), &code);
        let printed = String::from_utf8_lossy(&cap.0.borrow()).to_string();
        let got = match (&r, kind) {
            (Ok(v), '=') => it.prin1_string(v),
            (Ok(_), '>') => printed,
            (Err(e), '!') => e.message.clone(),
            (Ok(v), _) => format!("value {}", it.prin1_string(v)),
            (Err(e), _) => format!("error: {}", e.message),
        };
        if got != want {
            failures.push(format!(
                "{}:{}: {}\n    expected: {}\n    got:      {}",
                path.display(),
                code_line,
                code.trim(),
                want,
                got
            ));
        }
        code.clear();
    }
    (cases, failures)
}

#[test]
fn conformance_suite() {
    let dir = Path::new(env!("CARGO_MANIFEST_DIR")).join("tests/conformance");
    let mut files: Vec<_> = std::fs::read_dir(&dir)
        .unwrap()
        .map(|e| e.unwrap().path())
        .filter(|p| p.extension().is_some_and(|e| e == "lsp"))
        .collect();
    files.sort();
    assert!(!files.is_empty());
    let mut total = 0;
    let mut failures = Vec::new();
    for f in &files {
        let (n, fails) = lispcad::lang::eval::with_eval_stack({
            let f = f.clone();
            move || run_file(&f)
        });
        total += n;
        failures.extend(fails);
    }
    assert!(total > 100, "only {total} cases");
    assert!(
        failures.is_empty(),
        "{} of {total} conformance cases failed:\n{}",
        failures.len(),
        failures.join("\n")
    );
}
