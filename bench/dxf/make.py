"""Writes the benchmark drawing: N mixed entities (R2000) with ezdxf.

usage: make.py N OUT.dxf
Lines, circles, arcs, LWPOLYLINEs with bulges, TEXT, SPLINEs, 3DFACEs, POINTs, INSERTs with
an attribute, MTEXT and ELLIPSEs over five layers, in a fixed order (no randomness).
"""
import sys

import ezdxf

n = int(sys.argv[1])
doc = ezdxf.new("R2000")
for i in range(5):
    doc.layers.add(f"L{i}", color=i + 1)
blk = doc.blocks.new("MARK")
blk.add_circle((0, 0), 1)
blk.add_attdef("ID", (0, -2), dxfattribs={"height": 0.5})
msp = doc.modelspace()
for i in range(n):
    x, y = (i % 1000) * 1.5, (i // 1000) * 1.5
    a = {"layer": f"L{i % 5}"}
    k = i % 11
    if k == 0:
        msp.add_line((x, y), (x + 1, y + 0.5), dxfattribs=a)
    elif k == 1:
        msp.add_circle((x, y), 0.5, dxfattribs=a)
    elif k == 2:
        msp.add_arc((x, y), 0.6, 10, 250, dxfattribs=a)
    elif k == 3:
        msp.add_lwpolyline([(x, y, 0, 0, 0.3), (x + 1, y, 0, 0, 0), (x + 1, y + 1, 0, 0, -0.5)],
                           format="xyseb", close=True, dxfattribs=a)
    elif k == 4:
        msp.add_text(f"T{i}", dxfattribs={**a, "insert": (x, y), "height": 0.3})
    elif k == 5:
        msp.add_spline([(x, y), (x + 0.3, y + 0.6), (x + 0.7, y - 0.2), (x + 1, y)], dxfattribs=a)
    elif k == 6:
        msp.add_3dface([(x, y, 0), (x + 1, y, 0), (x + 1, y + 1, 1), (x, y + 1, 1)], dxfattribs=a)
    elif k == 7:
        msp.add_point((x, y, 0.5), dxfattribs=a)
    elif k == 8:
        ins = msp.add_blockref("MARK", (x, y), dxfattribs=a)
        ins.add_attrib("ID", str(i), (x, y - 2))
    elif k == 9:
        msp.add_mtext(f"M{i}\\Pline", dxfattribs={**a, "insert": (x, y), "char_height": 0.3})
    else:
        msp.add_ellipse((x, y), major_axis=(0.6, 0.1, 0), ratio=0.5, dxfattribs=a)
doc.saveas(sys.argv[2])
