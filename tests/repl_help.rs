//! The REPL's help for user code (through a pipe): `:help` / `(help 'name)` on defuns with the
//! comment above, "did you mean", `:apropos`, `:inspect`, and `trace` printing calls as
//! AutoCAD does.

mod cli_support;
use cli_support::repl_output;

/// (stdout, stderr) of a piped session in a directory holding `files`.
fn session(files: &[(&str, &str)], args: &[&str], input: &str) -> (String, String) {
    let dir = tempfile::tempdir().unwrap();
    for (name, text) in files {
        std::fs::write(dir.path().join(name), text).unwrap();
    }
    let o = repl_output(dir.path(), args, input);
    (
        String::from_utf8_lossy(&o.stdout).into_owned(),
        String::from_utf8_lossy(&o.stderr).into_owned(),
    )
}

const LIB: &str = "(setq unrelated 1)\n\n;;; Degrees to radians.\n;;; A: an angle in degrees.\n(defun dtr (a / r)\n  (setq r (* pi (/ a 180.0))))\n(defun bare () 1)\n";

#[test]
fn help_on_user_defuns_shows_parameters_and_comment() {
    let (out, _) = session(
        &[("lib.lsp", LIB)],
        &["lib.lsp"],
        ":help dtr\n(help 'DTR)\n:help bare\n",
    );
    let want = "(DTR A / R)\n  Degrees to radians.\n  A: an angle in degrees.\n";
    assert_eq!(
        out,
        format!("{want}{want}(BARE)\n  a user function\n"),
        "{out}"
    );
}

#[test]
fn help_on_a_defun_typed_in_the_session() {
    let (out, _) = session(
        &[],
        &[],
        ";; Twice x.\n(defun twice (x) (* 2 x))\n:help twice\n",
    );
    // The comment was its own entry, just before the defun's.
    assert_eq!(out, "nil\nTWICE\n(TWICE X)\n  Twice x.\n", "{out}");
}

#[test]
fn did_you_mean_for_functions_and_symbols() {
    let (out, err) = session(
        &[("lib.lsp", LIB)],
        &["lib.lsp"],
        "(dtrr 90)\n:help dtrr\nunrelatd\n",
    );
    assert!(err.contains("× no function definition: DTRR"), "{err}");
    assert!(err.contains("help: did you mean DTR?"), "{err}");
    assert!(
        out.contains("no help for dtrr: not a builtin or a defun; did you mean dtr?"),
        "{out}"
    );
    assert!(
        err.contains("; UNRELATD has no value; did you mean UNRELATED?"),
        "{err}"
    );
}

#[test]
fn apropos_lists_matching_builtins_and_defuns() {
    let (out, _) = session(
        &[("lib.lsp", LIB)],
        &["lib.lsp"],
        ":apropos DTR\n:apropos zzqq\n",
    );
    let lines: Vec<&str> = out.lines().collect();
    assert!(
        lines[0].starts_with("(DTR A / R)") && lines[0].ends_with("Degrees to radians."),
        "{out}"
    );
    assert!(
        lines.iter().any(|l| l.starts_with("(findtrustedfile")),
        "{out}"
    );
    assert!(
        lines
            .iter()
            .all(|l| l.to_lowercase().contains("dtr") || l.starts_with("nothing")),
        "{out}"
    );
    assert_eq!(*lines.last().unwrap(), "nothing matches zzqq");
}

#[test]
fn inspect_shows_the_properties_that_apply() {
    let (out, err) = session(
        &[],
        &[],
        ":inspect (circle '(0 0) 5)\n:inspect (sphere-surface '(0 0 0) 2)\n(draw (line '(0 0) '(3 4)))\n:inspect (entlast)\n",
    );
    assert!(err.is_empty(), "{err}");
    let want = "#<CIRCLE (0 0 0) R5>\n  type            CURVE\n  length          31.4159\n  closed          T\n";
    assert!(out.starts_with(want), "{out}");
    assert!(out.contains("  area            78.5398\n"), "{out}");
    assert!(
        out.contains("  bounding box    ((-5.0 -5.0 0.0) (5.0 5.0 0.0))\n"),
        "{out}"
    );
    assert!(
        out.contains(
            "#<SURFACE SPHERE R2>\n  type            SURFACE\n  surface area    50.2655\n"
        ),
        "{out}"
    );
    assert!(
        !out.contains("  length          50"),
        "no curve length for a surface: {out}"
    );
    // An entity: one group per line, then its curve's properties.
    let entity = out.split("  type            ENAME\n").nth(1).expect(&out);
    assert!(
        entity.starts_with("  entity\n    (-1 . <Entity name: "),
        "{out}"
    );
    assert!(entity.contains("\n    (0 . \"LINE\")\n"), "{out}");
    assert!(
        entity.contains("\n    (10 0.0 0.0 0.0)\n    (11 3.0 4.0 0.0)\n"),
        "{out}"
    );
    assert!(
        entity.ends_with("  length          5.0\n  closed          nil\n  start           (0.0 0.0 0.0)\n  end             (3.0 4.0 0.0)\n"),
        "{out}"
    );
}

#[test]
fn inspect_and_apropos_without_an_argument_say_how_to_use_them() {
    let (out, err) = session(&[], &[], ":inspect\n:apropos\n:inspect   \n");
    assert_eq!(out, "", "nothing evaluated, nothing listed");
    assert_eq!(
        err,
        "usage: :inspect EXPR (the properties of a curve, surface, mesh, entity or list)\n\
         usage: :apropos TEXT (the functions whose names contain TEXT)\n\
         usage: :inspect EXPR (the properties of a curve, surface, mesh, entity or list)\n"
    );
}

#[test]
fn trace_prints_calls_and_results_like_autocad() {
    let (out, _) = session(
        &[],
        &[],
        "(defun fact (n) (if (< n 2) 1 (* n (fact (1- n)))))\n(trace fact)\n(fact 3)\n(untrace fact)\n(fact 2)\n",
    );
    assert_eq!(
        out,
        "FACT\nFACT\nEntering (FACT 3)\n  Entering (FACT 2)\n    Entering (FACT 1)\n    Result:  1\n  Result:  2\nResult:  6\n6\nFACT\n2\n",
        "{out}"
    );
}

#[test]
fn trace_in_a_script_and_errors_inside_traced_calls() {
    let dir = tempfile::tempdir().unwrap();
    std::fs::write(
        dir.path().join("t.lsp"),
        "(defun half (x) (/ x 2))\n(trace half)\n(princ (half 8))\n(half \"a\")\n",
    )
    .unwrap();
    let o = cli_support::lispcad_in(dir.path(), &["run", "t.lsp"]);
    assert_eq!(o.status.code(), Some(1));
    let out = String::from_utf8_lossy(&o.stdout);
    assert_eq!(
        out, "Entering (HALF 8)\nResult:  4\n4Entering (HALF \"a\")\n",
        "{out}"
    );
    let err = String::from_utf8_lossy(&o.stderr);
    assert!(err.contains("bad argument type: numberp: \"a\""), "{err}");
}
