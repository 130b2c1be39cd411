#!/usr/bin/env bash
# make validate: three decks that together use every style, failure law,
# restart and the error-free paths, under valgrind's memcheck. A memory
# error (invalid read or write, use of uninitialized values in our code, a
# definite leak) fails the run. Open MPI's own start-up noise is not ours:
# only errors with a PERIDYNAMICS_EXT frame (pd_ or PD in the stack) count.
set -u
lmp=$(realpath "$1")
here=$(cd "$(dirname "$0")" && pwd)
command -v valgrind >/dev/null || { echo "valgrind: installing"; apt-get install -y -qq valgrind >/dev/null; }
work=$(mktemp -d)
cd "$work"
status=0
for deck in fracture contact plate; do
  valgrind --error-limit=no --leak-check=full --show-leak-kinds=definite --num-callers=30 \
    --log-file=vg.$deck "$lmp" -in "$here/in.$deck" -echo none -log log.$deck \
    -var materials "$here/../../potentials/materials.pd" > out.$deck 2>&1
  rc=$?
  ours=$(awk '/^==[0-9]+== (Invalid|Conditional|Use of uninit|Mismatched|[0-9,]+ bytes in [0-9,]+ blocks are definitely)/{blk=$0; keep=1; next}
              keep && /^==[0-9]+== *$/ {if (hit) print blk; keep=0; hit=0; next}
              keep && /(pd_|PD|PairPD|FixPD|ComputePD)/ {hit=1}' vg.$deck | wc -l)
  summary=$(grep "ERROR SUMMARY" vg.$deck | tail -1)
  if [ $rc -ne 0 ] || [ "$ours" -ne 0 ] || ! grep -q "^Total wall time" out.$deck; then
    echo "FAIL valgrind $deck: exit $rc, $ours memory errors in PERIDYNAMICS_EXT code ($summary); see $work/vg.$deck"
    status=1
  else
    echo "PASS valgrind $deck: no memory error in PERIDYNAMICS_EXT code ($summary)"
  fi
done
exit $status
