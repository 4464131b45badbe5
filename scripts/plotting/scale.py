"""Colour levels and colour-bar numbers.

Automatic levels come from robust quantiles of the solved points, not from min..max: on an
efficiency map the low-torque band (efficiency falling towards 0 as the load vanishes) would
otherwise take most of the colours, and the region of interest (the upper percent) one or two.
Values beyond the levels are drawn in the end colours (the colour bar's arrows say so).
Colour-bar numbers are plain decimals with as many digits as the levels need (no offset, no
exponent: a constant 80 degC field printed as 1e-11+8e1 is what this avoids)."""
import re
from dataclasses import dataclass, field as dc_field

import numpy as np
from matplotlib.ticker import FuncFormatter, MaxNLocator

from .data import PlotError

DEFAULT_COUNT = 12


def parse_levels(text):
    """--levels: a count ('12', 2..100) or an explicit increasing list ('0.9,0.95,0.97')."""
    t = text.strip()
    if re.fullmatch(r"[0-9]+", t):
        n = int(t)
        if not 2 <= n <= 100:
            raise PlotError(f"--levels {t}: a count of levels must be 2..100")
        return n
    values = []
    for part in t.split(","):
        try:
            x = float(part)
        except ValueError:
            raise PlotError(f"--levels {t}: '{part.strip()}' is not a number (give a count such as 12 "
                            "or a list such as 0.9,0.95,0.97,0.98,0.99)")
        if not np.isfinite(x):
            raise PlotError(f"--levels {t}: '{part.strip()}' is not a finite number")
        values.append(x)
    values = sorted(set(values))
    if len(values) < 2:
        raise PlotError(f"--levels {t}: an explicit list needs at least two different values")
    return values


def decimals_for(values, most=6):
    """Fewest decimals that write every value exactly (to 1e-9 of the largest)."""
    v = np.asarray(values, dtype=float)
    scale = max(1e-300, float(np.abs(v).max())) if v.size else 1.0
    for d in range(most + 1):
        if np.all(np.abs(np.round(v, d) - v) <= 1e-9 * scale):
            return d
    return most


def plain_formatter(decimals):
    def text(x, pos=None):
        s = f"{x:.{decimals}f}"
        return s[1:] if s.startswith("-") and float(s) == 0 else s  # no "-0.0"
    return FuncFormatter(text)


@dataclass
class Levels:
    levels: np.ndarray = dc_field(default_factory=lambda: np.array([]))
    extend: str = "neither"       # contourf's extend: values below / above the levels
    decimals: int = 0
    constant: float = None        # the single value of a constant field (then levels are a band around it)
    how: str = ""                 # how they were chosen (printed by --describe)

    def formatter(self):
        return plain_formatter(self.decimals)

    def describe(self):
        if self.constant is not None:
            return f"constant {self.constant:.{self.decimals}f}"
        return ",".join(f"{x:.{self.decimals}f}" for x in self.levels) + f" ({self.how}; extend {self.extend})"


def quantile_levels(v, n):
    """Levels at equally spaced quantiles of the solved points from the 10 % quantile to the best
    point, rounded to the fewest decimals that keep them apart: each band holds about as many
    points, so the levels crowd where the points do (on an efficiency map, the upper percent)
    and the low-load tail below the first level takes the end colour."""
    q = np.quantile(v, np.linspace(0.10, 1.0, n))
    for d in range(7):
        levels = np.unique(np.round(q, d))
        if len(levels) >= max(2, int(0.8 * len(np.unique(q)))):
            break
    top = np.ceil(v.max() * 10 ** d) / 10 ** d  # the best point inside the last band
    levels = np.unique(np.append(levels[levels < top], top))
    if len(levels) < 2:
        levels = np.array([levels[0] - 10.0 ** -d, levels[0]])
    below = v.min() < levels[0]
    return Levels(levels, "min" if below else "neither", decimals_for(levels), None,
                  f"quantiles 10 %..100 % of the solved points, {n} asked")


def make_levels(values, spec=None, focus="spread"):
    """Levels for the finite `values` (already in the unit drawn). spec: None (automatic), a
    count or an explicit list (--levels). focus: 'high' (efficiency: levels at the quantiles of the
    points from the 10 % quantile to the best point), 'spread' (2 % .. 98 % quantiles) or 'diverging' (symmetric about 0 up to
    the 98 % quantile of |value|)."""
    v = np.asarray(values, dtype=float)
    v = v[np.isfinite(v)]
    if v.size == 0:
        return None
    lo_v, hi_v = float(v.min()), float(v.max())
    if isinstance(spec, list):
        levels = np.asarray(spec, dtype=float)
        how = "--levels list"
    else:
        n = spec or DEFAULT_COUNT
        if hi_v - lo_v <= 1e-9 * max(1.0, abs(hi_v)):
            d = decimals_for([hi_v], 4)
            half = 0.5 * 10.0 ** -d
            return Levels(np.array([hi_v - half, hi_v + half]), "neither", d, hi_v, "constant field")
        if focus == "high":
            return quantile_levels(v, n)
        elif focus == "diverging":
            m = float(np.quantile(np.abs(v), 0.98)) or float(np.abs(v).max())
            lo, hi, how = -m, m, "symmetric about 0, 98 % quantile of |value|"
        else:
            lo, hi, how = float(np.quantile(v, 0.02)), float(np.quantile(v, 0.98)), "2 % .. 98 % quantiles"
        if hi <= lo:  # almost every point alike: the full range
            lo, hi = lo_v, hi_v
        loc = MaxNLocator(nbins=max(1, n - 1), steps=[1, 2, 2.5, 5, 10], symmetric=(focus == "diverging"))
        levels = loc.tick_values(lo, hi)
        # the locator rounds outwards: keep at most one level beyond the data at each end
        # (a diverging scale stays symmetric, so that white is 0 and equal colours equal sizes)
        while focus != "diverging" and len(levels) > 3 and levels[1] <= lo_v:
            levels = levels[1:]
        while focus != "diverging" and len(levels) > 3 and levels[-2] >= hi_v:
            levels = levels[:-1]
        if not isinstance(spec, int):
            how += f", {DEFAULT_COUNT} levels asked"
        else:
            how += f", --levels {spec}"
    below, above = lo_v < levels[0], hi_v > levels[-1]
    extend = "both" if below and above else "min" if below else "max" if above else "neither"
    return Levels(levels, extend, decimals_for(levels), None, how)
