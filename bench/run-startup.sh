#!/usr/bin/env bash
# Start-up of `lispcad run` on an empty script beside /bin/true and `lua5.4 -e ''`, measured
# with `perf stat -r N` (elapsed, task-clock, page faults), the three interleaved for ROUNDS
# rounds so that they share the machine's load; then instructions under cachegrind when
# valgrind is installed and system calls under strace (neither depends on load). Elapsed times
# on a loaded machine are mostly waiting for a CPU: compare them only with /bin/true's in the
# same round.
#   bench/run-startup.sh                 # N=300 ROUNDS=3, target/release/lispcad
#   BIN=/tmp/old-lispcad bench/run-startup.sh
#   BEFORE=/tmp/old-lispcad bench/run-startup.sh   # an older binary as one more row each round
# Page faults of a binary depend on where its file lies (a fresh copy in /tmp faulted 11 fewer
# pages than the same file hard-linked in target/): compare copies made the same way.
set -euo pipefail
cd "$(dirname "$0")/.."
N=${N:-300}
ROUNDS=${ROUNDS:-3}
BIN=${BIN:-target/release/lispcad}
BEFORE=${BEFORE:-}
[ -x "$BIN" ] || cargo build --release --bin lispcad
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
: >"$tmp/empty.lsp"

stat() {
    perf stat -r "$N" -e task-clock,page-faults "$@" 2>&1 >/dev/null |
        awk '/task-clock/ {t=$1} /page-faults/ {f=$1} /time elapsed/ {e=$1*1000}
             END {printf "%9.3f %11.3f %12s\n", e, t, f}'
}

echo "load: $(cut -d' ' -f1-3 /proc/loadavg)   N=$N"
printf "%-6s %-10s %9s %11s %12s\n" round program "elapsed ms" "task-clock" "page-faults"
for r in $(seq "$ROUNDS"); do
    printf "%-6s %-10s %s\n" "$r" true "$(stat /bin/true)"
    if command -v lua5.4 >/dev/null; then
        printf "%-6s %-10s %s\n" "$r" lua5.4 "$(stat lua5.4 -e '')"
    fi
    if [ -n "$BEFORE" ]; then
        printf "%-6s %-10s %s\n" "$r" before "$(stat "$BEFORE" run "$tmp/empty.lsp")"
    fi
    printf "%-6s %-10s %s\n" "$r" lispcad "$(stat "$BIN" run "$tmp/empty.lsp")"
done
echo "load: $(cut -d' ' -f1-3 /proc/loadavg)"
for bin in ${BEFORE:+"$BEFORE"} "$BIN"; do
    if command -v valgrind >/dev/null; then
        i=$(valgrind --tool=cachegrind --cache-sim=no --cachegrind-out-file=/dev/null \
            "$bin" run "$tmp/empty.lsp" 2>&1 | awk '/I *refs/ {print $NF}')
        echo "instructions (cachegrind), $bin run empty.lsp: $i"
    fi
    if command -v strace >/dev/null; then
        c=$(strace -f -c "$bin" run "$tmp/empty.lsp" 2>&1 >/dev/null | awk '$NF == "total" {print $4}')
        echo "system calls (strace -f -c), $bin run empty.lsp: $c"
    fi
done
