#!/usr/bin/env python3
"""The parametric eyeglass temple of scripts/temple.lsp, written in Python with ezdxf.

Reference for the batch benchmark (issue 5): the same temple, same formulas, same outputs as
`lispcad batch scripts/temple.lsp ...`, so 1000 variants can be timed against lispcad.

Per variant:
  1. the 11 type-value points of the closed outline from the parameters (as temple.lsp);
  2. the C1 quadratic interpolating spline through them (quadratic B-spline, chord-length
     parameters, knots at the midpoints between data parameters, periodic; src/geom/quadspline_fit.rs);
  3. the bend of paper 004 with the corrected formulas of SEEDS.md (src/geom/temple.rs) and the
     regeneration of the outline within TOL of the exact bend (quadratic Hermite pieces with joints
     taken from the exact bend, bisection where the error exceeds TOL; src/geom/temple_refine.rs);
  4. DXF R2000 (ezdxf): layers CUT (outline as a degree-2 SPLINE), CENTER (LINE/ARC/LINE), NOTES
     (TEXT with the parameter values); and an SVG written by hand (one <g> per layer, Y up,
     the outline as Q segments, the arc as an A segment).

Usage:
  temple_ezdxf.py -n 1000 -o out/py                 # a built-in sweep of N variants
  temple_ezdxf.py --vary variants.csv -o out/py     # one variant per CSV row (header: variable names)
  temple_ezdxf.py -n 1 -o out --set L1=150 --set BENDANG=30
Prints the number of variants, the total time and variants per second. Pure Python + ezdxf.
"""

import argparse
import bisect
import csv
import math
import os
import sys
import time

import ezdxf

DEFAULTS = {
    "L1": 140.0,  # total temple length (mm)
    "L2": 35.0,  # far end back to the bend vertex
    "R": 15.0,  # bend radius
    "BENDANG": 40.0,  # bend angle, degrees (ANGLE is an AutoLISP builtin)
    "HINGEW": 5.0,  # width at the hinge end
    "MINW": 3.5,  # slimmest width (at 0.7 L1)
    "TIPW": 7.0,  # width of the tip
    "TIPR": 2.0,  # radius of the rounded ear tip
    "BASEX": 0.0,
    "BASEY": 0.0,
}
TOL = 1e-6  # GEOMTOL x 1000
SMOOTH_TOL = 0.05  # the smooth refit scripts/temple.lsp uses
SAMPLES = 8  # per interval while refining
VERIFY = 32  # per interval when verifying the result
MAX_ROUNDS = 48
MAX_ADDED = 4000

# --- small vector helpers (2D; the temple is planar) -------------------------------------


def add(a, b):
    return (a[0] + b[0], a[1] + b[1])


def sub(a, b):
    return (a[0] - b[0], a[1] - b[1])


def mul(a, k):
    return (a[0] * k, a[1] * k)


def dot(a, b):
    return a[0] * b[0] + a[1] * b[1]


# Written with the same operation order as glam / lispcad (sqrt of the dot product, lerp as
# a(1-t) + bt, Bezier weights formed first) so both programs take the same branches.
def norm(a):
    return math.sqrt(a[0] * a[0] + a[1] * a[1])


def lerp(a, b, t):
    return (a[0] * (1.0 - t) + b[0] * t, a[1] * (1.0 - t) + b[1] * t)


def bez(s, u):
    v = 1.0 - u
    w0, w1, w2 = v * v, 2.0 * v * u, u * u
    return (
        s[0][0] * w0 + s[1][0] * w1 + s[2][0] * w2,
        s[0][1] * w0 + s[1][1] * w1 + s[2][1] * w2,
    )


def bez_d(s, u):
    return (
        2 * ((s[1][0] - s[0][0]) * (1 - u) + (s[2][0] - s[1][0]) * u),
        2 * ((s[1][1] - s[0][1]) * (1 - u) + (s[2][1] - s[1][1]) * u),
    )


# --- the outline's type-value points (as scripts/temple.lsp) ------------------------------


def outline_points(p):
    l1 = p["L1"]
    h0, hm, ht = p["HINGEW"] / 2, p["MINW"] / 2, p["TIPW"] / 2
    hq = hm + 0.3 * (h0 - hm)
    bx, by = p["BASEX"], p["BASEY"]
    pts = [
        (0.0, -h0), (0.04 * l1, -h0), (0.35 * l1, -hq), (0.7 * l1, -hm), (0.9 * l1, -ht),
        (l1, 0.0),
        (0.9 * l1, ht), (0.7 * l1, hm), (0.35 * l1, hq), (0.04 * l1, h0), (0.0, h0),
    ]
    return [(bx + x, by + y) for x, y in pts]


def script_points(p):
    """The 15 type-value points of scripts/temple.lsp: straight hinge butt, tip rounded on TIPR."""
    l1, r = p["L1"], p["TIPR"]
    h0, hm, ht = p["HINGEW"] / 2, p["MINW"] / 2, p["TIPW"] / 2
    hq = hm + 0.3 * (h0 - hm)
    bx, by = p["BASEX"], p["BASEY"]

    def tip(deg):
        a = math.pi * (deg / 180.0)
        return (l1 - r + r * math.cos(a), r * math.sin(a))

    pts = [
        (0.0, -h0), (0.04 * l1, -h0), (0.35 * l1, -hq), (0.7 * l1, -hm), (0.9 * l1, -ht),
        tip(-80.0), tip(-40.0), tip(0.0), tip(40.0), tip(80.0),
        (0.9 * l1, ht), (0.7 * l1, hm), (0.35 * l1, hq), (0.04 * l1, h0), (0.0, h0),
    ]
    return [(bx + x, by + y) for x, y in pts]


# --- closed C1 quadratic interpolating spline ---------------------------------------------


def split(s, u):
    ab = lerp(s[0], s[1], u)
    bc = lerp(s[1], s[2], u)
    m = lerp(ab, bc, u)
    return [s[0], ab, m], [m, bc, s[2]]


def solve_tridiagonal(a, b, c, r):
    n = len(b)
    cp = [0.0] * n
    x = [None] * n
    den = b[0]
    cp[0] = c[0] / den
    x[0] = mul(r[0], 1 / den)
    for i in range(1, n):
        den = b[i] - a[i] * cp[i - 1]
        cp[i] = c[i] / den
        x[i] = mul(sub(r[i], mul(x[i - 1], a[i])), 1 / den)
    for i in range(n - 2, -1, -1):
        x[i] = sub(x[i], mul(x[i + 1], cp[i]))
    return x


def solve_cyclic(a, b, c, r):
    """Numerical Recipes `cyclic`: beta = top-right corner a[0], alpha = bottom-left c[n-1]."""
    n = len(b)
    beta, alpha, gamma = a[0], c[n - 1], -b[0]
    bb = list(b)
    bb[0] = b[0] - gamma
    bb[n - 1] = b[n - 1] - alpha * beta / gamma
    aa = [0.0] + list(a[1:])
    cc = list(c[:-1]) + [0.0]
    x = solve_tridiagonal(aa, bb, cc, r)
    u = [(0.0, 0.0)] * n
    u[0] = (gamma, gamma)
    u[n - 1] = (alpha, alpha)
    z = [v[0] for v in solve_tridiagonal(aa, bb, cc, u)]
    fx = (x[0][0] + beta * x[n - 1][0] / gamma) / (1 + z[0] + beta * z[n - 1] / gamma)
    fy = (x[0][1] + beta * x[n - 1][1] / gamma) / (1 + z[0] + beta * z[n - 1] / gamma)
    return [(xi[0] - fx * zi, xi[1] - fy * zi) for xi, zi in zip(x, z)]


def jacobi_eigen(a):
    """Eigenvalues and eigenvector columns of a symmetric 3x3 matrix (cyclic Jacobi, as Rust)."""
    a = [row[:] for row in a]
    v = [[1.0, 0.0, 0.0], [0.0, 1.0, 0.0], [0.0, 0.0, 1.0]]
    for _ in range(50):
        off = abs(a[0][1]) + abs(a[0][2]) + abs(a[1][2])
        diag = abs(a[0][0]) + abs(a[1][1]) + abs(a[2][2])
        if off <= 1e-300 or off <= 1e-15 * diag:
            break
        for p, q in ((0, 1), (0, 2), (1, 2)):
            if abs(a[p][q]) <= 1e-300:
                continue
            theta = (a[q][q] - a[p][p]) / (2.0 * a[p][q])
            t = math.copysign(1.0, theta) / (abs(theta) + math.sqrt(theta * theta + 1.0))
            if theta == 0.0:
                t = 1.0
            c = 1.0 / math.sqrt(t * t + 1.0)
            sn = t * c
            for k in range(3):
                akp, akq = a[k][p], a[k][q]
                a[k][p] = c * akp - sn * akq
                a[k][q] = sn * akp + c * akq
            for k in range(3):
                apk, aqk = a[p][k], a[q][k]
                a[p][k] = c * apk - sn * aqk
                a[q][k] = sn * apk + c * aqk
            for row in v:
                vp, vq = row[p], row[q]
                row[p] = c * vp - sn * vq
                row[q] = sn * vp + c * vq
    return [a[0][0], a[1][1], a[2][2]], v


def principal_axes(pts):
    """The points' principal frame (2D: the first two axes), as quadspline_fit.rs."""
    n = len(pts)
    c = (sum(p[0] for p in pts) / n, sum(p[1] for p in pts) / n)
    a = [[0.0] * 3 for _ in range(3)]
    for p in pts:
        d = (p[0] - c[0], p[1] - c[1], 0.0)
        for i in range(3):
            for j in range(3):
                a[i][j] += d[i] * d[j]
    vals, vecs = jacobi_eigen(a)
    idx = sorted(range(3), key=lambda i: (-vals[i], i))
    top = max(abs(vals[idx[0]]), 1e-300)
    if abs(vals[idx[0]] - vals[idx[1]]) <= 1e-9 * top:
        return (1.0, 0.0), (0.0, 1.0)
    e0 = (vecs[0][idx[0]], vecs[1][idx[0]])
    e1 = (vecs[0][idx[1]], vecs[1][idx[1]])
    if dot(sub(pts[-1], pts[0]), e0) < 0:
        e0 = (-e0[0], -e0[1])
    # e1 = (e0 x e1) x e0 in the plane: e0 turned by +-90 degrees towards the old e1.
    z = e0[0] * e1[1] - e0[1] * e1[0]
    e1 = (-z * e0[1], z * e0[0])
    return e0, e1


def limited_slope(a, b, ha, hb):
    if a * b <= 0.0:
        return 0.0
    bessel = (hb * a + ha * b) / (ha + hb)
    cap = 2.0 * (1.0 - 1e-6) * min(abs(a), abs(b))
    return max(-cap, min(cap, bessel))


def interpolate_closed(q):
    """Segments [start, control, end], two per interval, point j at public t = j/n: the local
    shape-preserving quadratic spline of quadspline_fit.rs (chord length, limited Bessel slopes
    in the principal frame)."""
    n = len(q)
    h = [norm(sub(q[(j + 1) % n], q[j])) for j in range(n)]
    e0, e1 = principal_axes(q)
    loc = lambda v: (dot(v, e0), dot(v, e1))
    slopes = [loc(mul(sub(q[(j + 1) % n], q[j]), 1.0 / h[j])) for j in range(n)]
    tans = []
    for j in range(n):
        a, b = slopes[j - 1], slopes[j]
        m = [limited_slope(a[k], b[k], h[j - 1], h[j]) for k in range(2)]
        tans.append(add(mul(e0, m[0]), mul(e1, m[1])))
    segs = []
    for j in range(n):
        k = (j + 1) % n
        c0 = add(q[j], mul(tans[j], 0.25 * h[j]))
        c1 = sub(q[k], mul(tans[k], 0.25 * h[j]))
        m = lerp(c0, c1, 0.5)
        segs.append([q[j], c0, m])
        segs.append([m, c1, q[k]])
    return segs


def spline_eval(segs, t):
    n = len(segs)
    x = min(max(t, 0.0), 1.0) * n
    i = min(int(x), n - 1)
    return bez(segs[i], x - i)


def spline_deriv(segs, t):
    n = len(segs)
    x = min(max(t, 0.0), 1.0) * n
    i = min(int(x), n - 1)
    return mul(bez_d(segs[i], x - i), n)


# --- the bend (paper 004, corrected; SEEDS.md) -------------------------------------------


class Bend:
    def __init__(self, p):
        self.l1, self.l2, self.r = p["L1"], p["L2"], p["R"]
        theta = math.radians(p["BENDANG"])
        if self.r <= 0:
            raise ValueError(f"bend radius R must be > 0, got {self.r}")
        if abs(theta) >= math.pi:
            raise ValueError(f"bend angle must satisfy |theta| < pi, got {theta}")
        self.th = abs(theta)
        self.sign = -1.0 if theta < 0 else 1.0
        self.l = self.l1 - self.l2 - self.r * math.tan(self.th / 2)
        if self.l < 0:
            raise ValueError(f"L = L1 - L2 - R*tan(theta/2) = {self.l} must be >= 0")
        self.lp = self.l1 - self.l - self.r * self.th
        if self.lp < 0:
            raise ValueError(f"Lp = L1 - L - R*theta = {self.lp} must be >= 0")
        self.bx, self.by = p["BASEX"], p["BASEY"]
        self.sin, self.cos = math.sin(self.th), math.cos(self.th)

    def map(self, w):
        s = w[0] - self.bx
        d = self.sign * (w[1] - self.by)
        if s <= self.l or self.th == 0:
            return w
        if -d >= self.r:
            raise ValueError(f"point {w} lies {-d} inside the bend, not less than R = {self.r}")
        arc = self.r * self.th
        if s <= self.l + arc:
            a = (s - self.l) / self.r
            x, y = self.l + (self.r + d) * math.sin(a), -self.r + (self.r + d) * math.cos(a)
        else:
            t = s - self.l - arc
            x = self.l + self.r * self.sin + t * self.cos + d * self.sin
            y = -self.r + self.r * self.cos - t * self.sin + d * self.cos
        return (self.bx + x, self.by + self.sign * y)

    def jacobian(self, w):
        s = w[0] - self.bx
        d = self.sign * (w[1] - self.by)
        if s <= self.l or self.th == 0:
            return (1.0, 0.0), (0.0, 1.0)
        if s <= self.l + self.r * self.th:
            a = (s - self.l) / self.r
            k = (self.r + d) / self.r
            ds, dd = (k * math.cos(a), -k * math.sin(a)), (math.sin(a), math.cos(a))
        else:
            ds, dd = (self.cos, -self.sin), (self.sin, self.cos)
        g = self.sign
        return (ds[0], g * ds[1]), (g * dd[0], dd[1])

    def centerline(self):
        bx, by, g = self.bx, self.by, self.sign
        p1 = (bx, by)
        p2 = (bx + self.l, by)
        o1 = (bx + self.l, by - g * self.r)
        p3 = (bx + self.l + self.r * self.sin, by + g * (-self.r + self.r * self.cos))
        p4 = (p3[0] + self.lp * self.cos, p3[1] - g * self.lp * self.sin)
        if g > 0:
            a0, a1 = (90 - math.degrees(self.th)) % 360, 90.0
        else:
            a0, a1 = 270.0, (270 + math.degrees(self.th)) % 360
        return p1, p2, p3, p4, o1, a0, a1


# --- nearest point on a quadratic Bezier (exact cubic roots) -----------------------------


def cubic_roots_unit(c3, c2, c1, c0):
    def f(u):
        return ((c3 * u + c2) * u + c1) * u + c0

    def df(u):
        return (3 * c3 * u + 2 * c2) * u + c1

    cuts = [0.0]
    qa, qb, qc = 3 * c3, 2 * c2, c1
    if qa != 0:
        disc = qb * qb - 4 * qa * qc
        if disc >= 0:
            q = -0.5 * (qb + math.copysign(math.sqrt(disc), qb))
            rs = sorted([q / qa, qc / q] if q != 0 else [0.0])
            cuts += [r for r in rs if 0 < r < 1]
    elif qb != 0 and 0 < -qc / qb < 1:
        cuts.append(-qc / qb)
    cuts.append(1.0)
    out = []
    for lo, hi in zip(cuts, cuts[1:]):
        flo, fhi = f(lo), f(hi)
        if flo == 0:
            out.append(lo)
            continue
        if fhi == 0:
            out.append(hi)
            continue
        if (flo > 0) == (fhi > 0):
            continue
        rising = fhi > 0
        u = 0.5 * (lo + hi)
        for _ in range(100):
            fu = f(u)
            if fu == 0:
                break
            if (fu > 0) == rising:
                hi = u
            else:
                lo = u
            dv = df(u)
            nu = u - fu / dv if dv != 0 else -1
            if lo < nu < hi:
                step = abs(nu - u)
                u = nu
                if step <= 4 * sys.float_info.epsilon:
                    break
            else:
                u = 0.5 * (lo + hi)
            if hi - lo <= 4 * sys.float_info.epsilon:
                break
        out.append(u)
    return out


def seg_distance(s, p):
    a = (s[0][0] - 2 * s[1][0] + s[2][0], s[0][1] - 2 * s[1][1] + s[2][1])
    b = (2 * (s[1][0] - s[0][0]), 2 * (s[1][1] - s[0][1]))
    d = sub(s[0], p)
    us = [0.0, 1.0] + cubic_roots_unit(
        2 * dot(a, a), 3 * dot(a, b), dot(b, b) + 2 * dot(a, d), dot(d, b)
    )
    return min(norm(sub(bez(s, u), p)) for u in us)


# --- bend + regenerate within TOL ------------------------------------------------------------


def bent_tangent(segs, bend, t, fallback):
    w = spline_eval(segs, t)
    jx, jy = bend.jacobian(w)
    dv = spline_deriv(segs, t)
    v = add(mul(jx, dv[0]), mul(jy, dv[1]))
    n = norm(v)
    if n == 0:
        v, n = fallback, norm(fallback)
    return mul(v, 1 / n)


def cross(a, b):
    return a[0] * b[1] - a[1] * b[0]


def tangent_meet(p, tp, q, tq):
    """Meeting point of the tangent lines (cross-product solve, no 1 - cos^2 cancellation)."""
    dv = sub(q, p)
    ln = norm(dv)
    n = cross(tp, tq)
    n2 = n * n
    if n2 < 1e-24:
        if dot(tp, tq) > 0 and dot(dv, tp) > 0 and abs(cross(dv, tp)) <= 1e-12 * ln:
            return lerp(p, q, 0.5)
        return None
    alpha = cross(dv, tq) * n / n2
    gamma = cross(tp, dv) * n / n2
    if not (alpha > 0.05 * ln and gamma > 0.05 * ln):
        return None
    x1 = add(p, mul(tp, alpha))
    x2 = sub(q, mul(tq, gamma))
    if norm(sub(x1, x2)) > 1e-9 * ln:
        return None
    return lerp(x1, x2, 0.5)


def rigid_pair(segs, bend, ta, tb):
    """The original's two segments of [ta, tb] moved by the bend when the span lies where the
    bend is rigid (temple_refine.rs rigid_pair)."""
    n = len(segs)
    k0, k1 = ta * n, tb * n
    first = round(k0)
    if abs(k0 - first) > 1e-9 or abs(k1 - first - 2) > 1e-9 or first < 0 or first + 1 >= n:
        return None
    pair = segs[first:first + 2]
    ss = [p[0] - bend.bx for sg in pair for p in sg]
    end = bend.l + bend.r * bend.th
    if not (max(ss) <= bend.l or bend.th == 0 or min(ss) >= end):
        return None
    return tuple([bend.map(p) for p in sg] for sg in pair)


def hermite_piece(segs, bend, ta, tb, a, b, tan_a, tan_b):
    rigid = rigid_pair(segs, bend, ta, tb)
    if rigid is not None:
        return rigid
    tm = 0.5 * (ta + tb)
    m = bend.map(spline_eval(segs, tm))
    tmv = bent_tangent(segs, bend, tm, sub(b, a))
    x1 = tangent_meet(a, tan_a, m, tmv)
    x2 = tangent_meet(m, tmv, b, tan_b)
    if x1 is not None and x2 is not None:
        return [a, x1, m], [m, x2, b]
    h = norm(sub(b, a)) / 3
    x1 = add(a, mul(tan_a, h))
    x2 = sub(b, mul(tan_b, h))
    mid = lerp(x1, x2, 0.5)
    return [a, x1, mid], [mid, x2, b]


def kink_params(segs, bend):
    """Parameters where the outline crosses s = L or s = L + R*theta (corners of the exact bend)."""
    out = []
    if bend.th == 0:
        return out
    n = len(segs)
    for c in (bend.l, bend.l + bend.r * bend.th):
        c = bend.bx + c
        for i, sg in enumerate(segs):
            x0, x1, x2 = sg[0][0] - c, sg[1][0] - c, sg[2][0] - c
            a, b = x0 - 2 * x1 + x2, 2 * (x1 - x0)
            roots = []
            if abs(a) <= 1e-300:
                if b != 0:
                    roots.append(-x0 / b)
            else:
                disc = b * b - 4 * a * x0
                if disc >= 0:
                    q = -0.5 * (b + math.copysign(math.sqrt(disc), b))
                    roots.append(q / a)
                    if q != 0:
                        roots.append(x0 / q)
            out += [(i + u) / n for u in roots if 0 <= u <= 1]
    return sorted(out)


def split_params(ta, tb, err, tol, kinks):
    """Middle of the interval, or a short piece of half-width (tb-ta)*tol/(4 err) around a kink."""
    first = bisect.bisect_right(kinks, ta)
    h = tb - ta
    if first < len(kinks) and kinks[first] < tb:
        k = kinks[first]
        delta = h * min(tol / (4 * err), 0.25)
        margin = max(h * 1e-3, 1e-12)
        cuts = [t for t in (k - delta, k + delta) if ta + margin < t < tb - margin]
        if cuts:
            return cuts
    return [0.5 * (ta + tb)]


def measure(segs, bend, kinks, ts, pieces, i, samples):
    n = len(ts)
    ta, tb = ts[i], ts[i + 1] if i + 1 < n else 1.0
    first = bisect.bisect_right(kinks, ta)
    inside = [k for k in kinks[first:] if k < tb]
    err = 0.0
    for t in [ta + (tb - ta) * k / (samples + 1) for k in range(1, samples + 1)] + inside:
        e = bend.map(spline_eval(segs, t))
        err = max(err, min(seg_distance(pieces[i][0], e), seg_distance(pieces[i][1], e)))
    return err


def bend_outline(segs, npts, bend, tol=TOL):
    """Returns (segments, deviation, added points). Same loop as temple_refine.rs."""
    ts = [j / npts for j in range(npts)]
    bent = [bend.map(spline_eval(segs, t)) for t in ts]
    tans = [bent_tangent(segs, bend, t, (1.0, 0.0)) for t in ts]
    known = [None] * npts
    pieces = [None] * npts
    kinks = kink_params(segs, bend)
    added = 0
    rnd = 0
    while True:
        rnd += 1
        n = len(ts)
        for i in range(n):
            if pieces[i] is None:
                ta, tb = ts[i], ts[i + 1] if i + 1 < n else 1.0
                j = (i + 1) % n
                pieces[i] = hermite_piece(segs, bend, ta, tb, bent[i], bent[j], tans[i], tans[j])
        for i in range(n):
            if known[i] is None:
                known[i] = measure(segs, bend, kinks, ts, pieces, i, SAMPLES)
        errs = list(known)
        dev = max(errs)
        capped = rnd >= MAX_ROUNDS or added >= MAX_ADDED
        if dev <= tol or capped:
            errs = [e if e <= 0.25 * tol else measure(segs, bend, kinks, ts, pieces, i, VERIFY)
                    for i, e in enumerate(errs)]
            dev = max(errs)
            if dev <= tol or capped:
                break
        nts, nbent, ntans, nknown, npieces = [], [], [], [], []
        for i in range(n):
            nts.append(ts[i])
            nbent.append(bent[i])
            ntans.append(tans[i])
            ta, tb = ts[i], ts[i + 1] if i + 1 < n else 1.0
            if errs[i] > tol and added < MAX_ADDED and tb - ta > 1e-12:
                chord = sub(bent[(i + 1) % n], bent[i])
                for tm in split_params(ta, tb, errs[i], tol, kinks):
                    nts.append(tm)
                    nbent.append(bend.map(spline_eval(segs, tm)))
                    ntans.append(bent_tangent(segs, bend, tm, chord))
                    nknown.append(None)
                    npieces.append(None)
                    added += 1
                nknown.append(None)
                npieces.append(None)
            else:
                nknown.append(errs[i])
                npieces.append(pieces[i])
        if len(nts) == n:
            break
        ts, bent, tans, known, pieces = nts, nbent, ntans, nknown, npieces
    out = [s for pair in pieces for s in pair]
    return out, dev, added


# --- output ----------------------------------------------------------------------------------


GL_X = (0.1834346424956498, 0.525532409916329, 0.7966664774136267, 0.9602898564975363)
GL_W = (0.362683783378362, 0.3137066458778873, 0.2223810344533745, 0.1012285362903763)


def outline_length(segs):
    """Arc length, 8-point Gauss-Legendre per segment (ample for two decimals)."""
    total = 0.0
    for s in segs:
        for x, w in zip(GL_X, GL_W):
            total += 0.5 * w * (norm(bez_d(s, 0.5 - 0.5 * x)) + norm(bez_d(s, 0.5 + 0.5 * x)))
    return total


def to_bspline(segs):
    """Control points and knots of the exact degree-2 B-spline (interior knots doubled)."""
    n = len(segs)
    ctrl = [segs[0][0]]
    knots = [0.0] * 3
    for i, s in enumerate(segs):
        ctrl += [s[1], s[2]]
        if i + 1 < n:
            knots += [(i + 1) / n] * 2
    knots += [1.0] * 3
    return ctrl, knots


def fmt(x):
    return f"{x:.6f}".rstrip("0").rstrip(".")


def write_dxf(path, segs, center, notes, base):
    doc = ezdxf.new("R2000", setup=False)
    doc.header["$INSUNITS"] = 4
    for name, color in (("CUT", 1), ("CENTER", 5), ("NOTES", 7)):
        doc.layers.add(name, color=color)
    msp = doc.modelspace()
    ctrl, knots = to_bspline(segs)
    msp.add_open_spline([(x, y, 0) for x, y in ctrl], degree=2, knots=knots,
                        dxfattribs={"layer": "CUT"})
    p1, p2, p3, p4, o1, a0, a1 = center
    if norm(sub(p2, p1)) > 0:
        msp.add_line(p1, p2, dxfattribs={"layer": "CENTER"})
    if a0 != a1:
        msp.add_arc(o1, norm(sub(p2, o1)), a0, a1, dxfattribs={"layer": "CENTER"})
    if norm(sub(p4, p3)) > 0:
        msp.add_line(p3, p4, dxfattribs={"layer": "CENTER"})
    for i, text in enumerate(notes):
        msp.add_text(text, height=2.5,
                     dxfattribs={"layer": "NOTES", "insert": (base[0], base[1] - 15 - 4 * i)})
    tmp = path + ".tmp"
    doc.saveas(tmp)
    os.replace(tmp, path)
    return doc


def write_pdf(path, doc):
    """The drawing through ezdxf's drawing add-on and matplotlib's PDF backend (the peer of
    `lispcad -o x.pdf`); the figure is sized to the extents so the page is at 1:1."""
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    from ezdxf import bbox
    from ezdxf.addons.drawing import Frontend, RenderContext
    from ezdxf.addons.drawing.matplotlib import MatplotlibBackend

    ext = bbox.extents(doc.modelspace())
    margin = 5.0
    w, h = ext.size.x + 2 * margin, ext.size.y + 2 * margin
    fig = plt.figure(figsize=(w / 25.4, h / 25.4))
    ax = fig.add_axes([0, 0, 1, 1])
    ax.set_xlim(ext.extmin.x - margin, ext.extmax.x + margin)
    ax.set_ylim(ext.extmin.y - margin, ext.extmax.y + margin)
    Frontend(RenderContext(doc), MatplotlibBackend(ax)).draw_layout(doc.modelspace(), finalize=False)
    tmp = path + ".tmp.pdf"
    fig.savefig(tmp, format="pdf")
    plt.close(fig)
    os.replace(tmp, path)


def write_svg(path, segs, center, notes, base):
    p1, p2, p3, p4, o1, a0, a1 = center
    xs = [c[0] for s in segs for c in s] + [p1[0], p4[0], 0.0]
    ys = [c[1] for s in segs for c in s] + [p1[1], p4[1], base[1] - 15 - 4 * len(notes)]
    pad = 5.0
    x0, x1 = min(xs) - pad, max(xs) + pad
    y0, y1 = min(ys) - pad, max(ys) + pad
    w, h = x1 - x0, y1 - y0

    def pt(p):
        return f"{fmt(p[0])},{fmt(-p[1])}"

    d = [f"M{pt(segs[0][0])}"] + [f"Q{pt(s[1])} {pt(s[2])}" for s in segs] + ["Z"]
    r = norm(sub(p2, o1))
    sweep = (a1 - a0) % 360
    large = 1 if sweep > 180 else 0
    # Y is flipped, so a CCW arc in the drawing is clockwise on screen (sweep-flag 0).
    a_start = (o1[0] + r * math.cos(math.radians(a0)), o1[1] + r * math.sin(math.radians(a0)))
    a_end = (o1[0] + r * math.cos(math.radians(a1)), o1[1] + r * math.sin(math.radians(a1)))
    out = [
        '<?xml version="1.0" encoding="UTF-8"?>',
        f'<svg xmlns="http://www.w3.org/2000/svg" width="{fmt(w)}mm" height="{fmt(h)}mm" '
        f'viewBox="{fmt(x0)} {fmt(-y1)} {fmt(w)} {fmt(h)}">',
        '<g id="CUT" fill="none" stroke="#ff0000" stroke-width="0.2">',
        f'<path d="{" ".join(d)}"/>',
        "</g>",
        '<g id="CENTER" fill="none" stroke="#0000ff" stroke-width="0.2">',
        f'<path d="M{pt(p1)} L{pt(p2)}"/>',
        f'<path d="M{pt(a_start)} A{fmt(r)},{fmt(r)} 0 {large} 0 {pt(a_end)}"/>',
        f'<path d="M{pt(p3)} L{pt(p4)}"/>',
        "</g>",
        '<g id="NOTES" fill="#000000" font-family="sans-serif" font-size="2.5">',
    ]
    for i, text in enumerate(notes):
        out.append(f'<text x="{fmt(base[0])}" y="{fmt(-(base[1] - 15 - 4 * i))}">{text}</text>')
    out += ["</g>", "</svg>", ""]
    tmp = path + ".tmp"
    with open(tmp, "w") as f:
        f.write("\n".join(out))
    os.replace(tmp, path)


def run_variant(params, stem, pdf=False):
    pts = script_points(params)
    segs = interpolate_closed(pts)
    bend = Bend(params)
    bent, dev, added = bend_outline(segs, len(pts), bend, SMOOTH_TOL)
    # The same three TEXT lines as scripts/temple.lsp (rtos modes 2 and 1).
    notes = [
        f"L1 {params['L1']:.1f}  L2 {params['L2']:.1f}  R {params['R']:.1f}  "
        f"BEND {params['BENDANG']:.1f} deg",
        f"HINGE {params['HINGEW']:.2f}  MIN {params['MINW']:.2f}  TIP {params['TIPW']:.2f}",
        f"outline length {outline_length(bent):.2f}  BENDDEV {dev:.2E}",
    ]
    center = bend.centerline()
    base = (params["BASEX"], params["BASEY"])
    doc = write_dxf(stem + ".dxf", bent, center, notes, base)
    if pdf:
        write_pdf(stem + ".pdf", doc)
    else:
        write_svg(stem + ".svg", bent, center, notes, base)
    return dev, added


def sweep(n):
    """A deterministic sweep over realistic sizes (the same rows as bench/temple/variants.csv
    written by --write-csv)."""
    rows = []
    for i in range(n):
        rows.append({
            "L1": 130.0 + (i % 21),
            "R": 10.0 + (i // 21) % 11,
            "BENDANG": 25.0 + 5 * ((i // 231) % 5),
            "L2": 30.0 + 5 * ((i // 1155) % 3),
        })
    return rows


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("-n", type=int, default=10, help="number of built-in sweep variants")
    ap.add_argument("--vary", help="CSV table, header = variable names")
    ap.add_argument("--set", action="append", default=[], help="NAME=VALUE override")
    ap.add_argument("-o", "--out", default="out-py", help="output directory")
    ap.add_argument("--write-csv", help="write the built-in sweep as a CSV table and exit")
    ap.add_argument("--pdf", action="store_true", help="DXF + PDF (matplotlib) instead of DXF + SVG")
    args = ap.parse_args()
    if args.write_csv:
        rows = sweep(args.n)
        with open(args.write_csv, "w", newline="") as f:
            wr = csv.DictWriter(f, fieldnames=list(rows[0]))
            wr.writeheader()
            wr.writerows(rows)
        return 0
    if args.vary:
        with open(args.vary, newline="") as f:
            rows = [{k.strip().upper(): float(v) for k, v in r.items()} for r in csv.DictReader(f)]
    else:
        rows = sweep(args.n)
    overrides = {}
    for s in args.set:
        k, v = s.split("=", 1)
        overrides[k.strip().upper()] = float(v)
    os.makedirs(args.out, exist_ok=True)
    start = time.perf_counter()
    failed = 0
    worst = 0.0
    for i, row in enumerate(rows):
        params = dict(DEFAULTS)
        params.update(row)
        params.update(overrides)
        stem = os.path.join(args.out, f"temple-{i:04d}")
        try:
            dev, _ = run_variant(params, stem, args.pdf)
            worst = max(worst, dev)
        except ValueError as e:
            failed += 1
            print(f"row {i + 1}: {e}", file=sys.stderr)
    elapsed = time.perf_counter() - start
    done = len(rows) - failed
    print(f"{done} variants ({failed} failed) in {elapsed:.3f} s: "
          f"{done / elapsed:.1f} variants/s; worst BENDDEV {worst:.3g}")
    return 1 if failed else 0


if __name__ == "__main__":
    sys.exit(main())
