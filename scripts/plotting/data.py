"""Reading gearloss CSV files and their metadata sidecars; every problem a PlotError with a
message naming the file (and line and column for a bad cell)."""
import csv
import json
import os
import warnings

import numpy as np
import pandas as pd


class PlotError(Exception):
    """A problem of the input or the options: printed as one line, exit code 2."""


# Columns each kind of file must have (what `gearloss` writes), and the command that writes it.
REQUIRED = {
    "map": (["speed_in_rpm", "torque_in_Nm", "oil_temp_C", "P_total_W", "efficiency", "status"], "gearloss map"),
    "compare": (["speed_in_rpm", "torque_in_Nm"], "gearloss compare"),
    "cycle": (["time_s", "speed_kmh", "gear", "oil_temp_C", "P_gearbox_W"], "gearloss cycle -o"),
    "diagnose": (["speed_in_rpm", "torque_in_Nm", "P_loss_W", "P_model_before_W", "P_model_after_W"],
                 "gearloss diagnose --residuals"),
}


def guess_kind(columns):
    """The kind of gearloss file these columns look like (None when none)."""
    cols = set(columns)
    if any(c.startswith("dP_loss") for c in cols):
        return "compare"
    for kind in ("cycle", "diagnose", "map"):
        if set(REQUIRED[kind][0]) <= cols:
            return kind
    return None


class Table:
    """A gearloss CSV: its cells as text (pandas DataFrame of str), the file's path and the
    line of its header, so that a bad cell is reported as file:line: column."""

    def __init__(self, path, frame, header_line):
        self.path = path
        self.frame = frame
        self.header_line = header_line

    @property
    def columns(self):
        return list(self.frame.columns)

    def __len__(self):
        return len(self.frame)

    def has(self, col):
        return col in self.frame.columns

    def line_of(self, row_position):
        """The file's line of the row at this position (the frame keeps the file's row index)."""
        return self.header_line + 1 + int(self.frame.index[row_position])

    def text(self, col):
        self.require([col])
        return self.frame[col].str.strip()

    def require(self, cols, kind=None):
        missing = [c for c in cols if c not in self.frame.columns]
        if missing:
            what = f" for `plot.py {kind}`" if kind else ""
            raise PlotError(f"{self.path}: column{'s' if len(missing) > 1 else ''} "
                            f"{', '.join(repr(c) for c in missing)} missing{what}")

    def number(self, col):
        """Column `col` as floats: an empty cell is NaN (gearloss leaves cells empty where there
        is no number); anything else that is not a finite number is an error at its line."""
        s = self.text(col)
        v = pd.to_numeric(s.where(s != "", None), errors="coerce").astype(float)
        bad = ~np.isfinite(v.to_numpy()) & (s != "").to_numpy()
        if bad.any():
            i = int(np.argmax(bad))
            raise PlotError(f"{self.path}:{self.line_of(i)}: column '{col}': '{s.iloc[i]}' is not a number")
        return v.to_numpy()

    def subset(self, mask):
        """The rows where mask holds (line numbers kept for the messages)."""
        return Table(self.path, self.frame[np.asarray(mask, dtype=bool)], self.header_line)


def read_table(path, kind):
    """Reads a gearloss CSV of `kind` (map, compare, cycle, diagnose). Leading '#' lines (a shard's
    fingerprint line) are skipped. Errors: missing, a directory, unreadable, not text, empty, no
    rows, ragged rows, missing columns (naming the kind the file looks like)."""
    if not os.path.exists(path):
        raise PlotError(f"{path}: no such file")
    if os.path.isdir(path):
        raise PlotError(f"{path}: is a directory, not a CSV file")
    try:
        with open(path, encoding="utf-8", newline="") as f:
            skip = 0
            for line in f:
                if not line.startswith("#"):
                    break
                skip += 1
        with warnings.catch_warnings():
            # a row longer than the header: pandas would drop its cells (or take the first as an index)
            warnings.simplefilter("error", pd.errors.ParserWarning)
            frame = pd.read_csv(path, skiprows=skip, dtype=str, keep_default_na=False, encoding="utf-8",
                                index_col=False)
    except PermissionError:
        raise PlotError(f"{path}: not readable (permission denied)")
    except UnicodeDecodeError:
        raise PlotError(f"{path}: not a text CSV file (not UTF-8)")
    except pd.errors.EmptyDataError:
        raise PlotError(f"{path}: empty file (no header, no rows)")
    except (pd.errors.ParserError, pd.errors.ParserWarning) as e:
        raise PlotError(f"{path}: not a well-formed CSV file ({str(e).strip()})")
    except OSError as e:
        raise PlotError(f"{path}: not readable ({e.strerror or e})")
    frame.columns = [str(c).strip() for c in frame.columns]
    with open(path, encoding="utf-8", newline="") as f:  # pandas pads a short row with empty cells
        for i, row in enumerate(csv.reader(f)):
            if i > skip and len(row) != len(frame.columns) and row:
                raise PlotError(f"{path}:{i + 1}: {len(row)} cells, the header has {len(frame.columns)}")
    table = Table(path, frame.reset_index(drop=True), skip + 1)
    if len(frame) == 0:
        raise PlotError(f"{path}: header only, no rows")
    need, writer = REQUIRED[kind]
    missing = [c for c in need if c not in frame.columns]
    if kind == "compare" and not any(c.startswith("dP_loss") for c in frame.columns):
        missing.append("dP_loss_W")
    if missing:
        looks = guess_kind(frame.columns)
        hint = (f": it looks like a `{REQUIRED[looks][1]}` file, drawn by `plot.py {looks}`" if looks and looks != kind
                else f": `plot.py {kind}` draws the CSV of `{writer}`")
        raise PlotError(f"{path}: column{'s' if len(missing) > 1 else ''} "
                        f"{', '.join(repr(c) for c in missing)} missing{hint}")
    for col in table.columns:
        if col == "status" or col.startswith("status_"):
            check_status(table, col)
    return table


def known_status(s):
    """Whether s is a status cell gearloss writes (solver/operating_point.hpp): ok,
    above_oil_limit, no_equilibrium (with or without a cause), out_of_range: CAUSE; empty where a
    comparison has no point."""
    return s in ("", "ok", "above_oil_limit") or s.startswith("no_equilibrium") or s.startswith("out_of_range: ")


def check_status(table, col):
    """A status cell gearloss does not write is an error at its line: drawn anyway, it would be
    an unlabelled failure region."""
    s = table.text(col)
    bad = ~s.map(known_status).to_numpy(dtype=bool)
    if bad.any():
        i = int(np.argmax(bad))
        raise PlotError(f"{table.path}:{table.line_of(i)}: column '{col}': '{s.iloc[i]}' is not a status gearloss "
                        "writes (ok, above_oil_limit, no_equilibrium, out_of_range: CAUSE)")


def read_sidecar(csv_path, warn):
    """The metadata sidecar CSV.meta.json as a dict, or None when there is none. A sidecar that
    cannot be read or is not gearloss metadata is ignored with a warning (the pictures then say
    only what the CSV itself says)."""
    path = csv_path + ".meta.json"
    if not os.path.exists(path):
        return None
    try:
        with open(path, encoding="utf-8") as f:
            meta = json.load(f)
    except (OSError, ValueError) as e:
        warn(f"{path}: ignored, not readable as JSON ({e})")
        return None
    if not isinstance(meta, dict) or not str(meta.get("format", "")).startswith("gearloss-metadata/"):
        warn(f"{path}: ignored, not gearloss metadata (no \"format\": \"gearloss-metadata/1\")")
        return None
    return meta


def field(meta, *keys):
    """meta[k1][k2]... or None when any level is missing or of the wrong type."""
    v = meta
    for k in keys:
        if isinstance(v, dict) and k in v:
            v = v[k]
        elif isinstance(v, list) and isinstance(k, int) and -len(v) <= k < len(v):
            v = v[k]
        else:
            return None
    return v
