#!/usr/bin/env bash
# The thermal rating pictures of docs/rating.md: the thermal power limit curves of the transfer
# box and of the 2.5 MW wind-turbine gearbox (docs/img/rating-*.png).
# Usage: scripts/rating-figures.sh [GEARLOSS_BINARY]   (default build/app/gearloss)
set -euo pipefail
cd "$(dirname "$0")/.."
bin=${1:-build/app/gearloss}
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
"$bin" rating configs/transfer-box.yaml --speed 300:3000:150rpm --max-torque 2000Nm -o "$tmp/tb.csv"
/usr/bin/python3 scripts/plot-rating.py "$tmp/tb.csv" docs/img/rating-transfer-box.png \
    --title "Transfer gearbox (seed 001), 75W90-A, low ratio: thermal power limit at {limit} degC oil, 25 degC air"
"$bin" rating configs/wind-turbine-2.5MW.yaml --speed 6:20:1rpm -o "$tmp/wt.csv"
rated=()
while IFS=, read -r s p; do rated+=(--rated "$s:$p"); done < <(
    "$bin" map configs/wind-turbine-2.5MW.yaml -o - 2> /dev/null |
        python3 -c "import csv,sys; [print(f\"{r['speed_in_rpm']},{float(r['power_in_W'])/1e3}\") for r in csv.DictReader(sys.stdin)]")
/usr/bin/python3 scripts/plot-rating.py "$tmp/wt.csv" docs/img/rating-wind-turbine.png "${rated[@]}" \
    --title "2.5 MW wind-turbine gearbox, PAOR, housing + oil-air cooler: thermal power limit at {limit} degC oil"
