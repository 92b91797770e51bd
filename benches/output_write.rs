//! Writing 100,000 mixed entities (8 kinds × 12,500) to DXF (CAD profile) and SVG. The same
//! entities are written by ezdxf in bench/output/ezdxf_write.py; bench/output/run.sh compares.

use criterion::{criterion_group, criterion_main, Criterion};
use glam::{DVec2, DVec3};
use lispcad::geom::bspline::BSpline;
use lispcad::output::{dxf::write_cad, svg::write_svg, Drawing, EntityKind, OutputOptions};

/// Entity i of the benchmark set; bench/output/ezdxf_write.py builds the same list.
fn entity(i: usize) -> EntityKind {
    let x = (i % 1000) as f64 * 0.37;
    let y = (i / 1000) as f64 * 0.53;
    let p = |dx: f64, dy: f64| DVec3::new(x + dx, y + dy, 0.0);
    match i % 8 {
        0 => EntityKind::Line {
            p0: p(0.0, 0.0),
            p1: p(1.25, 0.75),
        },
        1 => EntityKind::Circle {
            center: p(0.5, 0.5),
            radius: 0.3,
            normal: DVec3::Z,
        },
        2 => EntityKind::Arc {
            center: p(0.5, 0.5),
            radius: 0.4,
            start: 0.5,
            end: 2.5,
            normal: DVec3::Z,
        },
        3 => EntityKind::LwPolyline {
            points: vec![
                DVec2::new(x, y),
                DVec2::new(x + 1.0, y),
                DVec2::new(x + 1.0, y + 0.5),
                DVec2::new(x, y + 0.5),
            ],
            bulges: vec![0.0, 0.25, 0.0, -0.25],
            closed: true,
            elevation: 0.0,
            normal: DVec3::Z,
        },
        4 => EntityKind::Point { p: p(0.1, 0.2) },
        5 => EntityKind::Text {
            insert: p(0.0, 0.0),
            height: 0.25,
            value: format!("T{i}"),
            rotation: 0.0,
            style: "Standard".into(),
        },
        6 => EntityKind::Spline {
            curve: BSpline::new(
                3,
                vec![
                    p(0.0, 0.0),
                    p(0.3, 0.6),
                    p(0.6, -0.2),
                    p(0.9, 0.4),
                    p(1.2, 0.0),
                ],
                None,
                None,
            )
            .unwrap(),
            fit_points: vec![],
            closed: false,
        },
        _ => EntityKind::Face3d {
            corners: [p(0.0, 0.0), p(1.0, 0.0), p(1.0, 1.0), p(0.0, 1.0)],
        },
    }
}

fn drawing(n: usize) -> Drawing {
    let mut d = Drawing::new();
    d.use_layer("A", Some(1)).unwrap();
    d.use_layer("B", Some(5)).unwrap();
    for i in 0..n {
        d.use_layer(if i % 2 == 0 { "A" } else { "B" }, None)
            .unwrap();
        d.add_kind(entity(i)).unwrap();
    }
    d
}

fn bench(c: &mut Criterion) {
    let d = drawing(100_000);
    let opts = OutputOptions::default();
    let mut g = c.benchmark_group("output_write_100k");
    g.sample_size(10);
    g.bench_function("dxf_cad", |b| b.iter(|| write_cad(&d).len()));
    g.bench_function("svg", |b| b.iter(|| write_svg(&d, &opts).len()));
    g.finish();
}

criterion_group!(benches, bench);
criterion_main!(benches);
