#!/usr/bin/env bash
# T14's resolution (20,000 particles), m = 1/2 and m = 0, 300 microseconds.
set -euo pipefail
lmp=$(realpath "${1:-../../build/lmp}")
cd "$(dirname "$0")"
for m in 0.5 0; do
  "$lmp" -in in.riemann -var m "$m" -var nh 5 -var steps 1500 -var tag "riemann_m$m" \
    -echo none -screen none -log "log.m$m"
  grep -E "^RIEMANN" "log.m$m" || { grep ERROR "log.m$m"; exit 1; }
done
