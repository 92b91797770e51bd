//! getpoint/getreal/... in batch runs: answers come from `--answers FILE`, one per line, and
//! initget's restrictions turn a bad answer into an error (no one to re-prompt).

mod cli_support;
use cli_support::lispcad_in;

/// Runs `script` with `answers`; (exit code, stdout, stderr).
fn run(script: &str, answers: &str) -> (i32, String, String) {
    let dir = tempfile::tempdir().unwrap();
    std::fs::write(dir.path().join("s.lsp"), script).unwrap();
    std::fs::write(dir.path().join("a.txt"), answers).unwrap();
    let o = lispcad_in(dir.path(), &["run", "s.lsp", "--answers", "a.txt"]);
    (
        o.status.code().expect("exit code, not a signal"),
        String::from_utf8_lossy(&o.stdout).into_owned(),
        String::from_utf8_lossy(&o.stderr).into_owned(),
    )
}

/// Each form's value printed with prin1, one per line.
fn values(forms: &str, answers: &str) -> Vec<String> {
    let script = format!("(foreach v (list {forms}) (prin1 v) (terpri))");
    let (code, out, err) = run(&script, answers);
    assert_eq!(code, 0, "stderr: {err}");
    out.lines().map(str::to_string).collect()
}

#[test]
fn points_absolute_relative_and_polar() {
    let got = values(
        "(setq p (getpoint \"Base: \")) (getpoint p \"Next: \") (getpoint '(10 10) \"@\") \
         (getpoint \"x\") (getpoint) (getpoint) (getpoint) (getpoint) (getpoint) (getpoint)",
        "1,2\n@3,4\n@-1,0.5,2\n5,6,7\n@1,1\n2<0\n\n#7,8\n*1, 2 ,3\n@\n",
    );
    assert_eq!(
        got,
        [
            "(1.0 2.0 0.0)",
            "(4.0 6.0 0.0)",
            "(9.0 10.5 2.0)",
            "(5.0 6.0 7.0)",
            // no base: relative to LASTPOINT, the previous answer
            "(6.0 7.0 7.0)",
            "(2.0 0.0 0.0)",
            "nil",
            "(7.0 8.0 0.0)",
            "(1.0 2.0 3.0)",
            // "@" alone: the last point
            "(1.0 2.0 3.0)",
        ]
    );
}

#[test]
fn numbers_strings_and_enter() {
    let got = values(
        "(getreal) (getreal) (getint) (getint) (getstring) (getstring T \"Name: \") (getstring) \
         (getreal) (getint)",
        "2.5\n3\n-7\n42\nhello world\nhello world\n\n\n\n",
    );
    assert_eq!(
        got,
        [
            "2.5",
            "3.0",
            "-7",
            "42",
            "\"hello\"",
            "\"hello world\"",
            "\"\"",
            "nil",
            "nil"
        ]
    );
}

#[test]
fn distances_and_angles() {
    let got = values(
        "(getdist) (getdist '(0 0)) (getdist '(1 1) \"d\") (getdist) (getangle) (getangle '(0 0)) \
         (getorient) (progn (setvar \"ANGBASE\" (/ pi 2)) (getangle)) \
         (getorient) (getangle '(0 0))",
        "12.5\n3,4\n@0,2\n0,0\n6,8\n90\n-1,-1\n270\n90\n90\n1,0\n",
    );
    assert_eq!(
        got,
        [
            "12.5", "5.0", "2.0", // no base: a second answer gives the other end
            "10.0", "1.5708", "3.92699", "4.71239",
            // typed 90 with ANGBASE 90: absolute 180, returned relative to ANGBASE
            "1.5708",
            // getorient ignores ANGBASE for its result, not for typed input
            "3.14159", // east is -90 from ANGBASE north: 270
            "4.71239",
        ]
    );
}

#[test]
fn keywords() {
    let got = values(
        "(progn (initget \"Width Height LType,LT eXit\") (getkword \"Option: \")) \
         (progn (initget \"Width Height LType,LT eXit\") (getkword)) \
         (progn (initget \"Width Height LType,LT eXit\") (getkword)) \
         (progn (initget \"Width Height LType,LT eXit\") (getkword)) \
         (progn (initget \"Ja Nein _ Yes No\") (getkword)) \
         (progn (initget \"Close\") (getpoint)) \
         (progn (initget \"Close\") (getpoint)) \
         (progn (initget 6 \"Auto\") (getreal)) \
         (progn (initget 128) (getint)) \
         (progn (initget 128) (getpoint))",
        "h\nltype\nx\n\nn\nc\n1,1\nauto\nabc\nnext one\n",
    );
    assert_eq!(
        got,
        [
            "\"Height\"",
            "\"LType\"",
            "\"eXit\"",
            "nil",
            "\"No\"",
            "\"Close\"",
            "(1.0 1.0 0.0)",
            "\"Auto\"",
            "\"abc\"",
            "\"next one\"",
        ]
    );
}

/// Runs one expression with answers; the first line of stderr and the exit code.
fn error_of(expr: &str, answers: &str) -> (i32, String) {
    let (code, _, err) = run(expr, answers);
    let first = err
        .lines()
        .find(|l| !l.trim().is_empty())
        .unwrap_or("")
        .trim()
        .trim_start_matches('×')
        .trim()
        .to_string();
    (code, first)
}

#[test]
fn initget_violations_are_errors_in_batch() {
    let cases = [
        (
            "(progn (initget 1) (getreal))",
            "\n",
            "getreal: answer \"\" rejected: an answer is required (initget 1)",
        ),
        (
            "(progn (initget 2) (getint))",
            "0\n",
            "getint: answer \"0\" rejected: the value must be nonzero (initget 2)",
        ),
        (
            "(progn (initget 4) (getdist))",
            "-3\n",
            "getdist: answer \"-3\" rejected: the value must be nonnegative (initget 4)",
        ),
        (
            "(getint)",
            "2.5\n",
            "getint: answer \"2.5\" rejected: requires an integer value",
        ),
        (
            "(getint)",
            "40000\n",
            "getint: answer \"40000\" rejected: requires an integer between -32768 and 32767",
        ),
        (
            "(getreal)",
            "ten\n",
            "getreal: answer \"ten\" rejected: requires a numeric value",
        ),
        (
            "(getpoint)",
            "1;2\n",
            "getpoint: answer \"1;2\" rejected: not a point (x,y or x,y,z, @dx,dy, d<a)",
        ),
        (
            "(progn (initget \"Yes No\") (getkword))",
            "maybe\n",
            "getkword: answer \"maybe\" rejected: invalid option keyword",
        ),
        (
            "(progn (getreal) (getreal))",
            "1\n",
            "getreal: no answers left in the --answers file",
        ),
    ];
    for (expr, answers, want) in cases {
        assert_eq!(error_of(expr, answers), (1, want.to_string()), "{expr}");
    }
}

#[test]
fn initget_applies_to_the_next_call_only() {
    let got = values("(progn (initget 2) (getint)) (getint)", "5\n0\n");
    assert_eq!(got, ["5", "0"]);
}

#[test]
fn without_answers_or_terminal_it_is_a_clear_error() {
    let dir = tempfile::tempdir().unwrap();
    for (f, call) in [
        ("getpoint", "(getpoint)"),
        ("getreal", "(getreal \"R: \")"),
        ("getstring", "(getstring)"),
    ] {
        let o = lispcad_in(dir.path(), &["eval", call]);
        assert_eq!(o.status.code(), Some(1));
        let err = String::from_utf8_lossy(&o.stderr);
        assert!(
            err.contains(&format!("{f}: no input available (use --answers FILE)")),
            "{err}"
        );
    }
}

#[test]
fn unreadable_answers_file_is_a_usage_error() {
    let dir = tempfile::tempdir().unwrap();
    let o = lispcad_in(
        dir.path(),
        &["eval", "(getint)", "--answers", "missing.txt"],
    );
    assert_eq!(o.status.code(), Some(2));
    assert!(String::from_utf8_lossy(&o.stderr).contains("cannot read the answers file missing.txt"));
}

#[test]
fn eval_reads_answers_too() {
    let dir = tempfile::tempdir().unwrap();
    std::fs::write(dir.path().join("a.txt"), "3,4\n").unwrap();
    let o = lispcad_in(
        dir.path(),
        &["eval", "(distance '(0 0) (getpoint))", "--answers", "a.txt"],
    );
    assert_eq!(String::from_utf8_lossy(&o.stdout).trim(), "5.0");
}

/// The table of AutoCAD's getangle/getorient reference: ANGBASE 90 (north), ANGDIR 1
/// (clockwise); typed degrees -> radians returned.
#[test]
fn getangle_and_getorient_follow_the_reference_table() {
    let got = values(
        "(progn (setvar \"ANGBASE\" (/ pi 2)) (setvar \"ANGDIR\" 1) nil) \
         (getangle) (getangle) (getangle) (getangle) \
         (getorient) (getorient) (getorient) (getorient)",
        "0\n-90\n180\n90\n0\n-90\n180\n90\n",
    );
    assert_eq!(
        got,
        ["nil", "0.0", "1.5708", "3.14159", "4.71239", "1.5708", "3.14159", "4.71239", "0.0"]
    );
}

/// Every batch row gets the whole answer list; without one a row fails instead of waiting.
#[test]
fn batch_rows_each_read_the_answers() {
    let dir = tempfile::tempdir().unwrap();
    let p = dir.path();
    std::fs::write(p.join("t.csv"), "L1\n1\n2\n").unwrap();
    std::fs::write(p.join("a.txt"), "10\n").unwrap();
    std::fs::write(
        p.join("s.lsp"),
        "(setq f (open (strcat \"r\" (itoa L1) \".txt\") \"w\")) (princ (* L1 (getreal)) f) (close f)\n",
    )
    .unwrap();
    let o = lispcad_in(
        p,
        &[
            "batch",
            "s.lsp",
            "--vary",
            "t.csv",
            "-o",
            "out/{L1}.svg",
            "--answers",
            "a.txt",
        ],
    );
    assert_eq!(
        o.status.code(),
        Some(0),
        "{}",
        String::from_utf8_lossy(&o.stderr)
    );
    assert_eq!(std::fs::read_to_string(p.join("r1.txt")).unwrap(), "10.0");
    assert_eq!(std::fs::read_to_string(p.join("r2.txt")).unwrap(), "20.0");
    let o = lispcad_in(
        p,
        &["batch", "s.lsp", "--vary", "t.csv", "-o", "out/{L1}.svg"],
    );
    assert_eq!(o.status.code(), Some(1));
    assert!(String::from_utf8_lossy(&o.stderr).contains("getreal: no input available"));
}

#[test]
fn getfiled_reads_a_file_name() {
    let got = values(
        "(getfiled \"Save\" \"\" \"dxf\" 1) (getfiled \"Save\" \"def.svg\" \"svg\" 1) \
         (getfiled \"Open\" \"\" \"dxf\" 0) (getfiled \"Open\" \"\" \"\" 0) (getfiled \"Open\" \"\" \"dxf\" 0)",
        "out\n\nx.dxf\nplain\n\n",
    );
    assert_eq!(
        got,
        [
            "\"out.dxf\"",
            "\"def.svg\"",
            "\"x.dxf\"",
            "\"plain\"",
            "nil"
        ]
    );
}

#[test]
fn getdist_accepts_architectural_and_fractional_input() {
    let got = values(
        "(getdist) (getdist) (getdist) (getdist)",
        "1'-6\"\n1 1/2\n3/4\n2,0\n4,0\n",
    );
    assert_eq!(got, ["18.0", "1.5", "0.75", "2.0"]);
}

#[test]
fn command_pause_takes_the_next_answer() {
    let got = values(
        "(progn (command \"_.LINE\" '(0 0) pause \"\") (cdr (assoc 11 (entget (entlast))))) \
         (progn (command \"_.CIRCLE\" pause pause) (cdr (assoc 40 (entget (entlast)))))",
        "5,5\n1,1\n2.5\n",
    );
    assert_eq!(got, ["(5.0 5.0 0.0)", "2.5"]);
}
