#!/usr/bin/env bash
# End-to-end regression cases of an independent hostile-input review (issue 13): values that
# are finite but absurd, names that look alike, outputs onto inputs, damaged shards. Each
# ends with the stated exit code, a located message without raw control bytes or hundreds of
# digits, and no "nan"/"inf" anywhere in the output.
# Usage: cli_hostile_values.sh GEARLOSS_BINARY SOURCE_DIR
# Every file is made inside the private mktemp -d directory (cli_common.sh).
set -u
source "$(dirname "$0")/cli_common.sh" "$@"
cp -r "$src/configs/oils" "$tmp/oils"
cp "$src/configs/spur-seed000.yaml" "$tmp/spur.yaml"
cp "$src/configs/automatic-6speed.yaml" "$tmp/auto.yaml"
spur=$tmp/spur.yaml
T="timeout -k 5 60"

# no_nonfinite FILE...: no nan/inf printed as a number in the files (a bad cell quoted in a
# message, 'nan', and a value spelt out as "+infinity" are words, not numbers).
no_nonfinite() { ! cat "$@" | sed "s/'[^']*'//g" | grep -qiwE -- '[-+]?(nan|inf)'; }

# expect NAME CODE PATTERN COMMAND...: exit CODE, PATTERN (grep -E) in stderr, a short message
# without an ESC byte, and no nan/inf in stdout or stderr.
expect() {
    local name=$1 code=$2 pattern=$3
    shift 3
    $T "$@" > "$tmp/out" 2> "$tmp/err"
    local rc=$?
    check "$name: exit $code (got $rc)" test $rc -eq "$code"
    [ -n "$pattern" ] && check "$name: message /$pattern/" grep -qE -- "$pattern" "$tmp/err"
    check "$name: message under 800 bytes" test "$(wc -c < "$tmp/err")" -lt 800
    check "$name: no ESC byte in the message" test "$(tr -dc '\033' < "$tmp/err" | wc -c)" -eq 0
    check "$name: no nan/inf in the output" no_nonfinite "$tmp/out" "$tmp/err"
}

# 1. A cycle sampled every 100 s (the integrator's first trial step was 100 s: its stages left
#    the oil's validity and a root finder threw, exit 4); a cycle that never moves (inf L/100 km).
printf 'time_s,speed_kmh\n0,50\n100,50\n' > "$tmp/steady50.csv"
expect "cycle at constant 50 km/h sampled every 100 s" 0 "" \
    "$bin" cycle "$tmp/auto.yaml" --cycle "$tmp/steady50.csv" --start-temp -10degC
printf 'time_s,speed_kmh\n0,0\n1,0\n' > "$tmp/standstill.csv"
expect "cycle standing still" 0 "" "$bin" cycle "$tmp/auto.yaml" --cycle "$tmp/standstill.csv" --start-temp -10degC
check "cycle standing still: says no distance" grep -q "no distance driven" "$tmp/out"
expect "cycle --start-temp 1e308degC" 2 "--start-temp: .*outside the stated range" \
    "$bin" cycle "$tmp/auto.yaml" --cycle nedc --start-temp 1e308degC
check "cycle --start-temp 1e308degC: no 300-digit number" test "$(grep -cE '[0-9]{40}' "$tmp/err")" -eq 0

# 2. Values that describe no oil, gear or bearing.
sed 's/astm_d341: {A: 9.0658, B: 3.4730}/astm_d341: {A: 1e308, B: 2.7865}/' "$tmp/oils/MINR.yaml" > "$tmp/oils/absurd.yaml"
expect "oil with ASTM D341 A = 1e308" 2 "absurd.yaml:[0-9]+:[0-9]+: oil.viscosity: .*not an oil" \
    "$bin" check "$spur" --oil "$tmp/oils/absurd.yaml"
sed 's/face_width: 20 mm/face_width: 1e-300 m/g' "$spur" > "$tmp/thin.yaml"
expect "face width 1e-300 m" 2 "thin.yaml:[0-9]+:[0-9]+: gears\[0\].face_width: " "$bin" check "$tmp/thin.yaml"
sed 's/d: 40 mm, D: 90 mm/d: 1e-300 mm, D: 1e-299 mm/' "$spur" > "$tmp/tiny.yaml"
expect "bearing bore 1e-300 mm" 2 "tiny.yaml:[0-9]+:[0-9]+: bearings\[0\].d: " "$bin" check "$tmp/tiny.yaml"
expect "point --speed '1e308 rad/s'" 2 "--speed: .*beyond the stated range" \
    "$bin" point "$spur" --speed '1e308 rad/s' --torque 250Nm

# 3. Recordings with a loss of 1e155 W (a residual statistic overflowed: exit 4).
"$bin" synth "$spur" -o "$tmp/rec.csv" 2> /dev/null
awk -F, 'NR == 3 { $3 = "1e155" } { print }' OFS=, "$tmp/rec.csv" > "$tmp/rec-big.csv"
expect "diagnose with a loss of 1e155 W" 2 "rec-big.csv:3:3: P_loss_W: .*beyond the stated range" \
    "$bin" diagnose "$spur" "$tmp/rec-big.csv"

# 4. Names: references echoed short and without control bytes; names that look alike; a ratio
#    name that would leave the output directory; a name that makes a column twice.
esc=$(printf 'in\033[31mRED-%0200d' 0)
sed "s/shaft: input,  position: -60 mm/shaft: \"$(printf 'in\\e[31mRED')-$(printf '%0200d' 0)\",  position: -60 mm/" "$spur" > "$tmp/escname.yaml"
expect "unknown shaft with ESC and 200 digits" 2 "escname.yaml:[0-9]+:[0-9]+: bearings\[0\].shaft: unknown shaft" \
    "$bin" check "$tmp/escname.yaml"
sed 's/name: in_b,/name: "in_a\xe2\x80\x8b",/' "$spur" > "$tmp/zwsp.yaml"
expect "a name with a zero-width space" 2 "zwsp.yaml:[0-9]+:[0-9]+: bearings\[1\].name: .*U\+200B" "$bin" check "$tmp/zwsp.yaml"
sed 's/name: in_b,/name: "in_b ",/' "$spur" > "$tmp/blank.yaml"
expect "a name ending in a blank" 2 "blank.yaml:[0-9]+:[0-9]+: bearings\[1\].name: .*blank" "$bin" check "$tmp/blank.yaml"
sed 's/^    g1: {engage/    "\/..\/..\/pwned": {engage/; s/gears: \[g1,/gears: ["\/..\/..\/pwned",/' "$src/configs/manual-6speed.yaml" > "$tmp/pwn.yaml"
mkdir -p "$tmp/sub"
expect "a ratio named /../../pwned" 2 "pwn.yaml:[0-9]+:[0-9]+: .*cannot contain '/'" \
    "$bin" map "$tmp/pwn.yaml" --format vecto --oil-temp 70degC -o "$tmp/sub/man.vtlm"
check "a ratio named /../../pwned: nothing written" test -z "$(find "$tmp" -name 'pwned*')"
sed 's/name: m, gears/name: min, gears/' "$spur" > "$tmp/min.yaml"
expect "a mesh named min with --detail" 2 "--detail: column 'lambda_min' would appear twice" \
    "$bin" map "$tmp/min.yaml" --speed 800rpm --torque 100Nm --oil-temp 70degC --detail -o "$tmp/min.csv"
sed 's/^name: .*/name: "oil,b"/' "$tmp/oils/75W90-syn-A.yaml" > "$tmp/oils/comma.yaml"
expect "compare of two oils of one name with a comma" 0 "" "$bin" compare "$spur" --oil "$tmp/oils/comma.yaml" \
    --oil "$tmp/oils/comma.yaml" --speed 800rpm --torque 100Nm --oil-temp 70degC -o "$tmp/cmp.csv"
check "compare: header and rows have 13 cells" test "$(awk -F, '{ print NF }' "$tmp/cmp.csv" | sort -u)" = 13

# 4b. Effects: a count that does not fit an int (a float-to-int overflow before), one effect twice;
#     a prescribed gear the vehicle does not have (it was clamped silently).
expect "synth --effect unstabilised_test=1e308" 2 "--effect: unstabilised_test: give a whole number" \
    "$bin" synth "$spur" --effect unstabilised_test=1e308 -o "$tmp/syn.csv"
expect "synth --effect windage twice" 2 "--effect: 'windage' given twice" \
    "$bin" synth "$spur" --effect windage=10W --effect windage=20W -o "$tmp/syn.csv"
printf 'time_s,speed_kmh,gear\n0,0,0\n1,10,1\n2,20,7\n' > "$tmp/gear7.csv"
expect "cycle with gear 7 on a six-speed" 2 "cycle: sample 3: gear 7 but the vehicle has gears 1..6" \
    "$bin" cycle "$src/configs/manual-6speed.yaml" --cycle "$tmp/gear7.csv" --start-temp 20degC

printf 'time_s,speed_kmh,speed_kmh\n0,0,0\n1,10,10\n' > "$tmp/twocols.csv"
expect "cycle file naming speed_kmh twice" 2 "twocols.csv:1:3: speed_kmh: column 'speed_kmh' given twice" \
    "$bin" cycle "$src/configs/manual-6speed.yaml" --cycle "$tmp/twocols.csv" --start-temp 20degC
expect "synth --noise-temp 1e-1K (an exponent, not a unit 'e')" 0 "" \
    "$bin" synth "$spur" --noise-temp 1e-1K -o "$tmp/syn.csv"

# 5. An output onto an input: the input stays.
cp "$spur" "$tmp/keep.yaml"
expect "map -o onto its own case" 2 "--output .* is the input config" \
    "$bin" map "$tmp/keep.yaml" --speed 800rpm --torque 100Nm -o "$tmp/keep.yaml"
check "map -o onto its own case: case unchanged" cmp -s "$spur" "$tmp/keep.yaml"
cp "$tmp/rec.csv" "$tmp/rec-keep.csv"
expect "diagnose --residuals onto the recordings" 2 "--residuals .* is the input recordings" \
    "$bin" diagnose "$spur" "$tmp/rec-keep.csv" --residuals "$tmp/rec-keep.csv"
check "diagnose --residuals onto the recordings: recordings unchanged" cmp -s "$tmp/rec.csv" "$tmp/rec-keep.csv"

# 6. A damaged shard: a cell edited to nan, a row with an extra cell.
for k in 1 2; do "$bin" map "$spur" --speed 600,800rpm --torque 100,200Nm --oil-temp 70degC --shard $k/2 -o "$tmp/s$k.csv"; done
awk -F, 'NR == 3 { $6 = "nan" } { print }' OFS=, "$tmp/s1.csv" > "$tmp/s1-edited.csv"
expect "merge of a shard with a nan cell" 2 "s1-edited.csv:3:6: .*not a finite number" \
    "$bin" merge "$tmp/s1-edited.csv" "$tmp/s2.csv" -o "$tmp/merged.csv"
awk 'NR == 3 { $0 = $0 ",extra" } { print }' "$tmp/s1.csv" > "$tmp/s1-extra.csv"
expect "merge of a shard with an extra cell" 2 "s1-extra.csv:3: .*cells, the header has" \
    "$bin" merge "$tmp/s1-extra.csv" "$tmp/s2.csv" -o "$tmp/merged.csv"
check "merge: nothing written" test ! -e "$tmp/merged.csv"
# Cells edited to what gearloss never writes: text or hexadecimal in a number column, a blank
# before a number, a status that is none, a carriage return at the end of the line.
edit() {  # edit NAME AWK-PROGRAM PATTERN
    awk -F, "$2" OFS=, "$tmp/s1.csv" > "$tmp/s1-$1.csv"
    expect "merge of a shard with $1" 2 "s1-$1.csv:3:[0-9]+: .*$3" "$bin" merge "$tmp/s1-$1.csv" "$tmp/s2.csv" -o "$tmp/merged.csv"
}
edit "text in a number cell" 'NR == 3 { $7 = "abc" } { print }' "'abc' is not a number as gearloss writes one"
edit "a hexadecimal number" 'NR == 3 { $7 = "0x10" } { print }' "'0x10' is not a number as gearloss writes one"
edit "a blank before a number" 'NR == 3 { $4 = " 25.00" } { print }' "is not a number as gearloss writes one"
edit "an edited status" 'NR == 3 { $NF = "ko" } { print }' "'ko' is not a status of a map point"
edit "a carriage return" 'NR == 3 { $0 = $0 "\r" } { print }' "is not a status of a map point"
check "merge of edited shards: nothing written" test ! -e "$tmp/merged.csv"

# 7. A sweep variant with a bad value: the error points at the value's line in the user's file
# (not at re-emitted text), names the variant, and comes before any point is solved (the
# first variant is good; nothing is written).
cp "$src/configs/transfer-box.yaml" "$tmp/sweep.yaml"
printf '\nsweep:\n  - {parameter: housing.oil_level, values: [-30 mm, -10 mm]}\n  - parameter: [gears.w2.face_width, gears.w1.face_width]\n    values:\n      - 30 mm\n      - -3 mm\n' >> "$tmp/sweep.yaml"
bad_line=$(grep -n -- "- -3 mm" "$tmp/sweep.yaml" | cut -d: -f1)
expect "sweep variant with a negative face width" 2 \
    "sweep.yaml:$bad_line:[0-9]+: .*face_width: must be positive.*\(sweep variant housing.oil_level=-30 mm, gears.w2.face_width=-3 mm\)" \
    "$bin" map "$tmp/sweep.yaml" -o "$tmp/sweep.csv"
check "sweep variant error: nothing written" test ! -e "$tmp/sweep.csv"

# 8. A sweep and an option that set the same value: an error naming both, never a column that
# labels values the option replaced (the sweep's oil column over rows of the --oil oil).
cp "$src/configs/transfer-box.yaml" "$tmp/oil-sweep.yaml"
printf '\nsweep:\n  - {parameter: oil, values: [oils/75W90-A.yaml, oils/75W140-A.yaml]}\n' >> "$tmp/oil-sweep.yaml"
expect "sweep of the oil with --oil" 2 "--oil: the case's sweep sets 'oil'" \
    "$bin" map "$tmp/oil-sweep.yaml" --oil "$tmp/oils/MINR.yaml" -o "$tmp/sweep.csv"
cp "$src/configs/transfer-box.yaml" "$tmp/temp-sweep.yaml"
printf '\nsweep:\n  - {parameter: thermal.mode, values: [stabilised, fixed]}\n' >> "$tmp/temp-sweep.yaml"
expect "sweep of the thermal mode with --oil-temp" 2 "--oil-temp: the case's sweep sets 'thermal.mode'" \
    "$bin" map "$tmp/temp-sweep.yaml" --oil-temp 70degC -o "$tmp/sweep.csv"
cp "$src/configs/transfer-box.yaml" "$tmp/twice.yaml"
printf '\nsweep:\n  - {parameter: gears.w1.face_width, values: [30 mm]}\n  - {parameter: [gears.w2.face_width, gears.w1.face_width], values: [35 mm]}\n' >> "$tmp/twice.yaml"
expect "a path on two sweep axes" 2 "twice.yaml:[0-9]+:[0-9]+: .*'gears.w1.face_width' is already set by the sweep's axis" \
    "$bin" map "$tmp/twice.yaml" -o "$tmp/sweep.csv"
expect "VECTO tables of a sweep case" 2 "--format vecto: the case has a sweep" \
    "$bin" map "$tmp/oil-sweep.yaml" --format vecto --oil-temp 70degC -o "$tmp/sweep.vtlm"
expect "VECTO with --json" 2 "--json: --format vecto writes loss tables only" \
    "$bin" map "$spur" --format vecto --oil-temp 70degC --json "$tmp/v.json" -o "$tmp/v.vtlm"
check "sweep option conflicts: nothing written" test ! -e "$tmp/sweep.csv" -a ! -e "$tmp/v.vtlm"

# A sweep value with a comma and a quote is one quoted cell: its shards merge into the single run
# (a merge that split every comma refused them).
cp "$src/configs/transfer-box.yaml" "$tmp/quoted.yaml"
printf '\nsweep:\n  - {parameter: name, values: ["box, A", "box \\"B\\""]}\n' >> "$tmp/quoted.yaml"
"$bin" map "$tmp/quoted.yaml" -o "$tmp/quoted.csv"
for k in 1 2 3; do "$bin" map "$tmp/quoted.yaml" --shard $k/3 -o "$tmp/quoted-$k.csv"; done
"$bin" merge "$tmp/quoted-3.csv" "$tmp/quoted-1.csv" "$tmp/quoted-2.csv" -o "$tmp/quoted-merged.csv"
check "sweep values with a comma and a quote: merged shards = single run" cmp -s "$tmp/quoted.csv" "$tmp/quoted-merged.csv"
check "sweep values with a comma and a quote: quoted cells" grep -q '^"box ""B""",600,' "$tmp/quoted.csv"

# 9. An output onto a file the case names (its oil file, an oil file among the sweep's values):
# exit 2 and the oil file unchanged.
cp "$tmp/oils/75W140-A.yaml" "$tmp/oil-before.yaml"
expect "map -o onto an oil file of the sweep" 2 "--output .* is the input named by the case at 'sweep\[0\].values\[1\]'" \
    "$bin" map "$tmp/oil-sweep.yaml" -o "$tmp/oils/75W140-A.yaml"
expect "map --json onto the case's oil file" 2 "--json .* is the input named by the case at 'oil'" \
    "$bin" map "$tmp/oil-sweep.yaml" --json "$tmp/oils/75W90-A.yaml" -o "$tmp/sweep.csv"
check "oil files unchanged" cmp -s "$tmp/oils/75W140-A.yaml" "$tmp/oil-before.yaml"
check "oil file unchanged (--json)" cmp -s "$tmp/oils/75W90-A.yaml" "$src/configs/oils/75W90-A.yaml"
# Every command that writes files refuses its case's oil file and a user bearing catalogue the
# case names as outputs, as map does (report, point --json, mesh-profile, synth, cycle and
# compare overwrote them before, exit 0).
cp "$src/configs/manual-6speed.yaml" "$tmp/man.yaml"
mkdir -p "$tmp/cat"
printf 'format: gearloss-bearing-catalogue/1\nseries:\n  - series: "63"\n    type: deep_groove_ball\n    skf_series: "63"\n    columns: [designation, d, D, B, C, C0]\n    bearings:\n      - ["6307 X", 35, 80, 22, 36, 20]\n' > "$tmp/cat/own.yaml"
printf '\nbearing_catalogue: cat/own.yaml\n' >> "$tmp/man.yaml"
cp "$tmp/oils/75W90-A.yaml" "$tmp/oil-before.yaml"
cp "$tmp/cat/own.yaml" "$tmp/cat-before.yaml"
p1=(--speed 1000rpm --torque 50Nm)
for target in "$tmp/oils/75W90-A.yaml" "$tmp/cat/own.yaml"; do
    t=$(basename "$target")
    expect "report -o onto $t" 2 "is the input named by the case" "$bin" report "$tmp/man.yaml" "${p1[@]}" --no-spread -o "$target"
    expect "point --json onto $t" 2 "is the input named by the case" "$bin" point "$tmp/man.yaml" "${p1[@]}" --json "$target"
    expect "synth -o onto $t" 2 "is the input named by the case" "$bin" synth "$tmp/man.yaml" "${p1[@]}" -o "$target"
    expect "cycle -o onto $t" 2 "is the input named by the case" "$bin" cycle "$tmp/man.yaml" --cycle nedc --start-temp 20degC -o "$target"
    expect "compare -o onto $t" 2 "is the input named by the case" "$bin" compare "$tmp/man.yaml" --oil "$tmp/oils/75W90-A.yaml" \
        --oil "$tmp/oils/75W140-A.yaml" "${p1[@]}" -o "$target"
done
check "oil file unchanged (every command)" cmp -s "$tmp/oils/75W90-A.yaml" "$tmp/oil-before.yaml"
check "user catalogue unchanged (every command)" cmp -s "$tmp/cat/own.yaml" "$tmp/cat-before.yaml"
check "no sidecar beside the inputs" test ! -e "$tmp/oils/75W90-A.yaml.meta.json" -a ! -e "$tmp/cat/own.yaml.meta.json"

# 10. Every shard of a job with a bad variant fails, not only the shard holding it (a job of up
# to 1 000 variants is checked whole by each shard); a sweep variant's plausibility warning
# is printed as the case's would be.
for k in 1 2 3; do
    expect "shard $k/3 of a job with bad variants (shard 1 holds a good one)" 2 "face_width: must be positive.*sweep variant" \
        "$bin" map "$tmp/sweep.yaml" --speed 600rpm --torque 100Nm --shard $k/3 -o "$tmp/shard$k.csv"
done
check "no shard written" test ! -e "$tmp/shard1.csv" -a ! -e "$tmp/shard2.csv" -a ! -e "$tmp/shard3.csv"
cp "$src/configs/transfer-box.yaml" "$tmp/hot.yaml"
sed -i 's/^  mode: stabilised/  mode: fixed\n  oil_temperature: 60 degC/' "$tmp/hot.yaml"
printf '\nsweep:\n  - {parameter: thermal.oil_temperature, values: [60 degC, 190 degC]}\n' >> "$tmp/hot.yaml"
"$bin" map "$tmp/hot.yaml" --speed 600rpm --torque 100Nm -o "$tmp/hot.csv" 2> "$tmp/hot.err"
check "hot sweep variant: map exit 0" test $? -eq 0
check "hot sweep variant: its warning at the value's line" \
    grep -qE "hot.yaml:$(grep -n "190 degC" "$tmp/hot.yaml" | cut -d: -f1):[0-9]+: .*190.0 degC is above the permissible" "$tmp/hot.err"

echo "$pass passed, $fail failed"
test $fail -eq 0
