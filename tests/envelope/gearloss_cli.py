"""The gearloss command line as a user drives it: maps, points and cycles read back from the
files the tool writes (CSV, its metadata sidecar, point and cycle JSON). Nothing here imports
the library under test."""
import csv
import json
import os
import subprocess
import tempfile
import threading


class ToolFailure(Exception):
    """The tool exited non-zero where a valid case and valid arguments were given."""

    def __init__(self, argv, rc, stderr):
        super().__init__(f"exit {rc}: {' '.join(argv[1:])}: {stderr.strip()[-400:]}")
        self.argv, self.rc, self.stderr = argv, rc, stderr


class Gearloss:
    def __init__(self, binary, workdir=None):
        self.binary = binary
        self.workdir = workdir or tempfile.mkdtemp(prefix="gearloss-envelope-")
        self._n = 0
        self._lock = threading.Lock()   # maps run from a thread pool: one name per file
        self._regimes = {}

    def _tmp(self, suffix):
        with self._lock:
            self._n += 1
            n = self._n
        return os.path.join(self.workdir, f"f{os.getpid()}_{n}{suffix}")

    def run(self, args, check=True):
        argv = [self.binary] + [str(a) for a in args]
        p = subprocess.run(argv, capture_output=True, text=True)
        if check and p.returncode != 0:
            raise ToolFailure(argv, p.returncode, p.stderr)
        return p

    def map(self, case, oil_temp_C, speeds, torques, oil=None, ratio=None):
        """Rows of `map --detail` at a fixed oil temperature as dicts of floats (status as str)."""
        out = self._tmp(".csv")
        args = ["map", case, "--detail", "--threads", "1", "-o", out]
        if oil_temp_C is not None:   # None: the case's thermal mode (stabilised: solved)
            args += ["--oil-temp", f"{oil_temp_C:g}degC"]
        if speeds is not None:
            args += ["--speed", ",".join(f"{s:g}" for s in speeds) + "rpm"]
        if torques is not None:
            args += ["--torque", ",".join(f"{t:g}" for t in torques) + "Nm"]
        if oil:
            args += ["--oil", oil]
        if ratio:
            args += ["--ratio", ratio]
        self.run(args)
        rows = read_csv(out)
        os.remove(out)
        meta = out + ".meta.json"
        if os.path.exists(meta):
            os.remove(meta)
        return rows

    def point_json(self, case, speed, torque, oil_temp_C, oil=None):
        args = ["point", case, "--speed", f"{speed:g}rpm", "--torque", f"{torque:g}Nm",
                "--oil-temp", f"{oil_temp_C:g}degC", "--json", "-"]
        if oil:
            args += ["--oil", oil]
        return json.loads(self.run(args).stdout)

    def point_regimes(self, case, speed, torque, oil_temp_C, oil=None):
        """The regimes `point` names, per component: every row of a section whose header has a
        'regime' column (today: churning, Changenet & Velex flow regime per gear), plus the
        point's status and the idle/loaded state of each mesh."""
        key = (case, speed, torque, oil_temp_C, oil)
        if key in self._regimes:
            return self._regimes[key]
        args = ["point", case, "--speed", f"{speed:g}rpm", "--torque", f"{torque:g}Nm",
                "--oil-temp", f"{oil_temp_C:g}degC"]
        if oil:
            args += ["--oil", oil]
        text = self.run(args).stdout
        regimes, section, in_regime_table = {}, None, False
        for line in text.splitlines():
            if line.startswith("status:"):
                regimes["status"] = line.split(":", 1)[1].strip()
            if line and not line.startswith(" "):
                section = line.split()[0]
                in_regime_table = line.rstrip().endswith("regime")
                continue
            words = line.split()
            if not words:
                continue
            if in_regime_table:
                regimes[f"{section}:{words[0]}"] = words[-1]
            if "idle" in words:
                regimes[f"{section}:{words[0]}"] = "idle"
        self._regimes[key] = regimes
        return regimes

    def mechanisms(self, case):
        """(name, total column, [component loss columns]) of every mechanism, from the JSON of
        one point: the tool's own list, never a list written here."""
        d = self.point_json(case, 1000, 10, 60)
        out = []
        for m in d["mechanisms"]:
            comps = []
            for c in m.get("components", []):
                comps += [k for k in c if k.startswith("P_") and k.endswith("_W")]
            out.append((m["name"], m["column"], comps))
        return out

    def cycle(self, case, cycle, start_C, ambient_C=None, oil=None):
        out = self._tmp(".json")
        args = ["cycle", case, "--cycle", cycle, "--start-temp", f"{start_C:g}degC", "--json", out]
        if ambient_C is not None:
            args += ["--ambient", f"{ambient_C:g}degC"]
        if oil:
            args += ["--oil", oil]
        self.run(args)
        with open(out) as f:
            d = json.load(f)
        os.remove(out)
        return d


def _num(v):
    if v == "":
        return float("nan")
    try:
        return float(v)
    except ValueError:
        return v


def read_csv(path):
    with open(path, newline="") as f:
        return [{k: _num(v) for k, v in row.items()} for row in csv.DictReader(f)]
