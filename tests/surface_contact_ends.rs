//! Where a tangent contact line ends inside one surface, at the other's boundary (issue 13): a
//! cylinder of radius 1 about the line y = 0, z = 1 from x = 0 to 4 (built as a ruled, swept and
//! revolved surface) lying on a plane region that covers x in [1, 3] only. The contact is the
//! ruling z = 0, y = 0 cut by the region: from (1, 0, 0) to (3, 0, 0), written here.

use lispcad::geom::surface::{surface_intersect_seeded, Surface};
use lispcad::geom::DVec3;

mod surface_support;
use surface_support::{assert_chords_on, cylinders, summary};

#[test]
fn a_contact_line_ends_at_the_other_surfaces_boundary_to_geomtol() {
    // The plate z = 0, and one tilted 0.1 rad about the axis (no mesh vertex on the contact:
    // it is traced on the true surfaces alone).
    for tilt in [0.0f64, 0.1] {
        let m = DVec3::new(0.0, tilt.sin(), -tilt.cos());
        let e2 = DVec3::new(0.0, tilt.cos(), tilt.sin());
        let ruling = DVec3::new(0.0, 0.0, 1.0) + m;
        let plate = Surface::plane(vec![
            ruling + DVec3::X - e2 * 5.0,
            ruling + DVec3::X * 3.0 - e2 * 5.0,
            ruling + DVec3::X * 3.0 + e2 * 5.0,
            ruling + DVec3::X + e2 * 5.0,
        ])
        .unwrap();
        let (e0, e1) = (ruling + DVec3::X, ruling + DVec3::X * 3.0);
        for (name, s) in cylinders() {
            for (x, y) in [(&s, &plate), (&plate, &s)] {
                let r = surface_intersect_seeded(x, y, 1e-2, 1e-6, 1e-9).unwrap();
                assert_eq!(r.len(), 1, "{name} {tilt}: {}", summary(&r));
                let c = &r[0];
                assert!(!c.closed && c.points.len() >= 2, "{name}: {}", summary(&r));
                let (a, b) = (c.points[0], *c.points.last().unwrap());
                let (a, b) = if a.x <= b.x { (a, b) } else { (b, a) };
                assert!(
                    a.distance(e0) <= 1e-9 && b.distance(e1) <= 1e-9,
                    "{name} {tilt}: ends {:e} {:e}",
                    a.distance(e0),
                    b.distance(e1)
                );
                for p in &c.points {
                    let rho = (p.y * p.y + (p.z - 1.0) * (p.z - 1.0)).sqrt();
                    assert!(
                        m.dot(*p - ruling).abs() <= 1e-9 && (rho - 1.0).abs() <= 1e-9,
                        "{name} {tilt}: {p}"
                    );
                }
                let l = c.length();
                assert!((l - 2.0).abs() <= 2e-9, "{name} {tilt}: {l}");
                // Every chord's midpoint on the cylinder and on the plate (within its extent in
                // x: the contact runs along x), to CHORDTOL 1e-6 + GEOMTOL.
                let off = |p: DVec3| {
                    let rho = (p.y * p.y + (p.z - 1.0) * (p.z - 1.0)).sqrt();
                    let beyond = if (1.0..=3.0).contains(&p.x) {
                        0.0
                    } else {
                        f64::INFINITY
                    };
                    m.dot(p - ruling).abs().max((rho - 1.0).abs()).max(beyond)
                };
                assert_chords_on(&format!("{name} {tilt}"), &r, off, 1e-6 + 1e-9);
                for _ in 0..2 {
                    let again = surface_intersect_seeded(x, y, 1e-2, 1e-6, 1e-9).unwrap();
                    assert!(again.len() == r.len());
                    assert!(again.iter().zip(&r).all(|(c, d)| c.points == d.points));
                }
            }
        }
    }
}
