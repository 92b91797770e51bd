"""Published-style routines (tests/routines/) on a drawing made by ezdxf: the drawing and
the values the routines must give, computed here independently (ezdxf's bulge and B-spline
geometry, numpy Gauss-Legendre arc lengths), for tests/routines_ezdxf.rs.

Usage:
  routines_ref.py make OUT.dxf   writes the drawing; prints the reference values as JSON
  routines_ref.py check IN.dxf   reads IN with the strict reader, audits it, prints JSON:
                                 audit counts, POINT locations, LWPOLYLINE (x, y, bulge)
  routines_ref.py block OUT.dxf  writes a drawing defining block DOOR with two ATTDEFs
  routines_ref.py inserts IN.dxf reads IN (strict, audited) and prints every INSERT with its
                                 ATTRIBs, and where ezdxf's own block transform puts each
                                 ATTDEF of the block for that INSERT
"""

import json
import math
import sys

import numpy as np
import ezdxf
from ezdxf.math import ConstructionCircle, ConstructionRay, Vec2, bulge_center, bulge_radius

GL_X, GL_W = np.polynomial.legendre.leggauss(24)

LW = [(0, -10), (10, -10), (10, -4), (0, -4)]
LW_B = [0.0, 0.5, 0.0, -0.3]
CTRL = [(30, 0), (33, 5), (37, -2), (40, 4), (44, 0)]


def integrate(f, a, b, parts=64):
    edges = np.linspace(a, b, parts + 1)
    total = 0.0
    for lo, hi in zip(edges[:-1], edges[1:]):
        xs = 0.5 * (hi - lo) * GL_X + 0.5 * (hi + lo)
        total += 0.5 * (hi - lo) * sum(w * f(x) for x, w in zip(xs, GL_W))
    return total


def seg_len(a, b, bulge):
    if bulge == 0:
        return math.dist(a, b)
    return bulge_radius(Vec2(a), Vec2(b), bulge) * abs(4 * math.atan(bulge))


def seg_point(a, b, bulge, s):
    """The point at distance s along one bulge segment."""
    if bulge == 0:
        return Vec2(a).lerp(Vec2(b), s / math.dist(a, b))
    c = bulge_center(Vec2(a), Vec2(b), bulge)
    r = bulge_radius(Vec2(a), Vec2(b), bulge)
    a0 = (Vec2(a) - c).angle
    turn = s / r if bulge > 0 else -s / r
    return c + Vec2.from_angle(a0 + turn, r)


def lw_segments():
    n = len(LW)
    return [(LW[i], LW[(i + 1) % n], LW_B[i]) for i in range(n)]


def lw_point_at(s):
    for a, b, bu in lw_segments():
        l = seg_len(a, b, bu)
        if s <= l:
            return seg_point(a, b, bu, s)
        s -= l
    raise ValueError("past the end")


def make(path):
    doc = ezdxf.new("R2010")
    msp = doc.modelspace()
    msp.add_line((14, -1), (26, 1))
    msp.add_circle((20, 0), 3)
    msp.add_arc((0, 10), 4, 30, 200)
    msp.add_lwpolyline([(x, y, b) for (x, y), b in zip(LW, LW_B)], format="xyb", close=True)
    sp = msp.add_open_spline(CTRL, degree=3)
    msp.add_polyline2d([(50, 0), (55, 3), (60, 0)])
    doc.saveas(path)

    bs = sp.construction_tool()
    t_end = bs.max_t
    speed = lambda t: bs.derivative(t, 1)[1].magnitude
    inner = sorted({k for k in bs.knots() if 0.0 < k < t_end})

    def arc_len(m, parts=16):
        # Piecewise between knots: the speed is only C1 across a knot.
        cuts = [0.0] + [k for k in inner if k < m] + [m]
        return sum(integrate(speed, a, b, parts) for a, b in zip(cuts[:-1], cuts[1:]))

    sp_len = arc_len(t_end, 64)
    lw_len = sum(seg_len(a, b, bu) for a, b, bu in lw_segments())
    total = (
        math.dist((14, -1), (26, 1))
        + 2 * math.pi * 3
        + 4 * math.radians(170)
        + lw_len
        + sp_len
        + 2 * math.dist((50, 0), (55, 3))
    )

    def sp_point(s):
        lo, hi = 0.0, t_end
        for _ in range(64):
            m = 0.5 * (lo + hi)
            if arc_len(m) < s:
                lo = m
            else:
                hi = m
        return bs.point(0.5 * (lo + hi))

    n = len(LW)
    rev = [[x, y, -LW_B[(n - 2 - i) % n]] for i, (x, y) in enumerate(LW[::-1])]
    hits = ConstructionCircle((20, 0), 3).intersect_ray(ConstructionRay((14, -1), (26, 1)))
    print(
        json.dumps(
            {
                "total": total,
                "div_lw": [list(lw_point_at(i * lw_len / 5)) for i in range(1, 5)],
                "div_spline": [[p.x, p.y] for p in (sp_point(i * sp_len / 4) for i in range(1, 4))],
                "rev_lw": rev,
                "inters": sorted([[p.x, p.y] for p in hits]),
            }
        )
    )


def check(path):
    doc = ezdxf.readfile(path)
    auditor = doc.audit()
    msp = doc.modelspace()
    print(
        json.dumps(
            {
                "audit_errors": len(auditor.errors),
                "audit_fixes": len(auditor.fixes),
                "points": [[p.dxf.location.x, p.dxf.location.y] for p in msp.query("POINT")],
                "lw": [[x, y, b] for x, y, b in msp.query("LWPOLYLINE")[0].get_points("xyb")],
            }
        )
    )


def block(path):
    doc = ezdxf.new("R2010")
    blk = doc.blocks.new("DOOR")
    blk.add_line((0, 0), (1, 0))
    blk.add_attdef("WIDTH", (1, 0.5), "900", dxfattribs={"height": 0.25})
    blk.add_attdef("NOTE", (0, -0.5), "none", dxfattribs={"height": 0.2})
    doc.saveas(path)


def inserts(path):
    doc = ezdxf.readfile(path)
    auditor = doc.audit()
    out = []
    for ins in doc.modelspace().query("INSERT"):
        m = ins.matrix44()
        defs = {a.dxf.tag: m.transform(a.dxf.insert) for a in doc.blocks.get(ins.dxf.name).attdefs()}
        out.append(
            {
                "name": ins.dxf.name,
                "insert": list(ins.dxf.insert),
                "scale": [ins.dxf.xscale, ins.dxf.yscale],
                "rotation": ins.dxf.rotation,
                "attribs": [
                    {
                        "tag": a.dxf.tag,
                        "text": a.dxf.text,
                        "at": list(a.dxf.insert),
                        "want_at": list(defs[a.dxf.tag]),
                        "height": a.dxf.height,
                    }
                    for a in ins.attribs
                ],
            }
        )
    print(
        json.dumps(
            {
                "audit_errors": len(auditor.errors),
                "audit_fixes": len(auditor.fixes),
                "inserts": out,
                "lines": [list(l.dxf.start) + list(l.dxf.end) for l in doc.modelspace().query("LINE")],
            }
        )
    )


if __name__ == "__main__":
    {"make": make, "check": check, "block": block, "inserts": inserts}[sys.argv[1]](sys.argv[2])
