#!/usr/bin/python3
"""The Python module `gearloss` on a shipped case (docs/python.md): one point, a small grid as
a table, optionally a picture of efficiency over torque (matplotlib) into the file given.

Usage (after scripts/build.sh, from the repository):
    PYTHONPATH=build/python /usr/bin/python3 scripts/python-example.py [OUT.png] [--config CASE.yaml]
"""
import argparse
import os
import sys

try:
    import gearloss
except ImportError:
    sys.exit("python-example.py: the module gearloss is not importable: build it (scripts/build.sh) and run with "
             "PYTHONPATH=build/python /usr/bin/python3 (the module is built for that interpreter)")

here = os.path.dirname(os.path.abspath(__file__))
parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
parser.add_argument("picture", nargs="?", help="also draw efficiency over torque into this file (.png, .svg, .pdf)")
parser.add_argument("--config", default=os.path.join(here, "..", "configs", "transfer-box.yaml"),
                    help="case file (default: the shipped transfer gearbox)")
args = parser.parse_args()

try:
    case = gearloss.load_case(args.config)
except gearloss.InputError as e:  # "file:line:col: key: message", as the command line prints it
    sys.exit(f"python-example.py: {e}")
print(case)
print(f"mechanisms: {', '.join(case.mechanisms)}; ratios: {', '.join(case.ratios) or '-'}")

p = case.point(1500, 200)
print(f"\n1500 rpm, 200 N*m: P_total {p['P_total_W']:.1f} W, efficiency {100 * p['efficiency']:.2f} %, "
      f"oil {p['oil_temp_C']:.1f} degC, lambda_min {p['lambda_min']:.3f} ({p['status']})")

speeds = [500, 1000, 2000, 3000]
torques = [50, 100, 200, 300, 400]
df = case.grid(speeds, torques, as_frame=False)  # a dict of numpy arrays (a DataFrame by default with pandas)
print(f"\nefficiency [%] ({case.thermal_mode} oil temperature), rows: speed [rpm], columns: torque [N*m]")
print("        " + "".join(f"{t:>8g}" for t in torques))
n = len(torques)
for i, s in enumerate(speeds):
    cells = df["efficiency"][i * n:(i + 1) * n]
    print(f"{s:>8g}" + "".join(f"{100 * e:8.2f}" if e == e else f"{'-':>8}" for e in cells))
missing = sorted({st for st, e in zip(df["status"], df["efficiency"]) if e != e})
if missing:
    print(f"-: no value (status: {', '.join(missing)})")

if args.picture:
    try:
        import matplotlib
        matplotlib.use("Agg")
        import matplotlib.pyplot as plt
    except ImportError:
        sys.exit("python-example.py: drawing needs matplotlib (Debian: python3-matplotlib)")
    fine = [float(t) for t in range(20, 401, 20)]
    fig, ax = plt.subplots(figsize=(6, 4))
    for s in speeds:
        g = case.grid([s], fine, as_frame=False)
        ax.plot(g["torque_in_Nm"], 100 * g["efficiency"], marker=".", label=f"{s} rpm")
    ax.set_xlabel("input torque [N m]")
    ax.set_ylabel("efficiency [%]")
    ax.set_title(f"{case.name}, oil {case.oil}, {case.thermal_mode} oil temperature", fontsize=9)
    ax.legend()
    ax.grid(alpha=0.3)
    fig.tight_layout()
    fig.savefig(args.picture)
    print(f"\nwrote {args.picture}")
