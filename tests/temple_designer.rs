//! The bundled temple as a designer judges it (issue 15 item 5), for the default and every row
//! of scripts/variants.csv: a straight hinge butt of HINGEW, a rounded ear tip of radius TIPR,
//! no overshoot between type-value points, and an outline without a tangent jump above 0.5°
//! anywhere but the two hinge corners. Also measures the exact bend against the smooth one.

use glam::DVec3;
use lispcad::builtins::geometry::CurveValue;
use lispcad::geom::curve::Curve;
use lispcad::geom::quadspline::QuadSpline;
use lispcad::geom::temple::{bend_spline, centerline, TempleParams};
use lispcad::geom::ParamCurve;
use lispcad::lang::eval::with_eval_stack;
use lispcad::lang::Value;

const SCRIPT: &str = concat!(env!("CARGO_MANIFEST_DIR"), "/scripts/temple.lsp");
const VARIANTS: &str = concat!(env!("CARGO_MANIFEST_DIR"), "/scripts/variants.csv");

/// The tolerance the script refits the bend within (its smooth variant).
const SMOOTH_TOL: f64 = 0.05;
/// Arc length over which a "jump" is measured: a turn of 0.5° within it is a radius of
/// curvature under 1.15 mm, which the eye reads as a corner at 1:1.
const WINDOW: f64 = 0.01;

struct Temple {
    vars: Vec<(String, f64)>,
    /// The unbent outline and its type-value points.
    outline: QuadSpline,
    bent: QuadSpline,
    params: TempleParams,
    benddev: f64,
}

fn spline_of(v: &Value) -> QuadSpline {
    match &v.as_obj::<CurveValue>().expect("a curve").0 {
        Curve::Spline(s) => s.clone(),
        other => panic!("not a quadratic spline: {other:?}"),
    }
}

fn get(vars: &[(String, f64)], k: &str, default: f64) -> f64 {
    vars.iter().find(|(n, _)| n == k).map_or(default, |v| v.1)
}

fn run(vars: Vec<(String, f64)>) -> Temple {
    with_eval_stack(move || {
        let mut it = lispcad::builtins::new_interp();
        it.out = Box::new(std::io::sink());
        for (k, v) in &vars {
            it.set_global(k, Value::Real(*v));
        }
        it.load_file(SCRIPT)
            .unwrap_or_else(|e| panic!("{}", e.message));
        let outline = spline_of(&it.global("OUTLINE"));
        let bent = spline_of(&it.global("BENT"));
        let benddev = match it.eval_source("q", "(getvar \"BENDDEV\")").unwrap() {
            Value::Real(x) => x,
            v => panic!("BENDDEV {v:?}"),
        };
        let params = TempleParams {
            l1: get(&vars, "L1", 140.0),
            l2: get(&vars, "L2", 35.0),
            r: get(&vars, "R", 15.0),
            theta: get(&vars, "BENDANG", 40.0).to_radians(),
            base: glam::DVec2::ZERO,
        };
        Temple {
            vars,
            outline,
            bent,
            params,
            benddev,
        }
    })
}

/// The default temple and one per row of variants.csv.
fn all_temples() -> Vec<Temple> {
    let text = std::fs::read_to_string(VARIANTS).unwrap();
    let mut lines = text.lines();
    let header: Vec<&str> = lines.next().unwrap().split(',').collect();
    let mut out = vec![run(vec![])];
    for line in lines.filter(|l| !l.trim().is_empty()) {
        let vars = header
            .iter()
            .zip(line.split(','))
            .filter_map(|(k, v)| v.parse::<f64>().ok().map(|x| (k.to_string(), x)))
            .collect();
        out.push(run(vars));
    }
    out
}

/// (arc length, point, unit tangent) densely along the spline; zero-speed samples (corners)
/// are left out.
fn samples(s: &QuadSpline, per_segment: usize) -> Vec<(f64, DVec3, DVec3)> {
    let mut out = Vec::new();
    let mut len = 0.0;
    let mut last: Option<DVec3> = None;
    for sg in &s.segments {
        for k in 0..=per_segment {
            let u = k as f64 / per_segment as f64;
            let p = lispcad::geom::quadspline::quad_bezier(sg, u);
            let d = (sg[1] - sg[0]) * (1.0 - u) + (sg[2] - sg[1]) * u;
            if let Some(q) = last {
                len += p.distance(q);
            }
            last = Some(p);
            if let Some(t) = d.try_normalize() {
                out.push((len, p, t));
            }
        }
    }
    out
}

/// The largest turn of the tangent within WINDOW of arc length, away from `skip` points.
fn worst_turn(s: &QuadSpline, skip: &[DVec3]) -> (f64, DVec3) {
    let pts = samples(s, 64);
    let mut worst = (0.0f64, DVec3::ZERO);
    let mut j = 0;
    for i in 0..pts.len() {
        if skip.iter().any(|c| c.distance(pts[i].1) < 0.05) {
            continue;
        }
        j = j.max(i);
        while j + 1 < pts.len() && pts[j + 1].0 - pts[i].0 <= WINDOW {
            j += 1;
        }
        if skip.iter().any(|c| c.distance(pts[j].1) < 0.05) {
            continue;
        }
        let a = pts[i].2.dot(pts[j].2).clamp(-1.0, 1.0).acos().to_degrees();
        if a > worst.0 {
            worst = (a, pts[i].1);
        }
    }
    worst
}

fn hinge_corners(t: &Temple) -> [DVec3; 2] {
    let h0 = get(&t.vars, "HINGEW", 5.0) / 2.0;
    [DVec3::new(0.0, -h0, 0.0), DVec3::new(0.0, h0, 0.0)]
}

#[test]
fn every_variant_is_smooth_except_at_the_hinge_corners() {
    for t in all_temples() {
        let (turn, at) = worst_turn(&t.bent, &hinge_corners(&t));
        assert!(
            turn <= 0.5,
            "{:?}: the outline turns {turn}° within {WINDOW} mm at {at}",
            t.vars
        );
        assert!(
            t.benddev <= SMOOTH_TOL,
            "{:?}: BENDDEV {}",
            t.vars,
            t.benddev
        );
    }
}

#[test]
fn the_exact_bend_keeps_its_corners_and_the_smooth_one_rounds_them() {
    // Measured on the sport variant (the largest bend): the exact refit (GEOMTOL·1000)
    // reproduces the corner where the outline enters the arc, the smooth one does not.
    let t = run(vec![
        ("L1".into(), 145.0),
        ("L2".into(), 42.0),
        ("R".into(), 18.0),
        ("BENDANG".into(), 52.0),
        ("HINGEW".into(), 5.5),
        ("MINW".into(), 4.0),
        ("TIPW".into(), 8.0),
    ]);
    let exact = bend_spline(&t.outline, &t.params, 1e-6).unwrap();
    let smooth = bend_spline(&t.outline, &t.params, SMOOTH_TOL).unwrap();
    let skip = hinge_corners(&t);
    let (e, _) = worst_turn(&exact.spline, &skip);
    let (s, _) = worst_turn(&smooth.spline, &skip);
    println!(
        "sport-145: exact bend turns {e:.3}° within {WINDOW} mm ({} points added, deviation \
         {:.1e}); smooth {s:.3}° ({} added, deviation {:.2e})",
        exact.added_points, exact.deviation, smooth.added_points, smooth.deviation
    );
    assert!(e > 0.5, "exact {e}");
    assert!(s <= 0.5, "smooth {s}");
    assert!(smooth.deviation <= SMOOTH_TOL && exact.deviation <= 1e-6);
}

#[test]
fn the_hinge_end_is_a_straight_butt_of_hingew() {
    for t in all_temples() {
        let h0 = get(&t.vars, "HINGEW", 5.0) / 2.0;
        // Every sample near the hinge end (x < 0.01·L1) lies on the butt (x = 0, |y| ≤ h0) or
        // on a straight edge (|y| = h0): nothing rounds the corners.
        for (_, p, _) in samples(&t.bent, 64) {
            if p.x < 0.01 * t.params.l1 {
                let on_butt = p.x.abs() < 1e-12 && p.y.abs() <= h0 + 1e-12;
                let on_edge = (p.y.abs() - h0).abs() < 1e-12;
                assert!(on_butt || on_edge, "{:?}: {p} off the butt", t.vars);
            }
        }
    }
}

#[test]
fn the_ear_tip_is_rounded_on_tipr() {
    for tipr in [1.5, 2.0, 3.0] {
        let t = run(vec![("TIPR".into(), tipr), ("BENDANG".into(), 0.0)]);
        // Radius of the circle through the apex and the outline 0.3·TIPR either side.
        let apex = DVec3::new(t.params.l1, 0.0, 0.0);
        let tip = t.outline.closest_point(apex);
        assert!(tip.distance < 1e-12);
        let len = t.outline.length(1e-9);
        let s0 = t.outline.length_to(tip.t, 1e-9);
        let at = |s: f64| t.outline.eval(t.outline.param_at_length(s, 1e-9));
        let (a, b) = (at(s0 - 0.3 * tipr), at((s0 + 0.3 * tipr).min(len)));
        let r = circumradius(a, apex, b);
        assert!((r / tipr - 1.0).abs() < 0.15, "TIPR {tipr}: tip radius {r}");
    }
}

fn circumradius(a: DVec3, b: DVec3, c: DVec3) -> f64 {
    let (ab, bc, ca) = (a.distance(b), b.distance(c), c.distance(a));
    let area2 = (b - a).cross(c - a).length();
    ab * bc * ca / (2.0 * area2)
}

#[test]
fn no_overshoot_between_type_value_points() {
    for t in all_temples() {
        // Unbent: between consecutive type-value points the outline stays in the box of the
        // two points (the spline's own guarantee, in the temple's frame).
        let s = &t.outline;
        let n = s.points.len();
        for j in 0..n {
            let (p, q) = (s.points[j], s.points[(j + 1) % n]);
            let (lo, hi) = (p.min(q), p.max(q));
            for sg in &s.segments[2 * j..2 * j + 2] {
                for k in 0..=32 {
                    let x = lispcad::geom::quadspline::quad_bezier(sg, k as f64 / 32.0);
                    assert!(
                        x.cmpge(lo - 1e-9).all() && x.cmple(hi + 1e-9).all(),
                        "{:?}: {x} outside the box of {p} and {q}",
                        t.vars
                    );
                }
            }
        }
        // Bent: no point of the outline lies farther from the bent centerline than the
        // widest type-value point of its stretch allows (plus the refit tolerance).
        let c = centerline(&t.params).unwrap();
        let widest = s.points.iter().map(|p| p.y.abs()).fold(0.0, f64::max);
        for (_, p, _) in samples(&t.bent, 16) {
            assert!(
                c.distance(p) <= widest + SMOOTH_TOL + 1e-9,
                "{:?}: {p} is {} from the centerline",
                t.vars,
                c.distance(p)
            );
        }
    }
}

/// The CUT layer of `lispcad run` DXF files as ezdxf reads them: per file, the entities in
/// order, a LINE as its ends and a SPLINE as ezdxf's own Bézier decomposition of it.
const READ_CUT: &str = r#"
import sys, json, ezdxf
out = []
for f in sys.argv[1:]:
    doc = ezdxf.readfile(f)
    audit = doc.audit()
    assert not audit.has_errors and not audit.has_fixes, f
    pieces = []
    for e in doc.modelspace():
        if e.dxf.layer != 'CUT':
            continue
        if e.dxftype() == 'LINE':
            pieces.append({'line': [list(e.dxf.start)[:2], list(e.dxf.end)[:2]]})
        elif e.dxftype() == 'SPLINE':
            b = e.construction_tool()
            pieces.append({'beziers': [[[p.x, p.y] for p in c] for c in b.bezier_decomposition()]})
        else:
            pieces.append({'other': e.dxftype()})
    out.append(pieces)
print(json.dumps(out))
"#;

fn xy(v: &serde_json::Value) -> DVec3 {
    DVec3::new(v[0].as_f64().unwrap(), v[1].as_f64().unwrap(), 0.0)
}

/// The CAD file holds the bent outline exactly as ezdxf reads it: the CUT layer is a chain,
/// in the outline's order from the lower hinge corner, of SPLINEs whose Bézier pieces are the
/// outline's own segments (to 1e-6 mm) and LINEs each covering a run of straight segments
/// (the straight ends next to the hinge corners and the butt), so the hinge corners are
/// entity ends, which LibreCAD draws sharp (tests/librecad.rs).
#[test]
fn the_cad_file_traces_the_outline_exactly_with_the_hinge_corners_as_entity_ends() {
    let dir = tempfile::tempdir().unwrap();
    let temples = all_temples();
    let mut files = Vec::new();
    for (i, t) in temples.iter().enumerate() {
        let f = dir.path().join(format!("t{i}.dxf"));
        let mut cmd = std::process::Command::new(env!("CARGO_BIN_EXE_lispcad"));
        cmd.args(["run", SCRIPT, "-o"]).arg(&f);
        for (k, v) in &t.vars {
            cmd.arg("--set").arg(format!("{k}={v}"));
        }
        let o = cmd.output().unwrap();
        assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
        files.push(f);
    }
    let py = concat!(env!("CARGO_MANIFEST_DIR"), "/.venv/bin/python");
    let o = std::process::Command::new(py)
        .args(["-c", READ_CUT])
        .args(&files)
        .output()
        .expect("validator python missing: run `bash .ci/setup` first");
    assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
    let read: Vec<serde_json::Value> = serde_json::from_slice(&o.stdout).unwrap();
    // The SPLINEs have simple knots (LibreCAD mishandles repeated ones), which put each joint
    // on the line through its two controls; the refit's joints sit off that line by up to
    // ~1e-9 of the outline's size (the writer's previous single SPLINE did too): 2e-7 mm seen.
    let close = |a: DVec3, b: DVec3| a.distance(b) <= 1e-6;
    for (t, pieces) in temples.iter().zip(&read) {
        let what = format!("{:?}", t.vars);
        let segs = &t.bent.segments;
        let mut next = 0;
        let mut ends = Vec::new();
        for piece in pieces.as_array().unwrap() {
            if let Some(l) = piece.get("line") {
                let (a, b) = (xy(&l[0]), xy(&l[1]));
                assert!(close(a, segs[next][0]), "{what}: line starts off the chain");
                let on_line = |p: DVec3| (p - a).cross(b - a).length() <= 1e-9 * a.distance(b);
                loop {
                    let s = segs[next];
                    assert!(
                        on_line(s[1]) && on_line(s[2]),
                        "{what}: a line over a curve"
                    );
                    next += 1;
                    if close(s[2], b) {
                        break;
                    }
                }
                ends.push((a, b));
            } else if let Some(bz) = piece.get("beziers") {
                let bz = bz.as_array().unwrap();
                ends.push((xy(&bz[0][0]), xy(&bz[bz.len() - 1][2])));
                for c in bz {
                    let s = segs[next];
                    for k in 0..3 {
                        assert!(
                            close(xy(&c[k]), s[k]),
                            "{what}: segment {next} read as {c} for {s:?}"
                        );
                    }
                    next += 1;
                }
            } else {
                panic!("{what}: unexpected CUT entity {piece}");
            }
        }
        assert_eq!(next, segs.len(), "{what}: the chain stops short");
        for w in ends.windows(2) {
            assert!(close(w[0].1, w[1].0), "{what}: chain broken");
        }
        // The hinge corners begin and end entities.
        for c in hinge_corners(t) {
            assert!(
                ends.iter().any(|(a, _)| close(*a, c)) && ends.iter().any(|(_, b)| close(*b, c)),
                "{what}: hinge corner {c} inside an entity"
            );
        }
    }
}
