#!/usr/bin/env python3
"""Pictures of gearloss outputs (PNG, SVG or PDF, by the output file's extension).

  plot.py map MAP.csv OUT.png [--kind efficiency|oil-temp|loss|breakdown] [--levels N|LIST]
          [--select AXIS=VALUE ...] [--max-panels N]
      a field over speed x torque (computed points dotted, points without a result hatched)
      or the loss breakdown (`gearloss map`); a sweep is drawn as one panel per variant
  plot.py compare DIFF.csv OUT.png [--levels N]
      differences oil k - reference of loss, oil temperature and efficiency, one row per
      oil k (`gearloss compare`, two or more oils); red = worse than the reference
  plot.py cycle TRACE.csv OUT.png
      speed and gear, oil temperature, transmission loss and its running total of the start,
      warm-start and pre-warmed runs overlaid (`gearloss cycle -o`)
  plot.py diagnose RESIDUALS.csv OUT.png
      residuals before/after a diagnosis (`gearloss diagnose --residuals`)

Titles name the case, oil, thermal mode (fixed at X degC / stabilised) and ratio from the
metadata sidecar CSV.meta.json when there is one; without it only what the CSV shows (the
file's name; the thermal mode when the oil-temperature column proves it). --title replaces it.
--levels: a count (12) or an explicit list (efficiency as fractions or percent:
0.9,0.95,0.97,0.98,0.99); by default the levels span the robust range of the solved points.
--describe prints the title, panel titles and colour levels to stdout.

Errors are one line "plot.py: error: ..." on stderr with exit code 2. Needs Debian's
python3-matplotlib, python3-numpy and python3-pandas (scripts/plot.sh installs them).
"""
import argparse
import os
import sys
import tempfile

KINDS = ("map", "compare", "cycle", "diagnose")
FORMATS = (".png", ".svg", ".pdf")
PACKAGES = {"numpy": "python3-numpy", "pandas": "python3-pandas", "matplotlib": "python3-matplotlib"}


class UsageError(Exception):
    pass


class Parser(argparse.ArgumentParser):
    def error(self, message):  # one line, not argparse's usage block
        raise UsageError(message)


def fail(message, code=2):
    sys.stderr.write(f"plot.py: error: {message}\n")
    sys.exit(code)


def warn(message):
    sys.stderr.write(f"plot.py: warning: {message}\n")


def parse(argv):
    ap = Parser(prog="plot.py", description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter,
                usage="plot.py map|compare|cycle|diagnose CSV OUT.png [options]")
    ap.add_argument("what", choices=KINDS)
    ap.add_argument("csv")
    ap.add_argument("out", help="output picture (.png, .svg or .pdf)")
    ap.add_argument("--kind", choices=["efficiency", "oil-temp", "loss", "breakdown"], default="efficiency",
                    help="for map: which picture (default efficiency)")
    ap.add_argument("--levels", help="colour levels: a count (e.g. 12) or a list (e.g. 0.9,0.95,0.97,0.98,0.99)")
    ap.add_argument("--select", action="append", default=[], metavar="AXIS=VALUE",
                    help="for a sweep map: draw only the variants with this value (repeatable)")
    ap.add_argument("--max-panels", type=int, default=12, help="for a sweep map: most panels drawn (default 12)")
    ap.add_argument("--title", default="", help="replaces the title made from the metadata")
    ap.add_argument("--describe", action="store_true", help="print the title, panels and colour levels")
    a = ap.parse_args(argv)
    if a.what != "map" and (a.kind != "efficiency" or a.select):
        raise UsageError(f"--kind and --select apply to map pictures, not to {a.what}")
    if a.max_panels < 1:
        raise UsageError("--max-panels must be at least 1")
    ext = os.path.splitext(a.out)[1].lower()
    if ext not in FORMATS:
        raise UsageError(f"{a.out}: the picture's extension must be one of {', '.join(FORMATS)}")
    return a


def save(fig, out):
    """Writes the picture next to `out` and renames it over `out`: no half-written file."""
    folder = os.path.dirname(os.path.abspath(out))
    if not os.path.isdir(folder):
        raise OSError(2, "its folder does not exist")
    fd, tmp = tempfile.mkstemp(dir=folder, prefix=".plot-", suffix=os.path.splitext(out)[1])
    os.close(fd)
    try:
        fig.savefig(tmp, dpi=110, format=os.path.splitext(out)[1][1:].lower())
        umask = os.umask(0)
        os.umask(umask)
        os.chmod(tmp, 0o666 & ~umask)
        os.replace(tmp, out)
    finally:
        if os.path.exists(tmp):
            os.unlink(tmp)


def run(a):
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    from plotting import compare, cycle, data, diagnose, maps, scale
    from plotting.data import PlotError

    if os.path.abspath(a.out) == os.path.abspath(a.csv):
        raise PlotError(f"{a.out}: the picture would overwrite the CSV it is drawn from")
    a.levels = scale.parse_levels(a.levels) if a.levels is not None else None
    table = data.read_table(a.csv, a.what)
    meta = data.read_sidecar(a.csv, warn)
    fig = plt.figure(layout="constrained")
    if a.what == "map":
        info = maps.plot_map(fig, table, meta, a)
    elif a.what == "compare":
        info = compare.plot_compare(fig, table, meta, a)
    elif a.what == "cycle":
        info = cycle.plot_cycle(fig, table, meta, a, warn)
    else:
        info = diagnose.plot_diagnose(fig, table, meta, a)
    try:
        save(fig, a.out)
    except OSError as e:
        raise PlotError(f"{a.out}: cannot write the picture ({e.strerror or e})")
    finally:
        plt.close(fig)
    if a.describe:
        print("title: " + info["title"].replace("\n", " | "))
        for p in info.get("panels", []):
            print("panel: " + p)
        lv = info.get("levels")
        if isinstance(lv, dict):
            for name, v in lv.items():
                print(f"levels {name}: {v.describe()}")
        elif lv is not None:
            print("levels: " + lv.describe())


def main(argv=None):
    try:
        a = parse(argv)
    except UsageError as e:
        fail(f"{e} (plot.py --help lists the options)")
    for module, package in PACKAGES.items():
        try:
            __import__(module)
        except ImportError:
            fail(f"Python module '{module}' is missing for {sys.executable}: install Debian's {package} "
                 "(scripts/install-deps.sh, or use scripts/plot.sh, which installs it)")
    from plotting.data import PlotError

    try:
        run(a)
    except PlotError as e:
        fail(str(e))
    except KeyboardInterrupt:
        fail("interrupted", 130)
    except BrokenPipeError:
        # --describe into `head`: the reader left; the picture is written. Quiet, as a shell
        # tool killed by SIGPIPE (128 + 13), and no second error when Python flushes stdout.
        os.dup2(os.open(os.devnull, os.O_WRONLY), sys.stdout.fileno())
        sys.exit(141)
    except Exception as e:  # a bug here, not the user's: still one line, the traceback on request
        if os.environ.get("PLOT_DEBUG"):
            raise
        fail(f"internal error drawing {a.csv} ({type(e).__name__}: {e}); PLOT_DEBUG=1 shows the traceback")


if __name__ == "__main__":
    main()
