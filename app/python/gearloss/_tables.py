"""CSV text as the CLI writes it -> a table: a pandas DataFrame when pandas is importable, else a
dict of lists (no numpy needed). Numbers are read with float() (the exact value the CSV cell
writes); an empty cell is NaN; a column with any cell that is not a number stays text."""
import csv
import io
import math


def _number(cell):
    if cell == "":
        return math.nan
    return float(cell)


def columns_of(text):
    """The CSV's columns in order: {name: list of float or str}."""
    rows = list(csv.reader(io.StringIO(text)))
    if not rows:
        return {}
    names, body = rows[0], rows[1:]
    out = {}
    for c, name in enumerate(names):
        cells = [r[c] if c < len(r) else "" for r in body]
        try:
            out[name] = [_number(x) for x in cells]
        except ValueError:
            out[name] = cells
    return out


def have_pandas():
    try:
        import pandas  # noqa: F401
    except ImportError:
        return False
    return True


def table(text, as_frame=None):
    """A DataFrame (pandas present and ``as_frame`` None or True) or a dict of lists."""
    cols = columns_of(text)
    if as_frame is None:
        as_frame = have_pandas()
    if as_frame:
        import pandas as pd
        return pd.DataFrame(cols, columns=list(cols))
    return cols


def require_numpy(what):
    """numpy, or an ImportError that says what needs it and how to get it."""
    try:
        import numpy
    except ImportError:
        raise ImportError(f"gearloss: {what} needs numpy, which this Python cannot import: install it "
                          "(pip install numpy) or make the venv with --system-site-packages to use the "
                          "system's numpy; load, check, point, compare, spread, sweeps and cycle work without it") from None
    return numpy
