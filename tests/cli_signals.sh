#!/usr/bin/env bash
# SIGINT and SIGTERM stop every command from inside its long loop (issue 13, part 4): map
# (grid, sweep expansion, shards, VECTO tables), compare, diagnose (candidate scans,
# cross-validation, bootstrap), synth (steady points and the raw log), cycle (and the
# pre-warmed run), merge. Each command runs on a workload of several seconds, gets the
# signal after 0.5 s, and must exit 130 (SIGINT) or 143 (SIGTERM) within 1.5 s, with nothing
# on stdout and no output or temporary file. Also `diagnose` never aborts (part 6): the
# six-speed campaigns above 1100 rpm and a recording with oil_temp_C = 9999.
# Every file is written in a mktemp -d directory (cli_common.sh), never onto /dev/...
source "$(dirname "$0")/cli_common.sh" "$@"
cd "$tmp" || exit 1

# Argument lists expanded here, not in the background job (a signal reaching a background
# subshell would run this script's EXIT trap there).
list() { python3 -c "print(','.join(f'{$1 + $2 * i:g}' for i in range($3)))"; }
# The maps run on the seed-000 spur case (thermal-EHL mesh friction, ~0.3 ms a point): their
# time is computation, not the release of a large result array.
spur="$src/configs/spur-seed000.yaml"
speeds="$(list 200 10 150)rpm"
torques="$(list 100 4.5 150)Nm"
tb="$src/configs/transfer-box.yaml"

# stopped NAME SIGNAL CODE COMMAND...: the command, started with its outputs in out/, gets
# SIGNAL $after s (0.5 unless given; it must still be running) after it installed its handler
# (await_handler, cli_common.sh), and must end with CODE within $SIGNAL_DEADLINE_MS (1500 ms:
# the 1 s of the contract plus this script's polling and the shared machine; tests/CMakeLists.txt
# widens it under the sanitizers), leaving out/ and stdout empty.
deadline_ms=${SIGNAL_DEADLINE_MS:-1500}
stopped() {
    local name=$1 sig=$2 code=$3
    shift 3
    rm -rf out
    mkdir out
    "$@" > stdout.txt 2> stderr.txt &
    local pid=$!
    check "$name: catches SIG$sig" await_handler $pid "$sig"
    sleep "${after:-0.5}"
    check "$name: still running after ${after:-0.5} s (the workload is long enough)" kill -0 $pid 2> /dev/null
    kill -"$sig" $pid
    local t0 ms
    t0=$(date +%s%N)
    while kill -0 $pid 2> /dev/null && [ $(($(date +%s%N) - t0)) -lt $((deadline_ms * 1000000)) ]; do sleep 0.02; done
    ms=$((($(date +%s%N) - t0) / 1000000))
    if kill -0 $pid 2> /dev/null; then
        check "$name: $sig stops it within $deadline_ms ms" false
        kill -KILL $pid
    fi
    wait $pid
    local rc=$?
    [ -n "${SIGNALS_VERBOSE:-}" ] && echo "$name: ended $ms ms after SIG$sig"
    check "$name: $sig exits $code (got $rc)" test $rc -eq "$code"
    check "$name: no output or temporary file" test -z "$(ls -A out)"
    check "$name: nothing on stdout" test ! -s stdout.txt
    check "$name: says it was interrupted" grep -q "interrupted (signal" stderr.txt
}

# map: the grid (OpenMP loop), with --json and --detail
stopped "map" INT 130 "$bin" map "$spur" --speed "$speeds" --torque "$torques" -o out/map.csv --json out/map.json
stopped "map --detail" TERM 143 "$bin" map "$spur" --speed "$speeds" --torque "$torques" --detail -o out/map.csv

# map of 4 million points of the transfer box: stops at once, also before the first second
# (the result array is filled block by block, not initialised up front)
big_speeds="$(list 300 1 2000)rpm"
big_torques="$(list 10 0.1 2000)Nm"
after=0.3 stopped "map 4e6 points" INT 130 "$bin" map "$tb" --speed "$big_speeds" --torque "$big_torques" -o out/big.csv

# map streamed to standard output redirected to a file: an interrupt cuts the file back to
# what it held (empty after `>`, the old text after `>>`); to a FIFO, which cannot be taken
# back, the rows sent stay sent and the message says the output stops part-way.
rm -rf out && mkdir out
for mode in new append; do
    if [ $mode = new ]; then
        "$bin" map "$tb" --speed "$big_speeds" --torque "$big_torques" > out/redirected.csv 2> stderr.txt &
    else
        echo "kept" > out/redirected.csv
        "$bin" map "$tb" --speed "$big_speeds" --torque "$big_torques" >> out/redirected.csv 2> stderr.txt &
    fi
    pid=$!
    check "map > file ($mode): catches SIGINT" await_handler $pid INT
    sleep 1.5
    kill -INT $pid
    wait $pid
    rc=$?
    check "map > file ($mode), interrupted after rows were written: exit 130 (got $rc)" test $rc -eq 130
    check "map > file ($mode): the file holds what it held before" \
        test "$(cat out/redirected.csv)" = "$([ $mode = new ] || echo kept)"
    check "map > file ($mode): no output written" grep -q "interrupted (signal 2); no output written" stderr.txt
done
mkfifo out/rows.fifo
cat out/rows.fifo > fifo-rows.csv &
reader=$!
"$bin" map "$tb" --speed "$big_speeds" --torque "$big_torques" -o out/rows.fifo 2> stderr.txt &
pid=$!
check "map -o FIFO: catches SIGTERM" await_handler $pid TERM
sleep 1.5
kill -TERM $pid
wait $pid
rc=$?
wait $reader
check "map -o FIFO, interrupted: exit 143 (got $rc)" test $rc -eq 143
check "map -o FIFO: the rows sent arrived" test "$(head -c 12 fifo-rows.csv)" = "speed_in_rpm"
check "map -o FIFO: says the output stops part-way" grep -q "the output 'out/rows.fifo' stops part-way" stderr.txt
rm -rf out

# map with a sweep of 10 000 variants (~0.2 ms to load each, 2 s in all; the values written 100
# to a line, below the reader's longest line) and a shard
mkdir -p sweep
cp -r "$src/configs/oils" sweep/
cp "$tb" sweep/case.yaml
printf '\nsweep:\n  - parameter: thermal.ambient\n    values: [\n%s]\n' \
    "$(python3 -c "
v = [f'{20 + 0.01 * i:.2f} degC' for i in range(10000)]
print(',\n'.join('      ' + ', '.join(v[i:i + 100]) for i in range(0, len(v), 100)))")" >> sweep/case.yaml
stopped "map sweep" TERM 143 "$bin" map sweep/case.yaml --speed 600rpm --torque 100Nm -o out/sweep.csv
# (a shard is half the grid: twice the map's points keep it running past 0.5 s on a fast machine)
stopped "map --shard" INT 130 "$bin" map "$spur" --speed "$(list 200 5 300)rpm" --torque "$torques" --shard 1/2 -o out/shard.csv
stopped "map --format vecto" TERM 143 "$bin" map "$spur" --speed "$(list 200 5 300)rpm" --torque "$(list 100 3.5 200)Nm" \
    --oil-temp 70degC --format vecto -o out/map.vtlm

# compare: two maps
stopped "compare" INT 130 "$bin" compare "$spur" --oil "$src/configs/oils/75W90-syn-A.yaml" \
    --oil "$src/configs/oils/75W90-syn-B.yaml" --speed "$speeds" --torque "$torques" -o out/diff.csv

# diagnose: a 2000-point campaign with a concealed windage (responses, joint fits, tests);
# the diagnosis is linear in the points, so it takes this many to last beyond 3 s
"$bin" synth "$tb" --speed "$(list 400 32 50)rpm" --torque "$(list 20 7 40)Nm" --effect windage=25W -o rec2000.csv
check "synth 2000-point campaign" test -s rec2000.csv
stopped "diagnose" TERM 143 "$bin" diagnose "$tb" rec2000.csv --bootstrap 200 --json out/d.json --residuals out/r.csv \
    --write-config out/cal.yaml
after=3 stopped "diagnose (SIGINT after 3 s)" INT 130 "$bin" diagnose "$tb" rec2000.csv --bootstrap 200 --json out/d.json

# synth: steady points (800 000) and a raw 0.5 Hz log (100 tests of 4 h)
stopped "synth" TERM 143 "$bin" synth "$tb" --speed "$(list 300 1 2000)rpm" --torque "$(list 10 1 400)Nm" -o out/rec.csv
stopped "synth --format log" INT 130 "$bin" synth "$tb" --speed "$(list 400 100 10)rpm" --torque "$(list 100 25 10)Nm" \
    --format log -o out/log.csv

# cycle: WLTC repeated 100 times (50 h), with pre-warming; SIGTERM is 143 here too
python3 - "$src/configs/cycles/wltc-class3b.csv" > long-cycle.csv << 'EOF'
import sys
rows = [l.split(",") for l in open(sys.argv[1]).read().split()[1:]]
print("time_s,speed_kmh")
period = float(rows[-1][0])
for k in range(100):
    for i, (t, v) in enumerate(rows):
        if k == 0 or i > 0:
            print(f"{float(t) + k * period:g},{v}")
EOF
stopped "cycle" TERM 143 "$bin" cycle "$src/configs/automatic-6speed.yaml" --cycle long-cycle.csv --start-temp -10degC \
    --prewarm 90degC -o out/trace.csv --json out/cycle.json
stopped "cycle (SIGINT)" INT 130 "$bin" cycle "$src/configs/manual-6speed.yaml" --cycle long-cycle.csv --start-temp 0degC \
    -o out/trace.csv

# merge: 16 shards of 100 000 rows (270 MB)
"$bin" map "$tb" --speed 600,700rpm --torque 100Nm --shard 1/2 -o seed-shard.csv
mkdir -p shards
python3 - seed-shard.csv shards << 'EOF'
import sys
first, header, row = open(sys.argv[1]).read().splitlines()[:3]
job = first.split(", job ", 1)[1]
n, rows = 16, 100000
body = (row + "\n") * rows
for k in range(1, n + 1):
    with open(f"{sys.argv[2]}/part{k:02d}.csv", "w") as f:
        f.write(f"# gearloss shard {k}/{n}: rows {rows * (k - 1)}-{rows * k} of {rows * n}, job {job}\n{header}\n{body}")
EOF
stopped "merge" INT 130 "$bin" merge shards/part01.csv shards/part02.csv shards/part03.csv shards/part04.csv \
    shards/part05.csv shards/part06.csv shards/part07.csv shards/part08.csv shards/part09.csv shards/part10.csv \
    shards/part11.csv shards/part12.csv shards/part13.csv shards/part14.csv shards/part15.csv shards/part16.csv \
    -o out/merged.csv
rm -rf shards
# A FIFO named as a shard is refused before it is opened (opening it would block where no
# signal is seen): exit 2 at once.
mkfifo nobody-writes
timeout 5 "$bin" merge seed-shard.csv nobody-writes -o merged.csv 2> fifo.err
rc=$?
check "merge of a FIFO: refused, exit 2 (got $rc)" test $rc -eq 2
check "merge of a FIFO: named" grep -q "nobody-writes.*not a regular file" fifo.err

# diagnose never aborts: the six-speed campaigns with points above 1100 rpm (a candidate scan
# used to drive the heat flow negative: exit 134), verdict present, exit 0.
for c in manual-6speed automatic-6speed; do
    "$bin" synth "$src/configs/$c.yaml" --speed 800,1200,1600,2000rpm --torque 50,100,150Nm -o "$c.csv"
    "$bin" diagnose "$src/configs/$c.yaml" "$c.csv" --json "$c.json" > "$c.txt" 2> "$c.err"
    rc=$?
    check "$c diagnose above 1100 rpm: exit 0 (got $rc)" test $rc -eq 0
    check "$c diagnose: verdict" grep -q '^verdict: ' "$c.txt"
    check "$c diagnose: JSON with a verdict" python3 -c "import json; assert json.load(open('$c.json'))['verdict']"
    check "$c diagnose: no nan" bash -c "! grep -qiw nan '$c.txt'"
done

# One recording with oil_temp_C = 9999: the row is not used (an outlier with its reason),
# never a -nan RMSE called no_significant_mismatch.
"$bin" synth "$tb" -o rec9.csv
awk -F, 'BEGIN { OFS = "," } NR == 3 { $4 = 9999 } { print }' rec9.csv > rec9999.csv
"$bin" diagnose "$tb" rec9999.csv --json d9999.json > d9999.txt 2> d9999.err
rc=$?
check "9999 degC row: exit 0 (got $rc)" test $rc -eq 0
check "9999 degC row: no nan" bash -c "! grep -qiw nan d9999.txt"
check "9999 degC row: outlier with the reason" grep -q "row 2: not used: recorded oil temperature 9999.0 degC" d9999.txt
check "9999 degC row: JSON outlier" python3 -c "
import json; d = json.load(open('d9999.json'))
assert any(o['row'] == 2 and 'not used' in o['reason'] for o in d['outliers'])
assert d['points'] == 8"

echo "$pass passed, $fail failed"
test $fail -eq 0
