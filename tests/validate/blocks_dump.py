"""Block definitions, block references and entity properties through ezdxf, for
tests/blocks_dxf.rs.

Usage:
  blocks_dump.py make OUT.dxf   writes an R2010 drawing with a block "PY" (a line and an
                                ATTDEF "NAME") for lispcad to open
  blocks_dump.py explode IN.dxf the model-space entities (as check lists them) after ezdxf
                                explodes every block reference in it
  blocks_dump.py check IN.dxf   reads IN with ezdxf's strict reader, audits it, and prints
                                JSON: audit errors/fixes and messages; every block (name,
                                flags, base point, record handle, entities); the model-space
                                entities; the handles of the LAYER, LTYPE, STYLE, APPID and
                                BLOCK_RECORD table records by name
"""

import json
import sys

import ezdxf
from ezdxf.math import Vec3


def vec(v):
    return [round(float(x), 12) for x in v]


def entity(e):
    t = e.dxftype()
    d = {
        "type": t,
        "handle": e.dxf.handle,
        "owner": e.dxf.owner,
        "layer": e.dxf.layer,
        "color": e.dxf.get("color", 256),
        "linetype": e.dxf.get("linetype", "BYLAYER"),
        "lineweight": e.dxf.get("lineweight", -1),
        "ltscale": e.dxf.get("ltscale", 1.0),
    }
    if e.dxf.hasattr("thickness"):
        d["thickness"] = e.dxf.thickness
    if t == "LINE":
        d["start"] = vec(e.dxf.start)
        d["end"] = vec(e.dxf.end)
    elif t in ("CIRCLE", "ARC"):
        d["center"] = vec(e.dxf.center)
        d["radius"] = e.dxf.radius
        d["extrusion"] = vec(e.dxf.extrusion)
        if t == "ARC":
            d["start_angle"] = e.dxf.start_angle
            d["end_angle"] = e.dxf.end_angle
    elif t == "ELLIPSE":
        d["center"] = vec(e.dxf.center)
        d["major_axis"] = vec(e.dxf.major_axis)
        d["ratio"] = e.dxf.ratio
        d["start_param"] = e.dxf.start_param
        d["end_param"] = e.dxf.end_param
        d["extrusion"] = vec(e.dxf.extrusion)
        d["start_point"] = vec(e.start_point)
        d["end_point"] = vec(e.end_point)
        major = Vec3(e.dxf.major_axis).magnitude
        d["axes"] = [major, major * e.dxf.ratio]
    elif t == "POINT":
        d["location"] = vec(e.dxf.location)
    elif t == "LWPOLYLINE":
        d["points"] = [[x, y, b] for x, y, _s, _e, b in e.get_points()]
        d["closed"] = e.closed
    elif t == "POLYLINE":
        d["points"] = [vec(v.dxf.location) for v in e.vertices]
        d["bulges"] = [v.dxf.bulge for v in e.vertices]
        d["closed"] = e.is_closed
    elif t in ("TEXT", "ATTDEF", "ATTRIB"):
        d["insert"] = vec(e.dxf.insert)
        d["text"] = e.dxf.text
        d["height"] = e.dxf.height
        d["rotation"] = e.dxf.rotation
        d["width"] = e.dxf.get("width", 1.0)
        if t != "TEXT":
            d["tag"] = e.dxf.tag
    elif t == "INSERT":
        d["name"] = e.dxf.name
        d["insert"] = vec(e.dxf.insert)
        d["scale"] = [e.dxf.xscale, e.dxf.yscale, e.dxf.zscale]
        d["rotation"] = e.dxf.rotation
        d["attribs"] = [entity(a) for a in e.attribs]
    return d


def check(path):
    doc = ezdxf.readfile(path)
    auditor = doc.audit()
    out = {
        "audit_errors": len(auditor.errors),
        "audit_fixes": len(auditor.fixes),
        "messages": [str(x.message) for x in auditor.errors + auditor.fixes],
        "blocks": {},
        "modelspace": [entity(e) for e in doc.modelspace()],
        "tables": {},
    }
    for b in doc.blocks:
        if b.name.lower() in ("*model_space", "*paper_space"):
            continue
        out["blocks"][b.name] = {
            "flags": b.block.dxf.flags,
            "base": vec(b.block.dxf.base_point),
            "record": b.block_record.dxf.handle,
            "entities": [entity(e) for e in b],
        }
    for name, table in [
        ("LAYER", doc.layers),
        ("LTYPE", doc.linetypes),
        ("STYLE", doc.styles),
        ("APPID", doc.appids),
        ("BLOCK_RECORD", doc.block_records),
    ]:
        out["tables"][name] = {r.dxf.name: r.dxf.handle for r in table}
    print(json.dumps(out))


def explode(path):
    """The model space after ezdxf explodes every block reference in it (one level)."""
    doc = ezdxf.readfile(path)
    msp = doc.modelspace()
    for ins in list(msp.query("INSERT")):
        ins.explode()
    print(json.dumps([entity(e) for e in msp]))


def make(path):
    doc = ezdxf.new("R2010")
    b = doc.blocks.new("PY", base_point=(1, 0))
    b.add_line((0, 0), (3, 0))
    b.add_attdef("NAME", (0, 1), dxfattribs={"height": 0.5})
    doc.modelspace().add_circle((0, 0), 1)
    doc.saveas(path)


if __name__ == "__main__":
    {"check": check, "make": make, "explode": explode}[sys.argv[1]](sys.argv[2])
