#!/usr/bin/env bash
# make bench: the benchmark block with legacy PERI and pd/ styles in one
# LAMMPS run; prints each Loop time and the speed-up of pd/ over peri/.
set -euo pipefail
lmp=$(realpath "$1")
here=$(cd "$(dirname "$0")" && pwd)
out=$(mktemp -d)
cd "$here"
"$lmp" -in in.block -echo none -screen none -log "$out/log.bench"
python3 - "$out/log.bench" <<'PY'
import re, sys
log = open(sys.argv[1]).read()
times, style = {}, None
for line in log.splitlines():
    m = re.match(r"BENCH (\S+)", line)
    if m: style = m.group(1)
    m = re.match(r"Loop time of ([0-9.eE+-]+) on 1 procs for 200 steps", line)
    if m and style: times[style] = float(m.group(1))
print("benchmark block: 4096 atoms, 122 bonds per atom, 200 steps, 1 rank")
print(f"{'style':22s} {'Loop time (s)':>14s}")
for s, t in times.items(): print(f"{s:22s} {t:14.4f}")
print("speed-up (legacy time / pd time):")
for new, old in [("pd_bond", "peri_pmb"), ("pd_bond_legacy", "peri_pmb"),
                 ("pd_ordinary", "peri_lps"), ("pd_ordinary_legacy", "peri_lps")]:
    print(f"  {new:20s} vs {old:10s} {times[old] / times[new]:6.2f}x")
print("cost of contact (hybrid/overlay with pd/contact, time / time without):")
print(f"  {'pd_ordinary_contact':20s} {times['pd_ordinary_contact'] / times['pd_ordinary']:6.2f}x")
nb = re.findall(r"pd/contact: list cutoff \S+ .*?: ([0-9.]+) neighbours per atom", log)
if nb: print(f"  contact list: {nb[0]} neighbours per atom (cutoff = contact distance + skin)")
print("cost of the nonlinear strain (time / time of m = 1/2):")
for new in ("pd_ordinary_m0", "pd_ordinary_m-1"):
    print(f"  {new:20s} {times[new] / times['pd_ordinary']:6.2f}x")
print("cost of correspondence (time / time of pd_ordinary m = 1/2):")
for new in ("pd_corr_classical", "pd_corr_extended", "pd_corr_j2"):
    print(f"  {new:20s} {times[new] / times['pd_ordinary']:6.2f}x")
PY
