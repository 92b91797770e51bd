//! Operations on parametric surfaces: closed forms where paper 002 gives them, the discrete
//! surface (tessellated within `chord_tol`) otherwise.

use super::error::{check_positive, SurfaceError};
use super::hits::{
    circle_plane, curve_mesh_hits, cylinder_section, point_in_polygon, segment_cylinder, ArcData,
    MeshHit,
};
use super::kinds::Surface;
use super::tessellate::mesh_surface;
use crate::geom::mesh::{
    intersect_meshes_edges, section, section_edges, Mesh, PairEdgedPolyline, Polyline3,
};
use crate::geom::ParamCurve;
use glam::DVec3;

/// [`surface_section_tol`] with the default GEOMTOL.
pub fn surface_section(
    s: &Surface,
    plane_point: DVec3,
    plane_normal: DVec3,
    chord_tol: f64,
) -> Result<Vec<Polyline3>, SurfaceError> {
    surface_section_tol(
        s,
        plane_point,
        plane_normal,
        chord_tol,
        crate::geom::GEOMTOL,
    )
}

/// Plane section of a surface. Exact (sampled within `chord_tol`) for a cylinder
/// ([`cylinder_section`]: circle, ellipse or rulings), a sphere (a circle) and a surface of
/// revolution cut across or through its axis; other kinds are sectioned through their mesh,
/// and every point of those seed curves is then carried onto the true surface by Newton
/// iteration to within `geom_tol` of the plane, and the curves densified within `chord_tol`.
pub fn surface_section_tol(
    s: &Surface,
    plane_point: DVec3,
    plane_normal: DVec3,
    chord_tol: f64,
    geom_tol: f64,
) -> Result<Vec<Polyline3>, SurfaceError> {
    surface_section_seeded(s, plane_point, plane_normal, chord_tol, chord_tol, geom_tol)
}

/// [`surface_section_tol`] with the seeding mesh made within `seed_tol` (the curves are still
/// densified within `chord_tol`): a fine curve from a coarse mesh.
pub fn surface_section_seeded(
    s: &Surface,
    plane_point: DVec3,
    plane_normal: DVec3,
    seed_tol: f64,
    chord_tol: f64,
    geom_tol: f64,
) -> Result<Vec<Polyline3>, SurfaceError> {
    let plane = (plane_point, plane_normal);
    section_seeded(s, plane, (seed_tol, chord_tol, geom_tol), true)
}

/// [`surface_section_seeded`] without the tangent-contact search: for benchmarks, which measure
/// what the search costs.
#[doc(hidden)]
pub fn surface_section_without_contacts(
    s: &Surface,
    plane_point: DVec3,
    plane_normal: DVec3,
    seed_tol: f64,
    chord_tol: f64,
    geom_tol: f64,
) -> Result<Vec<Polyline3>, SurfaceError> {
    let plane = (plane_point, plane_normal);
    section_seeded(s, plane, (seed_tol, chord_tol, geom_tol), false)
}

/// Most mesh section curves whose middle points seed the search for a region in the plane.
const MID_SEEDS: usize = 16;

fn section_seeded(
    s: &Surface,
    (plane_point, plane_normal): (DVec3, DVec3),
    (seed_tol, chord_tol, geom_tol): (f64, f64, f64),
    contacts: bool,
) -> Result<Vec<Polyline3>, SurfaceError> {
    let tol = check_positive("CHORDTOL (chord-tol)", chord_tol)?;
    let seed_tol = check_positive("seed tolerance", seed_tol)?;
    // The mesh's section seeds the curves, refined on the true surface; the points where the
    // plane touches without crossing (which the section misses) are searched for beside them.
    let refined = |m: Mesh| -> Result<Vec<Polyline3>, SurfaceError> {
        let seeds = section_edges(&m, plane_point, plane_normal)?;
        let n = plane_normal.normalize();
        let patch = super::refine::Patch::new(s);
        let plane = (plane_point, n);
        // Every chord returned is checked (`loose::settle_section`) but those densifying vouched
        // for meanwhile.
        let _ledger = super::loose::Ledger::open();
        // The contacts traced from the tips of lenses the seeds cut across (see `mend_section`).
        let mut tips: Vec<Polyline3> = Vec::new();
        let curves: Vec<Polyline3> = seeds
            .iter()
            .map(|(c, edges)| {
                let (r, loose) = super::refine::refine_section_loose(
                    &patch,
                    (c, edges),
                    plane,
                    (geom_tol, tol, seed_tol),
                );
                let (r, t) =
                    super::contact::mend_section(&patch, plane, r, &loose, (geom_tol, tol));
                tips.extend(t);
                r
            })
            .filter(|c| !c.points.is_empty())
            .collect();
        let mut curves = super::contact::regroup_section(
            &patch,
            (plane_point, n),
            curves,
            (seed_tol, geom_tol, tol),
        );
        curves.extend(tips);
        let curves = super::join::through_branches(curves, geom_tol);
        let settle = |c| super::loose::settle_section(&patch, plane, c, (geom_tol, tol));
        let mut curves = settle(curves);
        if !contacts {
            return Ok(curves);
        }
        let touch = (plane_point, n);
        let tols = (seed_tol, tol);
        let contacts = super::contact::plane_contacts(&patch, &m, touch, &curves, tols, geom_tol);
        curves.extend(settle(contacts));
        // A region lying in the plane narrower than the samples and the seed grid (a short
        // flat between creases) shows as a crossing or contact along it: looked for from the
        // curves. Only where the surface is tangent to the plane at one of their middle points:
        // the search builds its own tracer (0.45 % of the torus section's instructions).
        let mids: Vec<DVec3> = curves
            .iter()
            .filter_map(|c| c.points.get(c.points.len() / 2).copied())
            .take(MID_SEEDS)
            .collect();
        let flat = |p: &DVec3| super::common::flat_on_plane(&patch, *p, plane, geom_tol);
        if mids.iter().any(flat) {
            if let Some(mut l) = super::common::in_plane(s, plane, &mids, geom_tol, tol) {
                l.extend(settle(super::common::outside_plane_region(
                    s, plane, curves, geom_tol,
                )));
                return Ok(l);
            }
        }
        Ok(curves)
    };
    // A surface lying in the plane over a region: that region's boundary loops.
    let n = plane_normal.normalize_or_zero();
    if n != DVec3::ZERO && plane_point.is_finite() {
        if let Some(l) = super::common::in_plane(s, (plane_point, n), &[], geom_tol, tol) {
            return Ok(l);
        }
    }
    match s {
        Surface::Cylinder(c) => {
            if plane_normal.length() == 0.0 || !plane_normal.is_finite() || !plane_point.is_finite()
            {
                return Err(SurfaceError::Invalid(
                    "plane point and normal must be finite, the normal non-zero".into(),
                ));
            }
            Ok(cylinder_section(c, plane_point, plane_normal, tol))
        }
        Surface::Sphere(sp) => {
            let n = plane_normal.normalize_or_zero();
            if n == DVec3::ZERO || !plane_point.is_finite() {
                return Err(SurfaceError::Invalid(
                    "plane point and normal must be finite, the normal non-zero".into(),
                ));
            }
            // Sphere ∩ plane: the circle about the centre's projection, radius √(r² − d²).
            let d = n.dot(sp.center - plane_point);
            let rad2 = sp.radius * sp.radius - d * d;
            let c = sp.center - n * d;
            // Touching within GEOMTOL: the point of contact, on the plane.
            let touching = (d.abs() - sp.radius).abs() <= geom_tol;
            if rad2 < 0.0 && !touching {
                return Ok(Vec::new());
            }
            let rad = rad2.max(0.0).sqrt();
            if rad <= tol || touching {
                return Ok(vec![Polyline3 {
                    points: vec![c],
                    closed: false,
                }]);
            }
            let step = (2.0 * (1.0 - tol / rad).clamp(-1.0, 1.0).acos())
                .clamp(1e-4, std::f64::consts::FRAC_PI_8);
            let k = (std::f64::consts::TAU / step).ceil() as usize;
            let arc = ArcData::circle(c, rad, n);
            let points = (0..k)
                .map(|i| arc.point(std::f64::consts::TAU * i as f64 / k as f64))
                .collect();
            Ok(vec![Polyline3 {
                points,
                closed: true,
            }])
        }
        Surface::Revolve(r) => match revolve_section(r, plane_point, plane_normal, tol, geom_tol) {
            Some(curves) => Ok(curves),
            None => match super::cone::Cone::of(r).filter(|_| {
                plane_point.is_finite() && plane_normal.is_finite() && plane_normal.length() > 0.0
            }) {
                Some(k) => Ok(super::cone::cone_plane(
                    &k,
                    plane_point,
                    plane_normal.normalize(),
                    None,
                    geom_tol,
                    tol,
                )),
                None => refined(mesh_surface(s, seed_tol)?),
            },
        },
        Surface::Plane(_) => Ok(section(&mesh_surface(s, tol)?, plane_point, plane_normal)?),
        _ => refined(mesh_surface(s, seed_tol)?),
    }
}

/// The exact sections of a surface of revolution where they are simple: a plane perpendicular
/// to the axis cuts circles (arcs for a partial revolution) through the profile's crossings,
/// solved on the true profile to `geom_tol` (paper 002's arc/plane, inverted); a plane containing the axis cuts the profile itself,
/// turned into the plane. Other planes: None (use the mesh).
fn revolve_section(
    r: &super::kinds::Revolve,
    p: DVec3,
    n: DVec3,
    tol: f64,
    geom_tol: f64,
) -> Option<Vec<Polyline3>> {
    use glam::DQuat;
    use std::f64::consts::TAU;
    let n = n.normalize_or_zero();
    if n == DVec3::ZERO || !p.is_finite() {
        return None;
    }
    let axis = r.axis_dir;
    let along = n.dot(axis).abs();
    let (_, mut prof) = super::sampled::sample_curve(r.profile.as_ref(), tol, 16);
    // A closed profile ends where it starts: the same point bit for bit, so a seam lying on the
    // plane is one crossing (roundoff in the end point would hide it between last and first).
    let last = prof.len() - 1;
    let closed_profile = prof[0].distance(prof[last]) <= 1e-12 * (1.0 + prof[0].length());
    if closed_profile {
        prof[last] = prof[0];
    }
    if (1.0 - along) <= 1e-14 {
        return Some(super::coaxial::revolve_plane_perpendicular(
            r, p, geom_tol, tol,
        ));
    }
    if along <= 1e-14 && n.dot(r.axis_point - p).abs() <= tol {
        // The plane contains the axis: the profile turned by θ lies in it where its radial
        // direction does; find that direction from a profile point off the axis.
        let q = prof.iter().copied().find(|q| {
            let d = *q - r.axis_point;
            (d - axis * d.dot(axis)).length() > tol
        })?;
        let d = q - r.axis_point;
        let radial = (d - axis * d.dot(axis)).normalize();
        let target = axis.cross(n).normalize();
        let mut out = Vec::new();
        for dir in [target, -target] {
            let theta = radial
                .cross(dir)
                .dot(axis)
                .atan2(radial.dot(dir))
                .rem_euclid(TAU);
            if theta <= r.angle + 1e-12 || (r.angle >= TAU) {
                let rot = DQuat::from_axis_angle(axis, theta);
                let open = &prof[..prof.len() - usize::from(closed_profile)];
                out.push(Polyline3 {
                    points: open
                        .iter()
                        .map(|x| r.axis_point + rot * (*x - r.axis_point))
                        .collect(),
                    closed: closed_profile,
                });
            }
        }
        return Some(out);
    }
    None
}

/// [`surface_intersect_tol`] with the default GEOMTOL.
pub fn surface_intersect(
    a: &Surface,
    b: &Surface,
    chord_tol: f64,
) -> Result<Vec<Polyline3>, SurfaceError> {
    surface_intersect_tol(a, b, chord_tol, crate::geom::GEOMTOL)
}

/// Intersection curves of two surfaces: closed forms for sphere/sphere, sphere/plane,
/// plane/plane, the pairs with a cylinder and coaxial surfaces of revolution (a tangent contact
/// comes back as a one-point polyline); otherwise the meshes' intersection seeds the curves and
/// every point is carried onto both true surfaces by Newton iteration to within `geom_tol`, then
/// the curves are densified within `chord_tol`; isolated tangent contacts, which the meshes
/// miss, are found as zero minima of the distance between the surfaces.
pub fn surface_intersect_tol(
    a: &Surface,
    b: &Surface,
    chord_tol: f64,
    geom_tol: f64,
) -> Result<Vec<Polyline3>, SurfaceError> {
    surface_intersect_seeded(a, b, chord_tol, chord_tol, geom_tol)
}

/// What two surfaces share: curves (crossings, tangent points, a common region's boundary
/// loops), or the whole of both where they coincide everywhere with no boundary.
#[derive(Debug, Clone)]
pub enum Meet {
    Curves(Vec<Polyline3>),
    /// Coincident everywhere, no boundary (two equal spheres or tori): the other intersection
    /// functions return no curve for it.
    Everywhere,
}

/// [`surface_intersect_tol`], telling surfaces that coincide everywhere apart from surfaces
/// that do not meet.
pub fn surface_meet(
    a: &Surface,
    b: &Surface,
    chord_tol: f64,
    geom_tol: f64,
) -> Result<Meet, SurfaceError> {
    Ok(
        match intersect_seeded(a, b, (chord_tol, chord_tol, geom_tol), true)? {
            Some(c) => Meet::Curves(c),
            None => Meet::Everywhere,
        },
    )
}

/// [`surface_intersect_tol`] with the seeding meshes made within `seed_tol`.
pub fn surface_intersect_seeded(
    a: &Surface,
    b: &Surface,
    seed_tol: f64,
    chord_tol: f64,
    geom_tol: f64,
) -> Result<Vec<Polyline3>, SurfaceError> {
    intersect_seeded(a, b, (seed_tol, chord_tol, geom_tol), true).map(Option::unwrap_or_default)
}

/// [`surface_intersect_seeded`] without the tangent-contact search: for benchmarks, which
/// measure what the search costs.
#[doc(hidden)]
pub fn surface_intersect_without_contacts(
    a: &Surface,
    b: &Surface,
    seed_tol: f64,
    chord_tol: f64,
    geom_tol: f64,
) -> Result<Vec<Polyline3>, SurfaceError> {
    intersect_seeded(a, b, (seed_tol, chord_tol, geom_tol), false).map(Option::unwrap_or_default)
}

fn intersect_seeded(
    a: &Surface,
    b: &Surface,
    (seed_tol, chord_tol, geom_tol): (f64, f64, f64),
    contacts: bool,
) -> Result<Option<Vec<Polyline3>>, SurfaceError> {
    let ctol = check_positive("CHORDTOL (chord-tol)", chord_tol)?;
    let seed_tol = check_positive("seed tolerance", seed_tol)?;
    let gtol = check_positive("GEOMTOL", geom_tol)?;
    // A common region is its boundary loops (None: everywhere, no boundary), with the curves
    // elsewhere: the closed form's, or the meshes' kept where they leave the region.
    let tols = (seed_tol, gtol, ctol);
    match super::common::overlap(a, b, gtol, ctol) {
        Some(super::common::Overlap::Loops(mut l)) => {
            if let Some(c) = super::analytic::analytic_intersect(a, b, gtol, ctol) {
                l.extend(super::common::outside_common(a, b, c, gtol));
            } else {
                let region = super::beside::Region::new(a, b, gtol);
                // Meshes too fine to make (a twisted patch at a tiny CHORDTOL) leave the loops,
                // which are found on the true surfaces alone, as before the mesh path ran here.
                if let Ok(c) = through_meshes(a, b, tols, contacts, Some((&region, &mut l))) {
                    l.extend(c);
                }
            }
            return Ok(Some(l));
        }
        Some(super::common::Overlap::Everywhere) => return Ok(None),
        None => {}
    }
    if let Some(curves) = super::analytic::analytic_intersect(a, b, gtol, ctol) {
        return Ok(Some(curves));
    }
    through_meshes(a, b, tols, contacts, None).map(Some)
}

/// The seeding meshes' tolerance beside a common region, as a fraction of the smaller
/// surface's size. Crossings the meshes cannot tell from a touch at that tolerance can be
/// missed there: a loop less than about a hundredth of the size across, on surfaces curved on
/// the scale of their size.
const COARSE_SEED: f64 = 1e-4;

/// [`super::beside::seeds_outside`] keeping each point's mesh edge (its points are the seeds'
/// own, bit for bit).
fn seeds_outside_edged(
    region: &super::beside::Region,
    seeds: Vec<PairEdgedPolyline>,
    near: f64,
) -> Vec<PairEdgedPolyline> {
    let bits = |x: &DVec3| [x.x.to_bits(), x.y.to_bits(), x.z.to_bits()];
    let mut edge_at = std::collections::HashMap::new();
    for (c, e) in &seeds {
        for (p, e) in c.points.iter().zip(e) {
            edge_at.insert(bits(p), *e);
        }
    }
    let plain = seeds.into_iter().map(|c| c.0).collect();
    super::beside::seeds_outside(region, plain, near)
        .into_iter()
        .map(|c| {
            let e = c
                .points
                .iter()
                .map(|p| edge_at.get(&bits(p)).copied().flatten());
            let e = e.collect();
            (c, e)
        })
        .collect()
}

/// The intersection seeded by the meshes and refined on the true surfaces, with the tangent
/// contacts the meshes miss (when `contacts`). Beside a common region, only what lies outside
/// it: the curves are cut where they enter it, and end on its `loops`.
fn through_meshes(
    a: &Surface,
    b: &Surface,
    (seed_tol, gtol, ctol): (f64, f64, f64),
    contacts: bool,
    mut region: Option<(&super::beside::Region, &mut Vec<Polyline3>)>,
) -> Result<Vec<Polyline3>, SurfaceError> {
    use super::beside::{outside, Reach};
    let (pa, pb) = (super::refine::Patch::new(a), super::refine::Patch::new(b));
    // Beside a common region, seeded from coarse meshes: their curves are refined onto both
    // true surfaces to GEOMTOL and densified within CHORDTOL all the same, and meshes within
    // a tiny CHORDTOL of a twisted surface cost seconds where the region's loops take
    // milliseconds.
    let seed_tol = match region {
        Some(_) => seed_tol.max(COARSE_SEED * pa.scale().min(pb.scale())),
        None => seed_tol,
    };
    let (ma, mb) = (mesh_surface(a, seed_tol)?, mesh_surface(b, seed_tol)?);
    // Each seed point with the mesh edge it lies on (see `refine::bracket`); the seeds cut
    // beside a region go without.
    let seeds = intersect_meshes_edges(&ma, &mb);
    let seeds = match region.as_ref() {
        Some((r, _)) => seeds_outside_edged(r, seeds, 8.0 * seed_tol),
        None => seeds,
    };
    let reach = Reach {
        tol: gtol,
        chord_tol: ctol,
        seed_tol,
    };
    // Every chord returned is checked (`loose::settle_pair`) but those densifying vouched for
    // meanwhile.
    let _ledger = super::loose::Ledger::open();
    // The contacts traced from the tips of lenses the seeds cut across (see `mend_pair`).
    let mut tips: Vec<Polyline3> = Vec::new();
    let curves: Vec<Polyline3> = seeds
        .iter()
        .map(|(c, e)| {
            let (r, loose) =
                super::refine::refine_pair_curve(&pa, &pb, (c, e), (gtol, ctol, seed_tol));
            let (mut r, t) = super::contact::mend_pair(&pa, &pb, r, &loose, (gtol, ctol));
            tips.extend(t);
            super::refine::close_gap(&pa, &pb, &mut r, gtol, ctol);
            r
        })
        .filter(|c| !c.points.is_empty())
        .collect();
    let curves = match region.as_mut() {
        Some((r, loops)) => outside(r, (&pa, &pb), curves, loops, reach),
        None => curves,
    };
    let mut curves = super::contact::regroup_pair(&pa, &pb, curves, (seed_tol, gtol, ctol));
    curves.extend(tips);
    // A crossing ends on the region's loop where the surfaces coincide, so tangent there: the
    // contact traced from that end runs on along the loop (a fold crossing a rectangle along
    // its edge came back as the whole edge). Cut again.
    if let Some((r, loops)) = region.as_mut() {
        curves = outside(r, (&pa, &pb), curves, loops, reach);
    }
    let mut curves = super::join::through_branches(curves, gtol);
    let settle = |c| super::loose::settle_pair(&pa, &pb, c, (gtol, ctol));
    curves = settle(curves);
    if !contacts {
        return Ok(curves);
    }
    // Touching without crossing: the meshes miss each other there. Seeded from both meshes'
    // vertices (a coarse plane region has none near a contact on the other surface); the
    // region's loops count as curves found.
    let mut found = curves.clone();
    if let Some((_, loops)) = region.as_ref() {
        found.extend(loops.iter().cloned());
    }
    // Inside the region the surfaces touch everywhere: every mesh vertex there would seed a
    // search, and each walk would wander the region to its edge.
    // The seeds are mesh vertices, within the seeding tolerance of their own surface.
    let shared = |p: DVec3| {
        region
            .as_ref()
            .is_some_and(|(r, _)| r.holds(p, 8.0 * seed_tol))
    };
    let mut touch =
        super::contact::tangent_contacts(&pa, &pb, &ma, &mb, &found, &shared, seed_tol, gtol, ctol);
    found.extend(touch.iter().cloned());
    touch.extend(super::contact::tangent_contacts(
        &pb, &pa, &mb, &ma, &found, &shared, seed_tol, gtol, ctol,
    ));
    let touch = match region.as_mut() {
        Some((r, loops)) => outside(r, (&pa, &pb), touch, loops, reach),
        None => touch,
    };
    curves.extend(settle(touch));
    Ok(curves)
}

/// Where the segment `p0 → p1` meets a surface, as `(t, point)` sorted by t: closed form for
/// cylinders (paper 002's line/cylinder), planar regions (line/plane + point in polygon) and
/// spheres; through the mesh otherwise.
pub fn segment_surface_hits(
    p0: DVec3,
    p1: DVec3,
    s: &Surface,
    tol: f64,
) -> Result<Vec<(f64, DVec3)>, SurfaceError> {
    let tol = check_positive("tolerance", tol)?;
    Ok(match s {
        Surface::Cylinder(c) => segment_cylinder(p0, p1, c, tol)
            .into_iter()
            .map(|h| (h.t, h.point))
            .collect(),
        Surface::Plane(p) => p.segment_hit(p0, p1, tol).into_iter().collect(),
        Surface::Sphere(sp) => {
            // |p0 + v t − c|² = r²: a t² + 2 b t + c = 0.
            let v = p1 - p0;
            let w = p0 - sp.center;
            let a = v.dot(v);
            if a == 0.0 {
                return Ok(Vec::new());
            }
            let b = v.dot(w);
            let c = w.dot(w) - sp.radius * sp.radius;
            let disc = b * b - a * c;
            // Tangent when the line's distance from the centre is within tol of r.
            let d2 = (w.dot(w) - b * b / a).max(0.0);
            let mut ts = if (d2.sqrt() - sp.radius).abs() <= tol {
                vec![-b / a]
            } else if disc < 0.0 {
                vec![]
            } else {
                let q = -(b + b.signum() * disc.sqrt());
                let (r1, r2) = if q != 0.0 { (q / a, c / q) } else { (0.0, 0.0) };
                vec![r1.min(r2), r1.max(r2)]
            };
            ts.retain(|t| (0.0..=1.0).contains(t));
            ts.into_iter().map(|t| (t, p0 + v * t)).collect()
        }
        _ => {
            // The mesh seeds the hits; they are refined on the true surface (GEOMTOL-level
            // tolerance scaled from `tol`, the caller's GEOMTOL).
            let chord = (tol * 1e6).min(1e-2);
            let m = mesh_surface(s, chord)?;
            let line = crate::geom::line::Line { p0, p1 };
            let patch = super::refine::Patch::new(s);
            super::refine::curve_hits_refined(
                &patch,
                &m,
                &line,
                (&[0.0, 1.0], &[p0, p1]),
                tol,
                chord,
            )
        }
    })
}

/// Where a circle or arc meets a surface: closed form for planar regions (paper 002's
/// circle/plane, then point in polygon); otherwise the arc sampled within `tol` against the mesh.
pub fn arc_surface_hits(arc: &ArcData, s: &Surface, tol: f64) -> Result<Vec<DVec3>, SurfaceError> {
    let tol = check_positive("tolerance", tol)?;
    match s {
        Surface::Plane(p) => Ok(circle_plane(arc, p.boundary[0], p.normal, tol)
            .into_iter()
            .filter(|q| point_in_polygon(*q, &p.boundary, p.normal, tol).is_in())
            .collect()),
        _ => {
            struct ArcCurve<'a>(&'a ArcData);
            impl ParamCurve for ArcCurve<'_> {
                fn eval(&self, t: f64) -> DVec3 {
                    let a = self.0;
                    a.point(a.start_angle + t * a.sweep())
                }
            }
            let m = mesh_surface(s, tol)?;
            Ok(curve_mesh_hits(&ArcCurve(arc), &m, tol)
                .into_iter()
                .map(|h| h.point)
                .collect())
        }
    }
}

/// Any curve against a surface through its mesh (see [`curve_mesh_hits`]).
pub fn curve_surface_hits(
    curve: &dyn ParamCurve,
    s: &Surface,
    chord_tol: f64,
) -> Result<Vec<MeshHit>, SurfaceError> {
    let m: Mesh = mesh_surface(s, chord_tol)?;
    Ok(curve_mesh_hits(curve, &m, chord_tol))
}

/// Any curve against a parametric surface, the mesh hits (and near-misses of the mesh
/// boundary) refined on the true curve and surface to within `tol`: `(t, point)` sorted by t.
pub fn curve_surface_hits_refined(
    curve: &dyn ParamCurve,
    s: &Surface,
    chord_tol: f64,
    tol: f64,
) -> Result<Vec<(f64, DVec3)>, SurfaceError> {
    let chord_tol = check_positive("CHORDTOL (chord-tol)", chord_tol)?;
    let tol = check_positive("GEOMTOL", tol)?;
    let m: Mesh = mesh_surface(s, chord_tol)?;
    let (ts, pts) = super::sampled::sample_curve(curve, chord_tol, 16);
    let patch = super::refine::Patch::new(s);
    Ok(super::refine::curve_hits_refined(
        &patch,
        &m,
        curve,
        (&ts, &pts),
        tol,
        chord_tol,
    ))
}

/// Area: exact for cylinders (2πrh), spheres (4πr²) and planar regions (Newell's area); the
/// mesh's area otherwise (which approaches the surface's from below as `chord_tol` shrinks).
pub fn surface_area(s: &Surface, chord_tol: f64) -> Result<f64, SurfaceError> {
    use std::f64::consts::{PI, TAU};
    Ok(match s {
        Surface::Cylinder(c) => TAU * c.radius * c.height,
        Surface::Sphere(sp) => 4.0 * PI * sp.radius * sp.radius,
        Surface::Plane(p) => 0.5 * super::planar::newell_normal(&p.boundary).length(),
        _ => mesh_surface(s, chord_tol)?.area(),
    })
}

/// The boundary as closed polylines (of the mesh within `chord_tol`; a plane region's own
/// polygon).
pub fn surface_boundary(s: &Surface, chord_tol: f64) -> Result<Vec<Polyline3>, SurfaceError> {
    Ok(match s {
        Surface::Plane(p) => vec![Polyline3 {
            points: p.boundary.clone(),
            closed: true,
        }],
        _ => mesh_surface(s, chord_tol)?.boundary(),
    })
}

/// Whether the whole curve lies on the surface (within `tol`): an OVERLAP, not a set of hits.
/// Checked at 129 points along the curve, by closed-form distances for cylinders, spheres and
/// planar regions and by projection onto the true surface otherwise.
pub fn curve_on_surface(
    curve: &dyn ParamCurve,
    s: &Surface,
    tol: f64,
) -> Result<bool, SurfaceError> {
    let tol = check_positive("GEOMTOL", tol)?;
    let patch = match s {
        Surface::Cylinder(_) | Surface::Sphere(_) | Surface::Plane(_) => None,
        _ => Some(super::refine::Patch::new(s)),
    };
    let mut prev = None;
    for i in 0..=128 {
        let p = curve.eval(i as f64 / 128.0);
        let on = match s {
            Surface::Cylinder(c) => {
                let h = (p - c.base).dot(c.axis);
                let radial = (p - c.base - c.axis * h).length();
                (radial - c.radius).abs() <= tol && h >= -tol && h <= c.height + tol
            }
            Surface::Sphere(sp) => (p.distance(sp.center) - sp.radius).abs() <= tol,
            Surface::Plane(pl) => {
                pl.normal.dot(p - pl.boundary[0]).abs() <= tol
                    && point_in_polygon(p, &pl.boundary, pl.normal, tol).is_in()
            }
            _ => {
                let patch = patch.as_ref().expect("built for the other kinds");
                let uv = patch.project(p, prev);
                prev = Some(uv);
                patch.eval(uv).distance(p) <= tol
            }
        };
        if !on {
            return Ok(false);
        }
    }
    Ok(true)
}
