#!/usr/bin/env bash
# Regenerates the README pictures in docs/img from the shipped configs.
# Usage: scripts/make-figures.sh   (builds gearloss if needed, installs python3-matplotlib, -numpy, -pandas if missing)
set -euo pipefail
cd "$(dirname "$0")/.."
scripts/install-deps.sh
scripts/build.sh > /dev/null
bin=build/app/gearloss
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
out=docs/img
mkdir -p "$out"
speeds=$(python3 -c "print(','.join(f'{300+i*150}' for i in range(19)))")rpm
torques=$(python3 -c "print(','.join(f'{25+i*25}' for i in range(16)))")Nm
"$bin" map configs/transfer-box.yaml --speed "$speeds" --torque "$torques" -o "$tmp/map.csv"
scripts/plot.sh map "$tmp/map.csv" "$out/map-efficiency.png" --kind efficiency \
    --title "Transfer gearbox (seed 001), 75W90-A, stabilised: efficiency [%]"
scripts/plot.sh map "$tmp/map.csv" "$out/map-oil-temp.png" --kind oil-temp \
    --title "Transfer gearbox, 75W90-A: stabilised oil temperature [degC]"
"$bin" map configs/transfer-box.yaml -o "$tmp/seed.csv"
scripts/plot.sh map "$tmp/seed.csv" "$out/map-breakdown.png" --kind breakdown \
    --title "Transfer gearbox on the seed 001 grid: where the power goes"
"$bin" compare configs/transfer-box.yaml --oil configs/oils/75W90-A.yaml --oil configs/oils/75W140-A.yaml \
    --speed 400,600,800,1000,1200,1400,1600rpm --torque 100,150,200,250,300,350Nm -o "$tmp/diff.csv"
scripts/plot.sh compare "$tmp/diff.csv" "$out/compare-75W140-75W90.png" \
    --title "75W140-A minus 75W90-A on the transfer gearbox (stabilised)"
"$bin" cycle configs/automatic-6speed.yaml --cycle nedc --start-temp -10degC --prewarm 90degC --heater 2kW \
    -o "$tmp/trace.csv" > /dev/null
scripts/plot.sh cycle "$tmp/trace.csv" "$out/cycle-nedc-automatic.png" \
    --title "Six-speed automatic over the NEDC: from a -10 degC cold soak, warm at 90 degC, pre-warmed (2 kW)"
"$bin" synth configs/transfer-box.yaml --speed 400,550,700,850,1000,1150rpm --torque 100,160,220,280,340Nm \
    --effect windage=25W --seed 7 -o "$tmp/rec.csv"
"$bin" diagnose configs/transfer-box.yaml "$tmp/rec.csv" --residuals "$tmp/res.csv" > /dev/null
scripts/plot.sh diagnose "$tmp/res.csv" "$out/diagnose-windage.png" \
    --title "gearloss diagnose: concealed windage 25 W found and fitted"
# The FVA two-stage industrial gearbox imported from REXS (docs/rexs.md, "Example").
"$bin" import tests/data/rexs/FVA-Industriegetriebe_2stufig_1-4.rexs -o "$tmp/fva.yaml" 2> /dev/null
"$bin" map "$tmp/fva.yaml" --speed "$(python3 -c "print(','.join(f'{250*i}' for i in range(1, 15)))")rpm" \
    --torque "$(python3 -c "print(','.join(f'{50*i}' for i in range(1, 17)))")Nm" -o "$tmp/fva-map.csv"
scripts/plot.sh map "$tmp/fva-map.csv" "$out/rexs-fva-efficiency.png" --kind efficiency \
    --title "FVA two-stage gearbox imported from REXS 1.4, oil at 70 degC: efficiency [%]"
ls -1 "$out"
