//! getenv/setenv and vl-registry-* over the per-user settings file ($LISPCAD_SETTINGS here,
//! a temporary file): values persist across interpreters, getenv falls back to the process
//! environment, vl-registry-read is nil for what was never written.

use lispcad::lang::Interp;

fn eval(it: &mut Interp, code: &str) -> String {
    match it.eval_source("<test>", code) {
        Ok(v) => it.prin1_string(&v),
        Err(e) => format!("error: {}", e.message),
    }
}

#[test]
fn settings_persist_in_the_per_user_file() {
    let dir = tempfile::tempdir().unwrap();
    let file = dir.path().join("sub").join("settings");
    // The only test in this binary: setting the variable cannot race another test.
    std::env::set_var("LISPCAD_SETTINGS", &file);
    std::env::set_var("LISPCAD_TEST_FROM_ENV", "from-env");
    let mut it = lispcad::builtins::new_interp();
    assert_eq!(eval(&mut it, "(getenv \"MyRoutineDir\")"), "nil");
    assert_eq!(
        eval(&mut it, "(setenv \"MyRoutineDir\" \"C:\\\\tools\\tx\")"),
        "\"C:\\\\tools\\tx\""
    );
    assert_eq!(
        eval(&mut it, "(getenv \"LISPCAD_TEST_FROM_ENV\")"),
        "\"from-env\""
    );
    assert_eq!(
        eval(
            &mut it,
            "(vl-registry-read \"HKEY_CURRENT_USER\\\\Software\\\\Me\" \"Size\")"
        ),
        "nil"
    );
    assert_eq!(
        eval(
            &mut it,
            "(vl-registry-write \"HKEY_CURRENT_USER\\\\Software\\\\Me\" \"Size\" \"12\")"
        ),
        "\"12\""
    );
    let mut fresh = lispcad::builtins::new_interp();
    assert_eq!(
        eval(&mut fresh, "(getenv \"MyRoutineDir\")"),
        "\"C:\\\\tools\\tx\""
    );
    assert_eq!(
        eval(
            &mut fresh,
            "(vl-registry-read \"hkey_current_user\\\\software\\\\me\" \"size\")"
        ),
        "\"12\""
    );
    assert_eq!(
        eval(
            &mut fresh,
            "(vl-registry-delete \"HKEY_CURRENT_USER\\\\Software\\\\Me\" \"Size\")"
        ),
        "T"
    );
    assert_eq!(
        eval(
            &mut fresh,
            "(vl-registry-read \"HKEY_CURRENT_USER\\\\Software\\\\Me\" \"Size\")"
        ),
        "nil"
    );
    assert_eq!(
        eval(&mut fresh, "(setenv \"MyRoutineDir\" \"second\")"),
        "\"second\""
    );
    assert_eq!(eval(&mut it, "(getenv \"MyRoutineDir\")"), "\"second\"");
    let text = std::fs::read_to_string(&file).unwrap();
    assert_eq!(text, "env\\tMyRoutineDir\tsecond\n");
}
