"""`gearloss cycle -o` pictures: the run from the start temperature, the warm-start reference
run and the pre-warmed run (`warm_...`, `prewarmed_...` columns) overlaid: vehicle speed and
gear, oil temperature, transmission loss and its running total over the cycle."""
import numpy as np

from . import labels
from .data import PlotError
from .maps import mechanism_columns

# (column prefix, colour, line style)
RUNS = [("", "tab:blue", "-"), ("warm_", "tab:red", "-"), ("prewarmed_", "tab:green", "--")]


def run_label(prefix, t0):
    t0 = labels.number_text(t0)
    return {"": f"from {t0} degC (start)", "warm_": f"warm start at {t0} degC",
            "prewarmed_": f"pre-warmed, {t0} degC at the start"}[prefix]


def plot_cycle(fig, table, meta, opts, warn):
    if opts.levels is not None:
        raise PlotError("--levels applies to the map and compare pictures, not to cycle")
    fig.set_size_inches(11, 10.5)
    ax = fig.subplots(4, 1, sharex=True)
    t = table.number("time_s")
    dt = np.diff(t, append=t[-1])  # each row's rates hold until the next row
    runs = [r for r in RUNS if table.has(r[0] + "oil_temp_C") and table.has(r[0] + "P_gearbox_W")]
    if len(runs) == 1:
        warn(f"{table.path} holds only the run from the start temperature (no warm_... columns: written by a "
             "gearloss before the warm and pre-warmed runs were added to `cycle -o`); drawing that run alone")
    ax[0].plot(t, table.number("speed_kmh"), color="k", lw=0.8)
    ax[0].set_ylabel("vehicle speed [km/h]")
    g = ax[0].twinx()
    g.step(t, table.number("gear"), where="post", color="tab:orange", lw=0.7)
    g.set_ylabel("gear", color="tab:orange")
    names, losses = [], []
    for prefix, colour, style in runs:
        oil = table.number(prefix + "oil_temp_C")
        name = run_label(prefix, oil[0])
        names.append(name)
        ax[1].plot(t, oil, color=colour, ls=style, lw=1.2, label=f"oil, {name}")
        loss = np.nan_to_num(table.number(prefix + "P_gearbox_W"))
        conv = prefix + "P_converter_W"
        if table.has(conv):
            loss = loss + np.nan_to_num(table.number(conv))
        ax[2].plot(t, loss, color=colour, ls=style, lw=0.6, label=name)
        losses.append(loss)
        energy = np.cumsum(loss * dt) / 1e3
        ax[3].plot(t, energy, color=colour, ls=style, lw=1.4, label=f"{name}: {energy[-1]:.0f} kJ")
    for key, name in [("housing_temp_C", "housing"), ("clutch_temp_C", "clutch packs")]:
        if table.has(key):
            ax[1].plot(t, table.number(key), color="tab:blue", lw=0.7, ls=":" if key == "housing_temp_C" else "-.",
                       label=f"{name}, {names[0]}")
    ax[1].set_ylabel("temperature [degC]")
    ax[1].legend(fontsize=7, ncol=2)
    # the start run's mechanisms stacked under the lines: what a cold start loses, and where
    parts = mechanism_columns(table.columns, None, "P_gearbox_W")
    if table.has("P_converter_W"):
        parts.append(("P_converter_W", "converter"))
    parts = [(k, n) for k, n in parts if np.nan_to_num(table.number(k)).any()]
    if parts:
        ax[2].stackplot(t, *[np.nan_to_num(table.number(k)) for k, _ in parts], labels=[f"{n} (start)" for _, n in parts],
                        linewidth=0, alpha=0.35)
    converter = " + converter" if table.has("P_converter_W") else ""
    # a short peak (the converter stalled at the first start from cold) would flatten the rest:
    # the scale ends a little above the 99th percentile and the label gives the peak
    every = np.concatenate(losses)
    top, peak = float(np.quantile(every, 0.99)) * 1.2, float(every.max())
    clipped = ""
    if peak > 1.5 * top > 0:
        ax[2].set_ylim(0, top)
        clipped = f"\n(peak {peak / 1e3:.1f} kW off scale)"
    ax[2].set_ylabel(f"transmission loss [W]{clipped}")
    ax[2].legend(loc="upper left", fontsize=7, ncol=3, title=f"gearbox{converter} loss of each run; the start run's parts",
                 title_fontsize=7)
    ax[3].set_ylabel("transmission loss\nsince the start [kJ]")
    ax[3].set_xlabel("time [s]")
    ax[3].legend(loc="upper left", fontsize=8, title="running total of the trace's rates", title_fontsize=7)
    cycle = labels.command_option(meta, "--cycle")
    oil = ", ".join(labels.oil_names(meta))
    title = labels.figure_title(
        opts.title, f"{labels.case_text(meta, table.path)}: drive cycle" + (f" {cycle}" if cycle else ""),
        labels.join(f"oil {oil}" if oil else "", "; ".join(names)))
    labels.set_title(fig, title)
    return {"title": title, "panels": names}

