#!/usr/bin/env bash
# End-to-end regression cases of the second hostile-input review (issue 37, items 3, 5, 6):
# values read as they are written (units and kinds), nonsense refused at the row or key that
# holds it, messages that name the option or key at fault, and no nan/inf in any output of
# any command, for the inputs that are accepted as much as for those that are refused.
# Usage: cli_values_units_nan.sh GEARLOSS_BINARY SOURCE_DIR
# Every file is made inside the private mktemp -d directory (cli_common.sh).
set -u
source "$(dirname "$0")/cli_common.sh" "$@"
cp -r "$src/configs/oils" "$tmp/oils"
cp "$src/configs/spur-seed000.yaml" "$tmp/spur.yaml"
cp "$src/configs/transfer-box.yaml" "$tmp/tb.yaml"
cp "$src/configs/manual-6speed.yaml" "$tmp/man.yaml"
spur=$tmp/spur.yaml
tb=$tmp/tb.yaml
T="timeout -k 5 120"

# no_nonfinite FILE...: no nan/inf printed as a number (a quoted input in a message is a word).
no_nonfinite() { ! cat "$@" | sed "s/'[^']*'//g" | grep -qiwE -- '[-+]?(nan|inf|infinity)'; }

# expect NAME CODE PATTERN COMMAND...: exit CODE, PATTERN (grep -E) in stderr, the message on
# one line, and no nan/inf in stdout or stderr.
expect() {
    local name=$1 code=$2 pattern=$3
    shift 3
    $T "$@" > "$tmp/out" 2> "$tmp/err"
    local rc=$?
    check "$name: exit $code (got $rc)" test $rc -eq "$code"
    [ -n "$pattern" ] && check "$name: message /$pattern/" grep -qE -- "$pattern" "$tmp/err"
    [ "$code" -ne 0 ] && check "$name: one line" test "$(grep -cv '^gearloss: warning\|^gearloss: note' "$tmp/err")" -le 1
    check "$name: no nan/inf" no_nonfinite "$tmp/out" "$tmp/err"
}

# ---------------------------------------------------------------------------------------
# 3. Units and kinds.
sed 's/angle: 0 deg/angle: 60/' "$spur" > "$tmp/angle.yaml"
expect "angle: 60 (no unit; was 60 rad)" 2 "angle.yaml:[0-9]+:[0-9]+: meshes\[0\]\.angle: .*no angle unit" \
    "$bin" check "$tmp/angle.yaml"
sed 's/helix_angle: 20 deg, hand: right, material: 15CrNi6, Ra: 0.5 um}/helix_angle: 0.3, hand: right, material: 15CrNi6, Ra: 0.5 um}/' "$tb" > "$tmp/helix.yaml"
expect "helix_angle: 0.3 (was 17.2 deg)" 2 "helix.yaml:[0-9]+:[0-9]+: gears\[0\]\.helix_angle: .*no angle unit" \
    "$bin" check "$tmp/helix.yaml"
expect "--torque '200 Wh'" 2 "^gearloss: error: --torque: .*not a torque" \
    "$bin" point "$tb" --speed 800rpm --torque '200 Wh' --oil-temp 70degC
expect "--torque '200 J'" 2 "^gearloss: error: --torque: .*not a torque" \
    "$bin" point "$tb" --speed 800rpm --torque '200 J' --oil-temp 70degC
expect "--speed '1000 rpm/rev'" 2 "^gearloss: error: --speed: .*not a rotational speed" \
    "$bin" point "$tb" --speed '1000 rpm/rev' --torque 200Nm --oil-temp 70degC
expect "--speed 1000rpm,5 (mixed)" 2 "^gearloss: error: --speed: .*mixes items" \
    "$bin" map "$tb" --speed 1000rpm,5 --torque 200Nm --oil-temp 70degC -o "$tmp/mixed.csv"
# Documented spellings: '70C' is 70 degC; '1000,5rpm' is two speeds (a comma separates items).
"$bin" point "$tb" --speed 800rpm --torque 200Nm --oil-temp 70C > "$tmp/70C.txt" 2> /dev/null
"$bin" point "$tb" --speed 800rpm --torque 200Nm --oil-temp 70degC > "$tmp/70degC.txt" 2> /dev/null
check "--oil-temp 70C = 70degC (documented)" cmp -s "$tmp/70C.txt" "$tmp/70degC.txt"
"$bin" map "$tb" --speed 1000,5rpm --torque 200Nm --oil-temp 70degC -o "$tmp/two.csv" 2> /dev/null
check "--speed 1000,5rpm: rows 1000 and 5 rpm" \
    bash -c "[ \"\$(cut -d, -f1 '$tmp/two.csv' | tail -n +2 | tr '\n' ' ')\" = '1000 5 ' ]"

# Out-of-data values: oil at -100 degC (viscosity capped at 1e7 cSt, zero film, 'ok'), Ra 1e-300 um.
expect "--oil-temp -100degC" 2 "^gearloss: error: --oil-temp: .*below the data of oil" \
    "$bin" point "$tb" --speed 800rpm --torque 200Nm --oil-temp -100degC
expect "--format table --oil-temps -100,20degC" 2 "^gearloss: error: --oil-temps: .*below the data of oil" \
    "$bin" map "$tb" --format table --oil-temps -100,20degC -o "$tmp/table.csv"
expect "cycle --start-temp -90degC" 2 "below the data of oil" \
    "$bin" cycle "$tmp/man.yaml" --cycle nedc --start-temp -90degC
sed 's/Ra: 0.2 um/Ra: 1e-300 um/' "$spur" > "$tmp/ra.yaml"
expect "Ra: 1e-300 um" 2 "ra.yaml:[0-9]+:[0-9]+: gears\[0\]\.Ra: .*below 0.001 um" "$bin" check "$tmp/ra.yaml"
# A shaft with a gear and no bearing, and a case without bearings: a warning, not silence.
grep -v 'name: out_[ab],' "$spur" > "$tmp/nobear.yaml"
expect "gear shaft without bearings" 0 "" "$bin" check "$tmp/nobear.yaml"
check "gear shaft without bearings: warned at the shaft" grep -q "shaft 'output' carries gear(s) 'wheel' but no bearing" "$tmp/out"
grep -v 'name: \(in\|out\)_[ab],\|^bearings:' "$spur" > "$tmp/nobearings.yaml"
expect "case without bearings" 0 "" "$bin" point "$tmp/nobearings.yaml" --speed 800rpm --torque 100Nm --oil-temp 70degC
check "case without bearings: warned" grep -q "the case has no bearings" "$tmp/err"

# Drive cycles the vehicle cannot drive: an error at the row.
{ echo time_s,speed_kmh; for t in $(seq 0 19); do echo "$t,$(( t % 2 * 200 ))"; done; } > "$tmp/alt.csv"
expect "cycle 0/200 km/h every second" 2 "alt.csv:3:2: speed_kmh: .*beyond 1 g" \
    "$bin" cycle "$tmp/man.yaml" --cycle "$tmp/alt.csv" --start-temp 20degC
printf 'time_s,speed_kmh,gear\n0,0,0\n1,5,0\n2,8,1\n' > "$tmp/neutral.csv"
expect "cycle in gear 0 at 5 km/h" 2 "neutral.csv:3:3: gear: gear 0 \(neutral\) at 5 km/h" \
    "$bin" cycle "$tmp/man.yaml" --cycle "$tmp/neutral.csv" --start-temp 20degC
printf 'time_s,speed_kmh,gear\n0,0,1\n10,50,1\n20,100,1\n30,150,1\n40,200,1\n' > "$tmp/first.csv"
expect "cycle in gear 1 to 200 km/h" 2 "cycle: at t = [0-9]+ s .*input speed [0-9]+ rpm above the engine's max_speed" \
    "$bin" cycle "$tmp/man.yaml" --cycle "$tmp/first.csv" --start-temp 20degC

# Strings and YAML: a NUL or ESC escape in a value, a tag; an empty option.
sed 's/name: pinion/name: "pin\\0ion"/' "$spur" > "$tmp/nul.yaml"
expect "NUL in a name" 2 "nul.yaml:[0-9]+:[0-9]+: a control character \(U\+0000\)" "$bin" check "$tmp/nul.yaml"
sed 's|oil: oils/|oil: "oils/\\e[31m|' "$spur" > "$tmp/esc.yaml"
expect "ESC in a path" 2 "esc.yaml:[0-9]+:[0-9]+: a control character \(U\+001B\)" "$bin" check "$tmp/esc.yaml"
sed 's/module: 4 mm/module: !unit 4 mm/' "$spur" > "$tmp/tag.yaml"
expect "a !unit tag" 2 "tag.yaml:[0-9]+:[0-9]+: a YAML tag" "$bin" check "$tmp/tag.yaml"
sed 's/^name: .*/name: !!binary aGVsbG8=/' "$spur" > "$tmp/bin.yaml"
expect "a !!binary tag" 2 "bin.yaml:[0-9]+:[0-9]+: a YAML tag" "$bin" check "$tmp/bin.yaml"
expect "--shard ''" 2 "^gearloss: error: --shard: an empty value" "$bin" map "$spur" --shard '' -o "$tmp/shard.csv"
check "--shard '': nothing written" test ! -e "$tmp/shard.csv"
expect "an ESC in --oil" 2 "^gearloss: error: --oil: .*control character" "$bin" check "$spur" --oil "$(printf 'oils/\033[31mx.yaml')"

# ---------------------------------------------------------------------------------------
# 5. Oil tables: one temperature twice gave alpha_p(40) = -nan in check and report, and 'ok'.
sed 's/- \[70 degC, 1.194e-8 1\/Pa\]/- [40 degC, 1.194e-8 1\/Pa]/' "$tmp/oils/75W90-A.yaml" > "$tmp/oils/twice.yaml"
expect "piezoviscosity with 40 degC twice" 2 \
    "twice.yaml:$(grep -n '\[40 degC, 1.194e-8' "$tmp/oils/twice.yaml" | cut -d: -f1):[0-9]+: .*listed twice" \
    "$bin" check "$tb" --oil "$tmp/oils/twice.yaml"
sed 's/- \[70 degC, 36.7 cSt\]/- [100 degC, 36.7 cSt]/' "$tmp/oils/75W90-A.yaml" > "$tmp/oils/visc.yaml"
expect "viscosity points with 100 degC twice" 2 "visc.yaml:[0-9]+:[0-9]+: .*listed twice" \
    "$bin" check "$tb" --oil "$tmp/oils/visc.yaml"

# ---------------------------------------------------------------------------------------
# 6. Messages: the real problem, the right key, the option named, short numbers, one line.
expect "--oil-temp -273.15degC" 2 "^gearloss: error: --oil-temp: .*is absolute zero" \
    "$bin" point "$tb" --speed 800rpm --torque 200Nm --oil-temp -273.15degC
sed 's/heat_capacity: 8 kJ\/K/heat_capacity: 8 kJ\/degC/' "$spur" > "$tmp/hc.yaml"
expect "heat_capacity: 8 kJ/degC" 0 "" "$bin" check "$tmp/hc.yaml"
sed 's/module: 4 mm/module: 1e-9 mm/' "$spur" > "$tmp/mod.yaml"
expect "module 1e-9 mm" 2 "mod.yaml:[0-9]+:[0-9]+: gears\[0\]\.module: .*outside 0.05..100 mm" "$bin" check "$tmp/mod.yaml"
sed 's/face_width: 20 mm, Ra: 0.2 um, immersion/face_width: 20 mm, addendum_coefficient: 5, Ra: 0.2 um, immersion/' \
    "$spur" > "$tmp/add.yaml"
expect "addendum_coefficient: 5" 2 "add.yaml:[0-9]+:[0-9]+: gears\[0\]\.addendum_coefficient: " "$bin" check "$tmp/add.yaml"
sed '0,/module: 4 mm/s//module: 4.5 mm/' "$spur" > "$tmp/mods.yaml"
expect "modules 4.5 and 4 mm" 2 "normal modules differ \(4.5 mm vs 4 mm\)" "$bin" check "$tmp/mods.yaml"
expect "--torque '250 kg'" 2 "^gearloss: error: --torque: " \
    "$bin" point "$tb" --speed 800rpm --torque '250 kg' --oil-temp 70degC
check "--torque '250 kg': no <input>" bash -c "! grep -q '<input>' '$tmp/err'"
expect "--threads 0" 1 "^gearloss: usage error: --threads: .*1 to 1024" "$bin" map "$spur" --threads 0 -o "$tmp/t.csv"
expect "--threads abc" 1 "^gearloss: usage error: --threads: " "$bin" map "$spur" --threads abc -o "$tmp/t.csv"

# ---------------------------------------------------------------------------------------
# Values that break physics are never 'ok' (second red team, F7, F8, M1-M3, M5).
# F7: the wind turbine's rotor at 30 000 rpm turned its planet bearings at 467 000 rpm and its
# high-speed shaft at 3.1e6 rpm (n d_m far beyond any rolling bearing): 'ok' with 2.2e13 W of
# bearing loss against 3.1e8 W of input power. Now out_of_range, naming the bearing.
"$bin" point "$src/configs/wind-turbine-2.5MW.yaml" --speed 30000rpm --torque 1e5Nm > "$tmp/wt.txt" 2> "$tmp/wt.err"
check "F7 wind turbine at 30000 rpm: not ok" bash -c "! grep -q '^status: ok' '$tmp/wt.txt'"
check "F7 wind turbine at 30000 rpm: out_of_range at a bearing's n d_m" \
    grep -qE "out_of_range: bearing [^ ]+ speed .*n d_m .* beyond the rolling-bearing range" "$tmp/wt.txt" "$tmp/wt.err"
check "F7 wind turbine at 30000 rpm: no nan/inf" no_nonfinite "$tmp/wt.txt" "$tmp/wt.err"
"$bin" point "$src/configs/wind-turbine-2.5MW.yaml" --speed 15rpm --torque 1e6Nm > "$tmp/wt15.txt" 2> /dev/null
check "F7 wind turbine at its rated 15 rpm: still ok" grep -q '^status: ok' "$tmp/wt15.txt"
# F8: oil at 1000 degC was 'ok' with the viscosity floored at 0.5 cSt and a density of 292 kg/m^3.
expect "F8 --oil-temp 1000degC" 2 "^gearloss: error: --oil-temp: .*above the data of oil" \
    "$bin" point "$spur" --speed 800rpm --torque 100Nm --oil-temp 1000degC
expect "F8 --oil-temp 150degC still accepted" 0 "" "$bin" point "$spur" --speed 800rpm --torque 100Nm --oil-temp 150degC
"$bin" synth "$spur" -o "$tmp/rec_hot.csv" 2> /dev/null
awk -F, 'NR == 1 { for (i = 1; i <= NF; ++i) if ($i == "oil_temp_C") c = i; print; next } NR == 3 { $c = 900 } { print }' \
    OFS=, "$tmp/rec_hot.csv" > "$tmp/hot.csv"
"$bin" diagnose "$spur" "$tmp/hot.csv" > "$tmp/hot.txt" 2> "$tmp/hot.err"
check "F8 recordings with oil at 900 degC: the row is named as beyond the oil's data" \
    grep -qE "above the data of oil" "$tmp/hot.txt" "$tmp/hot.err"
# M1: an error during the cycle names the CSV file and the line of its row.
expect "M1 cycle error at its row: gear 1 to 200 km/h" 2 "first.csv:[3-6]: cycle: at t = [0-9]+ s .*max_speed" \
    "$bin" cycle "$tmp/man.yaml" --cycle "$tmp/first.csv" --start-temp 20degC
# M2: vehicle data blamed on the key that holds it (was: "oil reaches 367.4 degC", "input speed 52013 rpm").
sed 's/idle_speed: 800 rpm/idle_speed: 8000 rpm/' "$tmp/man.yaml" > "$tmp/idle.yaml"
expect "M2 idle_speed: 8000 rpm" 2 "idle.yaml:[0-9]+:[0-9]+: vehicle\.engine\.idle_speed: .*outside the plausible idle speeds" \
    "$bin" check "$tmp/idle.yaml"
sed 's/wheel_radius: 0.31 m/wheel_radius: 0.31 mm/' "$tmp/man.yaml" > "$tmp/wheel.yaml"
expect "M2 wheel_radius: 0.31 mm" 2 "wheel.yaml:[0-9]+:[0-9]+: vehicle\.wheel_radius: .*outside the range of road-vehicle wheels" \
    "$bin" check "$tmp/wheel.yaml"
# M3: viscosity points at 40 and 40.000001 degC: the fitted law breaks down at the ambient, which
# was blamed (thermal.ambient) instead of the points.
sed 's/- \[70 degC, 36.7 cSt\]/- [40.000001 degC, 36.7 cSt]/; s/- \[100 degC, 16.37 cSt\]//' "$tmp/oils/75W90-A.yaml" \
    > "$tmp/oils/steep.yaml"
expect "M3 viscosity law breaking down inside the range" 2 \
    "steep.yaml:[0-9]+:[0-9]+: viscosity\.points: .*fitted viscosity law gives 1e7 or more mm\^2/s at 0.0 degC" \
    "$bin" check "$tb" --oil "$tmp/oils/steep.yaml"
# M5: the wording list.
expect "M5 --start-temp -100degC (the stated bound: refused only by the oil data)" 2 "below the data of oil" \
    "$bin" cycle "$tmp/man.yaml" --cycle "$tmp/first.csv" --start-temp -100degC
check "M5 --start-temp -100degC: not 'outside the stated range'" bash -c "! grep -q 'outside the stated range' '$tmp/err'"
expect "M5 gearloss mapp" 1 "^gearloss: usage error: unknown command 'mapp'" "$bin" mapp "$spur"
expect "M5 --threads 1.5" 1 "^gearloss: usage error: --threads: .*not a whole number of threads 1 to 1024" \
    "$bin" map "$spur" --threads 1.5 -o "$tmp/t.csv"
sed '0,/teeth: 23/s//teeth: 100000000000/' "$spur" > "$tmp/teeth.yaml"
expect "M5 teeth: 100000000000" 2 "teeth.yaml:[0-9]+:[0-9]+: gears\[0\]\.teeth: whole number '100000000000' out of range" \
    "$bin" check "$tmp/teeth.yaml"
cp "$tmp/oils/75W90-A.yaml" "$tmp/m.csv.meta.json"
expect "M5 sidecar onto an input: the option named once" 2 "^gearloss: error: --output \(its metadata [^)]*\) '[^']*' is the input --oil" \
    "$bin" map "$spur" --speed 800rpm --torque 100Nm -o "$tmp/m.csv" --oil "$tmp/m.csv.meta.json"
expect "M5 --shard ' 1/2'" 2 "^gearloss: error: --shard: ' 1/2' is not K/N" "$bin" map "$spur" --shard ' 1/2' -o "$tmp/sh.csv"

# ---------------------------------------------------------------------------------------
# N3: sizes that no gearbox has, read silently before (a unit slip each); F6: an engine asked
# beyond its fuel map without max_torque, silent before.
cp "$src/configs/automatic-6speed.yaml" "$tmp/auto.yaml"
sed 's/{name: output_seal, shaft: I,   diameter: 40 mm}/{name: output_seal, shaft: I,   diameter: 1 m}/' "$tb" > "$tmp/seal1m.yaml"
expect "a 1 m seal on a 32-35 mm shaft" 2 "seal1m.yaml:[0-9]+:[0-9]+: seals\[1\]\.diameter: seal 'output_seal' of 1000 mm .*check the unit" \
    "$bin" check "$tmp/seal1m.yaml"
sed 's/{name: output_seal, shaft: I,   diameter: 40 mm}/{name: output_seal, shaft: I,   diameter: 90 mm}/' "$tb" > "$tmp/seal90.yaml"
expect "a 90 mm seal beside 80 mm bearings" 0 "seal90.yaml:[0-9]+:[0-9]+: seals\[1\]\.diameter: warning: seal 'output_seal' of 90 mm" \
    "$bin" point "$tmp/seal90.yaml" --speed 800rpm --torque 200Nm --oil-temp 70degC
sed 's/shaft: I,   position: 150 mm, locating: true/shaft: I,   position: -60 km, locating: true/' "$tb" > "$tmp/far.yaml"
expect "a bearing at -60 km" 2 "far.yaml:[0-9]+:[0-9]+: bearings\[5\]\.position: bearing 'B6_6307' .*no shaft is that long" \
    "$bin" check "$tmp/far.yaml"
sed 's/oil_volume: [0-9.]* L/oil_volume: 800 m^3/' "$tb" > "$tmp/sump.yaml"
expect "an 800 m^3 sump" 2 "sump.yaml:[0-9]+:[0-9]+: housing\.oil_volume: oil volume 8e\+05 L is [0-9]+ times the space the gears sweep" \
    "$bin" check "$tmp/sump.yaml"
sed 's/oil_volume: [0-9.]* L/oil_volume: 200 L/' "$tb" > "$tmp/sump200.yaml"
expect "a 200 L sump on 1.4 L of gears" 0 "housing\.oil_volume: warning: oil volume 200 L is 144 times" \
    "$bin" point "$tmp/sump200.yaml" --speed 800rpm --torque 200Nm --oil-temp 70degC
sed 's/torque_ratio: \[2.0,/torque_ratio: [0.2,/' "$tmp/auto.yaml" > "$tmp/tr.yaml"
expect "converter torque ratio 0.2 at stall" 2 "tr.yaml:[0-9]+:[0-9]+: vehicle\.torque_converter\.torque_ratio\[0\]: torque ratio 0.2 at stall" \
    "$bin" check "$tmp/tr.yaml"
sed 's/gears: \[g1, g2, g3, g4, g5, g6\]/gears: [g1, g1, g3, g4, g5, g6]/' "$tmp/man.yaml" > "$tmp/g1g1.yaml"
expect "vehicle.gears [g1, g1, ...]" 2 "g1g1.yaml:[0-9]+:[0-9]+: vehicle\.gears\[1\]: ratio 'g1' is listed twice" \
    "$bin" check "$tmp/g1g1.yaml"
mkdir -p "$tmp/cat"
sed 's/\["K 12x15x20", 12, 15, 20, 8.5, 12\]/["K 12x15x20", 12, 15, 20, 0.1, 5300]/' \
    "$src/configs/bearings/catalogue.yaml" > "$tmp/cat/catalogue.yaml"
sed 's/type: needle_roller, d: 38 mm, D: 43 mm, B: 27 mm, shaft: III, under_gear: w4/designation: K 12x15x20, shaft: III, under_gear: w4/' "$tb" > "$tmp/catrow.yaml"
echo "bearing_catalogue: cat/catalogue.yaml" >> "$tmp/catrow.yaml"
expect "catalogue row C 0.1 kN, C0 5300 kN" 2 "catalogue.yaml:[0-9]+:[0-9]+: .*C0 = 5300 kN against C = 0.1 kN" \
    "$bin" check "$tmp/catrow.yaml"
printf 'time_s,speed_kmh,gear\n0,20,2\n10,20,2\n10.2,20,2\n10.4,23.6,2\n10.6,27.2,2\n10.8,30.8,2\n11,34.4,2\n' > "$tmp/hard.csv"
expect "engine beyond its fuel map without max_torque" 0 "^gearloss: warning: the engine is asked beyond its fuel map \(200 N m\) on [0-9]+ rows? from t = 10.2 s \(line 4\)" \
    "$bin" cycle "$tmp/man.yaml" --cycle "$tmp/hard.csv" --start-temp 80degC --json "$tmp/hard.json"
check "engine beyond its fuel map: in the summary" grep -q "warning: the engine is asked beyond its fuel map" "$tmp/out"
check "engine beyond its fuel map: in --json" grep -q '"engine_beyond_fuel_map":{"rows":' "$tmp/hard.json"

# ---------------------------------------------------------------------------------------
# Every output of every command, for inputs that are accepted though hostile: no nan/inf.
# Oil recorded colder than the ambient (diagnose printed "+/- nan"), a cold oil at the edge of
# its data, the lowest and highest speeds and torques of the stated range.
"$bin" synth "$spur" -o "$tmp/rec.csv" 2> /dev/null
awk -F, 'NR == 1 { print; next } { $4 = 10; print }' OFS=, "$tmp/rec.csv" > "$tmp/cold.csv"
runs=(
    "map|$spur --speed 1,10,6000rpm --torque 0,1,2000Nm -o $tmp/o/map.csv --json $tmp/o/map.json"
    "map|$spur --detail --oil-temp -20degC --speed 1,6000rpm --torque 0,500Nm -o $tmp/o/cold.csv"
    "check|$spur --json"
    "check|$tb --oil-temp -30degC"
    "point|$spur --speed 1rpm --torque 0Nm --json $tmp/o/point.json"
    "point|$spur --speed 6000rpm --torque 2000Nm --oil-temp 150degC"
    "report|$spur --speed 100,3000rpm --torque 10,400Nm --no-spread -o $tmp/o/report.html"
    "compare|$tb --oil $src/configs/oils/75W90-A.yaml --oil $src/configs/oils/75W140-A.yaml --speed 10,3000rpm --torque 0,500Nm --detail -o $tmp/o/compare.csv --json $tmp/o/compare.json"
    "cycle|$tmp/man.yaml --cycle nedc --start-temp -30degC -o $tmp/o/cycle.csv --json $tmp/o/cycle.json"
    "diagnose|$spur $tmp/cold.csv --bootstrap 4 --json $tmp/o/diagnose.json --residuals $tmp/o/residuals.csv"
    "mesh-profile|$spur --mesh m --speed 800rpm --torque 200Nm --oil-temp 70degC"
)
mkdir -p "$tmp/o"
i=0
for r in "${runs[@]}"; do
    i=$((i + 1))
    cmd=${r%%|*}
    # shellcheck disable=SC2086
    $T "$bin" $cmd ${r#*|} > "$tmp/o/stdout_$i.txt" 2> "$tmp/o/stderr_$i.txt"
    rc=$?
    check "scan $cmd #$i: exit 0 (got $rc)" test $rc -eq 0
done
check "diagnose of oil colder than the ambient: no '+/- nan'" bash -c "! grep -q '+/- nan' '$tmp/o/stdout_10.txt'"
for f in "$tmp"/o/*; do
    check "no nan/inf in $(basename "$f")" no_nonfinite "$f"
done
check "the scan covered every output (CSV, sidecars, JSON, HTML)" \
    test "$(ls "$tmp"/o/*.meta.json 2> /dev/null | wc -l)" -ge 3 -a -s "$tmp/o/report.html" -a -s "$tmp/o/diagnose.json"

echo "$pass passed, $fail failed"
test $fail -eq 0
