//! CHPROP, CHANGE (its Properties option), EXPLODE (polylines into lines and arcs) and
//! OFFSET (by a distance or through a point, on the side a point gives), with AutoCAD's
//! prompts in their order. What lispcad does not model (per-entity line types, weights and
//! thickness; exploding blocks) is a clear error naming it.

use glam::{DVec2, DVec3};

use super::{cmd_err, unexpected, Input, Pending, Step};
use crate::builtins::drawing::curve_entity;
use crate::builtins::vla::curve::entity_curve;
use crate::geom::frame::Ocs;
use crate::lang::error::Exn;
use crate::lang::{Interp, Value};
use crate::output::drawing::{bulge_arc, bulge_segments};
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
                Some(o @ ("LW" | "LWEIGHT" | "T" | "THICKNESS" | "S" | "LTSCALE" | "TR"
                | "TRANSPARENCY" | "M" | "MATERIAL" | "PL" | "PLOTSTYLE" | "E" | "ELEV")) => {
                    return Err(cmd_err(
                        name,
                        format!("the {o} property is not modelled by lispcad (Color, LAyer and LType BYLAYER are)"),
                    ))
                }
                _ => return Err(unexpected(name, "C, LA, LT or \"\"", input)),
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
            ChState::Ltype => match kw.as_deref() {
                Some("BYLAYER") => ChState::Option,
                _ => {
                    return Err(cmd_err(
                        name,
                        format!(
                            "per-entity line types are not modelled by lispcad (only BYLAYER; set the layer's with -LAYER LType), got {}",
                            input.describe()
                        ),
                    ))
                }
            },
        };
        Ok(Step::More(Pending::Chprop(self)))
    }
}

/// An entity colour: Some(None) BYLAYER, Some(Some(c)) BYBLOCK (0) or 1..=255.
fn color_of(input: &Input, raw: &Value) -> Option<Option<i16>> {
    let c = match input {
        Input::Number(x) if x.fract() == 0.0 => *x as i64,
        _ => match input.name(raw)?.trim().to_uppercase().as_str() {
            "BYLAYER" => 256,
            "BYBLOCK" => 0,
            "RED" => 1,
            "YELLOW" => 2,
            "GREEN" => 3,
            "CYAN" => 4,
            "BLUE" => 5,
            "MAGENTA" => 6,
            "WHITE" => 7,
            _ => return None,
        },
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
                    "lispcad explodes polylines only, not {} (block references are kept as read)",
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
    d.add(n).map_err(|x| cmd_err("EXPLODE", x))?;
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
    d.add(n).map_err(|x| cmd_err("OFFSET", x))?;
    Ok(())
}
