"""`gearloss map` pictures: a field over speed x torque (efficiency, oil temperature, total
loss) or the loss breakdown; a sweep CSV (its leading columns name each variant's values) drawn
as one panel per variant on a shared colour scale, or refused beyond --max-panels."""
import math

import numpy as np

from . import labels, scale, surface
from .data import PlotError

FIELDS = {
    "efficiency": dict(column="efficiency", factor=100.0, label="efficiency [%]", cmap="viridis", focus="high",
                       name="efficiency"),
    "oil-temp": dict(column="oil_temp_C", factor=1.0, label="oil temperature [degC]", cmap="inferno",
                     focus="spread", name="oil temperature"),
    "loss": dict(column="P_total_W", factor=1.0, label="total power loss [W]", cmap="magma_r", focus="spread",
                 name="total power loss"),
}
KINDS = list(FIELDS) + ["breakdown"]
FIRST_POINT_COLUMN = "speed_in_rpm"


def sweep_axes(table):
    """The sweep's columns: those a map writes before its first point column."""
    cols = table.columns
    return cols[:cols.index(FIRST_POINT_COLUMN)] if FIRST_POINT_COLUMN in cols else []


def select_rows(table, axes, selections):
    """Keeps the rows whose sweep values match every --select AXIS=VALUE."""
    mask = np.ones(len(table), dtype=bool)
    for sel in selections:
        axis, eq, value = sel.partition("=")
        axis, value = axis.strip(), value.strip()
        if not eq or not axis:
            raise PlotError(f"--select {sel}: write AXIS=VALUE (e.g. --select oil=oils/75W90-A.yaml)")
        if axis not in axes:
            raise PlotError(f"--select {sel}: '{axis}' is not a sweep axis of {table.path}"
                            + (f" (its axes: {', '.join(axes)})" if axes else " (it has no sweep)"))
        cells = table.text(axis).to_numpy()
        known = list(dict.fromkeys(cells))
        if value not in known:
            raise PlotError(f"--select {sel}: no variant has {axis}={value} (values: {', '.join(known)})")
        mask &= cells == value
    return table.subset(mask)


def variants(table, axes):
    """[(label, Table)] per sweep variant in file order; one unlabelled entry without a sweep."""
    if not axes:
        return [("", table)]
    keys = [tuple(r) for r in table.frame[axes].itertuples(index=False, name=None)]
    order = list(dict.fromkeys(keys))
    out = []
    for k in order:
        mask = np.array([x == k for x in keys])
        out.append((", ".join(f"{a}={v}" for a, v in zip(axes, k)), table.subset(mask)))
    return out


def refuse_too_many(table, axes, groups, max_panels):
    counts = ", ".join(f"{a} ({len(set(table.text(a)))} values)" for a in axes)
    first = groups[0][1]
    example = " ".join(f"--select '{a}={first.text(a).iloc[0]}'" for a in axes)
    raise PlotError(f"{table.path} holds {len(groups)} sweep variants ({counts}), more than {max_panels} panels: "
                    f"draw some with --select AXIS=VALUE (e.g. {example}) or raise --max-panels")


def efficiency_levels(spec):
    """An explicit efficiency list may be written as fractions (0.97, as the CSV) or in percent."""
    if isinstance(spec, list) and max(abs(x) for x in spec) <= 1.0:
        return [100.0 * x for x in spec]
    return spec


def plot_map(fig, table, meta, opts):
    """Draws the map picture on `fig`; returns what --describe prints."""
    kind = opts.kind
    axes = sweep_axes(table)
    table = select_rows(table, axes, opts.select)
    groups = variants(table, [a for a in axes if a not in {s.partition("=")[0].strip() for s in opts.select}])
    if len(groups) > opts.max_panels:
        refuse_too_many(table, axes, groups, opts.max_panels)
    n = len(groups)
    ncols = min(n, 3 if n > 4 else 2 if n > 1 else 1)
    nrows = math.ceil(n / ncols)
    fig.set_size_inches(5.4 * ncols + (1.4 if kind != "breakdown" else 0.6), 4.3 * nrows + 1.3)
    ax = np.atleast_1d(fig.subplots(nrows, ncols, squeeze=False, sharex=True, sharey=True)).ravel()
    for extra in ax[n:]:
        extra.set_visible(False)
    oil_t = table.number("oil_temp_C")
    swept = set(axes)
    oil = "" if "oil" in swept else ", ".join(labels.oil_names(meta))
    thermal_swept = any(a.startswith("thermal") for a in swept)
    thermal = ""
    if not thermal_swept:  # the sidecar's mode, else what each variant's oil temperatures show
        per = {labels.thermal_text(meta, g.number("oil_temp_C")) for _, g in groups}
        thermal = per.pop() if len(per) == 1 else ""
    info = {"panels": []}
    what = FIELDS[kind]["name"] if kind in FIELDS else "loss breakdown"
    title = labels.figure_title(
        opts.title, f"{labels.case_text(meta, table.path)}: {what}",
        labels.join(f"oil {oil}" if oil else "", thermal, labels.ratio_text(meta),
                    ", ".join(opts.select), f"{n} sweep variants" if n > 1 else (groups[0][0] if axes else "")))
    labels.set_title(fig, title)
    info["title"] = title
    if kind == "breakdown":
        draw_breakdowns(fig, ax[:n], groups, thermal_swept)
        for a, (name, _) in zip(ax, groups):
            info["panels"].append(a.get_title())
        return info
    spec = FIELDS[kind]
    values = table.number(spec["column"]) * spec["factor"]
    lv_spec = efficiency_levels(opts.levels) if kind == "efficiency" else opts.levels
    ok_rows = np.array([surface.failure_class(s) is None for s in table.text("status")])
    levels = scale.make_levels(values[ok_rows], lv_spec, spec["focus"])
    if levels is None:
        raise PlotError(f"{table.path}: no point has a value of '{spec['column']}' "
                        "(every point failed: no equilibrium or out of range)")
    mappable = None
    all_handles = []
    for a, (name, g) in zip(ax, groups):
        grid = surface.Grid(g.number("speed_in_rpm"), g.number("torque_in_Nm"))
        z = g.number(spec["column"]) * spec["factor"]
        m, handles = surface.draw_field(a, grid, z, g.text("status").to_numpy(), levels, spec["cmap"])
        mappable = mappable or m
        head = name
        if thermal_swept or (not thermal and n > 1):
            t = labels.thermal_text(None, g.number("oil_temp_C"))
            head = labels.join(name, t)
        a.set_title(head, fontsize=9)
        all_handles.append(handles)
        info["panels"].append(head)
    surface.figure_legend(fig, all_handles, "points, over all panels" if n > 1 else None)
    for a in ax[:n]:  # shared axes hide inner tick labels: keep the axis names on the outer panels
        if not a.get_subplotspec().is_last_row():
            a.set_xlabel("")
        if not a.get_subplotspec().is_first_col():
            a.set_ylabel("")
    surface.colour_bar(fig, mappable, list(ax[:n]), levels, spec["label"])
    info["levels"] = levels
    return info


def mechanism_columns(columns, after, before):
    """The loss mechanisms' columns (P_<name>_W) between `after` (or the first P_ column) and
    `before`, in file order, so that a new mechanism is drawn without an edit here."""
    end = columns.index(before)
    start = columns.index(after) + 1 if after else next(i for i, k in enumerate(columns) if k.startswith("P_"))
    return [(k, k[2:-2].replace("_", " ")) for k in columns[start:end] if k.startswith("P_") and k.endswith("_W")]


def draw_breakdowns(fig, axes, groups, thermal_swept):
    import matplotlib.pyplot as plt

    colors = plt.rcParams["axes.prop_cycle"].by_key()["color"]
    columns = groups[0][1].columns
    parts = mechanism_columns(columns, "oil_temp_C", "P_total_W")
    # mechanisms that are zero everywhere are left out (listed in no legend)
    used = [(k, n) for k, n in parts if any(np.nan_to_num(g.number(k)).any() for _, g in groups)]
    for ax, (name, g) in zip(axes, groups):
        ok = np.array([surface.failure_class(s) is None for s in g.text("status")])
        speed, torque = g.number("speed_in_rpm")[ok], g.number("torque_in_Nm")[ok]
        speeds, torques = np.unique(speed), np.unique(torque)
        width = 0.8 / max(1, len(torques))
        for ti, t in enumerate(torques):
            rows = np.flatnonzero(torque == t)
            rows = rows[np.argsort(speed[rows])]
            x = np.searchsorted(speeds, speed[rows]) + (ti - (len(torques) - 1) / 2) * width
            bottom = np.zeros(len(rows))
            for pi, (k, label) in enumerate(used):
                v = np.nan_to_num(g.number(k)[ok][rows])
                ax.bar(x, v, width * 0.95, bottom=bottom, color=colors[pi % len(colors)],
                       label=label if ti == 0 else None, edgecolor="white", linewidth=0.3)
                bottom += v
        ax.set_xticks(range(len(speeds)))
        ax.set_xticklabels([labels.number_text(s) for s in speeds], rotation=90 if len(speeds) > 10 else 0)
        failed = int((~ok).sum())
        ax.set_xlabel("input speed [rpm]; bars: input torque " + ", ".join(labels.number_text(t) for t in torques)
                      + " N m" + (f"\n({failed} points without a result left out)" if failed else ""), fontsize=8)
        ax.set_ylabel("power loss [W]")
        head = name
        if thermal_swept:
            head = labels.join(name, labels.thermal_text(None, g.number("oil_temp_C")))
        ax.set_title(head, fontsize=9)
    axes[0].legend(fontsize=8)
