#!/usr/bin/env bash
# gearloss rating: the thermal power limit curve checked by an independent map of its points,
# the cooler duty table, the outputs (CSV, sidecar, JSON) and the refusals.
# Usage: cli_rating.sh GEARLOSS_BINARY SOURCE_DIR
source "$(dirname "$0")/cli_common.sh" "$@"
cfg=$src/configs/transfer-box.yaml

# The limit curve at 95 degC: each speed's torque, mapped with `gearloss map` at that torque,
# stabilises the oil at 95 degC within 0.1 K.
"$bin" rating "$cfg" --oil-limit 95degC -o "$tmp/r.csv" --json "$tmp/r.json" > "$tmp/r.txt"
check "rating: exit 0" test $? -eq 0
check "rating: header" grep -q '^speed_in_rpm,rating,torque_in_Nm,power_in_W,oil_temp_C,P_loss_W,P_mesh_W,.*,housing_heat_W,cooler_heat_W,efficiency,status$' "$tmp/r.csv"
check "rating: sidecar" test -s "$tmp/r.csv.meta.json"
check "rating: text names the limit" grep -q 'kW at' "$tmp/r.txt"
check "rating: json" python3 -c "import json,sys; j=json.load(open(sys.argv[1])); assert len(j['curve'])==3 and j['oil_limit_C']==95" "$tmp/r.json"
n=0
while IFS=, read -r speed rating torque rest; do
    [ "$speed" = speed_in_rpm ] && continue
    check "rating $speed rpm: a limit" test "$rating" = limit
    "$bin" map "$cfg" --speed "${speed}rpm" --torque "${torque}Nm" -o "$tmp/m.csv" 2> /dev/null
    T=$(python3 -c "import csv,sys; print(next(csv.DictReader(open(sys.argv[1])))['oil_temp_C'])" "$tmp/m.csv")
    check "rating $speed rpm: mapped at $torque N m the oil is at 95 degC (got $T)" \
        python3 -c "import sys; assert abs(float(sys.argv[1]) - 95.0) < 0.1" "$T"
    n=$((n + 1))
done < "$tmp/r.csv"
check "rating: three speeds checked" test $n -eq 3

# The cooler duty at 60 degC: one row per grid point, a duty of at least 0, and mapped with that
# duty as the case's cooler, the oil stabilises at 60 degC.
"$bin" rating "$cfg" --target-oil-temp 60degC -o "$tmp/d.csv" > /dev/null
check "duty: exit 0" test $? -eq 0
check "duty: nine grid points" test "$(tail -n +2 "$tmp/d.csv" | wc -l)" -eq 9
read -r speed torque duty < <(python3 -c "
import csv,sys
r=list(csv.DictReader(open(sys.argv[1])))[-1]
print(r['speed_in_rpm'], r['torque_in_Nm'], r['cooler_duty_W'])" "$tmp/d.csv")
sed "s|^  heat_rejection:|  cooler: {duty: ${duty} W}\n  heat_rejection:|; s|^oil: oils/|oil: $src/configs/oils/|" "$cfg" > "$tmp/cooled.yaml"
"$bin" map "$tmp/cooled.yaml" --speed "${speed}rpm" --torque "${torque}Nm" -o "$tmp/c.csv" 2> /dev/null
T=$(python3 -c "import csv,sys; print(next(csv.DictReader(open(sys.argv[1])))['oil_temp_C'])" "$tmp/c.csv")
check "duty: the case with a ${duty} W cooler stabilises at 60 degC (got $T)" \
    python3 -c "import sys; assert abs(float(sys.argv[1]) - 60.0) < 0.1" "$T"

# Refusals: a fixed-temperature case has no thermal rating; a limit below the ambient; a bad cooler.
sed "s|^  mode: stabilised|  mode: fixed\n  oil_temperature: 80 degC|; s|^oil: oils/|oil: $src/configs/oils/|" "$cfg" > "$tmp/fixed.yaml"
expect "fixed case" 2 "stabilised" "$bin" rating "$tmp/fixed.yaml"
expect "limit below ambient" 2 "above the ambient" "$bin" rating "$cfg" --oil-limit 10degC
sed "s|^  heat_rejection:|  cooler: {oil_flow: 10 L/min}\n  heat_rejection:|; s|^oil: oils/|oil: $src/configs/oils/|" "$cfg" > "$tmp/bad.yaml"
expect "cooler without inlet" 2 "inlet_temperature" "$bin" map "$tmp/bad.yaml"

echo "cli_rating: $pass passed, $fail failed"
[ "$fail" -eq 0 ]
