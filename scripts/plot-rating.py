#!/usr/bin/python3
"""The thermal power limit curve of `gearloss rating -o CURVE.csv` as a picture.

  plot-rating.py CURVE.csv OUT.png --title TITLE [--rated SPEED_RPM:POWER_KW ...]

Upper panel: the input power at which the stabilised oil reaches the permissible temperature,
per input speed (speeds where no torque reaches it up to the searched maximum are drawn as open
markers at that bound, speeds above the limit even at no load as crosses on the axis). Lower
panel: the losses at the limit, split by mechanism (they sum to the heat the housing and the
cooler carry away at that temperature). --rated marks operating points (e.g. a power curve).
Needs Debian's python3-matplotlib and python3-pandas.
"""
import argparse
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import pandas as pd  # noqa: E402


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("curve")
    ap.add_argument("out")
    ap.add_argument("--title", required=True)
    ap.add_argument("--rated", action="append", default=[], help="SPEED_RPM:POWER_KW of an operating point")
    a = ap.parse_args()
    d = pd.read_csv(a.curve)
    lim = d[d["rating"] == "limit"]
    none = d[d["rating"] == "no_limit_below"]
    hot = d[d["rating"] == "above_limit_at_zero_torque"]
    fig, (ax, bx) = plt.subplots(2, 1, figsize=(8, 7), sharex=True, gridspec_kw={"height_ratios": [3, 2]})
    ax.plot(lim["speed_in_rpm"], lim["power_in_W"] / 1e3, "o-", color="tab:red", label="thermal power limit")
    if len(none):
        ax.plot(none["speed_in_rpm"], none["power_in_W"] / 1e3, "o", mfc="none", color="tab:red",
                label="no limit up to the searched torque")
    if len(hot):
        ax.plot(hot["speed_in_rpm"], [0] * len(hot), "x", color="k", label="above the limit at no load")
    for r in a.rated:
        s, p = (float(x) for x in r.split(":"))
        ax.plot([s], [p], "s", color="tab:blue")
    if a.rated:
        ax.plot([], [], "s", color="tab:blue", label="operating points")
    ax.set_ylabel("input power at the oil limit [kW]")
    ax.set_ylim(bottom=0)
    ax.grid(alpha=0.3)
    ax.legend(loc="best", fontsize=8)
    # "{limit}" in the title: the permissible oil temperature the curve was computed at.
    limit = f"{lim['oil_temp_C'].iloc[0]:.0f}" if len(lim) else "?"
    ax.set_title(a.title.replace("{limit}", limit), fontsize=10)
    mech = [c for c in d.columns if c.startswith("P_") and c.endswith("_W") and c != "P_loss_W"]
    mech = [c for c in mech if lim[c].fillna(0).abs().sum() > 0]
    bottom = [0.0] * len(lim)
    width = 0.6 * (lim["speed_in_rpm"].diff().median() if len(lim) > 1 else 1.0)
    for c in mech:
        v = (lim[c].fillna(0) / 1e3).tolist()
        bx.bar(lim["speed_in_rpm"], v, width=width, bottom=bottom, label=c[2:-2])
        bottom = [b + x for b, x in zip(bottom, v)]
    if "cooler_heat_W" in lim and lim["cooler_heat_W"].abs().sum() > 0:
        bx.plot(lim["speed_in_rpm"], lim["cooler_heat_W"] / 1e3, "k--", label="of which the cooler removes")
    bx.set_xlabel("input speed [rpm]")
    bx.set_ylabel("losses at the limit [kW]")
    bx.grid(alpha=0.3)
    bx.legend(loc="best", fontsize=8, ncol=2)
    fig.tight_layout()
    fig.savefig(a.out, dpi=110)


if __name__ == "__main__":
    sys.exit(main())
