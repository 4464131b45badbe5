#!/usr/bin/env bash
# Map throughput: a 100 x 100 grid of the transfer gearbox (300-3000 rpm x
# 10-400 N m) with thermal coupling, on 1 and on 2 threads. Each figure is the
# median of REPS runs of the solve (timed inside gearloss, excluding start-up
# and CSV writing). Usage: scripts/benchmark.sh [REPS]
set -euo pipefail
cd "$(dirname "$0")/.."
reps=${1:-15}
scripts/install-deps.sh
scripts/build.sh > /dev/null
speeds=$(python3 -c "print(','.join(f'{300+i*2700/99:.3f}' for i in range(100)))")rpm
torques=$(python3 -c "print(','.join(f'{10+i*390/99:.3f}' for i in range(100)))")Nm
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
for threads in 1 2; do
    for _ in $(seq "$reps"); do
        build/app/gearloss map configs/transfer-box.yaml --speed "$speeds" --torque "$torques" \
            --threads "$threads" --stats -o "$tmp/map.csv" 2>> "$tmp/stats-$threads.txt"
    done
done
python3 - "$tmp" <<'PY'
import re, statistics, sys
d = sys.argv[1]
rate = {}
for t in (1, 2):
    lines = open(f"{d}/stats-{t}.txt").read().splitlines()
    rates = [float(re.search(r"([0-9.]+) points/s", l).group(1)) for l in lines]
    evals = re.search(r"([0-9.]+) loss evaluations/point", lines[0]).group(1)
    rate[t] = statistics.median(rates)
    print(f"threads {t}: median {rate[t]:,.0f} points/s (min {min(rates):,.0f}, max {max(rates):,.0f}, {len(rates)} runs), "
          f"{evals} loss evaluations/point")
print(f"speed-up 1 -> 2 threads: {rate[2] / rate[1]:.2f}")
PY
