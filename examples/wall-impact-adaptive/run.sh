#!/usr/bin/env bash
# The plate into the wall, adaptive (fix pd/timestep) and at the fixed 2e-8 s:
# prints each run's last thermo row (step, dt, time, kinetic + elastic +
# dissipated energy in J, broken bonds; 743.40 J at the start) or its ERROR.
set -euo pipefail
lmp=$(realpath "${1:-../../build/lmp}")
cd "$(dirname "$0")"
for adapt in 1 0; do
  "$lmp" -in in.wall -var adapt "$adapt" -echo none -screen none -log "log.adapt$adapt" || true
  echo "adapt $adapt: $(grep -E '^ERROR' "log.adapt$adapt" | head -1)$(awk '/^ +[0-9]+ +[-0-9.e+]+ +[-0-9.e+]+ +[-0-9.e+]+ +[0-9]+ *$/ {row = $0} END {print row}' "log.adapt$adapt")"
done
grep "pd/timestep: this run" log.adapt1
