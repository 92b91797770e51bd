"""Extended data, APPIDs, dictionaries and XRECORDs through ezdxf, for tests/xdata_dicts_dxf.rs.

Usage:
  xdata_dicts.py make OUT.dxf   writes a drawing with xdata on a LINE, an APPID, and a
                                dictionary PY_DICT (in the root dictionary) holding an
                                XRECORD "REC", for lispcad to open
  xdata_dicts.py check IN.dxf   reads IN with ezdxf's strict reader, audits it, and prints
                                JSON: audit errors/fixes, APPID names, every model-space
                                entity's xdata per application, and the dictionaries
                                reachable from the root with their XRECORDs' tags
"""

import json
import sys

import ezdxf
from ezdxf.math import Vec3


def val(v):
    if isinstance(v, (Vec3, tuple)):
        return [float(x) for x in v]
    return v


def make(path):
    doc = ezdxf.new("R2010")
    doc.appids.new("PYAPP")
    msp = doc.modelspace()
    line = msp.add_line((0, 0), (5, 0))
    line.set_xdata(
        "PYAPP",
        [(1000, "from python"), (1070, 42), (1010, (1, 2, 3)), (1040, 1.5)],
    )
    msp.add_circle((0, 0), 2)
    d = doc.rootdict.add_new_dict("PY_DICT")
    x = d.add_xrecord("REC")
    x.reset([(1, "py text"), (40, 2.25), (70, 9)])
    doc.saveas(path)


def walk(d, depth=0):
    out = {}
    if depth > 8:
        return out
    for key, obj in d.items():
        if isinstance(obj, str):
            out[key] = {"handle": obj}
            continue
        t = obj.dxftype()
        if t == "DICTIONARY":
            out[key] = {"type": t, "owner": obj.dxf.owner, "entries": walk(obj, depth + 1)}
        elif t == "XRECORD":
            out[key] = {
                "type": t,
                "owner": obj.dxf.owner,
                "tags": [[tag.code, val(tag.value)] for tag in obj.tags],
            }
        else:
            out[key] = {"type": t}
    return out


def check(path):
    doc = ezdxf.readfile(path)
    auditor = doc.audit()
    xdata = {}
    for e in doc.modelspace():
        apps = {}
        if e.xdata:
            for app in e.xdata.data.keys():
                apps[app] = [[tag.code, val(tag.value)] for tag in e.get_xdata(app)]
        xdata[e.dxf.handle] = {"type": e.dxftype(), "apps": apps}
    print(
        json.dumps(
            {
                "audit_errors": len(auditor.errors),
                "audit_fixes": len(auditor.fixes),
                "messages": [str(m.message) for m in auditor.errors + auditor.fixes],
                "appids": [a.dxf.name for a in doc.appids],
                "entities": xdata,
                "root": walk(doc.rootdict),
            }
        )
    )


if __name__ == "__main__":
    {"make": make, "check": check}[sys.argv[1]](sys.argv[2])
