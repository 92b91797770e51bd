//! SVG output: renders with rsvg-convert without warnings, and every path, evaluated by the
//! small SVG path evaluator below (M, L, h, A, Q, C, Z), lies on the drawn geometry and covers
//! it (sampled both ways).

mod output_support;

use glam::{DVec2, DVec3};
use lispcad::geom::frame::arbitrary_axis;
use lispcad::output::{render, save, Drawing, Entity, EntityKind, Format, Layer, OutputOptions};
use output_support::*;

const TOL: f64 = 1e-4;

// ---------------------------------------------------------------- a tiny SVG reader

fn attr<'a>(tag: &'a str, name: &str) -> Option<&'a str> {
    let key = format!(" {name}=\"");
    let i = tag.find(&key)? + key.len();
    let j = tag[i..].find('"')? + i;
    Some(&tag[i..j])
}

/// (layer label, path data in order) for every layer group.
fn layer_paths(svg: &str) -> Vec<(String, Vec<String>)> {
    let mut out: Vec<(String, Vec<String>)> = Vec::new();
    for line in svg.lines() {
        if line.starts_with("<g ") {
            assert_eq!(attr(line, "inkscape:groupmode"), Some("layer"));
            assert_eq!(attr(line, "transform"), Some("scale(1 -1)"));
            out.push((attr(line, "inkscape:label").unwrap().to_string(), vec![]));
        } else if line.starts_with("<path ") {
            out.last_mut()
                .unwrap()
                .1
                .push(attr(line, "d").unwrap().to_string());
        }
    }
    out
}

fn tokens(d: &str) -> Vec<String> {
    let mut t = Vec::new();
    let mut cur = String::new();
    for c in d.chars() {
        if c.is_ascii_alphabetic() && c != 'e' {
            if !cur.is_empty() {
                t.push(std::mem::take(&mut cur));
            }
            t.push(c.to_string());
        } else if c == ' ' || c == ',' {
            if !cur.is_empty() {
                t.push(std::mem::take(&mut cur));
            }
        } else {
            cur.push(c);
        }
    }
    if !cur.is_empty() {
        t.push(cur);
    }
    t
}

/// The SVG arc from p1 to p2 (circular, no rotation), per SVG 1.1 appendix F.6.5.
fn svg_arc(p1: DVec2, r: f64, large: bool, sweep: bool, p2: DVec2, n: usize) -> Vec<DVec2> {
    let h = (p1 - p2) / 2.0;
    let mut r = r;
    let lambda = h.length_squared() / (r * r);
    if lambda > 1.0 {
        r *= lambda.sqrt();
    }
    let num = (r * r * r * r - r * r * h.y * h.y - r * r * h.x * h.x).max(0.0);
    let den = r * r * h.y * h.y + r * r * h.x * h.x;
    let sign = if large != sweep { 1.0 } else { -1.0 };
    let coef = sign * (num / den).sqrt();
    let cp = DVec2::new(coef * h.y, -coef * h.x);
    let c = cp + (p1 + p2) / 2.0;
    let u = (h - cp) / r;
    let v = (-h - cp) / r;
    let t1 = u.y.atan2(u.x);
    let mut dt = u.perp_dot(v).atan2(u.dot(v));
    if !sweep && dt > 0.0 {
        dt -= std::f64::consts::TAU;
    } else if sweep && dt < 0.0 {
        dt += std::f64::consts::TAU;
    }
    (0..=n)
        .map(|i| {
            let t = t1 + dt * i as f64 / n as f64;
            c + DVec2::new(t.cos(), t.sin()) * r
        })
        .collect()
}

/// Straight pieces are sampled every 0.05 units (the reverse check uses their segments).
fn line_samples(a: DVec2, b: DVec2) -> usize {
    ((b - a).length() / 0.05).ceil().max(1.0) as usize
}

/// Sampled subpaths of a path's data.
fn eval_path(d: &str) -> Vec<Vec<DVec2>> {
    const N: usize = 1000;
    let t = tokens(d);
    let mut i = 0;
    let num = |i: &mut usize| -> f64 {
        let v: f64 = t[*i]
            .parse()
            .unwrap_or_else(|_| panic!("bad number {:?} in {d}", t[*i]));
        *i += 1;
        v
    };
    let mut subs: Vec<Vec<DVec2>> = Vec::new();
    let mut cur = DVec2::ZERO;
    let mut start = DVec2::ZERO;
    while i < t.len() {
        let cmd = t[i].clone();
        i += 1;
        match cmd.as_str() {
            "M" => {
                cur = DVec2::new(num(&mut i), num(&mut i));
                start = cur;
                subs.push(vec![cur]);
            }
            "L" => {
                let p = DVec2::new(num(&mut i), num(&mut i));
                let s = subs.last_mut().unwrap();
                let n = line_samples(cur, p);
                s.extend((1..=n).map(|k| cur.lerp(p, k as f64 / n as f64)));
                cur = p;
            }
            "h" => {
                let p = cur + DVec2::new(num(&mut i), 0.0);
                subs.last_mut().unwrap().push(p);
                cur = p;
            }
            "A" => {
                let r = num(&mut i);
                let r2 = num(&mut i);
                assert_eq!(r, r2, "circular arcs only");
                assert_eq!(num(&mut i), 0.0);
                let large = num(&mut i) != 0.0;
                let sweep = num(&mut i) != 0.0;
                let p = DVec2::new(num(&mut i), num(&mut i));
                let pts = svg_arc(cur, r, large, sweep, p, N);
                subs.last_mut().unwrap().extend(&pts[1..]);
                cur = p;
            }
            "Q" => {
                let c = DVec2::new(num(&mut i), num(&mut i));
                let p = DVec2::new(num(&mut i), num(&mut i));
                let s = subs.last_mut().unwrap();
                for k in 1..=N {
                    let u = k as f64 / N as f64;
                    s.push(cur * (1.0 - u) * (1.0 - u) + c * 2.0 * u * (1.0 - u) + p * u * u);
                }
                cur = p;
            }
            "C" => {
                let c1 = DVec2::new(num(&mut i), num(&mut i));
                let c2 = DVec2::new(num(&mut i), num(&mut i));
                let p = DVec2::new(num(&mut i), num(&mut i));
                let s = subs.last_mut().unwrap();
                for k in 1..=N {
                    let u = k as f64 / N as f64;
                    let w = 1.0 - u;
                    s.push(
                        cur * w * w * w
                            + c1 * 3.0 * u * w * w
                            + c2 * 3.0 * u * u * w
                            + p * u * u * u,
                    );
                }
                cur = p;
            }
            "Z" => {
                let s = subs.last_mut().unwrap();
                let n = line_samples(cur, start);
                s.extend((1..=n).map(|k| cur.lerp(start, k as f64 / n as f64)));
                cur = start;
            }
            other => panic!("unexpected path command {other:?} in {d}"),
        }
    }
    subs
}

// ---------------------------------------------------------------- reference geometry

/// Reference polylines of an entity seen along `view` (orthographic onto arbitrary_axis(view)).
fn reference(e: &EntityKind, view: DVec3) -> Vec<Vec<DVec2>> {
    let (rx, ry) = arbitrary_axis(view);
    let pr = |p: DVec3| DVec2::new(p.dot(rx), p.dot(ry));
    let circle3 = |c: DVec3, r: f64, n: DVec3, a0: f64, sw: f64| {
        let (ax, ay) = arbitrary_axis(n);
        dense(
            |s| pr(c + (ax * (a0 + sw * s).cos() + ay * (a0 + sw * s).sin()) * r),
            4000,
        )
    };
    let tau = std::f64::consts::TAU;
    match e {
        EntityKind::Line { p0, p1 } => vec![vec![pr(*p0), pr(*p1)]],
        EntityKind::Circle {
            center,
            radius,
            normal,
        } => vec![circle3(*center, *radius, *normal, 0.0, tau)],
        EntityKind::Arc {
            center,
            radius,
            start,
            end,
            normal,
        } => {
            let mut sw = (end - start).rem_euclid(tau);
            if sw == 0.0 {
                sw = tau;
            }
            vec![circle3(*center, *radius, *normal, *start, sw)]
        }
        EntityKind::Point { p } => vec![vec![pr(*p)]],
        EntityKind::LwPolyline {
            points,
            bulges,
            closed,
            elevation,
            normal,
        } => {
            assert_eq!(*normal, DVec3::Z, "reference handles plan polylines");
            let _ = elevation;
            let n = points.len();
            let segs = if *closed { n } else { n - 1 };
            (0..segs)
                .map(|i| {
                    bulge_ref(
                        points[i],
                        points[(i + 1) % n],
                        bulges.get(i).copied().unwrap_or(0.0),
                    )
                })
                .collect()
        }
        EntityKind::Polyline {
            points,
            bulges,
            closed,
        } => {
            let flat = points.iter().all(|p| p.z == points[0].z);
            let n = points.len();
            let segs = if *closed { n } else { n - 1 };
            (0..segs)
                .map(|i| {
                    let b = if flat {
                        bulges.get(i).copied().unwrap_or(0.0)
                    } else {
                        0.0
                    };
                    bulge_ref(pr(points[i]), pr(points[(i + 1) % n]), b)
                })
                .collect()
        }
        EntityKind::Spline { curve, .. } => {
            let (a, b) = curve.domain();
            vec![dense(|s| pr(curve.eval_u(a + (b - a) * s)), 4000)]
        }
        EntityKind::Face3d { corners } => {
            let mut c: Vec<DVec2> = corners.iter().map(|p| pr(*p)).collect();
            c.push(c[0]);
            vec![c]
        }
        EntityKind::Mesh {
            vertices,
            triangles,
        } => triangles
            .iter()
            .flat_map(|t| [(t[0], t[1]), (t[1], t[2]), (t[2], t[0])])
            .map(|(a, b)| vec![pr(vertices[a]), pr(vertices[b])])
            .collect(),
        EntityKind::Text { .. } | EntityKind::Unmodelled { .. } => vec![],
        EntityKind::Ellipse { .. } => vec![e.ellipse_points(4000).into_iter().map(pr).collect()],
    }
}

/// Every drawn (non-text) entity's path lies on its geometry and covers it.
fn check_paths(d: &Drawing, opts: &OutputOptions) {
    let svg = String::from_utf8(render(d, Format::Svg, opts).unwrap()).unwrap();
    let groups = layer_paths(&svg);
    for (label, paths) in &groups {
        let ents: Vec<&Entity> = d
            .entities()
            .filter(|e| &e.layer == label && !matches!(e.kind, EntityKind::Text { .. }))
            .collect();
        assert_eq!(
            ents.len(),
            paths.len(),
            "layer {label}: one path per entity"
        );
        for (e, p) in ents.iter().zip(paths) {
            let got = eval_path(p);
            let want = reference(&e.kind, opts.view_dir);
            let (want_ix, got_ix) = (SegIndex::new(&want), SegIndex::new(&got));
            for q in got.iter().flatten() {
                let dist = want_ix.dist(*q);
                assert!(
                    dist <= TOL,
                    "{:?}: svg point {q} is {dist} off (path {p})",
                    e.kind
                );
            }
            for q in want.iter().flatten() {
                let dist = got_ix.dist(*q);
                assert!(
                    dist <= TOL,
                    "{:?}: geometry point {q} not drawn ({dist}; path {p})",
                    e.kind
                );
            }
        }
    }
}

fn write_and_render(d: &Drawing, opts: &OutputOptions, name: &str) -> String {
    let dir = tempfile::tempdir().unwrap();
    let svg = dir.path().join(format!("{name}.svg"));
    save(d, &svg, opts).unwrap();
    render_svg(&svg, &dir.path().join(format!("{name}.png")));
    std::fs::read_to_string(&svg).unwrap()
}

#[test]
fn mixed_drawing_paths_follow_the_geometry() {
    check_paths(&mixed_drawing(), &OutputOptions::default());
}

#[test]
fn oblique_view_projects_everything_orthographically() {
    let opts = OutputOptions {
        view_dir: DVec3::new(1.0, -1.0, 1.0),
        ..OutputOptions::default()
    };
    let mut d = Drawing::new();
    d.add_kind(EntityKind::Mesh {
        vertices: vec![
            DVec3::new(0.0, 0.0, 0.0),
            DVec3::new(10.0, 0.0, 0.0),
            DVec3::new(10.0, 10.0, 4.0),
            DVec3::new(0.0, 10.0, 4.0),
        ],
        triangles: vec![[0, 1, 2], [0, 2, 3]],
    })
    .unwrap();
    // Seen obliquely a circle is an ellipse (polyline); its plane's normal along the view
    // keeps it an exact arc.
    d.add_kind(EntityKind::Circle {
        center: DVec3::new(5.0, 5.0, 0.0),
        radius: 3.0,
        normal: DVec3::Z,
    })
    .unwrap();
    d.add_kind(EntityKind::Arc {
        center: DVec3::new(-5.0, 5.0, 2.0),
        radius: 2.0,
        start: 0.5,
        end: 4.0,
        normal: DVec3::new(1.0, -1.0, 1.0),
    })
    .unwrap();
    d.add_kind(EntityKind::Spline {
        curve: cubic_s(),
        fit_points: vec![],
        closed: false,
    })
    .unwrap();
    check_paths(&d, &opts);
    let svg = write_and_render(&d, &opts, "oblique");
    assert!(svg.contains(" A2 2 0 "), "the facing arc stays an SVG arc");
}

#[test]
fn every_svg_renders_without_warnings() {
    let opts = OutputOptions::default();
    write_and_render(&mixed_drawing(), &opts, "mixed");
    write_and_render(&Drawing::new(), &opts, "empty");
    let mut d = Drawing::new();
    d.set_layer_record(Layer {
        color: -3,
        ..Layer::new("hidden & layer")
    })
    .unwrap();
    d.add(Entity::new(
        "hidden & layer",
        EntityKind::Text {
            insert: DVec3::ZERO,
            height: 3.0,
            value: "a < b & c > \"d\" — é".into(),
            rotation: 0.3,
            style: "Standard".into(),
        },
    ))
    .unwrap();
    let svg = write_and_render(&d, &opts, "escaped");
    assert!(svg.contains("display=\"none\""), "an off layer is hidden");
}

#[test]
fn document_is_in_millimetres_with_one_flip_per_layer() {
    let d = mixed_drawing();
    let opts = OutputOptions::default();
    let svg = String::from_utf8(render(&d, Format::Svg, &opts).unwrap()).unwrap();
    let root = svg.lines().next().unwrap();
    let (lo, hi) = d.extents().unwrap();
    let m = opts.margin;
    let vb: Vec<f64> = attr(root, "viewBox")
        .unwrap()
        .split(' ')
        .map(|x| x.parse().unwrap())
        .collect();
    assert!((vb[0] - (lo.x - m)).abs() < 1e-6);
    assert!(
        (vb[1] + (hi.y + m)).abs() < 1e-6,
        "Y flipped: the top is -(max y + margin)"
    );
    assert!((vb[2] - (hi.x - lo.x + 2.0 * m)).abs() < 1e-6);
    assert!((vb[3] - (hi.y - lo.y + 2.0 * m)).abs() < 1e-6);
    assert_eq!(attr(root, "width").unwrap(), format!("{}mm", vb[2]));
    assert_eq!(attr(root, "height").unwrap(), format!("{}mm", vb[3]));
    assert_eq!(
        attr(root, "xmlns:inkscape"),
        Some("http://www.inkscape.org/namespaces/inkscape")
    );
    let groups = layer_paths(&svg);
    let labels: Vec<&str> = groups.iter().map(|g| g.0.as_str()).collect();
    assert_eq!(labels, ["0", "Outline", "Construction"]);
    assert_eq!(
        svg.matches("scale(1 -1)").count(),
        3 + 1,
        "3 layer flips + 1 text un-flip"
    );
    // Quadratic splines as Q (2 pieces each), cubic as C, rational as a polyline.
    let outline = &groups[1].1;
    assert_eq!(outline[5].matches('C').count(), 2);
    assert_eq!(outline[6].matches('Q').count(), 2);
    assert_eq!(outline[7].matches('Q').count(), 4);
    assert!(!outline[8].contains('Q') && !outline[8].contains('C'));
    // Colours: layer colour on the group, override on the entity.
    assert!(svg.contains("stroke=\"#ff0000\""));
    assert!(svg.contains("stroke=\"#00ff00\""), "colour 3 override");
    assert!(svg.contains("stroke-width=\"0.25\""));
}

#[test]
fn svg_is_deterministic() {
    let d = mixed_drawing();
    let o = OutputOptions::default();
    assert_eq!(
        render(&d, Format::Svg, &o).unwrap(),
        render(&d, Format::Svg, &o).unwrap()
    );
}
