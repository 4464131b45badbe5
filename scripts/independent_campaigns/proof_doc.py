"""docs/diagnosis-proof.md: how the truth is built, the categories, the targets, the measured tables.

write_proof_doc is called by `scripts/independent-campaigns.py --proof-doc FILE` (which
scripts/prove-diagnosis.sh runs over every shipped case and every category). The document
holds the per-category and per-case tables and a summary of the failures; every campaign's
detail stays in the OUT directory (scores.md, failures.md, campaigns/...).
"""
import datetime
import subprocess

from .cases import CASES, ROOT
from .effects import LIBRARY
from .numerics import median
from .tables import CATEGORY_TITLES, measures, pct, summary_tables

PARAM_TOLERANCE = 0.15  # fitted parameters within 15 % of the truth (factors by their departure from 1)

# (category, index into tables.measures, target text, test on (count, n), or None: reported, no target)
TARGETS = [
    ("single", 0, ">= 95 % on every gearbox", None),  # tested per case below
    ("two", 0, ">= 95 % (issue 38)", lambda k, n: k >= 0.95 * n),
    ("two", 1, ">= 90 % (issue 38)", lambda k, n: k >= 0.90 * n),
    ("two", 2, "reported (the target is on every pair)", None),
    ("three", 0, "no target", None), ("three", 1, "no target", None), ("three", 2, "no target", None),
    ("outside", 0, ">= 85 %", lambda k, n: k >= 0.85 * n),
    ("outside", 1, "never (0)", lambda k, n: k == 0),
    ("outside", 2, ">= 80 % (issue 38)", lambda k, n: k >= 0.80 * n),
    ("outside", 3, ">= 70 % (issue 38)", lambda k, n: k >= 0.70 * n),
    ("outside", 4, "reported", None),
    ("form", 0, ">= 85 %", lambda k, n: k >= 0.85 * n),
    ("form", 1, "reported apart, not correct", None),
    ("form_effect", 0, "no target", None),
    ("multi_oil", 0, "no target", None), ("multi_oil", 1, "present in every campaign", lambda k, n: k == n),
    ("null", 0, ">= 97 %", lambda k, n: k >= 0.97 * n),
    # issue 38's own categories (synth_own.py, robustness.py)
    ("synth_own", 0, ">= 90 %", lambda k, n: k >= 0.90 * n),
    ("synth_own", 1, ">= 90 %", lambda k, n: k >= 0.90 * n),
    ("synth_own", 2, ">= 90 %", lambda k, n: k >= 0.90 * n),
    ("synth_own", 3, "reported", None),
    ("synth_own", 4, "every campaign", lambda k, n: k == n),
    ("order", 0, "every campaign", lambda k, n: k == n),
    ("order", 1, "every campaign", lambda k, n: k == n),
    ("order", 2, "every campaign", lambda k, n: k == n),
    ("order", 3, "every campaign", lambda k, n: k == n),
    ("outliers", 0, "every campaign", lambda k, n: k == n),
    ("outliers", 1, "every campaign", lambda k, n: k == n),
    ("outliers", 2, "every campaign", lambda k, n: k == n),
    ("outliers", 3, "every campaign", lambda k, n: k == n),
]

TRUTH_TEXT = """\
## How the truth is built

The campaigns come from `scripts/independent-campaigns.py` (package `scripts/independent_campaigns/`),
written from README.md, docs/config.md, the shipped cases and oils and the `--help` texts only; the
diagnosis source is not read. `gearloss synth` is not used: the truth never takes a candidate's own form,
the tool's coupled solve or its noise. Method and effect forms in detail:
[diagnosis-independent.md](diagnosis-independent.md).

1. **Model part:** `gearloss map CASE --oil-temp T --detail` on a 6 x 6 superset grid at T = 5, 10, ... 150 degC,
   interpolated per point in T (monotone cubic). For form campaigns the same case with another form selected
   under `mechanisms:`, for multi-oil campaigns the same case with another `oil:` (derived case files in
   OUT/cases/, mapped once per case + form and per case + oil). `diagnose` always receives the case itself.
2. **Concealed effects** in perturbed forms written in the script (other exponents, thresholds, speed or load
   dependences than the candidates), effects outside the library, and per-oil effects.
3. **Heat balance** solved in the script: the first crossing P_heat(T) = Q(T) warming up from ambient, with Q
   from a rig-measured resistance on derived cases (exact, checked against the binary within 0.3 K), the housing
   correlations README.md documents on the *_housing cases (own air data: within 0.5 % of the binary's heat flow), or a fixed
   oil temperature.
4. **Recordings:** rig-like sub-grids of 9-30 points (3-5 speeds x 3-6 torques; 9 = a rig's 3 x 3), speed outer /
   torque inner or shuffled, loss noise 1-3 %, oil temperature noise 0.3-0.5 K, an ambient drifting by up to
   +-4 K in half of the campaigns, the loss recorded as `P_loss_W` or as output torque and speed, sensor
   artefacts on the recorded input torque.
"""

CATEGORY_TEXT = """\
## Categories and scoring

| category | truth | correct when |
|---|---|---|
| single | one in-library effect in a perturbed form, 6-14 % of the loss (heat path: factor 0.72-0.85 or 1.18-1.35) | the top finding is the acceptable library name (any verdict) |
| two | two in-library effects, 5-10 % each, no name acceptable for both | *top*: the top finding is one of them; *second*: both in the top two findings; *shown*: the same over the pairs where neither effect hides behind the other refitted alone in its own family (expected BIC gain of the hidden one < 10, identifiability.py) |
| three | three in-library effects, 4-8 % each, no name acceptable for two | *top*: the top finding is one of them; *second*: at least two named; *third*: all three named (top three findings) |
| outside | one effect outside the library (a speed step, a loss in hot oil, a torque^2 resonance band, running-in) | a non-confident verdict (`unexplained_mismatch` / `partly_explained`); *wrong* is `missing_physics` with a library name |
| form | no effect; the model part from the same case with another published form (mesh friction, load-loss factor, film correction, windage form), only where the change is >= 3x the campaign's loss noise and the form's map solves every point | the top finding's id is `<axis>:<form>` (`friction:ehl_local`, ...); named among the top finding's equivalents is reported apart |
| form + effect | a form change with a 4-6 % torque-sensor offset or windage-like drag | both in the top two findings |
| multi-oil | 2-3 oils of one family on the same grid (column `oil` = a path relative to the recordings); a common effect (windage-like, sensor offset, seals, pump, heat path), a per-oil one (that oil's viscosity x 1.3-1.6 or / 1.3-1.6 at every temperature, or its mesh friction +-15-30 %), or one of each | every truth named with the right scope: `"oil": null` for a common effect, `"oil": "<the column text>"` for a per-oil one (`oil_viscosity`, `mesh_friction`) |
| null | nothing concealed | `no_significant_mismatch` |
| synth's own heat path | `gearloss synth` itself: one library effect (6-14 % of the loss, heat path x 0.75-0.85 or 1.2-1.3), 9 or 16 points, 1-3 % loss noise, diagnosed without and with `--loss-uncertainty`; plus the 3 x 3 `synth --effect mesh_friction=1.2` at 1.5 % | the effect as top finding AND `missing_physics`; 3 x 3: no resonance / local-contact lead, loss noise used >= its stated floor and >= half the true noise, factor within 5 % |
| row order | one campaign (no ambient drift, nothing along the run) written sorted by speed, by torque and shuffled, no run column; a true drift (linear or running-in) with a `run` column, rows shuffled | the same verdict and top finding for the three files, `run_order.recorded` false and no drift / running-in hypothesis; with the column: `run_order.recorded` (column `run`) and the drift named |
| outliers | 1.5 % loss noise, null or windage-like drag; the same with one row's loss +20 %; 3 x 3 and 4 x 4 campaigns made by `gearloss synth` (true draws from a noise-free twin) | no row whose true noise draws (loss, oil temperature) are both < 2.5 sigma listed as an outlier; the planted row listed |

Outside the library is also scored for the model of the remainder: the final model's cross-validated loss
residual (library findings + the remainder formula; `remainder_hypothesis.final_cv_rmse_W`) <= 1.5 x the
campaign's true loss noise, and the form recovered by a formula term (a step or threshold within one grid step
of the truth in the right variable, a power exponent within +-0.3; scripts/independent_campaigns/outside_model.py).
"""


def _git(*args):
    r = subprocess.run(["git", "-C", str(ROOT), *args], capture_output=True, text=True)
    return r.stdout.strip() if r.returncode == 0 else "?"


def _version(binary):
    r = subprocess.run([binary, "--version"], capture_output=True, text=True)
    return (r.stdout or r.stderr).strip().splitlines()[0] if r.returncode == 0 else "?"


def _scored(results, cat, case=None):
    return [r for r in results if r["truth"]["category"] == cat and "score" in r
            and (case is None or r["truth"]["case"] == case)]


def _cell(results, cat, case, idx):
    rs = _scored(results, cat, case)
    if not rs:
        return "-"
    return " / ".join(f"{100 * k / n:.0f} %" for _, k, n in (measures(rs, cat)[i] for i in idx)) + f" (n={len(rs)})"


def evaluate_targets(results):
    """[{category, measure, target, measured, met: yes | no | -}] for the targets of TARGETS."""
    rows = []
    for cat, idx, target, test in TARGETS:
        rs = _scored(results, cat)
        if not rs:
            rows.append(dict(category=CATEGORY_TITLES[cat], measure=measures([], cat)[idx][0], target=target,
                             measured="not run", met="-"))
            continue
        lab, k, n = measures(rs, cat)[idx]
        met = "-" if test is None or n == 0 else ("yes" if test(k, n) else "no")
        meas = pct(k, n)
        if cat == "single":  # on every gearbox
            per = {c: measures(_scored(results, cat, c), cat)[0] for c in {r["truth"]["case"] for r in rs}}
            worst = min(per, key=lambda c: per[c][1] / per[c][2])
            meas += f"; lowest {worst} {pct(per[worst][1], per[worst][2])}"
            met = "yes" if all(v[1] >= 0.95 * v[2] for v in per.values()) else "no"
        rows.append(dict(category=CATEGORY_TITLES[cat], measure=lab, target=target, measured=meas, met=met))
    ratios = [r["score"]["param_ratio"] for r in _scored(results, "single") if r["score"]["param_ratio"] is not None]
    within = sum(1 for x in ratios if abs(x - 1) <= PARAM_TOLERANCE)
    rows.append(dict(category=CATEGORY_TITLES["single"], measure="fitted parameter / truth (correct top findings)",
                     target="within 15 %",
                     measured=f"{pct(within, len(ratios))} within 15 %, median {median(ratios):.2f}" if ratios
                     else "no parameter compared",
                     met=("yes" if within == len(ratios) else "no") if ratios else "-"))
    return rows


def target_table(targets):
    out = ["## Targets and measured values\n", "| category | measure | target | measured | met |", "|---|---|---|---|---|"]
    for t in targets:
        met = "**no**" if t["met"] == "no" else t["met"]
        out.append(f"| {t['category']} | {t['measure']} | {t['target']} | {t['measured']} | {met} |")
    return out


def case_table(results, cases_info):
    out = ["## Per case\n", "Shares of the category's scored campaigns; several numbers are the measures in the order "
           "of the targets table (two: top / second; three: top / second / third; outside: not confident / wrong "
           "confident name; multi-oil: correct / oil_differences present).\n",
           "| case | heat path | single | two | three | outside | form | form + effect | multi-oil | null |",
           "|---|---|---|---|---|---|---|---|---|---|"]
    cases = sorted({r["truth"]["case"] for r in results}, key=list(CASES).index)
    spec = [("single", [0]), ("two", [0, 1]), ("three", [0, 1, 2]), ("outside", [0, 1]), ("form", [0]),
            ("form_effect", [0]), ("multi_oil", [0, 1]), ("null", [0])]
    for c in cases + [None]:
        cells = [_cell(results, cat, c, idx) for cat, idx in spec]
        out.append(f"| {c or '**all**'} | {cases_info.get(c, '') if c else ''} | " + " | ".join(cells) + " |")
    return out


def parameter_table(results):
    out = ["## Fitted parameters (correct single findings; factors compared by their departure from 1)\n",
           "| concealed effect | n | within 15 % | median fitted / true (range) |", "|---|---|---|---|"]
    for e in LIBRARY:
        ratios = [r["score"]["param_ratio"] for r in _scored(results, "single")
                  if r["truth"]["effects"][0]["name"] == e and r["score"]["param_ratio"] is not None]
        if ratios:
            w = sum(1 for x in ratios if abs(x - 1) <= PARAM_TOLERANCE)
            out.append(f"| {e} | {len(ratios)} | {pct(w, len(ratios))} | {median(ratios):.2f} "
                       f"({min(ratios):.2f}-{max(ratios):.2f}) |")
    return out


def failure_summary(results):
    out = ["## Failures (summary; every campaign in OUT/failures.md)\n",
           "| category | not correct | outcomes (count) | top findings naming none of the truths (count) |", "|---|---|---|---|"]
    for cat in CATEGORY_TITLES:
        rs = [r for r in _scored(results, cat) if not r["score"]["correct"]]
        if not _scored(results, cat):
            continue
        oc, nm = {}, {}
        for r in rs:
            oc[r["score"]["outcome"]] = oc.get(r["score"]["outcome"], 0) + 1
            if r["score"]["top"] and not r["score"].get("top_ok"):  # a name that is none of the truths
                nm[r["score"]["top"]] = nm.get(r["score"]["top"], 0) + 1
        top = lambda d: ", ".join(f"{k} {v}" for k, v in sorted(d.items(), key=lambda x: -x[1])[:6]) or "-"
        out.append(f"| {CATEGORY_TITLES[cat]} | {len(rs)} of {len(_scored(results, cat))} | {top(oc)} | {top(nm)} |")
    errs = [r for r in results if r.get("score", {}).get("outcome") == "error"]
    if errs:
        out.append(f"\n`diagnose` failed (non-zero exit, no JSON or timeout) in {len(errs)} campaigns, e.g. "
                   + "; ".join(f"{r['id']}: {r['score']['error'][:160]}" for r in errs[:3]))
    skipped = [r for r in results if "skipped" in r]
    if skipped:
        by = {}
        for r in skipped:
            by[r["truth"]["category"]] = by.get(r["truth"]["category"], 0) + 1
        out.append(f"\n{len(skipped)} planned campaigns were not built ("
                   + ", ".join(f"{CATEGORY_TITLES.get(k, k)} {v}" for k, v in by.items())
                   + "): effects not applicable to the case, too few points below 125 degC, an effect that shows on "
                     "its own less than the noise per point (loss and oil temperature), form changes under 3x the "
                     "noise; reasons in OUT/scores.md.")
    return out


def write_proof_doc(path, results, cases_info, run):
    n = sum(1 for r in results if "score" in r)
    dirty = " (with uncommitted changes)" if _git("status", "--porcelain") else ""
    head = [
        "# `gearloss diagnose`: proof on independently generated campaigns\n",
        f"Generated by `{run['command']}` on "
        f"{datetime.date.today().isoformat()}, this tree at commit `{_git('rev-parse', '--short', 'HEAD')}`{dirty}, "
        f"binary `{_version(run['binary'])}`: {n} campaigns diagnosed ({len(results) - n} planned ones not built) on "
        f"{len(run['cases'])} case variants ({', '.join(run['cases'])}), categories {', '.join(run['categories'])}, "
        f"in {run['seconds']:.0f} s. The detail of every campaign (recordings.csv, truth.json, diagnose.json, "
        f"scores.md, failures.md) is in the run's OUT directory (`{run['out']}` for this run), not here.\n",
        "The full proof is `scripts/prove-diagnosis.sh --seeds 3` (every shipped case variant, every category; it "
        "rewrites this file and exits 1 when a target is not met). `scripts/prove-diagnosis.sh --short` (ctest "
        "`prove_diagnosis_short`) runs a fixed set of 14 campaigns on the transfer gearbox (single, two, outside, "
        "form, null, the 3 x 3 synth campaign of issue 38, two outlier campaigns) and fails when a null campaign is not `no_significant_mismatch` or when fewer than the share "
        "stated in the script (85 %) of the others is correct.\n",
    ]
    targets = evaluate_targets(results)
    if run.get("quick"):
        head.append("**This run used `--quick`** (a few campaigns per category and case, one seed): its shares rest "
                    "on small counts and are a smoke test, not the proof. `scripts/prove-diagnosis.sh --seeds 3` "
                    "writes the proof's numbers here.\n")
    body = head + [TRUTH_TEXT, CATEGORY_TEXT] + target_table(targets) + [""] + case_table(results, cases_info) \
        + [""] + parameter_table(results) + [""] + summary_tables(results) + [""] + failure_summary(results)
    path.write_text("\n".join(body) + "\n")
    return targets
