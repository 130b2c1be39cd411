#!/usr/bin/env bash
# T14's D2 resolution (0.395 mm, 17,679 particles), extended and classical
# correspondence, each until the rod is at rest; prints our measurements
# (lines TAYLOR: at 80 us, TAYLOR_REST: at rest) and T14's (Table 3.2).
# NP=2 ./run.sh runs each on 2 MPI ranks.
set -euo pipefail
lmp=$(realpath "${1:-../../build/lmp}")
cd "$(dirname "$0")"
launch=()
if [ "${NP:-1}" -gt 1 ]; then launch=(mpirun -np "$NP"); fi
for s in extended classical; do
  "${launch[@]}" "$lmp" -in in.taylor -var strain "$s" -var tag "taylor_$s" \
    -echo none -screen none -log "log.$s"
  grep -E "^TAYLOR" "log.$s" || { grep ERROR "log.$s"; exit 1; }
done
echo "TAYLOR T14 peridynamics D2 (classical correspondence, 16929 particles): length_mm 21 radius_mm 7.5 epmax 2.9"
echo "TAYLOR T14 peridynamics D1 / D3: length_mm 22 / 21 radius_mm 7.1 / 7.4 epmax 2.7 / 3.3"
echo "TAYLOR T14 Table 3.2, FE and OTM: length_mm 21-22 radius_mm 6.8-7.2 epmax 2.5-3.2"
