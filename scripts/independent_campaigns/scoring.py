"""Running `gearloss diagnose` blind, scoring it against the truth, and the tables.

score turns a diagnose.json into an outcome (correct top finding, in 2nd place, wrong
name, missed, false alarm, ...) and, for a correct single finding, the fitted / true
parameter ratio. tabulate and failures write scores.md and failures.md.
"""
import json
import subprocess
import time

from .cases import CASES
from .effects import ACCEPT, LIBRARY, OUTSIDE
from .numerics import median

# Coarse families (what kind of thing went wrong), reported beside strict acceptance, never counted as correct.
FAMILY = {
    "windage": "extra loss", "churning": "extra loss", "bearing_drag": "extra loss", "seal_friction": "extra loss",
    "constant_parasitic": "extra loss", "oil_viscosity": "extra loss", "mesh_friction": "extra loss",
    "thermal_resistance": "heat path", "speed_dependent_cooling": "heat path",
    "torque_sensor_gain": "sensor", "torque_sensor_offset": "sensor", "unstabilised_test": "test procedure",
}
# Neutral value of the comparable library parameter: fitted and true factors are compared as (f - 1)
# ratios, amounts (W, N*m, cooling per 1000 rpm) directly.
NEUTRAL = {"churning_speed": 1.0, "seal_extra": 1.0, "mesh_low_film": 1.0, "visc_shift": 1.0, "heat_factor": 1.0,
           "sensor_gain": 1.0}
NULL_VERDICT = "no_significant_mismatch"
CONFIDENT_VERDICT = "missing_physics"


def run_diagnose(binary, config, cdir):
    t0 = time.time()
    cmd = ["nice", "-n", "19", binary, "diagnose", str(config), str(cdir / "recordings.csv"),
           "--json", str(cdir / "diagnose.json")]
    r = subprocess.run(cmd, capture_output=True, text=True)
    (cdir / "diagnose.txt").write_text(r.stdout + ("\n--- stderr ---\n" + r.stderr if r.stderr else ""))
    dt = time.time() - t0
    if r.returncode != 0 or not (cdir / "diagnose.json").exists():
        return {"error": f"exit {r.returncode}: {r.stderr.strip()[-300:]}"}, dt
    return json.loads((cdir / "diagnose.json").read_text()), dt


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
    eff = [e["name"] for e in truth["effects"]]
    res = {"verdict": diag.get("verdict", "error" if "error" in diag else "?"), "error": diag.get("error")}
    finds = diag.get("findings") or []
    res["names"] = [f.get("effect") for f in finds]
    res["top"] = res["names"][0] if finds else None
    res["second"] = res["names"][1] if len(finds) > 1 else None
    res["top_equivalent"] = sorted(equivalents(finds[0])) if finds else []
    res["fitted"] = first_param(finds[0]) if finds else (None, None)
    v = res["verdict"]
    cat = truth["category"]
    acc = [ACCEPT[e] for e in eff]
    if cat == "null":
        res["outcome"] = "correct" if v == NULL_VERDICT else ("false_alarm_named" if res["top"] else "false_alarm_unexplained")
    elif cat == "outside":
        if v == NULL_VERDICT:
            res["outcome"] = "missed"
        elif v == CONFIDENT_VERDICT and res["top"]:
            res["outcome"] = "wrong_confident_name"
        else:
            res["outcome"] = "correct_not_confident"
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
    else:  # two effects
        names = res["names"][:2]
        hit = [bool(a & set(names)) for a in acc]
        if v == NULL_VERDICT:
            res["outcome"] = "missed"
        elif all(hit):
            res["outcome"] = "both_named"
        elif res["top"] and any(res["top"] in a for a in acc):
            res["outcome"] = "one_named_top"
        elif any(hit):
            res["outcome"] = "one_named_second"
        elif res["top"]:
            res["outcome"] = "wrong_name"
        else:
            res["outcome"] = "not_confident_unnamed"
    # parameter vs truth for a correct single finding
    res["param_ratio"] = None
    if cat == "single" and res["top"] in acc[0]:
        tp, fp = truth["effects"][0].get("truth_parameter"), res["fitted"][1]
        z = NEUTRAL.get(eff[0], 0.0)  # factors are compared by their departure from 1
        if tp is not None and fp is not None and tp != z:
            res["param_ratio"] = (fp - z) / (tp - z)
    return res


def snr(truth):
    a = truth.get("size_loss_rel", 0.0) / truth.get("noise_loss", 1.0)
    b = truth.get("size_temp_rms_K", 0.0) / truth.get("noise_temp_K", 1.0)
    return max(a, b)


def failures(results):
    """Every campaign not scored correct, with its truth and what diagnose said (for inspection)."""
    good = {"correct_top", "correct", "both_named", "correct_not_confident"}
    out = ["| campaign | truth | size loss / temp. | verdict | findings | summary |", "|---|---|---|---|---|---|"]
    for r in results:
        if "score" not in r or r["score"]["outcome"] in good:
            continue
        t = r["truth"]
        eff = "; ".join(e["name"] + " " + ", ".join(f"{k}={v:.4g}" if isinstance(v, float) else f"{k}={v}"
                                                   for k, v in e["params"].items()) for e in t["effects"]) or "none"
        fit = r["score"]["fitted"]
        fnd = ", ".join(x for x in r["score"]["names"] if x) or "-"
        if fit and fit[0]:
            fnd += f" ({fit[0]} = {fit[1]:.4g})"
        out.append(f"| {r['id']} | {eff} | {100 * t.get('size_loss_rel', 0):.1f} % / {t.get('size_temp_rms_K', 0):.1f} K | "
                   f"{r['score']['verdict']} ({r['score']['outcome']}) | {fnd} | {r.get('summary', '').replace('|', '/')[:300]} |")
    return "\n".join(out)


def pct(a, b):
    return f"{a}/{b} ({100 * a / b:.0f} %)" if b else "-"


def tabulate(results, cases_info):
    out = []
    p = out.append
    by = lambda cat: [r for r in results if r["truth"]["category"] == cat and "score" in r]
    p("## Single in-library effect (perturbed form), per case\n")
    p("| case | heat path | n | correct top (confident) | correct top, verdict not confident | in 2nd finding / equivalent | wrong name | not named | missed (no mismatch) |")
    p("|---|---|---|---|---|---|---|---|---|")
    single = by("single")
    for c in sorted({r["truth"]["case"] for r in single}, key=list(CASES).index):
        rs = [r for r in single if r["truth"]["case"] == c]
        cnt = lambda o: sum(1 for r in rs if r["score"]["outcome"] == o)
        p(f"| {c} | {cases_info[c]} | {len(rs)} | {pct(cnt('correct_top'), len(rs))} | {cnt('correct_top_not_confident')} | "
          f"{cnt('second_or_equivalent')} | {cnt('wrong_name')} | {cnt('not_confident_unnamed')} | {cnt('missed')} |")
    cnt = lambda o: sum(1 for r in single if r["score"]["outcome"] == o)
    p(f"| **all** | | {len(single)} | {pct(cnt('correct_top'), len(single))} | {cnt('correct_top_not_confident')} | "
      f"{cnt('second_or_equivalent')} | {cnt('wrong_name')} | {cnt('not_confident_unnamed')} | {cnt('missed')} |")
    p("\n## Single in-library effect, per effect (all cases)\n")
    p("| concealed effect | acceptable | n | correct top | wrong name, same family | what was named instead (count) | "
      "median size: loss / oil temp. | fitted / true parameter, median (range); factors as (f - 1) ratios |")
    p("|---|---|---|---|---|---|---|---|")
    for e in LIBRARY:
        rs = [r for r in single if r["truth"]["effects"][0]["name"] == e]
        if not rs:
            continue
        ok = sum(1 for r in rs if r["score"]["outcome"] in ("correct_top", "correct_top_not_confident"))
        fam = {FAMILY[x] for x in ACCEPT[e]}
        same = sum(1 for r in rs if r["score"]["outcome"] not in ("correct_top", "correct_top_not_confident")
                   and FAMILY.get(r["score"]["top"]) in fam)
        other = {}
        for r in rs:
            if r["score"]["outcome"] not in ("correct_top", "correct_top_not_confident"):
                k = r["score"]["top"] or r["score"]["verdict"]
                other[k] = other.get(k, 0) + 1
        ratios = [r["score"]["param_ratio"] for r in rs if r["score"]["param_ratio"] is not None]
        rtxt = f"{median(ratios):.2f} ({min(ratios):.2f}-{max(ratios):.2f}, n={len(ratios)})" if ratios else "-"
        size = (f"{100 * median(r['truth'].get('size_loss_rel', float('nan')) for r in rs):.1f} % / "
                f"{median(r['truth'].get('size_temp_rms_K', float('nan')) for r in rs):.1f} K")
        p(f"| {e} | {', '.join(sorted(ACCEPT[e]))} | {len(rs)} | {pct(ok, len(rs))} | {same} | "
          f"{', '.join(f'{k} {v}' for k, v in sorted(other.items(), key=lambda x: -x[1])) or '-'} | {size} | {rtxt} |")
    p("\n## Single in-library effect by visibility (signal / noise = max(loss size / loss noise, temp. size / temp. noise))\n")
    p("| signal / noise | n | correct top | missed |")
    p("|---|---|---|---|")
    for lo, hi in [(0, 1), (1, 3), (3, 10), (10, 1e9)]:
        rs = [r for r in single if lo <= snr(r["truth"]) < hi]
        if rs:
            ok = sum(1 for r in rs if r["score"]["outcome"] in ("correct_top", "correct_top_not_confident"))
            p(f"| {lo:g}-{hi:g} | {len(rs)} | {pct(ok, len(rs))} | {sum(1 for r in rs if r['score']['outcome'] == 'missed')} |"
              .replace("-1e+09", "+"))
    two = by("two")
    if two:
        p("\n## Two effects at once\n")
        p("| n | both named (top two findings) | one named as top | one named second only | wrong top name | not named | missed |")
        p("|---|---|---|---|---|---|---|")
        cnt = lambda o: sum(1 for r in two if r["score"]["outcome"] == o)
        p(f"| {len(two)} | {pct(cnt('both_named'), len(two))} | {cnt('one_named_top')} | {cnt('one_named_second')} | "
          f"{cnt('wrong_name')} | {cnt('not_confident_unnamed')} | {cnt('missed')} |")
    p("\n## By heat path (resistance: exact re-implementation; housing: textbook, within ~2 %; fixed: no temperature evidence)\n")
    p("| heat path | single: correct top | two: both named | outside: correct (not confident) | null: correct |")
    p("|---|---|---|---|---|")
    for hk in ["resistance", "housing", "fixed"]:
        cells = []
        for cat, good in [("single", ("correct_top", "correct_top_not_confident")), ("two", ("both_named",)),
                          ("outside", ("correct_not_confident",)), ("null", ("correct",))]:
            rs = [r for r in by(cat) if r["truth"].get("heat") == hk]
            cells.append(pct(sum(1 for r in rs if r["score"]["outcome"] in good), len(rs)))
        p(f"| {hk} | " + " | ".join(cells) + " |")
    outside = by("outside")
    if outside:
        p("\n## Effects outside the library (correct = a non-confident verdict)\n")
        p("| effect | n | correct (not confident) | wrong (confident library name) | missed (no mismatch) | names given when wrong |")
        p("|---|---|---|---|---|---|")
        for e in OUTSIDE + ["all"]:
            rs = outside if e == "all" else [r for r in outside if r["truth"]["effects"][0]["name"] == e]
            if not rs:
                continue
            cnt = lambda o: sum(1 for r in rs if r["score"]["outcome"] == o)
            names = {}
            for r in rs:
                if r["score"]["outcome"] == "wrong_confident_name":
                    names[r["score"]["top"]] = names.get(r["score"]["top"], 0) + 1
            p(f"| {'**all**' if e == 'all' else e} | {len(rs)} | {pct(cnt('correct_not_confident'), len(rs))} | "
              f"{cnt('wrong_confident_name')} | {cnt('missed')} | {', '.join(f'{k} {v}' for k, v in names.items()) or '-'} |")
    null = by("null")
    if null:
        p("\n## Null campaigns (correct = no_significant_mismatch)\n")
        p("| case | n | correct | false alarm with a name | false alarm without a name |")
        p("|---|---|---|---|---|")
        for c in sorted({r["truth"]["case"] for r in null}, key=list(CASES).index) + ["all"]:
            rs = null if c == "all" else [r for r in null if r["truth"]["case"] == c]
            cnt = lambda o: sum(1 for r in rs if r["score"]["outcome"] == o)
            p(f"| {'**all**' if c == 'all' else c} | {len(rs)} | {pct(cnt('correct'), len(rs))} | "
              f"{cnt('false_alarm_named')} | {cnt('false_alarm_unexplained')} |")
    errs = [r for r in results if r.get("score", {}).get("error")]
    if errs:
        p(f"\n{len(errs)} campaigns where diagnose failed: " + "; ".join(f"{r['id']}: {r['score']['error'][:120]}" for r in errs[:5]))
    p("\n## Acceptance mapping used (perturbed effect -> acceptable library names)\n")
    for e in LIBRARY + OUTSIDE:
        p(f"- `{e}` -> {', '.join('`' + x + '`' for x in sorted(ACCEPT[e])) if ACCEPT[e] else 'none: a non-confident verdict (anything but missing_physics with a name, and not no_significant_mismatch)'}")
    return "\n".join(out)
