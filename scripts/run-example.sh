#!/usr/bin/env bash
# One command from a clean clone: install what is missing, build, and map the
# shipped transfer gearbox (seed 001 test grid) to out/transfer-box-map.csv.
set -euo pipefail
cd "$(dirname "$0")/.."
scripts/install-deps.sh
scripts/build.sh
mkdir -p out
build/app/gearloss map configs/transfer-box.yaml -o out/transfer-box-map.csv
echo "wrote out/transfer-box-map.csv:"
column -t -s, out/transfer-box-map.csv 2>/dev/null || cat out/transfer-box-map.csv
