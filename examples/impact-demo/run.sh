#!/usr/bin/env bash
# make demo: run the impact demo and summarize it.
set -euo pipefail
lmp=$(realpath "$1")
here=$(cd "$(dirname "$0")" && pwd)
out=$(realpath "${DEMO_DIR:-$(dirname "$lmp")/demo}")
mkdir -p "$out"
cd "$out"
rm -f impact.*.png
"$lmp" -in "$here/in.impact" -echo none -screen none -log log.lammps
echo "== impact demo (examples/impact-demo) =="
grep -E "^pd/|^pd/bonds" log.lammps | sed 's/^/  /'
grep -E "^Loop time" log.lammps | head -1 | sed 's/^/  /'
grep -E "^DEMO" log.lammps | sed 's/^DEMO /  /'
echo "  pictures: $out/impact.0.png (start), $out/impact.400.png (middle), $out/impact.800.png (end)   log: $out/log.lammps"
