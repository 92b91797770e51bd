//! The main job: scripts/temple.lsp over a grid of parameters. The bent outline must be
//! closed, pass through the bent type-value points, not cross itself, and sit on a centerline
//! of length L1; its DXF and SVG must pass the validators.

#[path = "output_support/mod.rs"]
mod support;

use glam::DVec3;
use lispcad::builtins::geometry::CurveValue;
use lispcad::geom::bspline::BSpline;
use lispcad::geom::curve::Curve;
use lispcad::geom::intersect::intersect;
use lispcad::geom::temple::{bend_point, TempleParams};
use lispcad::lang::eval::with_eval_stack;
use lispcad::lang::Value;

const SCRIPT: &str = concat!(env!("CARGO_MANIFEST_DIR"), "/scripts/temple.lsp");

struct Run {
    outline: Curve,
    points: Vec<DVec3>,
    centerline_length: f64,
    params: TempleParams,
}

fn curve_of(v: &Value) -> Curve {
    v.as_obj::<CurveValue>().expect("a curve").0.clone()
}

/// Runs the script with the given globals; returns what it built.
fn run(l1: f64, l2: f64, r: f64, bend_deg: f64) -> Run {
    with_eval_stack(move || {
        let mut it = lispcad::builtins::new_interp();
        it.out = Box::new(std::io::sink());
        for (k, v) in [("L1", l1), ("L2", l2), ("R", r), ("BENDANG", bend_deg)] {
            it.set_global(k, Value::Real(v));
        }
        it.load_file(SCRIPT)
            .unwrap_or_else(|e| panic!("{}", e.message));
        let outline = curve_of(&it.global("BENT"));
        let points = it
            .global("PTS")
            .iter()
            .map(|p| DVec3::from_array(it.point(p).unwrap()))
            .collect();
        let centerline = it
            .eval_source("q", "(temple-centerline L1 L2 R theta base)")
            .unwrap();
        let centerline_length = centerline.iter().map(|c| curve_of(c).length()).sum();
        Run {
            outline,
            points,
            centerline_length,
            params: TempleParams {
                l1,
                l2,
                r,
                theta: bend_deg.to_radians(),
                base: glam::DVec2::ZERO,
            },
        }
    })
}

/// The two halves of a closed quadratic spline as B-splines (segments 0..n/2 and n/2..n).
fn halves(c: &Curve) -> (Curve, Curve) {
    let Curve::Spline(s) = c else {
        panic!("the outline is a spline")
    };
    let half = |segs: &[[DVec3; 3]]| {
        let mut ctrl = vec![segs[0][0]];
        let mut knots = vec![0.0; 3];
        for (i, s) in segs.iter().enumerate() {
            ctrl.push(s[1]);
            ctrl.push(s[2]);
            if i + 1 < segs.len() {
                let u = (i + 1) as f64;
                knots.extend([u, u]);
            }
        }
        knots.extend([segs.len() as f64; 3]);
        Curve::BSpline(BSpline::new(2, ctrl, Some(knots), None).unwrap())
    };
    let n = s.segments.len();
    (half(&s.segments[..n / 2]), half(&s.segments[n / 2..]))
}

#[test]
fn the_outline_is_sound_over_a_grid_of_parameters() {
    let mut cases = 0;
    for l1 in [135.0, 145.0] {
        for r in [10.0, 20.0] {
            for bend in [0.0, 25.0, 45.0] {
                let run = run(l1, 35.0, r, bend);
                cases += 1;
                let what = format!("L1 {l1} R {r} bend {bend}");
                assert!(run.outline.is_closed(), "{what}: outline not closed");
                // The centerline keeps its length L1.
                assert!(
                    (run.centerline_length - l1).abs() < 1e-9,
                    "{what}: centerline length {}",
                    run.centerline_length
                );
                // The refitted outline passes through every bent type-value point.
                for p in &run.points {
                    let q = bend_point(*p, &run.params).unwrap();
                    let (_, on) = run.outline.closest_point(q);
                    assert!(
                        on.distance(q) < 1e-9,
                        "{what}: misses {q} by {}",
                        on.distance(q)
                    );
                }
                // No self-intersection: the two halves meet only at their two shared ends.
                let (a, b) = halves(&run.outline);
                let hits = intersect(&a, &b, 1e-9);
                assert_eq!(
                    hits.len(),
                    2,
                    "{what}: halves meet at {:?}",
                    hits.iter().map(|h| h.point).collect::<Vec<_>>()
                );
                let ends = [a.eval(0.0), a.eval(1.0)];
                for h in &hits {
                    assert!(
                        ends.iter().any(|e| e.distance(h.point) < 1e-7),
                        "{what}: self-intersection at {}",
                        h.point
                    );
                }
            }
        }
    }
    assert_eq!(cases, 12);
}

#[test]
fn the_outputs_pass_the_validators() {
    let dir = tempfile::tempdir().unwrap();
    let mut dxfs = Vec::new();
    for (i, set) in [["L1=140.0", "BENDANG=40.0"], ["L1=150.0", "BENDANG=20.0"]]
        .iter()
        .enumerate()
    {
        let dxf = dir.path().join(format!("t{i}.dxf"));
        let cam = dir.path().join(format!("t{i}-cam.dxf"));
        let svg = dir.path().join(format!("t{i}.svg"));
        let mut cmd = std::process::Command::new(env!("CARGO_BIN_EXE_lispcad"));
        cmd.arg("run").arg(SCRIPT);
        for s in set {
            cmd.arg("--set").arg(s);
        }
        let o = cmd
            .arg("-o")
            .arg(&dxf)
            .arg("-o")
            .arg(&svg)
            .output()
            .unwrap();
        assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
        let o = std::process::Command::new(env!("CARGO_BIN_EXE_lispcad"))
            .arg("run")
            .arg(SCRIPT)
            .arg("--dxf-profile")
            .arg("cam")
            .arg("-o")
            .arg(&cam)
            .output()
            .unwrap();
        assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
        support::render_svg(&svg, &dir.path().join(format!("t{i}.png")));
        let cam_report = support::check_dxf(&cam, true);
        assert!(cam_report.to_string().contains("POLYLINE"), "{cam_report}");
        dxfs.push(dxf);
    }
    let reports =
        support::check_dxf_many(&dxfs.iter().map(|p| p.as_path()).collect::<Vec<_>>(), false);
    for r in reports {
        let s = r.to_string();
        for t in ["SPLINE", "LINE", "ARC", "TEXT", "CUT", "CENTER", "NOTES"] {
            assert!(s.contains(t), "{t} missing from {s}");
        }
    }
}
