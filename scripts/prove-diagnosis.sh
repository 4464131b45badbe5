#!/usr/bin/env bash
# Proof that `gearloss diagnose` finds concealed physics: for every effect of
# the library and for null campaigns, on the shipped transfer-gearbox and FZG
# cases, synthesise rig-like recordings (realistic noise, 12-30 points) with
# `gearloss synth`, diagnose them blind, and tabulate effect concealed |
# effect named | parameter error | RMSE before -> after.
# Usage: scripts/prove-diagnosis.sh [--short] [--seeds N] [--binary PATH]
# --short: one seed per effect on the transfer gearbox plus 4 null campaigns (ctest).
set -euo pipefail
cd "$(dirname "$0")/.."
short=0
seeds=3
bin=build/app/gearloss
while [ $# -gt 0 ]; do
    case $1 in
        --short) short=1 ;;
        --seeds) seeds=$2; shift ;;
        --binary) bin=$2; shift ;;
        *) echo "unknown option $1" >&2; exit 1 ;;
    esac
    shift
done
if [ ! -x "$bin" ]; then
    scripts/install-deps.sh
    scripts/build.sh > /dev/null
fi
exec python3 - "$bin" "$short" "$seeds" <<'PY'
import json, os, subprocess, sys, tempfile, time

bin_, short, seeds = sys.argv[1], sys.argv[2] == "1", int(sys.argv[3])
# Campaign grids (rig-like: 12-30 points) and concealed effect sizes per case.
cases = {
    "transfer": {
        "config": "configs/transfer-box.yaml",
        "grids": [("400,600,800,1000,1200rpm", "100,175,250,325Nm"),      # 20 points
                  ("500,700,900,1100rpm", "120,200,280Nm"),               # 12 points
                  ("400,550,700,850,1000,1150rpm", "100,160,220,280,340Nm")],  # 30 points
        "effects": {
            "windage": "25W", "churning": "15", "bearing_drag": "2", "seal_friction": "3",
            "mesh_friction": "1.2", "oil_viscosity": "1.6", "thermal_resistance": "0.8",
            "speed_dependent_cooling": "0.6", "torque_sensor_gain": "1.006",
            "torque_sensor_offset": "0.5Nm", "unstabilised_test": "2", "constant_parasitic": "30W",
        },
    },
    "fzg": {
        "config": "configs/fzg-c40-paor.yaml",
        "grids": [("300,700,1100,1500,2000rpm", "70,132.5,215.5,319.2Nm"),
                  ("500,1000,1500,2000rpm", "98.8,171.6,265Nm"),
                  ("300,600,900,1200,1500,1800rpm", "46.6,98.8,171.6,265,378.3Nm")],
        "effects": {
            "windage": "20W", "churning": "1.6", "bearing_drag": "2", "seal_friction": "2.5",
            "mesh_friction": "1.2", "oil_viscosity": "1.6", "thermal_resistance": "0.8",
            "speed_dependent_cooling": "0.6", "torque_sensor_gain": "1.006",
            "torque_sensor_offset": "0.4Nm", "unstabilised_test": "2", "constant_parasitic": "25W",
        },
    },
}
noise = [("1.5%", "0.4K"), ("1%", "0.3K"), ("2%", "0.5K")]
runs = []
for case, c in cases.items():
    if short and case != "transfer":
        continue
    for s in range(1 if short else seeds):
        for eff, val in c["effects"].items():
            runs.append((case, eff, val, s))
    for s in range(4 if short else 3 * seeds):
        runs.append((case, None, None, s))
    # Raw 0.5 Hz rig logs (split into tests, seed 001's stabilisation criterion),
    # each with one extra test stopped before equilibrium that the criterion must flag.
    log_effects = ["windage", "mesh_friction", "torque_sensor_gain"] if short else \
        [e for e in c["effects"] if e != "unstabilised_test"]
    for e in log_effects:
        runs.append((case, e, c["effects"][e], "log"))

def unit_value(v):
    num = "".join(ch for ch in v if ch in "0123456789.-+e")
    return float(num)

rows, ok_eff, n_eff, ok_null, n_null = [], 0, 0, 0, 0
t0 = time.time()
with tempfile.TemporaryDirectory() as tmp:
    for case, eff, val, s in runs:
        c = cases[case]
        log = s == "log"
        si = 1 if log else s
        speeds, torques = c["grids"][si % len(c["grids"])]
        nl, nt = noise[si % len(noise)]
        seed = 1000 * (1 + list(cases).index(case)) + 37 * si + (0 if eff is None else 1 + sorted(c["effects"]).index(eff)) \
            + (500 if log else 0)
        rec, js = os.path.join(tmp, "rec.csv"), os.path.join(tmp, "d.json")
        cmd = [bin_, "synth", c["config"], "--speed", speeds, "--torque", torques, "--noise-loss", nl,
               "--noise-temp", nt, "--seed", str(seed), "-o", rec]
        if eff:
            cmd += ["--effect", f"{eff}={val}"]
        if log:
            cmd += ["--format", "log", "--effect", "unstabilised_test=1"]
        subprocess.run(cmd, check=True)
        subprocess.run([bin_, "diagnose", c["config"], rec, "--json", js], check=True, stdout=subprocess.DEVNULL)
        d = json.load(open(js))
        top = d["findings"][0]["effect"] if d["findings"] else d["verdict"]
        npts = len(speeds.split(",")) * len(torques.split(","))
        if eff is None:
            n_null += 1
            good = d["verdict"] == "no_significant_mismatch"
            ok_null += good
            rows.append((case, npts, nl, "none", "-", top, "-", d["rmse_before"], d["rmse_after"],
                         d.get("temp_rmse_before", 0), d.get("temp_rmse_after", 0), good))
        else:
            n_eff += 1
            good = top == eff
            if log:
                good = good and any("never stabilised" in o["reason"] for o in d["outliers"])
            ok_eff += good
            err = "-"
            if good and eff != "unstabilised_test":
                p = list(d["findings"][0]["parameters"].values())[0]
                true = unit_value(val)
                err = f"{100 * (p['value'] - true) / abs(true):+.1f} %"
            elif good:
                err = f"{len(d['findings'][0].get('rows', []))}/2 rows"
            f0 = d["findings"][0] if d["findings"] else None
            rows.append((case + (" (log)" if log else ""), npts, nl, f"{eff}={val}", "", top, err,
                         f0["rmse_before"] if f0 else d["rmse_before"], f0["rmse_after"] if f0 else d["rmse_after"],
                         (f0 or d).get("temp_rmse_before", 0), (f0 or d).get("temp_rmse_after", 0), good))

print("| case | points | noise | effect concealed | effect named | parameter error | loss RMSE before -> after [W] | oil temp. RMSE before -> after [K] | ok |")
print("|---|---|---|---|---|---|---|---|---|")
for case, npts, nl, conc, _, top, err, rb, ra, tb, ta, good in rows:
    print(f"| {case} | {npts} | {nl} | {conc} | {top} | {err} | {rb:.1f} -> {ra:.1f} | {tb:.2f} -> {ta:.2f} | {'yes' if good else 'NO'} |")
pe = ok_eff / n_eff if n_eff else 1.0
pn = ok_null / n_null if n_null else 1.0
print()
print(f"effect cases: {ok_eff}/{n_eff} correct top finding ({100 * pe:.0f} %, acceptance >= 90 %)")
print(f"null cases: {ok_null}/{n_null} 'no significant missing physics' ({100 * pn:.0f} %, acceptance >= 95 %)")
print(f"{len(runs)} campaigns in {time.time() - t0:.1f} s")
passed = pe >= 0.90 and pn >= 0.95
print(f"{ok_eff + ok_null} passed, {n_eff + n_null - ok_eff - ok_null} failed")
sys.exit(0 if passed else 1)
PY
