//! FILLET where an arc or circle takes part (line and arc, two arcs, a circle with a line,
//! arc or circle: the circle stays whole). The fillet circle's centre lies
//! on an offset of each curve (a parallel line, a concentric circle), so the candidates are
//! the intersections of those offsets; a candidate is kept only when the fillet arc joins
//! both kept parts smoothly (its direction at each tangent point continues the curve), and
//! of those the one whose tangent points lie nearest the pick points wins, as in AutoCAD.
//! Radius 0 trims or extends both curves to their intersection nearest the picks.

use glam::{DVec2, DVec3};

use super::cmd_err;
use crate::lang::error::Exn;
use crate::lang::Interp;
use crate::output::{Drawing, Entity, EntityKind};

const TAU: f64 = std::f64::consts::TAU;

#[derive(Clone, Copy)]
enum Curve {
    Line {
        a: DVec2,
        b: DVec2,
    },
    Arc {
        c: DVec2,
        r: f64,
        s: f64,
        e: f64,
    },
    /// A circle stays whole: AutoCAD adds the fillet arc and trims only the other object.
    Circle {
        c: DVec2,
        r: f64,
    },
}

/// An offset of a curve: a line through `p` along `u`, or a circle.
#[derive(Clone, Copy)]
enum Locus {
    Line { p: DVec2, u: DVec2 },
    Circle { c: DVec2, r: f64 },
}

fn sweep(from: f64, to: f64) -> f64 {
    (to - from).rem_euclid(TAU)
}

fn perp(v: DVec2) -> DVec2 {
    DVec2::new(-v.y, v.x)
}

impl Curve {
    fn of(e: &Entity) -> Result<Curve, Exn> {
        match e.kind {
            EntityKind::Line { p0, p1 } => Ok(Curve::Line {
                a: p0.truncate(),
                b: p1.truncate(),
            }),
            EntityKind::Arc {
                center,
                radius,
                start,
                end,
                normal,
            } if (normal - DVec3::Z).length() < 1e-12 => Ok(Curve::Arc {
                c: center.truncate(),
                r: radius,
                s: start,
                e: end,
            }),
            EntityKind::Circle {
                center,
                radius,
                normal,
            } if (normal - DVec3::Z).length() < 1e-12 => Ok(Curve::Circle {
                c: center.truncate(),
                r: radius,
            }),
            ref k => Err(cmd_err(
                "FILLET",
                format!(
                    "lispcad fillets lines, arcs and circles in the XY plane, not a {}",
                    k.type_name()
                ),
            )),
        }
    }

    /// Where the pick falls when none was given: the middle of the curve.
    fn middle(&self) -> DVec2 {
        match *self {
            Curve::Line { a, b } => (a + b) / 2.0,
            Curve::Arc { c, r, s, e } => c + DVec2::from_angle(s + sweep(s, e) / 2.0) * r,
            Curve::Circle { c, r } => c + DVec2::X * r,
        }
    }

    fn centre(&self) -> Option<(DVec2, f64)> {
        match *self {
            Curve::Arc { c, r, .. } | Curve::Circle { c, r } => Some((c, r)),
            Curve::Line { .. } => None,
        }
    }

    fn loci(&self, d: f64) -> Vec<Locus> {
        match *self {
            Curve::Line { a, b } => {
                let u = (b - a).normalize();
                let n = perp(u);
                vec![
                    Locus::Line { p: a + n * d, u },
                    Locus::Line { p: a - n * d, u },
                ]
            }
            Curve::Arc { c, r, .. } | Curve::Circle { c, r } => {
                let mut v = vec![Locus::Circle { c, r: r + d }];
                if d > 0.0 && r - d > 1e-12 {
                    v.push(Locus::Circle { c, r: r - d });
                }
                v
            }
        }
    }

    /// The point of the curve (extended) nearest `p`.
    fn foot(&self, p: DVec2) -> Option<DVec2> {
        match *self {
            Curve::Line { a, b } => {
                let u = (b - a).normalize();
                Some(a + u * (p - a).dot(u))
            }
            Curve::Arc { c, r, .. } | Curve::Circle { c, r } => {
                (p - c).try_normalize().map(|v| c + v * r)
            }
        }
    }

    /// The curve trimmed or extended so that it ends at `t` and keeps the part the pick
    /// `q` is on, and the unit direction from `t` into the kept part (zero for a circle,
    /// which is kept whole and fits either way).
    fn cut(&self, t: DVec2, q: DVec2) -> Option<(Curve, DVec2)> {
        match *self {
            Curve::Circle { .. } => Some((*self, DVec2::ZERO)),
            Curve::Line { a, b } => {
                let u = (b - a).normalize();
                let side = (q - t).dot(u);
                // With the pick at the cut, keep the longer part.
                let k = if side.abs() > 1e-12 {
                    u * side.signum()
                } else if (a - t).length() >= (b - t).length() {
                    (a - t).normalize()
                } else {
                    (b - t).normalize()
                };
                let c = if (a - t).dot(k) >= (b - t).dot(k) {
                    Curve::Line { a, b: t }
                } else {
                    Curve::Line { a: t, b }
                };
                let len = match c {
                    Curve::Line { a, b } => (b - a).length(),
                    _ => 0.0,
                };
                (len > 1e-12 && k.is_finite()).then_some((c, k))
            }
            Curve::Arc { c, r, s, e } => {
                let phi = (t - c).to_angle().rem_euclid(TAU);
                let tangent = perp((t - c) / r);
                let keep_start = if sweep(s, phi) <= sweep(s, e) {
                    sweep(s, (q - c).to_angle()) <= sweep(s, phi)
                } else {
                    // The tangent point is past an end: that end moves to it.
                    sweep(e, phi) <= sweep(phi, s)
                };
                let (arc, k) = if keep_start {
                    (Curve::Arc { c, r, s, e: phi }, -tangent)
                } else {
                    (Curve::Arc { c, r, s: phi, e }, tangent)
                };
                let span = match arc {
                    Curve::Arc { s, e, .. } => sweep(s, e),
                    _ => 0.0,
                };
                (span > 1e-12).then_some((arc, k))
            }
        }
    }
}

fn meet(l1: Locus, l2: Locus) -> Vec<DVec2> {
    match (l1, l2) {
        (Locus::Line { p: p1, u: u1 }, Locus::Line { p: p2, u: u2 }) => {
            let den = u1.perp_dot(u2);
            if den.abs() < 1e-12 {
                return vec![];
            }
            vec![p1 + u1 * ((p2 - p1).perp_dot(u2) / den)]
        }
        (Locus::Line { p, u }, Locus::Circle { c, r })
        | (Locus::Circle { c, r }, Locus::Line { p, u }) => {
            let f = p + u * (c - p).dot(u);
            let h2 = r * r - (f - c).length_squared();
            if h2 < -1e-12 {
                return vec![];
            }
            let h = h2.max(0.0).sqrt();
            vec![f + u * h, f - u * h]
        }
        (Locus::Circle { c: c1, r: r1 }, Locus::Circle { c: c2, r: r2 }) => {
            let d = (c2 - c1).length();
            if d < 1e-12 {
                return vec![];
            }
            let x = (d * d + r1 * r1 - r2 * r2) / (2.0 * d);
            let h2 = r1 * r1 - x * x;
            if h2 < -1e-12 {
                return vec![];
            }
            let u = (c2 - c1) / d;
            let f = c1 + u * x;
            let h = h2.max(0.0).sqrt();
            vec![f + perp(u) * h, f - perp(u) * h]
        }
    }
}

struct Solution {
    c1: Curve,
    c2: Curve,
    /// Centre, start and end angle of the fillet arc (none for radius 0).
    arc: Option<(DVec2, f64, f64)>,
}

/// The fillet of two curves with picks `q1`, `q2` and radius `r`, if one exists.
fn solve(k1: Curve, q1: DVec2, k2: Curve, q2: DVec2, r: f64) -> Option<Solution> {
    let mut best: Option<(f64, Solution)> = None;
    for l1 in k1.loci(r) {
        for l2 in k2.loci(r) {
            for centre in meet(l1, l2) {
                let (Some(t1), Some(t2)) = (k1.foot(centre), k2.foot(centre)) else {
                    continue;
                };
                let (Some((c1, d1)), Some((c2, d2))) = (k1.cut(t1, q1), k2.cut(t2, q2)) else {
                    continue;
                };
                let arc = if r > 0.0 {
                    let (a1, a2) = (t1 - centre, t2 - centre);
                    let (mut s1, mut s2) = (perp(a1).dot(d1), perp(a2).dot(d2));
                    // A circle takes the orientation the other object needs; between two
                    // circles the fillet is the arc of at most half a turn.
                    match (d1 == DVec2::ZERO, d2 == DVec2::ZERO) {
                        (true, true) => {
                            s1 = if sweep(a1.to_angle(), a2.to_angle()) <= TAU / 2.0 {
                                -1.0
                            } else {
                                1.0
                            };
                            s2 = -s1;
                        }
                        (true, false) => s1 = -s2,
                        (false, true) => s2 = -s1,
                        (false, false) => {}
                    }
                    // Counter-clockwise from t1 to t2, the arc leaves t1 against the first
                    // curve's kept direction and reaches t2 along the second's.
                    if s1 < 0.0 && s2 > 0.0 {
                        Some((centre, a1.to_angle(), a2.to_angle()))
                    } else if s1 > 0.0 && s2 < 0.0 {
                        Some((centre, a2.to_angle(), a1.to_angle()))
                    } else {
                        continue;
                    }
                } else {
                    None
                };
                let cost = (t1 - q1).length() + (t2 - q2).length();
                if best.as_ref().is_none_or(|(b, _)| cost < *b - 1e-12) {
                    best = Some((cost, Solution { c1, c2, arc }));
                }
            }
        }
    }
    best.map(|(_, s)| s)
}

/// atan2 rounding leaves 2e-16 where the angle is 0.
fn norm(a: f64) -> f64 {
    let a = a.rem_euclid(TAU);
    if a < 1e-12 || TAU - a < 1e-12 {
        0.0
    } else {
        a
    }
}

fn rebuilt(e: &Entity, c: Curve) -> Entity {
    let kind = match (c, &e.kind) {
        (Curve::Line { a, b }, EntityKind::Line { p0, p1 }) => EntityKind::Line {
            p0: a.extend(p0.z),
            p1: b.extend(p1.z),
        },
        (Curve::Arc { s, e: end, .. }, EntityKind::Arc { .. }) => {
            let mut k = e.kind.clone();
            if let EntityKind::Arc { start, end: e1, .. } = &mut k {
                *start = norm(s);
                *e1 = norm(end);
            }
            k
        }
        _ => e.kind.clone(),
    };
    Entity { kind, ..e.clone() }
}

/// FILLET of two objects of which at least one is an arc.
pub(super) fn fillet_curves(
    it: &mut Interp,
    (h1, q1): (u64, Option<DVec3>),
    (h2, q2): (u64, Option<DVec3>),
    r: f64,
) -> Result<(), Exn> {
    if h1 == h2 {
        return Err(cmd_err("FILLET", "the two objects are the same object"));
    }
    let d = it.ext::<Drawing>();
    let get = |h| {
        d.get(h)
            .cloned()
            .ok_or_else(|| cmd_err("FILLET", "the object is deleted"))
    };
    let (e1, e2) = (get(h1)?, get(h2)?);
    let (k1, k2) = (Curve::of(&e1)?, Curve::of(&e2)?);
    if let (Some((c1, _)), Some((c2, _))) = (k1.centre(), k2.centre()) {
        if (c1 - c2).length() < 1e-12 {
            // No circle of one radius touches two concentric ones at a single place.
            return Err(cmd_err(
                "FILLET",
                "the objects are concentric: lispcad does not fillet concentric arcs or circles",
            ));
        }
    }
    let pick = |q: Option<DVec3>, k: &Curve| q.map_or_else(|| k.middle(), |p| p.truncate());
    let (mut p1, mut p2) = (pick(q1, &k1), pick(q2, &k2));
    // Without a pick, a circle is taken where it faces the other object.
    if let (None, Curve::Circle { .. }) = (q1, k1) {
        p1 = k1.foot(p2).unwrap_or(p1);
    }
    if let (None, Curve::Circle { .. }) = (q2, k2) {
        p2 = k2.foot(p1).unwrap_or(p2);
    }
    let sol = solve(k1, p1, k2, p2, r).ok_or_else(|| {
        cmd_err(
            "FILLET",
            if r > 0.0 {
                format!("no fillet of radius {r} joins these objects")
            } else {
                "the objects do not meet, even extended".to_string()
            },
        )
    })?;
    let z = match e1.kind {
        EntityKind::Line { p0, .. } => p0.z,
        EntityKind::Arc { center, .. } | EntityKind::Circle { center, .. } => center.z,
        _ => 0.0,
    };
    let (c1, c2) = (rebuilt(&e1, sol.c1), rebuilt(&e2, sol.c2));
    let arc = sol.arc.map(|(c, start, end)| (c.extend(z), start, end));
    replace_and_add_arc(d, (h1, e1, c1), (h2, e2, c2), arc, r)
}

/// Puts the trimmed pair in place of the picked objects and adds the fillet arc (center,
/// start, end; CCW about +Z), on their layer when they share one, else on the current layer.
pub(super) fn replace_and_add_arc(
    d: &mut Drawing,
    (h1, e1, t1): (u64, Entity, Entity),
    (h2, e2, t2): (u64, Entity, Entity),
    arc: Option<(DVec3, f64, f64)>,
    r: f64,
) -> Result<(), Exn> {
    let (layer, color) = if e1.layer == e2.layer {
        (e1.layer.clone(), e1.color)
    } else {
        (d.current_layer().to_string(), None)
    };
    d.replace(h1, t1).map_err(|x| cmd_err("FILLET", x))?;
    d.replace(h2, t2).map_err(|x| cmd_err("FILLET", x))?;
    if let Some((center, start, end)) = arc {
        let mut n = Entity::new(
            &layer,
            EntityKind::Arc {
                center,
                radius: r,
                start: norm(start),
                end: norm(end),
                normal: DVec3::Z,
            },
        );
        n.color = color;
        d.add(n).map_err(|x| cmd_err("FILLET", x))?;
    }
    Ok(())
}
