//! Mesh operations on the benchmark pair of bench/surface: icospheres of 1,310,720 triangles,
//! B = A rotated 0.3 rad about (1, 2, 3) and moved by (0.5, 0.3, 0.2).

use criterion::{criterion_group, criterion_main, Criterion};
use lispcad::geom::mesh::{icosphere, intersect_meshes, section, Bvh, Mesh};
use lispcad::geom::{DMat4, DVec3};
use std::hint::black_box;

fn pair(level: u32) -> (Mesh, Mesh) {
    let a = icosphere(DVec3::ZERO, 1.0, level);
    let m = DMat4::from_translation(DVec3::new(0.5, 0.3, 0.2))
        * DMat4::from_axis_angle(DVec3::new(1.0, 2.0, 3.0).normalize(), 0.3);
    let b = a.map_vertices(|p| m.transform_point3(p)).unwrap();
    (a, b)
}

fn bench(c: &mut Criterion) {
    let (a, b) = pair(8);
    // The same plane with and without the cached hierarchy, so the two timings compare.
    let cut = |m: &Mesh| section(m, DVec3::new(0.0, 0.0, 0.1), DVec3::new(0.1, 0.2, 1.0)).unwrap();
    let mut g = c.benchmark_group("icosphere8");
    g.sample_size(10);
    g.bench_function("section_scan", |bch| bch.iter(|| cut(black_box(&a))));
    g.bench_function("bvh_build", |bch| bch.iter(|| Bvh::build(black_box(&a))));
    g.bench_function("intersect_with_bvh_build", |bch| {
        bch.iter(|| {
            // Fresh copies so the cached hierarchies are rebuilt every time.
            let (a2, b2) = (
                a.map_vertices(|p| p).unwrap(),
                b.map_vertices(|p| p).unwrap(),
            );
            intersect_meshes(&a2, &b2)
        })
    });
    a.bvh();
    b.bvh();
    g.bench_function("section_bvh", |bch| bch.iter(|| cut(black_box(&a))));
    g.bench_function("intersect_cached_bvh", |bch| {
        bch.iter(|| intersect_meshes(black_box(&a), black_box(&b)))
    });
    g.finish();
}

/// The refinement of surface/surface curves on the true surfaces: cone ∩ off-axis cylinder with
/// and without it (the mesh seeds alone), so the difference over the curve's point count is the
/// cost per refined point.
fn refine(c: &mut Criterion) {
    use lispcad::geom::curve::Curve;
    use lispcad::geom::surface::{mesh_surface, surface_intersect, Surface};
    let cone = Surface::revolve(
        std::sync::Arc::new(Curve::line(DVec3::ZERO, DVec3::new(2.0, 0.0, 4.0)).unwrap()),
        DVec3::ZERO,
        DVec3::Z,
        std::f64::consts::TAU,
    )
    .unwrap();
    let cyl = Surface::cylinder(DVec3::new(0.5, 0.0, -1.0), DVec3::Z, 1.0, 6.0).unwrap();
    let tol = 1e-3;
    let points: usize = surface_intersect(&cone, &cyl, tol)
        .unwrap()
        .iter()
        .map(|p| p.points.len())
        .sum();
    eprintln!("refine: cone/cylinder curve of {points} points at CHORDTOL {tol}");
    let mut g = c.benchmark_group("refine");
    g.sample_size(10);
    g.bench_function("cone_cylinder_seeds_only", |bch| {
        bch.iter(|| {
            let (ma, mb) = (
                mesh_surface(&cone, tol).unwrap(),
                mesh_surface(&cyl, tol).unwrap(),
            );
            intersect_meshes(&ma, &mb)
        })
    });
    g.bench_function("cone_cylinder_refined", |bch| {
        bch.iter(|| surface_intersect(black_box(&cone), black_box(&cyl), tol).unwrap())
    });
    // The same without the tangent-contact search: the difference is what the search adds.
    g.bench_function("cone_cylinder_refined_no_contacts", |bch| {
        bch.iter(|| {
            lispcad::geom::surface::surface_intersect_without_contacts(
                black_box(&cone),
                black_box(&cyl),
                tol,
                tol,
                lispcad::geom::GEOMTOL,
            )
            .unwrap()
        })
    });
    g.finish();
}

/// A section through the mesh (a torus cut by a plane beside its axis, which no closed form
/// covers): with and without the search for the points where the plane touches.
fn section_contacts(c: &mut Criterion) {
    use lispcad::geom::curve::Curve;
    use lispcad::geom::surface::{
        surface_section_seeded, surface_section_without_contacts, Surface,
    };
    let tube = Curve::circle(DVec3::new(3.0, 0.0, 0.0), 1.0, Some(DVec3::Y)).unwrap();
    let torus = Surface::revolve(
        std::sync::Arc::new(tube),
        DVec3::ZERO,
        DVec3::Z,
        std::f64::consts::TAU,
    )
    .unwrap();
    let (p, n) = (DVec3::new(3.5, 0.0, 0.0), DVec3::X);
    let (seed, tol, gtol) = (1e-3, 1e-3, lispcad::geom::GEOMTOL);
    let points: usize = surface_section_seeded(&torus, p, n, seed, tol, gtol)
        .unwrap()
        .iter()
        .map(|c| c.points.len())
        .sum();
    eprintln!("section: torus at x = 3.5, {points} points at CHORDTOL {tol}");
    let mut g = c.benchmark_group("torus_section");
    g.sample_size(10);
    g.bench_function("with_contacts", |bch| {
        bch.iter(|| surface_section_seeded(black_box(&torus), p, n, seed, tol, gtol).unwrap())
    });
    g.bench_function("without_contacts", |bch| {
        bch.iter(|| {
            surface_section_without_contacts(black_box(&torus), p, n, seed, tol, gtol).unwrap()
        })
    });
    g.finish();
}

/// A contact along a curve reached through the mesh path: a torus under a plane region touching
/// its top circle. The meshes' exact touch seeds fragments; the traced contact replaces them.
fn contact_line(c: &mut Criterion) {
    use lispcad::geom::curve::Curve;
    use lispcad::geom::surface::{surface_intersect_seeded, Surface};
    let tube = Curve::circle(DVec3::new(3.0, 0.0, 0.0), 1.0, Some(DVec3::Y)).unwrap();
    let torus = Surface::revolve(
        std::sync::Arc::new(tube),
        DVec3::ZERO,
        DVec3::Z,
        std::f64::consts::TAU,
    )
    .unwrap();
    let top = Surface::plane(vec![
        DVec3::new(-5.0, -5.0, 1.0),
        DVec3::new(5.0, -5.0, 1.0),
        DVec3::new(5.0, 5.0, 1.0),
        DVec3::new(-5.0, 5.0, 1.0),
    ])
    .unwrap();
    let (seed, tol, gtol) = (1e-2, 1e-3, lispcad::geom::GEOMTOL);
    let r = surface_intersect_seeded(&torus, &top, seed, tol, gtol).unwrap();
    let points: usize = r.iter().map(|c| c.points.len()).sum();
    eprintln!(
        "contact_line: torus top circle, {} curve(s), {points} points at CHORDTOL {tol}",
        r.len()
    );
    let mut g = c.benchmark_group("contact_line");
    g.sample_size(10);
    g.bench_function("torus_top_circle", |bch| {
        bch.iter(|| surface_intersect_seeded(black_box(&torus), &top, seed, tol, gtol).unwrap())
    });
    g.finish();
}

criterion_group!(benches, bench, refine, section_contacts, contact_line);
criterion_main!(benches);
