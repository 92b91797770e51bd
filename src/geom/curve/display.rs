//! How curves print: `#<LINE (0 0 0)-(1 1 0)>` and the like, with numbers as C's `%g`.

use std::f64::consts::TAU;
use std::fmt;

use glam::DVec3;

use super::Curve;

/// A number as C's `%g` prints it (6 significant digits), without a sign on zero: the printed
/// form of curves. Geometry keeps its own formatter: it knows nothing of the language.
pub fn fmt_g(x: f64) -> String {
    if x == 0.0 {
        return "0".into();
    }
    if !x.is_finite() {
        return if x.is_nan() {
            "nan"
        } else if x < 0.0 {
            "-inf"
        } else {
            "inf"
        }
        .into();
    }
    // The exponent after rounding to 6 digits decides the notation, as in C.
    let sci = format!("{x:.5e}");
    let (mantissa, exp) = sci.split_once('e').unwrap_or((&sci, "0"));
    let exp: i32 = exp.parse().unwrap_or(0);
    let trim = |s: &str| -> String {
        if s.contains('.') {
            s.trim_end_matches('0').trim_end_matches('.').to_string()
        } else {
            s.to_string()
        }
    };
    if (-4..6).contains(&exp) {
        trim(&format!("{:.*}", (5 - exp) as usize, x))
    } else {
        let sign = if exp < 0 { '-' } else { '+' };
        format!("{}e{sign}{:02}", trim(mantissa), exp.abs())
    }
}

fn fmt_pt(p: DVec3) -> String {
    format!("({} {} {})", fmt_g(p.x), fmt_g(p.y), fmt_g(p.z))
}

impl fmt::Display for Curve {
    /// `#<LINE (0 0 0)-(1 1 0)>`, `#<CIRCLE (0 0 0) R5>`, `#<ARC (0 0 0) R5 0 to 1.5708>`,
    /// `#<PLINE 4 closed>`, `#<SPLINE 5 points>`, `#<BSPLINE degree 3, 5 points>`.
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            Curve::Line(l) => write!(f, "#<LINE {}-{}>", fmt_pt(l.p0), fmt_pt(l.p1)),
            Curve::Circle(c) => {
                write!(f, "#<CIRCLE {} R{}>", fmt_pt(c.center()), fmt_g(c.radius()))
            }
            Curve::Arc(a) => write!(
                f,
                "#<ARC {} R{} {} to {}>",
                fmt_pt(a.center()),
                fmt_g(a.radius()),
                fmt_g(a.start_angle()),
                fmt_g(if a.sweep >= TAU {
                    a.start + TAU
                } else {
                    a.end_angle()
                })
            ),
            Curve::Polyline(p) => write!(
                f,
                "#<PLINE {} {}>",
                p.vertices.len(),
                if p.closed { "closed" } else { "open" }
            ),
            Curve::Spline(q) => write!(
                f,
                "#<SPLINE {} points{}>",
                q.points.len(),
                if q.closed { " closed" } else { "" }
            ),
            Curve::BSpline(b) => {
                write!(f, "#<BSPLINE degree {}, {} points>", b.degree, b.ctrl.len())
            }
            Curve::Ellipse(e) => write!(
                f,
                "#<ELLIPSE {} major {} ratio {}>",
                fmt_pt(e.center),
                fmt_pt(e.major),
                fmt_g(e.ratio)
            ),
        }
    }
}

#[cfg(test)]
mod tests {
    use super::fmt_g;

    #[test]
    fn fmt_g_matches_c() {
        for (x, want) in [
            (1.0, "1"),
            (0.5, "0.5"),
            (1.0 / 3.0, "0.333333"),
            (123456.0, "123456"),
            (1234567.0, "1.23457e+06"),
            (999999.5, "1e+06"),
            (1e-5, "1e-05"),
            (0.0001234567, "0.000123457"),
            (-2.5, "-2.5"),
            (-0.0, "0"),
        ] {
            assert_eq!(fmt_g(x), want, "{x}");
        }
    }
}
