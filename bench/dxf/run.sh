#!/usr/bin/env bash
# Open a 100,000-entity DXF (mixed types, written by ezdxf) and save it again: lispcad
# (read_dxf + DXF writer, examples/dxf_open_save.rs) vs ezdxf (readfile + saveas), each in
# its own process; prints the times, the ratios and each process's peak memory (RSS).
set -euo pipefail
cd "$(dirname "$0")/../.."
PY=${PYTHON:-.venv/bin/python}
[ -x "$PY" ] || { echo "no $PY: run bash .ci/setup" >&2; exit 1; }
N=${N:-100000}
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
"$PY" bench/dxf/make.py "$N" "$tmp/in.dxf"
cargo build -q --release --example dxf_open_save
peak() { grep "Maximum resident" "$1" | awk '{print $NF}'; }
/usr/bin/time -v target/release/examples/dxf_open_save "$tmp/in.dxf" "$tmp/lc.dxf" \
  >"$tmp/lc.txt" 2>"$tmp/lc.time"
/usr/bin/time -v "$PY" bench/dxf/ezdxf_open_save.py "$tmp/in.dxf" "$tmp/ez.dxf" \
  >"$tmp/ez.txt" 2>"$tmp/ez.time"
"$PY" - "$tmp" "$(peak "$tmp/lc.time")" "$(peak "$tmp/ez.time")" "$N" <<'PYEOF'
import sys
tmp, lc_kb, ez_kb, n = sys.argv[1], int(sys.argv[2]), int(sys.argv[3]), sys.argv[4]
rd = lambda f: dict(l.split() for l in open(f"{tmp}/{f}") if l.strip())
lc, ez = rd("lc.txt"), rd("ez.txt")
lo, ls, eo, es = (float(lc["open_s"]), float(lc["save_s"]), float(ez["open_s"]), float(ez["save_s"]))
print(f"| {n} entities | lispcad | ezdxf | ratio |")
print("|---|---|---|---|")
print(f"| open (s) | {lo:.3f} | {eo:.3f} | {eo / lo:.1f}x |")
print(f"| save (s) | {ls:.3f} | {es:.3f} | {es / ls:.1f}x |")
print(f"| open + save (s) | {lo + ls:.3f} | {eo + es:.3f} | {(eo + es) / (lo + ls):.1f}x |")
print(f"| peak memory (MB) | {lc_kb / 1024:.0f} | {ez_kb / 1024:.0f} | {ez_kb / lc_kb:.1f}x less |")
PYEOF
