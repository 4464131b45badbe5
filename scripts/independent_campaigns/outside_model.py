"""Outside the library: is the effect modelled, not only flagged (issue 38)?

Beside the honesty score of scoring.py (not named with confidence), two measures per campaign:
  * final model: the cross-validated loss residual of the final model (library findings + the
    remainder formula: `remainder_hypothesis.final_cv_rmse_W`; without a formula the findings'
    `cv_rmse_after`, without findings `rmse_before`) against the TRUE loss noise of the
    campaign (RMS over its rows of the drawn relative noise x the noise-free recorded loss):
    <= 1.5 is modelled. The report's own `final_cv_rmse_over_noise` is kept beside it.
  * form recovered by a term of the remainder formula (contract: terms[].shape, variable,
    exponent, threshold, lower/upper, gate, window):
      speed_step    a step/threshold in speed_rpm (or a gate on it) within one grid step (the spacing
                    of the two speed levels the truth lies between)
      hot_loss      a step/threshold in oil_temp_C (or a gate on it) within one grid step of oil
                    temperature: max(5 K, the campaign's oil temperature range / (points - 1))
      torque2_band  a power of torque_Nm with exponent 2 +- 0.3, and the band located in speed: a
                    window on speed_rpm (or a gate / threshold) within one speed step of the band's edges
      speed_power   a power of speed_rpm with the true exponent +- 0.3
      visc_loss     a power of viscosity_cSt with the true exponent +- 0.3
      running_in    a term along `order` (the campaign records a `run` column)
"""
import math
import re

FINAL_OVER_NOISE = 1.5
EXPONENT_TOL = 0.3


def _num(x):
    return x if isinstance(x, (int, float)) and math.isfinite(x) else None


def final_cv(diag):
    rh = diag.get("remainder_hypothesis") if isinstance(diag.get("remainder_hypothesis"), dict) else None
    if rh and _num(rh.get("final_cv_rmse_W")) is not None:
        return rh["final_cv_rmse_W"], "formula"
    if rh and _num(rh.get("cv_rmse_after")) and _num(rh.get("cv_rmse_before")):
        # before the contract's key: the formula's cross-validated reduction (its own scale, not W of the
        # findings' residual) applied to the findings' cross-validated residual (an estimate, said so)
        base = _num(diag.get("cv_rmse_after")) if diag.get("findings") else _num(diag.get("rmse_before"))
        if base is not None:
            return base * rh["cv_rmse_after"] / rh["cv_rmse_before"], "estimate: findings' CV residual x formula's reduction"
    if diag.get("findings") and _num(diag.get("cv_rmse_after")) is not None:
        return diag["cv_rmse_after"], "findings only"
    return _num(diag.get("rmse_before")), "model only"


def _speed_levels(truth):
    return sorted({x["speed_rpm"] for x in truth["rows"] if "dropped" not in x})


def _step_near(levels, x):
    """The spacing of the two levels around x (the grid step there)."""
    below = [v for v in levels if v <= x]
    above = [v for v in levels if v > x]
    if below and above:
        return above[0] - below[-1]
    return (levels[-1] - levels[0]) / max(len(levels) - 1, 1)


# A report before the contract's structured keys names its terms only by their text (`basis`, as
# README.md shows: "(T_in/350 N*m)^2 [n = 720 rpm]", "[n > 560 rpm]"); read from it what the text states.
_BASIS = [
    (re.compile(r"\[n\s*>\s*([\d.]+)\s*rpm\]"), lambda m: dict(variable="speed_rpm", shape="step", threshold=float(m[1]))),
    (re.compile(r"\[n\s*=\s*([\d.]+)\s*rpm\]"),
     lambda m: dict(variable="speed_rpm", shape="window", lower=float(m[1]), upper=float(m[1]))),
    (re.compile(r"\[T(?:_oil)?\s*>\s*([\d.]+)\s*degC\]"),
     lambda m: dict(variable="oil_temp_C", shape="threshold", threshold=float(m[1]))),
    (re.compile(r"\(T_in/[^)]*\)\^([-\d.]+)"), lambda m: dict(variable="torque_Nm", shape="power", exponent=float(m[1]))),
    (re.compile(r"\(n/[^)]*\)\^([-\d.]+)"), lambda m: dict(variable="speed_rpm", shape="power", exponent=float(m[1]))),
    (re.compile(r"\((?:nu|ν)/[^)]*\)\^([-\d.]+)"),
     lambda m: dict(variable="viscosity_cSt", shape="power", exponent=float(m[1]))),
    (re.compile(r"\(k/\d+\)"), lambda m: dict(variable="order", shape="power", exponent=1.0)),
]


def structured_terms(rh):
    """The remainder formula's terms with the contract's keys; terms without them are read from their text."""
    out = []
    for t in (rh.get("terms") or []):
        if not isinstance(t, dict):
            continue
        if "variable" in t or "shape" in t:
            out.append(t)
            continue
        for rx, make in _BASIS:
            for m in rx.finditer(str(t.get("basis", ""))):
                out.append(dict(make(m), from_text=True))
    return out


def _locations(terms, variable):
    """Thresholds / window edges the terms place on a variable (own shape or gate)."""
    out = []
    for t in terms:
        if t.get("variable") == variable:
            for k in ("threshold", "lower", "upper"):
                if _num(t.get(k)) is not None:
                    out.append(t[k])
        g = t.get("gate")
        if isinstance(g, dict) and g.get("variable") == variable and _num(g.get("threshold")) is not None:
            out.append(g["threshold"])
        wdw = t.get("window")  # a term confined to a band of another variable (docs/diagnosis-remainder.md)
        if isinstance(wdw, dict) and wdw.get("variable") == variable:
            out += [wdw[k] for k in ("lower", "upper") if _num(wdw.get(k)) is not None]
    return out


def _power(terms, variable, exponent):
    return any(t.get("variable") == variable and t.get("shape") == "power" and _num(t.get("exponent")) is not None
               and abs(t["exponent"] - exponent) <= EXPONENT_TOL for t in terms)


def form_recovered(truth, diag):
    """(True | False, what was looked for) for the campaign's outside effect."""
    e = truth["effects"][0]
    name, p = e["name"], e["params"]
    rh = diag.get("remainder_hypothesis") if isinstance(diag.get("remainder_hypothesis"), dict) else {}
    terms = structured_terms(rh)
    if name == "speed_step":
        levels = _speed_levels(truth)
        tol = _step_near(levels, p["above_rpm"])
        return any(abs(x - p["above_rpm"]) <= tol for x in _locations(terms, "speed_rpm")), f"speed step at {p['above_rpm']:g} rpm +- {tol:g}"
    if name == "hot_loss":
        temps = sorted(x["oil_temp_C"] for x in truth["rows"] if "dropped" not in x)
        tol = max(5.0, (temps[-1] - temps[0]) / max(len(temps) - 1, 1))
        return any(abs(x - p["above_degC"]) <= tol for x in _locations(terms, "oil_temp_C")), \
            f"threshold at {p['above_degC']:.1f} degC +- {tol:.1f} K"
    if name == "torque2_band":
        levels = _speed_levels(truth)
        lo, hi = p["band_rpm"]
        step = (levels[-1] - levels[0]) / max(len(levels) - 1, 1)
        # the band's edges halfway to the neighbouring levels (or open at the ends of the grid)
        edges = [v for v in (lo - step / 2 if lo > levels[0] else None, hi + step / 2 if hi < levels[-1] else None) if v]
        locs = _locations(terms, "speed_rpm")
        located = (all(any(abs(x - v) <= step for x in locs) for v in edges) if edges
                   else True)  # a band over every speed level needs no location
        return _power(terms, "torque_Nm", 2.0) and located, f"torque^2 in {lo:g}-{hi:g} rpm (edges {edges})"
    if name == "speed_power":
        return _power(terms, "speed_rpm", p["speed_exponent"]), f"n^{p['speed_exponent']:.2f}"
    if name == "visc_loss":
        return _power(terms, "viscosity_cSt", p["viscosity_exponent"]), f"nu^{p['viscosity_exponent']:.2f}"
    if name == "running_in":
        return any(t.get("variable") == "order" for t in terms), "a term along the run order"
    return None, "?"


def score_outside_model(truth, diag, res):
    cv, src = final_cv(diag)
    noise = truth.get("noise_loss_W")
    res["final_cv_W"], res["final_source"] = cv, src
    res["final_over_true_noise"] = cv / noise if cv is not None and noise else None
    rh = diag.get("remainder_hypothesis") if isinstance(diag.get("remainder_hypothesis"), dict) else {}
    res["final_over_noise_reported"] = _num(rh.get("final_cv_rmse_over_noise"))
    res["formula"] = bool(rh)
    res["final_ok"] = res["final_over_true_noise"] is not None and res["final_over_true_noise"] <= FINAL_OVER_NOISE
    res["form_ok"], res["form_looked_for"] = form_recovered(truth, diag)
