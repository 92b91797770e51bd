//! Temple bend throughput: interpolate an 11-point closed outline, bend its points, and bend +
//! regenerate the outline within 1e-6 (GEOMTOL×1000) of the exact bend.

use criterion::{criterion_group, criterion_main, Criterion};
use glam::DVec2;
use lispcad::geom::quadspline::QuadSpline;
use lispcad::geom::temple::{bend_points, bend_spline, bend_spline_interpolated, TempleParams};
use std::hint::black_box;

#[path = "../tests/temple_support/mod.rs"]
mod temple_support;
use temple_support::default_outline;

fn bench(c: &mut Criterion) {
    let pts = default_outline(140.0);
    let params = TempleParams {
        l1: 140.0,
        l2: 35.0,
        r: 15.0,
        theta: 40f64.to_radians(),
        base: DVec2::ZERO,
    };
    let spline = QuadSpline::interpolate(&pts, true).unwrap();
    c.bench_function("interpolate closed 11 points", |b| {
        b.iter(|| QuadSpline::interpolate(black_box(&pts), true).unwrap())
    });
    c.bench_function("bend_points 11", |b| {
        b.iter(|| bend_points(black_box(&pts), &params).unwrap())
    });
    c.bench_function("bend_spline 11-point outline tol 1e-6", |b| {
        b.iter(|| bend_spline(black_box(&spline), &params, 1e-6).unwrap())
    });
    c.bench_function("bend_spline 11-point outline tol 1e-3", |b| {
        b.iter(|| bend_spline(black_box(&spline), &params, 1e-3).unwrap())
    });
    let mut slow = c.benchmark_group("interpolated refit");
    slow.sample_size(10);
    slow.bench_function("bend_spline_interpolated 11-point outline tol 1e-6", |b| {
        b.iter(|| bend_spline_interpolated(black_box(&spline), &params, 1e-6).unwrap())
    });
    slow.finish();
}

criterion_group!(benches, bench);
criterion_main!(benches);
