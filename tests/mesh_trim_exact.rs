//! Trims decided by exact predicates with one symbolic perturbation (issue 13, item 1): cuts
//! through mesh vertices and along mesh edges give the right areas (closed forms), the same
//! answer on every run, no degenerate triangles, and non-manifold joins stay on their side; a
//! cutter coinciding with the surface over a region whose boundary runs on mesh edges cuts
//! there too.

use lispcad::geom::line::Line;
use lispcad::geom::mesh::{trim, Mesh, Trimmed};
use lispcad::geom::surface::{mesh_surface, Surface};
use lispcad::geom::DVec3;
use std::sync::Arc;

mod mesh_support;
use mesh_support::grid;

fn ruled(a: [f64; 3], b: [f64; 3], c: [f64; 3], d: [f64; 3], tol: f64) -> Mesh {
    let v = DVec3::from_array;
    let s = Surface::ruled(
        Arc::new(Line { p0: v(a), p1: v(b) }),
        Arc::new(Line { p0: v(c), p1: v(d) }),
    );
    mesh_surface(&s, tol).unwrap()
}

/// A vertical wall x = c (or through the line (c, 0)–(c + dx, 1) when tilted), covering
/// y, z in [-span, span], meshed coarsely so its own edges cross the other mesh too.
fn wall(c: f64, dx: f64, span: f64) -> Mesh {
    let (s, e) = (-span, span);
    ruled(
        [c + dx * s, s, -1.0],
        [c + dx * e, e, -1.0],
        [c + dx * s, s, 1.0],
        [c + dx * e, e, 1.0],
        0.01,
    )
}

/// Smallest `2·area / longest²` over the triangles: 0 for a degenerate triangle.
fn worst_shape(m: &Mesh) -> f64 {
    (0..m.len())
        .map(|t| {
            let [a, b, c] = m.corners_of(t);
            let l = (b - a)
                .length_squared()
                .max((c - b).length_squared())
                .max((a - c).length_squared());
            (b - a).cross(c - a).length() / l
        })
        .fold(f64::INFINITY, f64::min)
}

fn bits(m: &Mesh) -> (Vec<[u64; 3]>, Vec<[u32; 3]>) {
    (
        m.vertices()
            .iter()
            .map(|p| [p.x.to_bits(), p.y.to_bits(), p.z.to_bits()])
            .collect(),
        m.triangles().to_vec(),
    )
}

fn boundary_points(m: &Mesh) -> Vec<[u64; 3]> {
    let mut v: Vec<[u64; 3]> = m
        .boundary()
        .iter()
        .flat_map(|l| l.points.clone())
        .map(|p| [p.x.to_bits(), p.y.to_bits(), p.z.to_bits()])
        .collect();
    v.sort_unstable();
    v
}

/// Trims several times; every run must give the same bits. Checks area sums and shapes.
fn trim_checked(whole: &Mesh, cutter: &Mesh, keep: DVec3) -> Trimmed {
    let r = trim(whole, cutter, keep).unwrap();
    for _ in 0..4 {
        let again = trim(whole, cutter, keep).unwrap();
        assert_eq!(bits(&again.kept), bits(&r.kept), "run-to-run difference");
        assert_eq!(
            bits(&again.removed),
            bits(&r.removed),
            "run-to-run difference"
        );
    }
    let sum = r.kept.area() + r.removed.area();
    assert!(
        (sum - whole.area()).abs() <= 1e-12 * whole.area(),
        "{sum} vs {}",
        whole.area()
    );
    for part in [&r.kept, &r.removed] {
        if !part.is_empty() {
            assert!(worst_shape(part) > 1e-9, "degenerate triangle");
        }
    }
    r
}

#[test]
fn ruled_square_cut_by_a_wall_at_5_5_gives_55_and_45() {
    let sq = ruled(
        [0.0, 0.0, 0.0],
        [10.0, 0.0, 0.0],
        [0.0, 10.0, 0.0],
        [10.0, 10.0, 0.0],
        0.01,
    );
    let w = ruled(
        [5.5, -1.0, -1.0],
        [5.5, 11.0, -1.0],
        [5.5, -1.0, 1.0],
        [5.5, 11.0, 1.0],
        0.01,
    );
    let left = trim_checked(&sq, &w, DVec3::new(1.0, 5.0, 0.0));
    assert!(
        (left.kept.area() - 55.0).abs() < 1e-12,
        "{}",
        left.kept.area()
    );
    assert!((left.removed.area() - 45.0).abs() < 1e-12);
    let right = trim_checked(&sq, &w, DVec3::new(9.0, 5.0, 0.0));
    assert!((right.kept.area() - 45.0).abs() < 1e-12);
    let on_cut = |m: &Mesh| {
        let mut v = boundary_points(m);
        v.retain(|p| f64::from_bits(p[0]) == 5.5);
        v
    };
    assert_eq!(on_cut(&left.kept), on_cut(&left.removed));
    assert_eq!(on_cut(&left.kept).len(), 3);
}

#[test]
fn cylinder_cut_by_the_plane_y_0_gives_equal_halves_every_run() {
    for tol in [0.1, 0.01, 0.003] {
        let cyl = mesh_surface(
            &Surface::cylinder(DVec3::ZERO, DVec3::Z, 1.0, 2.0).unwrap(),
            tol,
        )
        .unwrap();
        let plane = ruled(
            [-2.0, 0.0, -1.0],
            [2.0, 0.0, -1.0],
            [-2.0, 0.0, 3.0],
            [2.0, 0.0, 3.0],
            tol,
        );
        let r = trim_checked(&cyl, &plane, DVec3::new(0.0, 1.0, 1.0));
        assert!(
            (r.kept.area() - r.removed.area()).abs() <= 1e-9 * cyl.area(),
            "{} vs {} at {tol}",
            r.kept.area(),
            r.removed.area()
        );
        assert!(r.kept.vertices().iter().all(|p| p.y >= -1e-15));
        assert_eq!(r.kept.boundary().len(), 1);
    }
}

#[test]
fn cut_along_grid_lines_through_vertices() {
    // A 4×4 grid over [-1, 1]²; the wall x = 0 runs along grid edges and through vertices,
    // the diagonal wall x = y through vertices and along the cells' diagonals.
    let g = grid(4, 1.0, 0.0);
    let r = trim_checked(&g, &wall(0.0, 0.0, 3.0), DVec3::new(-0.7, 0.1, 0.0));
    assert!((r.kept.area() - 2.0).abs() < 1e-12, "{}", r.kept.area());
    let r = trim_checked(&g, &wall(0.0, 1.0, 3.0), DVec3::new(0.7, -0.5, 0.0));
    assert!((r.kept.area() - 2.0).abs() < 1e-12, "{}", r.kept.area());
    // Along the cells' other diagonal (not mesh edges): through vertices only.
    let r = trim_checked(&g, &wall(0.0, -1.0, 3.0), DVec3::new(0.7, 0.5, 0.0));
    assert!((r.kept.area() - 2.0).abs() < 1e-12, "{}", r.kept.area());
}

#[test]
fn general_position_trims_leave_no_sliver() {
    let s = lispcad::geom::mesh::icosphere(DVec3::new(0.01, 0.02, 0.03), 1.0, 3);
    let m = lispcad::geom::DMat4::from_rotation_x(0.3) * lispcad::geom::DMat4::from_rotation_y(0.2);
    let cutter = grid(5, 3.0, 0.123)
        .map_vertices(|p| m.transform_point3(p))
        .unwrap();
    let r = trim_checked(&s, &cutter, DVec3::new(0.0, 0.0, 3.0));
    assert!(worst_shape(&r.kept) > 1e-6 && worst_shape(&r.removed) > 1e-6);
}

#[test]
fn a_fin_joined_through_a_non_manifold_edge_stays_on_its_side() {
    // Two squares [0,1]×[0,1] and [1,2]×[0,1] in z = 0, and a fin standing on the diagonal
    // edge (0,0)–(1,1): three facets share that edge.
    let v = vec![
        DVec3::new(0.0, 0.0, 0.0),
        DVec3::new(1.0, 0.0, 0.0),
        DVec3::new(1.0, 1.0, 0.0),
        DVec3::new(0.0, 1.0, 0.0),
        DVec3::new(2.0, 0.0, 0.0),
        DVec3::new(2.0, 1.0, 0.0),
        DVec3::new(0.5, 0.5, 1.0),
    ];
    let t = vec![
        [0, 1, 2],
        [0, 2, 3],
        [1, 4, 5],
        [1, 5, 2],
        [0, 2, 6], // the fin on the diagonal edge 0–2
    ];
    let m = Mesh::new(v, t).unwrap();
    // Cut at x = 1.5: the fin belongs to the left part.
    let r = trim_checked(&m, &wall(1.5, 0.0, 3.0), DVec3::new(1.9, 0.5, 0.0));
    assert!((r.kept.area() - 0.5).abs() < 1e-12);
    let fin = 0.5
        * (DVec3::new(1.0, 1.0, 0.0))
            .cross(DVec3::new(0.5, 0.5, 1.0))
            .length();
    assert!(
        (r.removed.area() - (1.5 + fin)).abs() < 1e-12,
        "{}",
        r.removed.area()
    );
    let r = trim_checked(&m, &wall(1.5, 0.0, 3.0), DVec3::new(0.1, 0.5, 0.0));
    assert!((r.kept.area() - (1.5 + fin)).abs() < 1e-12);
}

/// The facets of `m` whose centroid passes `keep`, as a mesh of their own on the same vertices.
fn facets_where(m: &Mesh, keep: impl Fn(DVec3) -> bool) -> Mesh {
    let t: Vec<[u32; 3]> = (0..m.len())
        .filter(|&i| {
            let [a, b, c] = m.corners_of(i);
            keep((a + b + c) / 3.0)
        })
        .map(|i| m.triangles()[i])
        .collect();
    Mesh::new(m.vertices().to_vec(), t).unwrap()
}

/// The rectangle [x0, x1] × [y0, y1] in z = 0, meshed by the surface mesher.
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

/// Trims `whole` by the coincident `cutter` from a keep point outside the region of area
/// `inner`: the region comes off whole, and every point of the cut (its boundary off the
/// surface's own) is a boundary point of the rest, bit for bit.
fn region_comes_off(name: &str, whole: &Mesh, cutter: &Mesh, outside: DVec3, inner: f64) {
    let r = trim_checked(whole, cutter, outside);
    let a = whole.area();
    assert!(
        (r.removed.area() - inner).abs() <= 1e-12 * a,
        "{name}: removed {} want {inner}",
        r.removed.area()
    );
    assert!((r.kept.area() - (a - inner)).abs() <= 1e-12 * a, "{name}");
    let kept_bd = boundary_points(&r.kept);
    // The removed part's boundary less the surface's own: the cut.
    let outer = boundary_points(whole);
    let mut cut = boundary_points(&r.removed);
    cut.retain(|p| outer.binary_search(p).is_err());
    assert!(
        cut.iter().all(|p| kept_bd.binary_search(p).is_ok()),
        "{name}: the parts do not share the cut"
    );
}

#[test]
fn a_coincident_region_bounded_by_mesh_edges_comes_off_whole() {
    // The 4×4 grid over [-2, 2]²; the region [-1, 1]² has its whole boundary on grid lines.
    let g = grid(4, 2.0, 0.0);
    let out = DVec3::new(-1.9, -1.9, 0.0);
    region_comes_off("sub-grid", &g, &grid(2, 1.0, 0.0), out, 4.0);
    let r = trim_checked(&g, &grid(2, 1.0, 0.0), out);
    assert_eq!(
        boundary_points(&r.removed).len(),
        8,
        "the region's 8 grid vertices"
    );
    let own = facets_where(&g, |c| c.x.abs() < 1.0 && c.y.abs() < 1.0);
    region_comes_off("own facets", &g, &own, out, 4.0);
    // Boundary on grid lines at x = -1 and y = ±1, across cells at x = 0.5.
    region_comes_off("partly on edges", &g, &rect(-1.0, 0.5, -1.0, 1.0), out, 3.0);
    // Kept from inside, the region is what is kept.
    let r = trim_checked(&g, &own, DVec3::new(0.2, 0.3, 0.0));
    assert!((r.kept.area() - 4.0).abs() <= 1e-12, "{}", r.kept.area());
    // A band across the whole grid, its ends on the grid's own boundary: three parts, the
    // one below kept (area 4), the band and the part above it removed.
    let r = trim_checked(&g, &rect(-2.0, 2.0, -1.0, 1.0), out);
    assert!((r.kept.area() - 4.0).abs() <= 1e-12, "{}", r.kept.area());
    // A cylinder cut by the half of its own facets with y > 0: along two rulings.
    let c = mesh_surface(
        &Surface::cylinder(DVec3::ZERO, DVec3::Z, 1.0, 2.0).unwrap(),
        0.01,
    )
    .unwrap();
    let half = facets_where(&c, |p| p.y > 0.0);
    region_comes_off(
        "cylinder",
        &c,
        &half,
        DVec3::new(0.0, -1.0, 1.0),
        half.area(),
    );
}

use proptest::prelude::*;

proptest! {
    #![proptest_config(ProptestConfig::with_cases(64))]
    /// A grid cut by a wall x = c + dx·y; half the cases snap c and dx to grid values, so the
    /// cut runs through vertices and along edges. The kept area is the exact polygon area.
    #[test]
    fn grid_cut_by_a_wall_random_and_snapped(
        n in 2usize..7,
        ci in -8i32..8, cf in -0.9f64..0.9, snap in any::<bool>(),
        di in -2i32..=2, df in -0.6f64..0.6,
    ) {
        let g = grid(n, 1.0, 0.0);
        let (c, dx) = if snap {
            (ci as f64 / 8.0, di as f64 / 2.0)
        } else {
            (cf, df)
        };
        let r = trim_checked(&g, &wall(c, dx, 4.0), DVec3::new(-1.0, -1.0, 0.0));
        // Left of x = c + dx·y within [-1, 1]²: ∫ (clamp(c + dx·y, −1, 1) + 1) dy.
        let k = 20000;
        let exact: f64 = (0..k).map(|i| {
            let y = -1.0 + (i as f64 + 0.5) * 2.0 / k as f64;
            ((c + dx * y).clamp(-1.0, 1.0) + 1.0) * 2.0 / k as f64
        }).sum();
        let (lo, hi) = (r.kept.area().min(r.removed.area()), r.kept.area().max(r.removed.area()));
        prop_assert!((lo - exact.min(4.0 - exact)).abs() < 1e-6, "{} vs {}", lo, exact);
        prop_assert!((hi - exact.max(4.0 - exact)).abs() < 1e-6);
    }

    /// A coincident rectangle inside the grid, each side either on a grid line (snapped) or
    /// anywhere: it comes off whole (its area exactly), sharing its boundary with the rest.
    #[test]
    fn grid_trimmed_by_a_coincident_rectangle_random_and_snapped(
        n in 2usize..7,
        i in [1usize..6, 1usize..6, 1usize..6, 1usize..6],
        f in [-0.9f64..0.9, -0.9f64..0.9, -0.9f64..0.9, -0.9f64..0.9],
        snap in [any::<bool>(), any::<bool>(), any::<bool>(), any::<bool>()],
    ) {
        let g = grid(n, 1.0, 0.0);
        // The grid's own coordinates for a snapped side (same expression, same bits).
        let side = |k: usize| if snap[k] {
            -1.0 + 2.0 * (i[k] % n).max(1) as f64 / n as f64
        } else {
            f[k]
        };
        let (mut x0, mut x1, mut y0, mut y1) = (side(0), side(1), side(2), side(3));
        if x0 > x1 { std::mem::swap(&mut x0, &mut x1); }
        if y0 > y1 { std::mem::swap(&mut y0, &mut y1); }
        prop_assume!(x1 - x0 >= 0.05 && y1 - y0 >= 0.05);
        let inner = (x1 - x0) * (y1 - y0);
        region_comes_off("random", &g, &rect(x0, x1, y0, y1), DVec3::new(-1.0, -1.0, 0.0), inner);
    }
}
