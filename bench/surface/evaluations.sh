#!/usr/bin/env bash
# Surface evaluations and instructions per call of the four surface benches of
# benches/mesh_ops.rs, counted by callgrind (repeatable whatever the machine's load, unlike
# wall time; issue 13 asks that refinement not cost more). Only what runs inside the bench's
# entry function is collected, so the icospheres built at start-up do not count.
# Usage: bench/surface/evaluations.sh [BENCH_BINARY]  (default: builds and uses the newest
# target/release/deps/mesh_ops-*). Compare two builds by running it on each, at the same
# entry count: the first call also meshes and caches what later calls reuse, so the figures per
# call fall as criterion fits more calls into its 3 s.
set -euo pipefail
cd "$(dirname "$0")/../.."
bin=${1:-}
if [ -z "$bin" ]; then
  cargo bench --bench mesh_ops --no-run
  bin=$(ls -t target/release/deps/mesh_ops-* | grep -v '\.d$' | head -1)
fi
out=$(mktemp -d)
for spec in "contact_line/torus_top_circle surface_intersect_seeded" \
  "refine/cone_cylinder_refined ops::surface_intersect$" \
  "torus_section/with_contacts surface_section_seeded" \
  "torus_section/without_contacts surface_section_without_contacts"; do
  set -- $spec
  f=$out/$(echo "$1" | tr / _).out
  valgrind --tool=callgrind --toggle-collect="*${2%$}*" --callgrind-out-file="$f" \
    "$bin" --bench --profile-time 3 "^$1\$" >"$f.log" 2>&1
  echo "$1: $(python3 bench/surface/evaluations.py "$f" "$2" 'Patch::derivs$' \
    'curve::Curve::eval$' 'Surface::eval_whole$' 'Tracer::eval$')"
done
rm -rf "$out"
