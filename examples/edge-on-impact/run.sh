#!/usr/bin/env bash
# The full example: horizon 5.5 spacings (10,400 particles), 15 and 35 m/s,
# 600 microseconds; damage pictures every 200 microseconds.
set -euo pipefail
lmp=$(realpath "${1:-../../build/lmp}")
cd "$(dirname "$0")"
for v in 15 35; do
  "$lmp" -in in.edge-on -var v0 "$v" -var steps 12000 -var images 4000 \
    -echo none -screen none -log "log.v$v"
  grep -E "^EDGE-ON" "log.v$v" || { grep ERROR "log.v$v"; exit 1; }
done
