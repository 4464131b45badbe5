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

print(f"report_content: {passed} passed, {len(failures)} failed")
sys.exit(1 if failures else 0)
