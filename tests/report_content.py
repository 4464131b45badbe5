#!/usr/bin/python3
"""Content of `gearloss report` pages, independent of any renderer: the numbers on the page
(embedded data and the values the map cells show) equal `gearloss map` CSV for the same points
(another route through the program), differences are oil k - reference, user text is escaped,
the page names no external resource, and bad input gives file:line errors and no output file.
Usage: report_content.py GEARLOSS SOURCE_DIR"""
import csv
import html
import io
import json
import math
import os
import re
import subprocess
import sys
import tempfile

binary, src = sys.argv[1], os.path.abspath(sys.argv[2])
failures = []
passed = 0


def check(name, ok, detail=""):
    global passed
    if ok:
        passed += 1
    else:
        failures.append(name)
        print(f"FAILED: {name} {detail}")


def run(*args, **kw):
    return subprocess.run([binary, *args], capture_output=True, text=True, timeout=600, **kw)


def page_data(page):
    m = re.search(r'<script type="application/json" id="gl-data">(.*?)</script>', page, re.S)
    return json.loads(m.group(1))


def map_csv(*args):
    r = run("map", *args, "-o", "-")
    assert r.returncode == 0, r.stderr
    return list(csv.DictReader(io.StringIO(r.stdout)))


def close(a, b, rel=1e-9, absolute=0.0):
    return abs(a - b) <= absolute + rel * max(abs(a), abs(b))


def half_unit(cell):
    """Half a unit in the last digit a CSV cell was written with ("1012.9" -> 0.05, "1.5e-05" -> 5e-7)."""
    mantissa, _, exponent = cell.lower().partition("e")
    decimals = len(mantissa.partition(".")[2])
    return 0.5 * 10.0 ** (-decimals + (int(exponent) if exponent else 0))


def as_written(value, cell):
    """The page's full-precision value rounds to the CSV cell (gearloss map writes 6 significant digits)."""
    return abs(value - float(cell)) <= half_unit(cell) * (1 + 1e-9)


def cell_titles(page, svg_id):
    """The values the cells of one picture show on hover: {(rpm, Nm): value}."""
    m = re.search(r'<svg class="gl-map" id="%s".*?</svg>' % re.escape(svg_id), page, re.S)
    out = {}
    for n, T, v in re.findall(r"<title>([-\d.e+]+) rpm, ([-\d.e+]+) N&#183;m: ([-\d.e+]+) ", m.group(0) if m else ""):
        out[(float(n), float(T))] = float(v)
    return out


tmp = tempfile.mkdtemp(prefix="report-content-")
case = os.path.join(src, "configs/transfer-box.yaml")
oil_b = os.path.join(src, "configs/oils/75W140-A.yaml")
grid = ["--speed", "600,1500,3000rpm", "--torque", "50,150,300Nm"]

# 1. Stabilised map with an oil comparison: the page against `gearloss map` for each oil.
out = os.path.join(tmp, "r.html")
r = run("report", case, *grid, "--oil", oil_b, "--spread-axes", "mesh.friction", "-o", out)
check("report exits 0", r.returncode == 0, r.stderr)
page = open(out, encoding="utf-8").read()
data = page_data(page)
ref_rows = map_csv(case, *grid)
b_rows = map_csv(case, *grid, "--oil", oil_b)
cols = data["oils"][0]["map"]
check("one column entry per map row", len(cols["status"]) == len(ref_rows) == 9)
loss_columns = [c for c in ref_rows[0] if c.startswith("P_") and c.endswith("_W")]
check("every loss column of the CSV is on the page", all(c in cols for c in loss_columns), str(loss_columns))
for oil_index, rows in ((0, ref_rows), (1, b_rows)):
    c = data["oils"][oil_index]["map"]
    for i, row in enumerate(rows):
        check(f"oil {oil_index} point {i} status", c["status"][i] == row["status"], f'{c["status"][i]} vs {row["status"]}')
        if row["P_total_W"] == "":
            continue
        for col in loss_columns:
            check(f"oil {oil_index} point {i} {col}", as_written(c[col][i], row[col]), f"{c[col][i]} vs {row[col]}")
        for col in ("oil_temp_C", "efficiency"):
            check(f"oil {oil_index} point {i} {col}", as_written(c[col][i], row[col]), f"{c[col][i]} vs {row[col]}")

# The numbers the cells show (5 significant digits) are the CSV's.
shown = cell_titles(page, "map-efficiency")
check("every efficiency cell shows a value", len(shown) == sum(1 for row in ref_rows if row["efficiency"]), str(len(shown)))
for row in ref_rows:
    key = (float(row["speed_in_rpm"]), float(row["torque_in_Nm"]))
    if row["efficiency"] and key in shown:
        # shown with 5 significant digits, the CSV with 6 decimals of the fraction
        check(f"efficiency shown at {key}", close(shown[key], 100 * float(row["efficiency"]), 5e-5, 5e-5), f"{shown[key]} vs {row['efficiency']}")
shown_t = cell_titles(page, "map-oil-temperature")
for row in ref_rows:
    key = (float(row["speed_in_rpm"]), float(row["torque_in_Nm"]))
    if row["oil_temp_C"]:
        check(f"oil temperature shown at {key}", key in shown_t and close(shown_t[key], float(row["oil_temp_C"]), 5e-5, 5e-4))
# Differences are oil k - reference (B - A): positive = more loss than the case's oil.
shown_d = cell_titles(page, "map-oil1-dP")
check("difference cells shown", len(shown_d) > 0)
for a, b in zip(ref_rows, b_rows):
    key = (float(a["speed_in_rpm"]), float(a["torque_in_Nm"]))
    if a["P_total_W"] and b["P_total_W"] and key in shown_d:
        want = float(b["P_total_W"]) - float(a["P_total_W"])
        # the CSV cells' rounding plus the 5 significant digits shown; the wrong sign misses by 2|dP|
        tol = half_unit(a["P_total_W"]) + half_unit(b["P_total_W"])
        check(f"dP shown at {key} is B - A", close(shown_d[key], want, 5e-5, tol), f"{shown_d[key]} vs {want}")
check("the spread section has its pictures", 'id="map-spread-band"' in page)
check("the footer gives the command line", "--spread-axes mesh.friction" in page)

# 2. Fixed oil temperature: titled so, and the numbers are those of map --oil-temp.
r = run("report", case, *grid, "--oil-temp", "70degC", "--no-spread", "-o", os.path.join(tmp, "f.html"))
check("fixed report exits 0", r.returncode == 0, r.stderr)
fixed = open(os.path.join(tmp, "f.html"), encoding="utf-8").read()
check("fixed temperature in the title", "oil temperature, fixed at 70.0 degC (--oil-temp)" in fixed)
check("no 'stabilised' temperature map when fixed", "stabilised oil temperature" not in fixed)
fixed_rows = map_csv(case, *grid, "--oil-temp", "70degC")
fd = page_data(fixed)["oils"][0]["map"]
check("fixed map totals", all(as_written(fd["P_total_W"][i], row["P_total_W"]) for i, row in enumerate(fixed_rows)))

# 3. Self-contained: nothing fetched from anywhere.
for name, text in (("stabilised", page), ("fixed", fixed)):
    check(f"{name}: no http(s) URL", "http://" not in text and "https://" not in text)
    refs = re.findall(r"""\b(?:src|href)\s*=\s*["']?([^"'\s>]*)""", text)
    check(f"{name}: every src/href is an anchor in the page", all(x.startswith("#") for x in refs), str(refs[:5]))

# 4. User text is escaped.
text = open(case, encoding="utf-8").read()
text = text.replace("name: Transfer gearbox (seed 001)", "name: <script>alert(\"x\")</script> & co", 1)
text = text.replace("oil: oils/75W90-A.yaml", "oil: " + os.path.join(src, "configs/oils/75W90-A.yaml"), 1)
hostile = os.path.join(tmp, "hostile<b>.yaml")
open(hostile, "w", encoding="utf-8").write(text)
r = run("report", hostile, *grid, "--no-spread", "-o", os.path.join(tmp, "h.html"))
check("hostile-name report exits 0", r.returncode == 0, r.stderr)
h = open(os.path.join(tmp, "h.html"), encoding="utf-8").read()
check("no script from the case name", "<script>alert" not in h)
check("the name is shown escaped", "&lt;script&gt;alert(&quot;x&quot;)&lt;/script&gt; &amp; co" in h)
check("the file name is shown escaped", "hostile&lt;b&gt;.yaml" in h and "hostile<b>" not in h)
check("the embedded data keep the name", page_data(h)["case"]["name"] == '<script>alert("x")</script> & co')
check("only the page's own three scripts", h.count("<script") == 3)

# 5. Assumed values: what the case leaves out is listed and flagged; giving it removes the flag.
assumed = {a["key"]: a for a in data["assumed"]}
check("the case's assumed values are listed", "gears.w1.pressure_angle" in assumed and "oil.X_L" in assumed, str(list(assumed)[:5]))
row = re.search(r'<tr class="gl-assumed"><td><span class="gl-flag">ASSUMED</span></td><td><code>gears\.w1\.pressure_angle</code></td><td>20 deg</td>', page)
check("an assumed value is flagged with its value", row is not None)
check("every assumed value has a flagged row", page.count('<tr class="gl-assumed"><td><span class="gl-flag">ASSUMED</span>') == len(data["assumed"]))
given = open(case, encoding="utf-8").read().replace("{name: w1, ", "{name: w1, pressure_angle: 20 deg, ", 1)
given = given.replace("oil: oils/75W90-A.yaml", "oil: " + os.path.join(src, "configs/oils/75W90-A.yaml"), 1)
gcase = os.path.join(tmp, "given.yaml")
open(gcase, "w", encoding="utf-8").write(given)
r = run("report", gcase, *grid, "--no-spread", "-o", os.path.join(tmp, "g.html"))
g = open(os.path.join(tmp, "g.html"), encoding="utf-8").read() if r.returncode == 0 else ""
gd = page_data(g) if g else {"assumed": []}
check("a value given is not assumed", g != "" and "gears.w1.pressure_angle" not in {a["key"] for a in gd["assumed"]}, r.stderr)
check("... and is shown as given, unflagged", "<tr><td><code>gears.w1.pressure_angle</code></td><td>20 deg</td>" in g)
check("the other gears' pressure angles stay assumed", "gears.w2.pressure_angle" in {a["key"] for a in gd["assumed"]})

# 6. Bad input: file:line:col error, exit 2, no output file (and an existing one untouched).
bad = os.path.join(tmp, "bad.yaml")
open(bad, "w", encoding="utf-8").write(text.replace("speeds: [600 rpm, 700 rpm, 800 rpm]", "speeds: [600 rpm, 7x0 rpm]", 1))
target = os.path.join(tmp, "bad.html")
r = run("report", bad, "-o", target)
check("bad case: exit 2", r.returncode == 2, str(r.returncode))
check("bad case: file:line:col named", re.search(r"bad\.yaml:\d+:\d+: operating\.speeds", r.stderr) is not None, r.stderr)
check("bad case: no output file", not os.path.exists(target))
open(target, "w").write("previous")
r = run("report", case, "--oil", bad, "-o", target)
check("bad --oil: exit 2", r.returncode == 2, r.stderr)
check("bad --oil: existing output untouched", open(target).read() == "previous")
r = run("report", case, "--speed", "fast", "-o", target)
check("bad --speed: exit 2 naming the option", r.returncode == 2 and "--speed" in r.stderr, r.stderr)
check("bad --speed: existing output untouched", open(target).read() == "previous")
r = run("report", case, *grid, "--no-spread", "-o", "-")
check("'-' writes the page to stdout", r.returncode == 0 and r.stdout.startswith("<!DOCTYPE html>") and r.stdout.rstrip().endswith("</html>"))

# 7. The first screen: a summary with its numbers printed, checked against `gearloss map` CSV
#    (another route through the program) and against hand calculations.
def table_rows(page, css_class):
    """Rows of the table of class `css_class` as lists of cell texts (tags stripped, entities decoded)."""
    m = re.search(r'<table class="gl-table %s"[^>]*>(.*?)</table>' % re.escape(css_class), page, re.S)
    rows = []
    for tr in re.findall(r"<tr[^>]*>(.*?)</tr>", m.group(1) if m else "", re.S):
        cells = re.findall(r"<t[hd][^>]*>(.*?)</t[hd]>", tr, re.S)
        rows.append([html.unescape(re.sub(r"<[^>]+>", "", c)).replace("\xa0", " ").strip() for c in cells])
    return rows


def summary_row(page, name):
    for row in table_rows(page, "gl-summary"):
        if row and row[0] == name:
            return row[1]
    return ""


def printed(text, value, digits=None, decimals=None):
    """`text` is `value` written with `digits` significant digits or `decimals` decimals (half a unit of
    the last digit, plus the CSV's own rounding, which the caller folds into `value`'s tolerance)."""
    try:
        shown = float(text.replace("%", "").replace("+", "").strip())
    except ValueError:
        return False
    if decimals is None:
        decimals = max(0, digits - 1 - int(math.floor(math.log10(abs(value))))) if value else digits - 1
    return abs(shown - value) <= 0.5 * 10.0 ** (-decimals) * (1 + 1e-6) + 1e-6 * abs(value)


check("summary before the maps, the maps before the case as given",
      0 < page.find('id="summary"') < page.find('id="maps"') < page.find('id="case"') < page.find('id="checks"'))
check("no assumed value before the maps", page.find('class="gl-assumed"') > page.find('id="maps"'))
# Ratio of the transfer box in 'low' by hand from the teeth: wheels 5-3 (17 -> 28) then 2-1 (23 -> 32):
# n_out/n_in = 17/28 * 23/32 = 0.436384, i = n_in/n_out = 2.29156 (printed with 4 digits: 2.292).
ratio = summary_row(page, "ratio")
check("ratio: i = n_in/n_out printed", re.search(r"i = nin/nout = 2\.292\b", ratio) is not None, ratio)
check("ratio: the named ratio and n_out/n_in", "'low'" in ratio and "0.436384" in ratio, ratio)
check("oils compared counts both oils", summary_row(page, "oils compared").startswith("2: 75W90-A"), summary_row(page, "oils compared"))
# Oil temperature over the map: the CSV's least and greatest, 3 significant digits.
temps = [float(row["oil_temp_C"]) for row in ref_rows if row["oil_temp_C"]]
m = re.search(r"stabilised: ([\d.]+) °C…([\d.]+) °C over the map", summary_row(page, "oil temperature"))
check("oil temperature range printed", m is not None and printed(m.group(1), min(temps), 3) and printed(m.group(2), max(temps), 3),
      summary_row(page, "oil temperature"))
# Thermal limit: the oil's permissible temperature as the loader assumed it (oil.max_temperature).
limit = float(assumed["oil.max_temperature"]["value"].split()[0])
check("thermal limit names the oil's permissible temperature",
      f"permissible sump temperature {limit:g} °C" in summary_row(page, "thermal limit"), summary_row(page, "thermal limit"))
# Key points: the rated point has the greatest input power n*T (by hand from the CSV's speed and torque;
# of two equal, the faster); best and worst are the CSV's greatest and least efficiency.
keyrows = table_rows(page, "gl-keypoints")
header = re.search(r'<table class="gl-table gl-keypoints">.*?</thead>', page, re.S)
split_columns = re.findall(r'data-column="([^"]+)"', header.group(0) if header else "")
with_eff = [row for row in ref_rows if row["efficiency"]]
power = lambda row: float(row["speed_in_rpm"]) * float(row["torque_in_Nm"])
expected = {"rated (highest input power)": max((row for row in ref_rows if row["P_total_W"]),
                                               key=lambda row: (power(row), float(row["speed_in_rpm"]))),
            "best efficiency": max(with_eff, key=lambda row: float(row["efficiency"])),
            "worst efficiency": min(with_eff, key=lambda row: float(row["efficiency"]))}
# One row per point: a point that is two of them is named so once ("rated (...), best efficiency").
roles = {}
for role, row in expected.items():
    roles.setdefault(id(row), []).append(role)
rows_by_role = {}
for role, row in expected.items():
    rows_by_role[", ".join(roles[id(row)])] = row
check("one key point row per point, rated first", [r[0] for r in keyrows[1:]] == list(rows_by_role), str([r[0] for r in keyrows]))
for row in keyrows[1:]:
    want = rows_by_role.get(row[0])
    if not want:
        continue
    check(f"{row[0]}: speed and torque", float(row[1]) == round(float(want["speed_in_rpm"])) and float(row[2]) == float(want["torque_in_Nm"]), str(row))
    check(f"{row[0]}: input power [kW] = n T pi/30", printed(row[3], power(want) * math.pi / 30 / 1000, 4), str(row))
    check(f"{row[0]}: efficiency [%]", printed(row[4], 100 * float(want["efficiency"]), decimals=2), f'{row[4]} vs {want["efficiency"]}')
    check(f"{row[0]}: total loss", printed(row[6], float(want["P_total_W"]), 4), f'{row[6]} vs {want["P_total_W"]}')
    for j, col in enumerate(split_columns):
        value, _, share = row[7 + j].partition(" (")
        P, total = float(want[col]), float(want["P_total_W"])
        check(f"{row[0]}: {col} and its share", printed(value, P, 4) and printed(share.rstrip(" %)"), 100 * P / total, decimals=1),
              f"{row[7 + j]} vs {P} of {total}")
# Mechanisms that are 0 W at every point (the CSV's all-zero columns) are named in one line, not drawn.
zero_columns = [c for c in loss_columns if c != "P_total_W" and all(float(row[c]) == 0 for row in ref_rows if row[c])]
drawn = re.findall(r'<svg class="gl-map" id="map-loss-([^"]+)"', page)
check("the transfer box has all-zero mechanisms (windage among them)", "P_windage_W" in zero_columns, str(zero_columns))
check("windage listed as zero everywhere", "windage: 0 W everywhere" in page)
check("one line names every all-zero mechanism", page.count(": 0 W everywhere") >= len(zero_columns) and
      max(line.count(": 0 W everywhere") for line in re.findall(r'<p class="gl-zero">(.*?)</p>', page)) == len(zero_columns))
check("no map of an all-zero mechanism", "windage" not in drawn and len(drawn) == len(loss_columns) - 1 - len(zero_columns), str(drawn))
check("the loss split leaves out the all-zero mechanisms", not set(split_columns) & set(zero_columns) and len(split_columns) > 0, str(split_columns))
# The oil ranking: lowest mean total loss (over the points where both oils have values) first.
both = [(a, b) for a, b in zip(ref_rows, b_rows) if a["P_total_W"] and b["P_total_W"]]
mean_a = sum(float(a["P_total_W"]) for a, _ in both) / len(both)
mean_b = sum(float(b["P_total_W"]) for _, b in both) / len(both)
ranking = table_rows(page, "gl-ranking")[1:]
order = ["75W90-A", "75W140-A"] if mean_a <= mean_b else ["75W140-A", "75W90-A"]
check("oils ranked by mean total loss", [r[1].split(" (")[0] for r in ranking] == order, str(ranking))
check("ranking means printed", len(ranking) == 2 and all(printed(r[2], mean_a if r[1].startswith("75W90-A") else mean_b, 4) for r in ranking), str(ranking))
# Values printed in the cells (readable without hovering, and in print): every point of the
# efficiency and total-loss maps, equal to the CSV.
def cell_labels(page, svg_id):
    m = re.search(r'<svg class="gl-map" id="%s".*?</svg>' % re.escape(svg_id), page, re.S)
    return {int(i): v for i, v in re.findall(r'class="gl-cell"[^>]*data-i="(\d+)">([^<]+)</text>', m.group(0) if m else "")}

labels = cell_labels(page, "map-efficiency")
check("every efficiency cell prints its value", sorted(labels) == [i for i, row in enumerate(ref_rows) if row["efficiency"]], str(labels))
check("efficiency labels equal the CSV (4 digits)", all(printed(v, 100 * float(ref_rows[i]["efficiency"]), 4) for i, v in labels.items()), str(labels))
labels = cell_labels(page, "map-total-loss")
check("total loss labels equal the CSV (3 digits)", len(labels) == len(both) and
      all(printed(v, float(ref_rows[i]["P_total_W"]), 3) for i, v in labels.items()), str(labels))
# The assumed values and the check dump are collapsed below the results, the dump's lines wrapped.
check("assumed values collapsed", re.search(r'<details id="assumed"><summary>Assumed values: \d+ values', page) is not None)
check("check dump collapsed", '<details id="check-dump"><summary>' in page and '<details id="check-dump" open' not in page)
check("long lines wrap", re.search(r"pre\{[^}]*white-space:pre-wrap", page) is not None)
check("print style keeps figures whole", re.search(r"@media print\{.*\.gl-figure\{break-inside:avoid", page, re.S) is not None)

# 8. A grid whose cells are too small for labels: a table of values under each map.
speeds = ",".join(str(n) for n in range(500, 4001, 250)) + "rpm"   # 15 speeds
torques = ",".join(str(t) for t in range(0, 401, 20)) + "Nm"        # 21 torques
r = run("report", case, "--speed", speeds, "--torque", torques, "--oil-temp", "70degC", "--no-spread", "-o", os.path.join(tmp, "big.html"))
big = open(os.path.join(tmp, "big.html"), encoding="utf-8").read() if r.returncode == 0 else ""
check("large grid report exits 0", r.returncode == 0, r.stderr)
check("no labels in cells too small", cell_labels(big, "map-efficiency") == {})
big_rows = {(round(float(row["speed_in_rpm"])), float(row["torque_in_Nm"])): row
            for row in map_csv(case, "--speed", speeds, "--torque", torques, "--oil-temp", "70degC")}
table = re.search(r'<table class="gl-table gl-values-table" data-map="map-total-loss">(.*?)</table>', big, re.S)
check("a table of values under the total-loss map", table is not None)
rows = [[html.unescape(re.sub(r"<[^>]+>", "", c)) for c in re.findall(r"<t[hd][^>]*>(.*?)</t[hd]>", tr, re.S)]
        for tr in re.findall(r"<tr>(.*?)</tr>", table.group(1) if table else "", re.S)]
shown_speeds = [int(x) for x in rows[0][1:]] if rows else []
check("the table keeps the first and last speed, at most 12", shown_speeds[:1] == [500] and shown_speeds[-1:] == [4000] and len(shown_speeds) <= 12, str(shown_speeds))
compared = 0
for row in rows[1:]:
    for n, text in zip(shown_speeds, row[1:]):
        want = big_rows[(n, float(row[0]))]["P_total_W"]
        compared += 1
        check(f"table value at {n} rpm {row[0]} N m", printed(text, float(want), 3) if want else text in ("n.e.", "o.r.", "–"), f"{text} vs {want}")
check("the table has rows, the first and last torque", compared > 100 and rows[1][0] == "400" and rows[-1][0] == "0", str(compared))
check("the page says which part the table shows", "12 of 15 speeds and 16 of 21 torques, evenly spread" in big)

# 9. --pdf without a browser: an error naming the option, before any solving; no file written.
target = os.path.join(tmp, "nopdf.html")
r = run("report", case, *grid, "--no-spread", "-o", target, "--pdf", os.path.join(tmp, "x.pdf"),
        env={"PATH": "/nonexistent", "HOME": tmp})
check("--pdf without chromium: exit 2 naming --pdf", r.returncode == 2 and "--pdf" in r.stderr and "Chromium" in r.stderr, r.stderr)
check("--pdf without chromium: no file written", not os.path.exists(target) and not os.path.exists(os.path.join(tmp, "x.pdf")))
r = run("report", case, *grid, "--no-spread", "--pdf", os.path.join(tmp, "x.pdf"), env={"PATH": "/usr/bin:/bin", "CHROMIUM": "/no/such/chromium"})
check("--pdf with a wrong CHROMIUM: exit 2 naming it", r.returncode == 2 and "CHROMIUM=/no/such/chromium" in r.stderr, r.stderr)
r = run("report", case, *grid, "--no-spread")
check("neither -o nor --pdf: exit 2 naming --output", r.returncode == 2 and "--output" in r.stderr, r.stderr)

print(f"report_content: {passed} passed, {len(failures)} failed")
sys.exit(1 if failures else 0)
