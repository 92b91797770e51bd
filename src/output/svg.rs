//! SVG output: one Inkscape layer (`<g inkscape:groupmode="layer">`) per drawing layer,
//! at true scale in the drawing's unit (`INSUNITS`: `width`/`height` in mm, or in inches for an
//! inch drawing; `viewBox` in drawing units), Y up by a single
//! `scale(1,-1)` on each layer group, so path data is in drawing coordinates.
//!
//! Geometry is projected orthographically along the view direction (VIEWDIR, default +Z = plan
//! view) onto the plane spanned by `arbitrary_axis(view_dir)`. Exactness: circles and arcs whose
//! plane faces the view are SVG `A` commands; non-rational splines of degree 1, 2, 3 are `L`,
//! `Q`, `C` segments of their Bézier decomposition (orthographic projection is affine, so the
//! projected control points are exact). Everything else (rational or higher-degree splines,
//! arcs seen obliquely, i.e. ellipses) is approximated by a fine polyline.

use std::fmt::Write as _;

use glam::{DVec2, DVec3};

use super::aci::aci_to_hex;
use super::drawing::{bulge_arc, bulge_segments, ccw_sweep, is_flat, Drawing, Entity, EntityKind};
use super::entity::BezierSource;
use super::OutputOptions;
use crate::geom::frame::{arbitrary_axis, Ocs};

/// Largest distance (drawing units) between a curve SVG cannot express and its polyline.
const FLATNESS: f64 = 2e-5;

/// Append `f` on (t0, t1] as line segments within FLATNESS, by recursive bisection with the
/// chord-midpoint test (at least 8 pieces, so no bump slips between samples).
fn flatten(d: &mut String, f: &dyn Fn(f64) -> DVec2, t0: f64, t1: f64) {
    fn rec(d: &mut String, f: &dyn Fn(f64) -> DVec2, t0: f64, t1: f64, depth: u32) {
        let (a, b) = (f(t0), f(t1));
        let tm = 0.5 * (t0 + t1);
        let m = f(tm);
        let q1 = f(0.5 * (t0 + tm));
        let q3 = f(0.5 * (tm + t1));
        let dev = |p: DVec2| {
            let ab = b - a;
            let l2 = ab.length_squared();
            if l2 == 0.0 {
                (p - a).length()
            } else {
                let s = ((p - a).dot(ab) / l2).clamp(0.0, 1.0);
                (p - (a + ab * s)).length()
            }
        };
        let flat = dev(m).max(dev(q1)).max(dev(q3)) <= FLATNESS;
        if depth >= 3 && (flat || depth >= 24) {
            line_to(d, b);
        } else {
            rec(d, f, t0, tm, depth + 1);
            rec(d, f, tm, t1, depth + 1);
        }
    }
    rec(d, f, t0, t1, 0);
}

/// Orthographic projection onto the view plane.
#[derive(Clone, Copy, Debug)]
pub struct View {
    pub right: DVec3,
    pub up: DVec3,
    pub dir: DVec3,
}

impl View {
    pub fn new(view_dir: DVec3) -> View {
        let (right, up) = arbitrary_axis(view_dir);
        View {
            right,
            up,
            dir: view_dir.normalize(),
        }
    }

    pub fn project(&self, p: DVec3) -> DVec2 {
        DVec2::new(p.dot(self.right), p.dot(self.up))
    }

    /// +1 when a plane with this normal faces the viewer, -1 when it faces away, None when the
    /// view is oblique to it (its circles project to ellipses).
    fn facing(&self, normal: DVec3) -> Option<f64> {
        let c = normal.normalize().dot(self.dir);
        if (c.abs() - 1.0).abs() < 1e-12 {
            Some(c.signum())
        } else {
            None
        }
    }
}

/// A number in path data: micrometre-of-a-millimetre resolution (1e-6 units), no "-0".
fn num(out: &mut String, x: f64) {
    let r = (x * 1e6).round();
    if r == 0.0 || !r.is_finite() {
        out.push('0');
    } else if (1e5..1e15).contains(&r.abs()) {
        // r·10⁻⁶ has at most 15 significant digits, so it is the only decimal that short
        // reading back as r/1e6: Ryū's shortest form is exactly its digits, and in this range
        // (0.1 to 1e9) Ryū writes them without an exponent. Integer arithmetic is cheaper.
        fixed6(out, r);
    } else {
        let mut b = ryu::Buffer::new();
        let s = b.format_finite(r / 1e6);
        out.push_str(s.strip_suffix(".0").unwrap_or(s));
    }
}

/// r·10⁻⁶ in plain decimal, trailing fractional zeros (and a bare point) dropped.
fn fixed6(out: &mut String, r: f64) {
    if r < 0.0 {
        out.push('-');
    }
    let n = r.abs() as u64;
    let (int, frac) = (n / 1_000_000, n % 1_000_000);
    out.push_str(itoa::Buffer::new().format(int));
    if frac != 0 {
        let mut digits = [b'0'; 6];
        let mut f = frac;
        for d in digits.iter_mut().rev() {
            *d = b'0' + (f % 10) as u8;
            f /= 10;
        }
        let len = 6 - digits.iter().rev().take_while(|&&d| d == b'0').count();
        out.push('.');
        // Pushed as characters: validating six ASCII bytes as UTF-8 cost more than this.
        out.extend(digits[..len].iter().map(|&d| char::from(d)));
    }
}

fn pt(out: &mut String, p: DVec2) {
    num(out, p.x);
    out.push(' ');
    num(out, p.y);
}

fn move_to(d: &mut String, p: DVec2) {
    if !d.is_empty() {
        d.push(' ');
    }
    d.push('M');
    pt(d, p);
}

fn line_to(d: &mut String, p: DVec2) {
    d.push_str(" L");
    pt(d, p);
}

/// `A r r 0 large sweep end`: sweep 1 = increasing angle in the path's own (Y-up drawing)
/// coordinates, i.e. counter-clockwise as drawn; the layer's flip does not change it because
/// the flag is interpreted before the transform.
fn arc_to(d: &mut String, r: f64, large: bool, ccw: bool, end: DVec2) {
    d.push_str(" A");
    num(d, r);
    d.push(' ');
    num(d, r);
    let _ = write!(d, " 0 {} {} ", large as u8, ccw as u8);
    pt(d, end);
}

/// An arc in the view plane: centre, radius, start angle and signed sweep (may be a full turn).
fn view_arc(d: &mut String, c: DVec2, r: f64, a0: f64, sweep: f64, start_new: bool) {
    let at = |t: f64| c + DVec2::new(t.cos(), t.sin()) * r;
    if start_new {
        move_to(d, at(a0));
    }
    // SVG cannot draw a full turn in one command: split into pieces of at most a half turn.
    let pieces = if sweep.abs() > std::f64::consts::PI {
        2
    } else {
        1
    };
    for k in 1..=pieces {
        let t = a0 + sweep * k as f64 / pieces as f64;
        let piece = sweep / pieces as f64;
        arc_to(d, r, piece.abs() > std::f64::consts::PI, piece > 0.0, at(t));
    }
}

/// The 3D circle arc (centre, radius, OCS of `normal`) from angle a0 over `sweep` (CCW in its
/// OCS), projected.
#[allow(clippy::too_many_arguments)]
fn circle_arc(
    d: &mut String,
    v: &View,
    center: DVec3,
    radius: f64,
    normal: DVec3,
    a0: f64,
    sweep: f64,
    start_new: bool,
) {
    let ocs = Ocs::new(normal);
    let at3 = |t: f64| ocs.on_circle(center, radius, t);
    match v.facing(normal) {
        Some(sign) => {
            // Facing the viewer the OCS axes map by a rotation (sign +1) or a reflection (-1).
            let c = v.project(center);
            let s = v.project(at3(a0)) - c;
            let start = s.y.atan2(s.x);
            view_arc(d, c, radius, start, sweep * sign, start_new);
        }
        None => {
            // An ellipse in this view: a fine polyline (within FLATNESS).
            if start_new {
                move_to(d, v.project(at3(a0)));
            }
            flatten(d, &|t| v.project(at3(t)), a0, a0 + sweep);
        }
    }
}

/// Path data of a polyline given in the OCS of `normal` at `elevation`.
fn ocs_polyline(
    d: &mut String,
    v: &View,
    points: &[DVec2],
    bulges: &[f64],
    closed: bool,
    elevation: f64,
    normal: DVec3,
) {
    let ocs = Ocs::new(normal);
    let to3 = |p: DVec2| ocs.to_wcs(p, elevation);
    move_to(d, v.project(to3(points[0])));
    for (a, b, bulge) in bulge_segments(points, bulges, closed) {
        match bulge_arc(a, b, bulge) {
            None => line_to(d, v.project(to3(b))),
            Some((c, r, a0, a1)) => {
                let c3 = to3(c);
                // The arc's OCS angle a0 is measured from `ocs.x`, which is exactly the OCS of
                // ocs.n.
                circle_arc(d, v, c3, r, ocs.n, a0, a1 - a0, false);
            }
        }
    }
    if closed {
        d.push_str(" Z");
    }
}

fn entity_path(e: &Entity, v: &View, beziers: &BezierSource) -> Option<String> {
    let mut d = String::new();
    match &e.kind {
        EntityKind::Line { p0, p1 } => {
            move_to(&mut d, v.project(*p0));
            line_to(&mut d, v.project(*p1));
        }
        EntityKind::Circle {
            center,
            radius,
            normal,
        } => {
            circle_arc(
                &mut d,
                v,
                *center,
                *radius,
                *normal,
                0.0,
                std::f64::consts::TAU,
                true,
            );
            d.push_str(" Z");
        }
        EntityKind::Arc {
            center,
            radius,
            start,
            end,
            normal,
        } => circle_arc(
            &mut d,
            v,
            *center,
            *radius,
            *normal,
            *start,
            ccw_sweep(*start, *end),
            true,
        ),
        EntityKind::Point { p } => {
            // A zero-length subpath with round caps renders as a dot of the stroke width.
            move_to(&mut d, v.project(*p));
            d.push_str(" h0");
        }
        EntityKind::LwPolyline {
            points,
            bulges,
            closed,
            elevation,
            normal,
        } => ocs_polyline(&mut d, v, points, bulges, *closed, *elevation, *normal),
        EntityKind::Polyline {
            points,
            bulges,
            closed,
        } => {
            let z = points[0].z;
            if is_flat(points) {
                let flat: Vec<DVec2> = points.iter().map(|p| p.truncate()).collect();
                ocs_polyline(&mut d, v, &flat, bulges, *closed, z, DVec3::Z);
            } else {
                move_to(&mut d, v.project(points[0]));
                for p in &points[1..] {
                    line_to(&mut d, v.project(*p));
                }
                if *closed {
                    d.push_str(" Z");
                }
            }
        }
        EntityKind::Spline { curve, .. } => {
            let pieces = beziers(curve);
            let exact = curve.weights.is_none() && curve.degree <= 3;
            for (i, (pts, _)) in pieces.iter().enumerate() {
                if i == 0 {
                    move_to(&mut d, v.project(pts[0]));
                }
                if exact {
                    d.push_str(match curve.degree {
                        1 => " L",
                        2 => " Q",
                        _ => " C",
                    });
                    for (k, p) in pts[1..].iter().enumerate() {
                        if k > 0 {
                            d.push(' ');
                        }
                        pt(&mut d, v.project(*p));
                    }
                }
            }
            if !exact {
                // Rational or degree > 3: SVG has no such curve; a fine polyline instead,
                // flattened span by span so every knot is a vertex.
                let mut spans: Vec<f64> = curve.knots[curve.degree..curve.ctrl.len() + 1].to_vec();
                spans.dedup();
                for w in spans.windows(2) {
                    flatten(&mut d, &|u| v.project(curve.eval_u(u)), w[0], w[1]);
                }
            }
        }
        EntityKind::Face3d { corners } => {
            move_to(&mut d, v.project(corners[0]));
            let n = if corners[3] == corners[2] { 3 } else { 4 };
            for c in &corners[1..n] {
                line_to(&mut d, v.project(*c));
            }
            d.push_str(" Z");
        }
        EntityKind::Text { .. } | EntityKind::Unmodelled { .. } => return None,
        EntityKind::Ellipse { .. } => {
            let pts = e.kind.ellipse_points(128);
            move_to(&mut d, v.project(pts[0]));
            for p in &pts[1..] {
                line_to(&mut d, v.project(*p));
            }
        }
        EntityKind::Mesh {
            vertices,
            triangles,
        } => {
            // Wireframe: every edge once.
            let mut edges: Vec<(usize, usize)> = triangles
                .iter()
                .flat_map(|t| [(t[0], t[1]), (t[1], t[2]), (t[2], t[0])])
                .map(|(a, b)| (a.min(b), a.max(b)))
                .filter(|(a, b)| a != b)
                .collect();
            edges.sort_unstable();
            edges.dedup();
            for (a, b) in edges {
                move_to(&mut d, v.project(vertices[a]));
                line_to(&mut d, v.project(vertices[b]));
            }
            if d.is_empty() {
                return None;
            }
        }
    }
    Some(d)
}

fn text_element(
    out: &mut String,
    (insert, height, value, rotation): (DVec3, f64, &str, f64),
    color: Option<&str>,
    v: &View,
) {
    let p = v.project(insert);
    let mut tf = String::from("translate(");
    pt(&mut tf, p);
    tf.push_str(") scale(1 -1)");
    if rotation != 0.0 {
        // Un-flipped (Y down) space: a negative SVG rotation turns counter-clockwise.
        tf.push_str(" rotate(");
        num(&mut tf, -rotation.to_degrees());
        tf.push(')');
    }
    let mut size = String::new();
    num(&mut size, height);
    let mut attrs = [
        ("transform", tf.as_str()),
        ("font-size", size.as_str()),
        ("font-family", "sans-serif"),
        ("stroke", "none"),
        ("fill", "currentColor"),
        ("color", color.unwrap_or_default()),
    ];
    let n = if color.is_some() { 6 } else { 5 };
    push_element(out, "text", &mut attrs[..n], value, true);
}

/// `<name attrs>` as the svg crate writes a start tag: attributes sorted by name, values
/// escaped.
fn push_start_tag(out: &mut String, name: &str, attrs: &mut [(&str, &str)]) {
    attrs.sort_by_key(|a| a.0);
    out.push('<');
    out.push_str(name);
    for (k, v) in attrs.iter() {
        out.push(' ');
        out.push_str(k);
        out.push_str("=\"");
        push_escaped(out, v, true);
        out.push('"');
    }
    out.push('>');
}

/// An element of one child as the svg crate writes a `Group` holding a `Blob` or a `Text`
/// (the child on a line of its own; a text's content escaped), the same bytes without the
/// crate's allocations for every attribute and escape, which a batch paid for every row.
fn push_element(
    out: &mut String,
    name: &str,
    attrs: &mut [(&str, &str)],
    child: &str,
    escape: bool,
) {
    push_start_tag(out, name, attrs);
    out.push('\n');
    if escape {
        push_escaped(out, child, false);
    } else {
        out.push_str(child);
    }
    out.push_str("\n</");
    out.push_str(name);
    out.push('>');
}

/// The svg crate's escaping in one pass: `&`, `<`, `>` in text, and quotes too in attribute
/// values (its successive replacements, `&` first, give the same bytes).
fn push_escaped(out: &mut String, s: &str, quotes: bool) {
    let special = |c: char| matches!(c, '&' | '<' | '>') || (quotes && matches!(c, '"' | '\''));
    if !s.contains(special) {
        out.push_str(s);
        return;
    }
    for c in s.chars() {
        match c {
            '&' => out.push_str("&amp;"),
            '<' => out.push_str("&lt;"),
            '>' => out.push_str("&gt;"),
            '"' if quotes => out.push_str("&quot;"),
            '\'' if quotes => out.push_str("&apos;"),
            c => out.push(c),
        }
    }
}

/// One drawing layer's part of the SVG: what its `<g>` is built from.
pub struct SvgLayer {
    /// The layer's name (the group's `inkscape:label`).
    pub name: String,
    /// Off or frozen: `display="none"` in the SVG.
    pub hidden: bool,
    id: String,
    color: String,
    body: String,
}

/// The SVG split by layer, so the PDF writer can put each layer in its own optional content
/// group; `to_svg` joins it into the document `write_svg` returns.
pub struct SvgLayers {
    /// The `<svg ...>` start tag (size, viewBox, namespaces).
    pub head: String,
    pub layers: Vec<SvgLayer>,
    stroke_width: String,
}

impl SvgLayers {
    /// Layer `i`'s `<g>` element; `show` draws it even when the layer is hidden.
    pub fn group(&self, i: usize, show: bool) -> String {
        let l = &self.layers[i];
        let mut attrs = [
            ("id", l.id.as_str()),
            ("inkscape:groupmode", "layer"),
            ("inkscape:label", l.name.as_str()),
            ("transform", "scale(1 -1)"),
            ("fill", "none"),
            ("stroke", l.color.as_str()),
            ("color", l.color.as_str()),
            ("stroke-width", self.stroke_width.as_str()),
            ("stroke-linecap", "round"),
            ("stroke-linejoin", "round"),
            ("display", "none"),
        ];
        let n = if l.hidden && !show { 11 } else { 10 };
        let mut out = String::with_capacity(l.body.len() + 400);
        push_element(&mut out, "g", &mut attrs[..n], &l.body, false);
        out
    }

    /// A whole SVG document of the head and the given groups.
    pub fn document<'a>(&self, groups: impl IntoIterator<Item = &'a str>) -> String {
        let mut s = self.head.clone();
        let mut any = false;
        for g in groups {
            s.push('\n');
            s.push_str(g);
            any = true;
        }
        if any {
            s.push_str("\n</svg>\n");
        } else {
            // The svg crate's empty element, as write_svg always wrote it.
            s.pop();
            s.push_str("/>\n");
        }
        s
    }

    /// The SVG document (every layer, hidden ones with `display="none"`).
    pub fn to_svg(&self) -> String {
        let groups: Vec<String> = (0..self.layers.len())
            .map(|i| self.group(i, false))
            .collect();
        self.document(groups.iter().map(String::as_str))
    }
}

/// The SVG document for the drawing (deterministic: same drawing and options, same bytes).
pub fn write_svg(d: &Drawing, opts: &OutputOptions) -> String {
    svg_layers(d, opts).to_svg()
}

/// The drawing's SVG, split by layer (layers without entities are left out).
pub fn svg_layers(d: &Drawing, opts: &OutputOptions) -> SvgLayers {
    svg_layers_prepared(&super::Prepared::new(d), opts)
}

/// `svg_layers` of a prepared drawing (its extents shared with the other formats).
pub fn svg_layers_prepared(p: &super::Prepared, opts: &OutputOptions) -> SvgLayers {
    let d = p.drawing;
    let v = View::new(opts.view_dir);
    let head = head(p, opts, &v);
    // Bucket entities by layer (layer table order, entities in insertion order).
    let layers = d.layers();
    let mut buckets: Vec<Vec<&Entity>> = vec![Vec::new(); layers.len()];
    for e in d.entities() {
        if let Some(i) = layers
            .iter()
            .position(|l| l.name.eq_ignore_ascii_case(&e.layer))
        {
            buckets[i].push(e);
        }
    }
    let mut stroke_width = String::new();
    num(&mut stroke_width, opts.stroke_width_mm / opts.unit_mm());
    let parts = layers
        .iter()
        .zip(&buckets)
        .enumerate()
        .filter(|(_, (_, ents))| !ents.is_empty())
        .map(|(i, (layer, ents))| SvgLayer {
            name: layer.name.clone(),
            hidden: layer.is_off() || layer.frozen,
            id: format!("layer{}", i + 1),
            color: aci_to_hex(layer.color),
            body: layer_body(ents, &v, &|c| p.beziers(c)),
        })
        .collect();
    SvgLayers {
        head,
        layers: parts,
        stroke_width,
    }
}

/// The `<svg>` start tag: physical size and viewBox from the extents in the view plane.
fn head(p: &super::Prepared, opts: &OutputOptions, v: &View) -> String {
    let (lo, hi) = view_extents(p, v);
    let unit = opts.unit_mm();
    let m = opts.margin.max(0.0) / unit;
    let (x0, y0) = (lo.x - m, -(hi.y + m));
    let (w, h) = (
        (hi.x - lo.x + 2.0 * m).max(1e-6),
        (hi.y - lo.y + 2.0 * m).max(1e-6),
    );
    let mut vb = String::new();
    for (i, x) in [x0, y0, w, h].into_iter().enumerate() {
        if i > 0 {
            vb.push(' ');
        }
        num(&mut vb, x);
    }
    // Physical size: an inch drawing is sized in inches, everything else in millimetres.
    let (per_unit, suffix) = if opts.insunits == 1 {
        (1.0, "in")
    } else {
        (unit, "mm")
    };
    let mm = |x: f64| {
        let mut s = String::new();
        num(&mut s, x * per_unit);
        s.push_str(suffix);
        s
    };
    let (width, height) = (mm(w), mm(h));
    let mut attrs = [
        ("xmlns", "http://www.w3.org/2000/svg"),
        (
            "xmlns:inkscape",
            "http://www.inkscape.org/namespaces/inkscape",
        ),
        ("version", "1.1"),
        ("width", width.as_str()),
        ("height", height.as_str()),
        ("viewBox", vb.as_str()),
    ];
    let mut s = String::new();
    push_start_tag(&mut s, "svg", &mut attrs);
    s
}

/// The extents in the view plane, (0, 0) twice for an empty drawing.
fn view_extents(p: &super::Prepared, v: &View) -> (DVec2, DVec2) {
    if v.right == DVec3::X && v.up == DVec3::Y {
        // Plan view: projecting is taking x and y (x·1 + y·0 + z·0 is x, up to the sign of a
        // zero, which no number written from here shows), so the box of the projected points
        // is the drawing's own box, shared with the DXF header.
        return match p.extents() {
            Some((lo, hi)) => (lo.truncate(), hi.truncate()),
            None => (DVec2::ZERO, DVec2::ZERO),
        };
    }
    projected_extents(p.drawing, v)
}

/// The box of every entity's extent points projected on the view plane.
fn projected_extents(d: &Drawing, v: &View) -> (DVec2, DVec2) {
    let mut lo = DVec2::splat(f64::INFINITY);
    let mut hi = DVec2::splat(f64::NEG_INFINITY);
    let mut pts = Vec::new();
    for e in d.entities() {
        pts.clear();
        e.kind.extent_points(&mut pts);
        for p in &pts {
            let q = v.project(*p);
            lo = lo.min(q);
            hi = hi.max(q);
        }
    }
    if !lo.is_finite() {
        return (DVec2::ZERO, DVec2::ZERO);
    }
    (lo, hi)
}

/// A layer's elements, serialized here into one string: the svg crate would copy and re-escape
/// every path's data (digits, spaces and command letters only, nothing to escape) several
/// times, which dominated writing large drawings. The bytes are the same as adding `Path` and
/// `Text` elements one by one (attributes in the crate's sorted order).
fn layer_body(ents: &[&Entity], v: &View, beziers: &BezierSource) -> String {
    let mut body = String::new();
    for e in ents {
        let own = match e.color {
            Some(c) if (1..=255).contains(&c) => Some(aci_to_hex(c)),
            _ => None,
        };
        if let EntityKind::Text {
            insert,
            height,
            value,
            rotation,
            ..
        } = &e.kind
        {
            if !body.is_empty() {
                body.push('\n');
            }
            let t = (*insert, *height, value.as_str(), *rotation);
            text_element(&mut body, t, own.as_deref(), v);
            continue;
        }
        if let Some(data) = entity_path(e, v, beziers) {
            if !body.is_empty() {
                body.push('\n');
            }
            body.push_str("<path d=\"");
            body.push_str(&data);
            body.push('"');
            if let Some(c) = &own {
                body.push_str(" stroke=\"");
                body.push_str(c);
                body.push('"');
            }
            body.push_str("/>");
        }
    }
    body
}

/// The usvg tree of an SVG this module wrote (for the PDF and PNG writers). Fonts are the
/// system's, loaded once per process and only when the SVG has text.
pub fn usvg_tree(svg: &str) -> Result<usvg::Tree, super::OutputError> {
    let mut opt = usvg::Options::default();
    if svg.contains("<text") {
        opt.fontdb = fonts();
    }
    usvg::Tree::from_str(svg, &opt).map_err(|e| super::OutputError::Convert(e.to_string()))
}

/// The process's font database, shared by the PDF, PNG and contact-sheet writers.
fn fonts() -> std::sync::Arc<usvg::fontdb::Database> {
    static FONTS: std::sync::OnceLock<std::sync::Arc<usvg::fontdb::Database>> =
        std::sync::OnceLock::new();
    FONTS
        .get_or_init(|| {
            let mut db = usvg::fontdb::Database::new();
            db.load_system_fonts();
            // fontdb's generic sans-serif is Arial; use the first sans family installed.
            let have = |f: &str| {
                db.faces()
                    .any(|face| face.families.iter().any(|x| x.0 == f))
            };
            let sans = [
                "DejaVu Sans",
                "Liberation Sans",
                "Noto Sans",
                "Arial",
                "Helvetica",
            ]
            .into_iter()
            .find(|f| have(f));
            if let Some(f) = sans {
                db.set_sans_serif_family(f);
                hold_in_memory(&mut db, f);
            }
            std::sync::Arc::new(db)
        })
        .clone()
}

/// Reads the files of `family`'s faces into memory. usvg and svg2pdf ask fontdb for a face's
/// bytes for every glyph they shape or embed, and for a file source fontdb opens and maps the
/// file each time: some 420 opens and maps per temple PDF, most of its cost. Faces of other
/// families (only used as fallbacks for missing glyphs) stay on disk.
fn hold_in_memory(db: &mut usvg::fontdb::Database, family: &str) {
    use usvg::fontdb::Source;
    let mut paths: Vec<std::path::PathBuf> = db
        .faces()
        .filter(|f| f.families.iter().any(|x| x.0 == family))
        .filter_map(|f| match &f.source {
            Source::File(p) => Some(p.clone()),
            _ => None,
        })
        .collect();
    paths.sort();
    paths.dedup();
    for path in paths {
        let Ok(bytes) = std::fs::read(&path) else {
            continue;
        };
        // Every face of the file (a collection may hold other families) is replaced.
        let ids: Vec<_> = db
            .faces()
            .filter(|f| matches!(&f.source, Source::File(p) if *p == path))
            .map(|f| f.id)
            .collect();
        for id in ids {
            db.remove_face(id);
        }
        db.load_font_data(bytes);
    }
}

#[cfg(test)]
mod tests;
