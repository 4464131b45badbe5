"""The model part, from the binary at fixed oil temperatures only.

`gearloss map CASE --oil-temp T --detail` over the superset grid at every temperature of
TGRID (5..150 degC), then per point and per loss column a PCHIP interpolation in the oil
temperature. This is the only use of the model: no synth, no candidate forms, no coupled
solve. run_map is also how the heat-balance checks get the binary's stabilised map.
"""
import csv
import subprocess
import time
from pathlib import Path

from .numerics import Pchip, num

TGRID = [5.0 + 5.0 * k for k in range(30)]  # 5 .. 150 degC, the model's fixed-temperature grid
COLS = ["P_total_W", "P_mesh_W", "P_churn_W", "P_bearing_W", "P_seal_W", "power_in_W", "power_out_W",
        "torque_out_Nm", "lambda_min"]


def fmt_list(v):
    return ",".join(f"{x:g}" for x in v)


def run_map(binary, config, speeds, torques, out_csv, oil_temp=None):
    cmd = ["nice", "-n", "19", binary, "map", str(config), "--speed", fmt_list(speeds) + "rpm",
           "--torque", fmt_list(torques) + "Nm", "--detail", "-o", str(out_csv)]
    if oil_temp is not None:
        cmd += ["--oil-temp", f"{oil_temp:g}degC"]
    r = subprocess.run(cmd, capture_output=True, text=True)
    if r.returncode != 0:
        raise RuntimeError(f"{' '.join(cmd)}\n{r.stderr}")
    with open(out_csv) as f:
        return list(csv.DictReader(f))


class ModelTable:
    """P(n, T_load, T_oil) per point of the superset grid and per column, interpolated in T_oil."""

    def __init__(self, binary, config, case, workdir, log):
        self.speeds, self.torques = case["speeds"], case["torques"]
        self.points = [(n, t) for n in self.speeds for t in self.torques]  # map's row order
        raw = {c: [[None] * len(TGRID) for _ in self.points] for c in COLS}
        self.failed = 0  # points x temperatures the map did not solve (status other than ok / above_oil_limit)
        t0 = time.time()
        for j, t in enumerate(TGRID):
            rows = run_map(binary, config, self.speeds, self.torques, Path(workdir) / f"map_{t:g}C.csv", t)
            assert len(rows) == len(self.points)
            for i, row in enumerate(rows):
                ok = row.get("status", "ok") in ("ok", "above_oil_limit")
                self.failed += not ok
                for c in COLS:
                    raw[c][i][j] = num(row.get(c)) if ok else None
        log(f"  mapped {len(self.points)} points x {len(TGRID)} oil temperatures in {time.time() - t0:.1f} s")
        self.interp = {c: [] for c in COLS}
        self.trange = []
        for i in range(len(self.points)):
            valid = [j for j in range(len(TGRID)) if raw["P_total_W"][i][j] is not None]
            # longest contiguous run of valid temperatures
            best, cur = [], []
            for j in range(len(TGRID)):
                if j in valid:
                    cur.append(j)
                    if len(cur) > len(best):
                        best = list(cur)
                else:
                    cur = []
            self.trange.append((TGRID[best[0]], TGRID[best[-1]]) if len(best) >= 2 else None)
            for c in COLS:
                js = [j for j in best if raw[c][i][j] is not None]
                if len(js) >= 2:
                    self.interp[c].append(Pchip([TGRID[j] for j in js], [raw[c][i][j] for j in js]))
                else:
                    self.interp[c].append(None)
        self.raw = raw

    def get(self, col, i, t):
        f = self.interp[col][i]
        if f is None:
            return 0.0 if col != "lambda_min" else None
        t = min(max(t, f.lo()), f.hi())
        return f(t)

    def valid(self, i, t):
        r = self.trange[i]
        return r is not None and r[0] - 1e-9 <= t <= r[1] + 1e-9
