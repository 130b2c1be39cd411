#!/bin/sh
# The ballistic-limit campaign: 15 impacts from one target on 2 partitions
# (about 35 s on 2 cores), the Lambert-Jonas fit and the pictures.
#   ./run.sh [path/to/lmp] [partitions]
set -e
cd "$(dirname "$0")"
LMP=$(realpath "${1:-../../build/lmp}")
P=${2:-2}
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1 OMPI_MCA_rmaps_base_oversubscribe=1
python3 ../../tools/campaign/pd_campaign.py campaign.ini -p "$P" --lmp "$LMP"
python3 ballistic_limit.py campaign.out/results.csv ballistic_limit.png
for v in 300 600; do
  python3 ../../tools/pd_picture.py "damage.v=$v.txt" "damage_v$v.png" --x x --y y \
    --spacing 0.001 --color c_dmg --range 0 1 --label damage --size 900x760 \
    --title "sphere at $v m/s through a 3 mm Al plate: damage seen from above"
done
