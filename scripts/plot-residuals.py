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

    def column(c, rec, before, after, residual_label, model_label, recorded_label):
        """Residual against speed (top) and recorded against model (bottom), before and after."""
        sc = ax[0][c].scatter(n, [r - b for r, b in zip(rec, before)], c=tq, marker="o", label="before", cmap="viridis")
        ax[0][c].scatter(n, [r - b for r, b in zip(rec, after)], c=tq, marker="x", label="after", cmap="viridis")
        ax[0][c].axhline(0, color="grey", lw=0.8)
        ax[0][c].set_xlabel("input speed [rpm]")
        ax[0][c].set_ylabel(residual_label)
        ax[0][c].legend()
        lo, hi = min(rec + before + after), max(rec + before + after)
        ax[1][c].plot([lo, hi], [lo, hi], color="grey", lw=0.8)
        ax[1][c].scatter(before, rec, marker="o", label="before")
        ax[1][c].scatter(after, rec, marker="x", label="after")
        ax[1][c].set_xlabel(model_label)
        ax[1][c].set_ylabel(recorded_label)
        ax[1][c].legend()
        return sc

    sc = column(0, P, Pb, Pa, "loss residual, recorded - model [W]", "model loss [W]", "recorded loss [W]")
    fig.colorbar(sc, ax=ax[0][0], label="input torque [N m]")
    if has_T:
        column(1, f("oil_temp_C"), f("oil_temp_model_before_C"), f("oil_temp_model_after_C"),
               "oil temperature residual [K]", "model oil temperature [degC]", "recorded oil temperature [degC]")
    fig.suptitle(a.title)
    fig.tight_layout()
    fig.savefig(a.out, dpi=110)


if __name__ == "__main__":
    main()
