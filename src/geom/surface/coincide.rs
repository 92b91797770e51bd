//! Analytic surfaces that coincide over a region: their intersection is that region, returned as
//! its boundary loops (closed polylines), as coplanar planar regions give theirs
//! ([`super::overlap`]).
//!
//! Handled exactly: surfaces of revolution with a straight meridian about one axis line —
//! cylinders, revolved segments coplanar with the axis (cones, cylinder and annulus pieces) —
//! lying on one meridian line (the common band: the meridian segments' overlap times the
//! angular spans' overlap); and a surface of revolution whose whole profile lies on a sphere
//! centred on its axis (the revolution itself: its boundary). Two equal spheres, and a whole
//! revolution of a meridian from pole to pole against its sphere, coincide everywhere and have
//! no boundary: [`Overlap::Everywhere`]. Other coincidences (a profile partly on the other
//! surface, sweeps, ruled and Coons patches) are traced on the true surfaces by
//! [`super::common`].

use super::coaxial::{circle, overlap, span_of, Axis, Span};
use super::common::Overlap;
use super::kinds::{Revolve, Sphere, Surface};
use crate::geom::mesh::Polyline3;
use glam::{DVec2, DVec3};
use std::f64::consts::TAU;

/// A surface with a straight meridian: its segment (ρ, z) about `ax` and its angular span.
struct Band {
    m0: DVec2,
    m1: DVec2,
    span: Span,
}

/// The region where `a` and `b` coincide (its boundary loops, none when they only share a
/// carrier and lie apart on it); None when they do not coincide in a way decided here.
pub(crate) fn coincident(a: &Surface, b: &Surface, tol: f64, chord_tol: f64) -> Option<Overlap> {
    match (a, b) {
        (Surface::Sphere(s), Surface::Sphere(t)) => {
            let same = s.center.distance(t.center) <= tol && (s.radius - t.radius).abs() <= tol;
            same.then_some(Overlap::Everywhere)
        }
        (Surface::Revolve(r), Surface::Sphere(s)) | (Surface::Sphere(s), Surface::Revolve(r)) => {
            let loops = revolve_on_sphere(r, s, tol, chord_tol)?;
            // A whole revolution with no boundary circle runs from pole to pole: the sphere.
            Some(if loops.is_empty() && r.angle >= TAU {
                Overlap::Everywhere
            } else {
                Overlap::Loops(loops)
            })
        }
        _ => {
            let ax = axis_of(a)?;
            let (ba, bb) = (band(&ax, a, tol)?, band(&ax, b, tol)?);
            common_band(&ax, &ba, &bb, tol, chord_tol).map(Overlap::Loops)
        }
    }
}

fn axis_of(s: &Surface) -> Option<Axis> {
    match s {
        Surface::Cylinder(c) => Some(Axis::new(c.base, c.axis)),
        Surface::Revolve(r) => Some(Axis::new(r.axis_point, r.axis_dir)),
        _ => None,
    }
}

/// The surface as a straight-meridian band about `ax` (None: another kind, another axis, or a
/// profile that is not a segment in one meridian half-plane).
fn band(ax: &Axis, s: &Surface, tol: f64) -> Option<Band> {
    match s {
        Surface::Cylinder(c) => {
            let (radius, z0, z1) = ax.cylinder(c, tol)?;
            Some(Band {
                m0: DVec2::new(radius, z0),
                m1: DVec2::new(radius, z1),
                span: (0.0, TAU),
            })
        }
        Surface::Revolve(r) => {
            if !ax.same_line(r.axis_point, r.axis_dir, tol) {
                return None;
            }
            let (p0, p1) = (r.profile.eval(0.0), r.profile.eval(1.0));
            let (m0, m1) = (ax.meridian(p0), ax.meridian(p1));
            let off = if m0.x >= m1.x { p0 } else { p1 };
            if m0.x.max(m1.x) <= tol || m0.distance(m1) <= tol {
                return None;
            }
            let at = ax.angle(off);
            // Straight, in one meridian half-plane (off the axis, at one angle).
            for i in 1..16 {
                let p = r.profile.eval(i as f64 / 16.0);
                let m = ax.meridian(p);
                if line_dist(m, m0, m1) > tol || !on_segment(m, m0, m1, tol) {
                    return None;
                }
                let da = (ax.angle(p) - at + TAU / 2.0).rem_euclid(TAU) - TAU / 2.0;
                if m.x > tol && (da * m.x).abs() > tol {
                    return None;
                }
            }
            Some(Band {
                m0,
                m1,
                span: span_of(ax, r, off),
            })
        }
        _ => None,
    }
}

fn line_dist(m: DVec2, a: DVec2, b: DVec2) -> f64 {
    let d = b - a;
    (m - a).perp_dot(d).abs() / d.length()
}

fn on_segment(m: DVec2, a: DVec2, b: DVec2, tol: f64) -> bool {
    let d = b - a;
    let f = (m - a).dot(d) / d.length_squared();
    f * d.length() >= -tol && (f - 1.0) * d.length() <= tol
}

/// Two bands on one meridian line: the common segment times the common spans.
fn common_band(ax: &Axis, a: &Band, b: &Band, tol: f64, chord_tol: f64) -> Option<Vec<Polyline3>> {
    if line_dist(b.m0, a.m0, a.m1) > tol || line_dist(b.m1, a.m0, a.m1) > tol {
        return None;
    }
    let d = a.m1 - a.m0;
    let f = |m: DVec2| (m - a.m0).dot(d) / d.length_squared();
    let (f0, f1) = (f(b.m0), f(b.m1));
    let (lo, hi) = (f0.min(f1).max(0.0), f0.max(f1).min(1.0));
    if (hi - lo) * d.length() < -tol {
        return Some(Vec::new()); // on one line, apart
    }
    let (m0, m1) = (a.m0 + d * lo, a.m0 + d * hi.max(lo));
    let mut out = Vec::new();
    for (start, sweep) in overlap(a.span, b.span) {
        out.extend(band_loops(ax, (m0, m1), (start, sweep), tol, chord_tol));
    }
    Some(out)
}

/// The boundary of the band `[m0, m1] × [start, start + sweep]`: the two end circles when it
/// goes all round (none at a meridian point on the axis), one loop otherwise.
fn band_loops(
    ax: &Axis,
    (m0, m1): (DVec2, DVec2),
    (start, sweep): Span,
    tol: f64,
    chord_tol: f64,
) -> Vec<Polyline3> {
    let ring = |m: DVec2| circle(ax, m, start, sweep, tol, chord_tol);
    if sweep >= TAU {
        let mut ends = vec![m0];
        if m0.distance(m1) > tol {
            ends.push(m1);
        }
        return ends.into_iter().filter(|m| m.x > tol).map(ring).collect();
    }
    // Ruling at start (m0 → m1), the arc at m1, the ruling back at the end, the arc at m0 back.
    let (mut a1, mut a0) = (ring(m1).points, ring(m0).points);
    a0.reverse();
    let mut pts: Vec<DVec3> = Vec::new();
    let push = |pts: &mut Vec<DVec3>, p: DVec3| {
        if pts.last().is_none_or(|q| q.distance(p) > tol) {
            pts.push(p);
        }
    };
    for p in a1.drain(..).chain(a0.drain(..)) {
        push(&mut pts, p);
    }
    if pts.len() > 1 && pts[0].distance(pts[pts.len() - 1]) <= tol {
        pts.pop();
    }
    vec![Polyline3 {
        points: pts,
        closed: true,
    }]
}

/// A surface of revolution lying wholly on a sphere centred on its axis: the surface itself is
/// the common region; its boundary (the end circles, and the two profile edges of a partial
/// revolution), from the revolution's own parameterisation.
fn revolve_on_sphere(r: &Revolve, s: &Sphere, tol: f64, chord_tol: f64) -> Option<Vec<Polyline3>> {
    let ax = Axis::new(r.axis_point, r.axis_dir);
    if ax.meridian(s.center).x > tol {
        return None;
    }
    let on = |p: DVec3| (p.distance(s.center) - s.radius).abs() <= tol;
    // A quick look before sampling the profile to the chord tolerance.
    if !(0..=16).all(|i| on(r.profile.eval(i as f64 / 16.0))) {
        return None;
    }
    let (ts, pts) = super::sampled::sample_curve(r.profile.as_ref(), chord_tol, 16);
    let mids = ts.windows(2).map(|w| r.profile.eval(0.5 * (w[0] + w[1])));
    if !pts.iter().copied().chain(mids).all(on) {
        return None;
    }
    let (e0, e1) = (pts[0], pts[pts.len() - 1]);
    let (m0, m1) = (ax.meridian(e0), ax.meridian(e1));
    if r.angle >= TAU {
        let mut out = Vec::new();
        for (m, e) in [(m0, e0), (m1, e1)] {
            if m.x > tol && !(out.len() == 1 && e0.distance(e1) <= tol) {
                out.push(circle(&ax, m, ax.angle(e), TAU, tol, chord_tol));
            }
        }
        return Some(out);
    }
    // Partial: profile at v = 0, end arc, profile at v = 1 backwards, start arc backwards.
    let rho = m0.x.max(m1.x).max(tol);
    let step = (2.0 * (1.0 - chord_tol / rho).clamp(-1.0, 1.0).acos()).clamp(1e-5, TAU / 16.0);
    let n = (r.angle / step).ceil().max(1.0) as usize;
    let rot = |p: DVec3, v: f64| {
        r.axis_point + glam::DQuat::from_axis_angle(r.axis_dir, v * r.angle) * (p - r.axis_point)
    };
    let arc = |p: DVec3| (0..=n).map(move |i| rot(p, i as f64 / n as f64));
    let mut loop_pts: Vec<DVec3> = Vec::new();
    let seq = pts
        .iter()
        .copied()
        .chain(arc(e1))
        .chain(pts.iter().rev().map(|p| rot(*p, 1.0)))
        .chain(arc(e0).collect::<Vec<_>>().into_iter().rev());
    for p in seq {
        if loop_pts.last().is_none_or(|q| q.distance(p) > tol) {
            loop_pts.push(p);
        }
    }
    if loop_pts.len() > 1 && loop_pts[0].distance(loop_pts[loop_pts.len() - 1]) <= tol {
        loop_pts.pop();
    }
    Some(vec![Polyline3 {
        points: loop_pts,
        closed: true,
    }])
}
