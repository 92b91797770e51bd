//! Paper 003: boundary corners and extension strips without cracks.

use lispcad::geom::mesh::{corners, extend, Mesh};
use lispcad::geom::surface::{mesh_surface, Surface};
use lispcad::geom::DVec3;
use std::f64::consts::{FRAC_PI_6, PI};

mod mesh_support;
use mesh_support::l_outline;

fn square() -> Mesh {
    Mesh::new(
        vec![DVec3::ZERO, DVec3::X, DVec3::new(1.0, 1.0, 0.0), DVec3::Y],
        vec![[0, 1, 2], [0, 2, 3]],
    )
    .unwrap()
}

fn l_shape() -> Mesh {
    let s = Surface::plane(l_outline()).unwrap();
    mesh_surface(&s, 1e-3).unwrap()
}

#[test]
fn square_has_four_corners() {
    let c = corners(&square(), FRAC_PI_6).unwrap();
    assert_eq!(c.len(), 4);
    for p in [DVec3::ZERO, DVec3::X, DVec3::new(1.0, 1.0, 0.0), DVec3::Y] {
        assert!(c.contains(&p));
    }
    // Above 90° nothing is a corner.
    assert!(corners(&square(), 1.6).unwrap().is_empty());
    assert!(corners(&square(), -1.0).is_err());
}

#[test]
fn cylinder_rims_have_no_corners() {
    let s = Surface::cylinder(DVec3::ZERO, DVec3::Z, 1.0, 2.0).unwrap();
    let m = mesh_surface(&s, 1e-3).unwrap();
    assert!(corners(&m, FRAC_PI_6).unwrap().is_empty());
}

#[test]
fn extended_square_is_crack_free_with_rounded_corners() {
    let d = 0.5;
    let e = extend(&square(), d, FRAC_PI_6).unwrap();
    // One boundary loop: the strips and corner fans close up with the original boundary.
    let b = e.boundary();
    assert_eq!(b.len(), 1);
    // Sides 1 + 4·d, rounded corners: four fans of six 15° triangles.
    let fans = 4.0 * 6.0 * 0.5 * d * d * (15f64).to_radians().sin();
    assert!(
        (e.area() - (1.0 + 4.0 * d + fans)).abs() < 1e-12,
        "{}",
        e.area()
    );
    assert!(e.vertices().iter().all(|p| p.z == 0.0));
    // Every outer boundary point is exactly d from the square.
    for p in &b[0].points {
        let dx = (p.x - p.x.clamp(0.0, 1.0)).abs();
        let dy = (p.y - p.y.clamp(0.0, 1.0)).abs();
        assert!(((dx * dx + dy * dy).sqrt() - d).abs() < 1e-12);
    }
    // Consistent orientation: every triangle faces +z like the original.
    for t in 0..e.len() {
        let [a, b, c] = e.corners_of(t);
        assert!((b - a).cross(c - a).z > 0.0);
    }
}

#[test]
fn reflex_corner_is_mitred() {
    let e = extend(&l_shape(), 0.25, FRAC_PI_6).unwrap();
    assert_eq!(e.boundary().len(), 1);
    // The inner corner (1,1) moves diagonally to (1.25, 1.25).
    assert!(e
        .vertices()
        .iter()
        .any(|p| (*p - DVec3::new(1.25, 1.25, 0.0)).length() < 1e-12));
    for t in 0..e.len() {
        let [a, b, c] = e.corners_of(t);
        assert!((b - a).cross(c - a).z > 0.0);
    }
}

#[test]
fn cylinder_extends_along_its_axis() {
    let s = Surface::cylinder(DVec3::ZERO, DVec3::Z, 1.0, 2.0).unwrap();
    let m = mesh_surface(&s, 1e-3).unwrap();
    let e = extend(&m, 0.5, FRAC_PI_6).unwrap();
    let (lo, hi) = e
        .vertices()
        .iter()
        .fold((f64::MAX, f64::MIN), |(l, h), p| (l.min(p.z), h.max(p.z)));
    assert!(
        (lo + 0.5).abs() < 1e-9 && (hi - 2.5).abs() < 1e-9,
        "{lo} {hi}"
    );
    assert_eq!(e.boundary().len(), 2);
    let exact = 2.0 * PI * 3.0;
    assert!((e.area() - exact).abs() < 0.01 * exact);
    assert!(extend(&m, 0.0, FRAC_PI_6).is_err());
}

/// Area covered twice or more, by rasterising the triangles (projected on z = 0) on a fine
/// grid offset by an irrational fraction so no sample falls on an edge.
fn overlap_area(m: &Mesh, cells: usize) -> f64 {
    let b = m.bounds().unwrap();
    let (x0, y0) = (b.min.x - 0.01, b.min.y - 0.01);
    let h = ((b.max.x - x0).max(b.max.y - y0) + 0.01) / cells as f64;
    let mut count = vec![0u8; cells * cells];
    for t in 0..m.len() {
        let [p, q, r] = m.corners_of(t);
        let area2 = (q - p).cross(r - p).z;
        if area2 == 0.0 {
            continue;
        }
        let lo = p.min(q).min(r);
        let hi = p.max(q).max(r);
        let i0 = (((lo.x - x0) / h).floor().max(0.0) as usize).min(cells - 1);
        let i1 = (((hi.x - x0) / h).ceil().max(0.0) as usize).min(cells - 1);
        let j0 = (((lo.y - y0) / h).floor().max(0.0) as usize).min(cells - 1);
        let j1 = (((hi.y - y0) / h).ceil().max(0.0) as usize).min(cells - 1);
        for j in j0..=j1 {
            for i in i0..=i1 {
                let s = DVec3::new(
                    x0 + (i as f64 + 0.5 + 0.0123) * h,
                    y0 + (j as f64 + 0.5 + 0.0371) * h,
                    0.0,
                );
                let w = |a: DVec3, b: DVec3| (b - a).cross(s - a).z / area2;
                if w(p, q) > 0.0 && w(q, r) > 0.0 && w(r, p) > 0.0 {
                    count[j * cells + i] = count[j * cells + i].saturating_add(1);
                }
            }
        }
    }
    count.iter().filter(|&&c| c >= 2).count() as f64 * h * h
}

fn ring() -> Mesh {
    use lispcad::geom::curve::Curve;
    let profile = Curve::line(DVec3::new(2.0, 0.0, 0.0), DVec3::new(5.0, 0.0, 0.0)).unwrap();
    let s = Surface::revolve(
        std::sync::Arc::new(profile),
        DVec3::ZERO,
        DVec3::Z,
        2.0 * PI,
    )
    .unwrap();
    mesh_surface(&s, 0.01).unwrap()
}

#[test]
fn a_ring_extended_by_3_never_overlaps_itself() {
    use lispcad::geom::mesh::extend_with;
    let r = ring();
    assert_eq!(overlap_area(&r, 400), 0.0);
    // Inward by 3 through a hole of radius 2: no clean extension, a clear error.
    let e = extend_with(&r, 3.0, FRAC_PI_6, true)
        .unwrap_err()
        .to_string();
    assert!(e.contains("extend-surface") && e.contains("hole"), "{e}");
    // Holes left alone: the outer rim grows to radius 8, nothing overlaps.
    let m = extend_with(&r, 3.0, FRAC_PI_6, false).unwrap();
    assert_eq!(overlap_area(&m, 400), 0.0);
    let exact = PI * (64.0 - 4.0);
    assert!((m.area() - exact).abs() < 0.01 * exact, "{}", m.area());
    assert!(m
        .vertices()
        .iter()
        .all(|p| p.truncate().length() >= 2.0 - 1e-9));
    // Inward by 1 fits the hole: extended consistently to radius 1.
    let m = extend_with(&r, 1.0, FRAC_PI_6, true).unwrap();
    assert_eq!(overlap_area(&m, 400), 0.0);
    let inner = m
        .vertices()
        .iter()
        .map(|p| p.truncate().length())
        .fold(f64::MAX, f64::min);
    assert!((inner - 1.0).abs() < 0.01, "{inner}");
}

fn shoelace(p: &[(f64, f64)]) -> f64 {
    let n = p.len();
    (0..n)
        .map(|i| p[i].0 * p[(i + 1) % n].1 - p[(i + 1) % n].0 * p[i].1)
        .sum::<f64>()
        / 2.0
}

/// The outline the L's extension by `d` should have, built here from first principles: the
/// convex corners rounded by chords every 15° (6 per right angle), the notch corner (1, 1)
/// mitred at (1 + d, 1 + d) when that lies within the notch edges (d ≤ 1), else the two corner
/// arcs of (2, 1) and (1, 2) cut where they cross the bisector y = x.
fn l_extension_outline(d: f64) -> Vec<(f64, f64)> {
    let fan = |c: (f64, f64), start_deg: f64| -> Vec<(f64, f64)> {
        (0..=6)
            .map(|k| {
                let a = (start_deg + 15.0 * k as f64).to_radians();
                (c.0 + d * a.cos(), c.1 + d * a.sin())
            })
            .collect()
    };
    let mut out = Vec::new();
    out.extend(fan((0.0, 0.0), 180.0));
    out.extend(fan((2.0, 0.0), 270.0));
    let a = fan((2.0, 1.0), 0.0);
    let b = fan((1.0, 2.0), 0.0);
    if d <= 1.0 {
        out.extend(a);
        out.push((1.0 + d, 1.0 + d));
        out.extend(b);
    } else {
        let k = a.iter().position(|p| p.1 > p.0).unwrap();
        let (p, q) = (a[k - 1], a[k]);
        let f = (p.1 - p.0) / ((p.1 - p.0) - (q.1 - q.0));
        let x = (p.0 + (q.0 - p.0) * f, p.1 + (q.1 - p.1) * f);
        out.extend(&a[..k]);
        out.push(x);
        // By symmetry the arc of (1, 2) crosses y = x at the mirror image of the same point.
        out.extend(b.iter().filter(|p| p.1 > p.0 + 1e-12));
    }
    out.extend(fan((0.0, 2.0), 90.0));
    out
}

#[test]
fn concave_corners_are_mitred_or_trimmed_without_overlap() {
    let l = l_shape();
    for d in [0.25, 0.5, 0.9, 1.5, 2.5] {
        let e = extend(&l, d, FRAC_PI_6).unwrap();
        assert_eq!(overlap_area(&e, 300), 0.0, "distance {d}");
        // The triangles' areas sum to the area of the expected outline, so they cover it
        // exactly once; and the two sides of the cut meet vertex to vertex (one boundary).
        let exact = shoelace(&l_extension_outline(d));
        assert!(
            (e.area() - exact).abs() < 1e-9,
            "{d}: {} vs {exact}",
            e.area()
        );
        assert_eq!(e.boundary().len(), 1, "distance {d}");
        for t in 0..e.len() {
            let [a, b, c] = e.corners_of(t);
            assert!((b - a).cross(c - a).z > 0.0, "distance {d}");
        }
    }
    // Past the notch the arcs meet on the bisector: no point beyond it on either side.
    let e = extend(&l, 1.5, FRAC_PI_6).unwrap();
    assert!(e
        .vertices()
        .iter()
        .any(|p| (p.x - p.y).abs() < 1e-12 && p.x > 2.4));
}

type P2 = (f64, f64);

/// The outline of a rectilinear polygon (counter-clockwise, unit edges next to each notch)
/// extended by `d`: 15° chords at convex corners; at a notch corner the mitre when d ≤ 1, else
/// the neighbouring corners' chord polylines cut where they cross the notch's bisector.
fn rectilinear_extension_outline(poly: &[(f64, f64)], d: f64) -> Vec<(f64, f64)> {
    let n = poly.len();
    let sub = |a: (f64, f64), b: (f64, f64)| (a.0 - b.0, a.1 - b.1);
    let out_dir = |e: (f64, f64)| (e.1, -e.0);
    // Per vertex: its chord points, or for a notch the corner and its bisector's normal.
    let mut parts: Vec<Result<Vec<P2>, (P2, P2)>> = Vec::new();
    for i in 0..n {
        let (p, c, q) = (poly[(i + n - 1) % n], poly[i], poly[(i + 1) % n]);
        let (a, b) = (sub(c, p), sub(q, c));
        let (oi, oo) = (out_dir(a), out_dir(b));
        if a.0 * b.1 - a.1 * b.0 > 0.0 {
            let start = oi.1.atan2(oi.0).to_degrees();
            parts.push(Ok((0..=6)
                .map(|k| {
                    let t = (start + 15.0 * k as f64).to_radians();
                    (c.0 + d * t.cos(), c.1 + d * t.sin())
                })
                .collect()));
        } else if d <= 1.0 {
            parts.push(Ok(vec![(c.0 + d * (oi.0 + oo.0), c.1 + d * (oi.1 + oo.1))]));
        } else {
            parts.push(Err((c, (oo.0 - oi.0, oo.1 - oi.1))));
        }
    }
    let side = |p: (f64, f64), c: (f64, f64), k: (f64, f64)| (p.0 - c.0) * k.0 + (p.1 - c.1) * k.1;
    let cross = |p: (f64, f64), q: (f64, f64), c, k| {
        let (sp, sq) = (side(p, c, k), side(q, c, k));
        let f = sp / (sp - sq);
        (p.0 + (q.0 - p.0) * f, p.1 + (q.1 - p.1) * f)
    };
    let mut pts: Vec<Vec<(f64, f64)>> = parts
        .iter()
        .map(|p| p.clone().unwrap_or_default())
        .collect();
    for i in 0..n {
        if let Err((c, k)) = parts[i] {
            let (ia, ib) = ((i + n - 1) % n, (i + 1) % n);
            let a = &pts[ia];
            let j = a.iter().position(|&p| side(p, c, k) < 0.0).unwrap();
            let x = cross(a[j - 1], a[j], c, k);
            pts[ia].truncate(j);
            pts[i] = vec![x];
            let b = &pts[ib];
            let j = b.iter().position(|&p| side(p, c, k) < 0.0).unwrap();
            let y = cross(b[j - 1], b[j], c, k);
            assert!((x.0 - y.0).hypot(x.1 - y.1) < 1e-12, "symmetric notch");
            pts[ib].drain(..j);
        }
    }
    pts.concat()
}

#[test]
fn a_cross_trims_all_four_notches() {
    // Five unit squares in a plus sign: four notch corners, each between two unit edges.
    let poly = [
        (1.0, 0.0),
        (2.0, 0.0),
        (2.0, 1.0),
        (3.0, 1.0),
        (3.0, 2.0),
        (2.0, 2.0),
        (2.0, 3.0),
        (1.0, 3.0),
        (1.0, 2.0),
        (0.0, 2.0),
        (0.0, 1.0),
        (1.0, 1.0),
    ];
    let outline = poly.map(|(x, y)| DVec3::new(x, y, 0.0));
    let m = mesh_surface(&Surface::plane(outline.to_vec()).unwrap(), 1e-3).unwrap();
    for d in [0.5, 1.5] {
        let e = extend(&m, d, FRAC_PI_6).unwrap();
        assert_eq!(overlap_area(&e, 300), 0.0, "distance {d}");
        let exact = shoelace(&rectilinear_extension_outline(&poly, d));
        assert!(
            (e.area() - exact).abs() < 1e-9,
            "{d}: {} vs {exact}",
            e.area()
        );
        assert_eq!(e.boundary().len(), 1, "distance {d}");
    }
    // The generic outline agrees with the L's own.
    let l = [
        (0.0, 0.0),
        (2.0, 0.0),
        (2.0, 1.0),
        (1.0, 1.0),
        (1.0, 2.0),
        (0.0, 2.0),
    ];
    for d in [0.5, 1.5] {
        let (a, b) = (
            shoelace(&rectilinear_extension_outline(&l, d)),
            shoelace(&l_extension_outline(d)),
        );
        assert!((a - b).abs() < 1e-12, "{a} {b}");
    }
}

#[test]
fn a_slot_too_narrow_for_the_distance_is_an_error() {
    // [0, 3]² with the slot [1, 2] × [1, 3] cut out: the slot's walls are not adjacent, and
    // extended by more than half the slot's width their strips collide.
    let outline = [
        (0.0, 0.0),
        (3.0, 0.0),
        (3.0, 3.0),
        (2.0, 3.0),
        (2.0, 1.0),
        (1.0, 1.0),
        (1.0, 3.0),
        (0.0, 3.0),
    ]
    .map(|(x, y)| DVec3::new(x, y, 0.0));
    let m = mesh_surface(&Surface::plane(outline.to_vec()).unwrap(), 1e-3).unwrap();
    let e = extend(&m, 0.4, FRAC_PI_6).unwrap();
    assert_eq!(overlap_area(&e, 300), 0.0);
    for d in [0.8, 1.5] {
        let e = extend(&m, d, FRAC_PI_6).unwrap_err().to_string();
        assert!(
            e.contains("extend-surface") && e.contains("folds"),
            "{d}: {e}"
        );
    }
}

#[test]
fn a_needle_notch_is_trimmed_not_refused() {
    // [0, 4]² with a notch 0.2 wide at the top coming to a point at (2, 1): its two walls turn
    // by about 176°, so their mitre would lie 15 d away; trimmed at the bisector x = 2 instead.
    let outline = [
        (0.0, 0.0),
        (4.0, 0.0),
        (4.0, 4.0),
        (2.1, 4.0),
        (2.0, 1.0),
        (1.9, 4.0),
        (0.0, 4.0),
    ]
    .map(|(x, y)| DVec3::new(x, y, 0.0));
    let m = mesh_surface(&Surface::plane(outline.to_vec()).unwrap(), 1e-3).unwrap();
    let d = 0.5;
    let e = extend(&m, d, FRAC_PI_6).unwrap();
    assert_eq!(overlap_area(&e, 400), 0.0);
    assert_eq!(e.boundary().len(), 1);
    for t in 0..e.len() {
        let [a, b, c] = e.corners_of(t);
        assert!((b - a).cross(c - a).z > 0.0);
    }
    // The notch is filled: the square [0, 4]² grown by d with its four corners on 15° chords,
    // less the small dip where the notch's corner arcs are cut below y = 4 + d (< 0.01).
    let fans = 4.0 * 6.0 * 0.5 * d * d * (15f64).to_radians().sin();
    let filled = 16.0 + 4.0 * 4.0 * d + fans;
    assert!(
        e.area() < filled && e.area() > filled - 0.01,
        "{} vs {filled}",
        e.area()
    );
    // Nothing lies beyond the bisector's reach: every new point is within d of the outline.
    let seg = |p: DVec3, a: DVec3, b: DVec3| {
        let f = ((p - a).dot(b - a) / (b - a).length_squared()).clamp(0.0, 1.0);
        (a + (b - a) * f - p).length()
    };
    for p in &e.vertices()[m.vertices().len()..] {
        let dist = (0..outline.len())
            .map(|i| seg(*p, outline[i], outline[(i + 1) % outline.len()]))
            .fold(f64::MAX, f64::min);
        assert!(dist <= d + 1e-9, "{p} at {dist}");
    }
}
