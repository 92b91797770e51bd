//! `defparam`, `lispcad params`, and the usage errors of `--set` names, table columns and
//! out-of-range values (SPEC §2).

use std::process::{Command, Output};

const TEMPLE: &str = concat!(env!("CARGO_MANIFEST_DIR"), "/scripts/temple.lsp");

fn lispcad(args: &[&str]) -> Output {
    Command::new(env!("CARGO_BIN_EXE_lispcad"))
        .args(args)
        .output()
        .unwrap()
}

fn err(o: &Output) -> String {
    String::from_utf8_lossy(&o.stderr).into_owned()
}

#[test]
fn params_lists_the_temple_parameters() {
    let o = lispcad(&["params", TEMPLE]);
    assert_eq!(o.status.code(), Some(0), "{}", err(&o));
    let out = String::from_utf8(o.stdout).unwrap();
    let lines: Vec<&str> = out.lines().collect();
    assert_eq!(lines[0], "NAME     DEFAULT  RANGE     DOC");
    assert_eq!(
        lines[1],
        "L1       140.0    100..200  total length of the temple along its centerline"
    );
    assert_eq!(
        lines[4].split_whitespace().take(3).collect::<Vec<_>>(),
        ["BENDANG", "40.0", "0..90"]
    );
    // Header plus L1 L2 R BENDANG HINGEW MINW TIPW TIPR BASEX BASEY.
    assert_eq!(lines.len(), 11);
}

#[test]
fn params_does_not_run_the_script() {
    let dir = tempfile::tempdir().unwrap();
    let script = dir.path().join("s.lsp");
    std::fs::write(
        &script,
        "(setq f (open \"side-effect.txt\" \"w\")) (close f)\n(defparam N 3 \"count\" 1 10)\n",
    )
    .unwrap();
    let o = lispcad(&["params", script.to_str().unwrap()]);
    assert_eq!(o.status.code(), Some(0), "{}", err(&o));
    assert!(String::from_utf8_lossy(&o.stdout).contains("N     3        1..10  count"));
    assert!(!dir.path().join("side-effect.txt").exists());
}

#[test]
fn a_mistyped_set_name_is_a_usage_error_with_a_suggestion() {
    let dir = tempfile::tempdir().unwrap();
    let out = dir.path().join("t.dxf");
    let o = lispcad(&[
        "run",
        TEMPLE,
        "--set",
        "BEND=30",
        "-o",
        out.to_str().unwrap(),
    ]);
    assert_eq!(o.status.code(), Some(2), "{}", err(&o));
    assert!(
        err(&o).contains("--set BEND: the script does not use BEND (did you mean BENDANG?)"),
        "{}",
        err(&o)
    );
    assert!(!out.exists());
}

#[test]
fn an_out_of_range_value_is_a_usage_error_naming_the_range() {
    let o = lispcad(&["run", TEMPLE, "--set", "L1=300"]);
    assert_eq!(o.status.code(), Some(2), "{}", err(&o));
    assert!(
        err(&o).contains("--set L1=300: parameter L1 must be a number in [100, 200]"),
        "{}",
        err(&o)
    );
    // At run time too (a value computed, not given on the command line).
    let o = lispcad(&[
        "eval",
        "(progn (setq L1 5) (defparam L1 140.0 \"len\" 100 200))",
    ]);
    assert_eq!(o.status.code(), Some(1), "{}", err(&o));
    assert!(
        err(&o).contains("parameter L1 = 5 is outside its range [100, 200]"),
        "{}",
        err(&o)
    );
    // The default applies when nothing was given; a given value wins.
    let o = lispcad(&["eval", "(progn (defparam L1 140.0 \"len\" 100 200) L1)"]);
    assert_eq!(String::from_utf8_lossy(&o.stdout).trim(), "140.0");
    let o = lispcad(&[
        "eval",
        "--set",
        "L1=150",
        "(progn (defparam L1 140.0 \"len\" 100 200) L1)",
    ]);
    assert_eq!(String::from_utf8_lossy(&o.stdout).trim(), "150");
}

#[test]
fn batch_columns_and_values_are_checked_before_any_row_runs() {
    let dir = tempfile::tempdir().unwrap();
    let d = dir.path().display();
    let bad_col = dir.path().join("c.csv");
    std::fs::write(&bad_col, "name,L1,BENDANGLE\n\"a\",140,30\n").unwrap();
    let pat = format!("{d}/out/{{name}}.dxf");
    let o = lispcad(&[
        "batch",
        TEMPLE,
        "--vary",
        bad_col.to_str().unwrap(),
        "-o",
        &pat,
    ]);
    assert_eq!(o.status.code(), Some(2), "{}", err(&o));
    assert!(
        err(&o).contains(
            "column BENDANGLE: the script does not use BENDANGLE (did you mean BENDANG?)"
        ),
        "{}",
        err(&o)
    );
    let bad_val = dir.path().join("v.csv");
    std::fs::write(&bad_val, "name,L1\n\"a\",140\n\"b\",250\n").unwrap();
    let o = lispcad(&[
        "batch",
        TEMPLE,
        "--vary",
        bad_val.to_str().unwrap(),
        "-o",
        &pat,
    ]);
    assert_eq!(o.status.code(), Some(2), "{}", err(&o));
    assert!(
        err(&o).contains("row 2: column L1=250: parameter L1 must be a number in [100, 200]"),
        "{}",
        err(&o)
    );
    let o = lispcad(&[
        "batch",
        TEMPLE,
        "--grid",
        "L1=150:250:50",
        "-o",
        &format!("{d}/out/{{L1}}.dxf"),
    ]);
    assert_eq!(o.status.code(), Some(2), "{}", err(&o));
    assert!(!dir.path().join("out").exists());
}

#[test]
fn names_used_only_by_a_loaded_file_are_accepted() {
    let dir = tempfile::tempdir().unwrap();
    std::fs::create_dir(dir.path().join("lib")).unwrap();
    std::fs::write(
        dir.path().join("lib/shape.lsp"),
        "(defparam RAD 5.0 \"radius\" 1 50)\n(draw (circle '(0 0) RAD))\n(princ RAD)\n",
    )
    .unwrap();
    let main = dir.path().join("main.lsp");
    std::fs::write(&main, "(load \"lib/shape\")\n").unwrap();
    let out = dir.path().join("o.svg");
    let m = main.to_str().unwrap();
    let o = lispcad(&["run", m, "--set", "RAD=7", "-o", out.to_str().unwrap()]);
    assert_eq!(o.status.code(), Some(0), "{}", err(&o));
    assert_eq!(String::from_utf8_lossy(&o.stdout), "7");
    assert!(out.is_file());
    // The loaded file's declared range and names still hold.
    let o = lispcad(&["run", m, "--set", "RAD=70"]);
    assert_eq!(o.status.code(), Some(2), "{}", err(&o));
    assert!(
        err(&o).contains("must be a number in [1, 50]"),
        "{}",
        err(&o)
    );
    let o = lispcad(&["run", m, "--set", "RADIUS=7"]);
    assert_eq!(o.status.code(), Some(2), "{}", err(&o));
    assert!(err(&o).contains("did you mean RAD?"), "{}", err(&o));
    // A batch column too.
    std::fs::write(dir.path().join("t.csv"), "RAD\n3\n4\n").unwrap();
    let o = lispcad(&[
        "batch",
        m,
        "--vary",
        dir.path().join("t.csv").to_str().unwrap(),
        "-o",
        dir.path().join("out/c-{row}.svg").to_str().unwrap(),
    ]);
    assert_eq!(o.status.code(), Some(0), "{}", err(&o));
}
