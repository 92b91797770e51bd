//! Golden files: small drawings whose SVG, CAD DXF and CAM DXF must match tests/golden/
//! byte for byte (reviewed by eye as PNGs from rsvg-convert and LibreCAD before committing).
//! Regenerate with `LISPCAD_UPDATE_GOLDEN=1 cargo test --test output_golden`.

mod output_support;

use std::path::PathBuf;

use glam::{DVec2, DVec3};
use lispcad::geom::quadspline::QuadSpline;
use lispcad::output::{render, Drawing, DxfProfile, Entity, EntityKind, Format, OutputOptions};
use output_support::*;

fn basic() -> Drawing {
    let mut d = Drawing::new();
    d.use_layer("Cut", Some(1)).unwrap();
    d.add_kind(EntityKind::LwPolyline {
        points: vec![
            DVec2::new(0.0, 0.0),
            DVec2::new(40.0, 0.0),
            DVec2::new(40.0, 20.0),
            DVec2::new(0.0, 20.0),
        ],
        bulges: vec![0.0, 0.0, 0.0, 0.4142135623730951],
        closed: true,
        elevation: 0.0,
        normal: DVec3::Z,
    })
    .unwrap();
    d.add_kind(EntityKind::Circle {
        center: DVec3::new(30.0, 10.0, 0.0),
        radius: 4.0,
        normal: DVec3::Z,
    })
    .unwrap();
    d.use_layer("Mark", Some(5)).unwrap();
    d.add_kind(EntityKind::Arc {
        center: DVec3::new(10.0, 10.0, 0.0),
        radius: 5.0,
        start: 0.0,
        end: std::f64::consts::PI,
        normal: DVec3::Z,
    })
    .unwrap();
    d.add_kind(EntityKind::Line {
        p0: DVec3::new(5.0, 10.0, 0.0),
        p1: DVec3::new(15.0, 10.0, 0.0),
    })
    .unwrap();
    d.add(
        Entity::new(
            "Mark",
            EntityKind::Text {
                insert: DVec3::new(2.0, 2.0, 0.0),
                height: 3.0,
                value: "L1=140".into(),
                rotation: 0.0,
                style: "Standard".into(),
            },
        )
        .with_color(3),
    )
    .unwrap();
    d
}

/// A temple-like closed outline as a C1 quadratic spline, and an open cubic.
fn splines() -> Drawing {
    let mut d = Drawing::new();
    d.use_layer("Outline", Some(1)).unwrap();
    // Segments [start, control, end], C1 at every joint (each control, joint and next control
    // collinear), closed.
    let p = |x: f64, y: f64| DVec3::new(x, y, 0.0);
    let segs = [
        [p(0.0, 0.0), p(0.0, 6.0), p(10.0, 6.0)],
        [p(10.0, 6.0), p(60.0, 6.0), p(110.0, 3.0)],
        [p(110.0, 3.0), p(130.0, 1.8), p(135.0, -10.0)],
        [p(135.0, -10.0), p(137.0, -14.72), p(132.0, -12.0)],
        [p(132.0, -12.0), p(122.0, -6.56), p(110.0, -2.0)],
        [p(110.0, -2.0), p(98.0, 2.56), p(10.0, -3.0)],
        [
            p(10.0, -3.0),
            p(0.0, -3.0 - 5.56 * 10.0 / 88.0),
            p(0.0, 0.0),
        ],
    ];
    let q = QuadSpline {
        points: segs.iter().map(|s| s[0]).collect(),
        closed: true,
        segments: segs.to_vec(),
    };
    d.add_kind(EntityKind::Spline {
        curve: q.to_bspline(),
        fit_points: vec![],
        closed: true,
    })
    .unwrap();
    d.use_layer("Guide", Some(8)).unwrap();
    d.add_kind(EntityKind::Spline {
        curve: cubic_s(),
        fit_points: vec![],
        closed: false,
    })
    .unwrap();
    d
}

/// A small pyramid mesh seen from (1, -1, 1).
fn mesh() -> Drawing {
    let mut d = Drawing::new();
    d.use_layer("Surface", Some(4)).unwrap();
    d.add_kind(EntityKind::Mesh {
        vertices: vec![
            DVec3::new(0.0, 0.0, 0.0),
            DVec3::new(20.0, 0.0, 0.0),
            DVec3::new(20.0, 20.0, 0.0),
            DVec3::new(0.0, 20.0, 0.0),
            DVec3::new(10.0, 10.0, 12.0),
        ],
        triangles: vec![[0, 1, 4], [1, 2, 4], [2, 3, 4], [3, 0, 4]],
    })
    .unwrap();
    d
}

fn golden_dir() -> PathBuf {
    manifest().join("tests/golden")
}

fn check(name: &str, d: &Drawing, opts: &OutputOptions, format: Format, ext: &str) {
    let bytes = render(d, format, opts).unwrap();
    let path = golden_dir().join(format!("{name}.{ext}"));
    if std::env::var_os("LISPCAD_UPDATE_GOLDEN").is_some() {
        std::fs::create_dir_all(golden_dir()).unwrap();
        std::fs::write(&path, &bytes).unwrap();
    }
    let want = std::fs::read(&path)
        .unwrap_or_else(|e| panic!("{}: {e} (set LISPCAD_UPDATE_GOLDEN=1)", path.display()));
    assert!(
        bytes == want,
        "{} differs from the golden file (review, then LISPCAD_UPDATE_GOLDEN=1)",
        path.display()
    );
}

fn all_formats(name: &str, d: &Drawing, opts: OutputOptions) {
    check(name, d, &opts, Format::Svg, "svg");
    check(name, d, &opts, Format::Dxf, "dxf");
    let cam = OutputOptions {
        dxf_profile: DxfProfile::Cam,
        ..opts
    };
    check(&format!("{name}_cam"), d, &cam, Format::Dxf, "dxf");
}

#[test]
fn golden_files_match() {
    all_formats("basic", &basic(), OutputOptions::default());
    all_formats("splines", &splines(), OutputOptions::default());
    let oblique = OutputOptions {
        view_dir: DVec3::new(1.0, -1.0, 1.0),
        ..OutputOptions::default()
    };
    check("mesh", &mesh(), &oblique, Format::Svg, "svg");
    check("mesh", &mesh(), &oblique, Format::Dxf, "dxf");
}

#[test]
fn golden_files_are_valid() {
    let dir = golden_dir();
    let mut cad = Vec::new();
    let mut cam = Vec::new();
    for entry in std::fs::read_dir(&dir).unwrap() {
        let p = entry.unwrap().path();
        match p.extension().and_then(|e| e.to_str()) {
            Some("dxf") if p.to_string_lossy().ends_with("_cam.dxf") => cam.push(p),
            Some("dxf") => cad.push(p),
            Some("svg") => {
                let png = tempfile::Builder::new().suffix(".png").tempfile().unwrap();
                render_svg(&p, png.path());
            }
            _ => {}
        }
    }
    cad.sort();
    cam.sort();
    assert_eq!((cad.len(), cam.len()), (3, 2));
    let refs: Vec<&std::path::Path> = cad.iter().map(|p| p.as_path()).collect();
    check_dxf_many(&refs, false);
    let refs: Vec<&std::path::Path> = cam.iter().map(|p| p.as_path()).collect();
    for v in check_dxf_many(&refs, true) {
        assert_eq!(v["cam"]["overlaps"].as_array().unwrap().len(), 0);
        assert_eq!(v["cam"]["congruent_edges"], 0);
    }
}
