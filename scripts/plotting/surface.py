"""A field over input speed x input torque (map and compare pictures).

Contours are drawn on the computed points only: the grid's own cells are split into triangles
(a cell with a failed corner keeps the triangle of its three solved corners, or nothing), so a
hole in the grid (no equilibrium) stays a hole and nothing is drawn beyond the solved points.
On a coarse grid the triangles are refined with a smooth (cubic) interpolation inside each
triangle (matplotlib's UniformTriRefiner), clipped to the computed range, so contours are no
longer polygons with corners at the grid lines; each computed point is marked by a small dot.
Points without a result (no equilibrium, out of the model's range) are drawn as hatched cells
with a legend entry, points above the oil's permissible temperature with an open triangle."""
import warnings

import matplotlib
import numpy as np
from matplotlib import colors as mcolors
from matplotlib import tri as mtri
from matplotlib.collections import PatchCollection
from matplotlib.lines import Line2D
from matplotlib.patches import Patch, Rectangle

FAILED_STYLE = {
    "no_equilibrium": dict(facecolor="0.85", edgecolor="0.45", hatch="////",
                           label="no equilibrium: losses exceed the heat rejection"),
    "out_of_range": dict(facecolor="0.93", edgecolor="0.55", hatch="\\\\\\\\",
                         label="out of the model's range (no result)"),
    "other": dict(facecolor="0.9", edgecolor="0.5", hatch="xx", label="no result"),
}


def failure_class(status):
    """'no_equilibrium', 'out_of_range', 'other' for a status without numbers; None when the point
    has a result (ok, above_oil_limit) or no status was written."""
    s = str(status).strip()
    if s in ("", "ok", "above_oil_limit"):
        return None
    if s.startswith("no_equilibrium"):
        return "no_equilibrium"
    if s.startswith("out_of_range"):
        return "out_of_range"
    return "other"


def cell_edges(values):
    v = np.asarray(values, dtype=float)
    if v.size == 1:
        half = 0.05 * abs(v[0]) or 0.5
        return np.array([v[0] - half, v[0] + half])
    mid = 0.5 * (v[:-1] + v[1:])
    return np.concatenate([[v[0] - (mid[0] - v[0])], mid, [v[-1] + (v[-1] - mid[-1])]])


class Grid:
    """The speed x torque points of a file (every row, solved or not): whether they form a full
    grid, and each row's place in it."""

    def __init__(self, x, y):
        self.x, self.y = np.asarray(x, float), np.asarray(y, float)
        self.xs, self.ix = np.unique(self.x, return_inverse=True)
        self.ys, self.iy = np.unique(self.y, return_inverse=True)
        cells = set(zip(self.ix.tolist(), self.iy.tolist()))
        self.full = len(cells) == len(self.x) == len(self.xs) * len(self.ys)
        self.xe, self.ye = cell_edges(self.xs), cell_edges(self.ys)

    def triangles(self, ok):
        """Triangles (row indices) of the grid cells whose corners are solved (`ok`)."""
        at = -np.ones((len(self.xs), len(self.ys)), dtype=int)
        at[self.ix[ok], self.iy[ok]] = np.flatnonzero(ok)
        out = []
        for i in range(len(self.xs) - 1):
            for j in range(len(self.ys) - 1):
                a, b, c, d = at[i, j], at[i + 1, j], at[i + 1, j + 1], at[i, j + 1]
                corners = [k for k in (a, b, c, d) if k >= 0]
                if len(corners) == 4:
                    out += [(a, b, c), (a, c, d)]
                elif len(corners) == 3:
                    out.append(tuple(corners))
        return np.array(out, dtype=int).reshape(-1, 3)


def _triangulation(grid, ok):
    """Triangulation of the solved points in coordinates scaled to the unit square (so that the
    cubic interpolation sees speed and torque alike), or None when they span no area."""
    sx = max(np.ptp(grid.x), 1e-12)
    sy = max(np.ptp(grid.y), 1e-12)
    u, v = (grid.x - grid.x.min()) / sx, (grid.y - grid.y.min()) / sy
    if grid.full:
        tris = grid.triangles(ok)
        if len(tris) == 0:
            return None, None
        # the triangulation needs only the points its triangles use; renumber them
        used = np.unique(tris)
        remap = -np.ones(len(grid.x), dtype=int)
        remap[used] = np.arange(len(used))
        t = mtri.Triangulation(u[used], v[used], remap[tris])
        return t, used
    idx = np.flatnonzero(ok)
    if len(idx) < 3:
        return None, None
    try:
        t = mtri.Triangulation(u[idx], v[idx])
    except (ValueError, RuntimeError):  # collinear points
        return None, None
    return t, idx


def draw_field(ax, grid, z, status, levels, cmap, refine=3, lines=True):
    """Filled contours of z (one value per row of grid; NaN where there is none) with `levels`
    (scale.Levels), the computed points, the failed cells and the points above the oil's limit.
    Returns the mappable for a colour bar, and the legend handles."""
    z = np.asarray(z, float)
    ok = np.isfinite(z)
    cmap = matplotlib.colormaps[cmap] if isinstance(cmap, str) else cmap
    norm = mcolors.BoundaryNorm(levels.levels, cmap.N, extend=levels.extend)
    handles = []
    mappable = None
    t, used = _triangulation(grid, ok)
    sx, sy = max(np.ptp(grid.x), 1e-12), max(np.ptp(grid.y), 1e-12)
    if t is not None:
        zt = z[used]
        if refine and levels.constant is None and len(used) >= 4:
            try:
                interp = mtri.CubicTriInterpolator(t, zt, kind="geom")
                t_fine, z_fine = mtri.UniformTriRefiner(t).refine_field(zt, interp, subdiv=refine)
                z_fine = np.clip(z_fine, zt.min(), zt.max())  # no extremes the points do not have
                t, zt = t_fine, z_fine
            except (ValueError, RuntimeError, np.linalg.LinAlgError):
                pass  # a degenerate triangulation: linear contours on the points
        tr = mtri.Triangulation(t.x * sx + grid.x.min(), t.y * sy + grid.y.min(), t.triangles)
        mappable = ax.tricontourf(tr, zt, levels=levels.levels, cmap=cmap, extend=levels.extend)
        if lines and levels.constant is None and len(levels.levels) > 2:
            step = max(1, len(levels.levels) // 6)
            with warnings.catch_warnings():  # a panel whose values miss every labelled level
                warnings.simplefilter("ignore", UserWarning)
                cl = ax.tricontour(tr, zt, levels=levels.levels[::step], colors="k", linewidths=0.45)
                ax.clabel(cl, fmt=levels.formatter(), fontsize=7)
    pts = ax.scatter(grid.x[ok], grid.y[ok], s=6 if t is not None else 40, c=z[ok] if t is None else "k",
                     cmap=cmap if t is None else None, norm=norm if t is None else None,
                     edgecolors="none" if t is not None else "k", linewidths=0.4, zorder=3)
    if mappable is None:
        mappable = pts
    handles.append(Line2D([], [], ls="", marker="o", ms=3, color="k", label="computed point"))
    # Failed points: hatched cells (on a grid) or crosses.
    classes = np.array([failure_class(s) for s in status], dtype=object)
    for cls, style in FAILED_STYLE.items():
        sel = classes == cls
        if not sel.any():
            continue
        label = f"{style['label']} ({int(sel.sum())})"
        if grid.full:
            rects = [Rectangle((grid.xe[i], grid.ye[j]), grid.xe[i + 1] - grid.xe[i], grid.ye[j + 1] - grid.ye[j])
                     for i, j in zip(grid.ix[sel], grid.iy[sel])]
            ax.add_collection(PatchCollection(rects, facecolor=style["facecolor"], edgecolor=style["edgecolor"],
                                              hatch=style["hatch"], linewidth=0.3, zorder=2))
        else:
            ax.scatter(grid.x[sel], grid.y[sel], marker="x", color=style["edgecolor"], zorder=3)
        handles.append(Patch(facecolor=style["facecolor"], edgecolor=style["edgecolor"], hatch=style["hatch"],
                             label=label))
    above = np.array([str(s).strip() == "above_oil_limit" for s in status])
    if above.any():
        ax.scatter(grid.x[above], grid.y[above], marker="^", s=16, facecolors="none", edgecolors="tab:red",
                   linewidths=0.6, zorder=4)
        handles.append(Line2D([], [], ls="", marker="^", mfc="none", mec="tab:red",
                              label=f"above the oil's permissible temperature ({int(above.sum())})"))
    # the computed range; with failed cells, their whole cells (which reach half a step beyond)
    failed = classes != None  # noqa: E711 (element-wise)
    pad = failed.any() or len(grid.xs) == 1 or len(grid.ys) == 1
    def limits(values, edges):
        if pad:
            return edges[0], edges[-1]
        margin = 0.03 * (values[-1] - values[0])
        return values[0] - margin, values[-1] + margin

    ax.set_xlim(*limits(grid.xs, grid.xe))
    ax.set_ylim(*limits(grid.ys, grid.ye))
    ax.set_xlabel("input speed [rpm]")
    ax.set_ylabel("input torque [N m]")
    return mappable, handles


def colour_bar(fig, mappable, axes, levels, label, location="right"):
    """A colour bar with plain numbers; a constant field shows its one value and says so."""
    if levels.constant is not None:
        value = levels.formatter()(levels.constant)
        cb = fig.colorbar(mappable, ax=axes, ticks=[levels.constant], format=levels.formatter(), location=location)
        cb.set_label(f"{label}\n(the same {value} at every point)")
        return cb
    step = max(1, int(np.ceil(len(levels.levels) / 12)))
    cb = fig.colorbar(mappable, ax=axes, ticks=levels.levels[::step], format=levels.formatter(), location=location)
    cb.set_label(label)
    return cb


def figure_legend(fig, handle_lists, title=None):
    """One legend for all panels, in a strip kept free at the bottom of the figure: each entry
    once, its count (the number in brackets) summed over the panels."""
    import re

    entries = {}
    for handles in handle_lists:
        for h in handles:
            m = re.fullmatch(r"(.*) \((\d+)\)", h.get_label())
            base, n = (m.group(1), int(m.group(2))) if m else (h.get_label(), None)
            if base not in entries:
                entries[base] = [h, n]
            elif n is not None:
                entries[base][1] += n
    out = []
    for base, (h, n) in entries.items():
        h.set_label(base if n is None else f"{base} ({n})")
        out.append(h)
    ncol = min(len(out), 3, max(1, int(fig.get_size_inches()[0] // 4)))
    rows = -(-len(out) // ncol) + (1 if title else 0)
    strip = (0.1 + 0.2 * rows) / fig.get_size_inches()[1]
    fig.get_layout_engine().set(rect=(0, strip, 1, 1 - strip))
    return fig.legend(handles=out, loc="lower center", ncol=ncol, fontsize=7.5, frameon=False, title=title,
                      title_fontsize=7.5)
