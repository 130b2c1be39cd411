#!/usr/bin/env bash
# The pre-cracked plate under the mode II crack-tip field, quasi-static:
# prints the load steps and the kink angle against the maximum tangential
# stress criterion; kink.png shows the damage about the tip at the end.
# Any of the deck's variables may follow the binary: ./run.sh lmp -var load dynamic
set -euo pipefail
lmp=$(realpath "${1:-../../build/lmp}")
shift || true
cd "$(dirname "$0")"
"$lmp" -in in.kink -echo none -screen none -log log.kink "$@"
grep -E "^KINK" log.kink || { grep ERROR log.kink; exit 1; }
