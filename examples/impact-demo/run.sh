#!/usr/bin/env bash
# make demo: run the impact demo and summarize it.
set -euo pipefail
lmp=$(realpath "$1")
here=$(cd "$(dirname "$0")" && pwd)
out=$(realpath "${DEMO_DIR:-$(dirname "$lmp")/demo}")
mkdir -p "$out"
cd "$out"
rm -f impact.*.png impact.*.txt
"$lmp" -in "$here/in.impact" -echo none -screen none -log log.lammps
for n in 0 400 800; do
  python3 "$here/../../tools/pd_picture.py" impact.$n.txt impact.$n.png --x x --y y --slab z -0.00026 0.00026 \
    --spacing 0.0005 --color c_dmg --range 0 0.5 --label damage --size 800x600 \
    --title "glass cylinder struck at 100 m/s: damage, cut through its axis" > /dev/null
done
echo "== impact demo (examples/impact-demo) =="
grep -E "^pd/|^pd/bonds" log.lammps | sed 's/^/  /'
grep -E "^Loop time" log.lammps | head -1 | sed 's/^/  /'
grep -E "^DEMO" log.lammps | sed 's/^DEMO /  /'
echo "  pictures: $out/impact.0.png (start), $out/impact.400.png (middle), $out/impact.800.png (end)   log: $out/log.lammps"
