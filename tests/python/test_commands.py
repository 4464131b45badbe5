"""Tests of the Python module's calls beside point and grid (docs/python.md): load from a path, a
YAML string or a dict, check, compare, spread, sweeps and cycle, each against the command line
(GEARLOSS_BIN) on the same case: the same report text, the same JSON keys and values, the same
CSV cells. Run by ctest with the build tree's module (python_module) and, installed by pip into
fresh venvs, by python_install (tests/python/install_check.py). Needs no numpy or pandas (the
tables are compared as dicts of lists; with pandas a DataFrame is checked too).
"""
import csv
import json
import math
import os
import shutil
import subprocess
import tempfile
import unittest
import warnings

import gearloss
from gearloss._tables import columns_of, have_pandas

BIN = os.environ["GEARLOSS_BIN"]
SRC = os.environ["GEARLOSS_SOURCE_DIR"]
CONFIGS = os.path.join(SRC, "configs")
TRANSFER = os.path.join(CONFIGS, "transfer-box.yaml")
AUTOMATIC = os.path.join(CONFIGS, "automatic-6speed.yaml")
DESIGNATIONS = os.path.join(CONFIGS, "fzg-c40-paor-designations.yaml")
OIL_A = os.path.join(CONFIGS, "oils", "75W90-A.yaml")
OIL_B = os.path.join(CONFIGS, "oils", "75W140-A.yaml")
OIL_C = os.path.join(CONFIGS, "oils", "75W90-syn-A.yaml")

try:
    import yaml
except ImportError:  # a venv without the system's packages
    yaml = None


def cli(*args, cwd=None):
    r = subprocess.run([BIN, *args], capture_output=True, text=True, cwd=cwd)
    if r.returncode != 0:
        raise AssertionError(f"gearloss {' '.join(args)} failed ({r.returncode}): {r.stderr}")
    return r.stdout


def cli_csv(tmp, *args):
    out = os.path.join(tmp, "out.csv")
    cli(*args, "-o", out)
    with open(out, newline="") as f:
        return f.read()


def read(path):
    with open(path, encoding="utf-8") as f:
        return f.read()


def same(a, b):
    """Cells equal (NaN, an empty cell, equals NaN)."""
    if isinstance(a, float) and isinstance(b, float) and math.isnan(a) and math.isnan(b):
        return True
    return a == b


class Tmp(unittest.TestCase):
    def setUp(self):
        self.tmp = tempfile.mkdtemp(prefix="gearloss-py-")
        self.addCleanup(shutil.rmtree, self.tmp)
        warnings.simplefilter("ignore", gearloss.CaseWarning)

    def assert_table_equals_csv(self, table, text):
        """Every cell of a module table (dict of lists) equals the CLI CSV's cell."""
        expected = columns_of(text)
        self.assertEqual(list(table), list(expected))  # the CLI's columns, in its order
        rows = len(next(iter(expected.values())))
        self.assertGreater(rows, 0)
        for name, cells in expected.items():
            self.assertEqual(len(table[name]), rows, name)
            for i, (a, b) in enumerate(zip(table[name], cells)):
                self.assertTrue(same(a, b), f"row {i + 1}, column {name}: {a!r} != CLI {b!r}")


class Load(Tmp):
    def assert_point_equal(self, a, b):
        self.assertEqual(list(a), list(b))
        for k in a:
            self.assertTrue(same(a[k], b[k]), f"{k}: {a[k]!r} != {b[k]!r}")

    def test_string_and_path_give_the_same_case(self):
        text = read(TRANSFER)
        by_path = gearloss.load(TRANSFER)
        by_text = gearloss.load(text, base_dir=CONFIGS)  # oil: oils/75W90-A.yaml, relative to base_dir
        self.assertEqual(by_text.file, "<string>")
        self.assertEqual(by_text.oil, by_path.oil)
        self.assert_point_equal(by_text.point(1234, 210), by_path.point(1234, 210))
        # Relative paths against the current directory when base_dir is not given.
        cwd = os.getcwd()
        os.chdir(CONFIGS)
        try:
            by_cwd = gearloss.load(text)
        finally:
            os.chdir(cwd)
        self.assert_point_equal(by_cwd.point(1234, 210), by_path.point(1234, 210))
        # Not found from elsewhere: an InputError naming the oil key.
        with self.assertRaises(gearloss.InputError) as e:
            gearloss.load(text, base_dir=self.tmp)
        self.assertEqual(e.exception.file, "<string>")
        self.assertIn("oil", str(e.exception))

    @unittest.skipIf(yaml is None, "PyYAML is not importable")
    def test_dict_equals_cli_on_the_same_document(self):
        with open(TRANSFER, encoding="utf-8") as f:
            doc = yaml.safe_load(f)
        doc["oil"] = OIL_B  # an absolute path
        doc["housing"]["oil_level"] = "-20 mm"
        case = gearloss.load(doc)
        self.assertEqual(case.file, "<dict>")
        # The CLI on the same document written as a file.
        path = os.path.join(self.tmp, "case.yaml")
        with open(path, "w", encoding="utf-8") as f:
            yaml.safe_dump(doc, f, sort_keys=False)
        text = cli_csv(self.tmp, "map", path, "--speed", "700,1500rpm", "--torque", "120,300Nm")
        self.assert_table_equals_csv(case.sweeps([700, 1500], [120, 300], as_frame=False), text)
        self.assertEqual(case.check(json=True)["oil"], gearloss.load(path).check(json=True)["oil"])
        # A wrong value: an InputError naming the key, in the document's text.
        doc["housing"]["oil_level"] = "-20 kg"
        with self.assertRaises(gearloss.InputError) as e:
            gearloss.load(doc)
        self.assertEqual(e.exception.file, "<dict>")
        self.assertIn("oil_level", str(e.exception))

    def test_designations_read_the_shipped_catalogue(self):
        # The bearings named by designation only: the catalogue the package ships is found.
        case = gearloss.load(DESIGNATIONS)
        text = cli_csv(self.tmp, "map", DESIGNATIONS, "--speed", "1500rpm", "--torque", "200Nm")
        self.assert_table_equals_csv(case.sweeps(1500, 200, as_frame=False), text)


class Check(Tmp):
    def test_report_and_json_equal_cli(self):
        case = gearloss.load(TRANSFER)
        self.assertEqual(case.check(), cli("check", TRANSFER))
        self.assertEqual(case.check(json=True), json.loads(cli("check", TRANSFER, "--json")))

    def test_with_oil_equals_cli_oil(self):
        case = gearloss.load(TRANSFER, ratio="high").with_oil(OIL_B)
        self.assertEqual(case.check(), cli("check", TRANSFER, "--ratio", "high", "--oil", OIL_B))
        self.assertEqual(case.check(json=True), json.loads(cli("check", TRANSFER, "--ratio", "high", "--oil", OIL_B,
                                                              "--json")))


class Compare(Tmp):
    def test_three_oils_equal_cli(self):
        case = gearloss.load(TRANSFER)
        table = case.compare([OIL_A, OIL_B, OIL_C], [600, 1800.5], [80, 333], as_frame=False)
        text = cli_csv(self.tmp, "compare", TRANSFER, "--oil", OIL_A, "--oil", OIL_B, "--oil", OIL_C,
                       "--speed", "600,1800.5rpm", "--torque", "80,333Nm")
        self.assert_table_equals_csv(table, text)
        if have_pandas():
            df = case.compare([OIL_A, OIL_B], [600], [80])
            self.assertEqual(df.shape[0], 1)

    def test_detail_fixed_oil_temperature_equals_cli(self):
        case = gearloss.load(TRANSFER)
        table = case.compare([OIL_A, OIL_B], [900], [150, 250], oil_temp_C=60, detail=True, as_frame=False)
        text = cli_csv(self.tmp, "compare", TRANSFER, "--oil", OIL_A, "--oil", OIL_B, "--speed", "900rpm",
                       "--torque", "150,250Nm", "--oil-temp", "60degC", "--detail")
        self.assert_table_equals_csv(table, text)

    def test_one_oil_is_an_error(self):
        with self.assertRaises(gearloss.InputError) as e:
            gearloss.load(TRANSFER).compare([OIL_A])
        self.assertEqual(e.exception.key, "oils")


class Spread(Tmp):
    def test_spread_equals_cli(self):
        case = gearloss.load(TRANSFER)
        table = case.spread(["mesh.film_correction", "churning.form"], [700, 2000], [100, 300], as_frame=False)
        text = cli_csv(self.tmp, "map", TRANSFER, "--spread", "--spread-axes", "mesh.film_correction,churning.form",
                       "--speed", "700,2000rpm", "--torque", "100,300Nm")
        self.assert_table_equals_csv(table, text)
        self.assertIn("forms_at_max", table)

    def test_unknown_axis_names_the_argument(self):
        with self.assertRaises(gearloss.InputError) as e:
            gearloss.load(TRANSFER).spread(["mesh.colour"], [700], [100])
        self.assertEqual(e.exception.key, "axes")


class Sweeps(Tmp):
    SWEEP = ("\nsweep:\n"
             "  - {parameter: oil, values: [oils/75W90-A.yaml, oils/75W140-A.yaml]}\n"
             "  - {parameter: housing.oil_level, values: [-30 mm, -10 mm]}\n")

    def test_file_and_string_equal_cli(self):
        text = read(TRANSFER) + self.SWEEP
        path = os.path.join(self.tmp, "sweep.yaml")
        with open(path, "w", encoding="utf-8") as f:
            f.write(text)
        os.symlink(os.path.join(CONFIGS, "oils"), os.path.join(self.tmp, "oils"))
        expected = cli_csv(self.tmp, "map", path, "--speed", "650,1300rpm", "--torque", "90,270Nm")
        table = gearloss.load(path).sweeps([650, 1300], [90, 270], as_frame=False)
        self.assert_table_equals_csv(table, expected)
        self.assertEqual(list(table)[:2], ["oil", "housing.oil_level"])
        self.assertEqual(len(table["oil"]), 2 * 2 * 2 * 2)
        from_text = gearloss.load(text, base_dir=CONFIGS).sweeps([650, 1300], [90, 270], as_frame=False)
        self.assertEqual(list(from_text), list(table))
        for name in table:
            self.assertTrue(all(same(a, b) for a, b in zip(from_text[name], table[name])), name)
        # The case's own grid and a fixed oil temperature, with the detail columns.
        expected = cli_csv(self.tmp, "map", path, "--oil-temp", "80degC", "--detail")
        self.assert_table_equals_csv(gearloss.load(path).sweeps(oil_temp_C=80, detail=True, as_frame=False), expected)

    def test_an_argument_that_the_sweep_sets_is_an_error(self):
        text = read(TRANSFER) + self.SWEEP
        case = gearloss.load(text, base_dir=CONFIGS).with_oil(OIL_C)
        with self.assertRaises(gearloss.InputError) as e:
            case.sweeps([600], [100])
        self.assertEqual(e.exception.key, "with_oil")


class Cycle(Tmp):
    def test_summary_and_trace_equal_cli(self):
        case = gearloss.load(AUTOMATIC)
        summary, trace = case.cycle("nedc", -10, prewarm_C=60, heater_W=1000, trace=True, as_frame=False)
        js = os.path.join(self.tmp, "cycle.json")
        out = os.path.join(self.tmp, "trace.csv")
        printed = cli("cycle", AUTOMATIC, "--cycle", "nedc", "--start-temp", "-10degC", "--prewarm", "60degC",
                      "--heater", "1000W", "--json", js, "-o", out)
        with open(js, encoding="utf-8") as f:
            expected = json.load(f)
        self.assertEqual(summary.pop("text"), printed)
        self.assertEqual(summary, expected)
        with open(out, newline="") as f:
            self.assert_table_equals_csv(trace, f.read())

    def test_oil_ambient_and_warm_start_equal_cli(self):
        case = gearloss.load(AUTOMATIC).with_oil(os.path.join(CONFIGS, "oils", "ATF-A.yaml"))
        summary = case.cycle("artemis-urban", 5, ambient_C=20, warm_temp_C=80)
        js = os.path.join(self.tmp, "cycle.json")
        cli("cycle", AUTOMATIC, "--oil", os.path.join(CONFIGS, "oils", "ATF-A.yaml"), "--cycle", "artemis-urban",
            "--start-temp", "5degC", "--ambient", "20degC", "--warm-temp", "80degC", "--json", js)
        with open(js, encoding="utf-8") as f:
            expected = json.load(f)
        summary.pop("text")
        self.assertEqual(summary, expected)

    def test_bad_arguments(self):
        case = gearloss.load(AUTOMATIC)
        with self.assertRaises(gearloss.InputError) as e:
            case.cycle("no-such-cycle", -10)
        self.assertEqual(e.exception.key, "cycle")
        with self.assertRaises(gearloss.InputError) as e:
            case.cycle("nedc", 20, prewarm_C=10)
        self.assertEqual(e.exception.key, "prewarm_C")
        with self.assertRaises(gearloss.InputError) as e:
            gearloss.load(TRANSFER).cycle("nedc", 20)  # no vehicle block
        self.assertEqual(e.exception.key, "vehicle")


class Installed(unittest.TestCase):
    """With GEARLOSS_EXPECT_PREFIX (the install test): the module and its data come from there."""

    @unittest.skipUnless(os.environ.get("GEARLOSS_EXPECT_PREFIX"), "not an installed module")
    def test_module_and_data_inside_the_venv(self):
        prefix = os.path.realpath(os.environ["GEARLOSS_EXPECT_PREFIX"])
        self.assertTrue(os.path.realpath(gearloss.__file__).startswith(prefix + os.sep), gearloss.__file__)
        data = os.path.realpath(os.environ["GEARLOSS_DATA_DIR"])
        self.assertTrue(data.startswith(prefix + os.sep), data)
        self.assertTrue(os.path.isfile(os.path.join(data, "bearings", "catalogue.yaml")))
        self.assertTrue(os.path.isfile(os.path.join(data, "cycles", "nedc.csv")))


if __name__ == "__main__":
    unittest.main(verbosity=2)
