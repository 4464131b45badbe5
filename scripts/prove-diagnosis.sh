#!/usr/bin/env bash
# Proof that `gearloss diagnose` finds concealed physics, on campaigns whose truth is made
# independently of the tool by scripts/independent-campaigns.py: the model part from the
# binary's fixed-temperature maps only, concealed effects in perturbed forms written in
# Python, the heat balance solved in Python, rig-like noise, drift and sensor artefacts
# (no `gearloss synth`). Categories: single, two, three, outside, form (+ form_effect),
# multi_oil, null; and issue 38's synth_own (campaigns made by `gearloss synth` itself: is a
# right answer said with confidence?), order (row order is not run order) and outliers
# (docs/diagnosis-proof.md and docs/diagnosis-independent.md explain them and their scoring).
# One category alone: scripts/independent-campaigns.py --only synth_own (or order, outliers, ...).
#
# Usage: scripts/prove-diagnosis.sh [--short] [--seeds N] [--binary PATH] [--out DIR] [--jobs N] [--reuse]
#   (full)   every shipped case variant x every category, N seeds (default 3); writes the
#            tables into docs/diagnosis-proof.md and every campaign's detail into OUT
#            (default out/prove-diagnosis: scores.md, failures.md, results.json, campaigns/);
#            exits 1 when a target of the document is not met.
#   --short  (ctest prove_diagnosis_short) a fixed set on the transfer gearbox, seed 0:
#            4 single, 1 pair, 2 outside the library, 2 model forms, 2 nulls, and from issue 38
#            the 3 x 3 `synth --effect mesh_friction=1.2` campaign at 1.5 % noise (synth seed 3:
#            no false lead, noise not underestimated, factor within 5 %) and two outlier campaigns
#            (1.5 % noise: no normal row listed; one row +20 %: listed) (14 campaigns, about
#            20 s on 2 cores with the maps). Fails (exit 1) when a null campaign is not
#            `no_significant_mismatch`, or when fewer than SHORT_MIN_SHARE of the other
#            campaigns are scored correct (single: correct top finding; two: both named in the
#            top two; outside: not named with confidence; form: the `<axis>:<form>` top
#            finding), or when fewer than SHORT_MIN_SCORED of them could be built and diagnosed.
#   --reuse  re-score OUT's diagnoses where the regenerated recordings are byte-identical.
set -euo pipefail
cd "$(dirname "$0")/.."

# The --short acceptance, stated here. 0.85 of the 12 non-null campaigns = 11 of 12 must be
# correct: at most one miss, in line with the targets (single >= 95 %, two >= 90 % both named,
# outside >= 85 %, form >= 85 %, synth_own >= 90 %, outliers every campaign); every null must be
# clean (target >= 97 %).
SHORT_MIN_SHARE=0.85
SHORT_MIN_SCORED=10

export PROVE_DIAGNOSIS_COMMAND="scripts/prove-diagnosis.sh${*:+ $*}"  # named in docs/diagnosis-proof.md
short=0
seeds=3
bin=build/app/gearloss
out=""
jobs=1
reuse=()
while [ $# -gt 0 ]; do
    case $1 in
        --short) short=1 ;;
        --seeds) seeds=$2; shift ;;
        --binary) bin=$2; shift ;;
        --out) out=$2; shift ;;
        --jobs) jobs=$2; shift ;;
        --reuse) reuse=(--reuse) ;;
        *) echo "unknown option $1" >&2; exit 1 ;;
    esac
    shift
done
if [ ! -x "$bin" ]; then
    scripts/install-deps.sh
    scripts/build.sh > /dev/null
fi

if [ "$short" = 1 ]; then
    keep=1
    if [ -z "$out" ]; then
        out=$(mktemp -d "${TMPDIR:-/tmp}/prove-diagnosis-short.XXXXXX")
        keep=0
    fi
    mkdir -p "$out"
    t0=$(date +%s)
    python3 scripts/independent-campaigns.py --binary "$bin" --quick --cases transfer --seeds 1 \
        --categories single,two,outside,form,null,synth_own,outliers --jobs "$jobs" --out "$out" "${reuse[@]}" > "$out/report.md"
    status=0
    python3 - "$out" "$SHORT_MIN_SHARE" "$SHORT_MIN_SCORED" "$(( $(date +%s) - t0 ))" <<'PY' || status=$?
import json, sys
out, min_share, min_scored, secs = sys.argv[1], float(sys.argv[2]), int(sys.argv[3]), sys.argv[4]
results = json.load(open(f"{out}/results.json"))
scored = [r for r in results if "score" in r]
nulls = [r for r in scored if r["truth"]["category"] == "null"]
others = [r for r in scored if r["truth"]["category"] != "null"]
print("| campaign | category | verdict | findings | outcome | correct |")
print("|---|---|---|---|---|---|")
for r in scored:
    s = r["score"]
    names = ", ".join(x for x in s["names"] if x) or "-"
    if s.get("error"):
        names = "error: " + s["error"][:120]
    print(f"| {r['id']} | {r['truth']['category']} | {s['verdict']} | {names} | {s['outcome']} | "
          f"{'yes' if s['correct'] else 'NO'} |")
for r in results:
    if "skipped" in r:
        print(f"| {r['id']} | {r['truth']['category']} | not built: {r['skipped']} | | skipped | - |")
ok_null = sum(r["score"]["correct"] for r in nulls)
ok = sum(r["score"]["correct"] for r in others)
share = ok / len(others) if others else 0.0
print()
print(f"null campaigns: {ok_null}/{len(nulls)} no_significant_mismatch (acceptance: all)")
print(f"other campaigns: {ok}/{len(others)} correct ({100 * share:.0f} %; acceptance >= {100 * min_share:.0f} % "
      f"of at least {min_scored} diagnosed)")
print(f"{len(scored)} campaigns in {secs} s")
passed = nulls and ok_null == len(nulls) and len(others) >= min_scored and share >= min_share
print("PASSED" if passed else "FAILED")
sys.exit(0 if passed else 1)
PY
    if [ "$status" != 0 ]; then
        echo; echo "campaigns not scored correct ($out/failures.md):"; cat "$out/failures.md"
    fi
    if [ "$keep" = 0 ]; then rm -rf "$out"; else echo "campaigns in $out"; fi
    exit "$status"
fi

out=${out:-out/prove-diagnosis}
mkdir -p "$out"
python3 scripts/independent-campaigns.py --binary "$bin" --seeds "$seeds" --jobs "$jobs" --out "$out" \
    --proof-doc docs/diagnosis-proof.md "${reuse[@]}" > "$out/report.md"
echo "tables in docs/diagnosis-proof.md; every campaign in $out (scores.md, failures.md, results.json)"
python3 - "$out" <<'PY'
import json, sys
targets = json.load(open(f"{sys.argv[1]}/targets.json"))
for t in targets:
    print(f"{t['category']}: {t['measure']}: {t['measured']} (target {t['target']}) -> {t['met']}")
missed = [t for t in targets if t["met"] == "no"]
print(f"{len(missed)} targets not met" if missed else "every target met")
sys.exit(1 if missed else 0)
PY
