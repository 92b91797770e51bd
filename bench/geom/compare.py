#!/usr/bin/env python3
"""Curve/curve intersection throughput: lispcad vs ezdxf vs OCCT (issue 3, item 4).

The pairs are the ones benches/geom_intersect.rs uses (the same xorshift generator, the
same draw order), so every library intersects exactly the same geometry. Rates are pairs per
CPU-second (process time), which stays meaningful on a shared, loaded machine.

    /work/main/.venv/bin/python bench/geom/compare.py            # runs cargo bench too
    /work/main/.venv/bin/python bench/geom/compare.py --no-cargo # peers only

lispcad's figures come from the CPU-time pre-pass of `cargo bench --bench geom_intersect`.
ezdxf has no 3D arc/arc and no Bézier/Bézier intersection: arc/arc is "n/a" and
spline/spline intersects the curves flattened to 1e-6 (approximate points).
OCCT: Geom2dAPI_InterCurveCurve for the planar pairs, GeomAPI_ExtremaCurveCurve for 3D arcs.
"""
import math
import os
import re
import subprocess
import sys
import time

N = 256
MASK = (1 << 64) - 1


class Rng:
    def __init__(self, seed=0x9E3779B97F4A7C15):
        self.s = seed

    def f(self):
        s = self.s
        s ^= (s << 13) & MASK
        s ^= s >> 7
        s ^= (s << 17) & MASK
        self.s = s
        return (s >> 11) / float(1 << 53)

    def pt(self, k):
        return (self.f() * k, self.f() * k, self.f() * k)

    def pt2(self, k):
        return (self.f() * k, self.f() * k, 0.0)


def add(a, b): return tuple(x + y for x, y in zip(a, b))
def sub(a, b): return tuple(x - y for x, y in zip(a, b))
def mul(a, k): return tuple(x * k for x in a)
def dot(a, b): return sum(x * y for x, y in zip(a, b))
def cross(a, b): return (a[1]*b[2]-a[2]*b[1], a[2]*b[0]-a[0]*b[2], a[0]*b[1]-a[1]*b[0])
def norm(a): return math.sqrt(dot(a, a))
def unit(a): return mul(a, 1.0 / norm(a))


def ocs_x(n):
    """DXF arbitrary-axis X for normal n (as src/geom/frame.rs)."""
    n = unit(n)
    if abs(n[0]) < 1/64 and abs(n[1]) < 1/64:
        return unit(cross((0, 1, 0), n))
    return unit(cross((0, 0, 1), n))


def pairs(kind):
    r = Rng()
    out = []
    while len(out) < N:
        if kind == "line/line":
            p = r.pt(10.0); d1 = sub(r.pt(1.0), (0.5,)*3); d2 = sub(r.pt(1.0), (0.5,)*3)
            out.append((("line", sub(p, d1), add(p, d1)), ("line", sub(p, d2), add(p, mul(d2, 2.0)))))
        elif kind == "line/circle":
            c = r.pt2(10.0); a = r.pt2(10.0)
            out.append((("line", a, add(c, mul(sub(c, a), 0.3))), ("circle", c, 1.0 + r.f() * 3.0)))
        elif kind == "circle/circle":
            c = r.pt2(10.0)
            r1 = 2.0 + r.f()
            c2 = add(c, r.pt2(3.0))
            r2 = 1.0 + r.f() * 2.0
            out.append((("circle", c, r1), ("circle", c2, r2)))
        elif kind == "arc/arc 3D":
            a = r.pt(10.0); b = r.pt(10.0)
            ab = sub(b, a); m = mul(add(a, b), 0.5)
            perp = lambda n: unit(sub(n, mul(ab, dot(n, ab) / dot(ab, ab))))
            n1 = perp(sub(r.pt(1.0), (0.5,)*3)); n2 = perp(sub(r.pt(1.0), (0.5,)*3))
            c1 = add(m, mul(unit(cross(n1, ab)), r.f() * 4.0 - 2.0))
            c2 = add(m, mul(unit(cross(n2, ab)), r.f() * 4.0 - 2.0))
            arc1 = ("arc", c1, norm(sub(a, c1)), r.f() * 6.0, r.f() * 6.0, n1)
            arc2 = ("arc", c2, norm(sub(a, c2)), r.f() * 6.0, r.f() * 6.0, n2)
            out.append((arc1, arc2))
        elif kind == "spline/line":
            ctrl = [(float(i), (r.f() - 0.5) * 4.0, 0.0) for i in range(7)]
            y = (r.f() - 0.5) * 2.0
            out.append((("bspline", ctrl), ("line", (-1.0, y, 0.0), (7.0, y + r.f() - 0.5, 0.0))))
        elif kind == "cubic spline/spline (9 roots)":
            bp = [-0.229, 3.011, -2.449, 1.391]
            bq = [-1.18432, 5.153146666666666, -3.49272, 1.87808]
            j = (r.f() - 0.5) * 1e-3
            pa = [(i / 3.0, bp[i] + j, 0.0) for i in range(4)]
            pb = [(bq[i] - j, i / 3.0, 0.0) for i in range(4)]
            out.append((("bspline", pa), ("bspline", pb)))
    return out


KINDS = ["line/line", "line/circle", "circle/circle", "arc/arc 3D", "spline/line",
         "cubic spline/spline (9 roots)"]


def rate(fn, prepared):
    """Pairs per CPU-second and hits per pass."""
    hits = sum(fn(a, b) for a, b in prepared)
    t0 = time.process_time(); n = 0
    while True:
        for a, b in prepared:
            fn(a, b)
        n += len(prepared)
        dt = time.process_time() - t0
        if dt > 0.5:
            return n / dt, hits


def ezdxf_case(kind):
    import ezdxf.math as m
    ps = pairs(kind)
    if kind == "line/line":
        prep = [((m.Vec3(a[1]), m.Vec3(a[2])), (m.Vec3(b[1]), m.Vec3(b[2]))) for a, b in ps]
        fn = lambda a, b: int(m.intersection_line_line_3d(a, b, virtual=False, abs_tol=1e-9) is not None)
    elif kind == "line/circle":
        prep = [(m.ConstructionLine(a[1], a[2]), m.ConstructionCircle(b[1], b[2])) for a, b in ps]
        fn = lambda l, c: len(c.intersect_line(l, abs_tol=1e-9))
    elif kind == "circle/circle":
        prep = [(m.ConstructionCircle(a[1], a[2]), m.ConstructionCircle(b[1], b[2])) for a, b in ps]
        fn = lambda x, y: len(x.intersect_circle(y, abs_tol=1e-9))
    elif kind == "spline/line":
        def prepare(a, b):
            return (m.BSpline([m.Vec3(p) for p in a[1]], order=4), (m.Vec2(b[1]), m.Vec2(b[2])))
        prep = [prepare(a, b) for a, b in ps]

        def fn(s, l):
            lo, hi = min(l[0].x, l[1].x), max(l[0].x, l[1].x)
            n = 0
            for bez in s.bezier_decomposition():
                for p in m.intersection_ray_cubic_bezier_2d(l[0], l[1], m.Bezier4P(bez)):
                    n += lo - 1e-9 <= p.x <= hi + 1e-9
            return n
    elif kind.startswith("cubic"):
        prep = [(m.Bezier4P([m.Vec3(p) for p in a[1]]), m.Bezier4P([m.Vec3(p) for p in b[1]])) for a, b in ps]

        def fn(x, y):
            return len(m.intersect_polylines_2d(
                [m.Vec2(p) for p in x.flattening(1e-6)], [m.Vec2(p) for p in y.flattening(1e-6)]))
    else:
        return None
    return rate(fn, prep)


def occt_case(kind):
    try:
        from OCP.gp import gp_Pnt2d, gp_Dir2d, gp_Ax2d, gp_Pnt, gp_Dir, gp_Ax2, gp_Circ2d, gp_Circ
        from OCP.Geom2d import Geom2d_Line, Geom2d_TrimmedCurve, Geom2d_Circle, Geom2d_BSplineCurve
        from OCP.Geom import Geom_Circle, Geom_TrimmedCurve, Geom_Line
        from OCP.Geom2dAPI import Geom2dAPI_InterCurveCurve
        from OCP.GeomAPI import GeomAPI_ExtremaCurveCurve
        try:
            from OCP.TColgp import TColgp_Array1OfPnt2d
            from OCP.TColStd import TColStd_Array1OfReal, TColStd_Array1OfInteger
        except ImportError:  # OCP >= 7.8 exposes NCollection arrays as OCP.collections
            from OCP.collections import Array1_gp_Pnt2d as TColgp_Array1OfPnt2d
            from OCP.collections import Array1_double as TColStd_Array1OfReal
            from OCP.collections import Array1_int as TColStd_Array1OfInteger
    except ImportError:
        return None
    ps = pairs(kind)

    def seg2d(a, b):
        d = (b[0] - a[0], b[1] - a[1]); L = math.hypot(*d)
        line = Geom2d_Line(gp_Pnt2d(a[0], a[1]), gp_Dir2d(d[0] / L, d[1] / L))
        return Geom2d_TrimmedCurve(line, 0.0, L)

    def circ2d(c, r):
        return Geom2d_Circle(gp_Circ2d(gp_Ax2d(gp_Pnt2d(c[0], c[1]), gp_Dir2d(1, 0)), r))

    def bspline2d(ctrl):
        n = len(ctrl); deg = 3
        poles = TColgp_Array1OfPnt2d(1, n)
        for i, p in enumerate(ctrl):
            poles.SetValue(i + 1, gp_Pnt2d(p[0], p[1]))
        spans = n - deg
        knots = TColStd_Array1OfReal(1, spans + 1); mults = TColStd_Array1OfInteger(1, spans + 1)
        for i in range(spans + 1):
            knots.SetValue(i + 1, i / spans)
            mults.SetValue(i + 1, deg + 1 if i in (0, spans) else 1)
        return Geom2d_BSplineCurve(poles, knots, mults, deg)

    def curve2d(c):
        if c[0] == "line":
            return seg2d(c[1], c[2])
        if c[0] == "circle":
            return circ2d(c[1], c[2])
        return bspline2d(c[1])

    if kind == "arc/arc 3D":
        def arc3d(c):
            _, ctr, r, a0, a1, n = c
            x = ocs_x(n)
            ax = gp_Ax2(gp_Pnt(*ctr), gp_Dir(*n), gp_Dir(*x))
            sweep = (a1 - a0) % (2 * math.pi)
            return Geom_TrimmedCurve(Geom_Circle(gp_Circ(ax, r)), a0, a0 + sweep)
        prep = [(arc3d(a), arc3d(b)) for a, b in ps]

        def fn(x, y):
            e = GeomAPI_ExtremaCurveCurve(x, y)
            return sum(1 for i in range(1, e.NbExtrema() + 1) if e.Distance(i) <= 1e-9)
    else:
        prep = [(curve2d(a), curve2d(b)) for a, b in ps]

        def fn(x, y):
            return Geom2dAPI_InterCurveCurve(x, y, 1e-9).NbPoints()
    return rate(fn, prep)


def lispcad_rates(repo):
    out = subprocess.run(["cargo", "bench", "--bench", "geom_intersect", "--", "--test"],
                         cwd=repo, capture_output=True, text=True)
    rates = {}
    for line in (out.stdout + out.stderr).splitlines():
        mm = re.match(r"(.+): (\d+) hits over \d+ pairs; ([0-9.e+-]+) pairs per CPU-second", line)
        if mm:
            rates[mm.group(1)] = (float(mm.group(3)), int(mm.group(2)))
    return rates


def main():
    repo = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
    ours = {} if "--no-cargo" in sys.argv else lispcad_rates(repo)
    fmt = lambda r: "n/a" if r is None else f"{r[0]:.3g} ({r[1]})"
    print(f"{'pair':32} {'lispcad pairs/s (hits)':>24} {'ezdxf':>20} {'OCCT':>20} {'vs ezdxf':>9} {'vs OCCT':>8}")
    for kind in KINDS:
        o = ours.get(kind)
        e = ezdxf_case(kind)
        c = occt_case(kind)
        ratio = lambda p: "" if (o is None or p is None) else f"{o[0] / p[0]:.0f}x"
        print(f"{kind:32} {fmt(o):>24} {fmt(e):>20} {fmt(c):>20} {ratio(e):>9} {ratio(c):>8}")
    print(f"({N} pairs per kind; rates are pairs per CPU-second; hits = points found per pass)")


if __name__ == "__main__":
    main()
