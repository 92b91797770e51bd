//! The drawing commands: LINE, CIRCLE, ARC, PLINE, SPLINE, POINT, each a small state machine
//! over AutoCAD's prompt sequence.
//!
//! PLINE arc segments follow AutoCAD's tangent continuity: an arc leaves its start vertex along
//! the direction the polyline arrived with, so with φ the signed angle from that tangent to
//! the chord, the included angle is 2φ, the bulge tan(φ/2), and the tangent at the arc's end is
//! the chord direction turned by φ.

use std::f64::consts::{PI, TAU};

use glam::{DVec2, DVec3};

use super::{add, angle2, cmd_err, unexpected, Input, Pending, Step};
use crate::geom::quadspline::QuadSpline;
use crate::lang::error::Exn;
use crate::lang::Interp;
use crate::output::{Drawing, EntityKind};

pub(crate) struct DrawCmd {
    name: &'static str,
    state: State,
}

enum State {
    Line {
        pts: Vec<DVec3>,
        segs: Vec<u64>,
    },
    Circle(CircleStep),
    Arc(ArcStep),
    Pline(Pline),
    Spline {
        pts: Vec<DVec3>,
    },
    /// The start and end tangent prompts after the fit points (Enter accepts each).
    SplineTangents(u8),
    Point,
}

enum CircleStep {
    Center,
    Radius(DVec3),
    Diameter(DVec3),
    TwoP(Vec<DVec3>),
    ThreeP(Vec<DVec3>),
}

#[derive(Clone, Copy, PartialEq)]
enum ArcExpect {
    First,
    AfterStart,
    Third,
    Center,
    StartAfterCenter,
    EndOrAngle,
    End,
    CenterOrOption,
    Angle,
    Radius,
}

struct ArcStep {
    expect: ArcExpect,
    start: Option<DVec3>,
    second: Option<DVec3>,
    center: Option<DVec3>,
    end: Option<DVec3>,
}

#[derive(Clone, Copy, PartialEq)]
enum PlExpect {
    Vertex,
    /// After "S" in arc mode: the arc's second point, then its end.
    Second,
    SecondEnd(DVec3),
    Length,
    Direction,
}

struct Pline {
    pts: Vec<DVec3>,
    bulges: Vec<f64>,
    /// The direction the polyline has at each vertex (for tangent arcs and undo).
    tangents: Vec<DVec2>,
    arc_mode: bool,
    expect: PlExpect,
    /// Width values still to be skipped (widths are accepted and ignored).
    skip: u8,
}

fn is_word(input: &Input, words: &[&str]) -> bool {
    input
        .keyword()
        .is_some_and(|k| words.iter().any(|w| *w == k))
}

impl DrawCmd {
    pub(crate) fn new(name: &'static str) -> DrawCmd {
        let state = match name {
            "LINE" => State::Line {
                pts: Vec::new(),
                segs: Vec::new(),
            },
            "CIRCLE" => State::Circle(CircleStep::Center),
            "ARC" => State::Arc(ArcStep {
                expect: ArcExpect::First,
                start: None,
                second: None,
                center: None,
                end: None,
            }),
            "PLINE" => State::Pline(Pline {
                pts: Vec::new(),
                bulges: Vec::new(),
                tangents: Vec::new(),
                arc_mode: false,
                expect: PlExpect::Vertex,
                skip: 0,
            }),
            "SPLINE" => State::Spline { pts: Vec::new() },
            _ => State::Point,
        };
        DrawCmd { name, state }
    }

    fn more(self) -> Result<Step, Exn> {
        Ok(Step::More(Pending::Draw(self)))
    }

    pub(crate) fn feed(mut self, it: &mut Interp, input: &Input) -> Result<Step, Exn> {
        let name = self.name;
        match &mut self.state {
            State::Point => match input {
                Input::Point(p) => {
                    add(it, name, EntityKind::Point { p: *p })?;
                    Ok(Step::Done)
                }
                _ => Err(unexpected(name, "a point", input)),
            },
            State::Line { pts, segs } => {
                match input {
                    Input::Point(p) => {
                        if let Some(prev) = pts.last() {
                            let h = add(it, name, EntityKind::Line { p0: *prev, p1: *p })?;
                            segs.push(h);
                        }
                        pts.push(*p);
                    }
                    Input::Enter => return Ok(Step::Done),
                    _ if is_word(input, &["C", "CLOSE"]) && segs.len() >= 2 => {
                        let (p0, p1) = (pts[pts.len() - 1], pts[0]);
                        add(it, name, EntityKind::Line { p0, p1 })?;
                        return Ok(Step::Done);
                    }
                    _ if is_word(input, &["U", "UNDO"]) => {
                        if let Some(h) = segs.pop() {
                            it.ext::<Drawing>().delete(h);
                        }
                        pts.pop();
                    }
                    _ => {
                        return Err(unexpected(
                            name,
                            "a point, \"C\" (close, after two segments), \"U\" or \"\"",
                            input,
                        ))
                    }
                }
                self.more()
            }
            State::Circle(step) => match circle(it, step, input)? {
                true => Ok(Step::Done),
                false => self.more(),
            },
            State::Arc(step) => match arc(it, step, input)? {
                true => Ok(Step::Done),
                false => self.more(),
            },
            State::Pline(pl) => match pline(it, pl, input)? {
                true => Ok(Step::Done),
                false => self.more(),
            },
            State::Spline { pts } => {
                match input {
                    Input::Point(p) => pts.push(*p),
                    Input::Enter => {
                        if pts.len() < 2 {
                            return Ok(Step::Done);
                        }
                        make_spline(it, pts, false)?;
                        self.state = State::SplineTangents(2);
                    }
                    _ if is_word(input, &["C", "CLOSE"]) => {
                        if pts.len() < 3 {
                            return Err(cmd_err(name, "closing needs at least 3 fit points"));
                        }
                        make_spline(it, pts, true)?;
                        self.state = State::SplineTangents(1);
                    }
                    _ if is_word(input, &["U", "UNDO"]) => {
                        pts.pop();
                    }
                    _ => {
                        return Err(unexpected(
                            name,
                            "a fit point, \"C\" (close), \"U\" or \"\" (the other SPLINE options are not supported)",
                            input,
                        ))
                    }
                }
                self.more()
            }
            State::SplineTangents(left) => match input {
                Input::Word(_) | Input::Select(_) => Ok(Step::DoneNotConsumed),
                _ => {
                    *left -= 1;
                    if *left == 0 {
                        Ok(Step::Done)
                    } else {
                        self.more()
                    }
                }
            },
        }
    }

    /// `(command)` in the middle of the command: a PLINE keeps what was drawn (as on Esc);
    /// everything else is abandoned.
    pub(crate) fn cancel(self, it: &mut Interp) -> Result<(), Exn> {
        if let State::Pline(pl) = self.state {
            if pl.pts.len() >= 2 {
                finish_pline(it, pl, false)?;
            }
        }
        Ok(())
    }
}

fn radius_input(input: &Input, from: DVec3) -> Option<f64> {
    match input {
        Input::Number(r) => Some(*r),
        Input::Point(p) => Some(p.truncate().distance(from.truncate())),
        _ => None,
    }
}

fn make_circle(it: &mut Interp, center: DVec3, radius: f64) -> Result<(), Exn> {
    if radius.is_nan() || radius <= 0.0 {
        return Err(cmd_err(
            "CIRCLE",
            format!("radius must be positive, got {radius}"),
        ));
    }
    add(
        it,
        "CIRCLE",
        EntityKind::Circle {
            center,
            radius,
            normal: DVec3::Z,
        },
    )?;
    Ok(())
}

/// The circle through three points in the XY plane: (centre, radius), or None if collinear.
fn circumcircle(a: DVec2, b: DVec2, c: DVec2) -> Option<(DVec2, f64)> {
    let (ab, ac) = (b - a, c - a);
    let d = 2.0 * ab.perp_dot(ac);
    if d.abs() <= 1e-12 * ab.length_squared().max(ac.length_squared()) {
        return None;
    }
    let o = DVec2::new(
        ac.y * ab.length_squared() - ab.y * ac.length_squared(),
        ab.x * ac.length_squared() - ac.x * ab.length_squared(),
    ) / d;
    Some((a + o, o.length()))
}

fn circle(it: &mut Interp, step: &mut CircleStep, input: &Input) -> Result<bool, Exn> {
    match step {
        CircleStep::Center => match input {
            Input::Point(p) => *step = CircleStep::Radius(*p),
            _ if is_word(input, &["2P"]) => *step = CircleStep::TwoP(Vec::new()),
            _ if is_word(input, &["3P"]) => *step = CircleStep::ThreeP(Vec::new()),
            _ => {
                return Err(unexpected(
                    "CIRCLE",
                    "a center point, \"2P\" or \"3P\" (TTR is not supported)",
                    input,
                ))
            }
        },
        CircleStep::Radius(c) => {
            if is_word(input, &["D", "DIAMETER"]) {
                *step = CircleStep::Diameter(*c);
                return Ok(false);
            }
            let r = radius_input(input, *c)
                .ok_or_else(|| unexpected("CIRCLE", "a radius, a point or \"D\"", input))?;
            make_circle(it, *c, r)?;
            return Ok(true);
        }
        CircleStep::Diameter(c) => {
            let d = match input {
                Input::Number(d) => *d,
                Input::Point(p) => 2.0 * p.truncate().distance(c.truncate()),
                _ => return Err(unexpected("CIRCLE", "a diameter", input)),
            };
            make_circle(it, *c, d / 2.0)?;
            return Ok(true);
        }
        CircleStep::TwoP(pts) | CircleStep::ThreeP(pts) => {
            let Input::Point(p) = input else {
                return Err(unexpected("CIRCLE", "a point on the circle", input));
            };
            pts.push(*p);
            let three = matches!(step, CircleStep::ThreeP(_));
            let pts = match step {
                CircleStep::TwoP(p) | CircleStep::ThreeP(p) => p.clone(),
                _ => unreachable!(),
            };
            if !three && pts.len() == 2 {
                let c = (pts[0] + pts[1]) / 2.0;
                make_circle(it, c, pts[0].truncate().distance(pts[1].truncate()) / 2.0)?;
                return Ok(true);
            }
            if three && pts.len() == 3 {
                let (c, r) = circumcircle(pts[0].truncate(), pts[1].truncate(), pts[2].truncate())
                    .ok_or_else(|| cmd_err("CIRCLE", "the three points are collinear"))?;
                make_circle(it, c.extend(pts[0].z), r)?;
                return Ok(true);
            }
        }
    }
    Ok(false)
}

/// An angle in [0, 2π), with a rounding hair below 2π taken as 0.
fn norm_angle(a: f64) -> f64 {
    let a = a.rem_euclid(TAU);
    if TAU - a < 1e-12 {
        0.0
    } else {
        a
    }
}

/// An ARC entity CCW from angle a0 to a1 about `center` (in the XY plane at center.z).
fn make_arc(it: &mut Interp, center: DVec3, radius: f64, a0: f64, a1: f64) -> Result<(), Exn> {
    if radius.is_nan() || radius <= 1e-300 {
        return Err(cmd_err(
            "ARC",
            "the arc has no radius (start point on the center)",
        ));
    }
    add(
        it,
        "ARC",
        EntityKind::Arc {
            center,
            radius,
            start: norm_angle(a0),
            end: norm_angle(a1),
            normal: DVec3::Z,
        },
    )?;
    Ok(())
}

fn arc_center_start_end(it: &mut Interp, c: DVec3, s: DVec3, e: DVec3) -> Result<(), Exn> {
    let c2 = c.truncate();
    let r = s.truncate().distance(c2);
    make_arc(
        it,
        c.truncate().extend(s.z),
        r,
        angle2(s.truncate() - c2),
        angle2(e.truncate() - c2),
    )
}

/// The arc from s by the included angle `deg` (degrees, CCW positive) about c.
fn arc_center_start_angle(it: &mut Interp, c: DVec3, s: DVec3, deg: f64) -> Result<(), Exn> {
    let c2 = c.truncate();
    let a0 = angle2(s.truncate() - c2);
    let a1 = a0 + deg.to_radians();
    let (lo, hi) = if deg >= 0.0 { (a0, a1) } else { (a1, a0) };
    make_arc(it, c2.extend(s.z), s.truncate().distance(c2), lo, hi)
}

/// The arc from s to e with centre `c2` on the left of the chord (CCW, sweep below π when
/// `minor`).
fn arc_start_end_center(it: &mut Interp, s: DVec3, e: DVec3, c2: DVec2) -> Result<(), Exn> {
    arc_center_start_end(it, c2.extend(s.z), s, e)
}

fn arc(it: &mut Interp, st: &mut ArcStep, input: &Input) -> Result<bool, Exn> {
    use ArcExpect::*;
    let point = match input {
        Input::Point(p) => Some(*p),
        _ => None,
    };
    let kw = input.keyword();
    let kw = kw.as_deref();
    match (st.expect, point, kw) {
        (First, Some(p), _) => {
            st.start = Some(p);
            st.expect = AfterStart;
        }
        (First, None, Some("C" | "CE" | "CENTER")) => st.expect = Center,
        (AfterStart, Some(p), _) => {
            st.second = Some(p);
            st.expect = Third;
        }
        (AfterStart, None, Some("C" | "CE" | "CENTER")) => st.expect = Center,
        (AfterStart, None, Some("E" | "EN" | "END")) => st.expect = End,
        (Third, Some(p3), _) => {
            let (p1, p2) = (st.start.unwrap_or_default(), st.second.unwrap_or_default());
            let (c, r) = circumcircle(p1.truncate(), p2.truncate(), p3.truncate())
                .ok_or_else(|| cmd_err("ARC", "the three points are collinear"))?;
            let (a1, a3) = (angle2(p1.truncate() - c), angle2(p3.truncate() - c));
            // Counter-clockwise p1 → p2 → p3 keeps the order; clockwise swaps the ends.
            let ccw = (p2 - p1).truncate().perp_dot((p3 - p2).truncate()) > 0.0;
            let (lo, hi) = if ccw { (a1, a3) } else { (a3, a1) };
            make_arc(it, c.extend(p1.z), r, lo, hi)?;
            return Ok(true);
        }
        (Center, Some(p), _) => {
            st.center = Some(p);
            st.expect = if st.start.is_some() {
                EndOrAngle
            } else {
                StartAfterCenter
            };
        }
        (StartAfterCenter, Some(p), _) => {
            st.start = Some(p);
            st.expect = EndOrAngle;
        }
        (EndOrAngle, Some(e), _) => {
            let (c, s) = (st.center.unwrap_or_default(), st.start.unwrap_or_default());
            arc_center_start_end(it, c, s, e)?;
            return Ok(true);
        }
        (EndOrAngle | CenterOrOption, None, Some("A" | "ANGLE")) => st.expect = Angle,
        (End, Some(e), _) => {
            st.end = Some(e);
            st.expect = CenterOrOption;
        }
        (CenterOrOption, Some(c), _) => {
            let (s, e) = (st.start.unwrap_or_default(), st.end.unwrap_or_default());
            arc_center_start_end(it, c, s, e)?;
            return Ok(true);
        }
        (CenterOrOption, None, Some("R" | "RADIUS")) => st.expect = Radius,
        (Angle, _, _) => {
            let Input::Number(deg) = input else {
                return Err(unexpected("ARC", "an included angle in degrees", input));
            };
            let s = st.start.unwrap_or_default();
            if let Some(c) = st.center {
                arc_center_start_angle(it, c, s, *deg)?;
            } else {
                let e = st.end.unwrap_or_default();
                let (a, b) = (s.truncate(), e.truncate());
                let Some((c, _, _, _)) =
                    crate::output::drawing::bulge_arc(a, b, (deg.to_radians() / 4.0).tan())
                else {
                    return Err(cmd_err("ARC", "start and end points coincide"));
                };
                arc_center_start_angle(it, c.extend(s.z), s, *deg)?;
            }
            return Ok(true);
        }
        (Radius, _, _) => {
            let Input::Number(r) = input else {
                return Err(unexpected("ARC", "a radius", input));
            };
            let (s, e) = (st.start.unwrap_or_default(), st.end.unwrap_or_default());
            let (a, b) = (s.truncate(), e.truncate());
            let half = a.distance(b) / 2.0;
            if half <= 0.0 || r.abs() < half {
                return Err(cmd_err(
                    "ARC",
                    format!("radius {r} is too small for the chord (at least {half})"),
                ));
            }
            // A positive radius gives the minor arc, a negative one the major arc (AutoCAD).
            let left = (b - a).perp().normalize();
            let h = (r * r - half * half).max(0.0).sqrt();
            let c = (a + b) / 2.0 + left * if *r > 0.0 { h } else { -h };
            arc_start_end_center(it, s, e, c)?;
            return Ok(true);
        }
        _ => {
            let want = match st.expect {
                First => "a start point or \"C\"",
                AfterStart => "a second point, \"C\" or \"E\"",
                Third | Center | StartAfterCenter => "a point",
                EndOrAngle => "an end point or \"A\"",
                End => "an end point",
                CenterOrOption => "a center point, \"A\" or \"R\"",
                Angle | Radius => "a number",
            };
            return Err(unexpected("ARC", want, input));
        }
    }
    Ok(false)
}

/// The bulge of the arc leaving `a` along `tangent` and ending at `b`, and the tangent at `b`;
/// None when `b` lies straight behind `a` (no finite arc is tangent there).
fn tangent_arc(a: DVec2, b: DVec2, tangent: DVec2) -> Option<(f64, DVec2)> {
    let chord = b - a;
    let phi = tangent.perp_dot(chord).atan2(tangent.dot(chord));
    if PI - phi.abs() < 1e-9 {
        return None;
    }
    let end = DVec2::from_angle(angle2(chord) + phi);
    Some(((phi / 2.0).tan(), end))
}

fn behind() -> Exn {
    cmd_err(
        "PLINE",
        "the arc end point lies straight behind the tangent direction; no tangent arc reaches it",
    )
}

/// The bulge of the arc a → s → b and the tangent at b.
fn three_point_arc(a: DVec2, s: DVec2, b: DVec2) -> Option<(f64, DVec2)> {
    let (c, _) = circumcircle(a, s, b)?;
    let sweep_dir = if (s - a).perp_dot(b - s) > 0.0 {
        1.0
    } else {
        -1.0
    };
    let (a0, a1) = (angle2(a - c), angle2(b - c));
    let mut theta = (a1 - a0) * sweep_dir;
    theta = theta.rem_euclid(TAU) * sweep_dir;
    let chord = b - a;
    Some((
        (theta / 4.0).tan(),
        DVec2::from_angle(angle2(chord) + theta / 2.0),
    ))
}

fn push_vertex(pl: &mut Pline, p: DVec3, bulge: f64, tangent: DVec2) {
    if let Some(b) = pl.bulges.last_mut() {
        *b = bulge;
    }
    pl.pts.push(p);
    pl.bulges.push(0.0);
    pl.tangents.push(tangent);
}

fn pline(it: &mut Interp, pl: &mut Pline, input: &Input) -> Result<bool, Exn> {
    if pl.skip > 0 {
        pl.skip -= 1;
        return Ok(false);
    }
    let last = pl.pts.last().copied();
    let tangent = pl.tangents.last().copied().unwrap_or(DVec2::X);
    match (pl.expect, input) {
        (_, Input::Point(p)) if last.is_none() => {
            pl.pts.push(*p);
            pl.bulges.push(0.0);
            pl.tangents.push(DVec2::X);
            return Ok(false);
        }
        (_, _) if last.is_none() => return Err(unexpected("PLINE", "a start point", input)),
        (PlExpect::Vertex, Input::Point(p)) => {
            let (a, b) = (last.unwrap_or_default().truncate(), p.truncate());
            if a.distance(b) == 0.0 {
                return Ok(false);
            }
            if pl.arc_mode {
                let (bulge, t) = tangent_arc(a, b, tangent).ok_or_else(behind)?;
                push_vertex(pl, *p, bulge, t);
            } else {
                push_vertex(pl, *p, 0.0, (b - a).normalize());
            }
        }
        (PlExpect::Second, Input::Point(p)) => pl.expect = PlExpect::SecondEnd(*p),
        (PlExpect::SecondEnd(s), Input::Point(p)) => {
            let a = last.unwrap_or_default().truncate();
            let (bulge, t) = three_point_arc(a, s.truncate(), p.truncate())
                .ok_or_else(|| cmd_err("PLINE", "the three arc points are collinear"))?;
            push_vertex(pl, *p, bulge, t);
            pl.expect = PlExpect::Vertex;
        }
        (PlExpect::Length, Input::Number(d)) => {
            let p = last.unwrap_or_default() + (tangent * *d).extend(0.0);
            push_vertex(pl, p, 0.0, tangent);
            pl.expect = PlExpect::Vertex;
        }
        (PlExpect::Direction, Input::Point(p)) => {
            let d = (p.truncate() - last.unwrap_or_default().truncate()).normalize_or_zero();
            if d == DVec2::ZERO {
                return Err(cmd_err("PLINE", "the direction point is the last vertex"));
            }
            if let Some(t) = pl.tangents.last_mut() {
                *t = d;
            }
            pl.expect = PlExpect::Vertex;
        }
        (PlExpect::Direction, Input::Number(deg)) => {
            if let Some(t) = pl.tangents.last_mut() {
                *t = DVec2::from_angle(deg.to_radians());
            }
            pl.expect = PlExpect::Vertex;
        }
        (PlExpect::Vertex, Input::Enter) => {
            finish_pline(it, std::mem::replace(pl, empty_pline()), false)?;
            return Ok(true);
        }
        (PlExpect::Vertex, Input::Word(_)) => {
            let k = input.keyword().unwrap_or_default();
            match k.as_str() {
                "A" | "ARC" => pl.arc_mode = true,
                "L" | "LINE" if pl.arc_mode => pl.arc_mode = false,
                "L" | "LENGTH" => pl.expect = PlExpect::Length,
                "C" | "CL" | "CLOSE" => {
                    if pl.pts.len() < 2 {
                        return Err(cmd_err("PLINE", "closing needs at least two vertices"));
                    }
                    if pl.arc_mode {
                        let a = last.unwrap_or_default().truncate();
                        let (bulge, _) =
                            tangent_arc(a, pl.pts[0].truncate(), tangent).ok_or_else(behind)?;
                        if let Some(b) = pl.bulges.last_mut() {
                            *b = bulge;
                        }
                    }
                    finish_pline(it, std::mem::replace(pl, empty_pline()), true)?;
                    return Ok(true);
                }
                "S" | "SECOND" if pl.arc_mode => pl.expect = PlExpect::Second,
                "D" | "DIRECTION" if pl.arc_mode => pl.expect = PlExpect::Direction,
                "W" | "WIDTH" | "H" | "HALFWIDTH" => pl.skip = 2,
                "U" | "UNDO" => {
                    if pl.pts.len() > 1 {
                        pl.pts.pop();
                        pl.bulges.pop();
                        pl.tangents.pop();
                        if let Some(b) = pl.bulges.last_mut() {
                            *b = 0.0;
                        }
                    }
                }
                _ => {
                    return Err(unexpected(
                        "PLINE",
                        "a point or one of A, L, C, S, D, W, H, U (CE, R and the arc angle option are not supported)",
                        input,
                    ))
                }
            }
        }
        _ => return Err(unexpected("PLINE", "a point", input)),
    }
    Ok(false)
}

fn empty_pline() -> Pline {
    Pline {
        pts: Vec::new(),
        bulges: Vec::new(),
        tangents: Vec::new(),
        arc_mode: false,
        expect: PlExpect::Vertex,
        skip: 0,
    }
}

fn finish_pline(it: &mut Interp, pl: Pline, closed: bool) -> Result<(), Exn> {
    if pl.pts.len() < 2 {
        return Ok(());
    }
    let mut bulges = pl.bulges;
    if !closed {
        if let Some(b) = bulges.last_mut() {
            *b = 0.0;
        }
    }
    let bulges = if bulges.iter().all(|b| *b == 0.0) {
        Vec::new()
    } else {
        bulges
    };
    add(
        it,
        "PLINE",
        EntityKind::LwPolyline {
            points: pl.pts.iter().map(|p| p.truncate()).collect(),
            bulges,
            closed,
            elevation: pl.pts[0].z,
            normal: DVec3::Z,
        },
    )?;
    Ok(())
}

fn make_spline(it: &mut Interp, pts: &[DVec3], closed: bool) -> Result<(), Exn> {
    let s = QuadSpline::interpolate(pts, closed).map_err(|e| cmd_err("SPLINE", e))?;
    add(
        it,
        "SPLINE",
        EntityKind::Spline {
            curve: s.to_bspline(),
            fit_points: s.points.clone(),
            closed,
        },
    )?;
    Ok(())
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::output::drawing::bulge_arc;
    use proptest::prelude::*;

    /// The unit tangent of a bulge arc at its start and end (direction of travel).
    fn arc_tangents(a: DVec2, b: DVec2, bulge: f64) -> (DVec2, DVec2) {
        let (_, _, a0, a1) = bulge_arc(a, b, bulge).expect("a proper arc");
        let s = if bulge > 0.0 { 1.0 } else { -1.0 };
        let t = |ang: f64| DVec2::new(-ang.sin(), ang.cos()) * s;
        (t(a0), t(a1))
    }

    proptest! {
        #![proptest_config(ProptestConfig::with_cases(256))]

        /// A PLINE arc leaves its vertex along the incoming tangent and reports its true end
        /// tangent, so consecutive arcs are tangent-continuous.
        #[test]
        fn tangent_arcs_are_tangent_continuous(
            ax in -50.0..50.0f64, ay in -50.0..50.0f64,
            len in 0.5..40.0f64, chord_turn in -3.1..3.1f64, t_ang in -3.2..3.2f64,
        ) {
            prop_assume!(chord_turn.abs() > 1e-3);
            let a = DVec2::new(ax, ay);
            let t = DVec2::from_angle(t_ang);
            let b = a + DVec2::from_angle(t_ang + chord_turn) * len;
            let (bulge, end_t) = tangent_arc(a, b, t).expect("not straight behind");
            let (t0, t1) = arc_tangents(a, b, bulge);
            prop_assert!((t0 - t).length() < 1e-9, "start tangent {t0} vs {t}");
            prop_assert!((t1 - end_t).length() < 1e-9, "end tangent {t1} vs {end_t}");
        }

        /// The "S" (second point) arc passes through its second point.
        #[test]
        fn three_point_arc_passes_through_the_second_point(
            cx in -20.0..20.0f64, cy in -20.0..20.0f64, r in 0.5..30.0f64,
            a0 in 0.0..TAU, d1 in 0.05..3.0f64, d2 in 0.05..3.0f64, ccw in any::<bool>(),
        ) {
            let s = if ccw { 1.0 } else { -1.0 };
            let c = DVec2::new(cx, cy);
            let at = |ang: f64| c + DVec2::from_angle(ang) * r;
            let (a, m, b) = (at(a0), at(a0 + s * d1), at(a0 + s * (d1 + d2)));
            let (bulge, _) = three_point_arc(a, m, b).expect("not collinear");
            let (cc, rr, _, _) = bulge_arc(a, b, bulge).expect("a proper arc");
            prop_assert!((cc - c).length() < 1e-6 * r.max(1.0), "centre {cc} vs {c}");
            prop_assert!((rr - r).abs() < 1e-6 * r.max(1.0));
            prop_assert!((4.0 * bulge.atan() - s * (d1 + d2)).abs() < 1e-9);
        }
    }

    #[test]
    fn point_strings_follow_the_command_line() {
        let last = DVec3::new(1.0, 2.0, 3.0);
        let p = |s: &str| super::super::parse_point_str(s, last);
        assert_eq!(p("4,5"), Some(DVec3::new(4.0, 5.0, 0.0)));
        assert_eq!(p(" 4 , 5 , 6 "), Some(DVec3::new(4.0, 5.0, 6.0)));
        assert_eq!(p("@1,1"), Some(DVec3::new(2.0, 3.0, 3.0)));
        assert_eq!(p("@"), Some(last));
        let q = p("@2<90").unwrap();
        assert!((q - DVec3::new(1.0, 4.0, 3.0)).length() < 1e-15);
        assert_eq!(p("abc"), None);
        assert_eq!(p("1,2,3,4"), None);
        assert_eq!(p("5"), None);
        assert_eq!(p("1,nan"), None);
    }
}
