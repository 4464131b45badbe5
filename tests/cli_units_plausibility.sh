#!/usr/bin/env bash
# End-to-end checks of rotational speed units, tips/contact-ratio reporting and the
# plausibility findings on the command line (black-box, from the specification).
# Usage: cli_units_plausibility.sh GEARLOSS_BINARY SOURCE_DIR
# Every file is written inside a private mktemp -d directory.
set -u
source "$(dirname "$0")/cli_common.sh" "$@"
# Private copies of the shipped cases, with their oils next to them (relative oil paths).
cp -r "$src/configs/oils" "$tmp/oils"
cp "$src/configs/transfer-box.yaml" "$tmp/tb.yaml"
cp "$src/configs/fzg-c40-paor.yaml" "$tmp/fzg.yaml"
tb=$tmp/tb.yaml
py=/usr/bin/python3

# ---------------------------------------------------------------------------------------
# 1. Rotational speeds on the command line. 10 Hz = 10 rev/s = 600 rev/min; 62.8319 rad/s
#    = 62.8319 * 60 / (2 pi) = 600.0003 rpm; 3600 deg/s = 10 rev/s; 0.01 kHz = 10 Hz.
"$bin" point "$tb" --speed 600rpm --torque 100Nm --oil-temp 70degC > "$tmp/p_rpm.txt"
check "point 600rpm exit 0" test $? -eq 0
check "point 600rpm prints 600.00 rpm" grep -q '^input  *600\.00 rpm' "$tmp/p_rpm.txt"
i=0
for s in 10Hz "600 1/min" 600min^-1 600rev/min 10rev/s 3600deg/s 0.01kHz; do
    i=$((i + 1))
    "$bin" point "$tb" --speed "$s" --torque 100Nm --oil-temp 70degC > "$tmp/p_$i.txt" 2> "$tmp/p_$i.err"
    check "point --speed '$s' exit 0" test $? -eq 0
    check "point --speed '$s' = 600 rpm (whole report)" cmp -s "$tmp/p_rpm.txt" "$tmp/p_$i.txt"
done
"$bin" point "$tb" --speed 62.8319rad/s --torque 100Nm --oil-temp 70degC > "$tmp/p_rad.txt"
check "point --speed 62.8319rad/s exit 0" test $? -eq 0
check "point --speed 62.8319rad/s = 600.00 rpm" grep -q '^input  *600\.00 rpm' "$tmp/p_rad.txt"

# A bare 1/s is ambiguous: exit 2, a message naming --speed and suggesting rad/s or Hz.
i=0
for s in 10/s "10 1/s" 10s^-1 "10 s^-1"; do
    i=$((i + 1))
    "$bin" point "$tb" --speed "$s" --torque 100Nm --oil-temp 70degC > /dev/null 2> "$tmp/bad_$i.err"
    check "point --speed '$s' exit 2" test $? -eq 2
    check "point --speed '$s' names --speed" grep -q -- '--speed' "$tmp/bad_$i.err"
    check "point --speed '$s' suggests rad/s and Hz" bash -c "grep -q 'rad/s' '$tmp/bad_$i.err' && grep -q 'Hz' '$tmp/bad_$i.err'"
done

# Lists on map: "10,20Hz" = 600, 1200 rpm; "600,700 1/min" and "600,700min^-1" = 600, 700 rpm.
i=0
for s in "10,20Hz" "600,1200rpm" "600 1/min, 1200 1/min" "600,1200min^-1" "600,1200 1/min"; do
    i=$((i + 1))
    "$bin" map "$tb" --speed "$s" --torque 100Nm --oil-temp 70degC -o "$tmp/ml_$i.csv" 2> "$tmp/ml_$i.err"
    check "map --speed '$s' exit 0" test $? -eq 0
    check "map --speed '$s' rows 600, 1200 rpm" \
        bash -c "[ \"\$(cut -d, -f1 '$tmp/ml_$i.csv' 2>/dev/null | tail -n +2 | tr '\n' ' ')\" = '600 1200 ' ]"
done
"$bin" map "$tb" --speed "10,20/s" --torque 100Nm --oil-temp 70degC -o "$tmp/ml_bad.csv" 2> "$tmp/ml_bad.err"
check "map --speed '10,20/s' exit 2" test $? -eq 2
check "map --speed '10,20/s' suggests rad/s and Hz" bash -c "grep -q 'rad/s' '$tmp/ml_bad.err' && grep -q 'Hz' '$tmp/ml_bad.err'"
check "map --speed '10,20/s' leaves no file" test ! -e "$tmp/ml_bad.csv"

# ---------------------------------------------------------------------------------------
# 1b. Recordings headers. The same campaign in rpm, Hz (n/60), 1/min, rad/s (n 2 pi/60),
#     with P_loss in kW (/1000) and the oil temperature in K (+273.15).
"$bin" synth "$src/configs/transfer-box.yaml" --seed 1 -o "$tmp/rec.csv"
check "synth exit 0" test $? -eq 0
check "synth header has speed_in_rpm" grep -q '^speed_in_rpm,' "$tmp/rec.csv"
# Whole-number Hz (600, 720, 900 rpm = 10, 12, 15 Hz): the reports must be identical.
"$bin" synth "$src/configs/transfer-box.yaml" --seed 1 --speed 600,720,900rpm -o "$tmp/rec2.csv"
python3 - "$tmp" << 'EOF'
import csv, math, sys
d = sys.argv[1]
def rewrite(src, dst, col, new_name, f):
    rows = list(csv.reader(open(f"{d}/{src}")))
    j = rows[0].index(col)
    rows[0][j] = new_name
    for r in rows[1:]:
        r[j] = f(float(r[j]))
    with open(f"{d}/{dst}", "w", newline="") as o:
        csv.writer(o, lineterminator="\n").writerows(rows)
rewrite("rec.csv", "rec_hz.csv", "speed_in_rpm", "speed_in_Hz", lambda n: repr(n / 60))
rewrite("rec.csv", "rec_permin.csv", "speed_in_rpm", "speed_in_1/min", lambda n: repr(n))
rewrite("rec.csv", "rec_rads.csv", "speed_in_rpm", "speed_in_rad/s", lambda n: repr(n * 2 * math.pi / 60))
rewrite("rec.csv", "rec_pers.csv", "speed_in_rpm", "speed_in_1/s", lambda n: repr(n / 60))
rewrite("rec.csv", "rec_kw.csv", "P_loss_W", "P_loss_kW", lambda p: repr(p / 1000))
rewrite("rec.csv", "rec_k.csv", "oil_temp_C", "oil_temp_K", lambda t: repr(t + 273.15))
rewrite("rec2.csv", "rec2_hz.csv", "speed_in_rpm", "speed_in_Hz", lambda n: repr(n / 60))
EOF
check "recordings rewritten" test -s "$tmp/rec_hz.csv"
"$bin" diagnose "$src/configs/transfer-box.yaml" "$tmp/rec.csv" --json "$tmp/d_rpm.json" > "$tmp/d_rpm.txt"
check "diagnose rpm exit 0" test $? -eq 0
"$bin" diagnose "$src/configs/transfer-box.yaml" "$tmp/rec2.csv" > "$tmp/d2_rpm.txt"
"$bin" diagnose "$src/configs/transfer-box.yaml" "$tmp/rec2_hz.csv" > "$tmp/d2_hz.txt" 2> "$tmp/d2_hz.err"
check "diagnose speed_in_Hz (whole Hz) exit 0" test $? -eq 0
check "diagnose speed_in_Hz (whole Hz) = rpm report" cmp -s "$tmp/d2_rpm.txt" "$tmp/d2_hz.txt"
check "diagnose speed_in_Hz: no unknown-column warning" bash -c "! grep -qi 'unknown' '$tmp/d2_hz.err'"
for v in hz permin rads kw k; do
    "$bin" diagnose "$src/configs/transfer-box.yaml" "$tmp/rec_$v.csv" --json "$tmp/d_$v.json" > "$tmp/d_$v.txt" 2> "$tmp/d_$v.err"
    check "diagnose rec_$v exit 0" test $? -eq 0
    check "diagnose rec_$v: no unknown-column warning" bash -c "! grep -qi 'unknown' '$tmp/d_$v.err'"
    # Verdict, summary and the residual location (everything above the candidate list) equal;
    # the RMSEs equal to 1e-6 relative. (Candidates whose fit is flat may move in the 4th digit.)
    check "diagnose rec_$v: same verdict and report" \
        bash -c "cmp -s <(sed '/^candidates/,\$d' '$tmp/d_rpm.txt') <(sed '/^candidates/,\$d' '$tmp/d_$v.txt')"
    check "diagnose rec_$v: same json numbers" python3 -c "
import json
a = json.load(open('$tmp/d_rpm.json')); b = json.load(open('$tmp/d_$v.json'))
assert a['verdict'] == b['verdict'], (a['verdict'], b['verdict'])
assert a['points'] == b['points']
for k in ('rmse_before', 'rmse_after', 'temp_rmse_before', 'temp_rmse_after'):
    assert abs(a[k] - b[k]) <= 1e-6 * max(1.0, abs(a[k])), (k, a[k], b[k])
"
done
check "diagnose rec_permin: identical report" cmp -s "$tmp/d_rpm.txt" "$tmp/d_permin.txt"
"$bin" diagnose "$src/configs/transfer-box.yaml" "$tmp/rec_pers.csv" > /dev/null 2> "$tmp/d_pers.err"
check "diagnose speed_in_1/s exit 2" test $? -eq 2
check "diagnose speed_in_1/s names the column" grep -q 'speed_in_1/s' "$tmp/d_pers.err"
check "diagnose speed_in_1/s suggests rad/s and Hz" bash -c "grep -q 'rad/s' '$tmp/d_pers.err' && grep -q 'Hz' '$tmp/d_pers.err'"

# ---------------------------------------------------------------------------------------
# 3. Contact ratios. FZG C40 helical (beta 25 deg), pinion h*_a 0.7, wheel tip 126.8703 mm:
#    eps_alpha = 0.9333 (hand: test_tips_contact_ratio.cpp), eps_beta = 1.1958.
sed 's/profile_shift: 0.1817, face_width: 40 mm/profile_shift: 0.1817, face_width: 40 mm, helix_angle: 25 deg, hand: right, addendum_coefficient: 0.7/; s/profile_shift: 0.1715, face_width: 40 mm/profile_shift: 0.1715, face_width: 40 mm, helix_angle: 25 deg, hand: left, tip_diameter: 126.8703 mm/; s/, centre_distance: 91.5 mm//' \
    "$tmp/fzg.yaml" > "$tmp/h951.yaml"
"$bin" check "$tmp/h951.yaml" > "$tmp/h951.txt" 2> "$tmp/h951.err"
check "eps_alpha < 1 helical: check exit 0" test $? -eq 0
check "eps_alpha < 1 helical: eps_alpha 0.9333" grep -q 'eps_alpha = 0\.9333' "$tmp/h951.txt"
check "eps_alpha < 1 helical: note in the C40 block" \
    bash -c "sed -n '/^  C40 /,/^\$/p' '$tmp/h951.txt' | grep -qE 'note: .*eps_alpha.*< 1'"
"$bin" point "$tmp/h951.yaml" --speed 1000rpm --torque 100Nm > /dev/null 2>&1
check "eps_alpha < 1 helical: point exit 0" test $? -eq 0
# Spur, h*_a 0.6 on both (eps_alpha 0.912): an error naming the mesh.
sed 's/profile_shift: 0.1817, face_width: 40 mm/profile_shift: 0.1817, face_width: 40 mm, addendum_coefficient: 0.6/; s/profile_shift: 0.1715, face_width: 40 mm/profile_shift: 0.1715, face_width: 40 mm, addendum_coefficient: 0.6/' \
    "$tmp/fzg.yaml" > "$tmp/spur_short.yaml"
"$bin" check "$tmp/spur_short.yaml" > /dev/null 2> "$tmp/spur_short.err"
check "spur eps_alpha < 1: exit 2" test $? -eq 2
check "spur eps_alpha < 1: names the mesh" grep -qE 'meshes\[0\]|C40' "$tmp/spur_short.err"
check "spur eps_alpha < 1: file:line:col" grep -qE 'spur_short\.yaml:[0-9]+:[0-9]+: ' "$tmp/spur_short.err"
# ohlendorf with eps_alpha < 1: an error at options.gear_loss_factor.
sed 's/gear_loss_factor: wimmer/gear_loss_factor: ohlendorf/' "$tmp/h951.yaml" > "$tmp/h951_ohl.yaml"
"$bin" check "$tmp/h951_ohl.yaml" > /dev/null 2> "$tmp/h951_ohl.err"
check "ohlendorf eps_alpha < 1: exit 2" test $? -eq 2
check "ohlendorf eps_alpha < 1: at options.gear_loss_factor" \
    grep -qE 'h951_ohl\.yaml:[0-9]+:[0-9]+: options\.gear_loss_factor: ' "$tmp/h951_ohl.err"

# ---------------------------------------------------------------------------------------
# 4. Tips. Default FZG C40: ISO 21771 (k = -0.0199) on both; d_a 82.456 / 118.365 mm.
"$bin" check "$tmp/fzg.yaml" > "$tmp/fzg.txt"
check "tips default: ISO 21771 on both" grep -qE 'tips: pinion ISO 21771 tip alteration.*wheel ISO 21771 tip alteration' "$tmp/fzg.txt"
check "tips default: d_a 82.456 / 118.365" grep -q 'd_a = 82\.456 / 118\.365' "$tmp/fzg.txt"
# tip_alteration_factor 0 on both: d_a = d + 2 m_n (1 + x) = 82.635 / 118.544 mm, eps_alpha 1.4624.
sed 's/profile_shift: 0.1817, face_width: 40 mm/profile_shift: 0.1817, face_width: 40 mm, tip_alteration_factor: 0/; s/profile_shift: 0.1715, face_width: 40 mm/profile_shift: 0.1715, face_width: 40 mm, tip_alteration_factor: 0/' \
    "$tmp/fzg.yaml" > "$tmp/fzg_k0.yaml"
"$bin" check "$tmp/fzg_k0.yaml" > "$tmp/fzg_k0.txt"
check "tips k=0: exit 0" test $? -eq 0
check "tips k=0: d_a 82.635 / 118.544" grep -q 'd_a = 82\.635 / 118\.544' "$tmp/fzg_k0.txt"
check "tips k=0: eps_alpha 1.4624" grep -q 'eps_alpha = 1\.4624' "$tmp/fzg_k0.txt"
check "tips k=0: given tip alteration factor on both" \
    grep -qE 'tips: pinion given tip alteration factor.*wheel given tip alteration factor' "$tmp/fzg_k0.txt"
"$bin" check "$tmp/fzg_k0.yaml" --json > "$tmp/fzg_k0.json"
check "tips k=0: json arrays" python3 -c "
import json
m = json.load(open('$tmp/fzg_k0.json'))['meshes'][0]
assert m['tip_sources'] == ['given tip alteration factor'] * 2, m['tip_sources']
assert all(abs(k) < 1e-12 for k in m['tip_alteration_factors']), m['tip_alteration_factors']
assert abs(m['tip_diameters_mm'][0] - 82.6353) < 1e-6 and abs(m['tip_diameters_mm'][1] - 118.5435) < 1e-6
assert abs(m['eps_alpha'] - 1.46245) < 1e-4, m['eps_alpha']
"
# tip_diameter on the pinion: its source is the given diameter, the wheel keeps ISO.
sed 's/profile_shift: 0.1817, face_width: 40 mm/profile_shift: 0.1817, face_width: 40 mm, tip_diameter: 82.635 mm/' \
    "$tmp/fzg.yaml" > "$tmp/fzg_da.yaml"
"$bin" check "$tmp/fzg_da.yaml" > "$tmp/fzg_da.txt"
check "tips da: pinion given tip diameter, wheel ISO" \
    grep -qE 'tips: pinion given tip diameter.*wheel ISO 21771 tip alteration' "$tmp/fzg_da.txt"
"$bin" check "$tmp/fzg_da.yaml" --json > "$tmp/fzg_da.json"
check "tips da: json arrays" python3 -c "
import json
m = json.load(open('$tmp/fzg_da.json'))['meshes'][0]
assert m['tip_sources'] == ['given tip diameter', 'ISO 21771 tip alteration'], m['tip_sources']
k = m['tip_alteration_factors']   # (82.635 - 72 - 9 * 1.1817)/9 = -3.33e-5; ISO -0.019867
assert abs(k[0] + 0.0003 / 9) < 1e-7 and abs(k[1] + 0.0198667) < 1e-6, k
"
# Both on one gear: an error naming the gear.
sed 's/profile_shift: 0.1817, face_width: 40 mm/profile_shift: 0.1817, face_width: 40 mm, tip_diameter: 82.635 mm, tip_alteration_factor: 0/' \
    "$tmp/fzg.yaml" > "$tmp/fzg_both.yaml"
"$bin" check "$tmp/fzg_both.yaml" > /dev/null 2> "$tmp/fzg_both.err"
check "tips both: exit 2" test $? -eq 2
check "tips both: names gears[0]" grep -qE 'fzg_both\.yaml:[0-9]+:[0-9]+: gears\[0\]' "$tmp/fzg_both.err"

# ---------------------------------------------------------------------------------------
# 5. Plausibility (hand geometry in test_plausibility.cpp: w5 r_a 40.37 mm, w4 r_a 54.21 mm
#    on the input shaft at y = 0; lowest tip -54.21 mm).
sed 's/oil_level: -30 mm /oil_level: 45 mm  /' "$tb" > "$tmp/sub.yaml"
"$bin" check "$tmp/sub.yaml" > "$tmp/sub_check.txt" 2> "$tmp/sub_check.err"
check "submerged: check exit 0" test $? -eq 0
check "submerged: w5 warning under plausibility, located" \
    bash -c "sed -n '/^plausibility/,\$p' '$tmp/sub_check.txt' | grep -qE 'sub\.yaml:[0-9]+:[0-9]+: housing\.oil_level: warning: .*w5.*submerged'"
check "submerged: w4 not fully submerged" bash -c "! grep -qE \"'w4' is fully submerged\" '$tmp/sub_check.txt'"
"$bin" point "$tmp/sub.yaml" --speed 600rpm --torque 100Nm > /dev/null 2> "$tmp/sub_point.err"
check "submerged: point exit 0" test $? -eq 0
check "submerged: point prints the w5 warning once on stderr" \
    test "$(grep -cE "w5.*submerged" "$tmp/sub_point.err")" -eq 1
# A sweep re-reads the case per variant: the warning still once.
cat "$tmp/sub.yaml" > "$tmp/sub_sweep.yaml"
printf '\nsweep:\n  - {parameter: oil, values: [oils/75W90-A.yaml, oils/75W140-A.yaml]}\n' >> "$tmp/sub_sweep.yaml"
"$bin" map "$tmp/sub_sweep.yaml" --speed 600rpm --torque 100Nm --oil-temp 70degC -o "$tmp/sub_sweep.csv" 2> "$tmp/sub_sweep.err"
check "submerged sweep: map exit 0" test $? -eq 0
check "submerged sweep: w5 warning once" test "$(grep -cE "w5.*submerged" "$tmp/sub_sweep.err")" -eq 1

sed 's/oil_level: -30 mm /oil_level: -60 mm /' "$tb" > "$tmp/dry.yaml"
"$bin" check "$tmp/dry.yaml" > "$tmp/dry.txt"
check "dry dip box: warning" grep -qE 'dry\.yaml:[0-9]+:[0-9]+: housing\.[a-z_]+: warning: no gear touches the oil' "$tmp/dry.txt"
"$bin" map "$tmp/dry.yaml" --speed 600rpm --torque 100Nm --oil-temp 70degC -o "$tmp/dry.csv" 2> "$tmp/dry_map.err"
check "dry dip box: map warns once on stderr" test "$(grep -c 'no gear touches the oil' "$tmp/dry_map.err")" -eq 1
sed 's/  oil_volume: 2 L /  lubrication: injection\n  oil_volume: 2 L /' "$tmp/dry.yaml" > "$tmp/jet.yaml"
"$bin" check "$tmp/jet.yaml" > "$tmp/jet.txt"
check "injection: check exit 0" test $? -eq 0
check "injection: no 'no gear touches' warning" bash -c "! grep -q 'no gear touches the oil' '$tmp/jet.txt'"

# Housing box L 0.4, H 0.3, A 0.55: W = (0.275 - 0.12)/0.7 = 0.22143 m, V = 26.57 L.
sed 's/height: 0.3 m,/height: 0.3 m, length: 0.4 m,/; s/oil_volume: 2 L /oil_volume: 27 L/' "$tb" > "$tmp/vol.yaml"
"$bin" check "$tmp/vol.yaml" > /dev/null 2> "$tmp/vol.err"
check "oil volume > box: exit 2" test $? -eq 2
check "oil volume > box: at housing.oil_volume" grep -qE 'vol\.yaml:[0-9]+:[0-9]+: housing\.oil_volume: ' "$tmp/vol.err"
check "oil volume > box: states 26.57 L" grep -q '26\.57 L' "$tmp/vol.err"
sed 's/height: 0.3 m,/height: 0.3 m, length: 0.4 m,/; s/oil_volume: 2 L /oil_volume: 26 L/' "$tb" > "$tmp/vol_ok.yaml"
"$bin" check "$tmp/vol_ok.yaml" > /dev/null 2>&1
check "oil volume 26 L < box: exit 0" test $? -eq 0
# Oil level 260 mm: 314.2 mm above the lowest tip > H 300 mm.
sed 's/height: 0.3 m,/height: 0.3 m, length: 0.4 m,/; s/oil_level: -30 mm /oil_level: 260 mm /' "$tb" > "$tmp/lvl.yaml"
"$bin" check "$tmp/lvl.yaml" > /dev/null 2> "$tmp/lvl.err"
check "oil level > housing height: exit 2" test $? -eq 2
check "oil level > housing height: at housing.oil_level" grep -qE 'lvl\.yaml:[0-9]+:[0-9]+: housing\.oil_level: ' "$tmp/lvl.err"

# Oil temperature limits. 75W90-A (PAO): 110 degC permissible.
"$bin" point "$tb" --speed 600rpm --torque 100Nm --oil-temp 120degC > /dev/null 2> "$tmp/hot.err"
check "--oil-temp 120degC: exit 0" test $? -eq 0
check "--oil-temp 120degC: one warning on stderr" test "$(grep -c 'warning' "$tmp/hot.err")" -eq 1
check "--oil-temp 120degC: names --oil-temp and 110" bash -c "grep -q -- '--oil-temp' '$tmp/hot.err' && grep -q '110' '$tmp/hot.err'"
"$bin" point "$tb" --speed 600rpm --torque 100Nm --oil-temp 100degC > /dev/null 2> "$tmp/warm.err"
check "--oil-temp 100degC: no warning" test ! -s "$tmp/warm.err"

# above_oil_limit / no_equilibrium: a baseline map (no limits reached) gives each point's
# stabilised temperature T. With the oil's max_temperature 60 degC and max_oil_temperature
# 80 degC: T <= 60 -> ok, 60 < T <= 80 -> above_oil_limit (numbers kept), T > 80 -> no_equilibrium
# (numbers empty).
"$bin" map "$tb" -o "$tmp/base.csv" --json "$tmp/base.json"
check "baseline map exit 0" test $? -eq 0
mkdir -p "$tmp/lim/oils"
cp "$src/configs/oils/75W90-A.yaml" "$tmp/lim/oils/75W90-A.yaml"
printf 'max_temperature: 60 degC\n' >> "$tmp/lim/oils/75W90-A.yaml"
sed 's/  ambient: 25 degC/  ambient: 25 degC\n  max_oil_temperature: 80 degC/' "$tb" > "$tmp/lim/tb.yaml"
"$bin" map "$tmp/lim/tb.yaml" -o "$tmp/lim.csv" --json "$tmp/lim.json" 2> "$tmp/lim.err"
check "limit map exit 0" test $? -eq 0
check "limit map: statuses, kept numbers, json counts" python3 -c "
import csv, json
base = list(csv.DictReader(open('$tmp/base.csv')))
lim = list(csv.DictReader(open('$tmp/lim.csv')))
assert len(base) == len(lim) == 9
counts = {'ok': 0, 'above_oil_limit': 0, 'no_equilibrium': 0}
numeric = [k for k in base[0] if k not in ('status',)]
for b, l in zip(base, lim):
    T = float(b['oil_temp_C'])
    want = 'ok' if T <= 60 else ('above_oil_limit' if T <= 80 else 'no_equilibrium')
    assert l['status'] == want, (T, l['status'], want)
    counts[want] += 1
    for k in numeric:
        if want == 'no_equilibrium' and k not in ('speed_in_rpm', 'torque_in_Nm', 'power_in_W', 'ambient_temp_C'):
            assert l[k] == '', (k, l[k])
        elif want != 'no_equilibrium':
            assert l[k] != '', (k, want)
            assert abs(float(l[k]) - float(b[k])) <= 1e-3 * max(1.0, abs(float(b[k]))), (k, b[k], l[k])
assert all(v > 0 for v in counts.values()), counts
j = json.load(open('$tmp/lim.json'))
for k, v in counts.items():
    assert j[k] == v, (k, j[k], v)
assert j['points'] == 9
jb = json.load(open('$tmp/base.json'))
assert jb['ok'] == 9 and jb['above_oil_limit'] == 0 and jb['no_equilibrium'] == 0, jb
"
check "limit map: no NaN/inf" bash -c "! grep -qiE 'nan|inf' '$tmp/lim.csv'"
"$bin" check "$tmp/lim/tb.yaml" > "$tmp/lim_check.txt"
check "limit check: permissible 60 degC shown" grep -q 'permissible oil temperature 60\.0 degC' "$tmp/lim_check.txt"

# ---------------------------------------------------------------------------------------
# 7. Churning forms and their ranges (docs/config.md "Churning forms and their ranges").
#    The tooth-surface form (heingartner_mba_2003) has no value for spur teeth (its
#    R_f / sqrt(tan beta)): the FZG C40 gears are spur, so selecting it is a finding for both
#    dipping gears -- in check (text and --json warnings), once on stderr of map and point,
#    and in the map's sidecar -- and both keep the default form (the same churning).
#    The shipped case with the default form is quiet.
cp "$tmp/fzg.yaml" "$tmp/fzg_hm.yaml"
printf 'mechanisms:\n  churning: {form: heingartner_mba_2003}\n' >> "$tmp/fzg_hm.yaml"
"$bin" check "$tmp/fzg_hm.yaml" > "$tmp/hm_check.txt" 2> "$tmp/hm_check.err"
check "churning form: check exit 0" test $? -eq 0
check "churning form: check names the form outside its range for the wheel" \
    grep -q "churning form heingartner_mba_2003 outside its defined range for gear 'wheel': helix angle 0 deg given, defined for > 0 deg" "$tmp/hm_check.txt"
check "churning form: check names the pinion too" grep -q "range for gear 'pinion'" "$tmp/hm_check.txt"
check "churning form: located at the case's oil level" grep -q "fzg_hm.yaml:[0-9]*:[0-9]*: .*note: churning form" "$tmp/hm_check.txt"
"$bin" check "$tmp/fzg_hm.yaml" --json > "$tmp/hm_check.json"
check "churning form: check --json lists the form and the findings" "$py" -c "
import json
j = json.load(open('$tmp/hm_check.json'))
ch = [m for m in j['mechanisms'] if m['name'] == 'churning'][0]
assert ch['forms'] == [{'axis': 'form', 'selected': 'heingartner_mba_2003', 'forms': ['changenet_velex_2007', 'heingartner_mba_2003', 'mauz_1987']}], ch
w = [x for x in j['warnings'] if 'churning form heingartner_mba_2003 outside' in x]
assert len(w) == 2, j['warnings']
"
"$bin" map "$tmp/fzg_hm.yaml" --speed 1000,2000rpm --torque 100Nm --oil-temp 80degC -o "$tmp/hm.csv" 2> "$tmp/hm_map.err"
check "churning form: map exit 0" test $? -eq 0
check "churning form: map stderr once per gear (not per point)" \
    bash -c "[ \"\$(grep -c 'churning form heingartner_mba_2003 outside' '$tmp/hm_map.err')\" = 2 ]"
check "churning form: the sidecar carries the findings" "$py" -c "
import json
j = json.load(open('$tmp/hm.csv.meta.json'))
assert j['model_forms']['churning.form'] == 'heingartner_mba_2003', j['model_forms']
assert sum('churning form heingartner_mba_2003 outside' in x for x in j['findings']) == 2, j.get('findings')
"
"$bin" map "$tmp/fzg.yaml" --speed 1000,2000rpm --torque 100Nm --oil-temp 80degC -o "$tmp/cv.csv" 2> "$tmp/cv_map.err"
check "churning form: spur gears keep the default form (same churning column)" \
    bash -c "diff <(cut -d, -f1-2,\$(head -1 '$tmp/cv.csv' | tr ',' '\n' | grep -n '^P_churn_W$' | cut -d: -f1) '$tmp/cv.csv') \
                  <(cut -d, -f1-2,\$(head -1 '$tmp/hm.csv' | tr ',' '\n' | grep -n '^P_churn_W$' | cut -d: -f1) '$tmp/hm.csv')"
check "churning form: the default form is quiet" bash -c "! grep -q 'churning form' '$tmp/cv_map.err'"
check "churning form: no findings key in the default sidecar" "$py" -c "
import json
assert 'findings' not in json.load(open('$tmp/cv.csv.meta.json'))
"
"$bin" point "$tmp/fzg_hm.yaml" --speed 1000rpm --torque 100Nm --oil-temp 80degC > /dev/null 2> "$tmp/hm_point.err"
check "churning form: point stderr names it" grep -q "churning form heingartner_mba_2003 outside" "$tmp/hm_point.err"
printf 'mechanisms:\n  churning: {form: dudley}\n' > "$tmp/bad_form.part"
cat "$tmp/fzg.yaml" "$tmp/bad_form.part" > "$tmp/fzg_bad.yaml"
"$bin" check "$tmp/fzg_bad.yaml" > /dev/null 2> "$tmp/bad_form.err"
check "churning form: an unknown form exits 2" test $? -eq 2
check "churning form: the error names the key and the form" grep -q "churning.*dudley" "$tmp/bad_form.err"

# ---------------------------------------------------------------------------------------
# 8. The splash form of Mauz (1987) (mauz_1987) and its speed range (docs/config.md
#    "Churning forms and their ranges"): fitted up to 60 m/s of pitch line as quoted in
#    secondary sources. The FZG C40 case with speeds up to 20 000 rpm runs its pitch line far
#    beyond: a note for both dipping gears in check (text and --json), once on stderr of map,
#    and in the map's sidecar. The default form's check says its range is not stated in a
#    verified source (and has no finding).
sed 's/^  speeds: .*/  speeds: [1000 rpm, 20000 rpm]/' "$tmp/fzg.yaml" > "$tmp/fzg_mauz.yaml"
printf 'mechanisms:\n  churning: {form: mauz_1987}\n' >> "$tmp/fzg_mauz.yaml"
"$bin" check "$tmp/fzg_mauz.yaml" > "$tmp/mauz_check.txt" 2> "$tmp/mauz_check.err"
check "mauz form: check exit 0" test $? -eq 0
check "mauz form: check names the speed range for the wheel" \
    grep -q "churning form mauz_1987 outside its fitted range for gear 'wheel': pitch-line speed [0-9.]*-[0-9.]* m/s given, fitted 0-60 m/s" "$tmp/mauz_check.txt"
check "mauz form: check names the pinion too" grep -q "mauz_1987 outside its fitted range for gear 'pinion'" "$tmp/mauz_check.txt"
check "mauz form: the range's provenance is stated" grep -q "fitted range: pitch-line speed 0-60 m/s (speed range as quoted in secondary sources" "$tmp/mauz_check.txt"
check "mauz form: the coefficients are said to be unverified" grep -q "coefficients as quoted in secondary sources, not checked against the ISO/TR text" "$tmp/mauz_check.txt"
check "mauz form: its sump settings are listed as assumed" grep -q "mechanisms.churning.splash_height" "$tmp/mauz_check.txt"
"$bin" check "$tmp/fzg_mauz.yaml" --json > "$tmp/mauz_check.json"
check "mauz form: check --json lists the form, its range and the findings" "$py" -c "
import json
j = json.load(open('$tmp/mauz_check.json'))
ch = [m for m in j['mechanisms'] if m['name'] == 'churning'][0]
assert ch['forms'][0]['selected'] == 'mauz_1987', ch
assert 'mauz_1987' in ch['forms'][0]['forms'], ch
r = j['churning_range']
assert r['form'] == 'mauz_1987' and r['limits'][0]['quantity'] == 'pitch-line speed' and r['limits'][0]['hi'] == 60, r
assert 'not checked against the ISO/TR text' in r['coefficients'], r
w = [x for x in j['warnings'] if 'churning form mauz_1987 outside its fitted range' in x]
assert len(w) == 2, j['warnings']
"
"$bin" map "$tmp/fzg_mauz.yaml" --speed 1000,20000rpm --torque 100Nm --oil-temp 80degC -o "$tmp/mauz.csv" 2> "$tmp/mauz_map.err"
check "mauz form: map exit 0" test $? -eq 0
check "mauz form: map stderr once per gear (not per point)" \
    bash -c "[ \"\$(grep -c 'churning form mauz_1987 outside' '$tmp/mauz_map.err')\" = 2 ]"
check "mauz form: the sidecar carries the findings" "$py" -c "
import json
j = json.load(open('$tmp/mauz.csv.meta.json'))
assert j['model_forms']['churning.form'] == 'mauz_1987', j['model_forms']
assert sum('churning form mauz_1987 outside' in x for x in j['findings']) == 2, j.get('findings')
"
"$bin" check "$tmp/fzg.yaml" > "$tmp/cv_check.txt"
check "default form: check says its range is not stated in a verified source" \
    grep -q "churning form changenet_velex_2007: fitted range: none checked (not stated in a verified source" "$tmp/cv_check.txt"
"$bin" check "$tmp/fzg.yaml" --json > "$tmp/cv_check.json"
check "default form: check --json says so too" "$py" -c "
import json
r = json.load(open('$tmp/cv_check.json'))['churning_range']
assert r['form'] == 'changenet_velex_2007' and r['limits'] == [] and 'not stated in a verified source' in r['provenance'], r
"

# ---------------------------------------------------------------------------------------
# Kinds that do not depend on spelling: a torque names a force; Hz counts revolutions; angles
# that repeat; '%' only alone; a right-to-left override in the case's name.
for t in "100 Pa*m^3" "100 kg*m^2/s^2"; do
    "$bin" point "$tb" --speed 600rpm --torque "$t" --oil-temp 70degC > /dev/null 2> "$tmp/kind.err"
    check "point --torque '$t' refused (exit 2)" test $? -eq 2
    check "point --torque '$t': no force named" grep -q "does not name a force" "$tmp/kind.err"
done
for s in "800 rpm^2/rpm" "800 rev*rpm/rev"; do
    "$bin" point "$tb" --speed "$s" --torque 100Nm --oil-temp 70degC > /dev/null 2> "$tmp/kind.err"
    check "point --speed '$s' refused (exit 2)" test $? -eq 2
done
"$bin" point "$tb" --speed 600rpm --torque "100 N*m*%" --oil-temp 70degC > /dev/null 2> "$tmp/kind.err"
check "point --torque '100 N*m*%' refused (exit 2)" test $? -eq 2
sed 's/^name: .*/name: "gear\\u202Ebox"/' "$tb" > "$tmp/bidi.yaml"
"$bin" check "$tmp/bidi.yaml" > /dev/null 2> "$tmp/bidi.err"
check "a case name with U+202E refused (exit 2)" test $? -eq 2
check "U+202E refused at the name's line" grep -q "bidi.yaml:5:" "$tmp/bidi.err"

echo "cli_units_plausibility: $pass passed, $fail failed"
test $fail -eq 0
