#!/usr/bin/env python3
"""Pictures of gearloss outputs (PNG or SVG, by the output file's extension).

  scripts/plot.py map MAP.csv OUT.png [--kind efficiency|oil-temp|breakdown]
      efficiency contour over speed x torque, oil temperature map, or the loss
      breakdown stacked over torque at each speed (`gearloss map` CSV)
  scripts/plot.py compare DIFF.csv OUT.png
      loss difference B - A and efficiency difference over speed x torque (`gearloss compare`)
  scripts/plot.py cycle TRACE.csv OUT.png
      vehicle speed and gear, temperatures, losses over time (`gearloss cycle -o`)
  scripts/plot.py diagnose RESIDUALS.csv OUT.png
      residuals before/after a diagnosis (`gearloss diagnose --residuals`)

Needs Debian's python3-matplotlib (scripts/plot.sh installs it and runs this script).
"""
import argparse
import csv
import math
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402


def read(path):
    with open(path, newline="") as f:
        rows = list(csv.DictReader(f))
    if not rows:
        sys.exit(f"plot.py: {path}: no rows")
    return rows


def col(rows, key):
    if key not in rows[0]:
        sys.exit(f"plot.py: column '{key}' missing (is this the right kind of file?)")
    return [float(r[key]) if r[key] not in ("", None) else math.nan for r in rows]


def grid(rows, zkey, xkey="speed_in_rpm", ykey="torque_in_Nm"):
    """Values of zkey on the speed x torque grid (NaN where missing)."""
    xs = sorted({float(r[xkey]) for r in rows})
    ys = sorted({float(r[ykey]) for r in rows})
    z = [[math.nan] * len(xs) for _ in ys]
    for r in rows:
        v = r.get(zkey, "")
        if v not in ("", None):
            z[ys.index(float(r[ykey]))][xs.index(float(r[xkey]))] = float(v)
    return xs, ys, z


def contour(ax, xs, ys, z, label, cmap="viridis"):
    if len(xs) > 1 and len(ys) > 1:
        norm = None
        flat = [v for r in z for v in r if not math.isnan(v)]
        if cmap == "coolwarm" and flat and min(flat) < 0 < max(flat):
            norm = matplotlib.colors.TwoSlopeNorm(0.0, min(flat), max(flat))  # white at zero
        cs = ax.contourf(xs, ys, z, levels=14, cmap=cmap, norm=norm)
        lines = ax.contour(xs, ys, z, levels=7, colors="k", linewidths=0.5)
        ax.clabel(lines, fmt="%.4g", fontsize=7)
    else:
        cs = ax.scatter([x for x in xs for _ in ys], [y for _ in xs for y in ys],
                        c=[z[j][i] for i in range(len(xs)) for j in range(len(ys))], cmap=cmap)
    plt.colorbar(cs, ax=ax, label=label)
    ax.set_xlabel("input speed [rpm]")
    ax.set_ylabel("input torque [N m]")


def mechanism_columns(header, after, before):
    """The loss mechanisms' columns (P_<name>_W) of a map or cycle CSV, in file order: the
    columns the tool writes between `after` (or the first P_ column) and `before`, so a new
    mechanism is drawn without an edit here."""
    keys = list(header)
    end = keys.index(before)
    start = keys.index(after) + 1 if after else next(i for i, k in enumerate(keys) if k.startswith("P_"))
    return [(k, k[2:-2].replace("_", " ")) for k in keys[start:end] if k.startswith("P_") and k.endswith("_W")]


def plot_map(rows, ax, kind, title):
    if kind == "efficiency":
        xs, ys, z = grid(rows, "efficiency")
        contour(ax, xs, ys, [[100 * v for v in r] for r in z], "efficiency [%]")
        ax.set_title(title or "gearbox efficiency")
    elif kind == "oil-temp":
        xs, ys, z = grid(rows, "oil_temp_C")
        contour(ax, xs, ys, z, "oil temperature [degC]", cmap="inferno")
        ax.set_title(title or "stabilised oil temperature")
    else:
        parts = [(k, n) for k, n in mechanism_columns(rows[0], "oil_temp_C", "P_total_W")
                 if any(r[k] not in ("", "0") for r in rows)]
        speeds = sorted({float(r["speed_in_rpm"]) for r in rows})
        torques = sorted({float(r["torque_in_Nm"]) for r in rows})
        width = 0.8 / max(1, len(torques))
        colors = plt.rcParams["axes.prop_cycle"].by_key()["color"]
        for ti, t in enumerate(torques):
            sub = sorted((r for r in rows if float(r["torque_in_Nm"]) == t), key=lambda r: float(r["speed_in_rpm"]))
            x = [speeds.index(float(r["speed_in_rpm"])) + (ti - (len(torques) - 1) / 2) * width for r in sub]
            bottom = [0.0] * len(sub)
            for pi, (k, name) in enumerate(parts):
                v = [float(r[k]) if r[k] else 0.0 for r in sub]
                ax.bar(x, v, width * 0.95, bottom=bottom, color=colors[pi % len(colors)],
                       label=name if ti == 0 else None, edgecolor="white", linewidth=0.3)
                bottom = [b + w for b, w in zip(bottom, v)]
        ax.set_xticks(range(len(speeds)))
        ax.set_xticklabels([f"{s:g}" for s in speeds])
        ax.set_xlabel("input speed [rpm] (bars: input torque " + ", ".join(f"{t:g}" for t in torques) + " N m)")
        ax.set_ylabel("power loss [W]")
        ax.legend()
        ax.set_title(title or "loss breakdown")


def plot_compare(rows, fig, title):
    ax = fig.subplots(1, 2)
    a = [k for k in rows[0] if k.startswith("P_total_")]
    xs, ys, z = grid(rows, "dP_loss_W")
    contour(ax[0], xs, ys, z, "loss difference B - A [W]", cmap="coolwarm")
    ax[0].set_title(f"{a[1][8:-2]} - {a[0][8:-2]}: power loss" if len(a) == 2 else "power loss difference")
    xs, ys, z = grid(rows, "d_efficiency")
    contour(ax[1], xs, ys, [[100 * v for v in r] for r in z], "efficiency difference B - A [points of %]", cmap="coolwarm")
    ax[1].set_title("efficiency difference")
    fig.suptitle(title or "lubricant comparison")


def plot_cycle(rows, fig, title):
    ax = fig.subplots(3, 1, sharex=True)
    t = col(rows, "time_s")
    ax[0].plot(t, col(rows, "speed_kmh"), color="k", lw=0.8)
    ax[0].set_ylabel("vehicle speed [km/h]")
    g = ax[0].twinx()
    g.step(t, col(rows, "gear"), where="post", color="tab:orange", lw=0.7)
    g.set_ylabel("gear", color="tab:orange")
    for key, name in [("oil_temp_C", "oil"), ("housing_temp_C", "housing"), ("clutch_temp_C", "clutch packs")]:
        if key in rows[0]:
            ax[1].plot(t, col(rows, key), label=name)
    ax[1].set_ylabel("temperature [degC]")
    ax[1].legend()
    parts = mechanism_columns(rows[0], None, "P_gearbox_W")
    if "P_converter_W" in rows[0]:
        parts.append(("P_converter_W", "converter"))
    ax[2].stackplot(t, *[col(rows, k) for k, _ in parts], labels=[n for _, n in parts], linewidth=0)
    ax[2].set_ylabel("power loss [W]")
    ax[2].set_xlabel("time [s]")
    ax[2].legend(loc="upper left", fontsize=8, ncol=3)
    fig.suptitle(title or "drive cycle")


def plot_diagnose(rows, fig, title):
    f = lambda k: col(rows, k)
    n, tq = f("speed_in_rpm"), f("torque_in_Nm")
    P, Pb, Pa = f("P_loss_W"), f("P_model_before_W"), f("P_model_after_W")
    has_T = any(r.get("oil_temp_C") for r in rows)
    ncol = 2 if has_T else 1
    ax = fig.subplots(2, ncol, squeeze=False)

    def column(c, rec, before, after, residual_label, model_label, recorded_label):
        sc = ax[0][c].scatter(n, [r - b for r, b in zip(rec, before)], c=tq, marker="o", label="before", cmap="viridis")
        ax[0][c].scatter(n, [r - b for r, b in zip(rec, after)], c=tq, marker="x", label="after", cmap="viridis")
        ax[0][c].axhline(0, color="grey", lw=0.8)
        ax[0][c].set_xlabel("input speed [rpm]")
        ax[0][c].set_ylabel(residual_label)
        ax[0][c].legend()
        vals = [v for v in rec + before + after if not math.isnan(v)]
        ax[1][c].plot([min(vals), max(vals)], [min(vals), max(vals)], color="grey", lw=0.8)
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
    fig.suptitle(title or "gearloss diagnose: residuals before and after")


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("what", choices=["map", "compare", "cycle", "diagnose"])
    ap.add_argument("csv")
    ap.add_argument("out", help="output picture (.png or .svg)")
    ap.add_argument("--kind", choices=["efficiency", "oil-temp", "breakdown"], default="efficiency",
                    help="for `map`: which picture")
    ap.add_argument("--title", default="")
    a = ap.parse_args()
    rows = read(a.csv)
    if a.what == "map":
        rows = [r for r in rows if r.get("status", "ok") == "ok"]
        fig, ax = plt.subplots(figsize=(8, 5.5))
        plot_map(rows, ax, a.kind, a.title)
    elif a.what == "compare":
        fig = plt.figure(figsize=(13, 5))
        plot_compare(rows, fig, a.title)
    elif a.what == "cycle":
        fig = plt.figure(figsize=(11, 8))
        plot_cycle(rows, fig, a.title)
    else:
        has_T = any(r.get("oil_temp_C") for r in rows)
        fig = plt.figure(figsize=(12 if has_T else 6, 8))
        plot_diagnose(rows, fig, a.title)
    fig.tight_layout()
    fig.savefig(a.out, dpi=110)


if __name__ == "__main__":
    main()
