#!/usr/bin/env bash
# Runs the four language benchmarks (bench/lang/{fib,loop,list,empty}) on lispcad, CPython 3,
# Lua 5.4 and Guile 3.0, REPS times each, interleaved (rep 1 of every program on every
# language, then rep 2, ...) so load from other processes on a shared machine spreads over
# all of them; prints the minimum wall time and the minimum CPU time (user+sys, less sensitive
# to other load) of each, with the ratio lispcad/peer.
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

TIMEFORMAT="%3R %3U %3S"
tfile="$(mktemp)"
trap 'rm -f "$tfile"' EXIT
declare -A cpu
for ((r = 1; r <= reps; r++)); do
  for p in "${progs[@]}"; do
    for l in "${langs[@]}"; do
      available "$l" || continue
      f="$here/lang/$p.${ext[$l]}"
      { time ${cmd[$l]} "$f" >/dev/null 2>&1 || { echo "FAILED: $l $p" >&2; exit 1; }; } 2>"$tfile"
      read -r e u s <"$tfile"
      ms=$(awk -v e="$e" 'BEGIN { printf "%d", e * 1000 }')
      cms=$(awk -v u="$u" -v s="$s" 'BEGIN { printf "%d", (u + s) * 1000 }')
      k="$l:$p"
      if [[ -z "${best[$k]:-}" || $ms -lt ${best[$k]} ]]; then best[$k]=$ms; fi
      if [[ -z "${cpu[$k]:-}" || $cms -lt ${cpu[$k]} ]]; then cpu[$k]=$cms; fi
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
table() { # title, name of the array of minima
  local -n m="$2"
  echo "$1"
  printf "%-6s %9s %9s %9s %9s   %8s %8s %8s\n" program lispcad cpython lua5.4 guile3 "/cpython" "/lua" "/guile"
  for p in "${progs[@]}"; do
    L="${m[lispcad:$p]}"
    P="${m[python:$p]:-}"; U="${m[lua:$p]:-}"; G="${m[guile:$p]:-}"
    printf "%-6s %9s %9s %9s %9s   %8s %8s %8s\n" "$p" "$L" "${P:--}" "${U:--}" "${G:--}" \
      "$(ratio "$L" "$P")" "$(ratio "$L" "$U")" "$(ratio "$L" "$G")"
  done
}
table "minimum wall time of $reps interleaved runs, in ms (ratio = lispcad / peer)" best
echo
table "minimum CPU time (user+sys) of the same runs, in ms" cpu
