//! CHPROP, CHANGE (its Properties option), EXPLODE (polylines into lines and arcs), FILLET
//! (two lines; arcs are in fillet.rs) and OFFSET (by a distance or through a point, on the side a point gives),
//! with AutoCAD's prompts in their order. CHPROP sets colour, layer, line type, line-type
//! scale, line weight and thickness; what lispcad does not model (transparency, material,
//! plot style) is a clear error naming it.

use glam::{DVec2, DVec3};

use super::{cmd_err, unexpected, Input, Pending, Step};
use crate::builtins::drawing::curve_entity;
use crate::builtins::vla::curve::entity_curve;
use crate::geom::frame::Ocs;
use crate::lang::error::Exn;
use crate::lang::{Interp, Value};
use crate::output::drawing::{bulge_arc, bulge_segments};
use crate::output::props::EntityProps;
use crate::output::{Drawing, Entity, EntityKind};

/// CHPROP / CHANGE: the objects, then property options until Enter.
pub(crate) struct ChpropCmd {
    name: &'static str,
    picked: Vec<u64>,
    state: ChState,
}

#[derive(PartialEq, Eq)]
enum ChState {
    Selecting,
    /// CHANGE asks for a change point or P (Properties) first.
    ChangeWhat,
    Option,
    Color,
    Layer,
    Ltype,
    Lweight,
    Thickness,
    Ltscale,
}

impl ChpropCmd {
    pub(crate) fn new(name: &'static str) -> ChpropCmd {
        ChpropCmd {
            name,
            picked: Vec::new(),
            state: ChState::Selecting,
        }
    }

    pub(crate) fn feed(mut self, it: &mut Interp, input: &Input, raw: &Value) -> Result<Step, Exn> {
        let name = self.name;
        let kw = input.keyword();
        self.state = match self.state {
            ChState::Selecting => match input {
                Input::Select(h) => {
                    self.picked.extend(h);
                    ChState::Selecting
                }
                Input::Enter if self.picked.is_empty() => {
                    return Err(cmd_err(name, "no objects selected"))
                }
                Input::Enter if name == "CHANGE" => ChState::ChangeWhat,
                Input::Enter => ChState::Option,
                _ => return Err(unexpected(name, "objects or \"\"", input)),
            },
            ChState::ChangeWhat => match kw.as_deref() {
                Some("P" | "PROPERTIES") => ChState::Option,
                _ => {
                    return Err(cmd_err(
                        name,
                        format!(
                            "only the Properties option (\"P\") is supported by lispcad, got {}",
                            input.describe()
                        ),
                    ))
                }
            },
            ChState::Option => match kw.as_deref() {
                _ if matches!(input, Input::Enter) => return Ok(Step::Done),
                Some("C" | "COLOR" | "COLOUR") => ChState::Color,
                Some("LA" | "LAYER") => ChState::Layer,
                Some("LT" | "LTYPE") => ChState::Ltype,
                Some("LW" | "LWEIGHT") => ChState::Lweight,
                Some("T" | "THICKNESS") => ChState::Thickness,
                Some("S" | "LTSCALE") => ChState::Ltscale,
                Some(o @ ("TR" | "TRANSPARENCY" | "M" | "MATERIAL" | "PL" | "PLOTSTYLE" | "E" | "ELEV")) => {
                    return Err(cmd_err(
                        name,
                        format!("the {o} property is not modelled by lispcad (Color, LAyer, LType, ltScale, LWeight and Thickness are)"),
                    ))
                }
                _ => return Err(unexpected(name, "C, LA, LT, S, LW, T or \"\"", input)),
            },
            ChState::Color => {
                let c = color_of(input, raw)
                    .ok_or_else(|| unexpected(name, "a colour (0..256, BYLAYER, BYBLOCK or a colour name)", input))?;
                let d = it.ext::<Drawing>();
                for &h in &self.picked {
                    if let Some(mut e) = d.get(h).cloned() {
                        e.color = c;
                        d.replace(h, e).map_err(|x| cmd_err(name, x))?;
                    }
                }
                ChState::Option
            }
            ChState::Layer => {
                let layer = input
                    .name(raw)
                    .map(|s| s.trim().to_string())
                    .filter(|s| !s.is_empty())
                    .ok_or_else(|| unexpected(name, "a layer name", input))?;
                let d = it.ext::<Drawing>();
                if d.layer(&layer).is_none() {
                    return Err(cmd_err(name, format!("cannot find layer \"{layer}\"")));
                }
                for &h in &self.picked {
                    if let Some(mut e) = d.get(h).cloned() {
                        e.layer = layer.clone();
                        d.replace(h, e).map_err(|x| cmd_err(name, x))?;
                    }
                }
                ChState::Option
            }
            ChState::Ltype => {
                let lt = input
                    .name(raw)
                    .map(|s| s.trim().to_string())
                    .filter(|s| !s.is_empty())
                    .ok_or_else(|| unexpected(name, "a line type name", input))?;
                let lt = linetype_of(it.ext::<Drawing>(), name, &lt)?;
                self.set(it, |p| p.linetype = Some(lt.clone()));
                ChState::Option
            }
            ChState::Lweight => {
                let w = lineweight_of(input)
                    .ok_or_else(|| unexpected(name, "a line weight in mm, BYLAYER, BYBLOCK or DEFAULT", input))?;
                self.set(it, |p| p.lineweight = Some(w));
                ChState::Option
            }
            ChState::Thickness => match input {
                Input::Number(t) if t.is_finite() => {
                    self.set(it, |p| p.thickness = Some(*t));
                    ChState::Option
                }
                _ => return Err(unexpected(name, "a thickness", input)),
            },
            ChState::Ltscale => match input {
                Input::Number(s) if s.is_finite() && *s > 0.0 => {
                    self.set(it, |p| p.ltscale = Some(*s));
                    ChState::Option
                }
                _ => return Err(unexpected(name, "a positive line-type scale", input)),
            },
        };
        Ok(Step::More(Pending::Chprop(self)))
    }
}

impl ChpropCmd {
    /// Changes the picked entities' line type, weight, thickness or scale.
    fn set(&self, it: &mut Interp, f: impl Fn(&mut EntityProps)) {
        let d = it.ext::<Drawing>();
        for &h in &self.picked {
            if d.get(h).is_some() {
                let mut p = d.props(h).cloned().unwrap_or_default();
                f(&mut p);
                d.set_props(h, p);
            }
        }
    }
}

/// A line type for CHPROP: BYLAYER, BYBLOCK, or a name the drawing's LTYPE table has (an
/// opened drawing's; a drawing made from scratch takes any valid name and writes it solid,
/// as it does for layers).
fn linetype_of(d: &Drawing, cmd: &str, name: &str) -> Result<String, Exn> {
    // "_ByLayer": the underscore asks for the English keyword.
    let word = name.strip_prefix('_').unwrap_or(name);
    for b in ["ByLayer", "ByBlock", "Continuous"] {
        if word.eq_ignore_ascii_case(b) {
            return Ok(b.to_string());
        }
    }
    if name
        .chars()
        .any(|c| "<>/\\\":;?*|,=`".contains(c) || c.is_control())
    {
        return Err(cmd_err(cmd, format!("invalid line type name \"{name}\"")));
    }
    match d.document() {
        Some(doc) => doc
            .table_records("LTYPE")
            .iter()
            .filter_map(|r| r.get(2))
            .find(|n| n.eq_ignore_ascii_case(name))
            .map(str::to_string)
            .ok_or_else(|| {
                cmd_err(
                    cmd,
                    format!("line type \"{name}\" is not loaded in the drawing"),
                )
            }),
        None => Ok(name.to_string()),
    }
}

/// A line weight (DXF 370): the nearest of AutoCAD's weights to a value in millimetres, or
/// BYLAYER (-1), BYBLOCK (-2), DEFAULT (-3).
fn lineweight_of(input: &Input) -> Option<i16> {
    const WEIGHTS: [i16; 24] = [
        0, 5, 9, 13, 15, 18, 20, 25, 30, 35, 40, 50, 53, 60, 70, 80, 90, 100, 106, 120, 140, 158,
        200, 211,
    ];
    match input {
        Input::Number(mm) if mm.is_finite() && *mm >= 0.0 && *mm <= 2.11 + 1e-9 => {
            let hundredths = mm * 100.0;
            WEIGHTS.iter().copied().min_by(|a, b| {
                (f64::from(*a) - hundredths)
                    .abs()
                    .total_cmp(&(f64::from(*b) - hundredths).abs())
            })
        }
        _ => match input.keyword().as_deref() {
            Some("BYLAYER") => Some(-1),
            Some("BYBLOCK") => Some(-2),
            Some("DEFAULT") => Some(-3),
            _ => None,
        },
    }
}

/// An entity colour: Some(None) BYLAYER, Some(Some(c)) BYBLOCK (0) or 1..=255.
fn color_of(input: &Input, raw: &Value) -> Option<Option<i16>> {
    let c = match input {
        Input::Number(x) if x.fract() == 0.0 => *x as i64,
        _ => {
            let name = input.name(raw)?;
            match name.trim().to_uppercase().as_str() {
                "BYLAYER" => 256,
                "BYBLOCK" => 0,
                _ => super::layer::named_color(&name)?,
            }
        }
    };
    match c {
        256 => Some(None),
        0..=255 => Some(Some(c as i16)),
        _ => None,
    }
}

/// EXPLODE: each selected polyline becomes its lines and arcs (same layer and colour) as
/// soon as it is given; Enter (or the next command) ends.
pub(crate) fn explode(it: &mut Interp, input: &Input) -> Result<Step, Exn> {
    match input {
        Input::Select(hs) => {
            for &h in hs {
                explode_one(it, h)?;
            }
            Ok(Step::More(Pending::Explode))
        }
        Input::Enter => Ok(Step::Done),
        Input::Word(_) => Ok(Step::DoneNotConsumed),
        _ => Err(unexpected("EXPLODE", "objects or \"\"", input)),
    }
}

fn explode_one(it: &mut Interp, h: u64) -> Result<(), Exn> {
    let d = it.ext::<Drawing>();
    let Some(e) = d.get(h).cloned() else {
        return Ok(());
    };
    if matches!(&e.kind, EntityKind::Unmodelled { dxf_type } if dxf_type == "INSERT") {
        return super::explode::explode_insert(it, h);
    }
    let (pts, bulges, closed, ocs, z) = match &e.kind {
        EntityKind::LwPolyline {
            points,
            bulges,
            closed,
            elevation,
            normal,
        } => (
            points.clone(),
            bulges.clone(),
            *closed,
            Ocs::new(*normal),
            *elevation,
        ),
        EntityKind::Polyline {
            points,
            bulges,
            closed,
        } => {
            let z = points.first().map_or(0.0, |p| p.z);
            let flat: Vec<DVec2> = points.iter().map(|p| p.truncate()).collect();
            if crate::builtins::entities::dxf_list::is_3d(points) {
                // A 3D polyline: straight segments between its vertices.
                let n = points.len();
                let segs = if *closed { n } else { n - 1 };
                for i in 0..segs {
                    let kind = EntityKind::Line {
                        p0: points[i],
                        p1: points[(i + 1) % n],
                    };
                    add_like(d, &e, kind)?;
                }
                d.delete(h);
                return Ok(());
            }
            (flat, bulges.clone(), *closed, Ocs::new(DVec3::Z), z)
        }
        other => {
            return Err(cmd_err(
                "EXPLODE",
                format!(
                    "lispcad explodes polylines and block references, not {}",
                    other.type_name()
                ),
            ))
        }
    };
    for (a, b, bulge) in bulge_segments(&pts, &bulges, closed) {
        let kind = match bulge_arc(a, b, bulge) {
            Some((c, r, a0, a1)) if bulge != 0.0 => {
                // DXF arcs run counter-clockwise (in the OCS) from start to end.
                let (s, t) = if a0 <= a1 { (a0, a1) } else { (a1, a0) };
                let tau = std::f64::consts::TAU;
                EntityKind::Arc {
                    center: ocs.to_wcs(c, z),
                    radius: r,
                    start: s.rem_euclid(tau),
                    end: t.rem_euclid(tau),
                    normal: ocs.n,
                }
            }
            _ => EntityKind::Line {
                p0: ocs.to_wcs(a, z),
                p1: ocs.to_wcs(b, z),
            },
        };
        add_like(d, &e, kind)?;
    }
    d.delete(h);
    Ok(())
}

fn add_like(d: &mut Drawing, e: &Entity, kind: EntityKind) -> Result<(), Exn> {
    let mut n = Entity::new(&e.layer, kind);
    n.color = e.color;
    let h = d.add(n).map_err(|x| cmd_err("EXPLODE", x))?;
    d.copy_props(e.handle, h);
    Ok(())
}

/// OFFSET: a distance (or "T" for through a point), then pairs of object and side point
/// (or object and through point) until Enter.
pub(crate) enum OffsetCmd {
    Distance,
    /// The distance (None: through), and the object once given.
    Object(Option<f64>),
    Side(Option<f64>, u64),
}

impl OffsetCmd {
    pub(crate) fn feed(self, it: &mut Interp, input: &Input) -> Result<Step, Exn> {
        let next = match (self, input) {
            (OffsetCmd::Distance, Input::Number(x)) if *x > 0.0 => OffsetCmd::Object(Some(*x)),
            (OffsetCmd::Distance, Input::Word(_))
                if matches!(input.keyword().as_deref(), Some("T" | "THROUGH")) =>
            {
                OffsetCmd::Object(None)
            }
            (OffsetCmd::Distance, _) => {
                return Err(unexpected("OFFSET", "a positive distance or T", input))
            }
            (OffsetCmd::Object(_), Input::Enter) => return Ok(Step::Done),
            (OffsetCmd::Object(d), Input::Select(hs)) if !hs.is_empty() => {
                OffsetCmd::Side(d, hs[0])
            }
            (OffsetCmd::Object(_), _) => {
                return Err(unexpected("OFFSET", "an object or \"\"", input))
            }
            (OffsetCmd::Side(d, h), Input::Point(p)) => {
                offset_toward(it, h, d, *p)?;
                OffsetCmd::Object(d)
            }
            (OffsetCmd::Side(..), _) => {
                return Err(unexpected("OFFSET", "a point on the side to offset", input))
            }
        };
        Ok(Step::More(Pending::Offset(next)))
    }
}

/// Adds the offset of entity `h` by `dist` on the side of `p` (through `p` without a
/// distance), on the same layer and colour.
fn offset_toward(it: &mut Interp, h: u64, dist: Option<f64>, p: DVec3) -> Result<(), Exn> {
    let d = it.ext::<Drawing>();
    let Some(e) = d.get(h).cloned() else {
        return Err(cmd_err("OFFSET", "the object is deleted"));
    };
    let curve = entity_curve(&e.kind)
        .ok_or_else(|| cmd_err("OFFSET", format!("cannot offset a {}", e.kind.type_name())))?
        .map_err(|x| cmd_err("OFFSET", x))?;
    let (_, foot) = curve.closest_point(p);
    let dist = dist.unwrap_or_else(|| (p - foot).truncate().length());
    // The side: the offset whose curve passes nearer the point.
    let mut best: Option<(f64, crate::geom::Curve)> = None;
    for s in [dist, -dist] {
        if let Ok(o) = curve.offset(s) {
            let gap = (o.closest_point(p).1 - p).length();
            if best.as_ref().is_none_or(|(g, _)| gap < *g) {
                best = Some((gap, o));
            }
        }
    }
    let Some((_, o)) = best else {
        return Err(cmd_err(
            "OFFSET",
            format!("cannot offset this {} by {dist}", e.kind.type_name()),
        ));
    };
    let mut n = Entity::new(&e.layer, curve_entity(&o));
    n.color = e.color;
    let made = d.add(n).map_err(|x| cmd_err("OFFSET", x))?;
    d.copy_props(e.handle, made);
    Ok(())
}

/// FILLET: "R" sets FILLETRAD; two lines, arcs or circles (entity names, or `(ename point)`
/// lists whose point says which part of each to keep) are trimmed or extended to the tangent
/// points of an arc of that radius (to their corner for radius 0; a circle stays whole), and
/// the arc is added; "P" and a 2D polyline fillet its every vertex, and two picked adjacent
/// segments of one polyline the vertex they share (`fillet_pline.rs`).
pub(crate) enum FilletCmd {
    First,
    Radius,
    /// After the Polyline option: the polyline to fillet at every vertex.
    Polyline,
    Second(u64, Option<DVec3>),
}

/// The entity of a selection argument and the point given with it.
fn picked(input: &Input, raw: &Value) -> Option<(u64, Option<DVec3>)> {
    let Input::Select(hs) = input else {
        return None;
    };
    let h = *hs.first()?;
    let pt = match raw {
        Value::Cons(c) => {
            let p = c.cdr.car();
            let xs: Option<Vec<f64>> = p.iter().map(Value::as_f64).collect();
            xs.filter(|x| x.len() >= 2)
                .map(|x| DVec3::new(x[0], x[1], x.get(2).copied().unwrap_or(0.0)))
        }
        _ => None,
    };
    Some((h, pt))
}

impl FilletCmd {
    pub(crate) fn feed(self, it: &mut Interp, input: &Input, raw: &Value) -> Result<Step, Exn> {
        let next = match self {
            FilletCmd::First => match input {
                Input::Enter => return Ok(Step::Done),
                Input::Word(_) => match input.keyword().as_deref() {
                    Some("R" | "RADIUS") => FilletCmd::Radius,
                    Some("P" | "POLYLINE") => FilletCmd::Polyline,
                    // The next command: FILLET was left waiting after its radius.
                    _ => return Ok(Step::DoneNotConsumed),
                },
                _ => match picked(input, raw) {
                    Some((h, p)) => FilletCmd::Second(h, p),
                    None => return Err(unexpected("FILLET", "an object or R", input)),
                },
            },
            FilletCmd::Radius => match input {
                Input::Number(r) if *r >= 0.0 => {
                    it.ext::<crate::builtins::system::SysVars>()
                        .put("FILLETRAD", Value::Real(*r));
                    FilletCmd::First
                }
                _ => return Err(unexpected("FILLET", "a radius >= 0", input)),
            },
            FilletCmd::Polyline => match picked(input, raw) {
                Some((h, _)) => {
                    let r = it
                        .ext::<crate::builtins::system::SysVars>()
                        .real("FILLETRAD");
                    super::fillet_pline::fillet_polyline(it, h, r)?;
                    return Ok(Step::Done);
                }
                None => return Err(unexpected("FILLET", "a 2D polyline", input)),
            },
            FilletCmd::Second(h1, p1) => match picked(input, raw) {
                Some((h2, p2)) => {
                    let r = it
                        .ext::<crate::builtins::system::SysVars>()
                        .real("FILLETRAD");
                    if h1 == h2 {
                        // Two segments of one polyline.
                        super::fillet_pline::fillet_segments(it, h1, (p1, p2), r)?;
                        return Ok(Step::Done);
                    }
                    let both_lines = [h1, h2].iter().all(|h| {
                        matches!(
                            it.ext::<Drawing>().get(*h).map(|e| &e.kind),
                            Some(EntityKind::Line { .. })
                        )
                    });
                    if both_lines {
                        fillet_lines(it, (h1, p1), (h2, p2), r)?;
                    } else {
                        super::fillet::fillet_curves(it, (h1, p1), (h2, p2), r)?;
                    }
                    return Ok(Step::Done);
                }
                None => return Err(unexpected("FILLET", "a second object", input)),
            },
        };
        Ok(Step::More(Pending::Fillet(next)))
    }
}

fn line_of(d: &Drawing, h: u64) -> Result<(Entity, DVec3, DVec3), Exn> {
    let e = d
        .get(h)
        .cloned()
        .ok_or_else(|| cmd_err("FILLET", "the object is deleted"))?;
    match e.kind {
        EntityKind::Line { p0, p1 } => Ok((e, p0, p1)),
        ref k => Err(cmd_err(
            "FILLET",
            format!("lispcad fillets two lines, not a {}", k.type_name()),
        )),
    }
}

fn fillet_lines(
    it: &mut Interp,
    (h1, q1): (u64, Option<DVec3>),
    (h2, q2): (u64, Option<DVec3>),
    r: f64,
) -> Result<(), Exn> {
    if h1 == h2 {
        return Err(cmd_err("FILLET", "the two objects are the same line"));
    }
    let d = it.ext::<Drawing>();
    let (e1, a1, b1) = line_of(d, h1)?;
    let (e2, a2, b2) = line_of(d, h2)?;
    let flat = |p: DVec3| p.truncate();
    let (u1, u2) = (flat(b1 - a1), flat(b2 - a2));
    let den = u1.perp_dot(u2);
    if den.abs() <= 1e-12 * u1.length() * u2.length() {
        return Err(cmd_err("FILLET", "the lines are parallel"));
    }
    // The corner: where the lines (extended) meet.
    let s = flat(a2 - a1).perp_dot(u2) / den;
    let corner = flat(a1) + u1 * s;
    // Each line keeps the end on the side of its pick point (without one, the end farther
    // from the corner).
    let keep = |a: DVec3, b: DVec3, q: Option<DVec3>| -> DVec2 {
        let (a, b) = (flat(a), flat(b));
        let far = if (a - corner).length() >= (b - corner).length() {
            a
        } else {
            b
        };
        let Some(q) = q else {
            return far;
        };
        let dir = flat(q) - corner;
        match ((a - corner).dot(dir) > 0.0, (b - corner).dot(dir) > 0.0) {
            (true, false) => a,
            (false, true) => b,
            _ => far,
        }
    };
    let (k1, k2) = (keep(a1, b1, q1), keep(a2, b2, q2));
    let (d1, d2) = ((k1 - corner).normalize(), (k2 - corner).normalize());
    let theta = d1.angle_to(d2).abs();
    if !d1.is_finite() || !d2.is_finite() || theta < 1e-12 {
        return Err(cmd_err(
            "FILLET",
            "a line ends at the corner on the kept side",
        ));
    }
    let t = r / (theta / 2.0).tan();
    if t > (k1 - corner).length() + 1e-9 || t > (k2 - corner).length() + 1e-9 {
        return Err(cmd_err(
            "FILLET",
            format!("radius {r} is too large for these lines"),
        ));
    }
    let (t1, t2) = (corner + d1 * t, corner + d2 * t);
    let z = a1.z;
    let trim = |e: Entity, a: DVec3, b: DVec3, k: DVec2, tp: DVec2| -> Entity {
        let kind = if flat(a) == k {
            EntityKind::Line {
                p0: a,
                p1: tp.extend(b.z),
            }
        } else {
            EntityKind::Line {
                p0: tp.extend(a.z),
                p1: b,
            }
        };
        Entity { kind, ..e }
    };
    let (c1, c2) = (
        trim(e1.clone(), a1, b1, k1, t1),
        trim(e2.clone(), a2, b2, k2, t2),
    );
    let arc = (r > 0.0).then(|| {
        let c = corner + (d1 + d2).normalize() * (r / (theta / 2.0).sin());
        let (s1, s2) = ((t1 - c).to_angle(), (t2 - c).to_angle());
        // The fillet is the short arc between the tangent points.
        let (start, end) = if crate::output::drawing::ccw_sweep(s1, s2) <= std::f64::consts::PI {
            (s1, s2)
        } else {
            (s2, s1)
        };
        (c.extend(z), start, end)
    });
    super::fillet::replace_and_add_arc(d, (h1, e1, c1), (h2, e2, c2), arc, r)
}
