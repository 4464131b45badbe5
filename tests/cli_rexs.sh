#!/usr/bin/env bash
# REXS import on the command line (docs/rexs.md): the FVA two-stage industrial gearbox imports
# from .rexs (REXS 1.4 and 1.6) and .rexsj to the same case, `check` accepts it, `map` solves it,
# and its gear and oil data equal the REXS attributes read by an independent reader
# (tests/rexs_independent.py: xml.etree and PyYAML); the zipped example reads; the worm stage
# is refused naming its component; hostile files (truncated, wrong version, a relation to a
# missing component, a bearing outside its shaft, a contradicting centre distance) exit 2 with
# the file and the component id.
# Usage: cli_rexs.sh GEARLOSS_BINARY SOURCE_DIR
set -u
source "$(dirname "$0")/cli_common.sh" "$@"
py=/usr/bin/python3
data=$src/tests/data/rexs
fva14=$data/FVA-Industriegetriebe_2stufig_1-4.rexs

mkdir -p "$tmp/j" "$tmp/v16"
"$bin" import "$fva14" -o "$tmp/x.yaml" 2> "$tmp/x.err"
check "import .rexs: exit 0" test $? -eq 0
check "import .rexs: oil file beside the case" test -s "$tmp/x.oil.yaml"
check "import .rexs: warns about the tip diameter of gear 16 (1 mm)" grep -q "component 16 .*tip_diameter" "$tmp/x.err"
"$bin" import "$data/FVA-Industriegetriebe_2stufig_1-4.rexsj" -o "$tmp/j/x.yaml" 2> /dev/null
check "import .rexsj: exit 0" test $? -eq 0
# The same case but for the header line naming the model file.
check ".rexs and .rexsj: the same case" cmp -s <(grep -v "^# Imported from" "$tmp/x.yaml") <(grep -v "^# Imported from" "$tmp/j/x.yaml")
check ".rexs and .rexsj: the same oil" cmp -s <(grep -v "^# The lubricant" "$tmp/x.oil.yaml") <(grep -v "^# The lubricant" "$tmp/j/x.oil.yaml")
"$bin" import "$data/FVA-Industriegetriebe_2_stufig_1-6.rexs" -o "$tmp/v16/x.yaml" 2> /dev/null
check "import REXS 1.6: exit 0" test $? -eq 0
check "REXS 1.6: gear data equal its attributes (independent reader)" "$py" "$src/tests/rexs_independent.py" "$data/FVA-Industriegetriebe_2_stufig_1-6.rexs" "$tmp/v16/x.yaml" "$tmp/v16/x.oil.yaml"
check "gear data equal the REXS attributes (independent reader)" "$py" "$src/tests/rexs_independent.py" "$fva14" "$tmp/x.yaml" "$tmp/x.oil.yaml"
check "comments name the REXS component and attribute" grep -q "teeth: 27 .*# REXS 15 number_of_teeth" "$tmp/x.yaml"
"$bin" check "$tmp/x.yaml" > "$tmp/check.txt" 2>&1
check "check accepts the imported case" test $? -eq 0
"$bin" map "$tmp/x.yaml" -o "$tmp/map.csv" 2> "$tmp/map.err"
check "map solves the imported case" test $? -eq 0
# The same gearbox in REXS 1.6 (other component ids; its tapered bearings sit 2 mm elsewhere):
# the same mesh and churning losses at every load case.
"$bin" map "$tmp/v16/x.yaml" -o "$tmp/v16/map.csv" 2> /dev/null
check "REXS 1.4 and 1.6: the same mesh and churning losses" "$py" - "$tmp/map.csv" "$tmp/v16/map.csv" <<'PY'
import csv, sys
a, b = ([r for r in csv.DictReader(l for l in open(f) if not l.startswith("#"))] for f in sys.argv[1:3])
assert len(a) == len(b) == 4
for x, y in zip(a, b):
    for k in ("speed_in_rpm", "torque_in_Nm", "P_mesh_W", "P_churn_W"):
        assert x[k] == y[k], (k, x[k], y[k])
PY
check "map: every load case solved" "$py" - "$tmp/map.csv" <<'PY'
import csv, sys
rows = list(csv.DictReader(l for l in open(sys.argv[1]) if not l.startswith("#")))
assert len(rows) == 4, len(rows)
for r in rows:
    eff = float(r["efficiency"])
    assert 0.9 < eff < 1.0, eff
PY

# The zipped example: one .rexs member among other files.
"$bin" import "$data/example_xml.rexs.zip" -o "$tmp/z.yaml" 2> "$tmp/z.err"
check "zip: the member is read and named in messages" grep -q "example_xml.rexs.zip:example.rexs" "$tmp/z.err"

# The worm stage is refused naming its component id, type and name.
"$bin" import "$data/FVA_worm_stage_1-4.rexs" -o "$tmp/w.yaml" 2> "$tmp/w.err"
check "worm stage: exit 2" test $? -eq 2
check "worm stage: names its component" grep -qF "component 3 (worm_stage 'Schneckenstufe [3]')" "$tmp/w.err"
check "worm stage: no case written" test ! -e "$tmp/w.yaml"

hostile() {  # hostile NAME EXPECTED_REGEX PYTHON_EDIT   (edits the 1.4 .rexs text `t`)
    "$py" -c "t = open('$fva14', encoding='utf-8').read(); $3; open('$tmp/h.rexs', 'w', encoding='utf-8').write(t)"
    rm -f "$tmp/h.yaml"
    "$bin" import "$tmp/h.rexs" -o "$tmp/h.yaml" 2> "$tmp/h.err"
    local rc=$?
    check "$1: exit 2" test $rc -eq 2
    check "$1: message" grep -qE "$2" "$tmp/h.err"
    check "$1: no case written" test ! -e "$tmp/h.yaml"
}
hostile "truncated" "h.rexs:[0-9]+: .*not well-formed XML" "t = t[: len(t) // 2]"
hostile "wrong version" "h.rexs: model.version: REXS version '3.1'" "t = t.replace('version=\"1.4\"', 'version=\"3.1\"', 1)"
hostile "missing relation target" "h.rexs:[0-9]+: relation 5 .*component 999" "t = t.replace('<ref hint=\"cylindrical_gear\" id=\"15\" role=\"part\"/>', '<ref hint=\"cylindrical_gear\" id=\"999\" role=\"part\"/>', 1)"
hostile "duplicate id" "duplicate component id 13" "t = t.replace('<component id=\"14\" name=\"Shaft [42]\"', '<component id=\"13\" name=\"Shaft [42]\"', 1)"
hostile "bearing outside its shaft" "component 33 .*outside shaft 12" "t = t.replace('<attribute id=\"u_coordinate_on_shaft_inner_side\" unit=\"mm\">65</attribute>', '<attribute id=\"u_coordinate_on_shaft_inner_side\" unit=\"mm\">650</attribute>', 1)"
hostile "centre distance contradicts the axes" "component 19 .*center_distance 200 mm" "t = t.replace('<attribute id=\"center_distance\" unit=\"mm\">190</attribute>', '<attribute id=\"center_distance\" unit=\"mm\">200</attribute>', 1)"
hostile "length in a wrong unit" "component 15 .*face_width.*unit 'kg'" "t = t.replace('<attribute id=\"face_width\" unit=\"mm\">50</attribute>', '<attribute id=\"face_width\" unit=\"kg\">50</attribute>', 1)"
hostile "deep nesting" "nested deeper" "t = t.replace('<components>', '<components>' + '<x>' * 100 + '</x>' * 100, 1)"
# JSON: truncated.
head -c 5000 "$data/FVA-Industriegetriebe_2stufig_1-4.rexsj" > "$tmp/t.rexsj"
"$bin" import "$tmp/t.rexsj" -o "$tmp/t.yaml" 2> "$tmp/t.err"
check "truncated JSON: exit 2" test $? -eq 2
check "truncated JSON: names the file" grep -q "t.rexsj: .*not valid JSON" "$tmp/t.err"
# Hostile models beyond the edits above (scripts/fuzz-cli.py draws the same kinds at random):
# each exits 2 naming the file (and the component where there is one), writes nothing, and
# does not crash.
hostile_file() {  # hostile_file NAME FILE EXPECTED_REGEX
    rm -f "$tmp/hf.yaml"
    "$bin" import "$2" -o "$tmp/hf.yaml" 2> "$tmp/hf.err"
    local rc=$?
    check "$1: exit 2" test $rc -eq 2
    check "$1: message" grep -qE "$3" "$tmp/hf.err"
    check "$1: no case written" test ! -e "$tmp/hf.yaml"
}
: > "$tmp/empty.rexs"
hostile_file "empty file" "$tmp/empty.rexs" "empty.rexs.*(empty|not well-formed|no model)"
: > "$tmp/empty.rexsj"
hostile_file "empty JSON file" "$tmp/empty.rexsj" "empty.rexsj.*(empty|not valid JSON)"
hostile "assembly loop" "relation 9999 \\(assembly\\): assembly relations form a loop: component 12" "t = t.replace('<relations>', '<relations><relation id=\"9999\" type=\"assembly\"><ref hint=\"cylindrical_gear\" id=\"15\" role=\"assembly\"/><ref hint=\"shaft\" id=\"12\" role=\"part\"/></relation>', 1)"
hostile "huge number" "component 15 .*face_width.*out of the range" "t = t.replace('<attribute id=\"face_width\" unit=\"mm\">50</attribute>', '<attribute id=\"face_width\" unit=\"mm\">1e308</attribute>', 1)"
hostile "NaN value" "component 15 .*face_width.*not a finite number" "t = t.replace('<attribute id=\"face_width\" unit=\"mm\">50</attribute>', '<attribute id=\"face_width\" unit=\"mm\">NaN</attribute>', 1)"
hostile "inf value" "component 15 .*normal_module.*not a finite number" "t = t.replace('<attribute id=\"normal_module\" unit=\"mm\">4.5</attribute>', '<attribute id=\"normal_module\" unit=\"mm\">inf</attribute>', 1)"
hostile "unknown unit" "component 15 .*face_width.*unit 'furlong'" "t = t.replace('<attribute id=\"face_width\" unit=\"mm\">50</attribute>', '<attribute id=\"face_width\" unit=\"furlong\">50</attribute>', 1)"
hostile "negative module" "does not load: .*h.yaml:[0-9]+.*REXS 15 normal_module" "t = t.replace('<attribute id=\"normal_module\" unit=\"mm\">4.5</attribute>', '<attribute id=\"normal_module\" unit=\"mm\">-4.5</attribute>', 1)"
"$py" - "$data/FVA-Industriegetriebe_2stufig_1-4.rexsj" "$tmp/dup.rexsj" <<'PY'
import re, sys
t = open(sys.argv[1], encoding="utf-8").read()
head, comps = t.split('"components"', 1)  # the component 14, not a ref to it
open(sys.argv[2], "w", encoding="utf-8").write(head + '"components"' + re.sub(r'("id" ?: ?)14\b', r"\g<1>13", comps, count=1))
PY
hostile_file "duplicate id (JSON)" "$tmp/dup.rexsj" "dup.rexsj: .*duplicate component id 13"
# A number beyond a double in JSON (1e400) is an input error, not an internal one.
sed 's/"floating_point" : 50\.0/"floating_point" : 1e400/; s/"floating_point": 50\.0/"floating_point": 1e400/' \
    "$data/FVA-Industriegetriebe_2stufig_1-4.rexsj" > "$tmp/over.rexsj"
check "1e400 in JSON: the edit took" grep -q "1e400" "$tmp/over.rexsj"
hostile_file "1e400 in JSON" "$tmp/over.rexsj" "over.rexsj: not a valid REXS value: .*number overflow"
# Archives: a member that unpacks to 48 MiB (within the 64 MiB bound) of an XML comment reads;
# one that unpacks to 70 MiB is refused as it unpacks (its header is not trusted).
"$py" - "$fva14" "$tmp" <<'PY'
import sys, zipfile
t = open(sys.argv[1], encoding="utf-8").read()
for name, mib in (("big", 48), ("over", 70)):
    with zipfile.ZipFile(f"{sys.argv[2]}/{name}.rexsz", "w", zipfile.ZIP_DEFLATED) as z:
        z.writestr("model.rexs", t.replace("\n", "\n<!--" + " " * (mib << 20) + "-->", 1))
PY
"$bin" import "$tmp/big.rexsz" -o "$tmp/big.yaml" 2> /dev/null
check "48 MiB member within the bound: imported" test $? -eq 0
hostile_file "70 MiB member" "$tmp/over.rexsz" "over.rexsz.*(64 MiB|larger|bound|exceeds)"

# The values REXS does not carry are listed by check with their source and in the map sidecar.
check "check lists the assumed oil level with its source" grep -qE "housing.oil_level = .*source: REXS import" "$tmp/check.txt"
check "map sidecar lists the assumed oil level" "$py" - "$tmp/map.csv.meta.json" <<'PY'
import json, sys
a = {x["key"]: x for x in json.load(open(sys.argv[1]))["assumed"]}
assert a["housing.oil_level"]["source"] == "REXS import", a.get("housing.oil_level")
assert a["thermal.heat_rejection.housing"]["reason"].startswith("REXS gives no casing geometry")
PY

# An output onto the model is refused (io::require_safe_outputs).
cp "$fva14" "$tmp/same.rexs"
"$bin" import "$tmp/same.rexs" -o "$tmp/same.rexs" 2> /dev/null
check "output onto the model: refused" test $? -eq 2
check "output onto the model: model intact" cmp -s "$fva14" "$tmp/same.rexs"

echo "cli_rexs: $pass passed, $fail failed"
test $fail -eq 0
