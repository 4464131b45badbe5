#!/usr/bin/env bash
# End-to-end checks of a mesh's centre distance against its profile shifts (ISO 21771):
# overlapping flanks are an error at the centre_distance line, a backlash beyond the housing
# tolerance a warning there, and `check` reports the fit of every mesh (text and --json).
# Usage: cli_geometry.sh GEARLOSS_BINARY SOURCE_DIR
# Every file is written inside a private mktemp -d directory.
set -u
source "$(dirname "$0")/cli_common.sh" "$@"
cp -r "$src/configs/oils" "$tmp/oils"
export GEARLOSS_DATA_DIR="$src/configs"  # the shipped data (bearing catalogue) wherever the binary is

# 1. FZG C40 gears (x 0.1817/0.1715 mesh without backlash at 91.5 mm, published) at 87..90 mm:
#    the flanks would overlap. Exit 2, naming file:line of centre_distance and both distances.
for aw in 87 88 89 90; do
    sed "s/centre_distance: 91.5 mm/centre_distance: $aw mm/" "$src/configs/fzg-c40-paor.yaml" > "$tmp/fzg$aw.yaml"
    "$bin" check "$tmp/fzg$aw.yaml" > /dev/null 2> "$tmp/fzg$aw.err"
    check "FZG at $aw mm: exit 2" test $? -eq 2
    check "FZG at $aw mm: names fzg$aw.yaml:15 and the key" grep -q "fzg$aw.yaml:15:[0-9]*: meshes\[0\]\.centre_distance" "$tmp/fzg$aw.err"
    check "FZG at $aw mm: names $aw.000 mm and 91.500 mm" \
        bash -c "grep -q 'centre distance $aw.000 mm' '$tmp/fzg$aw.err' && grep -q '91.500 mm' '$tmp/fzg$aw.err'"
    "$bin" point "$tmp/fzg$aw.yaml" --speed 1000rpm --torque 100Nm --oil-temp 80degC > /dev/null 2>&1
    check "FZG at $aw mm: point refuses it too" test $? -eq 2
done

# 2. Helical 23/67, m_n 3 mm, beta 15 deg, x1 = x2 = 0: a = 139.762 mm; given 140 mm is 0.238 mm
#    apart (js7 allows +/-0.020 mm): accepted with a warning at the centre_distance line.
sed -e 's/teeth: 16, module: 4.5 mm, profile_shift: 0.1817,/teeth: 23, module: 3 mm, profile_shift: 0, helix_angle: 15 deg, hand: left,/' \
    -e 's/teeth: 24, module: 4.5 mm, profile_shift: 0.1715,/teeth: 67, module: 3 mm, profile_shift: 0, helix_angle: 15 deg, hand: right,/' \
    -e 's/centre_distance: 91.5 mm/centre_distance: 140 mm/' "$src/configs/fzg-c40-paor.yaml" > "$tmp/h140.yaml"
grep -q 'teeth: 67, module: 3 mm' "$tmp/h140.yaml" || echo "FAILED: the 23/67 case was not written" >&2
"$bin" check "$tmp/h140.yaml" > "$tmp/h140.txt" 2> "$tmp/h140.err"
check "23/67 at 140 mm: exit 0" test $? -eq 0
warning="h140.yaml:15:[0-9]*: meshes\[0\]\.centre_distance: warning: centre distance 140.000 mm"
check "23/67 at 140 mm: check lists the warning at h140.yaml:15, naming both distances" \
    bash -c "grep '$warning' '$tmp/h140.txt' | grep -q '139.762 mm'"
check "23/67 at 140 mm: the implied x1 + x2 = 0.0797 and the backlash 0.181 mm" \
    bash -c "grep '$warning' '$tmp/h140.txt' | grep 'implies x1 + x2 = 0.0797' | grep -q 'j_wt = 0.181 mm'"
"$bin" point "$tmp/h140.yaml" --speed 1000rpm --torque 100Nm --oil-temp 80degC > /dev/null 2> "$tmp/h140_point.err"
check "23/67 at 140 mm: point runs (exit 0)" test $? -eq 0
check "23/67 at 140 mm: point warns on stderr at h140.yaml:15" grep -q "$warning" "$tmp/h140_point.err"
check "23/67 at 140 mm: check text reports the fit" grep -q 'shifts give 139.762 (x1 + x2 = 0.0000); a_w implies x1 + x2 = 0.0797' "$tmp/h140.txt"
"$bin" check "$tmp/h140.yaml" --json > "$tmp/h140.json" 2> /dev/null
check "23/67 at 140 mm: check --json reports the fit" python3 -c "
import json
f = json.load(open('$tmp/h140.json'))['meshes'][0]['centre_distance_fit']
assert f['given'] and f['beyond_tolerance'], f
assert abs(f['reference_mm'] - 139.7623) < 1e-3 and abs(f['working_mm'] - 140) < 1e-9, f
assert abs(f['sum_x_given']) < 1e-12 and abs(f['sum_x_implied'] - 0.0797) < 1e-4, f
assert abs(f['working_pressure_angle_deg'] - 20.9036) < 1e-4, f
assert abs(f['backlash_circumferential_mm'] - 0.1805) < 1e-4 and abs(f['backlash_normal_mm'] - 0.1636) < 1e-4, f
"

# 3. Internal pair: the planet-ring mesh of the planetary case given 48.80 mm (the shifts give
#    48.75 mm): moving an internal pair apart pushes the teeth into each other. Exit 2 at the key.
sed 's/{name: planet-ring, gears: \[planet, ring\]}/{name: planet-ring, gears: [planet, ring], centre_distance: 48.80 mm}/' \
    "$src/configs/planetary-test.yaml" > "$tmp/pr.yaml"
"$bin" check "$tmp/pr.yaml" > /dev/null 2> "$tmp/pr.err"
check "planet-ring at 48.80 mm: exit 2" test $? -eq 2
check "planet-ring at 48.80 mm: at pr.yaml:20, overlap" \
    bash -c "grep -q 'pr.yaml:20:[0-9]*: meshes\[1\]\.centre_distance' '$tmp/pr.err' && grep -q 'overlap' '$tmp/pr.err'"

# 4. A given tip diameter against its shift: FZG C40 wheel, d = 108 mm, x = 0.1715, full-depth tip
#    d + 2 m (1 + x) = 118.5435 mm; 119.5 mm is 0.956 mm longer (IT11 of 119.5 mm: 0.22 mm): a warning
#    at the tip_diameter key (line 12).
sed 's/profile_shift: 0.1715,/profile_shift: 0.1715, tip_diameter: 119.5 mm,/' "$src/configs/fzg-c40-paor.yaml" > "$tmp/tip.yaml"
"$bin" check "$tmp/tip.yaml" > "$tmp/tip.txt" 2> /dev/null
check "tip 119.5 mm: exit 0" test $? -eq 0
check "tip 119.5 mm: warning at tip.yaml:12 naming both diameters" \
    bash -c "grep 'tip.yaml:12:[0-9]*: gears\[1\]\.tip_diameter: warning' '$tmp/tip.txt' | grep '119.500 mm' | grep -q '118.54'"

# 5. Every shipped case passes with no centre-distance warning; check reports every mesh's fit.
for f in "$src"/configs/*.yaml; do
    name=$(basename "$f")
    "$bin" check "$f" > "$tmp/ship.txt" 2> "$tmp/ship.err"
    check "shipped $name: exit 0" test $? -eq 0
    check "shipped $name: no centre-distance or tip warning" \
        bash -c "! grep -qE 'centre_distance: warning|tip_(diameter|alteration_factor): warning' '$tmp/ship.txt'"
    check "shipped $name: fit reported per mesh" \
        bash -c "[ \$(grep -c '^    centre distance ' '$tmp/ship.txt') -eq \$(grep -c '^  [^ ].*: \(loaded\|idle\)\$' '$tmp/ship.txt') ]"
done

echo "cli_geometry: $pass passed, $fail failed"
test $fail -eq 0
