"""order and outliers: what the row order and single rows may (not) make the diagnosis say (issue 38).

order   the same campaign (built as the others: perturbed effect, own heat balance, noise; no
        ambient drift and no effect along the run, so the row order carries nothing) written
        three ways: sorted by speed, sorted by torque, shuffled; no `run`/time column. Correct
        when verdict and top finding are the same for the three files and none of the three
        forms a drift / running-in hypothesis (contract: `run_order.recorded == false`, no
        remainder term along `order`, no running-in or drift named).
        `drift_*`: a true drift along the run (loss_drift: linear +-12..25 % over the campaign;
        running_in: the decay of effects.RunningIn), the run order in a `run` column, the rows
        written in another (shuffled) order. Correct when the drift is named: `run_order.recorded`
        with column `run`, and a remainder term along `order` or a drift / running-in named.
outliers 1.5 % loss noise, no outlier (a null or a windage-like drag): no row may be listed as
        an outlier whose true noise draws (loss and oil temperature) are both < 2.5 standard
        deviations; `planted`: the same with one row's recorded loss +20 %, which must be listed
        (and no normal row). `outl_synth_*`: made by `gearloss synth` (3 x 3 null or mesh friction
        x 1.2, 4 x 4 null; the issue's normal rows listed were synth's), the true draws from a
        noise-free twin of the same grid (synth_own.build_synth_outlier).
"""
import csv
import json
import random
import re

from .campaigns import build_campaign
from .outside_model import structured_terms
from .synth_own import plan_synth_own, synth_configs

ORDERINGS = ["by_speed", "by_torque", "shuffled"]
ORDER_EFFECTS = [["speed_step"], ["aero_drag"], []]
DRIFT_EFFECTS = ["loss_drift", "running_in"]
OUTLIER_NOISE = 0.015
PLANTED_FACTOR = 1.20
NORMAL_Z = 2.5  # a row whose noise draw is below this many standard deviations is not an outlier
DRIFT_WORDS = re.compile(r"running[- ]in|drift|run order", re.I)


def plan_issue38(case_names, seeds, quick, categories):
    """The campaigns of the categories synth_own, order and outliers (after campaigns.plan's)."""
    cats = set(categories)
    specs = plan_synth_own(case_names, seeds, quick) if "synth_own" in cats else []
    own = dict(synth_configs(case_names))
    for cname in case_names:
        for s in range(seeds):
            add = lambda cat, **kw: specs.append(dict(case=cname, seed=s, category=cat, **kw))
            plan_robustness(cname, s, quick, cats, add)
            if "outliers" in cats and cname in own and not quick:  # the same made by synth, 9 and 16 points
                for eff, npts in [(None, 9), ("mesh_friction=1.2", 9), (None, 16)]:
                    add("outliers", effects=[], tag=f"outl_synth_{'mesh' if eff else 'null'}_{npts}pt", kind="clean",
                        synth=True, synth_effect=eff, points=npts, noise=OUTLIER_NOISE, config=own[cname])
    return specs


def plan_robustness(cname, seed, quick, cats, add):
    if "order" in cats:
        for eff in ([["speed_step"]] if quick else ORDER_EFFECTS):
            add("order", effects=eff, tag="order_" + ("+".join(eff) or "null"), kind="orderings",
                conditions=dict(drift=0.0, format="ploss"))
        for e in ([] if quick else DRIFT_EFFECTS):
            add("order", effects=[e], tag=f"drift_{e}", kind="drift",
                conditions=dict(drift=0.0, format="ploss", shuffle_file=True))
    if "outliers" in cats:
        for eff, planted in ([([], False), ([], True)] if quick else
                             [([], False), (["aero_drag"], False), ([], True), (["aero_drag"], True)]):
            add("outliers", effects=eff, tag="outl_" + ("planted" if planted else "clean") + "_" + ("+".join(eff) or "null"),
                kind="planted" if planted else "clean", conditions=dict(noise_loss=OUTLIER_NOISE, format="ploss"))


def _read(path):
    with open(path) as f:
        rd = csv.DictReader(f)
        return rd.fieldnames, list(rd)


def _write(path, cols, rows):
    path.parent.mkdir(parents=True, exist_ok=True)
    text = ",".join(cols) + "\n" + "".join(",".join(r[c] for c in cols) + "\n" for r in rows)
    unchanged = path.exists() and path.read_text() == text
    if not unchanged:
        path.write_text(text)
    return unchanged


def build_robustness(spec, c, cdir):
    """(truth, None) or (None, why); truth["runs"] lists the sub-folders diagnosed (one recordings.csv each)."""
    truth, why = build_campaign(spec, c.model, c.oil, c.heat, c.ambient, cdir)
    if truth is None:
        return None, why
    truth["kind"] = spec["kind"]
    cols, rows = _read(cdir / "recordings.csv")
    if spec["kind"] == "orderings":
        rng = random.Random(f"{spec['case']}|{spec['tag']}|{spec['seed']}|orderings")
        key_n = lambda r: (float(r["speed_in_rpm"]), float(r["torque_in_Nm"]))
        key_t = lambda r: (float(r["torque_in_Nm"]), float(r["speed_in_rpm"]))
        shuffled = list(rows)
        rng.shuffle(shuffled)
        same = True
        for name, rs in zip(ORDERINGS, [sorted(rows, key=key_n), sorted(rows, key=key_t), shuffled]):
            same &= _write(cdir / name / "recordings.csv", cols, rs)
        truth["runs"], truth["recordings_unchanged"] = list(ORDERINGS), truth["recordings_unchanged"] and same
    elif spec["kind"] in ("clean", "planted"):
        kept = [x for x in truth["rows"] if "dropped" not in x]
        z = [(float(r["P_loss_W"]) / x["P_recorded_noiseless_W"] - 1) / OUTLIER_NOISE for r, x in zip(rows, kept)]
        truth["noise_z_temp"] = [(float(r["oil_temp_C"]) - x["oil_temp_C"]) / truth["noise_temp_K"]
                                 for r, x in zip(rows, kept)]
        truth["planted_row"] = None
        if spec["kind"] == "planted":
            rng = random.Random(f"{spec['case']}|{spec['tag']}|{spec['seed']}|planted")
            k = rng.randrange(len(rows))
            rows[k]["P_loss_W"] = f"{float(rows[k]['P_loss_W']) * PLANTED_FACTOR:.3f}"
            truth["planted_row"] = k + 1  # 1-based data row, as `diagnose` numbers them
            truth["recordings_unchanged"] = _write(cdir / "recordings.csv", cols, rows)
        truth["noise_z"] = z
    (cdir / "truth.json").write_text(json.dumps(truth, indent=1))
    return truth, None


def _terms(diag):
    rh = diag.get("remainder_hypothesis")
    return structured_terms(rh) if isinstance(rh, dict) else []


def order_hypothesis(diag, with_summary=False):
    """Does the output form a hypothesis along the run order (a term along `order`, running-in or drift named
    in the remainder hypothesis or a finding; with_summary: also in the summary, which without a recorded
    order may well say that no such hypothesis is formed)?"""
    if any(isinstance(t, dict) and t.get("variable") == "order" for t in _terms(diag)):
        return True
    rh = diag.get("remainder_hypothesis")
    text = " ".join([json.dumps(rh) if rh else "", str(diag.get("summary") or "") if with_summary else ""]
                    + [str(f.get("effect")) + " " + str(f.get("description")) for f in diag.get("findings") or []
                       if isinstance(f, dict)])
    return bool(DRIFT_WORDS.search(text))


def _recorded(diag):
    ro = diag.get("run_order")
    return ro.get("recorded") if isinstance(ro, dict) else None, ro.get("column") if isinstance(ro, dict) else None


def score_order(truth, diags, res):
    if truth["kind"] == "orderings":
        keys = [(d.get("verdict"), ((d.get("findings") or [{}])[0] or {}).get("effect") if d.get("findings") else None)
                for d in diags]
        res["per_ordering"] = [f"{v}/{t}" for v, t in keys]
        res["identical"] = len(set(keys)) == 1
        res["no_order_hypothesis"] = all(not order_hypothesis(d) for d in diags)
        res["recorded_false"] = all(_recorded(d)[0] is False for d in diags)
        res["structure_along_row_order"] = sum(
            1 for d in diags if ((d.get("adequacy") or {}).get("loss_relative") or {}).get("structure_along") == "run order")
        ok = res["identical"] and res["no_order_hypothesis"] and res["recorded_false"]
        res["outcome"] = "correct" if ok else ("order_changes_answer" if not res["identical"] else
                                               "drift_hypothesis" if not res["no_order_hypothesis"] else
                                               "run_order_not_reported")
    else:
        d = diags[0]
        rec, col = _recorded(d)
        res["drift_named"] = rec is True and col == "run" and order_hypothesis(d, with_summary=True)
        res["outcome"] = "correct" if res["drift_named"] else \
            ("run_column_ignored" if rec is not True else "drift_not_named")


def score_outliers(truth, diag, res):
    listed = set()
    for o in diag.get("outliers") or []:
        if isinstance(o, dict) and isinstance(o.get("row"), int):
            listed.add(o["row"])
    z, zt = truth["noise_z"], truth.get("noise_z_temp") or [0.0] * len(truth["noise_z"])
    res["listed"] = sorted(listed)
    # a normal row: its true noise draw is below NORMAL_Z standard deviations in the loss and the oil temperature
    res["false_outliers"] = [r for r in listed if r != truth["planted_row"] and 1 <= r <= len(z)
                             and abs(z[r - 1]) < NORMAL_Z and abs(zt[r - 1]) < NORMAL_Z]
    res["planted_listed"] = truth["planted_row"] in listed if truth["planted_row"] else None
    if res["false_outliers"]:
        res["outcome"] = "normal_row_listed"
    elif truth["planted_row"] and not res["planted_listed"]:
        res["outcome"] = "planted_missed"
    else:
        res["outcome"] = "correct"
