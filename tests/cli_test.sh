#!/usr/bin/env bash
# End-to-end checks of the gearloss command line: exit codes, stdout/stderr,
# atomic output files. Usage: cli_test.sh GEARLOSS_BINARY SOURCE_DIR
set -u
source "$(dirname "$0")/cli_common.sh" "$@"

# A good map: 9 rows + header, no NaN/inf anywhere, status ok.
"$bin" map "$src/configs/transfer-box.yaml" -o "$tmp/map.csv"
rc=$?
check "map exit code 0" test $rc -eq 0
check "map has 10 lines" test "$(wc -l < "$tmp/map.csv")" -eq 10
check "map has no nan/inf" bash -c "! grep -qiE 'nan|inf' '$tmp/map.csv'"
check "map header" grep -q '^speed_in_rpm,torque_in_Nm,power_in_W,ambient_temp_C,oil_temp_C,P_mesh_W,P_churn_W,P_bearing_W,P_seal_W,P_clutch_W,P_aux_W,P_windage_W,P_empirical_W,P_total_W' "$tmp/map.csv"

# Command-line grid and fixed temperature override the config.
"$bin" map "$src/configs/transfer-box.yaml" --speed 600,700rpm --torque 150,200,250Nm --oil-temp 70degC -o "$tmp/o.csv"
check "override grid: 6 rows" test "$(wc -l < "$tmp/o.csv")" -eq 7
check "override oil temp" bash -c "cut -d, -f5 '$tmp/o.csv' | tail -n +2 | sort -u | grep -qx '70.000'"

# Bad config: exit 2, message names file:line and key, previous output untouched.
cp "$tmp/map.csv" "$tmp/before.csv"
sed 's/teeth: 32,/teeth: -3,/' "$src/configs/transfer-box.yaml" > "$src/configs/tmp-cli-bad-$$.yaml"
"$bin" map "$src/configs/tmp-cli-bad-$$.yaml" -o "$tmp/map.csv" 2> "$tmp/err.txt"
rc=$?
rm -f "$src/configs/tmp-cli-bad-$$.yaml"
check "bad config exit 2" test $rc -eq 2
check "bad config message" grep -qE 'tmp-cli-bad-[0-9]+.yaml:[0-9]+:[0-9]+: gears\[0\]\.teeth: ' "$tmp/err.txt"
check "previous output kept" cmp -s "$tmp/map.csv" "$tmp/before.csv"
check "no temporary left" bash -c "! ls '$tmp' | grep -q '\.tmp\.'"

# Bad command-line value: exit 2 naming the option.
"$bin" map "$src/configs/transfer-box.yaml" --speed 600kg -o "$tmp/x.csv" 2> "$tmp/err2.txt"
check "bad --speed exit 2" test $? -eq 2
check "bad --speed message" grep -q -- '--speed' "$tmp/err2.txt"
check "no file on error" test ! -e "$tmp/x.csv"

# Usage error: exit 1.
"$bin" map 2> /dev/null
check "usage exit 1" test $? -eq 1
"$bin" --version | grep -q '^gearloss '
check "version" test $? -eq 0

# point and check commands.
"$bin" point "$src/configs/transfer-box.yaml" --speed 800rpm --torque 250Nm > "$tmp/point.txt"
check "point exit 0" test $? -eq 0
check "point lists bearings" grep -q 'B6_6307.2' "$tmp/point.txt"
"$bin" check "$src/configs/fzg-c40-paor.yaml" --json > "$tmp/check.json"
check "check --json exit 0" test $? -eq 0
check "check json valid" python3 -c "import json,sys; d=json.load(open('$tmp/check.json')); assert abs(d['meshes'][0]['centre_distance_mm']-91.5)<1e-6"

# Interrupted run (SIGINT during a large map): exit 130, no output file.
# The argument lists are expanded here, not in the background job: a signal
# reaching a background subshell would run this script's EXIT trap there.
big_speeds="$(python3 -c "print(','.join(str(300+i) for i in range(2000)))")rpm"
big_torques="$(python3 -c "print(','.join(str(10+i) for i in range(400)))")Nm"
# interrupt SIGNAL EXIT_CODE FILE: a signal during a long map exits with the code and writes nothing.
interrupt() {
    "$bin" map "$src/configs/transfer-box.yaml" --speed "$big_speeds" --torque "$big_torques" -o "$tmp/$3" &
    local pid=$!
    check "$1 caught" await_handler $pid "$1"
    sleep 1
    kill -"$1" $pid
    wait $pid
    local rc=$?
    check "$1 exit $2" test $rc -eq "$2"
    check "$1 leaves no file" test ! -e "$tmp/$3"
    check "$1 leaves no temporary" bash -c "! ls '$tmp' | grep -q '\.tmp\.'"
}
interrupt INT 130 big.csv
interrupt TERM 143 big2.csv

# Disk full (simulated with a 64 KiB file-size limit): exit 3, the previous file
# is left as it was and no temporary file remains.
"$bin" map "$src/configs/transfer-box.yaml" -o "$tmp/full.csv"
cp "$tmp/full.csv" "$tmp/full-before.csv"
(ulimit -f 64; exec "$bin" map "$src/configs/transfer-box.yaml" --speed 300,400,500,600,700,800,900,1000rpm \
    --torque "$(python3 -c "print(','.join(str(10+i) for i in range(300)))")Nm" --detail -o "$tmp/full.csv") 2> "$tmp/err5.txt"
rc=$?
check "disk full exit 3" test $rc -eq 3
check "disk full message" grep -q "cannot write" "$tmp/err5.txt"
check "disk full keeps previous file" cmp -s "$tmp/full.csv" "$tmp/full-before.csv"
check "disk full leaves no temporary" bash -c "! ls '$tmp' | grep -q '\.tmp\.'"

# synth -> diagnose -> JSON, calibrated config, residuals.
"$bin" synth "$src/configs/transfer-box.yaml" --effect constant_parasitic=30W --seed 2 \
    --speed 400,700,1000rpm --torque 100,200,300Nm -o "$tmp/rec.csv"
check "synth exit 0" test $? -eq 0
"$bin" diagnose "$src/configs/transfer-box.yaml" "$tmp/rec.csv" --json "$tmp/d.json" \
    --write-config "$tmp/cal.yaml" --residuals "$tmp/res.csv" > "$tmp/d.txt"
check "diagnose exit 0" test $? -eq 0
# 9 points with the noise estimated from them: the effect is present (named with confidence),
# and the report says apart that these points cannot show it to be the whole cause (a
# remainder of about twice the noise would pass unseen); with the rig's noise declared
# (synth's 1.5 % and 0.4 K) the tests see one of 0.85 times it: shown to be the whole cause.
# The file has no run, date or time column: the run order is not recorded.
check "diagnose json keys" python3 -c "
import json; d = json.load(open('$tmp/d.json'))
assert d['verdict'] == 'missing_physics', d['verdict']
assert d['main_finding'] == {'effect': 'constant_parasitic', 'confidence': 'confident'}, d.get('main_finding')
assert d['adequacy']['detectable_remainder'] > 1.5, d['adequacy']
assert 'on 9 points' in d['completeness'] and '--loss-uncertainty' in d['completeness'], d['completeness']
assert d['noise_used']['source'] in ('neighbour differences', 'floor') and d['noise_used']['why'], d['noise_used']
assert d['noise_used']['loss_relative'] >= 0.01, d['noise_used']
assert d['run_order'] == {'recorded': False, 'column': None}, d['run_order']
f = d['findings'][0]
assert f['effect'] == 'constant_parasitic'
for k in ('description', 'parameters', 'rmse_before', 'rmse_after', 'cv_rmse_before', 'cv_rmse_after'): assert k in f, k
assert isinstance(d['outliers'], list)"
"$bin" diagnose "$src/configs/transfer-box.yaml" "$tmp/rec.csv" --json "$tmp/d2.json" \
    --loss-uncertainty 1.5% --temp-uncertainty 0.4K > /dev/null
check "diagnose with declared noise is confident" python3 -c "
import json; d = json.load(open('$tmp/d2.json'))
assert d['verdict'] == 'missing_physics', d['verdict']
assert d['findings'][0]['effect'] == 'constant_parasitic'
assert 0.7 < d['adequacy']['detectable_remainder'] < 1.0, d['adequacy']
assert d['noise_used']['source'] == 'declared', d['noise_used']"
# A run column gives the run order.
python3 -c "
rows = open('$tmp/rec.csv').read().split()
print(rows[0] + ',run'); [print(r + ',' + str(k)) for k, r in enumerate(rows[1:], 1)]" > "$tmp/rec-run.csv"
"$bin" diagnose "$src/configs/transfer-box.yaml" "$tmp/rec-run.csv" --json "$tmp/d3.json" > "$tmp/d3.txt"
check "diagnose run column" python3 -c "
import json; d = json.load(open('$tmp/d3.json'))
assert d['run_order'] == {'recorded': True, 'column': 'run'}, d['run_order']"
check "diagnose text says the run order" grep -q 'run order: from the .run. column' "$tmp/d3.txt"
check "calibrated config loads" bash -c "'$bin' check '$tmp/cal.yaml' > /dev/null"
check "residuals written" test "$(wc -l < "$tmp/res.csv")" -eq 10
# Malformed recordings: exit 2 naming the file and line.
printf 'speed_in_rpm,torque_in_Nm,P_loss_W\n600,150,210\n700,150\n' > "$tmp/bad.csv"
"$bin" diagnose "$src/configs/transfer-box.yaml" "$tmp/bad.csv" 2> "$tmp/err3.txt" > /dev/null
check "bad recordings exit 2" test $? -eq 2
check "bad recordings message" grep -q 'bad.csv:3: row has 2 cells' "$tmp/err3.txt"
"$bin" synth "$src/configs/transfer-box.yaml" --effect windage=-5W -o "$tmp/x2.csv" 2> "$tmp/err4.txt"
check "bad effect exit 2" test $? -eq 2
check "bad effect message" grep -q 'outside the physical bounds' "$tmp/err4.txt"

# mesh-profile: a CSV along the path; an unknown mesh is an input error.
"$bin" mesh-profile "$src/configs/spur-seed000.yaml" --mesh m --speed 1600rpm --torque 720Nm --positions 9 -o "$tmp/prof.csv"
check "mesh-profile exit 0" test $? -eq 0
check "mesh-profile rows" test "$(wc -l < "$tmp/prof.csv")" -eq 10
"$bin" mesh-profile "$src/configs/spur-seed000.yaml" --mesh nope --speed 1600rpm --torque 720Nm 2> "$tmp/err6.txt" > /dev/null
check "mesh-profile unknown mesh exit 2" test $? -eq 2
check "mesh-profile unknown mesh message" grep -q "unknown mesh 'nope'; meshes: m" "$tmp/err6.txt"

# Drive cycle: summary on stdout, a trace row per sample, JSON summary, bad cycle name.
"$bin" cycle "$src/configs/automatic-6speed.yaml" --cycle nedc --start-temp -10degC --prewarm 90degC --heater 2kW \
    -o "$tmp/trace.csv" --json "$tmp/cycle.json" > "$tmp/cycle.txt"
check "cycle exit 0" test $? -eq 0
check "cycle trace rows" test "$(wc -l < "$tmp/trace.csv")" -eq 1181
check "cycle trace no nan" bash -c "! grep -qiE 'nan|inf' '$tmp/trace.csv'"
check "cycle summary" grep -q "pre-warming saves" "$tmp/cycle.txt"
check "cycle json" python3 -c "
import json, sys
d = json.load(open('$tmp/cycle.json'))
assert d['cycle'] == 'nedc' and abs(d['distance_km'] - 11.02) < 0.01
assert d['prewarm']['reached'] and d['prewarm']['fuel_saved_percent'] > 0
assert d['start']['fuel_L'] > d['warm_start']['fuel_L']
"
"$bin" cycle "$src/configs/automatic-6speed.yaml" --cycle nedcc --start-temp -10degC 2> "$tmp/err7.txt" > /dev/null
check "cycle unknown name exit 2" test $? -eq 2
check "cycle unknown name message" grep -q "neither a cycle file nor one of" "$tmp/err7.txt"
"$bin" cycle "$src/configs/transfer-box.yaml" --cycle nedc --start-temp -10degC 2> "$tmp/err8.txt" > /dev/null
check "cycle without vehicle exit 2" test $? -eq 2
check "cycle without vehicle message" grep -q "no 'vehicle' block" "$tmp/err8.txt"

# VECTO torque-loss tables: one file per gear, negative torques included.
"$bin" map "$src/configs/manual-6speed.yaml" --format vecto --oil-temp 70degC --speed 1000,2000rpm --torque 50,100Nm -o "$tmp/m.vtlm"
check "vecto exit 0" test $? -eq 0
check "vecto six files" test "$(ls "$tmp"/m_g*.vtlm | wc -l)" -eq 6
# '#' provenance lines first (VECTO skips them; tests/cli_metadata.sh checks them), then the table.
check "vecto header" bash -c "grep -v '^#' '$tmp/m_g3.vtlm' | head -1 | grep -qx 'Input Speed \[rpm\],Input Torque \[Nm\],Torque Loss \[Nm\]'"
check "vecto rows" test "$(grep -vc '^#' "$tmp/m_g3.vtlm")" -eq 11
check "vecto negative torque" grep -q '^1000.00,-100.00,' "$tmp/m_g3.vtlm"

# Shards through the Slurm array script (array environment emulated, tasks 0-2), merged in
# any order: byte-identical to a single run. A missing shard is an error.
grid=(--speed 400,600,800,1000,1200rpm --torque 100,150,200,250Nm)
"$bin" map "$src/configs/transfer-box.yaml" "${grid[@]}" -o "$tmp/single.csv"
for k in 0 1 2; do
    SLURM_ARRAY_TASK_ID=$k SLURM_ARRAY_TASK_MIN=0 SLURM_ARRAY_TASK_MAX=2 GEARLOSS=$bin \
        bash "$src/scripts/slurm-map.sh" "$src/configs/transfer-box.yaml" "$tmp/shards" "${grid[@]}" > /dev/null 2>&1
done
check "slurm shards written" test "$(ls "$tmp"/shards/shard-*.csv | wc -l)" -eq 3
"$bin" merge "$tmp/shards/shard-3.csv" "$tmp/shards/shard-1.csv" "$tmp/shards/shard-2.csv" -o "$tmp/merged.csv"
check "merge exit 0" test $? -eq 0
check "merge byte-identical to a single run" cmp -s "$tmp/single.csv" "$tmp/merged.csv"
"$bin" merge "$tmp/shards/shard-1.csv" "$tmp/shards/shard-3.csv" 2> "$tmp/err9.txt" > /dev/null
check "merge missing shard exit 2" test $? -eq 2
check "merge missing shard message" grep -q "missing shard(s) 2 of 3" "$tmp/err9.txt"

# Shards of different jobs are refused (exit 2), naming both files and what differs. The
# case and its oil are copied twice under the same names, one oil with one number changed.
fg=(--speed 600,800rpm --torque 100,200Nm)
for d in j1 j2; do
    mkdir -p "$tmp/$d/oils"
    cp "$src/configs/transfer-box.yaml" "$tmp/$d/case.yaml"
    cp "$src/configs/oils/75W90-A.yaml" "$tmp/$d/oils/75W90-A.yaml"
done
sed -i 's/^density: 885 kg/density: 886 kg/' "$tmp/j2/oils/75W90-A.yaml"
check "fingerprint test oil edited" bash -c "! cmp -s '$tmp/j1/oils/75W90-A.yaml' '$tmp/j2/oils/75W90-A.yaml'"
refused() {  # refused NAME A B PATTERN: merge of A and B exits 2 naming both and PATTERN
    "$bin" merge "$2" "$3" -o "$tmp/refused.csv" 2> "$tmp/err-fp.txt" > /dev/null
    check "$1: exit 2" test $? -eq 2
    check "$1: names the difference" grep -qF -- "$4" "$tmp/err-fp.txt"
    check "$1: names both files" bash -c "grep -qF '$(basename "$2")' '$tmp/err-fp.txt' && grep -qF '$(basename "$3")' '$tmp/err-fp.txt'"
    check "$1: no output" test ! -e "$tmp/refused.csv"
}
"$bin" map "$tmp/j1/case.yaml" "${fg[@]}" --oil-temp 60degC --shard 1/2 -o "$tmp/t60-1.csv"
"$bin" map "$tmp/j1/case.yaml" "${fg[@]}" --oil-temp 90degC --shard 2/2 -o "$tmp/t90-2.csv"
refused "shards at two --oil-temp" "$tmp/t60-1.csv" "$tmp/t90-2.csv" "oil temperature override (--oil-temp)"
"$bin" map "$tmp/j1/case.yaml" "${fg[@]}" --oil-temp 60degC --shard 1/2 -o "$tmp/oilA-1.csv"
"$bin" map "$tmp/j2/case.yaml" "${fg[@]}" --oil-temp 60degC --shard 2/2 -o "$tmp/oilB-2.csv"
refused "case oil file edited" "$tmp/oilA-1.csv" "$tmp/oilB-2.csv" "oil file content (the case's 'oil' file)"
"$bin" map "$src/configs/transfer-box.yaml" "${fg[@]}" --oil "$tmp/j1/oils/75W90-A.yaml" --shard 1/2 -o "$tmp/xA-1.csv"
"$bin" map "$src/configs/transfer-box.yaml" "${fg[@]}" --oil "$tmp/j2/oils/75W90-A.yaml" --shard 2/2 -o "$tmp/xB-2.csv"
refused "--oil file edited" "$tmp/xA-1.csv" "$tmp/xB-2.csv" "oil file content (--oil)"
# A shard written by another release: its version field edited (the rows may differ
# between releases, so the fingerprint covers the version even when all else agrees).
"$bin" map "$tmp/j1/case.yaml" "${fg[@]}" --oil-temp 60degC --shard 2/2 -o "$tmp/oilA-2.csv"
sed '1s/ version=[^ ]*/ version=0.0.9/' "$tmp/oilA-2.csv" > "$tmp/old-2.csv"
check "version field edited" bash -c "head -1 '$tmp/old-2.csv' | grep -q ' version=0.0.9 '"
refused "shard of another release" "$tmp/oilA-1.csv" "$tmp/old-2.csv" "program version: 0.0.9 in"
# The same job from another working directory, the case (and --oil) named by other
# relative paths: file contents count, not paths, so the shards merge into the single run.
abs_src=$(cd "$src" && pwd)  # the subshells below change directory
cp "$src/configs/oils/75W140-A.yaml" "$tmp/j1/75W140-copy.yaml"
(cd "$tmp" && "$bin" map j1/case.yaml "${fg[@]}" --oil "$abs_src/configs/oils/75W140-A.yaml" --shard 1/2 -o cwd-1.csv)
(cd "$tmp/j1" && "$bin" map ./case.yaml "${fg[@]}" --oil 75W140-copy.yaml --shard 2/2 -o ../cwd-2.csv)
"$bin" map "$tmp/j2/../j1/case.yaml" "${fg[@]}" --oil "$src/configs/oils/75W140-A.yaml" -o "$tmp/cwd-single.csv"
"$bin" merge "$tmp/cwd-2.csv" "$tmp/cwd-1.csv" -o "$tmp/cwd-merged.csv"
check "same job from another directory merges" test $? -eq 0
check "merged from two directories = single run" cmp -s "$tmp/cwd-single.csv" "$tmp/cwd-merged.csv"

# Progress: rate and ETA on a terminal (a pseudo-terminal from script(1)), nothing otherwise.
GEARLOSS_PROGRESS_AFTER=0 script -qec "'$bin' map '$src/configs/transfer-box.yaml' ${grid[*]} -o '$tmp/p1.csv'" /dev/null > "$tmp/tty.txt"
check "progress on a terminal" grep -q 'points/s, ETA' "$tmp/tty.txt"
GEARLOSS_PROGRESS_AFTER=0 "$bin" map "$src/configs/transfer-box.yaml" "${grid[@]}" -o "$tmp/p2.csv" 2> "$tmp/notty.txt"
check "quiet without a terminal" test ! -s "$tmp/notty.txt"

# Pictures from every kind of output (PNG and SVG).
plot() { MPLCONFIGDIR="$tmp/mpl" /usr/bin/python3 "$src/scripts/plot.py" "$@" > /dev/null 2>&1; }
"$bin" map "$src/configs/transfer-box.yaml" -o "$tmp/pm.csv"
plot map "$tmp/pm.csv" "$tmp/eff.png" --kind efficiency
check "plot efficiency png" bash -c "head -c 8 '$tmp/eff.png' | od -An -c | grep -q 'P   N   G'"
plot map "$tmp/pm.csv" "$tmp/brk.svg" --kind breakdown
check "plot breakdown svg" grep -q '<svg' "$tmp/brk.svg"
plot map "$tmp/pm.csv" "$tmp/temp.png" --kind oil-temp
check "plot oil temperature" test -s "$tmp/temp.png"
"$bin" compare "$src/configs/transfer-box.yaml" --oil "$src/configs/oils/75W90-A.yaml" --oil "$src/configs/oils/75W140-A.yaml" -o "$tmp/pc.csv"
plot compare "$tmp/pc.csv" "$tmp/cmp.png"
check "plot compare" test -s "$tmp/cmp.png"
plot cycle "$tmp/trace.csv" "$tmp/cyc.png"
check "plot cycle" test -s "$tmp/cyc.png"
plot diagnose "$tmp/res.csv" "$tmp/diag.png"
check "plot diagnose" test -s "$tmp/diag.png"
plot cycle "$tmp/pm.csv" "$tmp/wrong.png"
check "plot wrong file kind fails" test $? -ne 0

# Grid overrides (--speed/--torque), one helper for map, compare and synth. A case whose
# operating block is a point list becomes the grid of its points' speeds x torques with the
# given axis replaced, as map has always done: compare and synth apply it the same way (compare
# ignored it and synth refused it). The case and its oil are copied into the temporary directory.
mkdir -p "$tmp/pl/oils"
cp "$src/configs/oils/75W90-A.yaml" "$tmp/pl/oils/75W90-A.yaml"
awk '/^operating:/ { print "operating:"; print "  points: [[600 rpm, 150 N*m], [800 rpm, 250 N*m]]"; skip = 1; next }
     skip && /^  / { next } { skip = 0; print }' "$src/configs/transfer-box.yaml" > "$tmp/pl/case.yaml"
check "point-list case written" grep -q '^  points: \[\[600 rpm' "$tmp/pl/case.yaml"
pl_oils=(--oil "$tmp/pl/oils/75W90-A.yaml" --oil "$src/configs/oils/75W140-A.yaml")
"$bin" map "$tmp/pl/case.yaml" --speed 600,700rpm --oil-temp 70degC -o "$tmp/pl/map.csv"
check "map --speed on a point list: exit 0" test $? -eq 0
check "map --speed on a point list: 2 speeds x 2 torques" test "$(wc -l < "$tmp/pl/map.csv")" -eq 5
"$bin" compare "$tmp/pl/case.yaml" "${pl_oils[@]}" --speed 600,700rpm --oil-temp 70degC -o "$tmp/pl/cmp.csv"
check "compare --speed on a point list: exit 0" test $? -eq 0
check "compare --speed on a point list: the points of map" \
    cmp -s <(cut -d, -f1,2 "$tmp/pl/map.csv") <(cut -d, -f1,2 "$tmp/pl/cmp.csv")
check "compare --speed on a point list: 700 rpm applied" grep -q '^700,' "$tmp/pl/cmp.csv"
"$bin" compare "$tmp/pl/case.yaml" "${pl_oils[@]}" --torque 200Nm --oil-temp 70degC -o "$tmp/pl/cmp-t.csv"
check "compare --torque on a point list: 2 speeds x 200 N*m" \
    test "$(cut -d, -f1,2 "$tmp/pl/cmp-t.csv" | tail -n +2 | tr '\n' ' ')" = "600,200 800,200 "
"$bin" synth "$tmp/pl/case.yaml" --speed 600,700rpm --seed 2 -o "$tmp/pl/rec.csv"
check "synth --speed on a point list: exit 0" test $? -eq 0
check "synth --speed on a point list: the points of map" \
    cmp -s <(cut -d, -f1,2 "$tmp/pl/map.csv" | tail -n +2) <(cut -d, -f1,2 "$tmp/pl/rec.csv" | tail -n +2 | sed 's/\.0*,/,/; s/\.0*$//')
# An override value that cannot apply is an error naming the option (exit 2, no file), never
# ignored: out of range on a point list (compare used to run the case's points), or empty.
cannot_apply() {  # cannot_apply NAME OPTION COMMAND...: exit 2, "OPTION:" on stderr, no output file
    local name=$1 option=$2
    shift 2
    "$@" -o "$tmp/pl/none.csv" > /dev/null 2> "$tmp/pl/err.txt"
    check "$name: exit 2" test $? -eq 2
    check "$name: names $option" grep -q -- "$option: " "$tmp/pl/err.txt"
    check "$name: no output file" test ! -e "$tmp/pl/none.csv"
}
cannot_apply "compare --speed 1e9rpm on a point list" --speed "$bin" compare "$tmp/pl/case.yaml" "${pl_oils[@]}" --speed 1e9rpm
cannot_apply "synth --torque 1e9Nm on a point list" --torque "$bin" synth "$tmp/pl/case.yaml" --torque 1e9Nm
cannot_apply "map --speed ''" --speed "$bin" map "$src/configs/transfer-box.yaml" --speed ''
cannot_apply "compare --torque ''" --torque "$bin" compare "$src/configs/transfer-box.yaml" "${pl_oils[@]}" --torque ''
cannot_apply "synth --speed ''" --speed "$bin" synth "$src/configs/transfer-box.yaml" --speed ''
cannot_apply "map --format vecto --torque ''" --torque "$bin" map "$src/configs/manual-6speed.yaml" --format vecto --oil-temp 70degC --torque ''

# check --oil-temp reports the oil at that temperature (text and JSON); without it, nothing more.
"$bin" check "$src/configs/transfer-box.yaml" --oil-temp 70degC > "$tmp/check70.txt"
check "check --oil-temp: exit 0" test $? -eq 0
check "check --oil-temp: oil line" grep -qE '^    at 70\.0 degC \(--oil-temp\): nu = [0-9.]+ cSt, rho = [0-9.]+ kg/m\^3, eta = [0-9.]+ mPa\*s' "$tmp/check70.txt"
check "check --oil-temp: line after the oil block" \
    bash -c "grep -A1 'permissible oil temperature' '$tmp/check70.txt' | grep -q 'at 70.0 degC (--oil-temp)'"
"$bin" check "$src/configs/transfer-box.yaml" > "$tmp/check.txt"
check "check --oil-temp: otherwise the same report" cmp -s "$tmp/check.txt" <(grep -v -- '(--oil-temp)' "$tmp/check70.txt")
"$bin" check "$src/configs/transfer-box.yaml" --oil-temp 70degC --json > "$tmp/check70.json"
check "check --oil-temp --json" python3 -c "
import json
d = json.load(open('$tmp/check70.json'))
o, s = d['oil'], d['oil_at_oil_temp']
assert abs(s['temperature_C'] - 70) < 1e-9, s
assert o['nu100_cSt'] < s['nu_cSt'] < o['nu40_cSt'], (o, s)  # between its 40 and 100 degC values
assert abs(s['eta_mPa_s'] - s['nu_cSt'] * s['rho_kg_m3'] * 1e-3) < 1e-6 * s['eta_mPa_s'], s
for k in ('alpha_p_1_Pa', 'beta_T_1_K'): assert s[k] > 0, k"
"$bin" check "$src/configs/transfer-box.yaml" --json > "$tmp/check.json"
check "check --json without --oil-temp: no oil_at_oil_temp" python3 -c "
import json; assert 'oil_at_oil_temp' not in json.load(open('$tmp/check.json'))"
"$bin" check "$src/configs/transfer-box.yaml" --oil-temp 150degC > "$tmp/check150.txt"
check "check --oil-temp above the oil's limit: line and warning" \
    bash -c "grep -q 'at 150.0 degC (--oil-temp)' '$tmp/check150.txt' && grep -q -- '--oil-temp: warning: fixed oil temperature 150.0 degC' '$tmp/check150.txt'"

# map --spread: the nominal columns unchanged, five more; the extremes bracket the nominal
# and name the forms; options that cannot combine with it are errors naming them.
"$bin" map "$src/configs/transfer-box.yaml" --speed 800,2000rpm --torque 150Nm -o "$tmp/nominal.csv"
"$bin" map "$src/configs/transfer-box.yaml" --speed 800,2000rpm --torque 150Nm --spread \
    --spread-axes mesh.friction,windage.form -o "$tmp/spread.csv" --json "$tmp/spread.json"
check "spread exit 0" test $? -eq 0
check "spread: nominal columns as without it" cmp -s <(cut -d, -f1-19 "$tmp/spread.csv") "$tmp/nominal.csv"
check "spread: columns and bracket" python3 -c "
import csv, json
rows = list(csv.DictReader(open('$tmp/spread.csv')))
assert len(rows) == 2
for r in rows:
    lo, P, hi = float(r['P_total_min_W']), float(r['P_total_W']), float(r['P_total_max_W'])
    assert lo <= P <= hi and lo < hi, r
    for k in ('forms_at_min', 'forms_at_max'):
        assert r[k] == 'nominal' or all(x.split('=')[0] in ('mesh.friction', 'windage.form') for x in r[k].split(';')), r[k]
    assert r['combinations_unsolved'] == '0'
s = json.load(open('$tmp/spread.json'))['spread']
assert s['combinations'] == 15 and [a['axis'] for a in s['axes']] == ['mesh.friction', 'windage.form'], s
assert s['widest_relative_spread'] > 0"
# Forms that do not apply to a case (Ohlendorf's and Buckingham's H_V at eps_alpha = 2.09) are
# left out, counted in the JSON and named in one line on stderr; the map succeeds.
"$bin" map "$src/tests/high-contact-ratio.yaml" --spread --spread-axes mesh.loss_factor -o "$tmp/hr.csv" --json "$tmp/hr.json" 2> "$tmp/err.txt"
check "spread: forms that do not apply are skipped, exit 0" test $? -eq 0
# (The case has no bearings on purpose: the warning that says so is the other stderr line.)
check "spread: one stderr line naming the skipped combinations and why" bash -c "test \$(grep -vc 'warning: the case has no bearings' '$tmp/err.txt') -eq 1 &&
    grep -q '2 of 3 form combinations do not apply to this case' '$tmp/err.txt' &&
    grep -q \"first: mesh.loss_factor=ohlendorf: mesh 'm' has eps_alpha = 2.086\" '$tmp/err.txt'"
check "spread: not applicable in the JSON, not unsolved in the CSV" python3 -c "
import csv, json
s = json.load(open('$tmp/hr.json'))['spread']
assert s['combinations'] == 3 and s['combinations_not_applicable'] == 2, s
assert s['not_applicable'] == ['mesh.loss_factor=ohlendorf', 'mesh.loss_factor=buckingham'], s
assert s['points_with_unsolved_combinations'] == 0, s
for r in csv.DictReader(open('$tmp/hr.csv')):
    assert r['combinations_unsolved'] == '0' and r['forms_at_min'] == r['forms_at_max'] == 'nominal', r
    assert r['P_total_min_W'] == r['P_total_W'] == r['P_total_max_W'], r"
"$bin" map "$src/configs/transfer-box.yaml" --spread-axes mesh.friction -o "$tmp/sx.csv" 2> "$tmp/err.txt"
check "spread-axes without --spread: exit 2" bash -c "test $? -eq 2 && grep -q -- '--spread-axes' '$tmp/err.txt' && test ! -e '$tmp/sx.csv'"
"$bin" map "$src/configs/transfer-box.yaml" --spread --spread-axes mesh.fricton -o "$tmp/sx.csv" 2> "$tmp/err.txt"
check "spread: unknown axis named with the known ones" \
    bash -c "test $? -eq 2 && grep -q 'mesh.fricton' '$tmp/err.txt' && grep -q 'windage.form' '$tmp/err.txt' && test ! -e '$tmp/sx.csv'"
for bad in , mesh.friction, ''; do
    "$bin" map "$src/configs/transfer-box.yaml" --spread --spread-axes "$bad" -o "$tmp/sx.csv" 2> "$tmp/err.txt"
    check "spread-axes '$bad': exit 2 naming the option" \
        bash -c "test $? -eq 2 && grep -q -- '--spread-axes' '$tmp/err.txt' && ! grep -q -- \"'-o'\" '$tmp/err.txt' && test ! -e '$tmp/sx.csv'"
done
"$bin" map "$src/configs/transfer-box.yaml" --spread --shard 1/2 -o "$tmp/sx.csv" 2> "$tmp/err.txt"
check "spread with --shard: exit 2" bash -c "test $? -eq 2 && grep -q -- '--spread' '$tmp/err.txt'"
"$bin" map "$src/configs/transfer-box.yaml" --spread --format vecto -o "$tmp/sx.vtlm" 2> "$tmp/err.txt"
check "spread with vecto: exit 2" bash -c "test $? -eq 2 && grep -q -- '--spread' '$tmp/err.txt'"
"$bin" check "$src/configs/transfer-box.yaml" > "$tmp/check.txt"
check "check lists the form axes" grep -q 'mesh.friction: \[schlenk\] iso_6336_20' "$tmp/check.txt"

echo "$pass passed, $fail failed"
test $fail -eq 0
