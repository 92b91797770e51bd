#!/usr/bin/env bash
# The main-job benchmark (issue 5): 1000 temple variants to DXF + SVG with lispcad (batch,
# -j 1 and -j 2) and with the same temple in Python + ezdxf; then (issue 15) the same batch
# with a contact sheet (--sheet sheet.pdf), and DXF + PDF per variant against Python + ezdxf
# with its matplotlib PDF backend (those two with -j $JOBS, default 2). Prints wall and CPU
# times, the ratios and the load average before and after (the machine is shared).
# BEFORE=path runs an older lispcad on the same -j 2 batch right after this build's and
# compares every output file's SHA-256 with this build's (a speed change must not change a byte).
# PDF=0 skips the contact sheet and the two DXF + PDF runs (about 4 minutes, most of it Python).
# Outputs go under $TMPDIR (default /tmp). On this machine's ext4, creating a file costs a scan
# of the files deleted from its block group in the last minutes (the previous run's 6,000
# outputs), so kernel time there depends on what ran before: TMPDIR=/dev/shm (tmpfs, for both
# tools) measures the programs rather than that history. (The file system has no journal, and
# ext4 then skips each inode freed less than 60 s ago, reading its inode block, at every file
# creation: perf shows `recently_deleted` under `__ext4_new_inode`. On ext4, start a run at
# least 65 s after the last mass deletion there, this script's own included.)
# Usage: [TMPDIR=dir] [JOBS=N] [BEFORE=path] [PDF=0] bench/run-temple.sh [ROWS.csv]
set -euo pipefail
cd "$(dirname "$0")/.."
table=${1:-bench/temple/variants.csv}
rows=$(( $(wc -l < "$table") - 1 ))
jobs=${JOBS:-2}
out=$(mktemp -d)
trap 'rm -rf "$out"' EXIT
cargo build --release -q
[ -x .venv/bin/python ] || bash .ci/setup
py=.venv/bin/python
# The PDF peer draws through matplotlib (not needed by the tests).
"$py" -c "import matplotlib" 2>/dev/null || .venv/bin/pip install -q matplotlib

# Wall and CPU (user+sys) seconds of a command, via bash's `times` in a subshell.
measure() {
  local t0 t1
  t0=$(date +%s.%N)
  ( "$@" >/dev/null 2>&1; times ) > "$out/times" 2>&1
  t1=$(date +%s.%N)
  local cpu
  cpu=$(tail -1 "$out/times" | awk '{ for (i=1;i<=2;i++) { split($i,a,"m"); sub("s","",a[2]); s+=a[1]*60+a[2] } print s }')
  echo "$(echo "$t1 - $t0" | bc -l) $cpu"
}

load0=$(cut -d' ' -f1-3 /proc/loadavg)
read -r lc1_wall lc1_cpu < <(measure target/release/lispcad batch scripts/temple.lsp --vary "$table" \
  -o "$out/j1/t-{row}.dxf" -o "$out/j1/t-{row}.svg" -j 1)
read -r lc2_wall lc2_cpu < <(measure target/release/lispcad batch scripts/temple.lsp --vary "$table" \
  -o "$out/j2/t-{row}.dxf" -o "$out/j2/t-{row}.svg" -j 2)
if [[ -n "${BEFORE:-}" ]]; then
  read -r bf_wall bf_cpu < <(measure "$BEFORE" batch scripts/temple.lsp --vary "$table" \
    -o "$out/bf/t-{row}.dxf" -o "$out/bf/t-{row}.svg" -j 2)
fi
read -r py_wall py_cpu < <(measure "$py" bench/temple/temple_ezdxf.py --vary "$table" -o "$out/py")
pdf=${PDF:-1}
if [[ "$pdf" != 0 ]]; then
read -r sh_wall sh_cpu < <(measure target/release/lispcad batch scripts/temple.lsp --vary "$table" \
  -o "$out/sh/t-{row}.dxf" -o "$out/sh/t-{row}.svg" -j "$jobs" --sheet "$out/sheet.pdf")
read -r pdf_wall pdf_cpu < <(measure target/release/lispcad batch scripts/temple.lsp --vary "$table" \
  -o "$out/pdf/t-{row}.dxf" -o "$out/pdf/t-{row}.pdf" -j "$jobs")
read -r pypdf_wall pypdf_cpu < <(measure "$py" bench/temple/temple_ezdxf.py --vary "$table" \
  -o "$out/pypdf" --pdf)
fi

load1=$(cut -d' ' -f1-3 /proc/loadavg)
cmp -s <(cd "$out/j1" && cat $(ls | sort)) <(cd "$out/j2" && cat $(ls | sort)) \
  && same="identical" || same="DIFFERENT"

printf '%d variants, DXF + SVG each (outputs of -j 1 and -j 2: %s)\n\n' "$rows" "$same"
printf '| run | wall s | CPU s | CPU ms/variant |\n|---|---|---|---|\n'
runs=("lispcad -j 1:$lc1_wall:$lc1_cpu" "lispcad -j 2:$lc2_wall:$lc2_cpu" "Python+ezdxf:$py_wall:$py_cpu")
if [[ "$pdf" != 0 ]]; then
  runs+=("lispcad -j $jobs + --sheet sheet.pdf:$sh_wall:$sh_cpu"
    "lispcad -j $jobs DXF + PDF:$pdf_wall:$pdf_cpu"
    "Python+ezdxf DXF + PDF (matplotlib):$pypdf_wall:$pypdf_cpu")
fi
for r in "${runs[@]}"; do
  IFS=: read -r name w c <<< "$r"
  printf '| %s | %.2f | %.2f | %.3f |\n' "$name" "$w" "$c" "$(echo "$c * 1000 / $rows" | bc -l)"
done
printf '\nPython/lispcad (CPU, -j 1): %.1fx   (wall, -j 1): %.1fx\n' \
  "$(echo "$py_cpu / $lc1_cpu" | bc -l)" "$(echo "$py_wall / $lc1_wall" | bc -l)"
printf 'speed-up -j 1 -> -j 2 (wall): %.2fx\n' "$(echo "$lc1_wall / $lc2_wall" | bc -l)"
printf 'Python/lispcad (CPU, -j 2): %.1fx\n' "$(echo "$py_cpu / $lc2_cpu" | bc -l)"
if [[ "$pdf" != 0 ]]; then
  printf 'contact sheet: %s bytes; its cost over the plain batch (CPU): %.2f s\n' \
    "$(stat -c %s "$out/sheet.pdf")" "$(echo "$sh_cpu - $lc2_cpu" | bc -l)"
  printf 'PDF: Python+matplotlib/lispcad (CPU): %.1fx   (wall): %.1fx\n' \
    "$(echo "$pypdf_cpu / $pdf_cpu" | bc -l)" "$(echo "$pypdf_wall / $pdf_wall" | bc -l)"
fi
if [[ -n "${BEFORE:-}" ]]; then
  digests() { (cd "$1" && ls | sort | xargs sha256sum); }
  cmp -s <(digests "$out/j2") <(digests "$out/bf") && bsame="identical" || bsame="DIFFERENT"
  printf 'BEFORE (%s) -j 2: wall %.2f s, CPU %.2f s; this build / BEFORE (CPU): %.2f; outputs (SHA-256 of %d files): %s\n' \
    "$BEFORE" "$bf_wall" "$bf_cpu" "$(echo "$lc2_cpu / $bf_cpu" | bc -l)" "$(ls "$out/j2" | wc -l)" "$bsame"
fi
printf 'load average (1/5/15 min) before: %s   after: %s\n' "$load0" "$load1"
