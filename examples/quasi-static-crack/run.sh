#!/usr/bin/env bash
# The notched plate opened in 26 load steps, each relaxed by fix pd/adr:
# prints the load-displacement table (one row per load step) and the
# summary; damage pictures crack.18.png, crack.19.png, crack.22.png.
set -euo pipefail
lmp=$(realpath "${1:-../../build/lmp}")
cd "$(dirname "$0")"
"$lmp" -in in.quasi-static -echo none -screen none -log log.quasi-static
grep -E "^(LOAD|QUASI-STATIC)" log.quasi-static || { grep ERROR log.quasi-static; exit 1; }
