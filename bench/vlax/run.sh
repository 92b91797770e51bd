#!/usr/bin/env bash
# The vlax-curve benchmark: 100,000 getDistAtParam/getPointAtDist calls on a bulged polyline
# and a cubic spline, lispcad vs Python + ezdxf computing the same from the entity each call.
# Prints both checksums (they agree to about 1e-6 relative) and the CPU-time ratio (CPU, not
# wall: the machine is shared). Usage: bench/vlax/run.sh [N per curve, default 25000]
set -euo pipefail
cd "$(dirname "$0")/../.."
n=${1:-25000}
cargo build --release -q
[ -x .venv/bin/python ] || bash .ci/setup
cpu() { /usr/bin/time -f "%U %S" "$@" 2>&1 >/dev/tty | tail -1 | awk '{ print $1 + $2 }'; }
lc=$(cpu target/release/lispcad run bench/vlax/vlax.lsp --set "N=$n")
py=$(cpu .venv/bin/python bench/vlax/vlax_ezdxf.py "$n")
printf 'lispcad %.2f s CPU, Python+ezdxf %.2f s CPU: %.0fx\n' "$lc" "$py" "$(echo "$py / $lc" | bc -l)"
