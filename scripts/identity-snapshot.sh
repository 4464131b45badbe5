#!/usr/bin/env bash
# Prints one md5 a line for the outputs of BINARY on every shipped case and on sweeps, shards,
# merges and VECTO tables, at 1 and 2 threads: two binaries that print the same lines write
# byte-identical outputs. JSON summaries are compared without their timing keys.
# Usage: scripts/identity-snapshot.sh BINARY > snapshot.txt; diff two snapshots.
set -euo pipefail
bin=$(cd "$(dirname "$1")" && pwd)/$(basename "$1")
src=$(cd "$(dirname "$0")/.." && pwd)
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
cd "$tmp"
cp -r "$src/configs" .
sum() { printf '%s  %s\n' "$(md5sum < "$2" | cut -c1-32)" "$1"; }
untimed() { python3 -c "import json,sys; d=json.load(open(sys.argv[1])); [d.pop(k,None) for k in ('seconds','points_per_second')]; print(json.dumps(d,sort_keys=True))" "$1" > "$1.untimed"; }
cases=(configs/*.yaml)
for t in 1 2; do
    for c in "${cases[@]}"; do
        n=$(basename "$c" .yaml)
        "$bin" map "$c" --threads $t -o plain.csv --json plain.json 2> /dev/null || true
        [ -f plain.csv ] && sum "map $n t$t" plain.csv && untimed plain.json && sum "json $n t$t" plain.json.untimed
        "$bin" map "$c" --threads $t --detail -o detail.csv 2> /dev/null && sum "detail $n t$t" detail.csv
        rm -f plain.csv plain.json detail.csv
    done
    "$bin" map configs/transfer-box.yaml --threads $t --speed "$(seq -s, 100 37 3000)rpm" --torque "$(seq -s, -50 23 900)Nm" \
        --detail -o big.csv --json big.json 2> /dev/null
    sum "big detail t$t" big.csv; untimed big.json; sum "big json t$t" big.json.untimed
    "$bin" map configs/fzg-c40-paor.yaml --threads $t --speed "$(seq -s, 100 211 6000)rpm" --torque "$(seq -s, 50 61 900)Nm" \
        -o - 2> /dev/null > stdout.csv
    sum "fzg stdout t$t" stdout.csv
    cp configs/transfer-box.yaml configs/sweep.yaml
    printf '\nsweep:\n  - {parameter: oil, values: [oils/75W90-A.yaml, oils/75W140-A.yaml]}\n  - {parameter: [gears.w2.face_width, gears.w1.face_width], values: [30 mm, "35 mm", 40 mm]}\n  - {parameter: housing.oil_level, values: [-30 mm, -10 mm]}\n' >> configs/sweep.yaml
    "$bin" map configs/sweep.yaml --threads $t -o sweep.csv --json sweep.json 2> /dev/null
    sum "sweep t$t" sweep.csv; untimed sweep.json; sum "sweep json t$t" sweep.json.untimed
    "$bin" map configs/sweep.yaml --threads $t --detail --oil-temp 80degC --speed 500,1500,3000rpm -o sweepd.csv 2> /dev/null
    sum "sweep detail t$t" sweepd.csv
    for k in 1 2 3 4 5; do "$bin" map configs/sweep.yaml --threads $t --shard $k/5 -o shard$k.csv 2> /dev/null; done
    "$bin" merge shard3.csv shard1.csv shard5.csv shard2.csv shard4.csv -o merged.csv
    sum "merged sweep t$t" merged.csv; cmp -s merged.csv sweep.csv && echo "merged = single t$t"
    for k in 1 2 3; do "$bin" map configs/wind-turbine-2.5MW.yaml --detail --threads $t --shard $k/3 -o ws$k.csv 2> /dev/null; done
    "$bin" merge ws1.csv ws2.csv ws3.csv -o wm.csv; sum "merged wind detail t$t" wm.csv
    "$bin" map configs/manual-6speed.yaml --threads $t --format vecto --oil-temp 70degC -o man.vtlm 2> /dev/null
    for f in man_*.vtlm; do sum "vecto $f t$t" "$f"; done
    "$bin" map configs/automatic-6speed.yaml --ratio g2 --threads $t --format vecto --oil-temp 90degC -o - 2> /dev/null > auto.vtlm
    sum "vecto automatic g2 stdout t$t" auto.vtlm
    rm -f ./*.csv ./*.vtlm ./*.json*
done
