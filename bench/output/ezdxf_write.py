"""Write the same 100,000 mixed entities as benches/output_write.rs with ezdxf (R2000).

Prints the seconds spent building the entities and saving the file, best of REPEAT runs.
Usage: ezdxf_write.py [N] [REPEAT]
"""

import math
import os
import sys
import tempfile
import time

import ezdxf


def build(n):
    doc = ezdxf.new("R2000")
    doc.header["$INSUNITS"] = 4
    doc.layers.add("A", color=1)
    doc.layers.add("B", color=5)
    msp = doc.modelspace()
    for i in range(n):
        x = (i % 1000) * 0.37
        y = (i // 1000) * 0.53
        a = {"layer": "A" if i % 2 == 0 else "B"}
        k = i % 8
        if k == 0:
            msp.add_line((x, y, 0), (x + 1.25, y + 0.75, 0), dxfattribs=a)
        elif k == 1:
            msp.add_circle((x + 0.5, y + 0.5, 0), 0.3, dxfattribs=a)
        elif k == 2:
            msp.add_arc((x + 0.5, y + 0.5, 0), 0.4, math.degrees(0.5), math.degrees(2.5), dxfattribs=a)
        elif k == 3:
            msp.add_lwpolyline(
                [(x, y, 0, 0, 0.0), (x + 1, y, 0, 0, 0.25), (x + 1, y + 0.5, 0, 0, 0.0), (x, y + 0.5, 0, 0, -0.25)],
                format="xyseb",
                close=True,
                dxfattribs=a,
            )
        elif k == 4:
            msp.add_point((x + 0.1, y + 0.2, 0), dxfattribs=a)
        elif k == 5:
            msp.add_text(f"T{i}", height=0.25, dxfattribs=dict(a, insert=(x, y, 0)))
        elif k == 6:
            pts = [(x, y, 0), (x + 0.3, y + 0.6, 0), (x + 0.6, y - 0.2, 0), (x + 0.9, y + 0.4, 0), (x + 1.2, y, 0)]
            msp.add_open_spline(pts, degree=3, dxfattribs=a)
        else:
            msp.add_3dface([(x, y, 0), (x + 1, y, 0), (x + 1, y + 1, 0), (x, y + 1, 0)], dxfattribs=a)
    return doc


def main():
    n = int(sys.argv[1]) if len(sys.argv) > 1 else 100_000
    repeat = int(sys.argv[2]) if len(sys.argv) > 2 else 3
    best_build = best_save = float("inf")
    with tempfile.TemporaryDirectory() as d:
        path = os.path.join(d, "out.dxf")
        for _ in range(repeat):
            t0 = time.perf_counter()
            doc = build(n)
            t1 = time.perf_counter()
            doc.saveas(path)
            t2 = time.perf_counter()
            best_build = min(best_build, t1 - t0)
            best_save = min(best_save, t2 - t1)
    print(f"ezdxf_build_s {best_build:.4f}")
    print(f"ezdxf_save_s {best_save:.4f}")


if __name__ == "__main__":
    main()
