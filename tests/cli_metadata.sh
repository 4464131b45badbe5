#!/usr/bin/env bash
# Self-describing outputs (issue 17, item 3; docs/outputs.md): the sidecar FILE.meta.json of
# every CSV written to a file, checked against the case read here independently (the YAML
# file), VECTO's '#' provenance lines, point --json against the text report and the map row,
# compare with three oils against two-oil runs, compare --detail against its totals.
# Every file is written in a mktemp -d directory.
# Usage: cli_metadata.sh GEARLOSS_BINARY SOURCE_DIR
set -u
source "$(dirname "$0")/cli_common.sh" "$@"
py=/usr/bin/python3
cd "$tmp" || exit 1
cp -r "$src/configs" .
box=configs/transfer-box.yaml
oils=configs/oils
small=(--speed 600,800rpm --torque 150,250Nm)
# json FILE EXPRESSION: the Python expression (d = the document) is true.
json() { "$py" -c "import json,sys; d=json.load(open(sys.argv[1])); sys.exit(0 if ($2) else 1)" "$1"; }
keys='all(k in d for k in ("format","gearloss_version","command","command_line","case","thermal","ratio","model_forms","assumed","sweep","columns")) and d["format"]=="gearloss-metadata/1"'
# The CSV's header equals the sidecar's column names, in order.
columns_match() {
    "$py" - "$1" <<'PY'
import csv, json, sys
f = sys.argv[1]
rows = [r for r in csv.reader(open(f)) if r and not r[0].startswith("#")]
names = [c["name"] for c in json.load(open(f + ".meta.json"))["columns"]]
sys.exit(0 if rows[0] == names else 1)
PY
}
# The oil's name as its YAML file writes it (read here, not by gearloss).
oil_name() { "$py" -c "import sys; print([l.split(':',1)[1].strip() for l in open(sys.argv[1]) if l.startswith('name:')][0])" "$1"; }

# map: schema keys, columns = header, oil name from the oil file, thermal mode as the case says.
"$bin" map "$box" "${small[@]}" -o map.csv 2> /dev/null
check "map: sidecar written" test -f map.csv.meta.json
check "map: schema keys" json map.csv.meta.json "$keys"
check "map: columns = CSV header" columns_match map.csv
name=$(oil_name "$oils/75W90-A.yaml")
check "map: oil name from the oil file ($name)" json map.csv.meta.json "d['oil']['name']=='$name' and d['oil']['base']=='PAO'"
check "map: stabilised mode, no fixed temperature" json map.csv.meta.json "d['thermal']['mode']=='stabilised' and d['thermal']['oil_temperature_C'] is None"
check "map: command line and command" json map.csv.meta.json "d['command']=='map' and d['command_line'][-1]=='map.csv'"
check "map: X_L assumed (the oil file gives none): ISO/TS 6336-20 PAO 0.8" \
    json map.csv.meta.json "any(a['key']=='oil.X_L' and a['value']=='0.8' for a in d['assumed'])"
check "map: a key the case gives is not assumed (thermal.mode)" json map.csv.meta.json "all(a['key']!='thermal.mode' for a in d['assumed'])"
check "map: units" json map.csv.meta.json "dict((c['name'],c['unit']) for c in d['columns'])['P_total_W']=='W' and dict((c['name'],c['unit']) for c in d['columns'])['status'] is None"
# --oil-temp: fixed mode with that temperature; the hash is the case's, not the options'.
"$bin" map "$box" "${small[@]}" --oil-temp 80degC -o fixed.csv 2> /dev/null
check "map --oil-temp: fixed at 80 degC" json fixed.csv.meta.json "d['thermal']['mode']=='fixed' and d['thermal']['oil_temperature_C']==80"
h1=$("$py" -c "import json; print(json.load(open('map.csv.meta.json'))['case']['hash'])")
h2=$("$py" -c "import json; print(json.load(open('fixed.csv.meta.json'))['case']['hash'])")
check "hash: same case, same hash" test -n "$h1" -a "$h1" = "$h2"
# One character changed in the case (a comment), then in its oil file: another hash each.
cp "$box" configs/box2.yaml
echo "#" >> configs/box2.yaml
"$bin" map configs/box2.yaml "${small[@]}" -o box2.csv 2> /dev/null
h3=$("$py" -c "import json; print(json.load(open('box2.csv.meta.json'))['case']['hash'])")
check "hash: one character more in the case, another hash" test -n "$h3" -a "$h3" != "$h1"
sed -i 's/^name: 75W90-A/name: 75W90-B/' "$oils/75W90-A.yaml"
"$bin" map "$box" "${small[@]}" -o oil2.csv 2> /dev/null
h4=$("$py" -c "import json; print(json.load(open('oil2.csv.meta.json'))['case']['hash'])")
check "hash: one character changed in the oil file, another hash" test -n "$h4" -a "$h4" != "$h1"
cp "$src/configs/oils/75W90-A.yaml" "$oils/75W90-A.yaml"
# --oil: the sidecar names the replacement oil and its file.
"$bin" map "$box" "${small[@]}" --oil "$oils/MINR.yaml" -o minr.csv 2> /dev/null
check "map --oil: the replacement oil" json minr.csv.meta.json "d['oil']['name']=='$(oil_name "$oils/MINR.yaml")' and d['oil']['file'].endswith('MINR.yaml')"
# The CSV bytes are those of standard output (no sidecar there).
"$bin" map "$box" "${small[@]}" -o - > stdout.csv 2> /dev/null
check "map: file = standard output bytes" cmp -s map.csv stdout.csv
check "map -o -: no sidecar" test ! -e -.meta.json

# --detail, --spread, a sweep, shards and their merge.
"$bin" map "$box" "${small[@]}" --detail -o detail.csv 2> /dev/null
check "map --detail: columns = header" columns_match detail.csv
"$bin" map "$box" --speed 800rpm --torque 250Nm --spread --spread-axes mesh.friction -o spread.csv 2> /dev/null
check "map --spread: columns = header" columns_match spread.csv
check "map --spread: forms are text" json spread.csv.meta.json "[c['unit'] for c in d['columns'] if c['name']=='forms_at_min']==[None]"
cp "$box" configs/sweep.yaml
printf '\nsweep:\n  - {parameter: oil, values: [oils/75W90-A.yaml, oils/75W140-A.yaml]}\n' >> configs/sweep.yaml
"$bin" map configs/sweep.yaml "${small[@]}" -o sweep.csv 2> /dev/null
check "sweep: axes listed" json sweep.csv.meta.json "d['sweep']==[{'label':'oil','values':['oils/75W90-A.yaml','oils/75W140-A.yaml']}]"
check "sweep: columns = header, label is text" columns_match sweep.csv
for k in 1 2; do "$bin" map configs/sweep.yaml "${small[@]}" --shard $k/2 -o shard$k.csv 2> /dev/null; done
check "shards: sidecars" test -f shard1.csv.meta.json -a -f shard2.csv.meta.json
"$bin" merge shard2.csv shard1.csv -o merged.csv
check "merge: byte-identical to the single run" cmp -s merged.csv sweep.csv
check "merge: sidecar from the shards" json merged.csv.meta.json "d['command']=='merge' and d['merged_from']==['shard2.csv','shard1.csv'] and d['sweep'][0]['label']=='oil'"
check "merge: columns = header" columns_match merged.csv

# Other commands writing a CSV file.
"$bin" mesh-profile configs/spur-seed000.yaml --mesh m --speed 1600rpm --torque 720Nm --oil-temp 70degC -o profile.csv 2> /dev/null
check "mesh-profile: sidecar" json profile.csv.meta.json "$keys and d['command']=='mesh-profile'"
"$bin" synth "$box" "${small[@]}" -o rec.csv 2> /dev/null
check "synth: sidecar" json rec.csv.meta.json "$keys and d['command']=='synth'"
"$bin" diagnose "$box" rec.csv --residuals res.csv > /dev/null 2>&1
check "diagnose --residuals: sidecar" json res.csv.meta.json "$keys and d['command']=='diagnose'"
"$bin" cycle configs/automatic-6speed.yaml --cycle nedc --start-temp 20degC -o trace.csv > /dev/null 2>&1
check "cycle -o: sidecar, transient" json trace.csv.meta.json "$keys and d['thermal']['mode']=='transient' and d['thermal']['start_temperature_C']==20"

# A failed run leaves neither the CSV nor its sidecar; an output onto an input is refused
# before anything is written, and a sidecar named like an input is refused too.
# (a VECTO table with a point without equilibrium fails while its rows are written)
"$bin" map configs/manual-6speed.yaml --format vecto --ratio g1 --speed 1000,6000rpm --torque 100,2000Nm -o failed.vtlm > /dev/null 2>&1
check "failed run: exit 2" test $? -eq 2
check "failed run: no table, no sidecar" test ! -e failed.vtlm -a ! -e failed.vtlm.meta.json
cp "$box" victim.yaml
cp victim.yaml victim.csv.meta.json
"$bin" map victim.yaml "${small[@]}" -o victim.csv > /dev/null 2> err.txt
check "sidecar onto an input: exit 2" test $? -eq 2
check "sidecar onto an input: untouched" cmp -s victim.yaml victim.csv.meta.json
check "sidecar onto an input: no CSV" test ! -e victim.csv
"$bin" map "$box" "${small[@]}" -o out.csv --json out.csv.meta.json > /dev/null 2>&1
check "sidecar = --json: exit 2" test $? -eq 2

# VECTO: '#' provenance lines, then the rows as before (the data rows of a table without
# the lines: compared with the table's rows, which do not depend on the comment lines).
"$bin" map configs/manual-6speed.yaml --format vecto --ratio g3 --oil-temp 70degC --speed 1000,2000rpm --torque 50,100Nm -o v.vtlm 2> /dev/null
check "vecto: provenance lines first" bash -c "head -5 v.vtlm | grep -c '^# ' | grep -qx 5"
check "vecto: oil temperature line" grep -qx '# oil temperature: 70 degC (fixed)' v.vtlm
check "vecto: gear line" grep -q '^# gear: g3, i = n_in/n_out = ' v.vtlm
check "vecto: header after the comments" bash -c "grep -v '^#' v.vtlm | head -1 | grep -qx 'Input Speed \[rpm\],Input Torque \[Nm\],Torque Loss \[Nm\]'"
check "vecto: sidecar" json v.vtlm.meta.json "$keys and d['ratio']['name']=='g3' and [c['unit'] for c in d['columns']]==['rpm','N*m','N*m']"
# The rows a reader that skips '#' lines sees are the rows of the map: loss torque =
# P_total / omega_in at the same points (fixed temperature, the map's own route).
"$bin" map configs/manual-6speed.yaml --ratio g3 --oil-temp 70degC --speed 1000,2000rpm --torque 50,100Nm -o g3.csv 2> /dev/null
check "vecto rows = map P_total / omega" "$py" - v.vtlm g3.csv <<'PY'
import csv, math, sys
rows = [r for r in csv.reader(open(sys.argv[1])) if r and not r[0].startswith("#")][1:]
vt = {(float(a), float(b)): float(c) for a, b, c in rows}
ok = True
for r in csv.DictReader(open(sys.argv[2])):
    n, T, P = float(r["speed_in_rpm"]), float(r["torque_in_Nm"]), float(r["P_total_W"])
    expect = P / (n * math.pi / 30)
    ok = ok and abs(vt[(n, T)] - expect) <= 1e-3 * expect + 1e-4
sys.exit(0 if ok and len(vt) == 10 else 1)
PY

# point --json: the values of the text report and of the map row at the same point.
"$bin" point "$box" --speed 800rpm --torque 250Nm --json point.json > point.txt 2> /dev/null
"$bin" map "$box" --speed 800rpm --torque 250Nm --detail -o one.csv 2> /dev/null
check "point --json: = text report and map row" "$py" - point.json point.txt one.csv <<'PY'
import csv, json, re, sys
d = json.load(open(sys.argv[1]))
text = open(sys.argv[2]).read()
row = next(csv.DictReader(open(sys.argv[3])))
total = float(re.search(r"total ([0-9.]+)\n", text).group(1))
temp = float(re.search(r"oil temperature ([0-9.]+) degC", text).group(1))
ok = abs(d["P_total_W"] - total) < 0.006 and abs(d["oil_temperature_C"] - temp) < 0.006
ok = ok and abs(d["P_total_W"] - float(row["P_total_W"])) <= 1e-5 * d["P_total_W"]
ok = ok and abs(sum(m["P_W"] for m in d["mechanisms"]) - d["P_total_W"]) <= 1e-9 * d["P_total_W"]
for m in d["mechanisms"]:
    ok = ok and abs(m["P_W"] - float(row[m["column"]])) <= 1e-5 * max(m["P_W"], 1)
ok = ok and abs(d["row"]["h_min_m12_um"] - float(row["h_min_m12_um"])) < 1e-9 and d["status"] == row["status"] == "ok"
sys.exit(0 if ok else 1)
PY
"$bin" point "$box" --speed 800rpm --torque 250Nm --json - > point-stdout.json 2> /dev/null
check "point --json -: JSON alone on stdout" json point-stdout.json "d['status']=='ok' and d['metadata']['command']=='point'"
# 700 rpm goes to rad/s and back: printed as 700, not 700.0000000000001 (15 significant digits);
# the embedded metadata describes no CSV, so it has no 'columns'.
"$bin" point "$box" --speed 700rpm --torque 250Nm --json - > point-700.json 2> /dev/null
check "point --json: 700 rpm prints as 700" grep -qE '"speed_rpm": 700(\.0)?,' point-700.json
check "point --json: no empty metadata.columns" json point-700.json "'columns' not in d['metadata']"

# compare: two oils keep today's columns; three oils: oils 1-2 equal the two-oil run, and
# dP = P_k - P_A recomputed here; --detail: the mechanisms add up to each oil's total.
A=$oils/75W90-A.yaml; Bo=$oils/75W140-A.yaml; Co=$oils/MINR.yaml
"$bin" compare "$box" "${small[@]}" --oil "$A" --oil "$Bo" -o c2.csv 2> /dev/null
check "compare 2 oils: header as before" bash -c "head -1 c2.csv | grep -qx 'speed_in_rpm,torque_in_Nm,P_total_75W90-A_W,P_total_75W140-A_W,dP_loss_W,oil_temp_75W90-A_C,oil_temp_75W140-A_C,dT_oil_K,efficiency_75W90-A,efficiency_75W140-A,d_efficiency,status_75W90-A,status_75W140-A'"
check "compare 2 oils: sidecar lists both oils" json c2.csv.meta.json "[o['name'] for o in d['oils']]==['75W90-A','75W140-A']"
"$bin" compare "$box" "${small[@]}" --oil "$A" --oil "$Bo" --oil "$Co" --detail --json c3.json -o c3.csv 2> /dev/null
check "compare 3 oils: = 2-oil run, dP recomputed, detail sums" "$py" - c2.csv c3.csv <<'PY'
import csv, sys
two = list(csv.DictReader(open(sys.argv[1])))
three = list(csv.DictReader(open(sys.argv[2])))
oils = ["75W90-A", "75W140-A", "MINR"]
ok = len(two) == len(three) == 4
for a, b in zip(two, three):
    for o in oils[:2]:
        ok = ok and a[f"P_total_{o}_W"] == b[f"P_total_{o}_W"] and a[f"oil_temp_{o}_C"] == b[f"oil_temp_{o}_C"]
    ok = ok and a["dP_loss_W"] == b["dP_loss_75W140-A_W"]
    for o in oils[1:]:
        d = float(b[f"P_total_{o}_W"]) - float(b["P_total_75W90-A_W"])
        # Cells carry 6 significant digits: each P_total within 5e-6 of its value.
        ok = ok and abs(float(b[f"dP_loss_{o}_W"]) - d) <= 1e-5 * float(b[f"P_total_{o}_W"])
    for o in oils:
        parts = [float(v) for k, v in b.items() if k.endswith(f"_{o}_W") and not k.startswith(("P_total", "dP"))]
        ok = ok and len(parts) == 8 and abs(sum(parts) - float(b[f"P_total_{o}_W"])) <= 1e-4 * float(b[f"P_total_{o}_W"])
sys.exit(0 if ok else 1)
PY
check "compare --json: summary and points" json c3.json "len(d['summary'])==3 and len(d['points'])==4 and d['reference']=='75W90-A' and d['metadata']['command']=='compare'"
check "compare --json: dP = P_k - P_A" json c3.json "all(abs(p['oils'][k]['dP_loss_W']-(p['oils'][k]['P_total_W']-p['oils'][0]['P_total_W']))<1e-9 for p in d['points'] for k in (1,2))"
"$bin" compare "$box" "${small[@]}" --oil "$A" -o c1.csv > /dev/null 2>&1
check "compare with one oil: exit 2, nothing written" test $? -eq 2 -a ! -e c1.csv -a ! -e c1.csv.meta.json

echo "cli_metadata: $pass passed, $fail failed"
[ "$fail" -eq 0 ]
