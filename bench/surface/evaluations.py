#!/usr/bin/env python3
"""Calls per entry call from a callgrind profile (bench/surface/evaluations.sh).

Usage: evaluations.py PROFILE ENTRY_RE [COUNTED_RE...]: the calls of functions matching ENTRY_RE,
their inclusive instructions per call, and the calls of each COUNTED_RE per entry call."""
import re, sys, collections

path, entry_re = sys.argv[1], re.compile(sys.argv[2])
evals = sys.argv[3:]
names = {}
calls = collections.Counter()
incl = collections.Counter()
total = 0
cfn = None
fn_re = re.compile(r'^(c?fn)=\((\d+)\)(?: (.*))?$')
with open(path, errors='replace') as f:
    pending = None
    for line in f:
        line = line.rstrip('\n')
        m = fn_re.match(line)
        if m:
            kind, idx, name = m.groups()
            if name:
                names[idx] = name
            if kind == 'cfn':
                cfn = idx
            continue
        if line.startswith('calls='):
            n = int(line[6:].split()[0])
            calls[cfn] += n
            pending = cfn
            continue
        if pending is not None:
            # The line after calls= is the call's inclusive cost: position, then instructions.
            parts = line.split()
            if len(parts) >= 2:
                incl[pending] += int(parts[1])
            pending = None
            continue
        if line.startswith('summary:') or line.startswith('totals:'):
            total = int(line.split()[1])
e = sum(n for i, n in calls.items() if entry_re.search(names.get(i, '')))
total = sum(n for i, n in incl.items() if entry_re.search(names.get(i, '')))
out = [f"entry {e}", f"instr/entry {total / max(e, 1) / 1e6:.2f} M"]
for r in evals:
    rr = re.compile(r)
    v = sum(n for i, n in calls.items() if rr.search(names.get(i, '')))
    out.append(f"{r.split('::')[-2] + '::' + r.split('::')[-1] if '::' in r else r} {v / max(e, 1):.1f}")
print("  ".join(out))
