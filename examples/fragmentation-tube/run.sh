#!/usr/bin/env bash
# The reduced study (make validate): the 2D ring at S09's four spacings,
# 600 and 200 m/s, three seeds each, two cases side by side (about a
# minute on 2 cores), then the table, distributions and pictures in
# ring.out/. Fails unless the finer three spacings agree within 15%.
set -euo pipefail
lmp=$(realpath "${1:-../../build/lmp}")
cd "$(dirname "$0")"
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1
rm -rf ring.out/results                 # a fresh run, not a resumed one
python3 ../../tools/campaign/pd_campaign.py campaign-2d.ini -p 2 --lmp "$lmp"
python3 report.py ring.out --check
