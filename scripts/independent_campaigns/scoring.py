"""Running `gearloss diagnose` blind and scoring it against the truth.

score turns a diagnose.json into an outcome (correct top finding, in 2nd place, wrong
name, missed, false alarm, the expected form, the right oil scope, ...) and, for a correct
single finding, the fitted / true parameter ratio. A diagnose that exits non-zero, writes no
JSON or times out scores `error` in every category (never correct). The tables are tables.py's.
"""
import json
import subprocess
import time

from .effects import ACCEPT
from .outside_model import score_outside_model
from .robustness import score_order, score_outliers
from .synth_own import score_synth_own

# Coarse families (what kind of thing went wrong), reported beside strict acceptance, never counted as correct.
FAMILY = {
    "windage": "extra loss", "churning": "extra loss", "bearing_drag": "extra loss", "seal_friction": "extra loss",
    "constant_parasitic": "extra loss", "oil_viscosity": "extra loss", "mesh_friction": "extra loss",
    "mesh_friction_mixed": "extra loss",
    "thermal_resistance": "heat path", "speed_dependent_cooling": "heat path",
    "torque_sensor_gain": "sensor", "torque_sensor_offset": "sensor", "unstabilised_test": "test procedure",
}
# Neutral value of the comparable library parameter: fitted and true factors are compared as (f - 1)
# ratios, amounts (W, N*m, cooling per 1000 rpm) directly.
NEUTRAL = {"churning_speed": 1.0, "seal_extra": 1.0, "mesh_low_film": 1.0, "visc_shift": 1.0, "heat_factor": 1.0,
           "sensor_gain": 1.0}
# Library names whose fitted parameter is not the truth's comparable one (mesh_friction_mixed: the
# rise at full boundary share, not a factor over the campaign): no parameter ratio is scored.
NOT_COMPARABLE = {"mesh_friction_mixed"}
NULL_VERDICT = "no_significant_mismatch"
CONFIDENT_VERDICT = "missing_physics"
# The outcome that counts as correct in each category (two: both named; three: all three named).
GOOD = {"correct_top", "correct_top_not_confident", "both_named", "all_three_named", "correct_not_confident",
        "correct"}
DIAGNOSE_TIMEOUT_S = 900


def run_diagnose(binary, config, cdir, extra=()):
    t0 = time.time()
    out = cdir / "diagnose.json"
    if out.exists():
        out.unlink()  # never score a stale file
    cmd = ["nice", "-n", "19", binary, "diagnose", str(config), str(cdir / "recordings.csv"), "--json", str(out),
           *extra]
    try:
        r = subprocess.run(cmd, capture_output=True, text=True, timeout=DIAGNOSE_TIMEOUT_S)
    except subprocess.TimeoutExpired:
        (cdir / "diagnose.txt").write_text(f"timed out after {DIAGNOSE_TIMEOUT_S} s\n")
        return {"error": f"timeout after {DIAGNOSE_TIMEOUT_S} s"}, time.time() - t0
    (cdir / "diagnose.txt").write_text(r.stdout + ("\n--- stderr ---\n" + r.stderr if r.stderr else ""))
    dt = time.time() - t0
    if r.returncode != 0 or not out.exists():
        return {"error": f"exit {r.returncode}: {r.stderr.strip()[-300:]}"}, dt
    try:
        return json.loads(out.read_text()), dt
    except ValueError as e:
        return {"error": f"unreadable diagnose.json: {e}"}, dt


def first_param(finding):
    ps = finding.get("parameters") or {}
    for k, v in ps.items():
        if isinstance(v, dict) and "value" in v:
            return k, v["value"]
        if isinstance(v, (int, float)):
            return k, v
    return None, None


def equivalents(finding):
    eq = finding.get("equivalent") or []
    if isinstance(eq, str):
        eq = [eq]
    out = set()
    for x in eq:
        out.add(x.get("effect") if isinstance(x, dict) else str(x))
    return out


def score(truth, diag):
    """diag: the diagnose JSON, or for campaigns diagnosed several times (order) the list of them."""
    if isinstance(diag, list):
        bad = [d for d in diag if "error" in d]
        res = score(truth, bad[0] if bad else diag[0])  # the first file's fields, for the tables
        if not bad:
            score_order(truth, diag, res)
            res["correct"] = res["outcome"] == "correct"
        return res
    eff = [e["name"] for e in truth["effects"]]
    res = {"verdict": diag.get("verdict", "error" if "error" in diag else "?"), "error": diag.get("error")}
    finds = diag.get("findings") or []
    if not isinstance(finds, list) or any(not isinstance(f, dict) for f in finds):
        res["error"], finds = (res["error"] or "findings is not a list of objects"), []
    res["names"] = [f.get("effect") for f in finds]
    res["top"] = res["names"][0] if finds else None
    res["second"] = res["names"][1] if len(finds) > 1 else None
    res["top_equivalent"] = sorted(equivalents(finds[0])) if finds else []
    res["fitted"] = first_param(finds[0]) if finds else (None, None)
    v = res["verdict"]
    cat = truth["category"]
    acc = [ACCEPT.get(e, {e}) for e in eff]  # synth_own: the library effect itself
    res["top_ok"] = any(res["top"] in a for a in acc)
    res["param_ratio"] = None
    if res["error"]:
        res["outcome"], res["correct"] = "error", False
        return res
    if cat in ("synth_own", "order", "outliers"):
        if cat == "synth_own":
            score_synth_own(truth, diag, res)
        elif cat == "outliers":
            score_outliers(truth, diag, res)
        else:
            score_order(truth, [diag], res)
        res["correct"] = res["outcome"] == "correct"
        return res
    if cat == "null":
        res["outcome"] = "correct" if v == NULL_VERDICT else ("false_alarm_named" if res["top"] else "false_alarm_unexplained")
    elif cat == "outside":
        if v == NULL_VERDICT:
            res["outcome"] = "missed"
        elif v == CONFIDENT_VERDICT and res["top"]:
            res["outcome"] = "wrong_confident_name"
        else:
            res["outcome"] = "correct_not_confident"
        score_outside_model(truth, diag, res)
    elif cat == "single":
        if v == NULL_VERDICT:
            res["outcome"] = "missed"
        elif res["top"] in acc[0]:
            res["outcome"] = "correct_top" if v == CONFIDENT_VERDICT else "correct_top_not_confident"
        elif acc[0] & (set(res["names"][1:2]) | set(res["top_equivalent"])):
            res["outcome"] = "second_or_equivalent"
        elif res["top"]:
            res["outcome"] = "wrong_name"
        else:
            res["outcome"] = "not_confident_unnamed"
    elif cat in ("form", "form_effect"):
        score_form(truth, res, acc)
    elif cat == "multi_oil":
        score_multi_oil(truth, diag, finds, res)
    else:  # two or three effects
        score_several(res, acc)
    # parameter vs truth for a correct single finding
    if cat == "single" and res["top"] in acc[0] and res["top"] not in NOT_COMPARABLE:
        tp, fp = truth["effects"][0].get("truth_parameter"), res["fitted"][1]
        z = NEUTRAL.get(eff[0], 0.0)  # factors are compared by their departure from 1
        if tp is not None and fp is not None and tp != z:
            res["param_ratio"] = (fp - z) / (tp - z)
    res["correct"] = res["outcome"] in GOOD
    if truth.get("pair_hidden"):  # the recordings hardly show the second effect (tables.py counts it apart)
        res["pair_hidden"] = True
    return res


def score_several(res, acc):
    """Two (three) effects: how many truths the top two (three) findings name. Outcomes: both_named
    (all_three_named), two_named (three only), one_named_top, one_named_second (one_named_not_top),
    wrong_name, not_confident_unnamed, missed."""
    k = len(acc)
    hit = [bool(a & set(res["names"][:k])) for a in acc]
    res["named"] = sum(hit)
    everyone, one_later = ("both_named", "one_named_second") if k == 2 else ("all_three_named", "one_named_not_top")
    if res["verdict"] == NULL_VERDICT:
        res["outcome"] = "missed"
    elif all(hit):
        res["outcome"] = everyone
    elif sum(hit) >= 2:
        res["outcome"] = "two_named"
    elif res["top_ok"]:
        res["outcome"] = "one_named_top"
    elif any(hit):
        res["outcome"] = one_later
    elif res["top"]:
        res["outcome"] = "wrong_name"
    else:
        res["outcome"] = "not_confident_unnamed"


def score_form(truth, res, acc):
    """form: correct when the top finding is the expected `<axis>:<form>` id (named among the top
    finding's equivalents is reported apart, not correct). form_effect: correct when the top two
    findings name both the form and the small effect."""
    exp, v, names = truth["form"]["expected"], res["verdict"], res["names"]
    res["expected"] = exp
    if v == NULL_VERDICT:
        res["outcome"] = "missed"
    elif truth["category"] == "form_effect":
        form_ok, eff_ok = exp in names[:2], bool(acc[0] & set(names[:2]))
        res["outcome"] = ("correct" if form_ok and eff_ok else "form_only" if form_ok else "effect_only" if eff_ok
                          else "form_among_equivalents" if exp in res["top_equivalent"]
                          else "wrong_name" if res["top"] else "not_named")
    elif res["top"] == exp:
        res["outcome"] = "correct"
    elif exp in res["top_equivalent"]:
        res["outcome"] = "named_among_equivalents"
    elif exp in names[1:]:
        res["outcome"] = "form_not_top"
    elif res["top"] and ":" in res["top"]:
        res["outcome"] = "wrong_form"
    elif res["top"]:
        res["outcome"] = "wrong_name"
    else:
        res["outcome"] = "not_named"


def score_multi_oil(truth, diag, finds, res):
    """Correct when every truth effect is named with the right oil scope: `"oil": null` for a
    common effect, the `oil` column's text for a per-oil one (a finding without the key has no
    scope). Also notes whether the JSON carries the top-level array `oil_differences`."""
    res["oil_differences"] = isinstance(diag.get("oil_differences"), list)
    res["scopes"] = []
    status = []
    for e in truth["effects"]:
        named = [f for f in finds if f.get("effect") in ACCEPT[e["name"]]]
        given = [f.get("oil", "<no oil key>") for f in named]
        st = "right" if any("oil" in f and f["oil"] == e["oil"] for f in named) else \
            ("wrong_scope" if named else "absent")
        status.append(st)
        res["scopes"].append({"effect": e["name"], "expected_oil": e["oil"], "given": given, "status": st})
    if res["verdict"] == NULL_VERDICT:
        res["outcome"] = "missed"
    elif all(s == "right" for s in status):
        res["outcome"] = "correct"
    elif all(s != "absent" for s in status):
        res["outcome"] = "named_wrong_scope"
    elif any(s != "absent" for s in status):
        res["outcome"] = "partly_named"
    elif res["top"]:
        res["outcome"] = "wrong_name"
    else:
        res["outcome"] = "not_named"


