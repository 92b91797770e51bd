"""Strict DXF check used by the Rust tests (tests/output_dxf.rs, tests/output_cam.rs).

Usage: check_dxf.py [--cam] FILE...   (several files: a JSON array, one object per file)

Loads FILE with ezdxf's strict reader (`ezdxf.readfile`, not `recover`), runs `doc.audit()`,
and prints one JSON object on stdout:
  version, audit_errors, audit_fixes (with their messages), layers, and every model-space
  entity with its type, handle, layer, colour and geometry as ezdxf reads it back.
With --cam it also reports coincident or overlapping edges (ezdxf's edgeminer
`filter_coincident_edges` plus a collinear/concentric overlap test) and the closedness of
every polyline. The Rust side compares the JSON with what it drew; this script only reads.
"""

import json
import logging
import math
import sys

import ezdxf
from ezdxf import edgeminer
from ezdxf.lldxf.encoding import decode_dxf_unicode
from ezdxf.math import Vec3

EPS = 1e-6


def v(p):
    return [float(p[0]), float(p[1]), float(p[2]) if len(p) > 2 else 0.0]


def dump_entity(e):
    t = e.dxftype()
    d = {
        "type": t,
        "handle": e.dxf.handle,
        # AutoCAD shows \\U+XXXX escapes as the character; so does this dump.
        "layer": decode_dxf_unicode(e.dxf.layer),
        "color": e.dxf.color if e.dxf.hasattr("color") else None,
    }
    if t == "LINE":
        d["start"] = v(e.dxf.start)
        d["end"] = v(e.dxf.end)
    elif t in ("CIRCLE", "ARC"):
        d["center_ocs"] = v(e.dxf.center)
        d["center_wcs"] = v(e.ocs().to_wcs(e.dxf.center))
        d["radius"] = e.dxf.radius
        d["extrusion"] = v(e.dxf.extrusion)
        if t == "ARC":
            d["start_angle"] = e.dxf.start_angle
            d["end_angle"] = e.dxf.end_angle
    elif t == "POINT":
        d["location"] = v(e.dxf.location)
    elif t == "LWPOLYLINE":
        d["points"] = [[x, y, b] for x, y, b in e.get_points("xyb")]
        d["closed"] = bool(e.closed)
        d["elevation"] = e.dxf.elevation
        d["extrusion"] = v(e.dxf.extrusion)
    elif t == "POLYLINE":
        d["points"] = [
            v(vx.dxf.location) + [vx.dxf.bulge if vx.dxf.hasattr("bulge") else 0.0]
            for vx in e.vertices
        ]
        d["closed"] = bool(e.is_closed)
        d["is_3d"] = bool(e.is_3d_polyline)
    elif t == "SPLINE":
        d["degree"] = e.dxf.degree
        d["knots"] = [float(k) for k in e.knots]
        d["control_points"] = [v(p) for p in e.control_points]
        d["weights"] = [float(w) for w in e.weights]
        d["fit_points"] = [v(p) for p in e.fit_points]
        d["flags"] = e.dxf.flags
    elif t == "3DFACE":
        d["corners"] = [v(e.dxf.get(f"vtx{i}")) for i in range(4)]
    elif t == "TEXT":
        d["insert"] = v(e.dxf.insert)
        d["height"] = e.dxf.height
        d["text"] = decode_dxf_unicode(e.dxf.text)
        d["rotation"] = e.dxf.rotation
        d["style"] = e.dxf.style
    return d


# ---- CAM edge checks ------------------------------------------------------------------

def bulge_arc(a, b, bulge):
    """(centre, radius, start angle, signed sweep) of a bulge segment."""
    dx, dy = b[0] - a[0], b[1] - a[1]
    d = math.hypot(dx, dy)
    theta = 4.0 * math.atan(bulge)
    r = d / (2.0 * abs(math.sin(theta / 2.0)))
    h = d / 2.0 / math.tan(theta / 2.0)
    cx = (a[0] + b[0]) / 2.0 - dy / d * h
    cy = (a[1] + b[1]) / 2.0 + dx / d * h
    a0 = math.atan2(a[1] - cy, a[0] - cx)
    return (cx, cy), r, a0, theta


def edges_of(e):
    """Edges as ('L', a, b) or ('A', centre, r, lo, span) with CCW angular interval."""
    t = e.dxftype()
    out = []

    def add_bulge(a, b, bulge):
        if math.hypot(b[0] - a[0], b[1] - a[1]) <= 1e-12:
            return
        if abs(bulge) < 1e-15:
            out.append(("L", (a[0], a[1]), (b[0], b[1])))
        else:
            c, r, a0, sweep = bulge_arc(a, b, bulge)
            lo = a0 if sweep > 0 else a0 + sweep
            out.append(("A", c, r, lo % math.tau, abs(sweep)))

    if t == "LINE":
        add_bulge(e.dxf.start, e.dxf.end, 0.0)
    elif t == "ARC":
        c = e.dxf.center
        s, en = e.dxf.start_angle, e.dxf.end_angle
        span = (en - s) % 360.0 or 360.0
        out.append(("A", (c[0], c[1]), e.dxf.radius, math.radians(s) % math.tau, math.radians(span)))
    elif t == "CIRCLE":
        c = e.dxf.center
        out.append(("A", (c[0], c[1]), e.dxf.radius, 0.0, math.tau))
    elif t == "POLYLINE":
        vs = [(vx.dxf.location, vx.dxf.bulge if vx.dxf.hasattr("bulge") else 0.0) for vx in e.vertices]
        n = len(vs)
        segs = n if e.is_closed else n - 1
        for i in range(segs):
            add_bulge(vs[i][0], vs[(i + 1) % n][0], vs[i][1])
    return out


def overlap(p, q):
    """Length of the overlap of two edges (0 when they merely touch or cross)."""
    if p[0] == "L" and q[0] == "L":
        (ax, ay), (bx, by) = p[1], p[2]
        dx, dy = bx - ax, by - ay
        ln = math.hypot(dx, dy)
        ux, uy = dx / ln, dy / ln
        off = lambda pt: abs((pt[0] - ax) * uy - (pt[1] - ay) * ux)
        if off(q[1]) > EPS or off(q[2]) > EPS:
            return 0.0
        ta = (q[1][0] - ax) * ux + (q[1][1] - ay) * uy
        tb = (q[2][0] - ax) * ux + (q[2][1] - ay) * uy
        return max(0.0, min(ln, max(ta, tb)) - max(0.0, min(ta, tb)))
    if p[0] == "A" and q[0] == "A":
        if math.hypot(p[1][0] - q[1][0], p[1][1] - q[1][1]) > EPS or abs(p[2] - q[2]) > EPS:
            return 0.0
        best = 0.0
        start = (q[3] - p[3]) % math.tau
        for shift in (-math.tau, 0.0, math.tau):
            u0, u1 = start + shift, start + shift + q[4]
            best += max(0.0, min(u1, p[4]) - max(u0, 0.0))
        return best * p[2]
    return 0.0


def cam_report(msp):
    edges = []
    for e in msp:
        for ed in edges_of(e):
            edges.append((ed, e.dxf.handle))
    overlaps = []
    for i in range(len(edges)):
        for j in range(i + 1, len(edges)):
            ov = overlap(edges[i][0], edges[j][0])
            if ov > 1e-5:
                overlaps.append([edges[i][1], edges[j][1], ov])

    # ezdxf's own edge tools: congruent edges (same ends either way, same midpoint).
    def midpoint(ed):
        if ed[0] == "L":
            return Vec3((ed[1][0] + ed[2][0]) / 2, (ed[1][1] + ed[2][1]) / 2, 0)
        c, r, lo, span = ed[1], ed[2], ed[3], ed[4]
        m = lo + span / 2
        return Vec3(c[0] + r * math.cos(m), c[1] + r * math.sin(m), 0)

    def ends(ed):
        if ed[0] == "L":
            return Vec3(ed[1][0], ed[1][1], 0), Vec3(ed[2][0], ed[2][1], 0)
        c, r, lo, span = ed[1], ed[2], ed[3], ed[4]
        return (
            Vec3(c[0] + r * math.cos(lo), c[1] + r * math.sin(lo), 0),
            Vec3(c[0] + r * math.cos(lo + span), c[1] + r * math.sin(lo + span), 0),
        )

    em_edges = []
    for ed, _h in edges:
        s, t = ends(ed)
        if s.isclose(t, abs_tol=1e-9):
            continue  # full circles have no distinct ends; covered by the overlap test
        em_edges.append(edgeminer.make_edge(s, t, payload=midpoint(ed)))
    line_eq = edgeminer.line_checker(abs_tol=EPS)

    def congruent(a, b):
        return line_eq(a, b) and a.payload.isclose(b.payload, abs_tol=EPS)

    deposit = edgeminer.Deposit(em_edges)
    unique = edgeminer.filter_coincident_edges(deposit, eq_fn=congruent)
    return {
        "overlaps": overlaps,
        "edge_count": len(em_edges),
        "congruent_edges": len(em_edges) - len(unique),
    }


def check(path, cam):
    # Anything ezdxf's loader repairs silently is logged; collect it as a failure too.
    records = []

    class Collect(logging.Handler):
        def emit(self, record):
            if record.levelno >= logging.WARNING:
                records.append(record.getMessage())

    handler = Collect()
    logger = logging.getLogger("ezdxf")
    logger.addHandler(handler)
    try:
        try:
            doc = ezdxf.readfile(path)
        except Exception as exc:  # the Rust test reports this as a failure
            return {"load_error": f"{type(exc).__name__}: {exc}"}
        auditor = doc.audit()
        msp = doc.modelspace()
        out = {
            "version": doc.dxfversion,
            "audit_errors": len(auditor.errors),
            "audit_fixes": len(auditor.fixes),
            "audit_messages": [str(m.message) for m in list(auditor.errors) + list(auditor.fixes)],
            "load_warnings": records,
            "insunits": doc.header.get("$INSUNITS"),
            "layers": [
                {"name": decode_dxf_unicode(l.dxf.name), "color": l.dxf.color, "linetype": l.dxf.linetype}
                for l in doc.layers
            ],
            "entities": [dump_entity(e) for e in msp],
        }
        if cam:
            out["cam"] = cam_report(msp)
        return out
    finally:
        logger.removeHandler(handler)


def main():
    args = sys.argv[1:]
    cam = "--cam" in args
    files = [a for a in args if a != "--cam"]
    results = [check(f, cam) for f in files]
    print(json.dumps(results[0] if len(results) == 1 else results))


if __name__ == "__main__":
    main()
