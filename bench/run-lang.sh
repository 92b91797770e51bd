#!/usr/bin/env bash
# Runs the language benchmarks (bench/lang/{fib,loop,list,strings,alist,empty}) on lispcad,
# CPython 3.11, Lua 5.4 and Guile 3.0, REPS times each (default 9), interleaved: rep 1 of every
# program on every language, then rep 2, ... so load from other processes on a shared machine
# spreads over all of them. Prints, per program:
#   - the median wall time and median CPU time (user+sys) of each language, in ms;
#   - paired ratios lispcad/peer: each rep's lispcad run is divided by the same rep's peer run
#     (adjacent in time, so they saw the same load), and the median of those ratios is shown;
#   - the peak resident memory (max RSS) of each, in MB, and its ratio.
# The load average before and after is printed: say it when quoting the figures. A peer not
# installed is left out (bench/install-peers.sh installs Lua 5.4 and Guile 3.0).
#
#   bench/run-lang.sh [REPS]        (LISPCAD=path overrides the binary; PROGS="fib list" picks;
#                                    BEFORE=path adds an older lispcad as one more peer)
set -euo pipefail
here="$(cd "$(dirname "$0")" && pwd)"
root="$(dirname "$here")"
reps="${1:-9}"
lispcad="${LISPCAD:-$root/target/release/lispcad}"
if [[ ! -x "$lispcad" ]]; then
  (cd "$root" && cargo build --release --quiet)
fi
python="$(command -v python3.11 || command -v python3)"
# A version manager's shim (pyenv) is a shell script: time the interpreter itself.
python="$("$python" -c 'import sys; print(sys.executable)')"
lua="$(command -v lua5.4 || true)"
guile="$(command -v guile || true)"

# Guile compiles a script on first use and caches it: one untimed warm-up run each.
if [[ -n "$guile" ]]; then
  for p in ${PROGS:-fib loop list strings alist empty}; do
    "$guile" --no-debug "$here/lang/$p.scm" >/dev/null 2>&1 || true
  done
fi

exec "$python" - "$here/lang" "$reps" "${PROGS:-fib loop list strings alist empty}" \
  "$lispcad" "$python" "$lua" "$guile" "${BEFORE:-}" <<'PY'
import os, statistics, subprocess, sys, time

lang_dir, reps, progs, lispcad, python, lua, guile, before = sys.argv[1:9]
reps, progs = int(reps), progs.split()
langs = [("lispcad", [lispcad, "run"], "lsp")]
if before:
    langs.append(("before", [before, "run"], "lsp"))
langs.append(("cpython", [python], "py"))
if lua:
    langs.append(("lua5.4", [lua], "lua"))
if guile:
    langs.append(("guile3", [guile, "--no-debug"], "scm"))

rss_file = os.path.join(os.environ.get("TMPDIR", "/tmp"), f"run-lang-{os.getpid()}.rss")

def run(cmd):
    """Wall seconds, CPU seconds (user+sys) and peak RSS in KB of one run. The peak comes from
    GNU time, which starts the program from its own small process: Linux carries a process's
    peak RSS across exec, so a program started straight from this (larger) Python process
    would report at least Python's size."""
    t0 = time.perf_counter()
    p = subprocess.Popen(["/usr/bin/time", "-f", "%M", "-o", rss_file] + cmd,
                         stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
    _, status, ru = os.wait4(p.pid, 0)
    wall = time.perf_counter() - t0
    p.returncode = os.waitstatus_to_exitcode(status)
    if p.returncode != 0:
        sys.exit(f"FAILED ({p.returncode}): {' '.join(cmd)}")
    with open(rss_file) as f:
        rss = int(f.read().split()[-1])
    return wall, ru.ru_utime + ru.ru_stime, rss

print(f"load average before: {' '.join(f'{x:.2f}' for x in os.getloadavg())}")
res = {}  # (lang, prog) -> list of (wall, cpu, rss)
for rep in range(reps):
    # Rotate the order each rep: the first run of a group pays a cold start.
    order = langs[rep % len(langs):] + langs[:rep % len(langs)]
    for p in progs:
        for name, cmd, ext in order:
            res.setdefault((name, p), []).append(run(cmd + [os.path.join(lang_dir, f"{p}.{ext}")]))
print(f"load average after:  {' '.join(f'{x:.2f}' for x in os.getloadavg())}")
os.remove(rss_file)

peers = [n for n, _, _ in langs[1:]]
def table(title, k, scale, unit, paired=True):
    print(f"\n{title}")
    head = f"{'program':8}" + "".join(f"{n:>10}" for n, _, _ in langs)
    head += "   " + "".join(f"{'/' + n:>10}" for n in peers)
    print(head)
    for p in progs:
        row = f"{p:8}"
        for n, _, _ in langs:
            row += f"{statistics.median(r[k] for r in res[(n, p)]) * scale:>10.{0 if unit == 'ms' else 1}f}"
        row += "   "
        for n in peers:
            a, b = res[("lispcad", p)], res[(n, p)]
            if paired:
                ratio = statistics.median(x[k] / max(y[k], 1e-9) for x, y in zip(a, b))
            else:
                ratio = max(x[k] for x in a) / max(max(y[k] for y in b), 1)
            row += f"{ratio:>10.2f}"
        print(row)

table(f"median wall time of {reps} interleaved runs, ms; ratio = median of paired lispcad/peer", 0, 1000, "ms")
table(f"median CPU time (user+sys) of the same runs, ms; paired ratios as above", 1, 1000, "ms")
table("peak resident memory (max RSS), MB; ratio of the largest peaks", 2, 1 / 1024, "MB", paired=False)
PY
