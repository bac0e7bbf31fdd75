#!/usr/bin/python3
"""Categorise the differences between two `robust_snapshot K -v` outputs
(lines: <entry> <case> <status> <hash>): per entry point, the cases whose
status changed (old -> new) and those with the same status but other bytes.

    tests/robust/snapshot_diff.py BASE.txt NEW.txt
"""
import sys, collections
def load(p):
    d = {}
    for line in open(p):
        f = line.split()
        if len(f) < 4: continue
        d[(f[0], f[1])] = (f[2], f[3])
    return d
a, b = load(sys.argv[1]), load(sys.argv[2])
st = collections.Counter(); hs = collections.Counter(); ex = collections.defaultdict(list)
for k in sorted(set(a) | set(b)):
    x, y = a.get(k), b.get(k)
    if x == y: continue
    if x is None or y is None: st[(k[0], str(x), str(y))] += 1; continue
    if x[0] != y[0]: st[(k[0], x[0], y[0])] += 1; ex[(k[0], x[0], y[0])].append(k[1])
    else: hs[(k[0], x[0])] += 1; ex[(k[0], x[0], 'hash')].append(k[1])
print("status changes:")
for (e, o, n), c in sorted(st.items()): print(f"  {e:34s} {o} -> {n}: {c}  e.g. {' '.join(ex[(e,o,n)][:5])}")
print("same status, different output:")
for (e, o), c in sorted(hs.items()): print(f"  {e:34s} {o}: {c}  e.g. {' '.join(ex[(e,o,'hash')][:5])}")
