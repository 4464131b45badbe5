#!/usr/bin/env bash
# gearloss duty (docs/duty.md) and an electric drive over a drive cycle (vehicle.motor): the duty's
# energy against independent single-point `gearloss map` runs, a hand-worked energy-weighted
# efficiency, a constant time series against the map's stabilised temperature, the energy
# balance of the EV reducer over a short cycle against a road load computed here, and bad spectra.
# Usage: cli_duty.sh GEARLOSS_BINARY SOURCE_DIR
source "$(dirname "$0")/cli_common.sh" "$@"
py=/usr/bin/python3
case=$src/configs/transfer-box.yaml

# 1. Energy = sum over bins of (single-point map loss x duration), the map run once per bin at the
# oil temperature the duty used for it (its stabilised one), negative torque included.
cat > "$tmp/level.csv" <<'CSV'
speed_in_rpm,torque_in_Nm,hours
800,250,10
600,100,5
800,-150,2
700,0,1
CSV
expect "time at level" 0 "" "$bin" duty "$case" "$tmp/level.csv" -o "$tmp/level_out.csv" --json "$tmp/level.json"
check "time at level: sidecar" test -s "$tmp/level_out.csv.meta.json"
sum=0
while IFS=, read -r n T h; do
    [ "$n" = speed_in_rpm ] && continue
    "$bin" map "$case" --speed "${n}rpm" --torque "${T}Nm" -o "$tmp/p.csv" 2> /dev/null
    # P_total_W is column 14 of a map row; energy in kWh = W x h / 1000.
    sum=$(awk -F, -v h="$h" -v s="$sum" 'NR == 2 { printf "%.9g", s + $14 * h / 1000 }' "$tmp/p.csv")
done < "$tmp/level.csv"
check "time at level: energy = sum of single-point maps x hours ($sum kWh)" "$py" - "$tmp/level.json" "$sum" <<'PY'
import json, sys
j = json.load(open(sys.argv[1]))
want = float(sys.argv[2])
assert abs(j["energy_loss_kWh"] - want) <= 1e-5 * want, (j["energy_loss_kWh"], want)
assert abs(sum(j["energy_loss_by_mechanism_kWh"].values()) - want) <= 1e-5 * want
assert j["duration_h"] == 18 and j["bins_above_oil_limit"] == 0, j
PY

# 2. Energy-weighted efficiency of two bins by hand, at --oil-temp 80degC. `gearloss map
# configs/transfer-box.yaml --speed 800rpm --torque 250Nm,-150Nm --oil-temp 80degC` gives the
# losses L1 = 522.063 W (drive) and L2 = 309.274 W (driven from the output).
#   bin 1, 3 h: P1 = 250 N m x 83.776 rad/s = 20943.95 W enters at the input, P1 - L1 leaves
#   bin 2, 1 h: |P2| = 150 x 83.776 = 12566.37 W leaves at the input, |P2| + L2 enters at the output
#   supplied  = 3 x 20943.95 + 1 x (12566.37 + 309.274) = 75707.50 Wh
#   delivered = 3 x (20943.95 - 522.063) + 1 x 12566.37   = 73832.03 Wh
#   eta = 73832.03 / 75707.50 = 0.975228 (the mean of the bins' efficiencies weighted by time,
#   (3 x 0.975073 + 0.975980) / 4 = 0.975300, is not it)
printf 'speed_in_rpm,torque_in_Nm,duration_h\n800,250,3\n800,-150,1\n' > "$tmp/two.csv"
expect "two bins" 0 "" "$bin" duty "$case" "$tmp/two.csv" --oil-temp 80degC --json "$tmp/two.json"
check "two bins: energy-weighted efficiency 0.975228 by hand" "$py" - "$tmp/two.json" <<'PY'
import json, sys
j = json.load(open(sys.argv[1]))
assert abs(j["efficiency"] - 0.975228) < 2e-6, j["efficiency"]
assert abs(j["energy_supplied_kWh"] - 75.7075) < 1e-3, j
PY
# Shares: the same spectrum as 75 % / 25 % of 4 h gives the same numbers.
printf 'speed_in_rpm,torque_in_Nm,share_%%\n800,250,75\n800,-150,25\n' > "$tmp/share.csv"
expect "shares" 0 "" "$bin" duty "$case" "$tmp/share.csv" --oil-temp 80degC --total-time 4h --json "$tmp/share.json"
check "shares = durations" "$py" -c "import json,sys; a=json.load(open('$tmp/two.json')); b=json.load(open('$tmp/share.json')); assert abs(a['efficiency']-b['efficiency'])<1e-12 and abs(a['energy_loss_kWh']-b['energy_loss_kWh'])<1e-9"

# 3. A constant time series long enough (10 h, time constant ~ 50 min) ends at the map's
# stabilised oil temperature, from a cold start and from a hot one.
"$py" -c "
print('time_s,speed_in_rpm,torque_in_Nm')
for i in range(0, 36001, 60): print(f'{i},700,200')" > "$tmp/series.csv"
"$bin" map "$case" --speed 700rpm --torque 200Nm -o "$tmp/p.csv" 2> /dev/null
T_map=$(awk -F, 'NR == 2 { print $5 }' "$tmp/p.csv")
for start in 20degC 105degC; do
    expect "series from $start" 0 "" "$bin" duty "$case" "$tmp/series.csv" --start-temp $start --json "$tmp/s.json" -o "$tmp/s.csv"
    check "series from $start: ends at the map's stabilised $T_map degC (0.05 K); energy balance" "$py" - "$tmp/s.json" "$T_map" <<'PY'
import json, sys
j = json.load(open(sys.argv[1]))
assert abs(j["oil_temp_end_C"] - float(sys.argv[2])) < 0.05, (j["oil_temp_end_C"], sys.argv[2])
# The loss goes to the ambient or into the stored heat.
assert abs(j["energy_loss_kWh"] - j["heat_to_ambient_kWh"] - j["heat_stored_kWh"]) < 1e-4 * j["energy_loss_kWh"], j
PY
done

# 4. The EV reducer over a short cycle: 0 -> 50 km/h in 10 s, 20 s at 50 km/h, back to 0 in 10 s
# (recuperation). The output energy in drive equals the road-load work computed here (final drive
# efficiency 1), the losses are positive in both directions, and the two shafts balance:
# E_in + E_out,supplied = E_out + E_in,recovered + E_loss.
"$py" -c "
print('time_s,speed_kmh')
for t in range(0, 41):
    v = 5 * t if t <= 10 else 50 if t <= 30 else 50 - 5 * (t - 30)
    print(f'{t},{v}')" > "$tmp/ev_cycle.csv"
expect "ev-reducer: check" 0 "" "$bin" check "$src/configs/ev-reducer.yaml"
expect "ev-reducer: map" 0 "" "$bin" map "$src/configs/ev-reducer.yaml" -o "$tmp/ev_map.csv"
check "ev-reducer: map, recuperation rows solved" grep -q '^1000,-150,.*,ok$' "$tmp/ev_map.csv"
expect "ev-reducer: cycle" 0 "" "$bin" cycle "$src/configs/ev-reducer.yaml" --cycle "$tmp/ev_cycle.csv" --start-temp 20degC \
    --json "$tmp/ev.json"
check "ev-reducer: road-load work, positive losses, energy balance" "$py" - "$tmp/ev.json" "$tmp/ev_cycle.csv" <<'PY'
import csv, json, sys
s = json.load(open(sys.argv[1]))["start"]
rows = list(csv.DictReader(open(sys.argv[2])))
# configs/ev-reducer.yaml: m = 1800 kg, e = 0.04, f0 = 140 N, f1 = 0.6 N/(km/h), f2 = 0.03 N h^2/km^2;
# each 1-s step at its mean speed and constant acceleration; drive steps count.
m, e, f0, f1, f2 = 1800, 0.04, 140, 0.6 * 3.6, 0.03 * 3.6 ** 2
work = 0.0
for a, b in zip(rows, rows[1:]):
    v0, v1 = float(a["speed_kmh"]) / 3.6, float(b["speed_kmh"]) / 3.6
    v = (v0 + v1) / 2
    F = (f0 if v > 0 else 0) + f1 * v + f2 * v * v + m * (1 + e) * (v1 - v0)
    if F * v > 0:
        work += F * v
assert abs(s["gearbox_output_kJ"] - work / 1e3) < 1e-6 * work, (s["gearbox_output_kJ"], work / 1e3)
assert s["recuperation_input_recovered_kJ"] > 0 and s["recuperation_output_supplied_kJ"] > s["recuperation_input_recovered_kJ"]
assert all(s[k] >= 0 for k in ("mesh_kJ", "churning_kJ", "bearings_kJ", "seals_kJ")) and s["gearbox_loss_kJ"] > 0
lhs = s["gearbox_input_kJ"] + s["recuperation_output_supplied_kJ"]
rhs = s["gearbox_output_kJ"] + s["recuperation_input_recovered_kJ"] + s["gearbox_loss_kJ"]
assert abs(lhs - rhs) < 0.005 * s["gearbox_loss_kJ"], (lhs, rhs, s["gearbox_loss_kJ"])
PY
# The motor's envelope: 310 N m cannot take the car to 50 km/h in 1 s.
printf 'time_s,speed_kmh\n0,0\n1,30\n2,30\n' > "$tmp/ev_hard.csv"
expect "ev-reducer: beyond the motor's torque" 2 "ev_hard.csv:2:.*motor torque [0-9]+ N m above the motor's limit 310 N m" \
    "$bin" cycle "$src/configs/ev-reducer.yaml" --cycle "$tmp/ev_hard.csv" --start-temp 20degC
# An engine and a motor together, or a motor and a torque converter, are refused at their line.
cp -r "$src/configs" "$tmp/cfg"
sed 's/^  motor: .*/  engine: {idle_speed: 800 rpm}\n  motor:/' "$src/configs/ev-reducer.yaml" > "$tmp/cfg/both.yaml"
expect "engine and motor" 2 "both.yaml:[0-9]+:[0-9]+: vehicle.motor: give either an engine or a motor" "$bin" check "$tmp/cfg/both.yaml"
sed 's/^  motor: .*/  torque_converter: {speed_ratio: [0, 1], torque_ratio: [2, 1], capacity: [120, 200]}\n  motor:/' \
    "$src/configs/ev-reducer.yaml" > "$tmp/cfg/tc.yaml"
expect "motor and converter" 2 "tc.yaml:[0-9]+:[0-9]+: vehicle.torque_converter: an electric motor drives without" "$bin" check "$tmp/cfg/tc.yaml"

# 5. Bad spectra: clean errors naming file:line:column.
bad() {  # bad NAME REGEX CSV-TEXT [options]
    local name=$1 pattern=$2 text=$3
    shift 3
    printf "$text" > "$tmp/bad.csv"
    expect "bad spectrum: $name" 2 "bad.csv:$pattern" "$bin" duty "$case" "$tmp/bad.csv" "$@"
}
bad "times backwards" "4:1: time_s: time 10 s does not increase" 'time_s,speed_in_rpm,torque_in_Nm\n0,700,200\n20,700,200\n10,700,200\n'
bad "a gap" "6:1: time_s: a gap of 1000 s after line 5" 'time_s,speed_in_rpm,torque_in_Nm\n0,700,200\n10,700,200\n20,700,200\n30,700,200\n1030,700,200\n'
bad "shares summing to 0" "3:3: share: the shares of the bins sum to 0" 'speed_in_rpm,torque_in_Nm,share\n700,200,0\n800,200,0\n'
bad "hours summing to 0" "2:3: hours: the durations of the bins sum to 0" 'speed_in_rpm,torque_in_Nm,hours\n700,200,0\n'
bad "negative hours" "3:3: hours: duration -2: a bin's time cannot be negative" 'speed_in_rpm,torque_in_Nm,hours\n700,200,1\n800,200,-2\n'
bad "speed beyond the grid" "3:1: speed_in_rpm: 1500 rpm beyond the case's operating range \\(its grid reaches 800 rpm\\)" 'speed_in_rpm,torque_in_Nm,hours\n700,200,1\n1500,200,1\n'
bad "NaN" "2:2: torque_in_Nm: 'nan' is out of range" 'speed_in_rpm,torque_in_Nm,hours\n700,nan,1\n'
bad "not a number" "2:3: hours: 'x' is not a number" 'speed_in_rpm,torque_in_Nm,hours\n700,200,x\n'
bad "unit of the wrong kind" "1:2: torque_in_kW: unit 'kW' is not" 'speed_in_rpm,torque_in_kW,hours\n700,200,1\n'
bad "two kinds" "1: .*both a time column and a bin's duration" 'time_s,speed_in_rpm,torque_in_Nm,hours\n0,700,200,1\n'
bad "no speed" "1: .*no speed_in_<unit> column" 'torque_in_Nm,hours\n200,1\n'
bad "one sample" "2: .*at least two samples" 'time_s,speed_in_rpm,torque_in_Nm\n0,700,200\n'
expect "--start-temp on a time-at-level spectrum" 2 "--start-temp" "$bin" duty "$case" "$tmp/level.csv" --start-temp 20degC
expect "--total-time on a time series" 2 "--total-time" "$bin" duty "$case" "$tmp/series.csv" --total-time 2h
expect "output onto the spectrum" 2 "--output .* is the input spectrum" "$bin" duty "$case" "$tmp/level.csv" -o "$tmp/level.csv"
check "spectrum unharmed" grep -q '^800,-150,2$' "$tmp/level.csv"

echo "$pass passed, $fail failed"
test $fail -eq 0
