#!/usr/bin/env bash
# Bearing designations on the command line (docs/config.md, "Bearing designations"): `gearloss
# check` (text and --json) lists each bearing's resolved values with their sources; the values
# are compared with the catalogue rows read here by another route (PyYAML on the shipped YAML,
# and the raw line the location names); an unknown designation exits 2 with file:line:col and
# suggestions; a user catalogue file overrides a shipped row; NA 4905 and 6307 2Z resolve.
# Usage: cli_bearings.sh GEARLOSS_BINARY SOURCE_DIR
# Every file is written inside a private mktemp -d directory.
set -u
source "$(dirname "$0")/cli_common.sh" "$@"
py=/usr/bin/python3
cat_yaml=$src/configs/bearings/catalogue.yaml
cp -r "$src/configs/oils" "$tmp/oils"
cp "$src/configs/fzg-c40-paor-designations.yaml" "$tmp/fzg.yaml"

# A copy of the FZG case whose first bearing line (pinion_NJ406) is replaced by $2.
with_bearing() {  # with_bearing OUT_FILE 'YAML FLOW MAPPING'
    "$py" - "$tmp/fzg.yaml" "$1" "$2" <<'PY'
import sys
src, out, line = sys.argv[1:]
t = open(src).read().split("\n")
i = next(k for k, l in enumerate(t) if "name: pinion_NJ406" in l)
t[i] = "  - " + line
open(out, "w").write("\n".join(t))
PY
}

# Every resolved catalogue value of every bearing of a check --json equals the row of the
# shipped YAML (read with PyYAML), found by the designation's printed name; the location's line
# of the raw file holds that row.
compare_json() {  # compare_json CHECK_JSON EXPECTED_DESIGNATIONS...
    "$py" - "$cat_yaml" "$@" <<'PY'
import json, sys, yaml
cat_file, jfile, *want = sys.argv[1:]
cat = yaml.safe_load(open(cat_file))
lines = open(cat_file).read().split("\n")
rows = {}
for s in cat["series"]:
    for r in s["bearings"]:
        rows[r[0]] = (s, dict(zip(s["columns"], r)))
j = json.load(open(jfile))
seen = []
scale = {"d": 1e-3, "D": 1e-3, "B": 1e-3, "T": 1e-3, "C": 1e3, "C0": 1e3}
for b in j["bearings"]:
    if "designation" not in b:
        continue
    seen.append(b["designation"])
    s, row = rows[b["catalogue_entry"]]
    loc = b["catalogue_location"]
    assert loc.startswith("<gearloss data>/bearings/catalogue.yaml:"), loc
    line = int(loc.rsplit(":", 1)[1])
    assert '"%s"' % b["catalogue_entry"] in lines[line - 1], (loc, lines[line - 1])
    assert b["type"] == s["type"], (b["type"], s["type"])
    names = set()
    for v in b["resolved"]:
        if v["name"] == "seals":  # from the designation's suffix, checked below
            continue
        names.add(v["name"])
        assert v["source"] == "catalogue " + loc, v
        key = "T" if v["name"].startswith("B (= T") else v["name"]
        if key == "series":
            assert v["value"] == s["skf_series"], (v, s["skf_series"])
        elif key in scale:
            assert abs(v["value_si"] - row[key] * scale[key]) <= 1e-9 * abs(v["value_si"]), (b["name"], v, row)
    assert {"d", "D", "C0", "series"} <= names, names
assert seen == want, (seen, want)
PY
}

# 1. The shipped example: text and JSON.
"$bin" check "$tmp/fzg.yaml" > "$tmp/check.txt" 2> "$tmp/check.err"
check "check designations: exit 0" test $? -eq 0
check "check text: resolved block" grep -q '^bearing data as resolved' "$tmp/check.txt"
check "check text: NJ 406 row named by the data folder" \
    grep -qE "designation 'NJ 406' = catalogue row 'NJ 406' \(<gearloss data>/bearings/catalogue.yaml:[0-9]+\)" "$tmp/check.txt"
# NJ 406 in SKF (2008) 6000 RU: d 30, D 90, B 23 mm, C 60.5 kN, C0 53 kN, series 4.
nj_line=$(grep -n '"NJ 406"' "$cat_yaml" | cut -d: -f1)
check "check text: d = 30 mm from the row's line" grep -q "^    d = 30 mm \[catalogue <gearloss data>/bearings/catalogue.yaml:$nj_line\]" "$tmp/check.txt"
check "check text: C0 = 53 kN" grep -q "^    C0 = 53 kN \[catalogue <gearloss data>/bearings/catalogue.yaml:$nj_line\]" "$tmp/check.txt"
check "check text: no absolute path" bash -c "! grep -q '$src' '$tmp/check.txt'"
"$bin" check "$tmp/fzg.yaml" --json > "$tmp/check.json"
check "check --json: exit 0" test $? -eq 0
check "check --json: values equal the catalogue rows" compare_json "$tmp/check.json" "NJ 406" "QJ 308 N2MA" "NJ 406" "QJ 308 N2MA"

# 2. NA 4905 and 6307 2Z / 6307 2RS1 resolve (and to the right rows).
with_bearing "$tmp/na.yaml" "{name: pinion_NJ406, designation: NA 4905, shaft: pinion, position: -50 mm}"
"$bin" check "$tmp/na.yaml" --json > "$tmp/na.json" 2> "$tmp/na.err"
check "NA 4905: exit 0" test $? -eq 0
check "NA 4905: values equal the catalogue row" compare_json "$tmp/na.json" "NA 4905" "QJ 308 N2MA" "NJ 406" "QJ 308 N2MA"
check "NA 4905: d 25 D 42 B 17 (INA TPI 117; NTN CAT. 2300 prints the same)" "$py" - "$tmp/na.json" <<'PY'
import json, sys
b = json.load(open(sys.argv[1]))["bearings"][0]
v = {x["name"]: x.get("value_si") for x in b["resolved"]}
assert b["type"] == "needle_roller" and b["catalogue_entry"] == "NA4905-XL", b
assert (round(v["d"] * 1e3, 6), round(v["D"] * 1e3, 6), round(v["B"] * 1e3, 6)) == (25, 42, 17), v
PY
for d in "6307 2Z" "6307 2RS1" "6307 Z"; do
    with_bearing "$tmp/dg.yaml" "{name: pinion_NJ406, designation: $d, shaft: pinion, position: -50 mm}"
    "$bin" check "$tmp/dg.yaml" --json > "$tmp/dg.json" 2> "$tmp/dg.err"
    check "'$d': exit 0" test $? -eq 0
    check "'$d': the 6307 row" compare_json "$tmp/dg.json" "$d" "QJ 308 N2MA" "NJ 406" "QJ 308 N2MA"
    check "'$d': catalogue entry 6307" "$py" -c "import json,sys; assert json.load(open(sys.argv[1]))['bearings'][0]['catalogue_entry'] == '6307'" "$tmp/dg.json"
done
# The suffix's seals: 2RS1 two contact seals, RS1 one, 2Z shields (no contact), read from the
# designation where the block has no 'seals' key; 6307/2Z is 6307 with the suffix 2Z.
for d in "6307 2RS1|RS1 (both sides)" "6307-RS1|RS1 (one side)" "6307/2Z|no contact (2Z)" "6307 Z|no contact (Z)"; do
    with_bearing "$tmp/dg.yaml" "{name: pinion_NJ406, designation: ${d%%|*}, shaft: pinion, position: -50 mm}"
    "$bin" check "$tmp/dg.yaml" --json > "$tmp/dg.json" 2> "$tmp/dg.err"
    check "'${d%%|*}': seals '${d#*|}' from the suffix, row 6307" "$py" - "$tmp/dg.json" "${d#*|}" <<'PY'
import json, sys
b = json.load(open(sys.argv[1]))["bearings"][0]
seals = [v for v in b["resolved"] if v["name"] == "seals"]
assert b["catalogue_entry"] == "6307", b
assert len(seals) == 1 and seals[0]["value"] == sys.argv[2] and "designation suffix" in seals[0]["source"], seals
PY
done
# A contact-angle suffix on a deep groove ball bearing names no bearing: refused at the key.
with_bearing "$tmp/dg.yaml" "{name: pinion_NJ406, designation: 6307 BE, shaft: pinion, position: -50 mm}"
line=$(grep -n 'designation: 6307 BE' "$tmp/dg.yaml" | cut -d: -f1)
"$bin" check "$tmp/dg.yaml" > /dev/null 2> "$tmp/dg.err"
check "'6307 BE': exit 2 (got $?)" test $? -eq 2
check "'6307 BE': file:line, the contradiction named" grep -qE "dg.yaml:$line:[0-9]+: .*designation: 'BE' is a contact-angle suffix.*7307 BE" "$tmp/dg.err"

# 3. Unknown designation: exit 2, file:line:col, the key, suggestions.
with_bearing "$tmp/bad.yaml" "{name: pinion_NJ406, designation: 6397, shaft: pinion, position: -50 mm}"
line=$(grep -n 'designation: 6397' "$tmp/bad.yaml" | cut -d: -f1)
"$bin" check "$tmp/bad.yaml" > "$tmp/bad.out" 2> "$tmp/bad.err"
check "unknown designation: exit 2 (got $?)" test $? -eq 2
check "unknown designation: file:line:col" grep -qE "bad.yaml:$line:[0-9]+:" "$tmp/bad.err"
check "unknown designation: names the key and the closest rows" grep -qE "designation.*no bearing '6397'.*closest: .*6307" "$tmp/bad.err"
check "unknown designation: one line, nothing on stdout" test "$(wc -l < "$tmp/bad.err")" -eq 1 -a ! -s "$tmp/bad.out"

# 4. A user catalogue overrides the shipped 6307 (B 22, C0 20 instead of 21, 19) and is named
#    as the case writes it.
mkdir -p "$tmp/own"
cat > "$tmp/own/mine.yaml" <<'YAML'
format: gearloss-bearing-catalogue/1
series:
  - series: "63"
    type: deep_groove_ball
    skf_series: "63"
    columns: [designation, d, D, B, C, C0]
    bearings:
      - ["6307 X", 35, 80, 22, 36, 20]
YAML
with_bearing "$tmp/own.yaml" "{name: pinion_NJ406, designation: 6307 2Z, shaft: pinion, position: -50 mm}"
sed -i '1i bearing_catalogue: own/mine.yaml' "$tmp/own.yaml"
"$bin" check "$tmp/own.yaml" --json > "$tmp/own.json" 2> "$tmp/own.err"
check "user catalogue: exit 0" test $? -eq 0
check "user catalogue: its row, located as written" "$py" - "$tmp/own.json" <<'PY'
import json, sys
b = json.load(open(sys.argv[1]))["bearings"][0]
assert b["catalogue_entry"] == "6307 X" and b["catalogue_location"] == "own/mine.yaml:8", b
v = {x["name"]: x for x in b["resolved"]}
assert abs(v["B"]["value_si"] - 22e-3) < 1e-12 and abs(v["C0"]["value_si"] - 20e3) < 1e-6, v
assert v["B"]["source"] == "catalogue own/mine.yaml:8", v["B"]
PY
"$bin" check "$tmp/own.yaml" > "$tmp/own.txt"
check "user catalogue: text names own/mine.yaml:8" grep -q "^    B = 22 mm \[catalogue own/mine.yaml:8\]" "$tmp/own.txt"
# A designation found in neither file: the message counts the rows and names both files.
sed -i 's/designation: 6307 2Z/designation: 6397/' "$tmp/own.yaml"
"$bin" check "$tmp/own.yaml" > /dev/null 2> "$tmp/own.err"
check "user catalogue, unknown row: both files named" grep -qE "no bearing '6397' .*rows from <gearloss data>/bearings/catalogue.yaml and own/mine.yaml\)" "$tmp/own.err"
# The same bearing twice in one user file: which row is meant? Refused at the second row.
printf '      - ["6307 Y", 35, 80, 23, 36, 20]\n' >> "$tmp/own/mine.yaml"
"$bin" check "$tmp/own.yaml" > /dev/null 2> "$tmp/own.err"
check "duplicate row in a user catalogue: exit 2 (got $?)" test $? -eq 2
check "duplicate row in a user catalogue: own/mine.yaml:9, first at line 8" grep -qE "own/mine.yaml:9:[0-9]+: .*'6307 Y' is listed twice in this file \(first at line 8" "$tmp/own.err"

# 5. The shipped catalogue is an input of a case that takes rows from it: its sidecar names the
#    rows, and the case hash changes when the data folder's catalogue does (same case file).
hash_with_data() {  # hash_with_data DATA_DIR OUT_DIR
    mkdir -p "$2"
    (cd "$2" && GEARLOSS_DATA_DIR="$1" "$bin" map "$tmp/fzg.yaml" --speed 1000rpm --torque 100Nm -o m.csv) &&
        "$py" -c "import json,sys; print(json.load(open(sys.argv[1]))['case']['hash'])" "$2/m.csv.meta.json"
}
cp -r "$src/configs" "$tmp/data"
h1=$(hash_with_data "$tmp/data" "$tmp/run1")
echo "# a comment: same rows, other file" >> "$tmp/data/bearings/catalogue.yaml"
h2=$(hash_with_data "$tmp/data" "$tmp/run2")
check "shipped catalogue edited: case hash changes ($h1 -> $h2)" test -n "$h1" -a -n "$h2" -a "$h1" != "$h2"
check "shipped catalogue edited: same numbers" cmp -s "$tmp/run1/m.csv" "$tmp/run2/m.csv"
check "sidecar: rows and their locations" "$py" - "$tmp/run1/m.csv.meta.json" <<'PY'
import json, sys
rows = json.load(open(sys.argv[1]))["bearing_catalogue_rows"]
assert [r["designation"] for r in rows] == ["NJ 406", "QJ 308 N2MA", "NJ 406", "QJ 308 N2MA"], rows
assert all(r["location"].startswith("<gearloss data>/bearings/catalogue.yaml:") for r in rows), rows
PY

echo "cli_bearings: $pass passed, $fail failed"
test $fail -eq 0
