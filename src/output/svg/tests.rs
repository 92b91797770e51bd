//! Unit tests of the SVG writer (kept beside it so svg.rs stays about the writer).

use super::*;

/// The integer path writes the bytes Ryū wrote for every number it takes: edges of its
/// range, trailing zeros, and a sweep of pseudo-random values over the range's decades.
#[test]
fn fixed_numbers_are_ryu_bytes() {
    let ryu_form = |r: f64| {
        let mut b = ryu::Buffer::new();
        let s = b.format_finite(r / 1e6);
        s.strip_suffix(".0").unwrap_or(s).to_string()
    };
    let mut rs = vec![
        1e5,
        1e15 - 1.0,
        123_456_789.0,
        100_000_000.0,
        999_999_999_999_999.0,
    ];
    let mut seed = 0x9E37_79B9_7F4A_7C15u64;
    for _ in 0..200_000 {
        seed ^= seed << 13;
        seed ^= seed >> 7;
        seed ^= seed << 17;
        let decade = 5 + (seed % 10) as i32;
        let frac = (seed >> 11) as f64 / (1u64 << 53) as f64;
        rs.push(
            (10f64.powi(decade) * (1.0 + 9.0 * frac))
                .round()
                .min(1e15 - 1.0),
        );
    }
    for r in rs {
        for r in [r, -r] {
            let mut s = String::new();
            fixed6(&mut s, r);
            assert_eq!(s, ryu_form(r), "r = {r}");
        }
    }
}

/// In plan view the SVG takes the drawing's own box (shared with the DXF header) instead
/// of projecting every extent point: the same box, for every kind of entity, negative
/// zeros and points off the plane included.
#[test]
fn plan_view_box_is_the_projected_box() {
    let mut d = Drawing::new();
    let v = View::new(DVec3::Z);
    assert_eq!((v.right, v.up), (DVec3::X, DVec3::Y));
    let p = super::super::Prepared::new(&d);
    assert_eq!(view_extents(&p, &v), (DVec2::ZERO, DVec2::ZERO));
    let kinds = [
        EntityKind::Line {
            p0: DVec3::new(-0.0, 0.0, 5.0),
            p1: DVec3::new(0.0, -0.0, -1e9),
        },
        EntityKind::Arc {
            center: DVec3::new(3.0, -2.0, 1.0),
            radius: 1.5,
            start: 0.3,
            end: 2.0,
            normal: DVec3::new(0.2, 0.1, 1.0).normalize(),
        },
        EntityKind::Circle {
            center: DVec3::new(-7.25, 1e-9, 0.0),
            radius: 0.125,
            normal: DVec3::Z,
        },
        EntityKind::Spline {
            curve: crate::geom::bspline::BSpline::new(
                2,
                vec![
                    DVec3::new(0.1, 0.2, 0.3),
                    DVec3::new(11.0, -13.0, 2.0),
                    DVec3::new(1e-7, 4.5, -3.0),
                    DVec3::new(-2.0, 8.0, 0.0),
                ],
                None,
                None,
            )
            .unwrap(),
            fit_points: Vec::new(),
            closed: false,
        },
    ];
    for k in kinds {
        d.add_kind(k).unwrap();
        let p = super::super::Prepared::new(&d);
        let (lo, hi) = view_extents(&p, &v);
        let (plo, phi) = projected_extents(&d, &v);
        assert_eq!((lo, hi), (plo, phi));
    }
    // The box grew past the first line's single projected point.
    let p = super::super::Prepared::new(&d);
    let (lo, hi) = view_extents(&p, &v);
    assert!(lo.x < -7.0 && hi.x > 3.0 && hi.y >= 8.0, "{lo} {hi}");
}

/// The hand-written elements are the svg crate's bytes: escaping in names, values and
/// text, the optional attributes, attribute order.
#[test]
fn elements_are_the_svg_crates_bytes() {
    use svg::node::element::{Group, Text};
    use svg::node::Blob;
    let tricky = ["plain", "a&b<c>d\"e'f", "", "&amp; é ' \" <<"];
    for name in tricky {
        for hidden in [false, true] {
            let mut attrs = vec![
                ("id", "layer1"),
                ("inkscape:label", name),
                ("stroke", "#ff0000"),
                ("transform", "scale(1 -1)"),
            ];
            let mut g = Group::new();
            for (k, v) in &attrs {
                g = g.set(*k, *v);
            }
            if hidden {
                attrs.push(("display", "none"));
                g = g.set("display", "none");
            }
            let body = format!("<path d=\"M0 0\"/>\n<text>{name}</text>");
            let mut mine = String::new();
            push_element(&mut mine, "g", &mut attrs, &body, false);
            assert_eq!(mine, g.add(Blob::new(body.clone())).to_string());
        }
        for color in [None, Some("#00ff00")] {
            let v = View::new(DVec3::Z);
            let mut mine = String::new();
            text_element(
                &mut mine,
                (DVec3::new(1.5, -2.0, 0.0), 2.5, name, 0.5),
                color,
                &v,
            );
            let mut t = Text::new(name)
                .set(
                    "transform",
                    "translate(1.5 -2) scale(1 -1) rotate(-28.64789)",
                )
                .set("font-size", "2.5")
                .set("font-family", "sans-serif")
                .set("stroke", "none")
                .set("fill", "currentColor");
            if let Some(c) = color {
                t = t.set("color", c);
            }
            assert_eq!(mine, t.to_string());
        }
    }
    let mut attrs = [("width", "1mm"), ("xmlns", "http://www.w3.org/2000/svg")];
    let mut mine = String::new();
    push_start_tag(&mut mine, "svg", &mut attrs);
    let mut doc = svg::Document::new().set("width", "1mm").to_string();
    doc.truncate(doc.len() - 2);
    assert_eq!(mine, doc + ">");
}

#[test]
fn numbers_are_compact() {
    let mut s = String::new();
    num(&mut s, -0.0000001);
    s.push(' ');
    num(&mut s, 1.5);
    s.push(' ');
    num(&mut s, 2.0);
    assert_eq!(s, "0 1.5 2");
}

#[test]
fn plan_arc_is_ccw_svg_arc() {
    let mut d = Drawing::new();
    d.add_kind(EntityKind::Arc {
        center: DVec3::ZERO,
        radius: 1.0,
        start: 0.0,
        end: std::f64::consts::FRAC_PI_2,
        normal: DVec3::Z,
    })
    .unwrap();
    let s = write_svg(&d, &OutputOptions::default());
    assert!(s.contains(r#"d="M1 0 A1 1 0 0 1 0 1""#), "{s}");
}

/// The extents and the SVG path share one decomposition per spline: `Prepared::beziers`
/// hands out the pieces of `to_beziers` (same bits), each curve decomposed once, two curves
/// kept apart; the extents computed through it are `Drawing::extents`.
#[test]
fn prepared_decomposes_each_spline_once() {
    let spline = |dx: f64| EntityKind::Spline {
        curve: crate::geom::bspline::BSpline::new(
            2,
            vec![
                DVec3::new(dx, 0.2, 0.0),
                DVec3::new(dx + 11.0, -13.0, 0.0),
                DVec3::new(dx + 1e-7, 4.5, 0.0),
                DVec3::new(dx - 2.0, 8.0, 0.0),
                DVec3::new(dx + 3.0, 9.0, 0.0),
            ],
            None,
            None,
        )
        .unwrap(),
        fit_points: Vec::new(),
        closed: false,
    };
    let mut d = Drawing::new();
    d.add_kind(spline(0.0)).unwrap();
    d.add_kind(spline(100.0)).unwrap();
    let p = super::super::Prepared::new(&d);
    assert_eq!(p.extents(), d.extents());
    let bits = |v: &[(Vec<DVec3>, Vec<f64>)]| -> Vec<u64> {
        v.iter()
            .flat_map(|(pts, ws)| {
                let c: Vec<f64> = pts.iter().flat_map(|q| q.to_array()).collect();
                c.into_iter()
                    .chain(ws.iter().copied())
                    .map(f64::to_bits)
                    .collect::<Vec<_>>()
            })
            .collect()
    };
    let curves: Vec<_> = d
        .entities()
        .map(|e| match &e.kind {
            EntityKind::Spline { curve, .. } => curve,
            _ => unreachable!(),
        })
        .collect();
    let first = p.beziers(curves[0]);
    let second = p.beziers(curves[1]);
    assert!(std::rc::Rc::ptr_eq(&first, &p.beziers(curves[0])));
    assert!(!std::rc::Rc::ptr_eq(&first, &second));
    assert_eq!(bits(&first), bits(&curves[0].to_beziers()));
    assert_eq!(bits(&second), bits(&curves[1].to_beziers()));
    assert_ne!(bits(&first), bits(&second));
}
