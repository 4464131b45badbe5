#!/usr/bin/env bash
# The installed program finds its data where it is installed, not where it was built:
#  - `cmake --install BUILD_DIR --prefix` a temporary folder installs bin/gearloss, the drive
#    cycles in share/gearloss/cycles and README/LICENSE in share/doc/gearloss;
#  - the installed binary runs a named cycle (nedc, artemis) of a shipped case from another
#    working directory, the case copied without a cycles/ folder beside it, so that the cycle
#    must come from the installed data; the summary equals the build tree's;
#  - GEARLOSS_DATA_DIR pointing at an empty folder: exit 2 and a message naming the variable
#    and the folder; a copy of the binary with no data beside it names the places it
#    searched, and runs with GEARLOSS_DATA_DIR set to the installed data;
#  - the installed share/gearloss/slurm-map.sh finds the installed binary from a spooled copy.
# Everything is written inside a temporary folder, removed on exit.
# Usage: cli_install.sh BUILD_DIR SOURCE_DIR
source "$(dirname "$0")/cli_common.sh" "$@"
build=$1
built_bin=$(find "$build/app" -maxdepth 1 -name gearloss -type f | head -n 1)
prefix="$tmp/prefix"

cmake --install "$build" --prefix "$prefix" > "$tmp/install.txt" 2>&1
rc=$?
check "cmake --install exit 0" test $rc -eq 0
[ $rc -eq 0 ] || cat "$tmp/install.txt"
check "installed binary" test -x "$prefix/bin/gearloss"
check "installed cycles" test -f "$prefix/share/gearloss/cycles/nedc.csv" -a -f "$prefix/share/gearloss/cycles/wltc-class3b.csv"
check "installed cycle count" test "$(ls "$prefix/share/gearloss/cycles"/*.csv | wc -l)" -eq "$(ls "$src/configs/cycles"/*.csv | wc -l)"
check "installed README and LICENSE" test -f "$prefix/share/doc/gearloss/README.md" -a -f "$prefix/share/doc/gearloss/LICENSE"
check "nothing of the source tree baked in" bash -c "! grep -qF '$src/configs' '$prefix/bin/gearloss'"

# The shipped case and its oil, without a cycles/ folder beside them.
mkdir -p "$tmp/case/oils" "$tmp/elsewhere" "$tmp/empty" "$tmp/lonely/bin"
cp "$src/configs/automatic-6speed.yaml" "$tmp/case/"
cp "$src/configs/oils/ATF-A.yaml" "$tmp/case/oils/"
args=(--start-temp -10degC --prewarm 90degC --heater 2kW)

(cd "$tmp/elsewhere" && env -u GEARLOSS_DATA_DIR "$prefix/bin/gearloss" cycle "$tmp/case/automatic-6speed.yaml" \
    --cycle nedc "${args[@]}" --json "$tmp/installed.json" > "$tmp/installed.txt" 2> "$tmp/installed.err")
rc=$?
check "installed: named cycle from another directory, exit 0" test $rc -eq 0
[ $rc -eq 0 ] || cat "$tmp/installed.err"
check "installed: cycle summary" grep -q "pre-warming saves" "$tmp/installed.txt"
check "installed: the cycle is nedc" python3 -c "
import json
d = json.load(open('$tmp/installed.json'))
assert d['cycle'] == 'nedc' and abs(d['distance_km'] - 11.02) < 0.01, d"
(cd "$src" && env -u GEARLOSS_DATA_DIR "$built_bin" cycle configs/automatic-6speed.yaml --cycle nedc "${args[@]}" \
    > "$tmp/built.txt" 2> /dev/null)
check "installed: summary equal to the build tree's" cmp -s "$tmp/installed.txt" "$tmp/built.txt"
(cd "$tmp/elsewhere" && env -u GEARLOSS_DATA_DIR "$prefix/bin/gearloss" cycle "$tmp/case/automatic-6speed.yaml" \
    --cycle artemis --start-temp 20degC > "$tmp/artemis.txt" 2>&1)
rc=$?
check "installed: artemis (two shipped files), exit 0" test $rc -eq 0
[ $rc -eq 0 ] || cat "$tmp/artemis.txt"

# GEARLOSS_DATA_DIR at an empty folder: a clear error, exit 2.
(cd "$tmp/elsewhere" && GEARLOSS_DATA_DIR="$tmp/empty" "$prefix/bin/gearloss" cycle "$tmp/case/automatic-6speed.yaml" \
    --cycle nedc --start-temp 20degC > /dev/null 2> "$tmp/empty.err")
check "GEARLOSS_DATA_DIR empty: exit 2" test $? -eq 2
check "GEARLOSS_DATA_DIR empty: message names the variable, the folder and what is missing" \
    grep -qF "GEARLOSS_DATA_DIR=$tmp/empty (no cycles/ folder there)" "$tmp/empty.err"
check "GEARLOSS_DATA_DIR empty: message names the cycle" grep -qF "'nedc' is a shipped cycle" "$tmp/empty.err"
check "GEARLOSS_DATA_DIR empty: one line" test "$(wc -l < "$tmp/empty.err")" -eq 1

# A binary without data beside it: the places searched, then GEARLOSS_DATA_DIR.
cp "$prefix/bin/gearloss" "$tmp/lonely/bin/"
(cd "$tmp/elsewhere" && env -u GEARLOSS_DATA_DIR "$tmp/lonely/bin/gearloss" cycle "$tmp/case/automatic-6speed.yaml" \
    --cycle nedc --start-temp 20degC > /dev/null 2> "$tmp/lonely.err")
check "no data beside the binary: exit 2" test $? -eq 2
check "no data beside the binary: the places searched" \
    grep -qF "$tmp/lonely/share/gearloss (not a folder); $tmp/configs (not a folder)" "$tmp/lonely.err"
check "no data beside the binary: the hint" grep -qF "Set GEARLOSS_DATA_DIR" "$tmp/lonely.err"
(cd "$tmp/elsewhere" && GEARLOSS_DATA_DIR="$prefix/share/gearloss" "$tmp/lonely/bin/gearloss" cycle \
    "$tmp/case/automatic-6speed.yaml" --cycle nedc "${args[@]}" > "$tmp/lonely.txt" 2> "$tmp/lonely.err")
rc=$?
check "GEARLOSS_DATA_DIR set: exit 0" test $rc -eq 0
[ $rc -eq 0 ] || cat "$tmp/lonely.err"
check "GEARLOSS_DATA_DIR set: same summary" cmp -s "$tmp/lonely.txt" "$tmp/built.txt"

# A cycle file, and a case with its own cycles/ folder, need no data folder.
(cd "$tmp/elsewhere" && GEARLOSS_DATA_DIR="$tmp/empty" "$prefix/bin/gearloss" cycle "$tmp/case/automatic-6speed.yaml" \
    --cycle "$src/configs/cycles/nedc.csv" "${args[@]}" > "$tmp/file.txt" 2> "$tmp/file.err")
rc=$?
check "cycle file with an empty GEARLOSS_DATA_DIR: exit 0" test $rc -eq 0
[ $rc -eq 0 ] || cat "$tmp/file.err"
mkdir -p "$tmp/case/cycles" && cp "$src/configs/cycles/nedc.csv" "$tmp/case/cycles/"
(cd "$tmp/elsewhere" && GEARLOSS_DATA_DIR="$tmp/empty" "$prefix/bin/gearloss" cycle "$tmp/case/automatic-6speed.yaml" \
    --cycle nedc "${args[@]}" > "$tmp/local.txt" 2> "$tmp/local.err")
rc=$?
check "the case's own cycles/ first, no data folder needed: exit 0" test $rc -eq 0
[ $rc -eq 0 ] || cat "$tmp/local.err"
check "the case's own cycles/: same summary" cmp -s "$tmp/local.txt" "$tmp/built.txt"

# The installed Slurm array script names the installed binary (sbatch runs a spooled copy of
# it, which cannot look beside itself): run as a copy elsewhere, with no GEARLOSS, no gearloss
# on PATH and a submit folder without a build, it still finds it (array environment emulated).
check "installed slurm-map.sh" test -x "$prefix/share/gearloss/slurm-map.sh"
check "installed slurm-map.sh names the installed binary" grep -qF "installed_bin=\"$prefix/bin/gearloss\"" "$prefix/share/gearloss/slurm-map.sh"
mkdir -p "$tmp/spool"
cp "$prefix/share/gearloss/slurm-map.sh" "$tmp/spool/slurm_script"
(cd "$tmp/elsewhere" && env -u GEARLOSS PATH=/usr/bin:/bin SLURM_SUBMIT_DIR="$tmp/elsewhere" SLURM_JOB_ID=7 \
    SLURM_ARRAY_TASK_ID=2 SLURM_ARRAY_TASK_MIN=1 SLURM_ARRAY_TASK_MAX=2 SLURM_ARRAY_TASK_STEP=1 SLURM_ARRAY_TASK_COUNT=2 \
    bash "$tmp/spool/slurm_script" "$src/configs/transfer-box.yaml" "$tmp/shards" --speed 1000,2000rpm --torque 100Nm \
    > "$tmp/slurm.txt" 2>&1)
rc=$?
check "installed slurm-map.sh: exit 0" test $rc -eq 0
[ $rc -eq 0 ] || cat "$tmp/slurm.txt"
check "installed slurm-map.sh: used the installed binary" grep -qF "($prefix/bin/gearloss)" "$tmp/slurm.txt"
check "installed slurm-map.sh: shard 2/2 written" grep -q "^# gearloss shard 2/2:" "$tmp/shards/shard-2.csv"

echo "$pass passed, $fail failed"
test $fail -eq 0
