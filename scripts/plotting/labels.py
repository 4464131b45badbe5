"""Titles from the metadata sidecar (CSV.meta.json, written by gearloss next to each CSV): case,
oil, thermal mode, ratio. Without a sidecar only what the CSV itself shows is said: the file's
name for the case, and the thermal mode only when the oil-temperature column proves it (one
value over every solved point: fixed; different values: each point's own, stabilised)."""
import os
import textwrap

import numpy as np

from .data import field

SEP = " \u00b7 "  # middle dot between the parts of a title line


def number_text(x):
    """A number as people write it: 80, 80.5, 0.975 (never 8e1 or an offset)."""
    if x is None or not np.isfinite(x):
        return "?"
    r = round(float(x), 6)
    return f"{r:.6f}".rstrip("0").rstrip(".") if r != int(r) else f"{int(r)}"


def case_text(meta, csv_path):
    for key in ("title", "name"):
        v = field(meta, "case", key)
        if isinstance(v, str) and v.strip():
            return v.strip()
    v = field(meta, "case", "file")
    if isinstance(v, str) and v:
        return os.path.basename(v)
    return os.path.basename(csv_path)


def oil_names(meta):
    """The oil name(s) of the sidecar: one for map/cycle/diagnose, a list for compare."""
    oils = field(meta, "oils")
    if isinstance(oils, list):
        return [str(field(o, "name") or field(o, "file") or "?") for o in oils]
    name = field(meta, "oil", "name") or field(meta, "oil", "file")
    return [str(name)] if name else []


def ratio_text(meta):
    name = field(meta, "ratio", "name")
    if isinstance(name, str) and name:
        return f"ratio {name}"
    value = field(meta, "ratio", "value")
    if isinstance(value, (int, float)) and not isinstance(value, bool):
        return f"ratio {number_text(value)}"
    return ""


def thermal_from_values(oil_temp_C):
    """('fixed', T) when every finite value is the same (two or more of them), ('stabilised', None)
    when they differ, (None, None) when the column cannot tell."""
    v = np.asarray(oil_temp_C, dtype=float)
    v = v[np.isfinite(v)]
    if len(v) < 2:
        return None, None
    if np.ptp(v) <= 1e-9 * max(1.0, abs(v).max()):
        return "fixed", float(v[0])
    return "stabilised", None


def thermal_text(meta, oil_temp_C=None):
    """'oil fixed at 80 degC', 'stabilised oil temperature' or '' (not known)."""
    mode = field(meta, "thermal", "mode")
    T = field(meta, "thermal", "oil_temperature_C")
    csv_mode, csv_T = thermal_from_values(oil_temp_C) if oil_temp_C is not None else (None, None)
    if mode not in ("fixed", "stabilised"):
        mode, T = csv_mode, csv_T
    if mode == "fixed":
        if not isinstance(T, (int, float)) or isinstance(T, bool):
            T = csv_T
        return f"oil fixed at {number_text(T)} degC" if T is not None else "oil temperature fixed"
    if mode == "stabilised":
        return "stabilised oil temperature"
    return ""


def command_option(meta, option):
    """The value given to `option` on the sidecar's recorded command line (None when absent)."""
    line = field(meta, "command_line")
    if not isinstance(line, list):
        return None
    for i, arg in enumerate(line):
        arg = str(arg)
        if arg == option and i + 1 < len(line):
            return str(line[i + 1])
        if arg.startswith(option + "="):
            return arg[len(option) + 1:]
    return None


def join(*parts):
    return SEP.join(p for p in parts if p)


def figure_title(user_title, head, details):
    """The user's --title, or 'head' over a line of details."""
    if user_title:
        return user_title
    return head + ("\n" + details if details else "")


def set_title(fig, title, fontsize=11):
    """The figure's title, each line wrapped at the figure's width: a long case name, oil and
    ratio list would otherwise run past both edges and be cut off in the saved picture. About
    72 / (0.55 x font size) characters fit per inch of width (a character is ~0.55 em wide)."""
    width = max(20, int(fig.get_figwidth() * 72 / (0.55 * fontsize)))
    lines = []
    for line in title.split("\n"):
        lines += textwrap.wrap(line, width, break_long_words=True, break_on_hyphens=False) or [""]
    fig.suptitle("\n".join(lines), fontsize=fontsize)
