"""Writes DXF sample drawings with ezdxf for the reader's round-trip tests.

usage: dxf_samples.py OUTDIR
One file per version (R12, R2000, R2004, R2007, R2010, R2013, R2018) plus binary ones, each
with every entity type the reader models or must keep, non-ASCII text (cp1252 / GBK before
R2007, UTF-8 after), a block with attributes, extended data and a dictionary.
"""
import sys
from pathlib import Path

import ezdxf
from ezdxf.math import Vec3

VERSIONS = ["R12", "R2000", "R2004", "R2007", "R2010", "R2013", "R2018"]


def fill(doc, text, modern):
    msp = doc.modelspace()
    doc.layers.add("Outline", color=1, linetype="Continuous")
    doc.layers.add("Frozen", color=3).freeze()
    lk = doc.layers.add("Locked", color=5)
    lk.lock()
    doc.appids.add("LISPCAD")
    msp.add_line((0, 0, 0), (10, 5, 1), dxfattribs={"layer": "Outline"})
    msp.add_circle((5, 5), 2.5, dxfattribs={"color": 2})
    msp.add_circle((1, 2, 3), 1.5, dxfattribs={"extrusion": (0, 0.6, 0.8)})
    msp.add_arc((3, 3), 4, 10, 200, dxfattribs={"layer": "Frozen"})
    msp.add_point((7, 8, 9))
    msp.add_text(text, dxfattribs={"insert": (1, 1), "height": 2.5, "rotation": 30})
    msp.add_3dface([(0, 0, 0), (1, 0, 0), (1, 1, 1), (0, 1, 1)])
    msp.add_polyline2d([(0, 0), (5, 0), (5, 5)], close=True)
    msp.add_polyline3d([(0, 0, 0), (1, 2, 3), (4, 5, 6)])
    mesh = msp.add_polymesh((3, 3))
    for m in range(3):
        for n in range(3):
            mesh.set_mesh_vertex((m, n), (m, n, (m * n) % 2))
    line = msp.add_line((20, 0), (30, 0), dxfattribs={"layer": "Locked"})
    line.set_xdata("LISPCAD", [(1000, "tagged " + text), (1040, 3.25), (1070, 7)])
    blk = doc.blocks.new("TAG")
    blk.add_circle((0, 0), 1)
    blk.add_attdef("NAME", (0, -2), dxfattribs={"height": 0.5})
    ins = msp.add_blockref("TAG", (40, 40), dxfattribs={"rotation": 15})
    ins.add_attrib("NAME", "value " + text, (40, 38))
    if modern:
        msp.add_lwpolyline([(0, 0, 0, 0, 0.5), (10, 0, 0, 0, 0), (10, 10, 0, 0, -1), (0, 10)],
                           format="xyseb", close=True, dxfattribs={"layer": "Outline"})
        msp.add_spline([(0, 0), (3, 5), (6, -2), (9, 4), (12, 0)])
        msp.add_spline(fit_points=[(0, 20), (5, 25), (10, 18), (15, 22)])
        msp.add_spline_control_frame([(0, 30, 0), (4, 35, 1), (8, 28, 2), (12, 33, 0)])
        msp.add_rational_spline([(0, 40), (5, 45), (10, 40)], [1, 0.7, 1], degree=2)
        msp.add_ellipse((50, 50), major_axis=(10, 2, 0), ratio=0.4)
        msp.add_ellipse((60, 50), major_axis=(0, 5, 0), ratio=0.5, start_param=0.3, end_param=2.5)
        msp.add_mtext("multi\\Pline " + text, dxfattribs={"insert": (0, -10), "char_height": 2})
        hatch = msp.add_hatch(color=4)
        hatch.paths.add_polyline_path([(0, 0), (4, 0), (4, 4), (0, 4)], is_closed=True)
        dim = msp.add_linear_dim(base=(0, 60), p1=(0, 55), p2=(20, 55))
        dim.render()
        d = doc.rootdict.get_required_dict("LISPCAD_DATA")
        x = d.add_xrecord("SETTINGS")
        x.reset([(1, "mode " + text), (40, 1.5), (70, 3)])
        psp = doc.paperspace("Layout1")
        psp.add_line((0, 0), (100, 50))
        lay2 = doc.layouts.new("Sheet2")
        lay2.add_circle((10, 10), 5)


def main():
    out = Path(sys.argv[1])
    out.mkdir(parents=True, exist_ok=True)
    for v in VERSIONS:
        modern = v != "R12"
        unicode = v >= "R2007"
        for cp, text in [("cp1252", "Größe café €"), ("cp936", "中文 Größe")]:
            if unicode and cp == "cp936":
                continue
            doc = ezdxf.new(v)
            if not unicode:
                doc.encoding = cp
                doc.header["$DWGCODEPAGE"] = "ANSI_1252" if cp == "cp1252" else "ANSI_936"
            else:
                text = "中文 Größe café € \u03b1"
            fill(doc, text, modern)
            name = f"{v}.dxf" if cp == "cp1252" else f"{v}_gbk.dxf"
            doc.saveas(out / name)
            if v in ("R12", "R2000", "R2018") and cp == "cp1252":
                doc.saveas(out / f"{v}_bin.dxf", fmt="bin")


main()
