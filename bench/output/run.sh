#!/usr/bin/env bash
# Compare lispcad's DXF/SVG writers with ezdxf on the same 100,000 mixed entities.
# Runs the criterion bench (benches/output_write.rs) and bench/output/ezdxf_write.py, then
# prints the times and the ratios (ezdxf save time / lispcad write time).
set -euo pipefail
cd "$(dirname "$0")/../.."
PY=${PYTHON:-.venv/bin/python}
[ -x "$PY" ] || { echo "no $PY: run bash .ci/setup" >&2; exit 1; }

cargo bench --bench output_write -- --noplot >/dev/null
read_ns() {
  "$PY" -c "import json,sys; print(json.load(open(sys.argv[1]))['mean']['point_estimate'])" \
    "target/criterion/output_write_100k/$1/new/estimates.json"
}
dxf_ns=$(read_ns dxf_cad)
svg_ns=$(read_ns svg)
ez=$("$PY" bench/output/ezdxf_write.py 100000 3)
echo "$ez"
"$PY" - "$dxf_ns" "$svg_ns" <<PYEOF
import sys
dxf = float(sys.argv[1]) / 1e9
svg = float(sys.argv[2]) / 1e9
ez = dict(l.split() for l in """$ez""".splitlines())
save = float(ez["ezdxf_save_s"]); build = float(ez["ezdxf_build_s"])
print(f"lispcad_dxf_s {dxf:.4f}")
print(f"lispcad_svg_s {svg:.4f}")
print(f"ratio ezdxf_save/lispcad_dxf {save / dxf:.1f}x")
print(f"ratio ezdxf_build+save/lispcad_dxf {(build + save) / dxf:.1f}x")
print(f"ratio ezdxf_save/lispcad_svg {save / svg:.1f}x")
PYEOF
