"""Pictures of gearloss outputs (scripts/plot.py, scripts/plotting/): every kind of file gives a
picture, titles say what the metadata (or the CSV itself) says, --levels is honoured, the colour
sense of compare is the same on every panel, and hostile inputs give one-line errors.

Run by ctest with /usr/bin/python3 (Debian's numpy, pandas, matplotlib):
  GEARLOSS_BIN=build/app/gearloss GEARLOSS_SOURCE=. /usr/bin/python3 tests/python/test_plots.py
Every file is written inside a temporary directory."""
import contextlib
import io
import json
import os
import shutil
import subprocess
import sys
import tempfile
import types
import unittest

SRC = os.path.abspath(os.environ.get("GEARLOSS_SOURCE", os.path.join(os.path.dirname(__file__), "..", "..")))
BIN = os.environ.get("GEARLOSS_BIN", os.path.join(SRC, "build", "app", "gearloss"))
PLOT = os.path.join(SRC, "scripts", "plot.py")
PNG_MAGIC = b"\x89PNG\r\n\x1a\n"
sys.path.insert(0, os.path.join(SRC, "scripts"))

import matplotlib  # noqa: E402

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402
import pandas as pd  # noqa: E402

import plot as plot_py  # noqa: E402  (scripts/plot.py)
from plotting import compare as pcompare  # noqa: E402
from plotting import data as pdata  # noqa: E402
from plotting import maps as pmaps  # noqa: E402

TMP = None


def gearloss(*args):
    subprocess.run([BIN, *args], check=True, cwd=SRC, stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)


def path(name):
    return os.path.join(TMP, name)


def plot(*args, env=None):
    """Runs plot.py; returns (exit code, stdout, stderr)."""
    e = dict(os.environ, MPLCONFIGDIR=path("mpl"))
    e.pop("PLOT_DEBUG", None)
    e.update(env or {})
    r = subprocess.run(["/usr/bin/python3", PLOT, *args], capture_output=True, text=True, env=e)
    return r.returncode, r.stdout, r.stderr


def described(out):
    """--describe output as {'title': str, 'panel': [..], 'levels': str, 'levels <q>': str}."""
    d = {"panel": []}
    for line in out.splitlines():
        key, _, value = line.partition(": ")
        if key == "panel":
            d["panel"].append(value)
        else:
            d[key] = value
    return d


def level_values(text):
    return [float(x) for x in text.split(" (")[0].split(",")]


def setUpModule():
    global TMP
    TMP = tempfile.mkdtemp(prefix="gearloss-plots-")
    speeds = ",".join(str(300 + 300 * i) for i in range(10)) + "rpm"
    torques = ",".join(str(25 + 50 * i) for i in range(8)) + "Nm"
    case = "configs/transfer-box.yaml"
    gearloss("map", case, "--speed", speeds, "--torque", torques, "-o", path("map.csv"))
    gearloss("map", case, "--oil-temp", "80degC", "-o", path("fixed.csv"))
    gearloss("map", case, "--oil-temp", "80degC", "--ratio", "high", "-o", path("meta.csv"))
    gearloss("map", case, "--oil-temp", "70degC", "--ratio", "high", "-o", path("real.csv"))
    # map.csv and fixed.csv stand for CSVs without their sidecar (an older gearloss, a copied file)
    for name in ("map.csv", "fixed.csv"):
        os.remove(path(name + ".meta.json"))
    # the sidecar the metadata writer gives (gearloss-metadata/1), written by hand here
    meta = {"format": "gearloss-metadata/1", "command": "map",
            "command_line": ["gearloss", "map", case, "--oil-temp", "80degC", "--ratio", "high", "-o", "meta.csv"],
            "case": {"file": case, "name": "transfer-box", "title": "Sidecar transfer box", "hash": "0"},
            "oil": {"name": "SidecarOil-75W90", "base": "mineral", "file": "oils/75W90-A.yaml"},
            "thermal": {"mode": "fixed", "oil_temperature_C": 80.0},
            "ratio": {"name": "high", "value": 1.0}, "sweep": [], "columns": []}
    with open(path("meta.csv.meta.json"), "w") as f:
        json.dump(meta, f)
    # a sweep of 2 oils x 2 oil levels: four variants
    os.makedirs(path("sw/oils"))
    for oil in ("75W90-A", "75W140-A"):
        shutil.copy(os.path.join(SRC, "configs/oils", oil + ".yaml"), path(f"sw/oils/{oil}.yaml"))
    with open(os.path.join(SRC, case)) as f, open(path("sw/case.yaml"), "w") as g:
        g.write(f.read() + "\nsweep:\n  - {parameter: oil, values: [oils/75W90-A.yaml, oils/75W140-A.yaml]}\n"
                "  - {parameter: housing.oil_level, values: [-30 mm, -10 mm]}\n")
    gearloss("map", path("sw/case.yaml"), "-o", path("sweep.csv"))
    oils = [os.path.join(SRC, "configs/oils", o + ".yaml") for o in ("75W90-A", "75W140-A", "75W90-syn-B")]
    cgrid = ["--speed", "400,800,1200,1600rpm", "--torque", "100,200,300Nm"]
    gearloss("compare", case, "--oil", oils[0], "--oil", oils[1], *cgrid, "-o", path("cmp2.csv"))
    gearloss("compare", case, "--oil", oils[0], "--oil", oils[2], *cgrid, "-o", path("cmpAC.csv"))
    # three oils in the columns the N-oil compare writes (per oil k; differences for k != the first)
    ab, ac = pd.read_csv(path("cmp2.csv")), pd.read_csv(path("cmpAC.csv"))
    names = ["75W90-A", "75W140-A", "75W90-syn-B"]
    three = ab[["speed_in_rpm", "torque_in_Nm"]].copy()
    for k, src in zip(names, (ab, ab, ac)):
        for col in ("P_total_{}_W", "oil_temp_{}_C", "efficiency_{}", "status_{}"):
            three[col.format(k)] = src[col.format(k)]
    for k, src in zip(names[1:], (ab, ac)):
        three[f"dP_loss_{k}_W"] = src["dP_loss_W"]
        three[f"dT_oil_{k}_K"] = src["dT_oil_K"]
        three[f"d_efficiency_{k}"] = src["d_efficiency"]
    three.to_csv(path("cmp3.csv"), index=False)
    gearloss("cycle", "configs/automatic-6speed.yaml", "--cycle", "nedc", "--start-temp", "-10degC",
             "--prewarm", "90degC", "--heater", "2kW", "-o", path("trace.csv"))
    gearloss("synth", case, "--speed", "400,700,1000rpm", "--torque", "100,200,300Nm", "--effect", "windage=25W",
             "--seed", "7", "-o", path("rec.csv"))
    gearloss("diagnose", case, path("rec.csv"), "--residuals", path("res.csv"))


def tearDownModule():
    shutil.rmtree(TMP, ignore_errors=True)


class Pictures(unittest.TestCase):
    def draw(self, *args):
        """plot.py's run() in this process (the command line's path, without an interpreter start
        per picture); returns what --describe printed and the warnings."""
        out = path(f"p{abs(hash(args))}.png")
        stdout, err = io.StringIO(), io.StringIO()
        with contextlib.redirect_stdout(stdout), contextlib.redirect_stderr(err):
            plot_py.run(plot_py.parse([*args[:2], out, *args[2:], "--describe"]))
        stdout, err = stdout.getvalue(), err.getvalue()
        with open(out, "rb") as f:
            self.assertEqual(f.read(8), PNG_MAGIC)
        self.assertGreater(os.path.getsize(out), 10000)  # a drawn picture, not an empty canvas
        return described(stdout), err

    def test_map_stabilised_without_sidecar(self):
        d, _ = self.draw("map", path("map.csv"))
        self.assertIn("map.csv", d["title"])  # the case is unknown: the file is named
        self.assertIn("stabilised oil temperature", d["title"])

    def test_map_fixed_without_sidecar_says_fixed(self):
        d, _ = self.draw("map", path("fixed.csv"), "--kind", "oil-temp")
        self.assertIn("oil fixed at 80 degC", d["title"])
        self.assertNotIn("stabilised", d["title"])
        self.assertEqual(d["levels"], "constant 80")  # one value, no offset notation

    def test_map_title_from_the_written_sidecar(self):
        # the sidecar gearloss wrote itself: the case's name from configs/transfer-box.yaml
        d, _ = self.draw("map", path("real.csv"))
        for part in ("Transfer gearbox", "oil 75W90-A", "70", "fixed", "ratio high"):
            self.assertIn(part, d["title"])
        self.assertNotIn("stabilised", d["title"])

    def test_map_title_from_sidecar(self):
        d, _ = self.draw("map", path("meta.csv"))
        for part in ("Sidecar transfer box", "oil SidecarOil-75W90", "oil fixed at 80 degC", "ratio high"):
            self.assertIn(part, d["title"])

    def test_breakdown(self):
        d, _ = self.draw("map", path("map.csv"), "--kind", "breakdown")
        self.assertIn("loss breakdown", d["title"])

    def test_levels_list_honoured(self):
        d, _ = self.draw("map", path("map.csv"), "--levels", "0.9,0.95,0.97,0.98,0.99")
        self.assertEqual(level_values(d["levels"]), [90, 95, 97, 98, 99])  # fractions drawn in percent
        d, _ = self.draw("map", path("map.csv"), "--levels", "96,97,98")
        self.assertEqual(level_values(d["levels"]), [96, 97, 98])

    def test_levels_count_honoured(self):
        for n in (4, 20):
            d, _ = self.draw("map", path("map.csv"), "--levels", str(n))
            self.assertTrue(n // 2 <= len(level_values(d["levels"])) <= n + 2, d["levels"])

    def test_automatic_levels_resolve_the_upper_efficiencies(self):
        # Half the solved points have an efficiency above the median: with levels spread from the
        # worst point (the low-torque band) to the best, few levels fall there; the picture must
        # give that upper half at least half of its levels.
        eff = pd.read_csv(path("map.csv"))["efficiency"].dropna().to_numpy() * 100
        d, _ = self.draw("map", path("map.csv"))
        levels = np.array(level_values(d["levels"]))
        self.assertGreaterEqual((levels >= np.median(eff)).sum(), len(levels) / 2, d["levels"])
        even = np.linspace(eff.min(), eff.max(), len(levels))  # what min..max would have given
        self.assertLess((even >= np.median(eff)).sum(), len(levels) / 2)

    def test_sweep_drawn_as_facets(self):
        d, _ = self.draw("map", path("sweep.csv"))
        self.assertEqual(len(d["panel"]), 4)
        self.assertIn("oil=oils/75W140-A.yaml, housing.oil_level=-10 mm", d["panel"])
        d, _ = self.draw("map", path("sweep.csv"), "--select", "housing.oil_level=-30 mm")
        self.assertEqual(d["panel"], ["oil=oils/75W90-A.yaml", "oil=oils/75W140-A.yaml"])

    def test_sweep_beyond_the_panels_refused(self):
        out = path("refused.png")
        code, _, err = plot("map", path("sweep.csv"), out, "--max-panels", "3")
        self.assertEqual(code, 2)
        self.assertIn("4 sweep variants", err)
        self.assertIn("--select", err)
        self.assertFalse(os.path.exists(out))

    def test_compare_two_oils(self):
        d, _ = self.draw("compare", path("cmp2.csv"))
        self.assertEqual(d["panel"][0], "75W140-A - 75W90-A: power loss")
        self.assertEqual(len(d["panel"]), 3)
        self.assertEqual(level_values(d["levels power loss"])[0], -level_values(d["levels power loss"])[-1])

    def test_compare_three_oils_one_row_each(self):
        d, _ = self.draw("compare", path("cmp3.csv"))
        self.assertEqual(len(d["panel"]), 6)
        self.assertIn("75W90-syn-B - 75W90-A: efficiency", d["panel"])

    def test_compare_red_means_worse_on_every_panel(self):
        # The colour of +1 W loss, +1 K and +0.1 points of efficiency read from each panel's colour
        # scale: more loss and hotter are red (red channel above blue), more efficient is blue.
        table = pdata.read_table(path("cmp3.csv"), "compare")
        fig = plt.figure(layout="constrained")
        opts = types.SimpleNamespace(levels=None, title="")
        worse = {"power loss": 1.0, "oil temperature": 1.0, "efficiency": -0.1}
        info = pcompare.plot_compare(fig, table, None, opts)
        self.assertEqual(len(info["mappables"]), 6)
        for title, filled in info["mappables"].items():
            quantity = title.split(": ")[1]
            for sign in (+1, -1):
                r, g, b, _ = filled.cmap(filled.norm(sign * worse[quantity]))
                self.assertEqual(r > b, sign > 0, f"{title}: {sign * worse[quantity]} drawn as {(r, g, b)}")
        plt.close(fig)

    def test_colour_bar_numbers_plain(self):
        table = pdata.read_table(path("fixed.csv"), "map")
        fig = plt.figure(layout="constrained")
        opts = types.SimpleNamespace(kind="oil-temp", levels=None, select=[], max_panels=12, title="")
        pmaps.plot_map(fig, table, None, opts)
        fig.canvas.draw()
        bar = fig.axes[-1]
        texts = [t.get_text() for t in bar.get_yticklabels()] + [bar.yaxis.get_offset_text().get_text()]
        self.assertEqual([t for t in texts if t], ["80"])
        self.assertIn("the same 80 at every point", bar.get_ylabel())
        plt.close(fig)

    def test_cycle_overlays_three_runs(self):
        d, err = self.draw("cycle", path("trace.csv"))
        self.assertEqual(len(d["panel"]), 3)
        self.assertTrue(d["panel"][0].startswith("from -10 degC"))
        self.assertTrue(d["panel"][1].startswith("warm start at 90 degC"))
        self.assertTrue(d["panel"][2].startswith("pre-warmed"))
        self.assertEqual(err, "")

    def test_cycle_of_an_older_gearloss_says_so(self):
        t = pd.read_csv(path("trace.csv"))
        t[[c for c in t.columns if not c.startswith(("warm_", "prewarmed_"))]].to_csv(path("old.csv"), index=False)
        d, err = self.draw("cycle", path("old.csv"))
        self.assertEqual(len(d["panel"]), 1)
        self.assertIn("only the run from the start temperature", err)

    def test_diagnose(self):
        d, _ = self.draw("diagnose", path("res.csv"))
        self.assertIn("diagnosis residuals", d["title"])

    def test_user_title_replaces(self):
        d, _ = self.draw("map", path("map.csv"), "--title", "My own title")
        self.assertEqual(d["title"], "My own title")


class Errors(unittest.TestCase):
    def refused(self, args, message, env=None):
        out = path("never.png")
        if os.path.exists(out):
            os.unlink(out)
        code, stdout, err = plot(*args, env=env)
        self.assertEqual(code, 2, err)
        self.assertNotIn("Traceback", err)
        self.assertEqual(len(err.strip().splitlines()), 1, err)
        self.assertTrue(err.startswith("plot.py: error: "), err)
        self.assertIn(message, err)
        self.assertFalse(os.path.exists(out))

    def write(self, name, text, mode="w"):
        with open(path(name), mode) as f:
            f.write(text)
        return path(name)

    def test_hostile_inputs(self):
        out = path("never.png")
        with open(path("map.csv")) as f:
            header, first = f.readline(), f.readline()
        cases = [
            (["map", path("missing.csv"), out], "no such file"),
            (["map", self.write("empty.csv", ""), out], "empty file"),
            (["map", self.write("header.csv", header), out], "header only"),
            (["map", TMP, out], "is a directory"),
            (["map", self.write("bin.csv", b"\xff\xfe\x00\x01", "wb"), out], "not a text CSV"),
            (["map", self.write("cell.csv", header + first.replace(",ok", ",ok").replace(first.split(",")[1], "x", 1)),
              out], "cell.csv:2: column 'torque_in_Nm': 'x' is not a number"),
            (["map", self.write("nan.csv", header + ",".join(c if i != 4 else "nan"
                                                              for i, c in enumerate(first.split(",")))), out],
             "nan.csv:2: column 'oil_temp_C': 'nan' is not a number"),
            (["map", self.write("short.csv", header + ",".join(first.split(",")[:5]) + "\n"), out],
             "short.csv:2: 5 cells, the header has 19"),
            (["map", self.write("ragged.csv", header + first.strip() + ",1,2,3\n"), out], "not a well-formed CSV"),
            (["map", self.write("cols.csv", "speed_in_rpm,torque_in_Nm\n600,100\n"), out], "missing"),
            (["cycle", path("map.csv"), out], "looks like a `gearloss map` file"),
            (["compare", path("map.csv"), out], "'dP_loss_W' missing"),
            (["map", path("trace.csv"), out], "plot.py cycle"),
            (["map", path("map.csv"), out, "--no-such-option"], "unrecognized arguments"),
            (["maps", path("map.csv"), out], "invalid choice"),
            (["map", path("map.csv"), path("out.txt")], "extension"),
            (["map", path("map.csv"), out, "--levels", "0.9,abc"], "'abc' is not a number"),
            (["map", path("map.csv"), out, "--levels", "1"], "2..100"),
            (["map", path("sweep.csv"), out, "--select", "oil=none.yaml"], "no variant has oil=none.yaml"),
            (["map", path("sweep.csv"), out, "--select", "speed=1"], "not a sweep axis"),
            (["cycle", path("trace.csv"), out, "--levels", "5"], "--levels applies to"),
            (["map", path("map.csv"), os.path.join(TMP, "no-folder", "x.png")], "cannot write"),
            (["map", self.write("status.csv", header + first.replace(",ok", ",fine")), out],
             "status.csv:2: column 'status': 'fine' is not a status gearloss writes"),
        ]
        for args, message in cases:
            with self.subTest(args=args[:2]):
                self.refused(args, message)

    def test_matplotlib_missing(self):
        fake = path("fake")
        os.makedirs(os.path.join(fake, "matplotlib"), exist_ok=True)
        self.write("fake/matplotlib/__init__.py", "raise ImportError('hidden by the test')\n")
        self.refused(["map", path("map.csv"), path("never.png")], "python3-matplotlib", env={"PYTHONPATH": fake})

    def test_describe_into_a_closed_pipe_is_quiet(self):
        # `plot.py ... --describe | head -1`: the reader leaves; no traceback, no 'internal error'.
        e = dict(os.environ, MPLCONFIGDIR=path("mpl"))
        e.pop("PLOT_DEBUG", None)
        # A pipe whose reader is already closed: the first write fails with EPIPE, every time.
        read_end, write_end = os.pipe()
        os.close(read_end)
        try:
            r = subprocess.run(["/usr/bin/python3", PLOT, "map", path("map.csv"), path("pipe.png"), "--describe"],
                               stdout=write_end, stderr=subprocess.PIPE, text=True, env=e)
        finally:
            os.close(write_end)
        self.assertEqual(r.stderr, "")
        self.assertEqual(r.returncode, 141)  # 128 + SIGPIPE, as a shell tool ends
        self.assertTrue(os.path.exists(path("pipe.png")))

    def test_long_title_stays_inside_the_picture(self):
        from plotting import labels
        fig = plt.figure(figsize=(6.4, 4.8))
        title = "case " + "very-long-case-name-" * 8 + "\n" + " \u00b7 ".join(f"ratio g{i} 3.{i}" for i in range(12))
        labels.set_title(fig, title)
        fig.canvas.draw()
        box = fig._suptitle.get_window_extent(fig.canvas.get_renderer())
        self.assertGreaterEqual(box.x0, 0)
        self.assertLessEqual(box.x1, fig.bbox.width)
        self.assertEqual(fig._suptitle.get_text().replace("\n", "").replace(" ", ""), title.replace("\n", "").replace(" ", ""))
        plt.close(fig)

    def test_broken_sidecar_is_ignored_with_a_warning(self):
        shutil.copy(path("fixed.csv"), path("side.csv"))
        self.write("side.csv.meta.json", "{not json")
        code, out, err = plot("map", path("side.csv"), path("side.png"), "--describe")
        self.assertEqual(code, 0, err)
        self.assertIn("plot.py: warning: ", err)
        self.assertIn("oil fixed at 80 degC", out)  # still what the CSV shows


if __name__ == "__main__":
    unittest.main(verbosity=1)
