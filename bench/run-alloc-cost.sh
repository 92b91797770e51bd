#!/usr/bin/env bash
# What the memory budget's accounting costs (issue 14: at most 3 %). Builds lispcad twice in
# release: as shipped (the counting global allocator, checks at the growth points) and with
# `--features uncounted` (plain mimalloc; the counter never moves, so every check passes at
# once). Then runs, interleaved and paired:
#   - bench/run-lang.sh's programs, with the uncounted binary as the "before" column
#     (ratios lispcad/before > 1 mean the accounting costs time);
#   - the temple batch (scripts/temple.lsp over bench/temple/variants.csv to DXF + SVG, -j 1),
#     REPS times each, median CPU and wall, paired ratio, and the outputs' digests compared;
#   - when valgrind is installed, the instructions each binary executes on the same programs
#     and on the first 100 temple rows (cachegrind, no cache simulation): a count that does not
#     depend on the machine's load, so a cost of a few per cent shows even on a busy machine.
#
#   bench/run-alloc-cost.sh [REPS]      (default 9; PROGS as for run-lang.sh; NOBUILD=1 reuses
#                                        the binaries as they are: COUNTED and UNCOUNTED paths,
#                                        by default target/release/lispcad{,-uncounted})
set -euo pipefail
cd "$(dirname "$0")/.."
reps="${1:-9}"
if [[ -z "${NOBUILD:-}" ]]; then
  cargo build --release --quiet --features uncounted
  cp target/release/lispcad target/release/lispcad-uncounted
  cargo build --release --quiet
fi
counted="${COUNTED:-target/release/lispcad}"
uncounted="${UNCOUNTED:-target/release/lispcad-uncounted}"
echo "## bench/run-lang.sh: lispcad = counted (as shipped), before = uncounted"
LISPCAD="$counted" BEFORE="$uncounted" bash bench/run-lang.sh "$reps"

echo
echo "## temple batch, 1000 variants to DXF + SVG, -j 1"
exec python3 - "$reps" "${PROGS:-fib loop list strings alist empty}" "$counted" "$uncounted" <<'PY'
import hashlib, os, re, shutil, statistics, subprocess, sys, tempfile, time

reps, progs = int(sys.argv[1]), sys.argv[2].split()
bins = {"counted": sys.argv[3], "uncounted": sys.argv[4]}
table = "bench/temple/variants.csv"

def run(binary, out):
    shutil.rmtree(out, ignore_errors=True)
    cmd = [binary, "batch", "scripts/temple.lsp", "--vary", table,
           "-o", f"{out}/t-{{row}}.dxf", "-o", f"{out}/t-{{row}}.svg", "-j", "1"]
    t0 = time.perf_counter()
    p = subprocess.Popen(cmd, stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
    _, status, ru = os.wait4(p.pid, 0)
    wall = time.perf_counter() - t0
    if status != 0:
        sys.exit(f"{cmd} failed")
    return wall, ru.ru_utime + ru.ru_stime

def digest(out):
    h = hashlib.sha256()
    for name in sorted(os.listdir(out)):
        with open(os.path.join(out, name), "rb") as f:
            h.update(name.encode() + f.read())
    return h.hexdigest()

with tempfile.TemporaryDirectory() as tmp:
    times = {k: [] for k in bins}
    digests = {}
    for _ in range(reps):
        for name, binary in bins.items():
            out = os.path.join(tmp, name)
            times[name].append(run(binary, out))
            digests[name] = digest(out)
    print("| binary | median wall s | median CPU s |\n|---|---|---|")
    for name, ts in times.items():
        print(f"| {name} | {statistics.median(t[0] for t in ts):.3f} "
              f"| {statistics.median(t[1] for t in ts):.3f} |")
    for i, what in ((0, "wall"), (1, "CPU")):
        ratios = [c[i] / u[i] for c, u in zip(times["counted"], times["uncounted"])]
        print(f"counted/uncounted ({what}, paired median of {reps}): "
              f"{statistics.median(ratios):.3f}")
    print("outputs:", "identical" if digests["counted"] == digests["uncounted"] else "DIFFERENT")
    print("load average after:", " ".join(f"{x:.2f}" for x in os.getloadavg()))

    if shutil.which("valgrind"):
        with open(table) as f:
            head = f.readlines()[:101]
        short = os.path.join(tmp, "rows100.csv")
        with open(short, "w") as f:
            f.writelines(head)
        work = [(p, ["run", f"bench/lang/{p}.lsp"]) for p in progs]
        work.append(("temple 100 rows", ["batch", "scripts/temple.lsp", "--vary", short, "-o",
                                         f"{tmp}/i/t-{{row}}.dxf", "-o", f"{tmp}/i/t-{{row}}.svg",
                                         "-j", "1"]))
        print("\ninstructions executed (valgrind cachegrind)")
        print("| workload | counted | uncounted | counted/uncounted |\n|---|---|---|---|")
        for name, args in work:
            n = {}
            for b, binary in bins.items():
                r = subprocess.run(["valgrind", "--tool=cachegrind", "--cache-sim=no",
                                    "--cachegrind-out-file=/dev/null", binary] + args,
                                   stdout=subprocess.DEVNULL, stderr=subprocess.PIPE, text=True)
                n[b] = int(re.search(r"I\s+refs:\s+([\d,]+)", r.stderr).group(1).replace(",", ""))
            print(f"| {name} | {n['counted']:,} | {n['uncounted']:,} "
                  f"| {n['counted'] / n['uncounted']:.4f} |")
PY
