"""Reference values for vlax-curve-* (tests/vlax_curve_python.rs): AutoCAD's parameter
conventions computed independently with ezdxf's B-spline basis, its bulge geometry and numpy
Gauss-Legendre arc lengths. Reads a JSON list of entities with queries on stdin, writes the
answers as JSON on stdout."""
import json
import math
import sys

import numpy as np
from ezdxf.math import BSpline, bulge_center, bulge_radius

GL_X, GL_W = np.polynomial.legendre.leggauss(24)


def integrate(f, a, b, parts=64):
    """∫_a^b f with composite 24-point Gauss-Legendre."""
    if b <= a:
        return 0.0
    edges = np.linspace(a, b, parts + 1)
    total = 0.0
    for lo, hi in zip(edges[:-1], edges[1:]):
        xs = 0.5 * (hi - lo) * GL_X + 0.5 * (hi + lo)
        total += 0.5 * (hi - lo) * sum(w * f(x) for x, w in zip(xs, GL_W))
    return total


def invert(length_to, total, lo, hi, s):
    """The parameter where length_to reaches s, by bisection."""
    if s < -1e-12 or s > total + 1e-9:
        return None
    a, b = lo, hi
    for _ in range(64):
        m = 0.5 * (a + b)
        if length_to(m) < s:
            a = m
        else:
            b = m
    return 0.5 * (a + b)


class Segments:
    """A polyline: per segment (kind, data) with parameter = index + fraction."""

    def __init__(self, pts, bulges, closed):
        n = len(pts)
        self.segs = []
        count = n if closed else n - 1
        for i in range(count):
            p, q = np.array(pts[i], float), np.array(pts[(i + 1) % n], float)
            b = bulges[i] if bulges else 0.0
            if b == 0.0:
                self.segs.append(('line', p, q))
            else:
                c = np.array(list(bulge_center(p[:2], q[:2], b)) + [p[2] if len(p) > 2 else 0.0])
                r = bulge_radius(p[:2], q[:2], b)
                a0 = math.atan2(p[1] - c[1], p[0] - c[0])
                sweep = 4.0 * math.atan(b)
                self.segs.append(('arc', c, r, a0, sweep))
        self.closed = closed
        self.pts = [np.array(p, float) for p in pts]

    def locate(self, u):
        i = min(int(math.floor(u)), len(self.segs) - 1)
        return self.segs[i], u - i, i

    def derivs(self, u):
        s, f, _ = self.locate(u)
        if s[0] == 'line':
            _, p, q = s
            return p + f * (q - p), q - p, np.zeros(3)
        _, c, r, a0, sw = s
        a = a0 + f * sw
        e = np.array([math.cos(a), math.sin(a), 0.0])
        t = np.array([-math.sin(a), math.cos(a), 0.0])
        return c + r * e, sw * r * t, -sw * sw * r * e

    def seg_len(self, s):
        return np.linalg.norm(s[2] - s[1]) if s[0] == 'line' else s[2] * abs(s[4])

    def length_to(self, u):
        s, f, i = self.locate(u)
        return sum(self.seg_len(x) for x in self.segs[:i]) + f * self.seg_len(s)

    def area(self):
        pts = self.pts + [self.pts[0]]
        a = 0.0
        for p, q in zip(pts[:-1], pts[1:]):
            a += 0.5 * (p[0] * q[1] - q[0] * p[1])
        for s in self.segs:
            if s[0] == 'arc':
                r, sw = s[2], s[4]
                a += 0.5 * r * r * (sw - math.sin(sw))
        return abs(a)


def spline_derivs(e):
    order = e['degree'] + 1
    w = e.get('weights')
    ctrl = [np.array(p, float) for p in e['ctrl']]
    if not w:
        sp = BSpline(ctrl, order=order, knots=e['knots'])
        return lambda u: [np.array(v) for v in list(sp.derivatives([u], n=2))[0]]
    num = BSpline([p * wi for p, wi in zip(ctrl, w)], order=order, knots=e['knots'])
    den = BSpline([(wi, 0, 0) for wi in w], order=order, knots=e['knots'])

    def d(u):
        a, a1, a2 = [np.array(v) for v in list(num.derivatives([u], n=2))[0]]
        ww, w1, w2 = [v[0] for v in list(den.derivatives([u], n=2))[0]]
        c = a / ww
        c1 = (a1 - w1 * c) / ww
        c2 = (a2 - 2 * w1 * c1 - w2 * c) / ww
        return [c, c1, c2]
    return d


def answer(e):
    k = e['kind']
    if k == 'LINE':
        p0, p1 = np.array(e['p0'], float), np.array(e['p1'], float)
        L = np.linalg.norm(p1 - p0)
        unit = (p1 - p0) / L
        lo, hi = 0.0, L
        derivs = lambda s: [p0 + s * unit, unit, np.zeros(3)]
        length_to = lambda s: s - lo
        area = 0.0
    elif k in ('CIRCLE', 'ARC'):
        c, r = np.array(e['c'], float), e['r']
        lo = e.get('a0', 0.0)
        hi = e['a1'] if k == 'ARC' else 2 * math.pi
        if hi <= lo:
            hi += 2 * math.pi
        def derivs(a):
            ev = np.array([math.cos(a), math.sin(a), 0.0])
            tv = np.array([-math.sin(a), math.cos(a), 0.0])
            return [c + r * ev, r * tv, -r * ev]
        length_to = lambda a: r * (a - lo)
        phi = hi - lo
        area = math.pi * r * r if k == 'CIRCLE' else 0.5 * r * r * (phi - math.sin(phi))
    elif k in ('LWPOLYLINE', 'POLYLINE'):
        pts = [list(p) + [0.0] * (3 - len(p)) for p in e['pts']]
        poly = Segments(pts, e.get('bulges'), e['closed'])
        lo, hi = 0.0, float(len(poly.segs))
        derivs = poly.derivs
        length_to = poly.length_to
        area = poly.area() if e['closed'] else None
    elif k == 'ELLIPSE':
        c, M, n = (np.array(e[x], float) for x in ('c', 'major', 'normal'))
        n = n / np.linalg.norm(n)
        m = e['ratio'] * np.cross(n, M)
        lo, hi = e['a0'], e['a1']
        if hi <= lo:
            hi += 2 * math.pi
        derivs = lambda a: [c + M * math.cos(a) + m * math.sin(a),
                            -M * math.sin(a) + m * math.cos(a),
                            -M * math.cos(a) - m * math.sin(a)]
        speed = lambda a: np.linalg.norm(derivs(a)[1])
        grid = np.linspace(lo, hi, 257)
        cum = np.concatenate([[0.0], np.cumsum([integrate(speed, a, b, 1)
                                                for a, b in zip(grid[:-1], grid[1:])])])

        def length_to(a):
            i = max(0, min(len(grid) - 2, int(np.searchsorted(grid, a, side='right')) - 1))
            return cum[i] + integrate(speed, grid[i], a, 1)
        area = None
    else:
        d = spline_derivs(e)
        p = e['degree']
        lo, hi = e['knots'][p], e['knots'][-p - 1]
        derivs = d
        speed = lambda u: np.linalg.norm(d(u)[1])
        # Cumulative lengths on a fine grid inside each knot span; a query integrates from
        # the grid node below it (24-point Gauss-Legendre on a tiny interval).
        grid = []
        for a, b in zip(e['knots'][p:-p - 1], e['knots'][p + 1:-p]):
            if b > a:
                grid.extend(np.linspace(a, b, 65)[:-1])
        grid = np.array(grid + [hi])
        cum = np.concatenate([[0.0], np.cumsum([integrate(speed, a, b, 1)
                                                for a, b in zip(grid[:-1], grid[1:])])])

        def length_to(u):
            i = max(0, min(len(grid) - 2, int(np.searchsorted(grid, u, side='right')) - 1))
            return cum[i] + integrate(speed, grid[i], u, 1)
        area = None
    total = length_to(hi)
    out = {'start': lo, 'end': hi, 'length': total, 'area': area, 'at': [], 'dist': []}
    for f in e['fractions']:
        u = lo + f * (hi - lo)
        pnt, d1, d2 = derivs(u)
        out['at'].append({'param': u, 'point': list(pnt), 'd1': list(d1), 'd2': list(d2),
                          'dist': length_to(u)})
    for f in e['fractions']:
        s = f * total
        u = invert(length_to, total, lo, hi, s)
        out['dist'].append({'dist': s, 'param': u, 'point': list(derivs(u)[0])})
    return out


print(json.dumps([answer(e) for e in json.load(sys.stdin)]))
