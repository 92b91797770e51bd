"""The vlax-curve benchmark in Python + ezdxf: the same drawing (a 40-vertex bulged LWPOLYLINE,
a 30-point cubic SPLINE) and the same 100,000 queries: distance at a parameter and point at a
distance, each computed from the entity on every call as vlax-curve does (LWPOLYLINE: segment
lengths from the bulges with ezdxf.math; SPLINE: arc length by 16-point Gauss-Legendre per
knot span on ezdxf's B-spline derivatives, inverted by Newton)."""
import math
import sys

import ezdxf
import numpy as np
from ezdxf.math import bulge_center, bulge_radius, Vec2

GX, GW = np.polynomial.legendre.leggauss(16)


def make_doc():
    doc = ezdxf.new()
    msp = doc.modelspace()
    pts = [(i * 2.0, 3.0 * math.sin(i * 0.4), 0, 0, 0.25 if i % 3 == 0 else 0.0) for i in range(40)]
    pl = msp.add_lwpolyline(pts, format='xyseb')
    ctrl = [(i * 1.5, 4.0 * math.cos(i * 0.3), 0.5 * math.sin(i * 0.7)) for i in range(30)]
    knots = [0.0] * 4 + [float(i) for i in range(1, 27)] + [27.0] * 4
    sp = msp.add_open_spline(ctrl, degree=3, knots=knots)
    return pl, sp


def pline_segments(e):
    pts = list(e.get_points('xyb'))
    segs = []
    for (x0, y0, b), (x1, y1, _) in zip(pts[:-1], pts[1:]):
        p, q = Vec2(x0, y0), Vec2(x1, y1)
        if b == 0.0:
            segs.append(('l', p, q, (q - p).magnitude))
        else:
            c, r = bulge_center(p, q, b), bulge_radius(p, q, b)
            sweep = 4.0 * math.atan(b)
            segs.append(('a', c, r, math.atan2(p.y - c.y, p.x - c.x), sweep, abs(sweep) * r))
    return segs


def pline_dist_at_param(e, u):
    segs = pline_segments(e)
    i = min(int(u), len(segs) - 1)
    f = u - i
    return sum(s[-1] for s in segs[:i]) + f * segs[i][-1]


def pline_point_at_dist(e, d):
    for s in pline_segments(e):
        if d <= s[-1]:
            f = d / s[-1]
            if s[0] == 'l':
                return s[1] + (s[2] - s[1]) * f
            a = s[3] + f * s[4]
            return Vec2(s[1].x + s[2] * math.cos(a), s[1].y + s[2] * math.sin(a))
        d -= s[-1]
    return s[2]


def span_length(bs, a, b):
    xs = 0.5 * (b - a) * GX + 0.5 * (b + a)
    return 0.5 * (b - a) * sum(w * bs.derivative(x, 1)[1].magnitude for x, w in zip(xs, GW))


def spline_dist_at_param(e, u):
    bs = e.construction_tool()
    ks = sorted(set(bs.knots()))
    total = 0.0
    for a, b in zip(ks[:-1], ks[1:]):
        if u <= a:
            break
        total += span_length(bs, a, min(b, u))
    return total


def spline_point_at_dist(e, d):
    bs = e.construction_tool()
    ks = sorted(set(bs.knots()))
    for a, b in zip(ks[:-1], ks[1:]):
        l = span_length(bs, a, b)
        if d <= l or b == ks[-1]:
            u = a + (b - a) * d / l
            for _ in range(8):
                err = span_length(bs, a, u) - d
                u -= err / bs.derivative(u, 1)[1].magnitude
            return bs.point(u)
        d -= l


def main():
    n = int(sys.argv[1]) if len(sys.argv) > 1 else 25000
    pl, sp = make_doc()
    total = 0.0
    for e, dist_at, point_at, end in (
            (pl, pline_dist_at_param, pline_point_at_dist, 39.0),
            (sp, spline_dist_at_param, spline_point_at_dist, 27.0)):
        length = dist_at(e, end)
        for i in range(n):
            u = end * ((i * 7919) % 25000) / 25000.0
            total += dist_at(e, u)
            p = point_at(e, length * ((i * 7927) % 25000) / 25000.0)
            total += p.x + p.y
    print('checksum %.6f' % total)


main()
