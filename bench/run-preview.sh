#!/usr/bin/env bash
# Editor-support latencies (issue 16): LSP diagnostics per change on a 5,000-line file, and the
# live preview's save-to-page-update time for the temple in headless chromium.
# Usage: bench/run-preview.sh   (needs `bash .ci/setup` for chromium and playwright-core)
set -euo pipefail
cd "$(dirname "$0")/.."
cargo build --release -q
bin=$PWD/target/release/lispcad
python3 bench/preview/lsp_latency.py "$bin"

dir=$(mktemp -d)
trap 'kill $srv 2>/dev/null || true; rm -rf "$dir"' EXIT
cp scripts/temple.lsp "$dir/temple.lsp"
"$bin" serve "$dir/temple.lsp" --port 0 2> "$dir/serve.log" &
srv=$!
until grep -q '^serving ' "$dir/serve.log"; do sleep 0.1; done
url=$(sed -n 's/^serving \([^ ]*\).*/\1/p' "$dir/serve.log")
(cd tests/browser && LISPCAD_LATENCY_RUNS=20 node preview.mjs "$url" "$dir/temple.lsp" /dev/null)
