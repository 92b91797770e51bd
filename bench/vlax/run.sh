#!/usr/bin/env bash
# The vlax-curve benchmark: 100,000 getDistAtParam/getPointAtDist calls on a bulged polyline
# and a cubic spline, lispcad vs Python + ezdxf computing the same from the entity each call.
# Prints both checksums (they must agree to about 1e-6 relative) and the time ratio.
set -euo pipefail
cd "$(dirname "$0")/../.."
cargo build --release -q
[ -x .venv/bin/python ] || bash .ci/setup
t0=$(date +%s.%N); target/release/lispcad run bench/vlax/vlax.lsp; t1=$(date +%s.%N)
.venv/bin/python bench/vlax/vlax_ezdxf.py; t2=$(date +%s.%N)
lc=$(echo "$t1 - $t0" | bc -l); py=$(echo "$t2 - $t1" | bc -l)
printf 'lispcad %.2f s, Python+ezdxf %.2f s: %.1fx\n' "$lc" "$py" "$(echo "$py / $lc" | bc -l)"
