#!/usr/bin/env bash
# REXS import on the command line (docs/rexs.md): the FVA two-stage industrial gearbox imports
# from .rexs (REXS 1.4 and 1.6) and .rexsj to the same case, `check` accepts it, `map` solves it,
# and its gear and oil data equal the REXS attributes read by an independent reader
# (tests/rexs_independent.py: xml.etree and PyYAML); the zipped example reads; the worm stage
# is refused naming its component; hostile files (truncated, wrong version, a relation to a
# missing component, a bearing outside its shaft, a contradicting centre distance) exit 2 with
# the file and the component id; the hand-made planetary, two-stage planetary and idler models
# import with the ratios worked out from their tooth numbers, and hostile planetary forms are
# refused at the component; public models of other exporters (SEW 1.0, the FVA planetary stage
# 1.1, the worm stage in JSON) import or are refused at the component.
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

# Gear-train topology on the hand-made models (tests/data/rexs/README.md): the ratios `check`
# prints equal those worked out from the tooth numbers. Planetary stage, sun 16, ring 62 held,
# carrier output: i = 1 + 62/16 = 4.875. Two such stages in series (the second 19/71):
# i = 4.875 (1 + 71/19) = 23.09211. Idler train 20-31-40, 18-45: n_out/n_in = -(20/40)(18/45) = -0.2.
mkdir -p "$tmp/topo"
for m in planetary_1-4 planetary_1-2 planetary_two_stage_1-4 idler_3stage_1-4 idler_3stage_1-2 idler_3stage_1-0; do
    "$bin" import "$data/handmade_$m.rexs" -o "$tmp/topo/$m.yaml" 2> /dev/null
    check "hand-made $m: import exit 0" test $? -eq 0
    "$bin" check "$tmp/topo/$m.yaml" > "$tmp/topo/$m.check" 2>&1
    check "hand-made $m: check accepts it" test $? -eq 0
done
check "planetary: i = 4.875" grep -q "i = n_in/n_out = 4.87500)" "$tmp/topo/planetary_1-4.check"
check "planetary REXS 1.2: i = 4.875" grep -q "i = n_in/n_out = 4.87500)" "$tmp/topo/planetary_1-2.check"
check "two planetary stages: i = 23.09211" grep -q "i = n_in/n_out = 23.09211)" "$tmp/topo/planetary_two_stage_1-4.check"
check "idler: n_out/n_in = -0.2 (output reversed)" grep -q "n_out/n_in = -0.200000 " "$tmp/topo/idler_3stage_1-4.check"
check "idler REXS 1.0: n_out/n_in = -0.2" grep -q "n_out/n_in = -0.200000 " "$tmp/topo/idler_3stage_1-0.check"
check "idler REXS 1.0: bearings by their catalogue designation ('name' in 1.0)" grep -q 'designation: "6206" .*# REXS 115 name' "$tmp/topo/idler_3stage_1-0.yaml"
check "idler REXS 1.2 and 1.4: the same case" cmp -s <(grep -v "^# Imported from\|^oil:" "$tmp/topo/idler_3stage_1-4.yaml") <(grep -v "^# Imported from\|^oil:" "$tmp/topo/idler_3stage_1-2.yaml")
"$bin" map "$tmp/topo/planetary_1-4.yaml" -o "$tmp/topo/p.csv" 2> /dev/null
check "planetary: map solves it" test $? -eq 0
check "planetary: efficiency of every load case plausible" "$py" - "$tmp/topo/p.csv" <<'PY'
import csv, sys
rows = list(csv.DictReader(l for l in open(sys.argv[1]) if not l.startswith("#")))
assert len(rows) == 2, len(rows)
for r in rows:
    assert 0.95 < float(r["efficiency"]) < 1.0, r["efficiency"]
PY
pl=$data/handmade_planetary_1-4.rexs
hostile_pl() {  # hostile_pl NAME EXPECTED_REGEX PYTHON_EDIT   (edits the planetary model's text `t`)
    "$py" -c "t = open('$pl', encoding='utf-8').read(); $3; open('$tmp/hp.rexs', 'w', encoding='utf-8').write(t)"
    rm -f "$tmp/hp.yaml"
    "$bin" import "$tmp/hp.rexs" -o "$tmp/hp.yaml" 2> "$tmp/hp.err"
    check "$1: exit 2" test $? -eq 2
    check "$1: message" grep -qE "$2" "$tmp/hp.err"
}
hostile_pl "planetary stage without its carrier relation" "hp.rexs:[0-9]+: component 5 \(planetary_stage 'Planetary stage'\): no planet_carrier_shaft" "t = t.replace('type=\"planet_carrier_shaft\"', 'type=\"other\"')"
hostile_pl "ring gear that is external" "component 23 \(cylindrical_gear 'Ring'\): .*external gear" "t = t.replace('ring_gear', 'cylindrical_gear')"

# Public models the importer was not written against (tests/data/rexs/README.md).
# SEW three-stage helical gearbox, FVA-Workbench 5.0.4, REXS 1.0: no lubricant component (the oil
# is given with --oil), angles in the degree sign, a bearing's designation in `name`, shaft 36 on
# three bearings (u = 13.5, 66 and 135 mm: statically indeterminate; the NUP at 66 mm is nearer
# 13.5, 52.5 mm against 69 mm, and is written there, paired).
sew=$data/SEW_3-stage_cylindrical_gearbox_1.0.rexs
mkdir -p "$tmp/sew"
"$bin" import "$sew" -o "$tmp/sew/x.yaml" 2> "$tmp/sew/err"
check "SEW 1.0 without a lubricant: exit 2" test $? -eq 2
check "SEW 1.0 without a lubricant: says to give --oil" grep -q "no lubricant component: give an oil file with --oil" "$tmp/sew/err"
"$bin" import "$sew" -o "$tmp/sew/x.yaml" --oil "$src/configs/oils/MINR.yaml" 2> "$tmp/sew/err"
check "SEW 1.0 with --oil: exit 0" test $? -eq 0
check "SEW 1.0: gear data equal its attributes (independent reader)" "$py" "$src/tests/rexs_independent.py" "$sew" "$tmp/sew/x.yaml" -
check "SEW 1.0: the middle bearing of shaft 36 paired with the nearer outer one" grep -qE "position: 13.5 mm +# assumed: REXS 50 u_coordinate_on_shaft_inner_side \[mm\] = 66 mm" "$tmp/sew/x.yaml"
check "SEW 1.0: a warning names the bearing and its shaft" grep -q "component 50 .*shaft 36 has bearings at 3 axial positions" "$tmp/sew/err"
"$bin" check "$tmp/sew/x.yaml" > /dev/null 2>&1
check "SEW 1.0: check accepts the imported case" test $? -eq 0
"$bin" map "$tmp/sew/x.yaml" -o "$tmp/sew/map.csv" 2> /dev/null
check "SEW 1.0: map solves the imported case" test $? -eq 0
# The worm stage in JSON writes enums without a value as null: read as absent, the stage refused.
"$bin" import "$data/FVA_worm_stage_1-4.rexsj" -o "$tmp/w.yaml" 2> "$tmp/w.err"
check "worm stage JSON (null values): refused at the worm stage" grep -qE "component [0-9]+ \(worm_stage 'Schneckenstufe \[3\]'\): .*not represented" "$tmp/w.err"
# FVA planetary stage, FVA-Workbench 5.5, REXS 1.1: a two-cheek carrier of two coaxial shafts
# (4 with the bearings and the load, 6 joined to it through couplings) and a connecting shaft 260
# with no gear and no bearing. As published its concept bearings (REXS 1.1 gives them no
# diameters) take the shafts' bores, 43.2 mm for the planets, which have no catalogue row for an
# assumed bearing: the nearest bore's row is scaled to it.
fpl=$data/FVA_Planetary_stage_-_Minus_gearing_1.1.rexs
"$bin" import "$fpl" -o "$tmp/pl.yaml" 2> "$tmp/pl.err"
check "FVA planetary 1.1 as published: exit 0" test $? -eq 0
check "FVA planetary 1.1: the carrier of two shafts is not refused" bash -c "! grep -q 'planet_carrier_shaft' '$tmp/pl.err'"
# Its planet bearing 232 (a concept bearing taking axial load: deep groove ball) sits on the
# 43.2 mm planet pin; the catalogue's deep groove ball bearings nearest that bore are at 45 mm,
# the lightest 16009 (configs/bearings/catalogue.yaml: 45 x 75 x 10 mm, C0 10.8 kN). Scaled by
# 43.2/45 = 0.96: D = 72 mm, B = 9.6 mm, C0 = 10.8 x 0.96^2 = 9.95328 kN, series 160, declared assumed.
check "FVA planetary 1.1: the 43.2 mm planet bearing scaled from 16009 (warning)" grep -q "component 232 .*no catalogue deep_groove_ball bearing of bore 43.2 mm: assumed as 16009 x 0.96 (bore 45 mm)" "$tmp/pl.err"
check "FVA planetary 1.1: D = 75 x 0.96 = 72 mm" bash -c "grep -A10 'name: bearing_232 ' '$tmp/pl.yaml' | grep -q 'D: 72 mm'"
check "FVA planetary 1.1: B = 10 x 0.96 = 9.6 mm" bash -c "grep -A10 'name: bearing_232 ' '$tmp/pl.yaml' | grep -q 'B: 9.6 mm'"
check "FVA planetary 1.1: C0 = 10.8 x 0.9216 = 9.95328 kN" bash -c "grep -A10 'name: bearing_232 ' '$tmp/pl.yaml' | grep -q 'C0: 9.95328 kN'"
check "FVA planetary 1.1: the scaled values are declared assumed" grep -q "key: bearings.bearing_232.C0, reason: \"catalogue row 16009 x 0.96" "$tmp/pl.yaml"
"$bin" check "$tmp/pl.yaml" > "$tmp/pl.check" 2>&1
check "FVA planetary 1.1 as published: check accepts it, i = 1 + 61/17 = 4.58824" grep -q "i = n_in/n_out = 4.58824)" "$tmp/pl.check"
"$bin" map "$tmp/pl.yaml" -o "$tmp/pl.csv" 2> /dev/null
check "FVA planetary 1.1 as published: map solves it" test $? -eq 0
# With catalogue bores given to its concept bearings (REXS 1.3 names, inner_diameter): sun 17,
# ring 61 (held: connected to the housing only), carrier output, i = 1 + 61/17 = 4.58824.
"$py" - "$fpl" "$tmp/pl3.rexs" <<'PY'
import re, sys
t = open(sys.argv[1], encoding="utf-8").read().replace('version="1.1"', 'version="1.3"', 1)
for cid, d in {"232": 45, "233": 45, "234": 45, "244": 45, "245": 45, "246": 45, "36": 35, "37": 35, "59": 60, "60": 60}.items():
    t, n = re.subn(r'(<component id="%s" [^>]*type="concept_bearing"[^>]*>)' % cid,
                   r'\1<attribute id="inner_diameter" unit="mm">%d</attribute>' % d, t)
    assert n == 1, cid
open(sys.argv[2], "w", encoding="utf-8").write(t)
PY
"$bin" import "$tmp/pl3.rexs" -o "$tmp/pl3.yaml" 2> "$tmp/pl3.err"
check "FVA planetary (bores given): exit 0" test $? -eq 0
check "FVA planetary: shaft 6 a part of the carrier, shaft 4" grep -q "^# shaft_6 (REXS 6): a part of the carrier of planetary stage 9 .*turning with shaft 4" "$tmp/pl3.yaml"
check "FVA planetary: the connecting shaft 260 set aside with a warning" grep -q "component 260 (shaft 'Shaft \[260\]'): the shaft carries no gear and sits in no bearing" "$tmp/pl3.err"
"$bin" check "$tmp/pl3.yaml" > "$tmp/pl3.check" 2>&1
check "FVA planetary: check accepts it" test $? -eq 0
check "FVA planetary: i = 1 + 61/17 = 4.58824" grep -q "i = n_in/n_out = 4.58824)" "$tmp/pl3.check"
"$bin" map "$tmp/pl3.yaml" -o "$tmp/pl3.csv" 2> /dev/null
check "FVA planetary: map solves it" test $? -eq 0

echo "cli_rexs: $pass passed, $fail failed"
test $fail -eq 0
