//! The CAM profile: AutoCAD R12 (AC1009) for laser and CNC software, which reads only LINE,
//! ARC, CIRCLE and POLYLINE (with bulges) reliably.
//!
//! Everything is flattened to the XY plane. Splines and tilted arcs become arcs by biarc
//! fitting (`biarc`), within `cam_tol`. A closed outline (closed spline or closed polyline)
//! becomes one closed POLYLINE, so the machine cuts it as one contour. Duplicate and
//! overlapping edges are removed (a cutter would otherwise burn the same edge twice): later
//! open edges lose the parts another edge already covers; closed outlines and circles are kept
//! whole and identical copies of them dropped. Points, faces and meshes are not cutting
//! geometry and are left out with a warning; text is kept, as R12 TEXT on a layer of its own.

use glam::{DVec2, DVec3};

use super::biarc::{fit_bspline, fit_span, BulgeChain, Projected};
use super::cam_overlap::{remove_overlaps, same_closed, Edge, Seg, EPS};
use super::cam_tidy;
use super::drawing::{bulge_arc, ccw_sweep, is_flat, Drawing, Entity, EntityKind};
use super::dxf::{degrees, DxfWriter};
use crate::geom::frame::Ocs;
use crate::geom::ParamCurve as _;

/// An R12-safe layer name: upper case, letters, digits, `$`, `-`, `_`; at most 31 characters.
pub fn r12_layer_name(name: &str) -> String {
    let s: String = name
        .chars()
        .map(|c| {
            let c = c.to_ascii_uppercase();
            if c.is_ascii_alphanumeric() || "$-_".contains(c) {
                c
            } else {
                '_'
            }
        })
        .take(31)
        .collect();
    if s.is_empty() {
        "0".to_string()
    } else {
        s
    }
}

/// What one drawing entity contributes to the cut.
enum Prim {
    Circle(DVec2, f64),
    Closed(BulgeChain),
    /// Open chains: single surviving pieces are written as LINE/ARC, longer runs as POLYLINE.
    Open(BulgeChain),
}

fn parallel_to_z(n: DVec3) -> Option<f64> {
    let n = n.normalize();
    (n.x.abs() < 1e-12 && n.y.abs() < 1e-12).then_some(n.z.signum())
}

fn chain_of(points: Vec<DVec2>, bulges: Vec<f64>) -> BulgeChain {
    BulgeChain { points, bulges }
}

/// A chain that ends where it starts, as a closed polyline (the repeated end dropped).
fn close_chain(mut c: BulgeChain) -> Option<BulgeChain> {
    if c.points.len() >= 3 && (c.points[c.points.len() - 1] - c.points[0]).length() <= EPS {
        c.points.pop();
        Some(c)
    } else {
        None
    }
}

/// Arcs of the 3D circle (centre, radius, OCS of normal) between angles t0..t1, fitted in XY.
fn fit_tilted_arc(
    center: DVec3,
    radius: f64,
    normal: DVec3,
    t0: f64,
    t1: f64,
    tol: f64,
    out: &mut BulgeChain,
) {
    let ocs = Ocs::new(normal);
    let f = Projected(move |t: f64| ocs.on_circle(center, radius, t));
    fit_span(&f, t0, t1, tol, out);
}

/// Append the OCS polyline (points, bulges) in the plane of `normal` at `elevation`, projected
/// to XY: bulges stay bulges when the plane is parallel to XY, tilted arcs are fitted.
fn ocs_polyline(
    points: &[DVec2],
    bulges: &[f64],
    closed: bool,
    elevation: f64,
    normal: DVec3,
    tol: f64,
) -> BulgeChain {
    let ocs = Ocs::new(normal);
    let to_xy = |p: DVec2| ocs.to_wcs(p, elevation).truncate();
    let mut out = BulgeChain::default();
    let flip = parallel_to_z(normal);
    let segs = super::drawing::bulge_segments(points, bulges, closed);
    out.points.push(to_xy(points[0]));
    for (a, b, bulge) in segs {
        match (flip, bulge_arc(a, b, bulge)) {
            (Some(sign), _) => {
                out.bulges.push(bulge * sign);
                out.points.push(to_xy(b));
            }
            (None, None) => {
                out.bulges.push(0.0);
                out.points.push(to_xy(b));
            }
            (None, Some((c, r, a0, a1))) => {
                let mut piece = BulgeChain::default();
                fit_tilted_arc(ocs.to_wcs(c, elevation), r, ocs.n, a0, a1, tol, &mut piece);
                out.bulges.extend(piece.bulges);
                out.points.extend(piece.points.into_iter().skip(1));
            }
        }
    }
    out
}

fn to_prims(e: &Entity, tol: f64) -> Vec<Prim> {
    match &e.kind {
        EntityKind::Line { p0, p1 } => {
            let (a, b) = (p0.truncate(), p1.truncate());
            if (b - a).length() <= EPS {
                return vec![];
            }
            vec![Prim::Open(chain_of(vec![a, b], vec![0.0]))]
        }
        EntityKind::Circle {
            center,
            radius,
            normal,
        } => match parallel_to_z(*normal) {
            Some(_) => vec![Prim::Circle(center.truncate(), *radius)],
            None => {
                let mut c = BulgeChain::default();
                let tau = std::f64::consts::TAU;
                // Two halves so each fitted span starts with a well-defined chord.
                fit_tilted_arc(*center, *radius, *normal, 0.0, tau / 2.0, tol, &mut c);
                fit_tilted_arc(*center, *radius, *normal, tau / 2.0, tau, tol, &mut c);
                close_chain(c).map(Prim::Closed).into_iter().collect()
            }
        },
        EntityKind::Arc {
            center,
            radius,
            start,
            end,
            normal,
        } => {
            let sweep = ccw_sweep(*start, *end);
            match parallel_to_z(*normal) {
                Some(sign) => {
                    let ocs = Ocs::new(*normal);
                    let at = |t: f64| ocs.on_circle(*center, *radius, t).truncate();
                    if sweep >= std::f64::consts::TAU - 1e-15 {
                        return vec![Prim::Circle(center.truncate(), *radius)];
                    }
                    let bulge = sign * (sweep / 4.0).tan();
                    vec![Prim::Open(chain_of(
                        vec![at(*start), at(*start + sweep)],
                        vec![bulge],
                    ))]
                }
                None => {
                    let mut c = BulgeChain::default();
                    fit_tilted_arc(
                        *center,
                        *radius,
                        *normal,
                        *start,
                        *start + sweep,
                        tol,
                        &mut c,
                    );
                    vec![Prim::Open(c)]
                }
            }
        }
        EntityKind::LwPolyline {
            points,
            bulges,
            closed,
            elevation,
            normal,
        } => {
            let c = ocs_polyline(points, bulges, *closed, *elevation, *normal, tol);
            if *closed {
                // The chain repeats the first vertex at its end.
                close_chain(c).map(Prim::Closed).into_iter().collect()
            } else {
                vec![Prim::Open(c)]
            }
        }
        EntityKind::Polyline {
            points,
            bulges,
            closed,
        } => {
            let flat = is_flat(points);
            let pts: Vec<DVec2> = points.iter().map(|p| p.truncate()).collect();
            let bul = if flat { bulges.clone() } else { vec![] };
            let c = ocs_polyline(&pts, &bul, *closed, 0.0, DVec3::Z, tol);
            if *closed {
                close_chain(c).map(Prim::Closed).into_iter().collect()
            } else {
                vec![Prim::Open(c)]
            }
        }
        EntityKind::Spline { curve, closed, .. } => {
            let c = fit_bspline(curve, tol);
            let ends_meet = (curve.eval(0.0) - curve.eval(1.0)).truncate().length() <= EPS;
            if *closed || ends_meet {
                if let Some(cl) = close_chain(c.clone()) {
                    return vec![Prim::Closed(cl)];
                }
            }
            vec![Prim::Open(c)]
        }
        EntityKind::Ellipse { start, end, .. } => {
            // Flattened finely (the CAM profile's arcs fit lines and circles only).
            let pts: Vec<DVec2> = e
                .kind
                .ellipse_points(256)
                .iter()
                .map(|p| p.truncate())
                .collect();
            let n = pts.len();
            let c = chain_of(pts, vec![0.0; n]);
            if ccw_sweep(*start, *end) >= std::f64::consts::TAU - 1e-12 {
                close_chain(c).map(Prim::Closed).into_iter().collect()
            } else {
                vec![Prim::Open(c)]
            }
        }
        EntityKind::Point { .. }
        | EntityKind::Text { .. }
        | EntityKind::Face3d { .. }
        | EntityKind::Unmodelled { .. }
        | EntityKind::Mesh { .. } => vec![],
    }
}

// ---------------------------------------------------------------- writing

struct Item<'a> {
    entity: &'a Entity,
    prim: Prim,
    /// Edge index range of this item in the edge list (open chains and fixed outlines).
    edges: std::ops::Range<usize>,
    dropped: bool,
}

/// A CAM file and what was left out of it, for the user.
pub struct CamOutput {
    pub dxf: String,
    pub warnings: Vec<String>,
}

/// Write the drawing as the CAM profile (R12) with splines fitted within `tol`.
pub fn write_cam(d: &Drawing, tol: f64) -> String {
    let opts = super::OutputOptions {
        cam_tol: tol,
        ..Default::default()
    };
    write_cam_with(d, &opts).dxf
}

/// The CAM profile with the writer options (`cam_tol`, `cam_min_seg`, `insunits`): fitted
/// within half the tolerance, short segments merged within the other half (see `cam_tidy`);
/// open paths first, then closed contours from the innermost out, outer ones
/// counter-clockwise and holes clockwise, each started on its smoothest stretch; text on its
/// own layer; a warning for whatever was left out.
pub fn write_cam_with(d: &Drawing, opts: &super::OutputOptions) -> CamOutput {
    let mut warnings = Vec::new();
    let mut left_out: std::collections::BTreeMap<&str, usize> = Default::default();
    let mut texts: Vec<&Entity> = Vec::new();
    for e in d.entities() {
        match &e.kind {
            EntityKind::Text { .. } => texts.push(e),
            EntityKind::Point { .. } | EntityKind::Face3d { .. } | EntityKind::Mesh { .. } => {
                *left_out.entry(e.kind.type_name()).or_default() += 1;
            }
            _ => {}
        }
    }
    let mut items = cut_items(d, opts, &mut warnings);
    drop_duplicates(&mut items);
    let edges = edges_of(&mut items);
    let dups = items.iter().filter(|it| it.dropped).count();
    if dups > 0 {
        warnings.push(format!(
            "{dups} duplicate closed outline(s) or circle(s) dropped (cut once)"
        ));
    }
    for (kind, n) in &left_out {
        warnings.push(format!("{n} {kind} left out: not cutting geometry"));
    }
    let order = cut_order(&mut items);
    let cut_layers: Vec<String> = items
        .iter()
        .filter(|it| !it.dropped)
        .map(|it| r12_layer_name(&it.entity.layer))
        .collect();
    let text_layer = |e: &Entity| {
        let l = r12_layer_name(&e.layer);
        if cut_layers.contains(&l) {
            r12_layer_name(&format!("{l}_TEXT"))
        } else {
            l
        }
    };
    let extra: Vec<String> = texts.iter().map(|e| text_layer(e)).collect();

    let mut w = DxfWriter::new();
    write_r12_head(&mut w, d, &extra, opts.insunits);
    w.str(0, "SECTION");
    w.str(2, "ENTITIES");
    for it in order.iter().map(|&i| &items[i]) {
        let layer = r12_layer_name(&it.entity.layer);
        let color = it.entity.color;
        match &it.prim {
            Prim::Circle(c, r) => {
                head(&mut w, "CIRCLE", &layer, color);
                w.point(10, c.extend(0.0));
                w.float(40, *r);
            }
            Prim::Closed(ch) => write_polyline(&mut w, &layer, color, ch, true),
            Prim::Open(_) => write_open(&mut w, &layer, color, &edges[it.edges.clone()]),
        }
    }
    for (e, layer) in texts.iter().zip(&extra) {
        write_text(&mut w, e, layer);
    }
    w.str(0, "ENDSEC");
    w.str(0, "EOF");
    CamOutput {
        dxf: w.out,
        warnings,
    }
}

/// Every entity's cutting primitives, fitted within half the tolerance when short segments
/// are merged within the other half.
fn cut_items<'a>(
    d: &'a Drawing,
    opts: &super::OutputOptions,
    warnings: &mut Vec<String>,
) -> Vec<Item<'a>> {
    let (tol, min_seg) = (opts.cam_tol, opts.cam_min_seg);
    let fit_tol = if min_seg > 0.0 { 0.5 * tol } else { tol };
    let mut items = Vec::new();
    for e in d.entities() {
        for mut prim in to_prims(e, fit_tol) {
            let short = match &mut prim {
                Prim::Closed(ch) => cam_tidy::merge_short(ch, true, min_seg, tol - fit_tol),
                Prim::Open(ch) => cam_tidy::merge_short(ch, false, min_seg, tol - fit_tol),
                Prim::Circle(..) => 0,
            };
            if short > 0 {
                warnings.push(format!(
                    "{short} segment(s) of a {} on layer {} are shorter than {min_seg}: the \
                     geometry itself is that small",
                    e.kind.type_name(),
                    e.layer
                ));
            }
            items.push(Item {
                entity: e,
                prim,
                edges: 0..0,
                dropped: false,
            });
        }
    }
    items
}

/// Identical closed outlines and circles: keep the first.
fn drop_duplicates(items: &mut [Item]) {
    for i in 0..items.len() {
        for j in 0..i {
            if items[j].dropped {
                continue;
            }
            let dup = match (&items[i].prim, &items[j].prim) {
                (Prim::Circle(c1, r1), Prim::Circle(c2, r2)) => {
                    (*c1 - *c2).length() <= EPS && (r1 - r2).abs() <= EPS
                }
                (Prim::Closed(a), Prim::Closed(b)) => same_closed(a, b),
                _ => false,
            };
            if dup {
                items[i].dropped = true;
                break;
            }
        }
    }
}

/// The edges of the surviving items, each item told its range, with overlaps removed.
fn edges_of(items: &mut [Item]) -> Vec<Edge> {
    let mut edges: Vec<Edge> = Vec::new();
    for (order, it) in items.iter_mut().enumerate() {
        if it.dropped {
            continue;
        }
        let start = edges.len();
        let mut push = |seg: Seg, open: bool| {
            edges.push(Edge {
                seg,
                open,
                order,
                keep: vec![(0.0, 1.0)],
            })
        };
        match &it.prim {
            Prim::Circle(c, r) => push(Seg::circle(*c, *r), false),
            Prim::Closed(ch) => {
                let n = ch.points.len();
                for i in 0..n {
                    push(
                        Seg::from_bulge(ch.points[i], ch.points[(i + 1) % n], ch.bulges[i]),
                        false,
                    );
                }
            }
            Prim::Open(ch) => {
                for (w, b) in ch.points.windows(2).zip(&ch.bulges) {
                    push(Seg::from_bulge(w[0], w[1], *b), true);
                }
            }
        }
        it.edges = start..edges.len();
    }
    remove_overlaps(&mut edges);
    edges
}

/// An open chain's surviving pieces: consecutive pieces that still join form one run.
fn write_open(w: &mut DxfWriter, layer: &str, color: Option<i16>, edges: &[Edge]) {
    let mut run = BulgeChain::default();
    let mut last_end: Option<DVec2> = None;
    for e in edges {
        for &(s0, s1) in &e.keep {
            let (a, b, bu) = e.seg.piece(s0.max(0.0), s1.min(1.0));
            let joins = last_end.is_some_and(|p| (p - a).length() <= EPS) && s0 <= 0.0;
            if !joins && !run.points.is_empty() {
                write_run(w, layer, color, &run);
                run = BulgeChain::default();
            }
            if run.points.is_empty() {
                run.points.push(a);
            }
            run.points.push(b);
            run.bulges.push(bu);
            last_end = (s1 >= 1.0).then_some(b);
        }
    }
    if !run.points.is_empty() {
        write_run(w, layer, color, &run);
    }
}

fn write_text(w: &mut DxfWriter, e: &Entity, layer: &str) {
    if let EntityKind::Text {
        insert,
        height,
        value,
        rotation,
        ..
    } = &e.kind
    {
        head(w, "TEXT", layer, e.color);
        w.point(10, insert.truncate().extend(0.0));
        w.float(40, *height);
        w.str(1, value);
        if *rotation != 0.0 {
            w.float(50, degrees(*rotation));
        }
    }
}

/// The order to cut in: open paths first (drawing order), then closed contours and circles
/// innermost first, so no part falls out before its holes are cut. Orients each closed chain
/// (outer counter-clockwise, holes clockwise, by nesting depth) and picks its start.
fn cut_order(items: &mut [Item]) -> Vec<usize> {
    let live: Vec<usize> = (0..items.len()).filter(|&i| !items[i].dropped).collect();
    let probe = |p: &Prim| match p {
        Prim::Circle(c, r) => Some(*c + DVec2::new(*r, 0.0)),
        Prim::Closed(ch) => ch.points.first().copied(),
        Prim::Open(_) => None,
    };
    let inside = |outer: &Prim, p: DVec2| match outer {
        Prim::Circle(c, r) => c.distance(p) < *r - EPS,
        Prim::Closed(ch) => cam_tidy::contains(ch, p),
        Prim::Open(_) => false,
    };
    let mut depth = vec![0usize; items.len()];
    for &i in &live {
        if let Some(p) = probe(&items[i].prim) {
            depth[i] = live
                .iter()
                .filter(|&&j| j != i && inside(&items[j].prim, p))
                .count();
        }
    }
    for &i in &live {
        if let Prim::Closed(ch) = &mut items[i].prim {
            let ccw = cam_tidy::signed_area(ch) > 0.0;
            if ccw != depth[i].is_multiple_of(2) {
                cam_tidy::reverse_closed(ch);
            }
            cam_tidy::choose_start(ch);
        }
    }
    let (mut open, mut closed): (Vec<usize>, Vec<usize>) = live
        .into_iter()
        .partition(|&i| matches!(items[i].prim, Prim::Open(_)));
    closed.sort_by(|&a, &b| depth[b].cmp(&depth[a]));
    open.extend(closed);
    open
}

fn head(w: &mut DxfWriter, kind: &str, layer: &str, color: Option<i16>) {
    w.str(0, kind);
    w.str(8, layer);
    if let Some(c) = color {
        w.int(62, c as i64);
    }
}

/// A single piece as LINE or ARC, longer runs as an open POLYLINE.
fn write_run(w: &mut DxfWriter, layer: &str, color: Option<i16>, run: &BulgeChain) {
    if run.bulges.len() == 1 {
        let (a, b, bu) = (run.points[0], run.points[1], run.bulges[0]);
        match bulge_arc(a, b, bu) {
            None => {
                head(w, "LINE", layer, color);
                w.point(10, a.extend(0.0));
                w.point(11, b.extend(0.0));
            }
            Some((c, r, a0, a1)) => {
                // ARC runs counter-clockwise from 50 to 51.
                let (s, e) = if a1 > a0 { (a0, a1) } else { (a1, a0) };
                head(w, "ARC", layer, color);
                w.point(10, c.extend(0.0));
                w.float(40, r);
                w.float(50, degrees(s));
                w.float(51, degrees(e));
            }
        }
    } else {
        write_polyline(w, layer, color, run, false);
    }
}

fn write_polyline(
    w: &mut DxfWriter,
    layer: &str,
    color: Option<i16>,
    ch: &BulgeChain,
    closed: bool,
) {
    head(w, "POLYLINE", layer, color);
    w.int(66, 1);
    w.point(10, DVec3::ZERO);
    w.int(70, closed as i64);
    for (i, p) in ch.points.iter().enumerate() {
        w.str(0, "VERTEX");
        w.str(8, layer);
        w.point(10, p.extend(0.0));
        let b = ch.bulges.get(i).copied().unwrap_or(0.0);
        if b != 0.0 {
            w.float(42, b);
        }
        w.int(70, 0);
    }
    w.str(0, "SEQEND");
    w.str(8, layer);
}

fn write_r12_head(w: &mut DxfWriter, d: &Drawing, extra_layers: &[String], insunits: i32) {
    w.str(0, "SECTION");
    w.str(2, "HEADER");
    w.str(9, "$ACADVER");
    w.str(1, "AC1009");
    w.str(9, "$INSBASE");
    w.point(10, DVec3::ZERO);
    let (lo, hi) = d
        .extents()
        .map(|(lo, hi)| {
            (
                lo * DVec3::new(1.0, 1.0, 0.0),
                hi * DVec3::new(1.0, 1.0, 0.0),
            )
        })
        .unwrap_or((DVec3::ZERO, DVec3::ZERO));
    w.str(9, "$EXTMIN");
    w.point(10, lo);
    w.str(9, "$EXTMAX");
    w.point(10, hi);
    w.str(9, "$LUNITS");
    w.int(70, 2);
    // R12 has no $INSUNITS; $MEASUREMENT (R14) is read by R12 readers too and keeps an inch
    // drawing from being taken for millimetres.
    if super::measurement(insunits) == 0 {
        w.str(9, "$MEASUREMENT");
        w.int(70, 0);
    }
    w.str(0, "ENDSEC");

    w.str(0, "SECTION");
    w.str(2, "TABLES");
    w.str(0, "TABLE");
    w.str(2, "LTYPE");
    w.int(70, 1);
    w.str(0, "LTYPE");
    w.solid_linetype_fields("CONTINUOUS", "Solid line");
    w.str(0, "ENDTAB");

    let mut names: Vec<(String, i16)> = Vec::new();
    for l in d.layers() {
        let n = r12_layer_name(&l.name);
        if !names.iter().any(|(m, _)| *m == n) {
            names.push((n, l.color));
        }
    }
    for n in extra_layers {
        if !names.iter().any(|(m, _)| m == n) {
            names.push((n.clone(), 7));
        }
    }
    w.str(0, "TABLE");
    w.str(2, "LAYER");
    w.int(70, names.len() as i64);
    for (n, c) in &names {
        w.str(0, "LAYER");
        w.str(2, n);
        w.int(70, 0);
        w.int(62, *c as i64);
        w.str(6, "CONTINUOUS");
    }
    w.str(0, "ENDTAB");

    w.str(0, "TABLE");
    w.str(2, "STYLE");
    w.int(70, 1);
    w.str(0, "STYLE");
    w.str(2, "STANDARD");
    w.text_style_fields();
    w.str(0, "ENDTAB");
    w.str(0, "ENDSEC");

    w.str(0, "SECTION");
    w.str(2, "BLOCKS");
    w.str(0, "ENDSEC");
}

#[cfg(test)]
mod tests {
    use super::*;

    fn line(a: (f64, f64), b: (f64, f64)) -> EntityKind {
        EntityKind::Line {
            p0: DVec3::new(a.0, a.1, 0.0),
            p1: DVec3::new(b.0, b.1, 0.0),
        }
    }

    #[test]
    fn duplicate_and_covered_lines_are_removed() {
        let mut d = Drawing::new();
        d.add_kind(line((0.0, 0.0), (10.0, 0.0))).unwrap();
        d.add_kind(line((10.0, 0.0), (0.0, 0.0))).unwrap(); // reversed duplicate
        d.add_kind(line((2.0, 0.0), (5.0, 0.0))).unwrap(); // covered
        d.add_kind(line((5.0, 0.0), (15.0, 0.0))).unwrap(); // half covered
        let s = write_cam(&d, 0.01);
        assert_eq!(s.matches("\nLINE\n").count(), 2, "{s}");
        assert!(
            s.contains(" 10\n10.0\n 20\n0.0\n 30\n0.0\n 11\n15.0\n"),
            "{s}"
        );
    }

    #[test]
    fn layer_names_are_r12_safe() {
        assert_eq!(r12_layer_name("Cut line/2"), "CUT_LINE_2");
        assert_eq!(r12_layer_name(""), "0");
    }
}
