"""The tables of scores.md, the list of failures.md, and the measures the proof document uses.

measures gives each category's headline numbers (the ones docs/diagnosis-proof.md sets targets
for); tabulate writes every table of scores.md (per category, per case, per effect, per form,
per multi-oil kind, the campaign conditions, the skips); failures lists every campaign not
scored correct with its truth and what `diagnose` said.
"""
from .cases import CASES
from .effects import ACCEPT, LIBRARY, OUTSIDE
from .numerics import median
from .scoring import FAMILY

CATEGORY_TITLES = {
    "single": "single in-library effect", "two": "two effects", "three": "three effects",
    "outside": "outside the library", "form": "model form", "form_effect": "model form + small effect",
    "multi_oil": "multi-oil", "null": "null",
    "synth_own": "synth's own heat path", "order": "row order", "outliers": "outliers",
}


def snr(truth):
    a = truth.get("size_loss_rel", 0.0) / truth.get("noise_loss", 1.0)
    b = truth.get("size_temp_rms_K", 0.0) / truth.get("noise_temp_K", 1.0)
    return max(a, b)


def failures(results):
    """Every campaign not scored correct, with its truth and what diagnose said (for inspection)."""
    out = ["| campaign | truth | size loss / temp. | verdict | findings | summary |", "|---|---|---|---|---|---|"]
    for r in results:
        if "score" not in r or (r["score"]["correct"] and r["score"]["outcome"] != "correct_top_not_confident"):
            continue
        t = r["truth"]
        eff = "; ".join(e["name"] + (f" [oil {e['oil'] or 'all'}]" if "oil" in e else "") + " "
                        + ", ".join(f"{k}={v:.4g}" if isinstance(v, float) else f"{k}={v}"
                                    for k, v in e["params"].items()) for e in t["effects"])
        if "form" in t:
            eff = f"form {t['form']['expected']} ({100 * t['form']['mean_abs_rel_change_at_null']:.1f} %)" \
                + ("; " + eff if eff else "")
        if "oils" in t:
            eff = "oils " + ", ".join(o["name"] for o in t["oils"]) + "; " + (eff or "none")
        eff = eff or "none"
        fit = r["score"]["fitted"]
        fnd = ", ".join(x for x in r["score"]["names"] if x) or "-"
        if r["score"].get("scopes"):
            fnd += "; oil scopes " + ", ".join(f"{s['effect']}: {s['given']}" for s in r["score"]["scopes"])
        if r["score"].get("error"):
            fnd = "error: " + r["score"]["error"][:200]
        if fit and fit[0]:
            fnd += f" ({fit[0]} = {fit[1]:.4g})"
        out.append(f"| {r['id']} | {eff} | {100 * t.get('size_loss_rel', 0):.1f} % / {t.get('size_temp_rms_K', 0):.1f} K | "
                   f"{r['score']['verdict']} ({r['score']['outcome']}) | {fnd} | {r.get('summary', '').replace('|', '/')[:300]} |")
    return "\n".join(out)


def pct(a, b):
    return f"{a}/{b} ({100 * a / b:.1f} %)" if b else "-"  # one decimal: 54/57 is 94.7 %, under a 95 % target


def by_case(rs):
    """[(label, campaigns)]: per case in the order of CASES, then all of them."""
    cases = sorted({r["truth"]["case"] for r in rs}, key=list(CASES).index)
    return [(c, [r for r in rs if r["truth"]["case"] == c]) for c in cases] + [("**all**", rs)]


def per_case_table(title, rs, columns):
    """Lines of a table with a row per case and one for all: columns = [(header, cell(campaigns))]."""
    out = [f"\n## {title}\n"] if title else [""]
    out += ["| case | n | " + " | ".join(h for h, _ in columns) + " |", "|---|---|" + "---|" * len(columns)]
    for c, sub in by_case(rs):
        out.append(f"| {c} | {len(sub)} | " + " | ".join(str(cell(sub)) for _, cell in columns) + " |")
    return out


def count(*outcomes):
    return lambda rs: sum(1 for r in rs if r["score"]["outcome"] in outcomes)


def share(pred):
    return lambda rs: pct(sum(1 for r in rs if pred(r["score"])), len(rs))


def measures(rs, cat):
    """[(label, count, n)]: a category's headline numbers over its scored campaigns rs."""
    n = len(rs)
    c = lambda pred: sum(1 for r in rs if pred(r["score"]))
    o = lambda *names: c(lambda s: s["outcome"] in names)
    if cat == "single":
        return [("correct top finding (any verdict)", o("correct_top", "correct_top_not_confident"), n),
                ("correct top finding, verdict missing_physics", o("correct_top"), n)]
    if cat == "two":
        shown = [r for r in rs if not r["score"].get("pair_hidden")]
        return [("top finding is a truth", c(lambda s: s.get("top_ok")), n),
                ("both named in the top two (second)", o("both_named"), n),
                ("both named where each effect shows beside the other refitted alone (second, shown)",
                 sum(1 for r in shown if r["score"]["outcome"] == "both_named"), len(shown))]
    if cat == "three":
        return [("top finding is a truth", c(lambda s: s.get("top_ok")), n),
                ("at least two named (second)", c(lambda s: s.get("named", 0) >= 2), n),
                ("all three named (third)", o("all_three_named"), n)]
    if cat == "outside":
        return [("not confident (unexplained / partly explained)", o("correct_not_confident"), n),
                ("wrong confident library name", o("wrong_confident_name"), n),
                ("final model cross-validated residual <= 1.5 x true noise", c(lambda s: s.get("final_ok")), n),
                ("form recovered by the remainder formula", c(lambda s: s.get("form_ok")), n),
                ("remainder formula present", c(lambda s: s.get("formula")), n)]
    if cat == "synth_own":
        one = [r for r in rs if r["truth"].get("kind") != "mesh3x3"]
        m3 = [r for r in rs if r["truth"].get("kind") == "mesh3x3"]
        k = lambda sub, pred: sum(1 for r in sub if pred(r))
        dec = [r for r in one if r["truth"].get("declared")]
        est = [r for r in one if not r["truth"].get("declared")]
        return [("right top finding with missing_physics", k(one, lambda r: r["score"]["correct"]), len(one)),
                ("same, noise estimated (no declared uncertainty)", k(est, lambda r: r["score"]["correct"]), len(est)),
                ("same, --loss-uncertainty declared", k(dec, lambda r: r["score"]["correct"]), len(dec)),
                ("right top finding (any verdict)", k(one, lambda r: r["score"].get("top_ok")), len(one)),
                ("3x3 mesh_friction=1.2: no false lead, noise >= floor, factor within 5 %",
                 k(m3, lambda r: r["score"]["correct"]), len(m3))]
    if cat == "order":
        tri = [r for r in rs if r["truth"].get("kind") == "orderings"]
        dr = [r for r in rs if r["truth"].get("kind") == "drift"]
        k = lambda sub, pred: sum(1 for r in sub if pred(r["score"]))
        return [("three orderings: same verdict and top finding", k(tri, lambda x: x.get("identical")), len(tri)),
                ("three orderings: no drift / running-in hypothesis", k(tri, lambda x: x.get("no_order_hypothesis")),
                 len(tri)),
                ("three orderings: run_order.recorded false in the JSON", k(tri, lambda x: x.get("recorded_false")),
                 len(tri)),
                ("`run` column with a true drift: drift named", k(dr, lambda x: x.get("drift_named")), len(dr))]
    if cat == "outliers":
        cl = [r for r in rs if r["truth"].get("kind") == "clean"]
        pl = [r for r in rs if r["truth"].get("kind") == "planted"]
        sy = [r for r in rs if r["truth"].get("synth")]
        return [("no row within 2.5 x the noise listed", c(lambda s: not s.get("false_outliers")), n),
                ("campaigns without an outlier: none listed within 2.5 x the noise",
                 sum(1 for r in cl if not r["score"].get("false_outliers")), len(cl)),
                ("planted +20 % row listed", sum(1 for r in pl if r["score"].get("planted_listed")), len(pl)),
                ("made by synth (3 x 3, 4 x 4): none listed within 2.5 x the noise",
                 sum(1 for r in sy if not r["score"].get("false_outliers")), len(sy))]
    if cat == "form":
        return [("correct form (top finding)", o("correct"), n),
                ("form named among the top finding's equivalents", o("named_among_equivalents"), n)]
    if cat == "form_effect":
        return [("form and effect in the top two findings", o("correct"), n)]
    if cat == "multi_oil":
        return [("every truth named with the right oil scope", o("correct"), n),
                ("top-level oil_differences present", c(lambda s: s.get("oil_differences")), n)]
    return [("no_significant_mismatch", o("correct"), n)]


def summary_tables(results):
    """The categories at a glance, and the campaign conditions each category covers."""
    out = ["## Campaigns per category\n", "| category | planned | skipped | diagnosed | diagnose failed | headline numbers |",
           "|---|---|---|---|---|---|"]
    cats = [c for c in CATEGORY_TITLES if any(r["truth"]["category"] == c for r in results)]
    for cat in cats:
        allr = [r for r in results if r["truth"]["category"] == cat]
        rs = [r for r in allr if "score" in r]
        err = sum(1 for r in rs if r["score"]["outcome"] == "error")
        head = "; ".join(f"{lab} {pct(k, n)}" for lab, k, n in measures(rs, cat)) if rs else "-"
        out.append(f"| {CATEGORY_TITLES[cat]} | {len(allr)} | {len(allr) - len(rs)} | {len(rs)} | {err} | {head} |")
    out += ["\n## Campaign conditions per category (count, and in parentheses how many were scored correct)\n",
            "Points per campaign (per oil for multi-oil campaigns): 9 is a rig's 3 speeds x 3 torques. Ambient drift: "
            "the ambient moves by up to +-4 K over the campaign. Loss noise 1-3 % (one standard deviation).\n",
            "| category | n | 9 points | 10-19 points | 20-30 points | ambient drift | no drift | loss noise 1-2 % | "
            "loss noise 2-3 % | output torque + speed recorded |", "|---|---|---|---|---|---|---|---|---|---|"]
    for cat in cats:
        rs = [r for r in results if r["truth"]["category"] == cat and "score" in r]
        if not rs:
            continue

        def cell(pred):
            sel = [r for r in rs if pred(r["truth"])]
            return f"{len(sel)} ({sum(1 for r in sel if r['score']['correct'])})"
        npts = lambda t: min(t["points_per_oil"].values()) if "points_per_oil" in t else t["points"]
        out.append(f"| {CATEGORY_TITLES[cat]} | {len(rs)} | {cell(lambda t: npts(t) == 9)} | "
                   f"{cell(lambda t: 10 <= npts(t) <= 19)} | {cell(lambda t: npts(t) >= 20)} | "
                   f"{cell(lambda t: t['ambient_drift_K'] != 0)} | {cell(lambda t: t['ambient_drift_K'] == 0)} | "
                   f"{cell(lambda t: t['noise_loss'] < 0.02)} | {cell(lambda t: t['noise_loss'] >= 0.02)} | "
                   f"{cell(lambda t: t['format'] == 'torques')} |")
    return out


def single_tables(single, cases_info):
    out = []
    p = out.append
    p("\n## Single in-library effect (perturbed form), per case\n")
    p("| case | heat path | n | correct top (confident) | correct top, verdict not confident | in 2nd finding / equivalent | wrong name | not named | missed (no mismatch) |")
    p("|---|---|---|---|---|---|---|---|---|")
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
    return out


def tabulate(results, cases_info):
    out = summary_tables(results)
    p = out.append
    by = lambda cat: [r for r in results if r["truth"]["category"] == cat and "score" in r]
    single = by("single")
    if single:
        out += single_tables(single, cases_info)
    two = by("two")
    if two:
        p("\n## Two effects at once\n")
        p("| n | top finding is a truth | both named (top two findings) | pairs with both shown: both named | one named as top | one named second only | wrong top name | not named | missed | diagnose failed |")
        p("|---|---|---|---|---|---|---|---|---|---|")
        cnt = lambda o: sum(1 for r in two if r["score"]["outcome"] == o)
        shown = [r for r in two if not r["score"].get("pair_hidden")]
        p(f"| {len(two)} | {pct(sum(1 for r in two if r['score'].get('top_ok')), len(two))} | "
          f"{pct(cnt('both_named'), len(two))} | "
          f"{pct(sum(1 for r in shown if r['score']['outcome'] == 'both_named'), len(shown))} | "
          f"{cnt('one_named_top')} | {cnt('one_named_second')} | "
          f"{cnt('wrong_name')} | {cnt('not_confident_unnamed')} | {cnt('missed')} | {cnt('error')} |")
        hidden = [r for r in two if r["score"].get("pair_hidden")]
        if hidden:
            p(f"\n{len(hidden)} pair(s) where one effect hides behind the other refitted alone (its own family, "
              "identifiability.py): the recordings hardly show both; the figure over the pairs with both shown leaves them out:\n")
            for r in hidden:
                p(f"- {r['truth']['case']}/s{r['truth']['seed']}/{r['truth']['tag']}: {r['truth']['pair_hidden']}; "
                  f"findings {', '.join(str(x) for x in r['score']['names'][:2]) or 'none'}")
    out += per_case_table("Three effects at once (4-8 % each)", by("three"), [
        ("top finding is a truth", share(lambda x: x.get("top_ok"))),
        ("at least two named (second)", share(lambda x: x.get("named", 0) >= 2)),
        ("all three named (third)", share(lambda x: x["outcome"] == "all_three_named")),
        ("wrong top name", count("wrong_name")), ("not named", count("not_confident_unnamed")),
        ("missed", count("missed")), ("diagnose failed", count("error"))]) if by("three") else []
    p("\n## By heat path (resistance: exact re-implementation; housing: textbook, within ~2 %; fixed: no temperature evidence)\n")
    p("| heat path | single: correct top | two: both named | three: all named | outside: correct (not confident) | form: correct | multi-oil: correct | null: correct |")
    p("|---|---|---|---|---|---|---|---|")
    for hk in ["resistance", "housing", "fixed"]:
        cells = []
        for cat, good in [("single", ("correct_top", "correct_top_not_confident")), ("two", ("both_named",)),
                          ("three", ("all_three_named",)), ("outside", ("correct_not_confident",)),
                          ("form", ("correct",)), ("multi_oil", ("correct",)), ("null", ("correct",))]:
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
    out += issue38_tables(by("outside"), by("synth_own"), by("order"), by("outliers"))
    out += per_case_table("Null campaigns (correct = no_significant_mismatch)", by("null"), [
        ("correct", share(lambda x: x["outcome"] == "correct")), ("false alarm with a name", count("false_alarm_named")),
        ("false alarm without a name", count("false_alarm_unexplained")),
        ("diagnose failed", count("error"))]) if by("null") else []
    out += form_tables(by("form"), by("form_effect")) + multi_oil_tables(by("multi_oil")) + skip_table(results)
    errs = [r for r in results if r.get("score", {}).get("error")]
    if errs:
        p(f"\n{len(errs)} campaigns where diagnose failed (scored `error`, never correct): "
          + "; ".join(f"{r['id']}: {r['score']['error'][:120]}" for r in errs[:5]))
    p("\n## Acceptance mapping used (perturbed effect -> acceptable library names)\n")
    for e in LIBRARY + OUTSIDE + ["oil_visc_factor", "oil_mesh_friction"]:
        p(f"- `{e}` -> {', '.join('`' + x + '`' for x in sorted(ACCEPT[e])) if ACCEPT[e] else 'none: a non-confident verdict (anything but missing_physics with a name, and not no_significant_mismatch)'}"
          + (" (scoped to its oil)" if e.startswith("oil_") else ""))
    p("- form campaigns -> the id `<axis>:<form>` (`friction:`, `loss_factor:`, `film_correction:`, `windage:`) "
      "as the top finding; multi-oil common effects -> the names above with `\"oil\": null`")
    return "\n".join(out)


def form_tables(form, form_effect):
    out = []
    if form:
        out += ["\n## Model form (truth: the same case with another published form; expected top finding `<axis>:<form>`)\n",
                "| expected | n | correct (top finding) | among the top finding's equivalents | named, not top | "
                "another form | another name | not named | missed | diagnose failed | median change / noise |",
                "|---|---|---|---|---|---|---|---|---|---|---|"]
        for exp in sorted({r["truth"]["form"]["expected"] for r in form}) + ["all"]:
            rs = form if exp == "all" else [r for r in form if r["truth"]["form"]["expected"] == exp]
            cnt = lambda o: sum(1 for r in rs if r["score"]["outcome"] == o)
            ratio = median(r["truth"]["form"]["mean_abs_rel_change_at_null"] / r["truth"]["noise_loss"] for r in rs)
            out.append(f"| {'**all**' if exp == 'all' else '`' + exp + '`'} | {len(rs)} | {pct(cnt('correct'), len(rs))} | "
                       f"{cnt('named_among_equivalents')} | {cnt('form_not_top')} | {cnt('wrong_form')} | "
                       f"{cnt('wrong_name')} | {cnt('not_named')} | {cnt('missed')} | {cnt('error')} | {ratio:.1f} |")
        out += per_case_table(None, form, [("correct form", share(lambda x: x["correct"]))])
    if form_effect:
        out += ["\n## Model form + a small in-library effect (4-6 %)\n",
                "| n | form and effect in the top two | form only | effect only | form among equivalents | "
                "another name | not named | missed | diagnose failed |", "|---|---|---|---|---|---|---|---|---|"]
        cnt = lambda o: sum(1 for r in form_effect if r["score"]["outcome"] == o)
        out.append(f"| {len(form_effect)} | {pct(cnt('correct'), len(form_effect))} | {cnt('form_only')} | "
                   f"{cnt('effect_only')} | {cnt('form_among_equivalents')} | {cnt('wrong_name')} | "
                   f"{cnt('not_named')} | {cnt('missed')} | {cnt('error')} |")
    return out


def multi_oil_tables(multi):
    if not multi:
        return []
    out = ["\n## Multi-oil campaigns (2-3 oils of one family, column `oil`; correct = every truth named with the right "
           "oil scope)\n",
           "| truth | n | correct | all named, a scope wrong or missing | partly named | another name | not named | "
           "missed | diagnose failed | oil_differences present |", "|---|---|---|---|---|---|---|---|---|---|"]
    for kind in ["common", "per_oil", "both", "all"]:
        rs = multi if kind == "all" else [r for r in multi if r["truth"]["kind"] == kind]
        if not rs:
            continue
        cnt = lambda o: sum(1 for r in rs if r["score"]["outcome"] == o)
        out.append(f"| {'**all**' if kind == 'all' else kind} | {len(rs)} | {pct(cnt('correct'), len(rs))} | "
                   f"{cnt('named_wrong_scope')} | {cnt('partly_named')} | {cnt('wrong_name')} | {cnt('not_named')} | "
                   f"{cnt('missed')} | {cnt('error')} | {sum(1 for r in rs if r['score'].get('oil_differences'))} |")
    per = {}
    for r in multi:
        for s in r["score"].get("scopes", []):
            k = (s["effect"], "common" if s["expected_oil"] is None else "one oil")
            per.setdefault(k, [0, 0])
            per[k][1] += 1
            per[k][0] += s["status"] == "right"
    if per:
        out += ["\n| truth effect | scope | n | named with the right scope |", "|---|---|---|---|"]
        for (e, sc), (k, n) in sorted(per.items()):
            out.append(f"| {e} | {sc} | {n} | {pct(k, n)} |")
    return out


def skip_table(results):
    skipped = [r for r in results if "skipped" in r]
    if not skipped:
        return []
    reasons = {}
    for r in skipped:
        why = r["skipped"]
        key = (r["truth"]["category"], why.split(": mean")[0] if why.startswith("form change") else why.split(" (")[0])
        reasons.setdefault(key, []).append(r["id"])
    out = ["\n## Skipped campaigns (not built: the reason, how many, examples)\n", "| category | reason | n | examples |",
           "|---|---|---|---|"]
    for (cat, why), ids in sorted(reasons.items()):
        out.append(f"| {CATEGORY_TITLES.get(cat, cat)} | {why} | {len(ids)} | {', '.join(ids[:3])} |")
    return out


def issue38_tables(outside, own, order, outl):
    """Outside: modelled and form recovered per effect; synth_own per effect; order and outliers per campaign."""
    out = []
    if outside:
        out += ["\n## Outside the library: the final model and the recovered form (issue 38)\n",
                "final = cross-validated loss residual of library findings + remainder formula over the TRUE loss noise "
                "(the report's own ratio in parentheses where given); form = the remainder formula's term recovers the "
                "effect's shape (scripts/independent_campaigns/outside_model.py).\n",
                "| effect | n | final <= 1.5 x noise | form recovered | formula present | median final / noise |",
                "|---|---|---|---|---|---|"]
        for e in OUTSIDE + ["all"]:
            rs = outside if e == "all" else [r for r in outside if r["truth"]["effects"][0]["name"] == e]
            if not rs:
                continue
            k = lambda key: sum(1 for r in rs if r["score"].get(key))
            fin = [r["score"]["final_over_true_noise"] for r in rs if r["score"].get("final_over_true_noise") is not None]
            out.append(f"| {'**all**' if e == 'all' else e} | {len(rs)} | {pct(k('final_ok'), len(rs))} | "
                       f"{pct(k('form_ok'), len(rs))} | {k('formula')} | {f'{median(fin):.2f}' if fin else '-'} |")
    if own:
        out += ["\n## synth's own heat path (correct = right top finding AND missing_physics)\n",
                "| effect | n | correct, noise estimated | correct, declared | right top (any verdict) | verdicts given |",
                "|---|---|---|---|---|---|"]
        for e in sorted({r["truth"]["synth_effect"] for r in own if r["truth"]["kind"] != "mesh3x3"}) + ["all"]:
            rs = [r for r in own if r["truth"]["kind"] != "mesh3x3" and (e == "all" or r["truth"]["synth_effect"] == e)]
            est = [r for r in rs if not r["truth"]["declared"]]
            dec = [r for r in rs if r["truth"]["declared"]]
            ok = lambda sub: pct(sum(1 for r in sub if r["score"]["correct"]), len(sub))
            verdicts = {}
            for r in rs:
                verdicts[r["score"]["verdict"]] = verdicts.get(r["score"]["verdict"], 0) + 1
            out.append(f"| {'**all**' if e == 'all' else e} | {len(rs)} | {ok(est)} | {ok(dec)} | "
                       f"{pct(sum(1 for r in rs if r['score'].get('top_ok')), len(rs))} | "
                       f"{', '.join(f'{k} {v}' for k, v in sorted(verdicts.items()))} |")
        m3 = [r for r in own if r["truth"]["kind"] == "mesh3x3"]
        if m3:
            out += ["\n| 3 x 3 mesh_friction=1.2, 1.5 % (synth seed) | verdict | top | factor | loss noise used | false lead | correct |",
                    "|---|---|---|---|---|---|---|"]
            for r in m3:
                s = r["score"]
                f = s["fitted"][1] if s.get("top_ok") and s["fitted"] else None
                ftxt = "-" if f is None else f"{f:.4f}"
                ntxt = "-" if s.get("noise_used") is None else f"{100 * s['noise_used']:.2f} %"
                out.append(f"| {r['id']} | {s['verdict']} | {s['top']} | {ftxt} | {ntxt} | "
                           f"{'yes' if s.get('false_lead') else 'no'} | {'yes' if s['correct'] else 'no'} |")
    if order:
        out += ["\n## Row order (three orderings without a run column; a true drift with a `run` column)\n",
                "| campaign | kind | per ordering: verdict/top | outcome | structure test along row order |",
                "|---|---|---|---|---|"]
        for r in order:
            s = r["score"]
            out.append(f"| {r['id']} | {r['truth']['kind']} | {'; '.join(s.get('per_ordering', [s['verdict']]))} | "
                       f"{s['outcome']} | {s.get('structure_along_row_order', '-')} |")
    if outl:
        out += ["\n## Outliers (1.5 % loss noise; true noise draws known)\n",
                "| campaign | listed rows | normal rows listed (abs(z) < 2.5) | planted row | outcome |", "|---|---|---|---|---|"]
        for r in outl:
            s = r["score"]
            out.append(f"| {r['id']} | {s.get('listed')} | {s.get('false_outliers')} | "
                       f"{r['truth'].get('planted_row') or '-'} | {s['outcome']} |")
    return out
