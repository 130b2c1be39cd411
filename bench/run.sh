#!/usr/bin/env bash
# make bench [FULL=1]: bench/report.py times the pd/ and legacy PERI styles
# with the lmp binary given and prints the tables (see bench/README.md).
# FULL=1 (or any value but 0/no) adds the size sweep, memory and 2 ranks;
# PASSES=N runs the block's styles N times over (report.py's default: 3).
set -euo pipefail
lmp=$(realpath "$1")
here=$(cd "$(dirname "$0")" && pwd)
args=()
case "${FULL:-0}" in 0|no|"") ;; *) args+=(--full) ;; esac
[ -z "${PASSES:-}" ] || args+=(--passes "$PASSES")
exec python3 "$here/report.py" --lmp "$lmp" ${args[@]+"${args[@]}"}
