#!/usr/bin/env bash
# End-to-end checks of bounded parsing (issue 13, "Parsers are bounded" and the recordings
# parts of "diagnose never aborts"): every hostile input below ends with exit 2 and a
# located message of the expected class, within a few seconds, quoting nothing it should not.
# Usage: cli_bounded_inputs.sh GEARLOSS_BINARY SOURCE_DIR
# Every file (FIFOs included) is made inside the private mktemp -d directory.
set -u
source "$(dirname "$0")/cli_common.sh" "$@"
cp -r "$src/configs/oils" "$tmp/oils"
cp "$src/configs/transfer-box.yaml" "$tmp/tb.yaml"
tb=$tmp/tb.yaml
T="timeout -k 5 20"  # a hang is a failure (exit 124 or 137), never a stuck test

# expect NAME PATTERN COMMAND...: exit 2 and PATTERN (grep -E) in stderr.
expect() {
    local name=$1 pattern=$2
    shift 2
    $T "$@" > "$tmp/out" 2> "$tmp/err"
    local rc=$?
    check "$name: exit 2 (got $rc)" test $rc -eq 2
    check "$name: message /$pattern/" grep -qE -- "$pattern" "$tmp/err"
    check "$name: message at most one short line" test "$(wc -c < "$tmp/err")" -lt 800
}

# 1. Units: nesting depth and overflow (command line and file).
deep=$(printf '(%.0s' $(seq 50000))Nm$(printf ')%.0s' $(seq 50000))
expect "--torque with 50000 nested parentheses" "--torque: .*unit nested too deeply" \
    "$bin" point "$tb" --speed 800rpm --torque "100 $deep" --oil-temp 70degC
expect "--torque 1e308 kNm" "--torque: .*out of range" "$bin" point "$tb" --speed 800rpm --torque 1e308kNm --oil-temp 70degC
expect "--speed 1e308 kHz" "--speed: .*out of range" "$bin" point "$tb" --speed 1e308kHz --torque 100Nm --oil-temp 70degC
expect "map --torque list with 1e308 kNm" "--torque: .*out of range" \
    "$bin" map "$tb" --speed 800rpm --torque 100,1e308kNm --oil-temp 70degC -o "$tmp/m.csv"
sed 's/oil_volume: 2 L /oil_volume: 1e308 km^3/' "$tb" > "$tmp/huge.yaml"
expect "file value 1e308 km^3" "huge.yaml:[0-9]+:[0-9]+: housing.oil_volume: .*out of range" "$bin" check "$tmp/huge.yaml"
# 50 000 parentheses in a file, folded over short lines.
awk -v opening="$(printf '(%.0s' $(seq 10000))" -v closing="$(printf ')%.0s' $(seq 50000))" '
    /oil_volume:/ { print "  oil_volume: 2"; for (i = 0; i < 5; i++) print "    " opening; print "    L" closing; next }
    { print }' "$tb" > "$tmp/parens.yaml"
expect "file unit with 50000 nested parentheses" "parens.yaml:[0-9]+:[0-9]+: housing.oil_volume: .*unit nested too deeply" \
    "$bin" check "$tmp/parens.yaml"

# 2. YAML: alias expansion, depth, a second document, line length.
{
    echo "name: bomb"
    echo "a0: &a0 [x, x]"
    for i in $(seq 1 64); do echo "a$i: &a$i [*a$((i - 1)), *a$((i - 1))]"; done
} > "$tmp/bomb.yaml"
expect "64 levels of aliases" "bomb.yaml:[0-9]+:[0-9]+: too many nodes after alias expansion" "$bin" check "$tmp/bomb.yaml"
{ echo "name: deep"; echo "shafts: $(printf '[%.0s' $(seq 100))$(printf ']%.0s' $(seq 100))"; } > "$tmp/deep.yaml"
expect "100 nested lists" "deep.yaml:2:[0-9]+: YAML nested too deeply" "$bin" check "$tmp/deep.yaml"
{ cat "$tb"; echo "---"; echo "{[broken"; } > "$tmp/two.yaml"
line=$(($(wc -l < "$tb") + 1))
expect "a second (broken) document" "two.yaml:$line:1: a second YAML document" "$bin" check "$tmp/two.yaml"
{ cat "$tb"; echo "note_x: $(head -c 70000 /dev/zero | tr '\0' x)"; } > "$tmp/long.yaml"
expect "a 70000-byte line" "long.yaml:$line: line longer than 65536 bytes" "$bin" check "$tmp/long.yaml"
check "a 70000-byte line is not quoted" bash -c "! grep -q xxxxxxxxxx '$tmp/err'"

# 3. Only regular files: FIFOs, devices, directories are refused by name, unread.
mkfifo "$tmp/fifo"
expect "check FIFO" "fifo: is not a regular file \(a FIFO\)" "$bin" check "$tmp/fifo"
expect "check /dev/zero" "/dev/zero: is not a regular file \(a character device\)" "$bin" check /dev/zero
expect "check a directory" "is not a regular file \(a directory\)" "$bin" check "$tmp"
expect "--oil /dev/urandom" "/dev/urandom: is not a regular file" \
    "$bin" point "$tb" --oil /dev/urandom --speed 800rpm --torque 100Nm --oil-temp 70degC
expect "--oil FIFO" "fifo: is not a regular file" "$bin" point "$tb" --oil "$tmp/fifo" --speed 800rpm --torque 100Nm
expect "diagnose recordings FIFO" "fifo: is not a regular file" "$bin" diagnose "$tb" "$tmp/fifo"
expect "diagnose recordings /dev/zero" "/dev/zero: is not a regular file" "$bin" diagnose "$tb" /dev/zero
expect "cycle file FIFO" "fifo: is not a regular file" \
    "$bin" cycle "$src/configs/automatic-6speed.yaml" --cycle "$tmp/fifo" --start-temp -10degC
expect "cycle file directory" "is not a regular file \(a directory\)" \
    "$bin" cycle "$src/configs/automatic-6speed.yaml" --cycle "$tmp" --start-temp -10degC

# 4. Messages never quote a file that is not YAML/CSV.
printf 'root:$6$Zq9ab$SECRETHASHSECRETHASH:19000:0:99999:7:::\ndaemon:*:19000:0:99999:7:::\n' > "$tmp/shadow"
expect "check a shadow-like file" "does not look like a gearloss file" "$bin" check "$tmp/shadow"
check "check a shadow-like file quotes nothing" bash -c "! grep -qE 'root|SECRET|daemon' '$tmp/err'"
expect "diagnose a shadow-like file" "not a gearloss recordings CSV" "$bin" diagnose "$tb" "$tmp/shadow"
check "diagnose a shadow-like file quotes nothing" bash -c "! grep -qE 'root|SECRET|daemon' '$tmp/err'"
expect "--oil a shadow-like file" "does not look like a gearloss file" \
    "$bin" point "$tb" --oil "$tmp/shadow" --speed 800rpm --torque 100Nm
check "--oil a shadow-like file quotes nothing" bash -c "! grep -qE 'root|SECRET|daemon' '$tmp/err'"
{ printf 'GIF89a'; head -c 2000 /dev/urandom; printf 'SECRETTAIL'; } > "$tmp/junk"
expect "check binary junk" "junk:[0-9]+:[0-9]+: control byte 0x[0-9A-F]{2}: not a text" "$bin" check "$tmp/junk"
check "check binary junk quotes nothing" bash -c "! grep -qE 'GIF89a|SECRETTAIL' '$tmp/err'"

# 5. Component names: check --json must never emit invalid JSON.
sed 's/{name: w1,/{name: "w\xe4rme",/; s/\[w2, w1\]/[w2, "w\xe4rme"]/' "$tb" > "$tmp/latin1.yaml"
expect "Latin-1 gear name" "latin1.yaml:[0-9]+:[0-9]+: gears\[0\]\.name: .*printable UTF-8" "$bin" check "$tmp/latin1.yaml" --json
check "Latin-1 gear name: no JSON written" test ! -s "$tmp/out"
sed 's/{name: output_seal,/{name: input_seal,/' "$tb" > "$tmp/seals.yaml"
expect "duplicate seal names" "seals.yaml:[0-9]+:[0-9]+: seals\[1\]\.name: duplicate seal name 'input_seal'" "$bin" check "$tmp/seals.yaml"
sed 's/{name: m24,/{name: m12,/' "$tb" > "$tmp/meshes.yaml"
expect "duplicate mesh names" "duplicate mesh name 'm12'" "$bin" check "$tmp/meshes.yaml"
sed 's/{name: w1,/{name: "w1\\nx",/' "$tb" > "$tmp/newline.yaml"
expect "gear name with a line break" "gears\[0\]\.name: .*printable UTF-8" "$bin" check "$tmp/newline.yaml"

# 6. Recordings: duplicates, separators, bad cells, time stamps.
"$bin" synth "$tb" --seed 1 -o "$tmp/rec.csv" 2> /dev/null
{ cat "$tmp/rec.csv"; sed -n 2p "$tmp/rec.csv"; } > "$tmp/dup.csv"
dupline=$(wc -l < "$tmp/dup.csv")
$T "$bin" diagnose "$tb" "$tmp/dup.csv" --threads 2 > "$tmp/dup.out" 2> "$tmp/dup.err"
check "duplicate recording row: exit 0" test $? -eq 0
check "duplicate recording row: warning naming both lines" \
    grep -q "dup.csv:$dupline: row repeats line 2 exactly; counted once" "$tmp/dup.out" "$tmp/dup.err"
# Semicolon- and tab-separated copies (the separator detected from the header) diagnose as the
# comma-separated file does; with decimal commas too (a European spreadsheet) the first number
# is refused at its cell, naming the separator found.
"$bin" diagnose "$tb" "$tmp/rec.csv" --bootstrap 4 > "$tmp/comma.out" 2> /dev/null
tr ',' ';' < "$tmp/rec.csv" > "$tmp/semi.csv"
tr ',' '\t' < "$tmp/rec.csv" > "$tmp/tab.csv"
for f in semi tab; do
    $T "$bin" diagnose "$tb" "$tmp/$f.csv" --bootstrap 4 > "$tmp/$f.out" 2> /dev/null
    check "$f-separated recordings: exit 0 (got $?)" test $? -eq 0
    check "$f-separated recordings: the comma file's diagnosis" cmp -s <(sed "s/$f\.csv/rec.csv/g" "$tmp/$f.out") "$tmp/comma.out"
done
tr ',.' ';,' < "$tmp/rec.csv" > "$tmp/semi-dc.csv"
expect "decimal-comma recordings" "semi-dc.csv:2:[0-9]+: [a-zA-Z_]+: '[0-9]+,[0-9]+' has a decimal comma.*separated by ';' \(detected\)" \
    "$bin" diagnose "$tb" "$tmp/semi-dc.csv"
printf 'speed_in_rpm,torque_in_Nm,P_loss_W\n600,150,210\n700,abc,240\n' > "$tmp/cell.csv"
expect "bad cell" "cell.csv:3:2: torque_in_Nm: 'abc' is not a number" "$bin" diagnose "$tb" "$tmp/cell.csv"
printf 'speed_in_rpm,torque_in_Nm,P_loss_W\n600,150,nan\n' > "$tmp/nan.csv"
expect "nan cell" "nan.csv:2:3: P_loss_W: 'nan' is out of range" "$bin" diagnose "$tb" "$tmp/nan.csv"
{
    echo "time_s,speed_in_rpm,speed_out_rpm,torque_in_Nm,torque_out_Nm,oil_temp_C,room_temp_C"
    for i in $(seq 0 39); do echo "$((5000000000000000000 + 2048 * i)),600,261,150,340,40,25"; done
} > "$tmp/far.csv"
expect "time_s near 5e18" "far.csv:2:1: time_s: time 5e\+18 s is out of range" "$bin" diagnose "$tb" "$tmp/far.csv"

echo "$pass passed, $fail failed"
test $fail -eq 0
