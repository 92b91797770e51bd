//! A crossing running alongside a tangent contact, closer to it than the seeding meshes resolve
//! (issue 13): the sheet z = f(y) = y²(d − y) over y in [−1, 1], ruled along x from 0 to 4,
//! meets the plane z = 0 in a contact along y = 0 (a double root of f: the sheet lies on the
//! plane there, f ≥ 0 on both sides) and a crossing along y = d (a simple root, at the angle
//! atan(d²) between the surfaces: 1e-4 rad for d = 0.01, 9e-4 rad for d = 0.03, both under
//! 0.06°). Both are straight lines of length 4 from x = 0 to x = 4. The meshes see one change
//! of side for the two, and the refined seed curve fell on the contact: the crossing was lost.

use lispcad::geom::curve::Curve;
use lispcad::geom::mesh::Polyline3;
use lispcad::geom::surface::{surface_intersect_seeded, surface_section_seeded, Surface};
use lispcad::geom::DVec3;
use std::sync::Arc;

mod surface_support;
use surface_support::summary;

/// The sheet for root `d`: the profile is one cubic Bézier span with control points evenly
/// spaced in y (so y is linear in the parameter and z is exactly the cubic f), its Bernstein
/// coefficients from f and f' at the ends.
fn sheet(d: f64) -> Surface {
    let f = |y: f64| y * y * (d - y);
    let df = |y: f64| 2.0 * d * y - 3.0 * y * y;
    // y = 2t − 1: dz/dt = 2 f'(y).
    let z = [
        f(-1.0),
        f(-1.0) + 2.0 * df(-1.0) / 3.0,
        f(1.0) - 2.0 * df(1.0) / 3.0,
        f(1.0),
    ];
    let ctrl: Vec<DVec3> = (0..4)
        .map(|i| DVec3::new(0.0, 2.0 * i as f64 / 3.0 - 1.0, z[i]))
        .collect();
    let far: Vec<DVec3> = ctrl.iter().map(|c| *c + DVec3::X * 4.0).collect();
    let p = Curve::bspline(ctrl, 3, None, None).unwrap();
    let q = Curve::bspline(far, 3, None, None).unwrap();
    Surface::ruled(Arc::new(p), Arc::new(q))
}

/// The contact (every point within d/4 of y = 0, where the sheet is parallel to the plane)
/// and the crossing (within d/4 of y = d): open, from x = 0 to x = 4 to 1e-9, length 4 to
/// 1e-6, every point within 1e-9 of the plane and of the sheet.
fn check(name: &str, r: &[Polyline3], d: f64) {
    assert_eq!(r.len(), 2, "{name}: {}", summary(r));
    let f = |y: f64| y * y * (d - y);
    let on_line = |c: &Polyline3, y0: f64| c.points.iter().all(|p| (p.y - y0).abs() <= 0.25 * d);
    let contact = r.iter().find(|c| on_line(c, 0.0));
    let crossing = r.iter().find(|c| on_line(c, d));
    let (Some(contact), Some(crossing)) = (contact, crossing) else {
        panic!("{name}: {}", summary(r));
    };
    for c in [contact, crossing] {
        assert!(!c.closed, "{name}: {}", summary(r));
        for p in &c.points {
            assert!(p.z.abs() <= 1e-9, "{name}: {p} off the plane");
            assert!((p.z - f(p.y)).abs() <= 1e-9, "{name}: {p} off the sheet");
            assert!((-1e-9..=4.0 + 1e-9).contains(&p.x), "{name}: {p}");
        }
        let (a, b) = (c.points[0].x, c.points[c.points.len() - 1].x);
        let (a, b) = (a.min(b), a.max(b));
        assert!(
            a.abs() <= 1e-9 && (b - 4.0).abs() <= 1e-9,
            "{name}: {}",
            summary(r)
        );
        assert!((c.length() - 4.0).abs() <= 1e-6, "{name}: {}", summary(r));
    }
    // Tangent along the contact: the sheet's slope f'(y) = 2dy − 3y² vanishes there.
    for p in &contact.points {
        assert!(
            (2.0 * d * p.y - 3.0 * p.y * p.y).abs() <= 1e-6,
            "{name}: {p}"
        );
    }
}

/// One way of asking for the intersection.
type Run<'a> = Box<dyn Fn() -> Vec<Polyline3> + 'a>;

#[test]
fn a_crossing_beside_a_contact_line_comes_back_with_it() {
    let plate = Surface::plane(vec![
        DVec3::new(-1.0, -2.0, 0.0),
        DVec3::new(5.0, -2.0, 0.0),
        DVec3::new(5.0, 2.0, 0.0),
        DVec3::new(-1.0, 2.0, 0.0),
    ])
    .unwrap();
    for d in [0.01, 0.03] {
        let s = sheet(d);
        let runs: [(&str, Run); 3] = [
            (
                "section",
                Box::new(|| {
                    surface_section_seeded(&s, DVec3::ZERO, DVec3::Z, 1e-2, 1e-6, 1e-9).unwrap()
                }),
            ),
            (
                "sheet ∩ plate",
                Box::new(|| surface_intersect_seeded(&s, &plate, 1e-2, 1e-6, 1e-9).unwrap()),
            ),
            (
                "plate ∩ sheet",
                Box::new(|| surface_intersect_seeded(&plate, &s, 1e-2, 1e-6, 1e-9).unwrap()),
            ),
        ];
        for (name, run) in &runs {
            let r = run();
            check(&format!("{name} d = {d}"), &r, d);
            for _ in 0..2 {
                let again = run();
                assert_eq!(again.len(), r.len());
                assert!(again
                    .iter()
                    .zip(&r)
                    .all(|(c, e)| c.points == e.points && c.closed == e.closed));
            }
        }
    }
}

#[test]
fn a_crossing_beyond_the_other_surfaces_edge_is_not_reported() {
    // The plate stops at y = d/2: the sheet crosses the plate's plane at y = d, off the plate,
    // so only the contact is shared. The scan across the contact sees the gap's sign change
    // there (measured to the plate's edge), which must not pass for a crossing.
    let d = 0.01;
    let plate = Surface::plane(vec![
        DVec3::new(-1.0, -0.5, 0.0),
        DVec3::new(5.0, -0.5, 0.0),
        DVec3::new(5.0, 0.5 * d, 0.0),
        DVec3::new(-1.0, 0.5 * d, 0.0),
    ])
    .unwrap();
    let s = sheet(d);
    for (x, y) in [(&s, &plate), (&plate, &s)] {
        let r = surface_intersect_seeded(x, y, 1e-2, 1e-6, 1e-9).unwrap();
        assert_eq!(r.len(), 1, "{}", summary(&r));
        let c = &r[0];
        for p in &c.points {
            assert!(p.y.abs() <= 0.25 * d && p.z.abs() <= 1e-9, "{p}");
            assert!((p.z - p.y * p.y * (d - p.y)).abs() <= 1e-9, "{p}");
        }
        assert!((c.length() - 4.0).abs() <= 1e-6, "{}", summary(&r));
    }
}
