"""gearloss from Python: gearbox power losses, efficiency and oil temperature (docs/python.md).

The same library as the ``gearloss`` command line, called directly::

    import gearloss
    case = gearloss.load("configs/transfer-box.yaml")   # or a YAML string, or a dict
    print(case.check())                    # the report of `gearloss check`
    p = case.point(800, 250)               # rpm, N*m
    p["P_total_W"], p["efficiency"], p["oil_temp_C"], p["status"]
    df = case.grid()                       # the case's grid: a pandas DataFrame (numpy arrays without pandas)
    case.compare(["configs/oils/75W90-A.yaml", "configs/oils/75W140-A.yaml"])
    case.spread(), case.sweeps(), case.cycle("nedc", start_temp_C=-10)
    d = gearloss.diagnose(case, "recordings.csv")
    d.verdict, d.findings[0].effect

Names carry their units as in the CSV columns (``speed_rpm``, ``torque_Nm``, ``oil_temp_C``);
values the CSV leaves empty (no equilibrium, out of range) are NaN.

Errors: :class:`InputError` (a ``ValueError``) for a wrong case, oil file, recordings or argument,
with the command line's ``file:line:col: key: message`` text and ``file``, ``line``,
``column``, ``key``, ``message`` attributes; :class:`OutputError` (an ``OSError``); both derive
from :class:`Error`. Ctrl-C stops a long solve with ``KeyboardInterrupt``. The plausibility
warnings the command line prints on stderr are issued as :class:`CaseWarning`.
"""
import json as _json
import math
import os as _os
import warnings as _warnings
from collections.abc import Mapping as _Mapping

from . import _data_dir
from ._tables import have_pandas as _have_pandas, require_numpy as _require_numpy, table as _table


def _shipped_data():
    """The shipped data (drive cycles, the bearing catalogue): the package's own ``data`` folder
    when installed (pip), else the source tree of the build this module comes from."""
    here = _os.path.join(_os.path.dirname(_os.path.abspath(__file__)), "data")
    return here if _data_dir.DATA_DIR is None else _data_dir.DATA_DIR


# GEARLOSS_DATA_DIR, when set, names another folder.
_os.environ.setdefault("GEARLOSS_DATA_DIR", _shipped_data())

from . import _gearloss  # noqa: E402

__version__ = _gearloss.__version__
Error = _gearloss.Error
InputError = _gearloss.InputError
OutputError = _gearloss.OutputError

__all__ = ["load", "load_case", "Case", "diagnose", "synth", "Diagnosis", "Finding", "Error", "InputError",
           "OutputError", "CaseWarning"]


class CaseWarning(UserWarning):
    """A plausibility warning about a case ("file:line:col: key: warning: ..."), as the CLI prints."""


def _warn(texts):
    for text in texts:
        _warnings.warn(text, CaseWarning, stacklevel=3)


def load(source, ratio=None, base_dir=None):
    """Loads and checks a case (docs/config.md), as every gearloss command does.

    ``source``: a file path (str or path-like), a YAML document as a string (any string that
    holds a line break or starts with ``{``), or a dict (the YAML document as Python values:
    ``{"gears": [...], "oil": "oils/PAOR.yaml", ...}``, quantities as strings: ``"40 mm"``).
    Relative paths inside a string or a dict (the oil file, ``cycles/``) resolve against
    ``base_dir`` (default: the current directory); a file's resolve against its folder.
    ``ratio`` selects one of ``gearbox.ratios`` (the CLI's ``--ratio``). Raises
    :class:`InputError` naming file (``<string>`` or ``<dict>``), line, column and key of what is
    wrong. Plausibility warnings are issued as :class:`CaseWarning`.
    """
    if isinstance(source, _Mapping):
        # JSON is YAML: the dict's document as text, read by the same reader as a file.
        text = _json.dumps(source, indent=1, default=_json_value)
        impl = _gearloss.load_case_text(text, "<dict>", _base(base_dir), ratio)
    elif isinstance(source, str) and ("\n" in source or source.lstrip().startswith("{")):
        impl = _gearloss.load_case_text(source, "<string>", _base(base_dir), ratio)
    else:
        if base_dir is not None:
            raise TypeError("base_dir is for a case given as a string or a dict; a file's paths resolve against its folder")
        impl = _gearloss.load_case(_os.fspath(source), ratio)
    case = Case(impl)
    _warn(case.warnings)
    return case


def load_case(path, ratio=None, base_dir=None):
    """The same as :func:`load` (its first name)."""
    return load(path, ratio, base_dir)


def _json_value(v):
    """A value of a case's dict that json does not know: a path as its text, a numpy number as a
    number, anything else as its str (a quantity object's "40 mm")."""
    if isinstance(v, _os.PathLike):
        return _os.fspath(v)
    if hasattr(v, "item"):  # numpy scalars
        return v.item()
    return str(v)


def _base(base_dir):
    return _os.fspath(base_dir) if base_dir is not None else _os.getcwd()


class Case:
    """A loaded gearbox case. Make one with :func:`load`.

    Properties (read-only): ``file``, ``name``, ``ratio`` (selected, or None), ``ratios``,
    ``mechanisms`` (loss mechanism names) and ``mechanism_columns`` (their CSV columns),
    ``oil`` (its name), ``oil_file`` (set by :meth:`with_oil`), ``thermal_mode``
    ("stabilised" or "fixed"), ``oil_temp_C`` (fixed mode), ``ambient_temp_C``,
    ``speeds_rpm`` and ``torques_Nm`` (the case's grid), ``points`` (a point list's
    (rpm, N*m) pairs), ``sweep`` (its axes: (label, values)), ``warnings``, ``columns``
    (the map CSV's columns).
    """

    def __init__(self, impl):
        self._impl = impl
        self._info = impl.info

    def __getattr__(self, name):
        info = self.__dict__.get("_info")
        if info is not None and name in info:
            value = info[name]
            return list(value) if isinstance(value, list) else value
        raise AttributeError(f"'Case' object has no attribute '{name}'")

    def __dir__(self):
        return sorted(set(super().__dir__()) | set(self._info))

    def __repr__(self):
        ratio = f", ratio {self.ratio!r}" if self.ratio else ""
        return f"<gearloss.Case {self.file!r}: {self.name!r}, oil {self.oil!r}{ratio}, {self.thermal_mode} oil temperature>"

    def with_oil(self, path):
        """The same case with the oil of ``path`` (an oil YAML file; the CLI's ``--oil``)."""
        case = Case(self._impl.with_oil(str(path)))
        _warn(case.warnings)
        return case

    def point(self, speed_rpm, torque_Nm, oil_temp_C=None):
        """One operating point (``gearloss point``): a dict keyed like the map CSV's columns.

        Keys: ``speed_in_rpm``, ``torque_in_Nm``, ``power_in_W``, ``ambient_temp_C``,
        ``oil_temp_C``, one ``P_<mechanism>_W`` per mechanism, ``P_total_W``, ``power_out_W``,
        ``torque_out_Nm``, ``efficiency`` (a fraction), ``lambda_min``, ``status`` ("ok",
        "above_oil_limit", "no_equilibrium", "out_of_range: <cause>"), then every component's
        column of ``map --detail`` (``P_mesh_<m>_W``, the films ``lambda_<m>`` and
        ``h_min_<m>_um``, ``mu_<m>``, ``P_bearing_<b>_W``, ...). Values are NaN where the
        CSV leaves the cell empty. ``oil_temp_C`` fixes the oil temperature (no thermal
        solve; the CLI's ``--oil-temp``).
        """
        values = self._impl.point(float(speed_rpm), float(torque_Nm), _optional_float(oil_temp_C))
        _warn(values.pop("warnings"))
        return values

    def grid(self, speeds_rpm=None, torques_Nm=None, oil_temp_C=None, threads=None, detail=False, as_frame=None):
        """Every point of a grid (``gearloss map``), solved in parallel.

        ``speeds_rpm`` and ``torques_Nm`` replace the case's axes (the CLI's ``--speed`` and
        ``--torque``); rows run speed-major, torque-minor, as in the map CSV. ``oil_temp_C``
        fixes the oil temperature; ``threads`` (default: all cores); ``detail`` adds the
        per-component columns of ``map --detail``. Returns a pandas DataFrame with the map
        CSV's columns when pandas is importable (``as_frame`` None or True), else (or with
        ``as_frame=False``) a dict of numpy arrays in column order (``status`` an object
        array of str). Empty CSV cells are NaN.
        """
        np = _require_numpy("Case.grid")
        out = self._impl.grid(_optional_floats(speeds_rpm), _optional_floats(torques_Nm),
                              _optional_float(oil_temp_C), threads, bool(detail))
        _warn(out["warnings"])
        columns = out["columns"]
        columns["status"] = np.array(columns["status"], dtype=object)
        if as_frame is None:
            as_frame = _have_pandas()
        if as_frame:
            import pandas as pd
            return pd.DataFrame(columns, columns=list(columns))
        return columns

    map = grid  # the CLI's name

    def check(self, json=False):
        """The report of ``gearloss check`` (str), or with ``json=True`` its ``--json`` as a dict.

        The case is read again from its file, string or dict, with the oil of :meth:`with_oil`."""
        text = _gearloss.check(self._impl, bool(json))
        return _json.loads(text) if json else text

    def compare(self, oils, speeds_rpm=None, torques_Nm=None, oil_temp_C=None, threads=None, detail=False,
                as_frame=None):
        """The same map for two or more oil files (``gearloss compare --oil A --oil B ...``): the
        CSV's table (a DataFrame with pandas, else a dict of lists), one row per point with each
        oil's values and their differences to the first oil, as the CLI's columns and cells."""
        if isinstance(oils, (str, _os.PathLike)):
            oils = [oils]
        text = _gearloss.compare(self._impl, [_os.fspath(o) for o in oils], _optional_floats(speeds_rpm),
                                 _optional_floats(torques_Nm), _optional_float(oil_temp_C), threads, bool(detail))
        return _table(text, as_frame)

    def spread(self, axes=None, speeds_rpm=None, torques_Nm=None, oil_temp_C=None, threads=None, detail=False,
               as_frame=None):
        """The map with the model-form spread (``gearloss map --spread``): the map's columns, then
        ``P_total_min_W``, ``P_total_max_W``, the forms giving each and the combinations without a
        solution. ``axes`` restricts the form axes (``--spread-axes``: ``["mesh.friction",
        "windage.form"]``). Combinations that do not apply to the case are named in a
        :class:`CaseWarning`."""
        if isinstance(axes, str):
            axes = [a for a in axes.split(",")]
        out = _gearloss.spread(self._impl, None if axes is None else [str(a) for a in axes],
                               _optional_floats(speeds_rpm), _optional_floats(torques_Nm),
                               _optional_float(oil_temp_C), threads, bool(detail))
        if out["note"]:
            _warn(["map --spread: " + out["note"]])
        return _table(out["csv"], as_frame)

    def sweeps(self, speeds_rpm=None, torques_Nm=None, oil_temp_C=None, threads=None, detail=False, as_frame=None):
        """Every variant of the case's ``sweep:`` block (``gearloss map`` of a sweep case): the
        swept values' columns (labelled as the sweep names them), then the map's columns, one row
        per variant and point, the first axis slowest. A case without a sweep gives its map."""
        out = _gearloss.sweeps(self._impl, _optional_floats(speeds_rpm), _optional_floats(torques_Nm),
                               _optional_float(oil_temp_C), threads, bool(detail))
        _warn(out["warnings"])
        return _table(out["csv"], as_frame)

    def cycle(self, cycle, start_temp_C, ambient_C=None, prewarm_C=None, heater_W=100.0, warm_temp_C=90.0,
              trace=False, as_frame=None):
        """A drive cycle from a cold start (``gearloss cycle``): the ``--json`` summary as a dict.

        ``cycle``: a shipped cycle's name (``nedc``, ``wltc``, ``artemis``, ...; the case's own
        ``cycles/`` folder first) or a CSV file (``time_s,speed_kmh[,gear]``). ``ambient_C``
        defaults to the start temperature (a cold soak); ``prewarm_C`` and ``heater_W`` pre-warm
        the oil first. With ``trace=True`` returns ``(summary, trace)``, the trace the table of
        ``-o`` (a DataFrame with pandas). The summary dict also holds the printed summary under
        ``"text"``. Rows beyond the engine's fuel map are reported as a :class:`CaseWarning`."""
        out = _gearloss.cycle(self._impl, _os.fspath(cycle), float(start_temp_C), _optional_float(ambient_C),
                              _optional_float(prewarm_C), float(heater_W), float(warm_temp_C), bool(trace))
        if out["warning"]:
            _warn([out["warning"].rstrip("\n")])
        summary = _json.loads(out["json"])
        summary["text"] = out["text"]
        return (summary, _table(out["trace"], as_frame)) if trace else summary

    def diagnose(self, recordings_csv, **options):
        """The same as :func:`diagnose` (``gearloss diagnose``) on this case."""
        return diagnose(self, recordings_csv, **options)

    def synth(self, effects=None, **options):
        """The same as :func:`synth` (``gearloss synth``) on this case."""
        return synth(self, effects, **options)


def _optional_float(v):
    return None if v is None else float(v)


def _optional_floats(v):
    if v is None:
        return None
    try:
        return [float(x) for x in v]
    except TypeError:
        return [float(v)]


class Finding:
    """One named effect of a diagnosis: ``effect``, ``description``, ``parameter`` (dict: name,
    value, uncertainty, unit, form, case_form), ``shape`` (dict: name, value, grid of a shape
    setting fitted with the parameter, such as mesh.mixed_friction_onset; None without one),
    ``rmse_before_W``, ``rmse_after_W``,
    ``cv_rmse_before_W``, ``cv_rmse_after_W``, ``temp_rmse_before_K``, ``temp_rmse_after_K``,
    ``delta_bic``, ``cv_loglik_gain``, ``stability``, ``mechanism_stability``, ``equivalent``,
    ``separating_measurement``, ``rows``, ``oil``."""

    def __init__(self, d):
        self.__dict__.update(d)

    @property
    def improvement(self):
        """The loss RMSE after over before the effect (smaller is better)."""
        return self.rmse_after_W / self.rmse_before_W if self.rmse_before_W else math.nan

    def __repr__(self):
        p = self.parameter
        return (f"<gearloss.Finding {self.effect}: {p['name']} = {p['value']:.4g} {p['unit']}, "
                f"RMSE {self.rmse_before_W:.3g} -> {self.rmse_after_W:.3g} W>")


class Diagnosis:
    """What ``gearloss diagnose`` reports, as Python objects.

    ``verdict`` (missing_physics, partly_explained, unexplained_mismatch,
    no_significant_mismatch), ``summary``, ``location`` (where the mismatch lives),
    ``remaining``, ``findings`` (list of :class:`Finding`, the named effects),
    ``candidates`` (dicts, best first), ``rmse_before_W``, ``rmse_after_W`` (the fit's
    improvement), ``cv_rmse_after_W``, ``temp_rmse_before_K``, ``temp_rmse_after_K``,
    ``adequacy``, ``noise_used`` (the noise the verdict was judged against and why),
    ``main_finding`` (effect and confidence), ``completeness``, ``remaining_structure``,
    ``run_order``, ``outliers`` ((row, reason) pairs), ``remainder_hypothesis``, ``oils``,
    ``oil_differences``, ``warnings``, ``recordings_warnings``, ``points``, ``residuals``
    (columns as ``--residuals`` writes them: a DataFrame with pandas, else a dict of
    lists), ``text`` (the CLI's report).
    """

    def __init__(self, d):
        d = dict(d)
        d["findings"] = [Finding(f) for f in d["findings"]]
        residuals = d["residuals"]
        if _have_pandas():
            import pandas as pd
            residuals = pd.DataFrame(residuals, columns=list(residuals))
        d["residuals"] = residuals
        self.__dict__.update(d)

    @property
    def effects(self):
        """The names of the findings' effects, in the order found."""
        return [f.effect for f in self.findings]

    def __str__(self):
        return self.text

    def __repr__(self):
        return (f"<gearloss.Diagnosis {self.verdict}: {', '.join(self.effects) or 'no effect named'}; "
                f"RMSE {self.rmse_before_W:.3g} -> {self.rmse_after_W:.3g} W over {self.points} points>")


def diagnose(case, recordings_csv, bootstrap=24, threads=None, loss_uncertainty=None, temp_uncertainty_K=None):
    """Recordings against the model (``gearloss diagnose``): returns a :class:`Diagnosis`.

    ``recordings_csv``: steady points or a raw rig log (``time_s`` column), as for the CLI.
    ``loss_uncertainty``: the loss noise as a fraction (0.015 for the CLI's 1.5%);
    ``temp_uncertainty_K``: oil temperature noise in K; both estimated when None.
    """
    return Diagnosis(_gearloss.diagnose(case._impl, str(recordings_csv), int(bootstrap), threads,
                                        _optional_float(loss_uncertainty), _optional_float(temp_uncertainty_K)))


def synth(case, effects=None, noise_loss=0.015, noise_temp_K=0.4, seed=1, log=False, speeds_rpm=None,
          torques_Nm=None, path=None):
    """Synthetic recordings with concealed effects (``gearloss synth``): the CSV text, also
    written to ``path`` when given.

    ``effects``: {name: value} or ["name=value"], values as the CLI's ``--effect`` takes them
    (a number in SI units, or a string with its unit: {"windage": "30W"}).
    """
    if effects is None:
        effects = []
    elif isinstance(effects, dict):
        effects = [f"{k}={v}" for k, v in effects.items()]
    text = _gearloss.synth(case._impl, [str(e) for e in effects], float(noise_loss), float(noise_temp_K), int(seed),
                           bool(log), _optional_floats(speeds_rpm), _optional_floats(torques_Nm))
    if path is not None:
        with open(path, "w", encoding="utf-8") as f:
            f.write(text)
    return text
