#!/usr/bin/env python3
"""Independent blind campaigns for `gearloss diagnose`.

`gearloss synth` would synthesise recordings with the candidates' own forms and the tool's
own heat balance. This script makes its truth by another route, written here and nowhere
else (scripts/prove-diagnosis.sh runs it over every shipped case and category):

  * the MODEL part only: `gearloss map CASE --oil-temp T --detail` over a temperature
    grid (5..150 degC every 5 K), interpolated per point and per loss column (PCHIP);
  * concealed effects in PERTURBED forms written here (exponents, thresholds, speed
    dependences the library's candidates do not have), effects OUTSIDE the library,
    two and three effects at once, and null campaigns;
  * MODEL-FORM campaigns: the model part from the same case with another published form
    selected in a derived case (`mechanisms:`), built only when the change is >= 3x the
    loss noise; expected finding `<axis>:<form>`;
  * MULTI-OIL campaigns: 2-3 oils of one family on the same grid, a column `oil` naming
    each row's oil file, the model part per oil from a derived case with that `oil:`, and
    effects common to all oils or acting on one oil only (findings scoped by `"oil"`);
  * the steady oil temperature from a heat balance solved here, P_heat(T) = Q(T), with
    Q re-implemented from the case's `thermal.heat_rejection`: resistance, with the
    documented speed dependence R = R0 (n/n_ref)^-b above n_ref, or a textbook
    housing-surface model (+ the network's oil-housing conductance in series);
    fixed-temperature cases use their fixed temperature;
  * noise (1-3 % on loss, 0.3-0.5 K on temperature), optional ambient drift, sensor
    artefacts on the recorded torque, steady-point recordings in the CSV format of
    `gearloss diagnose` (P_loss_W, or output torque and speed);

then runs `gearloss diagnose CASE recordings.csv --json out.json` blind and scores the
verdict and findings against the truth. The diagnosis source is not read by this script
or its author: only README.md, docs/config.md, docs/diagnosis-proof.md, the shipped
configs and the --help texts.

Issue 38 added three categories that ask other questions: `synth_own` (campaigns made by
`gearloss synth` itself: is a right answer said with confidence, with and without a declared
uncertainty?), `order` (the same campaign sorted by speed, by torque and shuffled; a drift with a
`run` column) and `outliers` (1.5 % noise: no normal row listed; a planted +20 % row listed); and
the outside-library campaigns are also scored for the model of the remainder (outside_model.py).

Every shipped stabilised case uses the housing-surface model (some with a thermal
network), whose correlations are not documented. So most stabilised campaigns run on a
DERIVED case: the shipped gearbox with its `thermal` block replaced by a rig-measured
thermal resistance (`heat_rejection: resistance`, optionally speed-dependent), which this
script reproduces exactly (checked against the binary's stabilised map: <= 0.3 K). The
*_housing cases run the shipped files as they are, with the housing correlations that
README.md documents written here with the script's own air data; its heat flow is within
0.5 % of the binary's (--housing-check prints the comparison). Derived case files
are written to OUT/cases/ and are exactly what `diagnose` receives.

Usage:
  scripts/independent-campaigns.py [--binary build/app/gearloss] [--cases transfer,fzg]
        [--seeds N] [--quick] [--categories single,two,...] [--out DIR] [--jobs N] [--reuse]
        [--only CATEGORY|TAG|EFFECT[,..]] [--noise-scale F] [--no-pair-gate] [--check-pair-fit]
        [--housing-check] [--proof-doc FILE]
Outputs in OUT: scores.md (the tables), failures.md (every campaign not scored correct),
results.json, and per campaign recordings.csv (+ oils/ for multi-oil), truth.json,
diagnose.json, diagnose.txt. --proof-doc writes docs/diagnosis-proof.md's tables (proof_doc.py).
Deterministic for a given seed (Python's random seeded with strings); adding categories
does not change the recordings of the others.
"""
# The stages live in scripts/independent_campaigns/ (one module each, see its __init__.py);
# this file parses the arguments and runs them.
import argparse
import concurrent.futures
import json
import os
import sys
import tempfile
import time
from pathlib import Path

sys.dont_write_bytecode = True  # no __pycache__ left in scripts/
sys.path.insert(0, str(Path(__file__).resolve().parent))  # the package, from any working directory

from independent_campaigns import campaigns  # noqa: E402
from independent_campaigns.campaigns import CATEGORIES, build_campaign, plan, prepare_case  # noqa: E402
from independent_campaigns.cases import CASES, DEFAULT_CASES, ROOT  # noqa: E402
from independent_campaigns.heat_balance import housing_check  # noqa: E402
from independent_campaigns.multi_oil import build_multi_oil_campaign  # noqa: E402
from independent_campaigns.proof_doc import write_proof_doc  # noqa: E402
from independent_campaigns.robustness import build_robustness, plan_issue38  # noqa: E402
from independent_campaigns.synth_own import build_synth_campaign, build_synth_outlier  # noqa: E402
from independent_campaigns.scoring import run_diagnose, score  # noqa: E402
from independent_campaigns.tables import failures, tabulate  # noqa: E402


def command_line():
    """This run's command as typed, with paths inside the repository made relative to it."""
    words = [os.path.relpath(w, ROOT) if os.path.isabs(w) and w.startswith(str(ROOT) + os.sep) else w
             for w in sys.argv[1:]]
    own = "scripts/independent-campaigns.py " + " ".join(words)
    outer = os.environ.get("PROVE_DIAGNOSIS_COMMAND")  # set by scripts/prove-diagnosis.sh
    return f"{outer}` (`{own}" if outer else own


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--binary", default=str(ROOT / "build" / "app" / "gearloss"))
    ap.add_argument("--cases", default=None,
                    help="comma list of: " + ",".join(CASES) + " (default: all; with --quick: transfer)")
    ap.add_argument("--seeds", type=int, default=1)
    ap.add_argument("--quick", action="store_true", help="a few campaigns per category on the transfer gearbox (< 1 min)")
    ap.add_argument("--categories", default=",".join(CATEGORIES),
                    help="comma list of: " + ",".join(CATEGORIES) + " (default all; 'form' includes form_effect)")
    ap.add_argument("--out", default=None, help="keep campaigns, derived cases and maps here")
    ap.add_argument("--jobs", type=int, default=1, help="diagnose runs in parallel (default 1)")
    ap.add_argument("--reuse", action="store_true",
                    help="re-score: reuse OUT's diagnose.json where the regenerated recordings are byte-identical")
    ap.add_argument("--only", default=None,
                    help="comma list of categories, campaign tags or effect names to run (e.g. synth_own, order,outliers, "
                         "aero_drag,null0): only the cases those campaigns need are mapped")
    ap.add_argument("--proof-doc", default=None, help="also write the proof document (docs/diagnosis-proof.md) here")
    ap.add_argument("--noise-scale", type=float, default=1.0,
                    help="multiply the drawn loss and temperature noise (e.g. 0.1: which misses the noise causes)")
    ap.add_argument("--no-pair-gate", action="store_true",
                    help="build every pair that passes the single-effect noise gate, also those where one effect "
                         "hides behind the other refitted alone (independent_campaigns/identifiability.py)")
    ap.add_argument("--check-pair-fit", action="store_true",
                    help="check that fit on itself: each effect of a pair fitted alone to its own noise-free "
                         "recordings (truth.json: fit_check_chi2, near 0)")
    ap.add_argument("--housing-check", action="store_true",
                    help="compare the textbook housing model written here with the binary's stabilised map")
    args = ap.parse_args()
    binary = os.path.abspath(args.binary)
    if not os.access(binary, os.X_OK):
        sys.exit(f"no executable at {binary} (build with scripts/build.sh, or give --binary)")
    case_names = args.cases.split(",") if args.cases else (["transfer"] if args.quick else DEFAULT_CASES)
    if len(set(case_names)) != len(case_names):
        sys.exit("a case is listed twice in --cases")
    for c in case_names:
        if c not in CASES:
            sys.exit(f"unknown case {c}; known: {', '.join(CASES)}")
    categories = args.categories.split(",")
    if "form" in categories and "form_effect" not in categories:
        categories.append("form_effect")
    for c in categories:
        if c not in CATEGORIES:
            sys.exit(f"unknown category {c}; known: {', '.join(CATEGORIES)}")
    if not 0 < args.noise_scale <= 10:
        sys.exit("--noise-scale must be in (0, 10]")
    if args.noise_scale != 1 and args.proof_doc:
        sys.exit("--proof-doc reports the proof's own noise levels: not with --noise-scale")
    campaigns.NOISE_SCALE = args.noise_scale
    campaigns.PAIR_GATE = not args.no_pair_gate
    campaigns.CHECK_PAIR_FIT = args.check_pair_fit
    out = Path(args.out) if args.out else Path(tempfile.mkdtemp(prefix="indep-camp-"))
    out.mkdir(parents=True, exist_ok=True)
    log = lambda s: print(s, file=sys.stderr, flush=True)
    t_start = time.time()

    if args.housing_check:
        housing_check(binary, case_names, out, log)
        return

    specs = plan(case_names, args.seeds, args.quick, categories) \
        + plan_issue38(case_names, args.seeds, args.quick, categories)
    if args.only:
        keep = set(args.only.split(","))
        specs = [s for s in specs if s["tag"] in keep or s["category"] in keep or any(e in keep for e in s["effects"])
                 or s.get("synth_effect") in keep]
    if not specs:
        sys.exit("no campaign planned (check --only / --categories)")
    # the model tables are mapped only for the cases a planned campaign needs (synth_own needs none)
    cases = {cname: prepare_case(binary, cname, out, log) for cname in case_names
             if any(s["case"] == cname and s["category"] != "synth_own" and not s.get("synth") for s in specs)}
    results, pending = [], []
    for s in specs:
        cid = f"{s['case']}/s{s['seed']}/{s['tag']}"
        cdir = out / "campaigns" / s["case"] / f"s{s['seed']}" / s["tag"]
        c = cases.get(s["case"])
        if s["category"] == "synth_own":
            truth, why = build_synth_campaign(s, binary, cdir)
        elif s.get("synth"):  # outliers made by synth
            truth, why = build_synth_outlier(s, binary, cdir)
        elif s["category"] in ("order", "outliers"):
            truth, why = build_robustness(s, c, cdir)
        elif s["category"] == "multi_oil":
            truth, why = build_multi_oil_campaign(s, c, cdir)
        elif "form" in s:
            model, why = c.form_table(*s["form"])
            truth, why = build_campaign(s, model, c.oil, c.heat, c.ambient, cdir, case_model=c.model) \
                if model else (None, f"form {s['form'][0]}:{s['form'][1]}: {why}")
        else:
            truth, why = build_campaign(s, c.model, c.oil, c.heat, c.ambient, cdir)
        if truth is None:
            log(f"  skip {cid}: {why}")
            results.append({"id": cid, "skipped": why, "truth": {"category": s["category"], "case": s["case"]}})
            continue
        pending.append((cid, s, truth, cdir))

    def diagnose(s, truth, cdir):
        if args.reuse and truth["recordings_unchanged"] and (cdir / "diagnose.json").exists():
            return json.loads((cdir / "diagnose.json").read_text()), 0.0
        config = ROOT / truth["config"] if "config" in truth else cases[s["case"]].config  # synth_own: as shipped
        return run_diagnose(binary, config, cdir, truth.get("diagnose_args", []))

    def work(item):
        cid, s, truth, cdir = item
        if truth.get("runs"):  # one campaign written several ways (order): each file diagnosed
            runs = [diagnose(s, truth, cdir / sub) for sub in truth["runs"]]
            diag, dt = [d for d, _ in runs], sum(t for _, t in runs)
            summary = " || ".join((d.get("summary") or "")[:130] for d in diag)
        else:
            diag, dt = diagnose(s, truth, cdir)
            summary = diag.get("summary") or ""
        sc = score(truth, diag)
        return {"id": cid, "truth": {k: v for k, v in truth.items() if k != "rows"}, "score": sc, "seconds": dt,
                "reused": dt == 0.0,
                "summary": summary[:400]}

    with concurrent.futures.ThreadPoolExecutor(max_workers=max(1, args.jobs)) as ex:
        for k, res in enumerate(ex.map(work, pending)):
            sc = res["score"]
            log(f"  [{k + 1}/{len(pending)}] {res['id']}: {sc['verdict']} top={sc['top']} 2nd={sc['second']} "
                f"-> {sc['outcome']} ({res['seconds']:.1f} s)")
            results.append(res)
    table = tabulate(results, {cname: c.info for cname, c in cases.items()})
    skipped = [r for r in results if "skipped" in r]
    reused = sum(1 for r in results if r.get("reused"))
    header = (f"{len(pending)} campaigns diagnosed ({len(skipped)} skipped) on {', '.join(case_names)}, "
              f"seeds {args.seeds}, in {time.time() - t_start:.0f} s"
              + (f" ({reused} diagnoses reused from an earlier run with byte-identical recordings)" if reused else "")
              + f"; campaigns in {out}")
    print(header + "\n\n" + table)
    (out / "results.json").write_text(json.dumps(results, indent=1, default=str))
    (out / "scores.md").write_text(header + "\n\n" + table + "\n")
    (out / "failures.md").write_text(failures(results) + "\n")
    if args.proof_doc:
        targets = write_proof_doc(Path(args.proof_doc), results, {cname: c.info for cname, c in cases.items()},
                                  dict(seeds=args.seeds, cases=case_names, categories=categories, out=str(out),
                                       seconds=time.time() - t_start, binary=binary, command=command_line(),
                                       quick=args.quick))
        (out / "targets.json").write_text(json.dumps(targets, indent=1))


if __name__ == "__main__":
    main()
