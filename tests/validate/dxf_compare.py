"""Compares DXF files as ezdxf sees them (the reader's round-trip tests).

usage: dxf_compare.py ORIG COPY [ORIG COPY ...]
For each pair: both are read with ezdxf's strict `readfile`; COPY is audited (errors and
fixes counted); every object of ORIG (entities, table records, blocks, objects) must exist in
COPY under the same handle, with the same type, the same DXF attributes (numbers and vectors
equal to 1e-9), the same extended data and the same type-specific data (polyline points,
spline knots, text, hatch paths, dictionary entries, xrecord tags). Prints a JSON list of
{"orig", "copy", "diffs": [...], "audit_errors", "audit_fixes", "objects", "extra"}.
"""
import json
import math
import sys

import ezdxf
from ezdxf import recover
from ezdxf.entities import DXFGraphic
from ezdxf.lldxf.tagger import binary_tags_loader
from ezdxf.math import Vec2, Vec3

TOL = 1e-9


def same(a, b):
    if a is None or b is None:
        return a is b
    if isinstance(a, (Vec3, Vec2, tuple, list)) and isinstance(b, (Vec3, Vec2, tuple, list)):
        a, b = list(a), list(b)
        return len(a) == len(b) and all(same(x, y) for x, y in zip(a, b))
    if isinstance(a, float) or isinstance(b, float):
        try:
            return math.isclose(float(a), float(b), rel_tol=TOL, abs_tol=TOL)
        except (TypeError, ValueError):
            return False
    return a == b


def extra(e):
    t = e.dxftype()
    try:
        if t == "LWPOLYLINE":
            return [list(p) for p in e.get_points()]
        if t == "SPLINE":
            return [list(map(list, e.control_points)), list(e.knots), list(e.weights),
                    list(map(list, e.fit_points))]
        if t == "MTEXT":
            return e.text
        if t == "HATCH":
            return [len(e.paths), [type(p).__name__ for p in e.paths]]
        if t in ("DICTIONARY", "ACDBDICTIONARYWDFLT"):
            return sorted((k, v.dxf.handle if hasattr(v, "dxf") else str(v)) for k, v in e.items())
        if t == "XRECORD":
            return [(tag.code, tag.value) for tag in e.tags]
    except Exception as ex:  # noqa: BLE001 - reported as a difference
        return "error: " + str(ex)
    return None


def xdata(e):
    out = {}
    if e.xdata is not None:
        for app in e.xdata.data:
            out[app] = [(t.code, t.value) for t in e.get_xdata(app)]
    return out


def file_handseed(path):
    """$HANDSEED as written in the file (ezdxf raises it for objects it makes on loading)."""
    data = open(path, "rb").read()
    if data.startswith(b"AutoCAD Binary DXF"):
        tags = binary_tags_loader(data)
    else:
        lines = data.decode("latin-1").splitlines()
        tags = ((int(lines[i].strip()), lines[i + 1]) for i in range(0, len(lines) - 1, 2))
    prev = None
    for code, value in tags:
        if prev == "$HANDSEED":
            return int(value.strip(), 16)
        prev = value if code == 9 else None
    return None


def compare(orig, copy):
    diffs = []
    damaged = False
    try:
        a = ezdxf.readfile(orig)
    except (ezdxf.DXFStructureError, ValueError):
        # A damaged original (some real files are): ezdxf's own recovery reads it, and the
        # copy, kept as it was, may need the same.
        damaged = True
        a, _ = recover.readfile(orig)
    try:
        b = ezdxf.readfile(copy)
    except ezdxf.DXFStructureError as ex:
        if not damaged:
            return {"orig": orig, "copy": copy, "load_error": str(ex), "diffs": []}
        b, _ = recover.readfile(copy)
    # ezdxf's audit silently re-links some owners (SEQEND): audit both before comparing.
    orig_audit = a.audit()
    auditor = b.audit()
    fixes = [str(f.message) for f in auditor.fixes]
    errors = [str(f.message) for f in auditor.errors]
    if a.dxfversion != b.dxfversion:
        diffs.append(f"version {a.dxfversion} -> {b.dxfversion}")
    seed = file_handseed(orig)
    ha = {h: e for h, e in a.entitydb.items()
          if e.is_alive and (seed is None or int(h, 16) < seed)}
    seed_b = file_handseed(copy)
    hb = {h: e for h, e in b.entitydb.items()
          if e.is_alive and (seed_b is None or int(h, 16) < seed_b)}
    r12 = a.dxfversion <= "AC1009"
    if r12:
        # ezdxf numbers an R12 file's tables and objects itself when loading: compare the
        # graphical entities, whose handles are the file's.
        ha = {h: e for h, e in ha.items() if isinstance(e, DXFGraphic)}
        hb = {h: e for h, e in hb.items() if isinstance(e, DXFGraphic)}
    for h, ea in ha.items():
        eb = hb.get(h)
        if eb is None:
            diffs.append(f"{h} {ea.dxftype()} missing")
            continue
        if ea.dxftype() != eb.dxftype():
            diffs.append(f"{h} type {ea.dxftype()} -> {eb.dxftype()}")
            continue
        da = ea.dxf.all_existing_dxf_attribs()
        db = eb.dxf.all_existing_dxf_attribs()
        if r12:
            # R12 files have no owners: ezdxf links them to records it numbers on loading.
            da.pop("owner", None)
            db.pop("owner", None)
        for k in sorted(set(da) | set(db)):
            if not same(da.get(k), db.get(k)):
                diffs.append(f"{h} {ea.dxftype()} {k}: {da.get(k)!r} -> {db.get(k)!r}")
        if not same_deep(extra(ea), extra(eb)):
            diffs.append(f"{h} {ea.dxftype()} data: {extra(ea)!r} -> {extra(eb)!r}")
        if xdata(ea) != xdata(eb):
            diffs.append(f"{h} {ea.dxftype()} xdata: {xdata(ea)!r} -> {xdata(eb)!r}")
    new = [f"{h} {e.dxftype()}" for h, e in hb.items() if h not in ha]
    return {"orig": orig, "copy": copy, "diffs": diffs, "audit_errors": errors,
            "audit_fixes": fixes, "orig_audit_errors": len(orig_audit.errors),
            "orig_audit_fixes": len(orig_audit.fixes), "objects": len(ha), "extra": new}


def same_deep(a, b):
    if isinstance(a, (list, tuple)) and isinstance(b, (list, tuple)):
        return len(a) == len(b) and all(same_deep(x, y) for x, y in zip(a, b))
    return same(a, b)


def main():
    args = sys.argv[1:]
    pairs = [(args[i], args[i + 1]) for i in range(0, len(args), 2)]
    if len(pairs) > 50:
        # Many files (LibreCAD's parts): use both cores.
        import multiprocessing
        with multiprocessing.Pool(2) as pool:
            out = pool.starmap(compare, pairs, chunksize=16)
    else:
        out = [compare(a, b) for a, b in pairs]
    print(json.dumps(out, indent=1))


if __name__ == "__main__":
    main()
