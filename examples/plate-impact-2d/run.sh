#!/usr/bin/env bash
# Run the 2D impact with m = 0.5 and m = 0 and summarize both.
set -euo pipefail
lmp=$(realpath "${1:-../../build/lmp}")
cd "$(dirname "$0")"
for m in 0.5 0; do
  "$lmp" -in in.plate-impact -var m "$m" -var tag "impact_m$m" -echo none -screen none -log "log.m$m"
  grep -E "^SUMMARY" "log.m$m" | sed "s/^SUMMARY /  /" || { grep ERROR "log.m$m"; exit 1; }
done
