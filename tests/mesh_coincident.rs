//! Meshes that coincide over a region (issue 13, item 1): `intersect_meshes` returns the
//! region's boundary loops, closed, instead of nothing or fragments. Two overlapping planar
//! meshes, a mesh against its own copy, two meshes of one cylinder sharing their facet strips.
//! References: the overlap rectangle written out, and the meshes' own boundaries.

use lispcad::geom::mesh::{intersect_meshes, Mesh, Polyline3};
use lispcad::geom::surface::{mesh_surface, Surface};
use lispcad::geom::DVec3;

fn rect(x0: f64, x1: f64, y0: f64, y1: f64) -> Mesh {
    let s = Surface::plane(vec![
        DVec3::new(x0, y0, 0.0),
        DVec3::new(x1, y0, 0.0),
        DVec3::new(x1, y1, 0.0),
        DVec3::new(x0, y1, 0.0),
    ])
    .unwrap();
    mesh_surface(&s, 0.01).unwrap()
}

/// The area enclosed by a closed loop in z = const (shoelace).
fn area_xy(c: &Polyline3) -> f64 {
    let p = &c.points;
    0.5 * (0..p.len())
        .map(|i| {
            let (a, b) = (p[i], p[(i + 1) % p.len()]);
            a.x * b.y - b.x * a.y
        })
        .sum::<f64>()
        .abs()
}

#[test]
fn overlapping_planar_meshes_give_the_overlap_boundary() {
    let (a, b) = (rect(0.0, 2.0, 0.0, 2.0), rect(1.0, 3.0, 0.5, 1.5));
    for r in [intersect_meshes(&a, &b), intersect_meshes(&b, &a)] {
        assert_eq!(r.len(), 1, "{r:?}");
        assert!(r[0].closed);
        assert!((r[0].length() - 4.0).abs() <= 1e-12, "{}", r[0].length());
        assert!((area_xy(&r[0]) - 1.0).abs() <= 1e-12);
        for p in &r[0].points {
            let on_x = (p.x - 1.0).abs() <= 1e-12 || (p.x - 2.0).abs() <= 1e-12;
            let on_y = (p.y - 0.5).abs() <= 1e-12 || (p.y - 1.5).abs() <= 1e-12;
            assert!(on_x || on_y, "{p}");
            assert!(p.z == 0.0);
        }
    }
    // Side by side (touching along x = 2 only) they share no region.
    let c = rect(2.0, 3.0, 0.0, 2.0);
    assert!(intersect_meshes(&a, &c).iter().all(|l| !l.closed));
}

#[test]
fn a_mesh_against_its_copy_gives_its_boundary() {
    let s = Surface::cylinder(DVec3::ZERO, DVec3::Z, 1.0, 2.0).unwrap();
    let m = mesh_surface(&s, 0.01).unwrap();
    let r = intersect_meshes(&m, &m.clone());
    let bd = m.boundary();
    assert_eq!(r.len(), bd.len());
    let mut got: Vec<f64> = r.iter().map(Polyline3::length).collect();
    let mut want: Vec<f64> = bd.iter().map(Polyline3::length).collect();
    got.sort_by(f64::total_cmp);
    want.sort_by(f64::total_cmp);
    assert!(r.iter().all(|c| c.closed));
    for (g, w) in got.iter().zip(&want) {
        assert!((g - w).abs() <= 1e-12, "{g} vs {w}");
    }
}

#[test]
fn two_meshes_of_one_cylinder_give_the_band_boundary() {
    let a = Surface::cylinder(DVec3::ZERO, DVec3::Z, 1.0, 5.0).unwrap();
    let b = Surface::cylinder(DVec3::new(0.0, 0.0, 3.0), DVec3::Z, 1.0, 5.0).unwrap();
    let (ma, mb) = (
        mesh_surface(&a, 0.01).unwrap(),
        mesh_surface(&b, 0.01).unwrap(),
    );
    // The polygon at the foot of a: the band's loops are the same polygon at z = 3 and 5.
    let foot = ma
        .boundary()
        .into_iter()
        .find(|c| c.points.iter().all(|p| p.z == 0.0))
        .unwrap();
    let r = intersect_meshes(&ma, &mb);
    let loops: Vec<&Polyline3> = r.iter().filter(|c| c.closed).collect();
    assert_eq!(loops.len(), 2, "{r:?}");
    for z in [3.0, 5.0] {
        let l = loops
            .iter()
            .find(|c| c.points.iter().all(|p| p.z == z))
            .unwrap_or_else(|| panic!("no loop at z = {z}: {loops:?}"));
        // The same polygon, its sides split where the facets of a cross them.
        assert!(l.points.len() >= foot.points.len());
        assert!((l.length() - foot.length()).abs() <= 1e-12);
    }
}

#[test]
fn a_trim_by_a_coincident_cutter_cuts_along_the_region_boundary() {
    use lispcad::geom::mesh::trim;
    // The square [0, 2]² cut by the coincident rectangle [1, 3] × [0.5, 1.5]: the overlap
    // (area 1) on one side, the rest (area 3) on the other, sharing the cut exactly.
    let (a, b) = (rect(0.0, 2.0, 0.0, 2.0), rect(1.0, 3.0, 0.5, 1.5));
    let t = trim(&a, &b, DVec3::new(0.1, 0.1, 0.0)).unwrap();
    assert!((t.kept.area() - 3.0).abs() <= 1e-12, "{}", t.kept.area());
    assert!(
        (t.removed.area() - 1.0).abs() <= 1e-12,
        "{}",
        t.removed.area()
    );
    let t = trim(&a, &b, DVec3::new(1.5, 1.0, 0.0)).unwrap();
    assert!((t.kept.area() - 1.0).abs() <= 1e-12, "{}", t.kept.area());
    // A cylinder mesh cut by a coincident piece of itself at z = 3: its strips are planar
    // rectangles, so the parts hold 3/5 and 2/5 of its area.
    let c = Surface::cylinder(DVec3::ZERO, DVec3::Z, 1.0, 5.0).unwrap();
    let d = Surface::cylinder(DVec3::new(0.0, 0.0, 3.0), DVec3::Z, 1.0, 5.0).unwrap();
    let (mc, md) = (
        mesh_surface(&c, 0.01).unwrap(),
        mesh_surface(&d, 0.01).unwrap(),
    );
    let whole = mc.area();
    let t = trim(&mc, &md, DVec3::new(1.0, 0.0, 1.0)).unwrap();
    assert!(
        (t.kept.area() - 0.6 * whole).abs() <= 1e-12 * whole,
        "{}",
        t.kept.area()
    );
    assert!((t.removed.area() - 0.4 * whole).abs() <= 1e-12 * whole);
    assert!(t.kept.vertices().iter().all(|p| p.z <= 3.0));
}
