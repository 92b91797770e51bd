#!/usr/bin/env bash
# Mesh benchmark: lispcad vs trimesh / manifold3d on two icospheres of 1,310,720 triangles.
# Usage: bench/surface/run.sh [OUT_DIR]   (venv: $BENCH_VENV, default OUT_DIR/venv)
set -euo pipefail
here="$(cd "$(dirname "$0")" && pwd)"
repo="$(cd "$here/../.." && pwd)"
out="${1:-/tmp/lispcad-surface-bench}"
mkdir -p "$out"
venv="${BENCH_VENV:-$out/venv}"
if [ ! -x "$venv/bin/python" ]; then
  python3 -m venv "$venv"
  "$venv/bin/pip" install -q -r "$here/requirements.txt"
fi
(cd "$repo" && cargo build --release --example mesh_bench)
"$venv/bin/python" "$here/bench.py" --out "$out" --lispcad "$repo/target/release/examples/mesh_bench"
