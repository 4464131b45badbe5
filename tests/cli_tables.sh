#!/usr/bin/env bash
# gearloss map --format table / co2mpas (docs/tables.md): the shape of the long CSV and of the
# lookup arrays, values against single-point runs of `gearloss map` (another route: the csv
# format with --oil-temp, --ratio, --speed, --torque), total = sum of mechanisms, the CO2MPAS
# fit error recomputed from the table's CSV, and hostile inputs.
# Usage: cli_tables.sh GEARLOSS_BINARY SOURCE_DIR
source "$(dirname "$0")/cli_common.sh" "$@"
py=/usr/bin/python3
cp -r "$src/configs" "$tmp/cfg"
case=$tmp/cfg/manual-6speed.yaml

# 1. Shape: 6 ratios x 3 speeds x 7 torques (3 magnitudes, both signs, 0) x 4 temperatures.
expect "table" 0 "" "$bin" map "$case" --format table --speed 1000,2500,4000rpm --torque 30,90,180Nm \
    --oil-temps 20,50,80,110degC -o "$tmp/t.csv" --json "$tmp/t.json"
check "table: rows = 6 x 3 x 7 x 4 + header" test "$(wc -l < "$tmp/t.csv")" -eq $((6 * 3 * 7 * 4 + 1))
check "table: header" grep -q '^ratio,ratio_value,speed_in_rpm,torque_in_Nm,oil_temp_C,torque_loss_Nm,P_total_W,P_mesh_W,.*,efficiency,status$' "$tmp/t.csv"
check "table: overrun rows" grep -q '^g1,[^,]*,1000,-180,20.00,' "$tmp/t.csv"
check "table: drive rows" grep -q '^g6,[^,]*,4000,180,110.00,' "$tmp/t.csv"
check "table and arrays agree, total = sum of mechanisms" "$py" - "$tmp/t.csv" "$tmp/t.json" <<'PY'
import json, sys
import pandas as pd
d = pd.read_csv(sys.argv[1])
j = json.load(open(sys.argv[2]))
bp, tab = j["breakpoints"], j["tables"]
dims = [len(bp["ratio"]), len(bp["speed_in_rpm"]), len(bp["torque_in_Nm"]), len(bp["oil_temp_C"])]
assert dims == [6, 3, 7, 4], dims
assert j["index_order"] == ["ratio", "speed_in_rpm", "torque_in_Nm", "oil_temp_C"]
mech = [c for c in d.columns if c.startswith("P_") and c != "P_total_W"]
assert set(tab) == {"torque_loss_Nm", "P_total_W", *mech}, sorted(tab)
for name, a in tab.items():
    shape, x = [], a
    while isinstance(x, list):
        shape.append(len(x)); x = x[0]
    assert shape == dims, (name, shape)
assert (d.status == "ok").all()
assert ((d[mech].sum(axis=1) - d.P_total_W).abs() <= 1e-5 * d.P_total_W.abs() + 1e-3).all()
assert (d.torque_in_Nm < 0).sum() == (d.torque_in_Nm > 0).sum() == 6 * 3 * 3 * 4
for _, r in d.iterrows():
    i = (bp["ratio"].index(r.ratio), bp["speed_in_rpm"].index(r.speed_in_rpm),
         bp["torque_in_Nm"].index(r.torque_in_Nm), bp["oil_temp_C"].index(r.oil_temp_C))
    for c in ["P_total_W", "torque_loss_Nm", *mech]:
        v = tab[c][i[0]][i[1]][i[2]][i[3]]
        assert abs(v - r[c]) <= 1e-5 * abs(v) + 1e-3, (c, i, v, r[c])
PY

# 2. Values against `gearloss map` run at single points (the csv format's own route).
for point in "g1 1000 -180 20" "g3 2500 90 50" "g6 4000 180 110" "g4 1000 0 80" "g2 4000 -30 110"; do
    set -- $point
    "$bin" map "$case" --ratio "$1" --oil-temp "$4degC" --speed "$2rpm" --torque="$3Nm" > "$tmp/one.csv"
    check "point $point: as gearloss map gives it" "$py" - "$tmp/t.csv" "$tmp/one.csv" "$1" "$2" "$3" "$4" <<'PY'
import sys
import pandas as pd
t, one = pd.read_csv(sys.argv[1]), pd.read_csv(sys.argv[2])
ratio, n, T, oil = sys.argv[3], float(sys.argv[4]), float(sys.argv[5]), float(sys.argv[6])
row = t[(t.ratio == ratio) & (t.speed_in_rpm == n) & (t.torque_in_Nm == T) & (t.oil_temp_C == oil)]
assert len(row) == 1 and len(one) == 1
row, one = row.iloc[0], one.iloc[0]
for c in [c for c in one.index if c.startswith("P_")] + ["efficiency"]:
    if pd.isna(one[c]):
        assert pd.isna(row[c]), c
    else:
        assert abs(row[c] - one[c]) <= 1e-5 * abs(one[c]) + 1e-9, (c, row[c], one[c])
assert abs(row.torque_loss_Nm - one.P_total_W / (n * 3.141592653589793 / 30)) <= 1e-5 * row.torque_loss_Nm
PY
done

# 3. The CO2MPAS fit: its reported error is the error of its coefficients recomputed from the
# table's CSV at the two reference temperatures (CO2MPAS's form written again here, JRC 2019).
expect "co2mpas" 0 "" "$bin" map "$case" --format co2mpas --speed 1000,2500,4000rpm --torque 30,90,180Nm -o "$tmp/c.json"
expect "table at the references" 0 "" "$bin" map "$case" --format table --speed 1000,2500,4000rpm --torque 30,90,180Nm \
    --oil-temps 40,80degC -o "$tmp/ref.csv"
check "co2mpas: errors recomputed from the CSV" "$py" - "$tmp/ref.csv" "$tmp/c.json" <<'PY'
import json, math, sys
import pandas as pd
d, j = pd.read_csv(sys.argv[1]), json.load(open(sys.argv[2]))
assert j["gear_box_temperature_references"] == [40.0, 80.0]
def torque_in(p, r):
    n_in, k = r.speed_in_rpm, abs(r.ratio_value)
    w_in = n_in * math.pi / 30
    P_out = r.torque_in_Nm * w_in - r.P_total_W
    if P_out >= 0:
        return (P_out / w_in - p["gbp10"] * n_in - p["gbp00"]) / p["gbp01"]
    n_out = k * n_in
    return (p["gbp01"] * P_out / (k * w_in) - p["gbp10"] * n_out - p["gbp00"]) * n_out / n_in
def errors(p, rows):
    e = [abs(torque_in(p, r) - r.torque_in_Nm) for r in rows.itertuples()]
    rel = [x / r.torque_loss_Nm for x, r in zip(e, rows.itertuples())]
    return {"points": len(e), "rms_Nm": math.sqrt(sum(x * x for x in e) / len(e)), "max_Nm": max(e),
            "rms_rel": math.sqrt(sum(x * x for x in rel) / len(rel)), "max_rel": max(rel)}
def same(a, b):  # within the CSV's 6 significant digits of P_total_W
    for k in b:
        assert abs(a[k] - b[k]) <= 1e-5 * abs(b[k]) + 1e-4, (k, a[k], b[k])
for phase, T in (("cold", 40.0), ("hot", 80.0)):
    at = d[d.oil_temp_C == T]
    same(errors(j["gear_box_efficiency_parameters_cold_hot"][phase], at), j["fit_error"][phase]["all"])
    for g in j["gears"]:
        rows = at[at.ratio == g["ratio"]]
        same(errors(g["gear_box_efficiency_parameters_cold_hot"][phase], rows), g["fit_error"][phase])
        same(errors(j["gear_box_efficiency_parameters_cold_hot"][phase], rows), j["fit_error"][phase][g["ratio"]])
        p = g["gear_box_efficiency_parameters_cold_hot"][phase]
        assert p["gbp00"] < 0 and 0.9 < p["gbp01"] <= 1, p   # a loss, as CO2MPAS's defaults
PY

# 4. Defaults: every ratio, the case's grid, 20 degC to the oil's limit (75W90-A: 110 degC).
expect "table defaults" 0 "" "$bin" map "$case" --format table -o "$tmp/d.csv"
check "table defaults: temperatures 20..100 in 20 K and 110" test "$(cut -d, -f5 "$tmp/d.csv" | sort -u | sort -n | tr "\n" " ")" = "oil_temp_C 20.00 40.00 60.00 80.00 100.00 110.00 "
check "table --ratio: one ratio" test "$("$bin" map "$case" --format table --ratio g2 --oil-temp 70degC | cut -d, -f1,5 | sort -u | wc -l)" -eq 2

# 5. Hostile inputs: nothing written, exit 2 with a message naming the option.
for bad in "20,40" "40,20degC" "20,,40degC" "20,40rpm" "hot" "5000degC"; do
    expect "--oil-temps '$bad'" 2 "--oil-temps" "$bin" map "$case" --format table --oil-temps "$bad" -o "$tmp/bad.csv"
done
expect "co2mpas with three temperatures" 2 "exactly two" "$bin" map "$case" --format co2mpas --oil-temps 20,40,80degC -o "$tmp/bad.csv"
expect "co2mpas with --oil-temp" 2 "--oil-temp" "$bin" map "$case" --format co2mpas --oil-temp 80degC -o "$tmp/bad.csv"
expect "--oil-temps and --oil-temp" 2 "not both" "$bin" map "$case" --format table --oil-temps 40,80degC --oil-temp 80degC -o "$tmp/bad.csv"
expect "--oil-temps with --format csv" 2 "--oil-temps" "$bin" map "$case" --oil-temps 40,80degC -o "$tmp/bad.csv"
for opt in "--shard 1/2" "--spread" "--detail"; do
    expect "table $opt" 2 "${opt%% *}" "$bin" map "$case" --format table $opt -o "$tmp/bad.csv"
done
expect "co2mpas --json" 2 "--json" "$bin" map "$case" --format co2mpas --json "$tmp/bad.json" -o "$tmp/bad.csv"
cp "$case" "$tmp/cfg/sweep.yaml"
printf '\nsweep:\n  - {parameter: housing.oil_level, values: [-30 mm, -10 mm]}\n' >> "$tmp/cfg/sweep.yaml"
# The location is the section's content: the line of the key or one of the two after it.
near() { echo "($1|$(($1 + 1))|$(($1 + 2)))"; }
line=$(near "$(grep -n '^sweep:' "$tmp/cfg/sweep.yaml" | cut -d: -f1)")
expect "table of a sweep case" 2 "sweep.yaml:$line:[0-9]+: sweep: --format table" "$bin" map "$tmp/cfg/sweep.yaml" --format table -o "$tmp/bad.csv"
expect "co2mpas of a sweep case" 2 "sweep.yaml:$line:[0-9]+: sweep: --format co2mpas" "$bin" map "$tmp/cfg/sweep.yaml" --format co2mpas -o "$tmp/bad.csv"
line=$(near "$(grep -n '^operating:' "$tmp/cfg/wind-turbine-2.5MW.yaml" | cut -d: -f1)")
expect "table of a point-list case" 2 "wind-turbine-2.5MW.yaml:$line:[0-9]+: operating: .*grid" "$bin" map "$tmp/cfg/wind-turbine-2.5MW.yaml" --format table -o "$tmp/bad.csv"
check "hostile inputs: nothing written" test ! -e "$tmp/bad.csv" -a ! -e "$tmp/bad.json"
cp "$case" "$tmp/keep.yaml"
expect "table onto its case" 2 "config" "$bin" map "$case" --format table -o "$case"
expect "arrays onto the oil file" 2 "oil" "$bin" map "$case" --format table -o "$tmp/x.csv" --json "$tmp/cfg/oils/75W90-A.yaml"
check "the case is unchanged" cmp -s "$case" "$tmp/keep.yaml"
expect "a point list with --speed only" 0 "" "$bin" map "$case" --format table --speed 1500rpm --oil-temp 60degC -o "$tmp/pl.csv"

# 6. Size: 6 ratios x 30 speeds x 61 torques (30 magnitudes, both signs, 0) x 6 temperatures in seconds.
speeds=$(seq -s, 500 150 4850)rpm
torques=$(seq -s, 6 6 180)Nm
start=$(date +%s.%N)
expect "large table" 0 "" "$bin" map "$case" --format table --speed "$speeds" --torque "$torques" -o "$tmp/big.csv" --json "$tmp/big.json"
secs=$(echo "$(date +%s.%N) - $start" | bc)
echo "table of $(($(wc -l < "$tmp/big.csv") - 1)) points (csv $(wc -c < "$tmp/big.csv") bytes, json $(wc -c < "$tmp/big.json") bytes): $secs s"
check "large table: rows" test "$(wc -l < "$tmp/big.csv")" -eq $((6 * 30 * 61 * 6 + 1))
check "large table: under 120 s" test "$(echo "$secs < 120" | bc)" -eq 1

echo "$pass passed, $fail failed"
test $fail -eq 0
