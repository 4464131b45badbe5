"""`gearloss compare` pictures: one row of panels per oil k against the reference oil A (the
first), with the differences oil k - A of power loss, oil temperature and efficiency.

One colour sense on every panel: red = oil k worse than A (more loss, hotter, lower
efficiency), blue = better, white = no difference, on a diverging scale symmetric about 0 and
shared by every row. The efficiency difference keeps the CSV's sign (positive: k more efficient),
so its colours run the other way (red for negative); every colour bar says which way is worse.

Columns: two oils are today's `dP_loss_W`, `dT_oil_K`, `d_efficiency`; three or more give
`dP_loss_<k>_W`, `dT_oil_<k>_K`, `d_efficiency_<k>` for every k but the first, whose name
comes from `P_total_<k>_W` (in file order, the reference first)."""
import numpy as np

from . import labels, scale, surface
from .data import PlotError

# (quantity, column for two oils, column pattern for N oils, factor, unit, worse when positive)
QUANTITIES = [
    ("power loss", "dP_loss_W", "dP_loss_{}_W", 1.0, "W", True),
    ("oil temperature", "dT_oil_K", "dT_oil_{}_K", 1.0, "K", True),
    ("efficiency", "d_efficiency", "d_efficiency_{}", 100.0, "points of %", False),
]
WORSE = {"power loss": "more loss", "oil temperature": "hotter", "efficiency": "less efficient"}
BETTER = {"power loss": "less loss", "oil temperature": "cooler", "efficiency": "more efficient"}


def oil_names(table):
    names = [c[len("P_total_"):-len("_W")] for c in table.columns if c.startswith("P_total_") and c.endswith("_W")]
    if len(names) < 2:
        raise PlotError(f"{table.path}: a compare CSV names each oil in a column P_total_<oil>_W; "
                        f"found {len(names)}")
    return names


def plot_compare(fig, table, meta, opts):
    if isinstance(opts.levels, list):
        raise PlotError("--levels: compare draws three quantities on their own scales; give a count "
                        "(e.g. --levels 10), not a list")
    oils = oil_names(table)
    ref, others = oils[0], oils[1:]
    two = len(oils) == 2

    def column(pattern_two, pattern_n, k):
        return pattern_two if two else pattern_n.format(k)

    quantities = [q for q in QUANTITIES if all(table.has(column(q[1], q[2], k)) for k in others)]
    if not quantities or quantities[0][0] != "power loss":
        table.require([column(QUANTITIES[0][1], QUANTITIES[0][2], k) for k in others], "compare")
    nrows, ncols = len(others), len(quantities)
    fig.set_size_inches(5.0 * ncols + 0.6, 4.0 * nrows + 2.2)
    ax = fig.subplots(nrows, ncols, squeeze=False, sharex=True, sharey=True)
    grid = surface.Grid(table.number("speed_in_rpm"), table.number("torque_in_Nm"))
    status_ref = table.text(f"status_{ref}").to_numpy() if table.has(f"status_{ref}") else None
    info = {"panels": [], "levels": {}, "mappables": {}}
    temps = table.number(f"oil_temp_{ref}_C") if table.has(f"oil_temp_{ref}_C") else None
    title = labels.figure_title(
        opts.title, f"{labels.case_text(meta, table.path)}: oils compared with {ref}",
        labels.join(f"differences oil - {ref}; red: worse than {ref}, blue: better",
                    labels.thermal_text(meta, temps), labels.ratio_text(meta)))
    labels.set_title(fig, title)
    info["title"] = title
    row_handles = []
    for c, (name, col2, coln, factor, unit, worse_positive) in enumerate(quantities):
        values = {k: table.number(column(col2, coln, k)) * factor for k in others}
        # one scale per quantity, shared by every oil's row
        levels = scale.make_levels(np.concatenate(list(values.values())), opts.levels, "diverging")
        if levels is None:
            raise PlotError(f"{table.path}: no point has a value of '{column(col2, coln, others[0])}' "
                            "(every point failed for one of the oils)")
        cmap = "RdBu_r" if worse_positive else "RdBu"  # red where oil k is worse
        mappable = None
        for r, k in enumerate(others):
            status = status_ref
            if table.has(f"status_{k}"):
                sk = table.text(f"status_{k}").to_numpy()
                status = sk if status is None else np.where([surface.failure_class(s) is not None for s in status], status, sk)
            if status is None:
                status = np.array(["ok"] * len(table))
            m, handles = surface.draw_field(ax[r][c], grid, values[k], status, levels, cmap)
            mappable = mappable or m
            head = f"{k} - {ref}: {name}"
            ax[r][c].set_title(head, fontsize=9)
            info["panels"].append(head)
            info["mappables"][head] = m
            if c == 0:
                row_handles.append(handles)
            if r != nrows - 1:
                ax[r][c].set_xlabel("")
            if c != 0:
                ax[r][c].set_ylabel("")
        who = others[0] if two else "oil"
        sign = "> 0" if worse_positive else "< 0"
        label = (f"{name} difference, {who} - {ref} [{unit}]\n"
                 f"red ({sign}): {WORSE[name]} (worse); blue: {BETTER[name]} (better)")
        surface.colour_bar(fig, mappable, list(ax[:, c]), levels, label, location="bottom")
        info["levels"][name] = levels
    surface.figure_legend(fig, row_handles, "points, over all rows" if nrows > 1 else None)
    return info
