#!/usr/bin/env bash
# Runs the four language benchmarks (bench/lang/{fib,loop,list,empty}) on lispcad, CPython 3,
# Lua 5.4 and Guile 3.0, REPS times each, interleaved (rep 1 of every program on every
# language, then rep 2, ...) so load from other processes on a shared machine spreads over
# all of them; prints the minimum wall time of each and the ratio lispcad/peer.
#
#   bench/run-lang.sh [REPS]        (default 5; LISPCAD=path overrides the binary)
set -euo pipefail
here="$(cd "$(dirname "$0")" && pwd)"
root="$(dirname "$here")"
reps="${1:-5}"
lispcad="${LISPCAD:-$root/target/release/lispcad}"
if [[ ! -x "$lispcad" ]]; then
  (cd "$root" && cargo build --release --quiet)
fi
python="$(command -v python3.11 || command -v python3)"
lua="$(command -v lua5.4 || true)"
guile="$(command -v guile || true)"

langs=(lispcad python lua guile)
progs=(fib loop list empty)
declare -A cmd best
cmd[lispcad]="$lispcad run"
cmd[python]="$python"
cmd[lua]="$lua"
cmd[guile]="$guile --no-debug"
declare -A ext=([lispcad]=lsp [python]=py [lua]=lua [guile]=scm)

available() { [[ "$1" == lispcad || "$1" == python ]] && return 0; [[ -n "${!1}" ]]; }

# Guile compiles a script on first use and caches it: one untimed warm-up run.
if [[ -n "$guile" ]]; then
  for p in "${progs[@]}"; do $guile "$here/lang/$p.scm" >/dev/null 2>&1 || true; done
fi

now() { date +%s%N; }
for ((r = 1; r <= reps; r++)); do
  for p in "${progs[@]}"; do
    for l in "${langs[@]}"; do
      available "$l" || continue
      f="$here/lang/$p.${ext[$l]}"
      t0=$(now)
      ${cmd[$l]} "$f" >/dev/null 2>&1 || { echo "FAILED: $l $p" >&2; exit 1; }
      t1=$(now)
      ms=$(( (t1 - t0) / 1000000 ))
      k="$l:$p"
      if [[ -z "${best[$k]:-}" || $ms -lt ${best[$k]} ]]; then best[$k]=$ms; fi
    done
  done
done

ratio() { # lispcad ms / peer ms, 2 decimals; "-" without a peer
  local a="$1" b="${2:-}"
  [[ -z "$b" ]] && { echo "-"; return; }
  ((b == 0)) && b=1
  ((a == 0)) && a=1
  awk -v a="$a" -v b="$b" 'BEGIN { printf "%.2f", a / b }'
}
echo "minimum wall time of $reps interleaved runs, in ms (ratio = lispcad / peer)"
printf "%-6s %9s %9s %9s %9s   %8s %8s %8s\n" program lispcad cpython lua5.4 guile3 "/cpython" "/lua" "/guile"
for p in "${progs[@]}"; do
  L="${best[lispcad:$p]}"
  P="${best[python:$p]:-}"; U="${best[lua:$p]:-}"; G="${best[guile:$p]:-}"
  printf "%-6s %9s %9s %9s %9s   %8s %8s %8s\n" "$p" "$L" "${P:--}" "${U:--}" "${G:--}" \
    "$(ratio "$L" "$P")" "$(ratio "$L" "$U")" "$(ratio "$L" "$G")"
done
