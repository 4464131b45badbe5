#!/usr/bin/env python3
"""Residual plots before/after a diagnosis (PNG).

Usage: scripts/plot-residuals.py RESIDUALS.csv OUT.png [--title TEXT]
RESIDUALS.csv is written by `gearloss diagnose ... --residuals FILE`.
Needs Debian's python3-matplotlib (scripts/plot-residuals.sh installs it).
"""
import argparse
import csv

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("residuals")
    ap.add_argument("out")
    ap.add_argument("--title", default="gearloss diagnose: residuals before and after")
    a = ap.parse_args()
    rows = list(csv.DictReader(open(a.residuals)))
    f = lambda k: [float(r[k]) if r[k] else float("nan") for r in rows]
    n, tq = f("speed_in_rpm"), f("torque_in_Nm")
    P, Pb, Pa = f("P_loss_W"), f("P_model_before_W"), f("P_model_after_W")
    has_T = any(r["oil_temp_C"] for r in rows)
    ncol = 2 if has_T else 1
    fig, ax = plt.subplots(2, ncol, figsize=(6 * ncol, 8), squeeze=False)
    sc = ax[0][0].scatter(n, [p - b for p, b in zip(P, Pb)], c=tq, marker="o", label="before", cmap="viridis")
    ax[0][0].scatter(n, [p - b for p, b in zip(P, Pa)], c=tq, marker="x", label="after", cmap="viridis")
    ax[0][0].axhline(0, color="grey", lw=0.8)
    ax[0][0].set_xlabel("input speed [rpm]")
    ax[0][0].set_ylabel("loss residual, recorded - model [W]")
    ax[0][0].legend()
    fig.colorbar(sc, ax=ax[0][0], label="input torque [N m]")
    lo, hi = min(P + Pb + Pa), max(P + Pb + Pa)
    ax[1][0].plot([lo, hi], [lo, hi], color="grey", lw=0.8)
    ax[1][0].scatter(Pb, P, marker="o", label="before")
    ax[1][0].scatter(Pa, P, marker="x", label="after")
    ax[1][0].set_xlabel("model loss [W]")
    ax[1][0].set_ylabel("recorded loss [W]")
    ax[1][0].legend()
    if has_T:
        T, Tb, Ta = f("oil_temp_C"), f("oil_temp_model_before_C"), f("oil_temp_model_after_C")
        ax[0][1].scatter(n, [t - b for t, b in zip(T, Tb)], c=tq, marker="o", label="before", cmap="viridis")
        ax[0][1].scatter(n, [t - b for t, b in zip(T, Ta)], c=tq, marker="x", label="after", cmap="viridis")
        ax[0][1].axhline(0, color="grey", lw=0.8)
        ax[0][1].set_xlabel("input speed [rpm]")
        ax[0][1].set_ylabel("oil temperature residual [K]")
        ax[0][1].legend()
        lo, hi = min(T + Tb + Ta), max(T + Tb + Ta)
        ax[1][1].plot([lo, hi], [lo, hi], color="grey", lw=0.8)
        ax[1][1].scatter(Tb, T, marker="o", label="before")
        ax[1][1].scatter(Ta, T, marker="x", label="after")
        ax[1][1].set_xlabel("model oil temperature [degC]")
        ax[1][1].set_ylabel("recorded oil temperature [degC]")
        ax[1][1].legend()
    fig.suptitle(a.title)
    fig.tight_layout()
    fig.savefig(a.out, dpi=110)


if __name__ == "__main__":
    main()
