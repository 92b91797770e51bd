//! Shared by the output tests: sample drawings, the Python validator, rsvg-convert.
#![allow(dead_code)]

use std::path::{Path, PathBuf};
use std::process::Command;

use glam::{DVec2, DVec3};
use lispcad::geom::bspline::BSpline;
use lispcad::output::{Drawing, Entity, EntityKind, Layer};

pub fn manifest() -> PathBuf {
    PathBuf::from(env!("CARGO_MANIFEST_DIR"))
}

/// The venv python `.ci/setup` creates. Missing = test failure (never a skip).
pub fn python() -> PathBuf {
    let p = manifest().join(".venv/bin/python");
    assert!(
        p.exists(),
        "validator python missing at {}: run `bash .ci/setup` first",
        p.display()
    );
    p
}

/// Runs `tests/validate/SCRIPT MODE PATH`; for any mode but `make`, its JSON, whose ezdxf audit
/// must show 0 errors and 0 fixes.
pub fn validator_json(script: &str, mode: &str, path: &Path) -> serde_json::Value {
    let out = Command::new(python())
        .arg(manifest().join("tests/validate").join(script))
        .arg(mode)
        .arg(path)
        .output()
        .unwrap_or_else(|e| panic!("running {script}: {e}"));
    assert!(
        out.status.success(),
        "{script} {mode} failed: {}",
        String::from_utf8_lossy(&out.stderr)
    );
    if mode == "make" {
        return serde_json::Value::Null;
    }
    let v: serde_json::Value =
        serde_json::from_slice(&out.stdout).unwrap_or_else(|e| panic!("JSON from {script}: {e}"));
    assert_eq!(v["audit_errors"], 0, "audit: {}", v["messages"]);
    assert_eq!(v["audit_fixes"], 0, "audit: {}", v["messages"]);
    v
}

/// `lispcad run s.lsp ARGS` in `dir` with `script` as s.lsp; its standard output. A failure
/// fails the test with both outputs.
pub fn run_script(dir: &Path, script: &str, args: &[&str]) -> String {
    std::fs::write(dir.join("s.lsp"), script).unwrap();
    let out = Command::new(env!("CARGO_BIN_EXE_lispcad"))
        .current_dir(dir)
        .arg("run")
        .arg("s.lsp")
        .args(args)
        .output()
        .expect("running lispcad");
    assert!(
        out.status.success(),
        "lispcad failed:\n{}\n{}",
        String::from_utf8_lossy(&out.stdout),
        String::from_utf8_lossy(&out.stderr)
    );
    String::from_utf8_lossy(&out.stdout).to_string()
}

/// The CUT layer's extent as ezdxf reads it ([min x, min y, max x, max y]) and the header's
/// `$INSUNITS` and `$MEASUREMENT`. SPLINEs are flattened to 0.5 µm: ezdxf's own bounding box
/// flattens them coarsely (0.37 mm inside a temple's ear tip).
pub fn ezdxf_cut_extent(dxf: &Path) -> ([f64; 4], i64, i64) {
    let code = format!(
        "import ezdxf\nfrom ezdxf import bbox\ndoc = ezdxf.readfile(r'{}')\n\
         b = bbox.BoundingBox()\n\
         for e in doc.modelspace().query('*[layer==\"CUT\"]'):\n\
         \x20   x = bbox.extents([e])\n\
         \x20   b.extend(e.flattening(0.0005) if e.dxftype() == 'SPLINE' else [x.extmin, x.extmax])\n\
         print(b.extmin.x, b.extmin.y, b.extmax.x, b.extmax.y, \
         doc.header.get('$INSUNITS', 0), doc.header.get('$MEASUREMENT', 0))",
        dxf.display()
    );
    let out = Command::new(python()).args(["-c", &code]).output().unwrap();
    assert!(
        out.status.success(),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
    let s = String::from_utf8(out.stdout).unwrap();
    let f: Vec<&str> = s.split_whitespace().collect();
    let x = |i: usize| -> f64 { f[i].parse().unwrap() };
    (
        [x(0), x(1), x(2), x(3)],
        f[4].parse().unwrap(),
        f[5].parse().unwrap(),
    )
}

/// Run tests/validate/check_dxf.py on one file and check the verdict (see `check_dxf_many`).
pub fn check_dxf(path: &Path, cam: bool) -> serde_json::Value {
    check_dxf_many(&[path], cam).remove(0)
}

/// Run tests/validate/check_dxf.py once over several files; every file must load with the
/// strict reader, audit with 0 errors and 0 fixes, and load without ezdxf warnings.
pub fn check_dxf_many(paths: &[&Path], cam: bool) -> Vec<serde_json::Value> {
    let mut cmd = Command::new(python());
    cmd.arg(manifest().join("tests/validate/check_dxf.py"));
    if cam {
        cmd.arg("--cam");
    }
    cmd.args(paths);
    let out = cmd.output().expect("running check_dxf.py");
    assert!(
        out.status.success(),
        "check_dxf.py failed: {}",
        String::from_utf8_lossy(&out.stderr)
    );
    let v: serde_json::Value = serde_json::from_slice(&out.stdout).unwrap_or_else(|e| {
        panic!(
            "bad JSON from check_dxf.py ({e}): {}",
            String::from_utf8_lossy(&out.stdout)
        )
    });
    let all = if paths.len() == 1 {
        vec![v]
    } else {
        v.as_array().unwrap().clone()
    };
    for (v, path) in all.iter().zip(paths) {
        let path = path.display();
        assert!(
            v.get("load_error").is_none(),
            "ezdxf.readfile refused {path}: {v}"
        );
        assert_eq!(
            v["audit_errors"], 0,
            "audit errors in {path}: {}",
            v["audit_messages"]
        );
        assert_eq!(
            v["audit_fixes"], 0,
            "audit fixes in {path}: {}",
            v["audit_messages"]
        );
        assert_eq!(
            v["load_warnings"].as_array().map_or(0, |a| a.len()),
            0,
            "ezdxf warned while loading {path}: {}",
            v["load_warnings"]
        );
    }
    all
}

/// Render with rsvg-convert to PNG; stderr must be empty.
pub fn render_svg(svg: &Path, png: &Path) {
    let out = Command::new("rsvg-convert")
        .arg("-o")
        .arg(png)
        .arg(svg)
        .output()
        .expect("rsvg-convert not installed: run `bash .ci/setup`");
    assert!(
        out.status.success(),
        "rsvg-convert failed on {}",
        svg.display()
    );
    assert!(
        out.stderr.is_empty(),
        "rsvg-convert warned on {}: {}",
        svg.display(),
        String::from_utf8_lossy(&out.stderr)
    );
}

pub fn v3(x: f64, y: f64, z: f64) -> DVec3 {
    DVec3::new(x, y, z)
}

pub fn cubic_s() -> BSpline {
    BSpline::new(
        3,
        vec![
            v3(0.0, 40.0, 0.0),
            v3(10.0, 60.0, 0.0),
            v3(25.0, 20.0, 0.0),
            v3(40.0, 55.0, 0.0),
            v3(55.0, 40.0, 0.0),
        ],
        None,
        None,
    )
    .unwrap()
}

pub fn quad_wave() -> BSpline {
    BSpline::new(
        2,
        vec![
            v3(60.0, 0.0, 0.0),
            v3(65.0, 10.0, 0.0),
            v3(70.0, 0.0, 0.0),
            v3(75.0, -10.0, 0.0),
            v3(80.0, 0.0, 0.0),
        ],
        Some(vec![0.0, 0.0, 0.0, 0.5, 0.5, 1.0, 1.0, 1.0]),
        None,
    )
    .unwrap()
}

/// A closed, C1 quadratic outline (temple-like blob): clamped ends meet at the start point
/// with matching tangents.
pub fn closed_quad_outline() -> BSpline {
    let c = v3(100.0, 30.0, 0.0);
    let pts: Vec<DVec3> = [
        (20.0, 0.0),
        (20.0, 12.0),
        (0.0, 12.0),
        (-20.0, 12.0),
        (-20.0, 0.0),
        (-20.0, -8.0),
        (0.0, -8.0),
        (20.0, -8.0),
        (20.0, 0.0),
    ]
    .iter()
    .map(|(x, y)| c + v3(*x, *y, 0.0))
    .collect();
    BSpline::new(
        2,
        pts,
        Some(vec![
            0.0, 0.0, 0.0, 0.25, 0.25, 0.5, 0.5, 0.75, 0.75, 1.0, 1.0, 1.0,
        ]),
        None,
    )
    .unwrap()
}

/// A rational quadratic: an exact quarter circle (weights 1, √2/2, 1).
pub fn rational_quarter() -> BSpline {
    BSpline::new(
        2,
        vec![
            v3(150.0, 0.0, 0.0),
            v3(150.0, 10.0, 0.0),
            v3(140.0, 10.0, 0.0),
        ],
        None,
        Some(vec![1.0, std::f64::consts::FRAC_1_SQRT_2, 1.0]),
    )
    .unwrap()
}

/// Every entity kind, two layers with colours, a colour override, OCS arcs.
pub fn mixed_drawing() -> Drawing {
    let mut d = Drawing::new();
    d.set_layer_record(Layer {
        color: 1,
        ..Layer::new("Outline")
    })
    .unwrap();
    d.set_layer_record(Layer {
        color: 5,
        ..Layer::new("Construction")
    })
    .unwrap();
    let add =
        |d: &mut Drawing, layer: &str, kind: EntityKind| d.add(Entity::new(layer, kind)).unwrap();
    add(
        &mut d,
        "0",
        EntityKind::Line {
            p0: v3(0.0, 0.0, 0.0),
            p1: v3(50.0, 0.0, 0.0),
        },
    );
    d.add(
        Entity::new(
            "Construction",
            EntityKind::Line {
                p0: v3(0.0, 0.0, 0.0),
                p1: v3(0.0, 30.0, 5.0),
            },
        )
        .with_color(3),
    )
    .unwrap();
    add(
        &mut d,
        "Outline",
        EntityKind::Circle {
            center: v3(20.0, 15.0, 0.0),
            radius: 7.5,
            normal: DVec3::Z,
        },
    );
    add(
        &mut d,
        "Outline",
        EntityKind::Arc {
            center: v3(40.0, 15.0, 0.0),
            radius: 5.0,
            start: 0.3,
            end: 2.5,
            normal: DVec3::Z,
        },
    );
    // Mirrored arc (extrusion -Z): OCS x is -WX.
    add(
        &mut d,
        "Outline",
        EntityKind::Arc {
            center: v3(40.0, 30.0, 0.0),
            radius: 4.0,
            start: 0.0,
            end: std::f64::consts::FRAC_PI_2,
            normal: -DVec3::Z,
        },
    );
    add(
        &mut d,
        "0",
        EntityKind::Point {
            p: v3(5.0, 5.0, 0.0),
        },
    );
    add(
        &mut d,
        "Outline",
        EntityKind::LwPolyline {
            points: vec![
                DVec2::new(0.0, -20.0),
                DVec2::new(30.0, -20.0),
                DVec2::new(30.0, -10.0),
                DVec2::new(0.0, -10.0),
            ],
            bulges: vec![0.0, 0.5, 0.0, -0.3],
            closed: true,
            elevation: 0.0,
            normal: DVec3::Z,
        },
    );
    add(
        &mut d,
        "Construction",
        EntityKind::Polyline {
            points: vec![
                v3(60.0, -20.0, 0.0),
                v3(70.0, -15.0, 3.0),
                v3(80.0, -20.0, 6.0),
            ],
            bulges: vec![],
            closed: false,
        },
    );
    add(
        &mut d,
        "Outline",
        EntityKind::Polyline {
            points: vec![
                v3(60.0, -40.0, 0.0),
                v3(80.0, -40.0, 0.0),
                v3(80.0, -30.0, 0.0),
            ],
            bulges: vec![0.4, 0.0, 0.0],
            closed: true,
        },
    );
    add(
        &mut d,
        "Outline",
        EntityKind::Spline {
            curve: cubic_s(),
            fit_points: vec![],
            closed: false,
        },
    );
    add(
        &mut d,
        "Outline",
        EntityKind::Spline {
            curve: quad_wave(),
            fit_points: vec![],
            closed: false,
        },
    );
    add(
        &mut d,
        "Outline",
        EntityKind::Spline {
            curve: closed_quad_outline(),
            fit_points: vec![],
            closed: true,
        },
    );
    add(
        &mut d,
        "Outline",
        EntityKind::Spline {
            curve: rational_quarter(),
            fit_points: vec![],
            closed: false,
        },
    );
    add(
        &mut d,
        "0",
        EntityKind::Face3d {
            corners: [
                v3(120.0, -40.0, 0.0),
                v3(140.0, -40.0, 0.0),
                v3(140.0, -20.0, 10.0),
                v3(120.0, -20.0, 10.0),
            ],
        },
    );
    add(
        &mut d,
        "0",
        EntityKind::Text {
            insert: v3(0.0, 70.0, 0.0),
            height: 5.0,
            value: "lispcad 1:1 mm".to_string(),
            rotation: 0.0,
            style: "Standard".to_string(),
        },
    );
    add(
        &mut d,
        "Construction",
        EntityKind::Mesh {
            vertices: vec![
                v3(160.0, 0.0, 0.0),
                v3(180.0, 0.0, 0.0),
                v3(180.0, 20.0, 5.0),
                v3(160.0, 20.0, 5.0),
            ],
            triangles: vec![[0, 1, 2], [0, 2, 3]],
        },
    );
    d
}

pub fn dense(f: impl Fn(f64) -> DVec2, n: usize) -> Vec<DVec2> {
    (0..=n).map(|i| f(i as f64 / n as f64)).collect()
}

/// A bulge segment's arc, derived independently of the library: centre from the chord's
/// midpoint along its left normal by (d/2)/tan(θ/2), then rotation of (a - c) by s·θ.
pub fn bulge_ref(a: DVec2, b: DVec2, bulge: f64) -> Vec<DVec2> {
    if bulge == 0.0 {
        return vec![a, b];
    }
    let th = 4.0 * bulge.atan();
    let ch = b - a;
    let d = ch.length();
    let left = DVec2::new(-ch.y, ch.x) / d;
    let c = (a + b) / 2.0 + left * (d / 2.0) / (th / 2.0).tan();
    // Chord error below 1e-7: sagitta r·(1 - cos(Δ/2)) ≈ r·Δ²/8.
    let r = (a - c).length();
    let n = ((th.abs() * (r / 8e-7).sqrt()).ceil() as usize).clamp(4, 20000);
    dense(|s| c + DVec2::from_angle(th * s).rotate(a - c), n)
}

/// Segments bucketed on a grid, so a distance query looks at a few cells only. Queries
/// farther than one cell from everything answer infinity (a failure at the tolerances here).
pub struct SegIndex {
    cell: f64,
    map: std::collections::HashMap<(i64, i64), Vec<(DVec2, DVec2)>>,
}

impl SegIndex {
    pub fn new(lines: &[Vec<DVec2>]) -> SegIndex {
        let cell = 0.5;
        let mut map: std::collections::HashMap<(i64, i64), Vec<(DVec2, DVec2)>> =
            std::collections::HashMap::new();
        for l in lines {
            let segs: Vec<(DVec2, DVec2)> = if l.len() == 1 {
                vec![(l[0], l[0])]
            } else {
                l.windows(2).map(|w| (w[0], w[1])).collect()
            };
            for (a, b) in segs {
                let lo = (a.min(b) / cell).floor();
                let hi = (a.max(b) / cell).floor();
                for i in lo.x as i64..=hi.x as i64 {
                    for j in lo.y as i64..=hi.y as i64 {
                        map.entry((i, j)).or_default().push((a, b));
                    }
                }
            }
        }
        SegIndex { cell, map }
    }

    pub fn dist(&self, q: DVec2) -> f64 {
        let c = (q / self.cell).floor();
        let mut best = f64::INFINITY;
        for i in -1..=1 {
            for j in -1..=1 {
                let key = (c.x as i64 + i, c.y as i64 + j);
                for (a, b) in self.map.get(&key).map(|v| v.as_slice()).unwrap_or(&[]) {
                    let ab = *b - *a;
                    let s = if ab.length_squared() == 0.0 {
                        0.0
                    } else {
                        ((q - *a).dot(ab) / ab.length_squared()).clamp(0.0, 1.0)
                    };
                    best = best.min((q - (*a + ab * s)).length());
                }
            }
        }
        best
    }
}
