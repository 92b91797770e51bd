//! `lispcad batch`: per-row failures, determinism across -j, interruption.

use std::path::{Path, PathBuf};
use std::process::Command;

fn lispcad() -> Command {
    Command::new(env!("CARGO_BIN_EXE_lispcad"))
}

/// A small temple-like script: fast even in debug builds (point bending, no refit).
const SCRIPT: &str = r#"
(if (not L1) (setq L1 140.0))
(if (not R) (setq R 15.0))
(setq pts '((0 3) (60 4.5) (100 5) (130 6) (140 3) (140 -3) (130 -6) (100 -5) (60 -4.5) (0 -3)))
(layer "CUT" 1)
(draw (spline (bend-temple pts L1 30.0 R 0.5) T))
(layer "CENTER" 5)
(draw (temple-centerline L1 30.0 R 0.5))
"#;

fn setup(dir: &Path) -> PathBuf {
    let script = dir.join("t.lsp");
    std::fs::write(&script, SCRIPT).unwrap();
    script
}

fn files(dir: &Path) -> Vec<(String, Vec<u8>)> {
    let mut v: Vec<_> = std::fs::read_dir(dir)
        .unwrap()
        .map(|e| {
            let p = e.unwrap().path();
            (
                p.file_name().unwrap().to_string_lossy().to_string(),
                std::fs::read(&p).unwrap(),
            )
        })
        .collect();
    v.sort();
    v
}

#[test]
fn a_bad_row_is_reported_and_the_others_are_written() {
    let dir = tempfile::tempdir().unwrap();
    let script = setup(dir.path());
    let table = dir.path().join("v.csv");
    std::fs::write(
        &table,
        "name,L1,R\n\"small\",135,12\n\"broken\",140,0\n\"large\",150,18\n",
    )
    .unwrap();
    let out = dir.path().join("out");
    let o = lispcad()
        .arg("batch")
        .arg(&script)
        .arg("--vary")
        .arg(&table)
        .arg("-o")
        .arg(format!("{}/{{name}}-{{L1}}.dxf", out.display()))
        .arg("-j")
        .arg("2")
        .output()
        .unwrap();
    let err = String::from_utf8_lossy(&o.stderr);
    assert_eq!(o.status.code(), Some(1), "{err}");
    assert!(err.contains("row 2/3 FAILED"), "{err}");
    assert!(err.contains("bend radius R must be > 0"), "{err}");
    assert!(err.contains("2 done, 1 failed"), "{err}");
    let names: Vec<String> = files(&out).into_iter().map(|f| f.0).collect();
    assert_eq!(names, ["large-150.dxf", "small-135.dxf"]);
}

#[test]
fn outputs_do_not_depend_on_the_number_of_jobs() {
    let dir = tempfile::tempdir().unwrap();
    let script = setup(dir.path());
    let run = |jobs: &str, out: &str| {
        let o = lispcad()
            .arg("batch")
            .arg(&script)
            .arg("--grid")
            .arg("L1=135:150:5,R=10,15")
            .arg("-o")
            .arg(format!("{}/{out}/t-{{L1}}-{{R}}.dxf", dir.path().display()))
            .arg("-o")
            .arg(format!("{}/{out}/t-{{row}}.svg", dir.path().display()))
            .arg("-j")
            .arg(jobs)
            .output()
            .unwrap();
        assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
        files(&dir.path().join(out))
    };
    let one = run("1", "j1");
    let four = run("4", "j4");
    assert_eq!(one.len(), 16);
    assert_eq!(one, four);
}

#[cfg(unix)]
#[test]
fn an_interrupted_batch_leaves_no_partial_file() {
    let dir = tempfile::tempdir().unwrap();
    let script = dir.path().join("slow.lsp");
    // Each row spins for a while, then draws: the signal lands mid-batch.
    std::fs::write(
        &script,
        "(setq i 0) (while (< i 300000) (setq i (1+ i))) (draw (circle '(0 0) N))",
    )
    .unwrap();
    let out = dir.path().join("out");
    let mut child = lispcad()
        .arg("batch")
        .arg(&script)
        .arg("--grid")
        .arg("N=1:5000:1")
        .arg("-o")
        .arg(format!("{}/c-{{N}}.svg", out.display()))
        .arg("-j")
        .arg("2")
        .stderr(std::process::Stdio::null())
        .spawn()
        .unwrap();
    // Signal once the first file is out (not after a fixed delay, which a fast machine
    // outruns): the batch is then surely under way and far from done.
    let started = std::time::Instant::now();
    while !out.exists() || std::fs::read_dir(&out).unwrap().next().is_none() {
        assert!(
            started.elapsed().as_secs() < 120,
            "the batch wrote nothing in 120 s"
        );
        std::thread::sleep(std::time::Duration::from_millis(10));
    }
    let _ = Command::new("kill")
        .arg("-TERM")
        .arg(child.id().to_string())
        .status();
    let status = child.wait().unwrap();
    assert!(
        !status.success(),
        "an interrupted batch must not report success"
    );
    let written = if out.exists() {
        files(&out)
    } else {
        Vec::new()
    };
    assert!(written.len() < 5000, "the batch was not interrupted");
    for (name, bytes) in written {
        assert!(name.ends_with(".svg"), "stray file {name}");
        let text = String::from_utf8(bytes).unwrap();
        assert!(text.trim_end().ends_with("</svg>"), "{name} is partial");
    }
}

#[test]
fn an_excel_table_with_bom_semicolons_and_crlf_binds_every_column() {
    let dir = tempfile::tempdir().unwrap();
    let script = setup(dir.path());
    let table = dir.path().join("v.csv");
    std::fs::write(
        &table,
        "\u{feff}name;L1;R\r\n\"small\";135;12\r\n\"large\";150;18\r\n",
    )
    .unwrap();
    let out = dir.path().join("out");
    let o = lispcad()
        .arg("batch")
        .arg(&script)
        .arg("--vary")
        .arg(&table)
        .arg("-o")
        .arg(format!("{}/{{name}}-{{L1}}-{{R}}.dxf", out.display()))
        .output()
        .unwrap();
    let err = String::from_utf8_lossy(&o.stderr);
    assert_eq!(o.status.code(), Some(0), "{err}");
    let names: Vec<String> = files(&out).into_iter().map(|f| f.0).collect();
    assert_eq!(names, ["large-150-18.dxf", "small-135-12.dxf"]);
}

#[test]
fn a_ragged_table_is_a_usage_error_naming_its_line() {
    let dir = tempfile::tempdir().unwrap();
    let script = setup(dir.path());
    let table = dir.path().join("v.csv");
    std::fs::write(&table, "L1,R\n135,12\n\n150\n").unwrap();
    let o = lispcad()
        .arg("batch")
        .arg(&script)
        .arg("--vary")
        .arg(&table)
        .arg("-o")
        .arg(format!("{}/o-{{row}}.dxf", dir.path().display()))
        .output()
        .unwrap();
    let err = String::from_utf8_lossy(&o.stderr);
    assert_eq!(o.status.code(), Some(2), "{err}");
    assert!(err.contains("line 4: 1 fields, the header has 2"), "{err}");
}

#[cfg(unix)]
#[test]
fn a_ten_billion_row_grid_streams_and_stops_on_a_signal() {
    use std::io::{BufRead, BufReader};
    let dir = tempfile::tempdir().unwrap();
    let script = setup(dir.path());
    let mut child = lispcad()
        .arg("batch")
        .arg(&script)
        .arg("--grid")
        .arg("L1=0:99999:1,R=0:99999:1")
        .arg("-o")
        .arg(format!("{}/out/t-{{row}}.svg", dir.path().display()))
        .arg("-j")
        .arg("1")
        .arg("--max-steps")
        .arg("1")
        .stderr(std::process::Stdio::piped())
        .spawn()
        .unwrap();
    let mut lines = BufReader::new(child.stderr.take().unwrap()).lines();
    // The count comes first, before any row (building the grid first took 24 GB).
    assert_eq!(lines.next().unwrap().unwrap(), "batch: 10000000000 rows");
    assert!(lines
        .next()
        .unwrap()
        .unwrap()
        .starts_with("row 1/10000000000 FAILED"));
    let _ = Command::new("kill")
        .arg("-INT")
        .arg(child.id().to_string())
        .status();
    let rest: Vec<String> = lines.map_while(Result::ok).collect();
    let status = child.wait().unwrap();
    assert_eq!(status.code(), Some(1));
    let summary = rest
        .iter()
        .find(|l| l.starts_with("batch: "))
        .expect("summary");
    assert!(summary.contains(" not run"), "{summary}");
}

/// Rows share a worker's interpreter (the script compiled once, the globals reset per row):
/// nothing a row leaves behind — a global, a redefined builtin, a layer, an entity — may reach
/// the next. Each row's files must be byte for byte those of `lispcad run` with the row's
/// values given by `--set`.
#[test]
fn every_row_is_written_as_a_fresh_run_would_write_it() {
    let dir = tempfile::tempdir().unwrap();
    let script = dir.path().join("leaky.lsp");
    std::fs::write(
        &script,
        format!(
            "{SCRIPT}
(if seen (setq L1 (+ L1 100.0)))
(setq seen T)
(if (= R 10) (progn (layer \"EXTRA\" 3) (draw (line '(0 0) (list L1 R)))))
(draw (line '(0 -10) (list (+ L1 0.5) -10)))
(setq + -)
"
        ),
    )
    .unwrap();
    let grid = [("135", "10"), ("140", "15"), ("145", "10"), ("150", "20")];
    let o = lispcad()
        .arg("batch")
        .arg(&script)
        .arg("--grid")
        .arg("L1=135:150:5,R=10,15,20")
        .arg("-o")
        .arg(format!("{}/batch/t-{{L1}}-{{R}}.dxf", dir.path().display()))
        .arg("-o")
        .arg(format!("{}/batch/t-{{L1}}-{{R}}.svg", dir.path().display()))
        .arg("-j")
        .arg("1")
        .output()
        .unwrap();
    assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
    assert_eq!(files(&dir.path().join("batch")).len(), 24);
    for (l1, r) in grid {
        let solo = dir.path().join("solo");
        std::fs::create_dir_all(&solo).unwrap();
        let o = lispcad()
            .arg("run")
            .arg(&script)
            .arg("--set")
            .arg(format!("L1={l1}"))
            .arg("--set")
            .arg(format!("R={r}"))
            .arg("-o")
            .arg(solo.join("t.dxf"))
            .arg("-o")
            .arg(solo.join("t.svg"))
            .output()
            .unwrap();
        assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
        for ext in ["dxf", "svg"] {
            let batch = std::fs::read(dir.path().join(format!("batch/t-{l1}-{r}.{ext}"))).unwrap();
            let run = std::fs::read(solo.join(format!("t.{ext}"))).unwrap();
            assert!(
                batch == run,
                "row L1={l1} R={r}: the batch's .{ext} differs from run's"
            );
        }
    }
}
