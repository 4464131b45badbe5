#!/usr/bin/env bash
# Lists and units as people type them (docs/config.md, "Lists and ranges" and the units):
# START:STOP:STEP ranges on the command line (--speed, --torque, --oil-temps) and in case files
# (the grid's speeds and torques, a sweep's values), each compared byte for byte with the same
# values written out one by one; the errors of an empty, endless, descending or huge range;
# products of units written N·m, N⋅m and N m; the effects and noise defaults in `synth --help`;
# every file a help text names exists; tiny p-values print as a bound.
# Usage: cli_lists_units.sh GEARLOSS_BINARY SOURCE_DIR
source "$(dirname "$0")/cli_common.sh" "$@"
cp -r "$src/configs" "$tmp/cfg"
case=$tmp/cfg/transfer-box.yaml

same() {  # same NAME FILE_A FILE_B: byte for byte
    check "$1" cmp -s "$2" "$3"
}

# 1. Ranges on the command line equal the lists written out (inclusive end, float steps, the
#    unit on STEP or on every part, a range among plain items taking the list's unit).
"$bin" map "$case" --speed 600,650,700,750,800rpm --torque 150,162.5,175Nm -o "$tmp/list.csv" 2> /dev/null
expect "range: --speed 600:800:50rpm" 0 "" "$bin" map "$case" --speed 600:800:50rpm --torque 150:175:12.5Nm -o "$tmp/r1.csv"
same "range: equals the list written out" "$tmp/list.csv" "$tmp/r1.csv"
expect "range: units on every part" 0 "" "$bin" map "$case" --speed 600rpm:800rpm:50rpm --torque 150Nm:175Nm:12.5Nm -o "$tmp/r2.csv"
same "range: units on every part, same map" "$tmp/list.csv" "$tmp/r2.csv"
expect "range: among items" 0 "" "$bin" map "$case" --speed 600:700:50,750,800rpm --torque 150,162.5:175:12.5Nm -o "$tmp/r3.csv"
same "range: among items, same map" "$tmp/list.csv" "$tmp/r3.csv"
# 0:1:0.1 is eleven values ending at 1 (ten steps of 0.1 do not make exactly 1 in binary).
"$bin" map "$case" --speed 800rpm --torque 0:1:0.1Nm -o "$tmp/fine.csv" 2> /dev/null
check "range: 0:1:0.1 has 11 values, ends at 1, 0.3 is 0.3" test "$(cut -d, -f2 "$tmp/fine.csv" | tail -n +2 | tr '\n' ' ')" = \
    "0 0.1 0.2 0.3 0.4 0.5 0.6 0.7 0.8 0.9 1 "
expect "range: empty" 2 "--speed: '3000:300:10rpm': empty range" "$bin" map "$case" --speed 3000:300:10rpm -o "$tmp/x.csv"
expect "range: zero step" 2 "--speed: .*STEP is zero" "$bin" map "$case" --speed 300:3000:0rpm -o "$tmp/x.csv"
expect "range: negative step" 2 "--speed: .*STEP is negative" "$bin" map "$case" --speed 3000:300:-10rpm -o "$tmp/x.csv"
expect "range: huge" 2 "--torque: .*at most 1000000" "$bin" map "$case" --torque 1:1e9:1Nm -o "$tmp/x.csv"
expect "range: units differ" 2 "--speed: .*one unit" "$bin" map "$case" --speed 300rpm:3000:100rpm -o "$tmp/x.csv"
expect "range: two parts" 2 "--speed: .*not a range" "$bin" map "$case" --speed 300:3000rpm -o "$tmp/x.csv"
check "range: no output written on error" test ! -e "$tmp/x.csv"
# Every command that takes the grid options reads them through the same parser.
expect "range: synth" 0 "" "$bin" synth "$case" --speed 600:800:100rpm --torque 150:250:50Nm -o "$tmp/s.csv"
check "range: synth has 9 points" test "$(tail -n +2 "$tmp/s.csv" | wc -l)" -eq 9
expect "range: compare" 0 "" "$bin" compare "$case" --oil "$tmp/cfg/oils/75W90-A.yaml" --oil "$tmp/cfg/oils/75W140-A.yaml" \
    --speed 600:800:100rpm --torque 200Nm -o "$tmp/c.csv"
check "range: compare has 3 points" test "$(tail -n +2 "$tmp/c.csv" | wc -l)" -eq 3
# --oil-temps: a range in degC counts in degrees Celsius.
"$bin" map "$tmp/cfg/manual-6speed.yaml" --format table --speed 1000rpm --torque 90Nm --oil-temps 20,40,60,80degC \
    -o "$tmp/t1.csv" 2> /dev/null
expect "range: --oil-temps" 0 "" "$bin" map "$tmp/cfg/manual-6speed.yaml" --format table --speed 1000rpm --torque 90Nm \
    --oil-temps 20:80:20degC -o "$tmp/t2.csv"
same "range: --oil-temps 20:80:20degC equals 20,40,60,80degC" "$tmp/t1.csv" "$tmp/t2.csv"
expect "range: --oil-temps empty" 2 "--oil-temps: .*empty range" "$bin" map "$tmp/cfg/manual-6speed.yaml" --format table \
    --oil-temps 80:20:20degC -o "$tmp/x.csv"

# 2. Products of units: N·m (U+00B7), N⋅m (U+22C5) and N m read as N*m.
"$bin" map "$case" --speed 700rpm --torque 150,200,250Nm -o "$tmp/nm.csv" 2> /dev/null
for t in "150N·m,200N·m,250N·m" "150,200,250 N⋅m" "150,200,250 N m" "0.15,0.2,0.25 kN m"; do
    expect "units: --torque '$t'" 0 "" "$bin" map "$case" --speed 700rpm --torque "$t" -o "$tmp/u.csv"
    same "units: --torque '$t' equals 150,200,250Nm" "$tmp/nm.csv" "$tmp/u.csv"
done
expect "units: 'N·' alone" 2 "--torque: cannot read unit" "$bin" point "$case" --speed 700rpm --torque "150 N·"

# 3. Case files: ranges and the new units in the grid, and in a sweep.
"$bin" map "$case" -o "$tmp/grid.csv" 2> /dev/null
sed -e 's/^  speeds: \[600 rpm, 700 rpm, 800 rpm\]/  speeds: 600:800:100 rpm/' \
    -e 's/^  torques: \[150 N\*m, 200 N\*m, 250 N\*m\]/  torques: [150:200:50 N·m, 250 N m]/' "$case" > "$tmp/cfg/ranges.yaml"
check "yaml: the grid lines were replaced" grep -q '^  speeds: 600:800:100 rpm' "$tmp/cfg/ranges.yaml"
expect "yaml: ranges" 0 "" "$bin" map "$tmp/cfg/ranges.yaml" -o "$tmp/grid2.csv"
same "yaml: ranges give the same map" "$tmp/grid.csv" "$tmp/grid2.csv"
sed -e 's/^  speeds: \[600 rpm, 700 rpm, 800 rpm\]/  speeds: 800:600:100 rpm/' "$case" > "$tmp/cfg/empty.yaml"
expect "yaml: empty range" 2 "empty\.yaml:[0-9]+:[0-9]+: operating\.speeds: .*empty range" "$bin" map "$tmp/cfg/empty.yaml" -o "$tmp/x.csv"
cp "$case" "$tmp/cfg/sweep-list.yaml"
printf 'sweep:\n  - parameter: housing.oil_level\n    values: [-30 mm, -20 mm, -10 mm]\n' >> "$tmp/cfg/sweep-list.yaml"
cp "$case" "$tmp/cfg/sweep-range.yaml"
printf 'sweep:\n  - parameter: housing.oil_level\n    values: [-30:-10:10 mm]\n' >> "$tmp/cfg/sweep-range.yaml"
"$bin" map "$tmp/cfg/sweep-list.yaml" -o "$tmp/sw1.csv" 2> /dev/null
expect "yaml: sweep range" 0 "" "$bin" map "$tmp/cfg/sweep-range.yaml" -o "$tmp/sw2.csv"
same "yaml: a sweep's range equals its values written out" "$tmp/sw1.csv" "$tmp/sw2.csv"
check "yaml: the sweep has 3 x 9 points" test "$(tail -n +2 "$tmp/sw2.csv" | wc -l)" -eq 27

# 4. synth --help: every effect the model offers (the names an unknown effect's message lists)
#    with its default, and the default noise.
"$bin" synth --help > "$tmp/synth-help.txt"
"$bin" synth "$case" --effect no_such_effect=1 -o "$tmp/x.csv" 2> "$tmp/known.txt"
known=$(sed -n 's/.*known for this case: //p' "$tmp/known.txt" | tr -d ' ' | tr ',' ' ')
check "synth --help: the unknown-effect message lists effects" test -n "$known"
for e in $known; do
    case $e in
    *:*) check "synth --help: form $e" grep -qF -- "$e" "$tmp/synth-help.txt" ;;
    *) check "synth --help: effect $e with its default" grep -qE -- "^  $e +default " "$tmp/synth-help.txt" ;;
    esac
done
check "synth --help: default loss noise" grep -qE -- "--noise-loss 1.5%" "$tmp/synth-help.txt"
check "synth --help: default temperature noise" grep -qE -- "--noise-temp 0.4 K" "$tmp/synth-help.txt"

# 5. Every file a help text names exists in the source tree (paths under its top-level folders).
subs=$("$bin" --help | sed -n '/^Subcommands:/,/^$/p' | awk '/^  [a-z]/{print $1}')
check "help: subcommands found" test "$(echo "$subs" | wc -w)" -ge 10
{
    "$bin" --help
    for s in $subs; do "$bin" "$s" --help; done
} > "$tmp/help.txt"
roots=$(cd "$src" && ls -d */ | tr -d / | paste -sd'|')
paths=$(grep -oE "(^|[^A-Za-z0-9_./-])($roots)/[A-Za-z0-9_./+-]*[A-Za-z0-9_]" "$tmp/help.txt" | sed -E 's/^[^A-Za-z]//' | sort -u)
check "help: some paths named" test -n "$paths"
for p in $paths; do check "help names $p, which exists" test -e "$src/$p"; done

# 6. A p-value below 1e-16 prints as a bound (a declared noise far below the recorded one).
"$bin" synth "$case" --seed 3 --noise-loss 3% -o "$tmp/rec.csv" 2> /dev/null
"$bin" diagnose "$case" "$tmp/rec.csv" --loss-uncertainty 0.01% --quiet > "$tmp/diag.txt" 2> /dev/null
check "p-values: 'p < 1e-16' printed" grep -q "p < 1e-16" "$tmp/diag.txt"
check "p-values: none printed below 1e-16" bash -c "! grep -oE 'p = [0-9.]+e-[0-9]+' '$tmp/diag.txt' |
    awk '{ if (\$3 + 0 < 1e-16) bad = 1 } END { exit !bad }'"
check "p-values: no 'p = 0'" bash -c "! grep -qE 'p = 0([^.]|$)' '$tmp/diag.txt'"

echo "cli_lists_units: $pass passed, $fail failed"
[ "$fail" -eq 0 ]
