"""Tests of the Python module `gearloss` (docs/python.md), run by ctest (tests/CMakeLists.txt)
with /usr/bin/python3 and PYTHONPATH=BUILD/python.

The other route is the command line: the same points through the built `gearloss` binary
(GEARLOSS_BIN), whose CSV cells must equal the module's values formatted as the CSV writes
them (6 significant digits; fixed decimals for temperatures and efficiency; empty for NaN).
Every file is written inside a temporary directory.
"""
import csv
import math
import os
import shutil
import signal
import subprocess
import tempfile
import threading
import time
import unittest

import numpy as np

import gearloss

BIN = os.environ["GEARLOSS_BIN"]
SRC = os.environ["GEARLOSS_SOURCE_DIR"]
TRANSFER = os.path.join(SRC, "configs", "transfer-box.yaml")
PAOR = os.path.join(SRC, "configs", "oils", "PAOR.yaml")

# Columns the CSV writes with fixed decimals (io/csv_format.hpp append_csv_fixed, map_runner.cpp).
FIXED = {"ambient_temp_C": 2, "oil_temp_C": 3, "efficiency": 6}


def csv_cell(column, value):
    """A module value as the map CSV writes it."""
    if isinstance(value, str):
        return value
    if not math.isfinite(value):
        return ""
    if column in FIXED:
        return f"{value:.{FIXED[column]}f}"
    return f"{0.0 if value == 0 else value:.6g}"


def run_cli(*args):
    r = subprocess.run([BIN, *args], capture_output=True, text=True)
    return r.returncode, r.stdout, r.stderr


def cli_map(tmp, config, *options):
    out = os.path.join(tmp, "map.csv")
    rc, _, err = run_cli("map", config, *options, "-o", out)
    if rc != 0:
        raise AssertionError(f"gearloss map failed ({rc}): {err}")
    with open(out, newline="") as f:
        rows = list(csv.reader(f))
    return rows[0], rows[1:]


def rpm_list(v):
    return ",".join(str(x) for x in v) + "rpm"


def nm_list(v):
    return ",".join(str(x) for x in v) + "Nm"


class Tmp(unittest.TestCase):
    def setUp(self):
        self.tmp = tempfile.mkdtemp(prefix="gearloss-py-")
        self.addCleanup(shutil.rmtree, self.tmp)


class PointAndGrid(Tmp):
    speeds = [600, 1234.5, 2800]
    torques = [50, 150, 333.3]

    def setUp(self):
        super().setUp()
        self.case = gearloss.load_case(TRANSFER)

    def assert_rows_equal(self, header, rows, get):
        for i, row in enumerate(rows):
            for column, text in zip(header, row):
                self.assertEqual(csv_cell(column, get(i, column)), text, f"row {i + 1}, column {column}")

    def test_case_properties(self):
        c = self.case
        self.assertIn("transfer-box.yaml", repr(c))
        self.assertEqual(c.file, TRANSFER)
        self.assertEqual(c.ratios, ["low", "high"])
        self.assertEqual(c.ratio, "low")
        self.assertEqual(c.oil, "75W90-A")
        self.assertEqual(c.speeds_rpm, [600.0, 700.0, 800.0])  # configs/transfer-box.yaml operating:
        self.assertEqual(c.torques_Nm, [150.0, 200.0, 250.0])
        self.assertIn("mesh", c.mechanisms)
        self.assertEqual(len(c.mechanisms), len(c.mechanism_columns))

    def test_point_equals_cli_map_detail(self):
        header, rows = cli_map(self.tmp, TRANSFER, "--speed", rpm_list(self.speeds), "--torque", nm_list(self.torques),
                               "--detail")
        points = [self.case.point(s, t) for s in self.speeds for t in self.torques]
        self.assertEqual(list(points[0]), header)  # the same columns in the same order
        self.assertEqual(len(rows), 9)
        self.assert_rows_equal(header, rows, lambda i, col: points[i][col])
        # The films of the detail columns are there, and the balance closes: P_in = P_out + P_loss.
        p = points[4]
        self.assertTrue(any(k.startswith("lambda_") and k != "lambda_min" for k in p))
        self.assertTrue(any(k.startswith("h_min_") for k in p))
        self.assertAlmostEqual(p["power_in_W"], p["power_out_W"] + p["P_total_W"], delta=1e-9 * p["power_in_W"])
        self.assertAlmostEqual(p["P_total_W"], sum(p[c] for c in self.case.mechanism_columns), delta=1e-9 * p["P_total_W"])

    def test_grid_equals_cli_map(self):
        header, rows = cli_map(self.tmp, TRANSFER, "--speed", rpm_list(self.speeds), "--torque", nm_list(self.torques))
        df = self.case.grid(self.speeds, self.torques)
        self.assertEqual(list(df.columns), header)
        self.assertEqual(df.shape, (len(self.speeds) * len(self.torques), len(header)))
        self.assert_rows_equal(header, rows, lambda i, col: df[col].iloc[i])
        # Speed-major, torque-minor, as the CSV.
        self.assertEqual(list(df["speed_in_rpm"][:3]), [600.0] * 3)
        self.assertEqual(list(df["torque_in_Nm"][:3]), [50.0, 150.0, 333.3])

    def test_grid_arrays_without_frame(self):
        cols = self.case.grid(as_frame=False, threads=1)
        header, rows = cli_map(self.tmp, TRANSFER)  # the case's own 3 x 3 grid
        self.assertEqual(list(cols), header)
        for name, a in cols.items():
            self.assertIsInstance(a, np.ndarray, name)
            self.assertEqual(a.shape, (9,), name)
        self.assertEqual(cols["status"].dtype, object)
        self.assert_rows_equal(header, rows, lambda i, col: cols[col][i])

    def test_grid_detail_and_fixed_oil_temperature(self):
        header, rows = cli_map(self.tmp, TRANSFER, "--speed", "900rpm", "--torque", "10,400Nm", "--oil-temp", "70degC",
                               "--detail")
        df = self.case.grid(900, [10, 400], oil_temp_C=70, detail=True)
        self.assertEqual(list(df.columns), header)
        self.assert_rows_equal(header, rows, lambda i, col: df[col].iloc[i])
        self.assertTrue((df["oil_temp_C"] == 70.0).all())

    def test_no_values_are_nan(self):
        # 1e6 rpm is the stated range's end; the transfer box has no equilibrium there or its
        # components leave their range: no numbers, as the CSV's empty cells.
        header, rows = cli_map(self.tmp, TRANSFER, "--speed", "999999rpm", "--torque", "150Nm")
        df = self.case.grid(999999, 150)
        self.assertNotEqual(df["status"][0], "ok")
        self.assertTrue(math.isnan(df["P_total_W"][0]))
        self.assert_rows_equal(header, rows, lambda i, col: df[col].iloc[i])

    def test_ratio_and_oil(self):
        high = gearloss.load_case(TRANSFER, ratio="high")
        self.assertEqual(high.ratio, "high")
        header, rows = cli_map(self.tmp, TRANSFER, "--ratio", "high", "--oil", PAOR, "--speed", "700rpm",
                               "--torque", "200Nm")
        paor = high.with_oil(PAOR)
        self.assertEqual(paor.oil, "PAOR")
        self.assertEqual(paor.oil_file, PAOR)
        self.assertEqual(high.oil, "75W90-A")  # the original case is unchanged
        p = paor.point(700, 200)
        self.assert_rows_equal(header, rows, lambda i, col: p[col])
        self.assertNotEqual(csv_cell("P_total_W", high.point(700, 200)["P_total_W"]), rows[0][header.index("P_total_W")])


class Errors(Tmp):
    def broken_case(self, old, new):
        """The transfer box with `old` replaced by `new` (the oil file named absolutely): its
        path and the 1-based line of the change, found in the text."""
        with open(TRANSFER) as f:
            text = f.read()
        self.assertIn(old, text)
        text = text.replace("oil: oils/", f"oil: {SRC}/configs/oils/", 1).replace(old, new, 1)
        path = os.path.join(self.tmp, "broken.yaml")
        with open(path, "w") as f:
            f.write(text)
        line = text[: text.index(new)].count("\n") + 1
        return path, line

    def assert_same_as_cli(self, e, path):
        rc, _, err = run_cli("check", path)
        self.assertEqual(rc, 2)
        self.assertEqual(err.strip().splitlines()[-1], "gearloss: error: " + str(e))

    def test_bad_value_names_file_line_key(self):
        path, line = self.broken_case("torques: [150 N*m, 200 N*m, 250 N*m]", "torques: [150 N*m, 200 kg, 250 N*m]")
        with self.assertRaises(gearloss.InputError) as cm:
            gearloss.load_case(path)
        e = cm.exception
        self.assertIsInstance(e, ValueError)
        self.assertIsInstance(e, gearloss.Error)
        self.assertEqual(e.file, path)
        self.assertEqual(e.line, line)
        self.assertIsInstance(e.column, int)
        self.assertIn("torques", e.key)
        self.assertTrue(str(e).startswith(f"{path}:{line}:{e.column}: {e.key}: "), str(e))
        self.assertEqual(str(e), f"{path}:{line}:{e.column}: {e.key}: {e.message}")
        self.assert_same_as_cli(e, path)

    def test_yaml_syntax_error_line(self):
        path, line = self.broken_case("torques: [150 N*m, 200 N*m, 250 N*m]", "torques: [150 N*m, 200 N*m, 250 N*m")
        with self.assertRaises(gearloss.InputError) as cm:
            gearloss.load_case(path)
        self.assertEqual(cm.exception.file, path)
        self.assertGreaterEqual(cm.exception.line, line)  # the parser notices the missing ']' at or after it
        self.assert_same_as_cli(cm.exception, path)

    def test_arguments(self):
        case = gearloss.load_case(TRANSFER)
        with self.assertRaises(gearloss.InputError) as cm:
            case.point(2e6, 100)
        self.assertEqual(cm.exception.key, "speed_rpm")
        self.assertIsNone(cm.exception.line)
        with self.assertRaises(gearloss.InputError) as cm:
            case.grid(torques_Nm=[100, float("nan")])
        self.assertEqual(cm.exception.key, "torques_Nm")
        with self.assertRaises(gearloss.InputError) as cm:
            case.grid(threads=5000)
        self.assertEqual(cm.exception.key, "threads")
        with self.assertRaises(gearloss.InputError) as cm:
            gearloss.load_case(TRANSFER, ratio="overdrive")
        self.assertEqual(cm.exception.key, "ratio")
        self.assertIn("unknown ratio 'overdrive'", str(cm.exception))
        with self.assertRaises(gearloss.InputError):
            gearloss.load_case(os.path.join(self.tmp, "missing.yaml"))
        with self.assertRaises(gearloss.InputError):
            case.with_oil(os.path.join(self.tmp, "missing-oil.yaml"))


class Diagnosis(Tmp):
    def test_synth_campaign_names_the_concealed_effect(self):
        case = gearloss.load_case(TRANSFER)
        rec = os.path.join(self.tmp, "rec.csv")
        grid = ["--speed", "400,700,1000,1300rpm", "--torque", "100,200,300Nm"]
        rc, _, err = run_cli("synth", TRANSFER, "--effect", "windage=30W", "--seed", "3", *grid, "-o", rec)
        self.assertEqual(rc, 0, err)
        # The module's synth is the CLI's, byte for byte.
        text = gearloss.synth(case, {"windage": "30W"}, seed=3, speeds_rpm=[400, 700, 1000, 1300],
                              torques_Nm=[100, 200, 300])
        with open(rec) as f:
            self.assertEqual(text, f.read())
        d = gearloss.diagnose(case, rec, loss_uncertainty=0.015, temp_uncertainty_K=0.4)
        self.assertEqual(d.effects[0], "windage")
        self.assertEqual(d.points, 12)
        self.assertLess(d.rmse_after_W, 0.5 * d.rmse_before_W)
        f = d.findings[0]
        self.assertLess(f.improvement, 0.5)
        # Concealed: 30 W at 1000 rpm; found within four of its uncertainties.
        self.assertEqual(f.parameter["unit"], "W")
        self.assertLess(abs(f.parameter["value"] - 30.0), 4 * f.parameter["uncertainty"] + 1e-9)
        self.assertIn("speed", d.location)
        self.assertIsNone(f.shape)  # windage has no shape setting fitted with it
        self.assertEqual(len(d.residuals), 12)
        # The CLI's diagnosis of the same recordings: the same verdict, effects and numbers.
        out = os.path.join(self.tmp, "d.json")
        rc, stdout, err = run_cli("diagnose", TRANSFER, rec, "--loss-uncertainty", "1.5%", "--temp-uncertainty", "0.4K",
                                  "--json", out)
        self.assertEqual(rc, 0, err)
        import json
        with open(out) as fh:
            j = json.load(fh)
        self.assertEqual(d.verdict, j["verdict"])
        self.assertEqual(d.effects, [x["effect"] for x in j["findings"]])
        self.assertAlmostEqual(d.rmse_after_W, j["rmse_after"], delta=1e-9 * j["rmse_after"])
        self.assertEqual(d.text, stdout)
        self.assertEqual(d.main_finding, j.get("main_finding"))
        self.assertEqual(d.unsettled, j.get("unsettled"))  # None here, and absent from the JSON
        self.assertEqual(d.run_order, j["run_order"])
        self.assertEqual(d.noise_used["source"], j["noise_used"]["source"])

    def test_bad_recordings(self):
        bad = os.path.join(self.tmp, "bad.csv")
        with open(bad, "w") as f:
            f.write("speed_in_rpm,torque_in_Nm,P_loss_W\n600,150,210\n700,150\n")
        with self.assertRaises(gearloss.InputError) as cm:
            gearloss.diagnose(gearloss.load_case(TRANSFER), bad)
        self.assertEqual((cm.exception.file, cm.exception.line), (bad, 3))


class Interrupt(unittest.TestCase):
    def test_ctrl_c_stops_a_long_grid_and_the_gil_is_free(self):
        case = gearloss.load_case(TRANSFER)
        speeds = list(np.linspace(300, 3000, 1000))
        torques = list(np.linspace(10, 400, 1000))  # 10^6 points: tens of seconds on this machine
        ticks = []

        def other_thread():
            t0 = time.monotonic()
            while time.monotonic() - t0 < 0.5:  # runs only while the grid has released the GIL
                ticks.append(1)
                time.sleep(0.01)
            os.kill(os.getpid(), signal.SIGINT)

        threading.Thread(target=other_thread, daemon=True).start()
        t0 = time.monotonic()
        with self.assertRaises(KeyboardInterrupt):
            case.grid(speeds, torques, threads=1, as_frame=False)
        elapsed = time.monotonic() - t0
        self.assertGreater(len(ticks), 10)
        self.assertLess(elapsed, 8.0)
        # The library's interrupt flag was reset: the next solve is complete.
        self.assertEqual(case.grid(as_frame=False)["status"].tolist(), ["ok"] * 9)


if __name__ == "__main__":
    unittest.main(verbosity=2)
