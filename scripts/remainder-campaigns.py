#!/usr/bin/env python3
"""Campaigns with an effect outside the diagnosis' library, and how well the remainder formula
models it (the measurement behind docs/diagnose.md, "The remainder formula").

Each campaign: a case, a loss law the library has no candidate for (a step in oil temperature,
a load threshold, a speed power gated by the oil temperature, a resonance window, ...) written
as an empirical calibration term, `gearloss synth` of the case with it (the coupled model: the
extra loss heats the oil), then `gearloss diagnose` of the case without it. Reported per
campaign and in total:
  - final: the cross-validated loss residual of the final model (findings + formula) over the
    noise (1.5 % of the loss, as synthesised), <= 1.5 counts;
  - formula: whether a remainder formula is reported;
  - form: whether its first term has the effect's form (step or threshold within one grid
    step of the recorded values, exponent within +-0.3).

Usage: scripts/remainder-campaigns.py GEARLOSS [--synth GEARLOSS_NEW] [--seeds 2] [--out DIR]
(GEARLOSS diagnoses; the synthesis needs a gearloss that knows the empirical term.)
"""
import argparse, csv, json, math, os, subprocess, sys, tempfile

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
NOISE = 0.015

# Cases and the grid each is recorded on.
CASES = {
    "fzg": ("configs/fzg-c40-paor.yaml", "500,1000,1500,2000,2500,3000rpm", "70,132.5,215.5,319.2Nm"),
    "spur": ("configs/spur-seed000.yaml", "400,800,1200,1600rpm", "200,400,600,720,800Nm"),
    "transfer": ("configs/transfer-box.yaml", "500,600,700,800,900rpm", "100,150,200,250Nm"),
}


def run(cmd):
    r = subprocess.run(cmd, capture_output=True, text=True)
    if r.returncode != 0:
        raise RuntimeError(" ".join(cmd) + "\n" + r.stderr[-2000:])
    return r.stdout


def truth_config(base, terms_yaml, out):
    text = open(os.path.join(ROOT, base)).read()
    oil_dir = os.path.join(ROOT, os.path.dirname(base))
    lines = []
    for line in text.splitlines():
        if line.startswith("oil:"):
            rel = line.split(":", 1)[1].split("#")[0].strip()
            line = "oil: " + os.path.join(oil_dir, rel)
        lines.append(line)
    text = "\n".join(lines) + "\ncalibration:\n  empirical:\n    terms:\n" + terms_yaml
    open(out, "w").write(text)


def read_csv(path):
    with open(path) as f:
        return list(csv.DictReader(f))


def levels(values, rel):
    """Sorted distinct levels (values within 1 % merged), as the library forms them."""
    v = sorted(values)
    out = [v[0]]
    span = v[-1] - v[0]
    for x in v[1:]:
        tol = 0.01 * max(abs(x), abs(out[-1])) if rel else 0.01 * span
        if x - out[-1] > tol:
            out.append(x)
    return out


def within_one_step(found, truth, lv):
    """The truth lies between two adjacent levels; found is within one level step of that gap."""
    below = [x for x in lv if x < truth]
    above = [x for x in lv if x >= truth]
    lo = below[-2] if len(below) >= 2 else (below[-1] if below else lv[0])
    hi = above[1] if len(above) >= 2 else (above[0] if above else lv[-1])
    return lo <= found <= hi


def effects(baseline):
    """Outside-library laws for one case, sized against its losses and placed within its
    recorded ranges (from the noiseless baseline campaign)."""
    loss = sorted(float(r["P_loss_W"]) for r in baseline)
    temp = sorted(float(r["oil_temp_C"]) for r in baseline)
    speeds = levels([float(r["speed_in_rpm"]) for r in baseline], True)
    torques = levels([float(r["torque_in_Nm"]) for r in baseline], True)
    L = loss[len(loss) // 2]
    t_mid = 0.5 * (temp[len(temp) // 2 - 1] + temp[len(temp) // 2])
    t_lo = 0.5 * (temp[len(temp) // 3 - 1] + temp[len(temp) // 3])
    n_mid = 0.5 * (speeds[len(speeds) // 2 - 1] + speeds[len(speeds) // 2])
    T_mid = 0.5 * (torques[len(torques) // 2 - 1] + torques[len(torques) // 2])
    n_win = speeds[len(speeds) // 2]
    win_lo = 0.5 * (speeds[len(speeds) // 2 - 1] + n_win)
    win_hi = 0.5 * (n_win + speeds[len(speeds) // 2 + 1])
    Tmax = torques[-1]
    c = 0.15 * L
    f = lambda s: "      - " + s + "\n"
    return [
        ("hot_oil_step", f(f"{{coefficient: {c:.4g} W, factors: [{{variable: oil_temperature, shape: step, above: {t_mid:.4g} degC}}]}}"),
         {"shape": "step", "variable": "oil_temp_C", "threshold": t_mid, "side": "above"}),
        ("cold_oil_step", f(f"{{coefficient: {c:.4g} W, factors: [{{variable: oil_temperature, shape: step, below: {t_lo:.4g} degC}}]}}"),
         {"shape": "step", "variable": "oil_temp_C", "threshold": t_lo, "side": "below"}),
        ("load_threshold", f(f"{{coefficient: {2 * c:.4g} W, factors: [{{variable: torque, shape: threshold, above: {T_mid:.4g} N*m, reference: {Tmax - T_mid:.4g} N*m}}]}}"),
         {"shape": "threshold", "variable": "torque_Nm", "threshold": T_mid, "side": "above"}),
        ("speed_step", f(f"{{coefficient: {c:.4g} W, factors: [{{variable: speed, shape: step, above: {n_mid:.4g} rpm}}]}}"),
         {"shape": "step", "variable": "speed_rpm", "threshold": n_mid, "side": "above"}),
        ("speed_power_1.6", f(f"{{coefficient: {c:.4g} W, factors: [{{variable: speed, shape: power, reference: {speeds[-1]:.4g} rpm, exponent: 1.6}}]}}"),
         {"shape": "power", "variable": "speed_rpm", "exponent": 1.6}),
        ("speed_power_gated_hot", f(f"{{coefficient: {2 * c:.4g} W, factors: [{{variable: speed, shape: power, reference: {speeds[-1]:.4g} rpm, exponent: 2}}, {{variable: oil_temperature, shape: step, above: {t_mid:.4g} degC}}]}}"),
         {"shape": "power", "variable": "speed_rpm", "exponent": 2.0, "gate": {"variable": "oil_temp_C", "threshold": t_mid}}),
        ("resonance_window", f(f"{{coefficient: {c:.4g} W, factors: [{{variable: speed, shape: window, lower: {win_lo:.4g} rpm, upper: {win_hi:.4g} rpm}}]}}"),
         {"shape": "window", "variable": "speed_rpm", "lower": win_lo, "upper": win_hi}),
    ]


def parse_basis(basis):
    """The form of a term from its text, for reports without the structured fields (the
    formula of earlier versions: powers 1-3 of speed, steps and bands at speed levels, hot-oil
    steps)."""
    import re
    t = {}
    m = re.fullmatch(r"\[n > ([\d.]+) rpm\]", basis)
    if m:
        return {"shape": "step", "variable": "speed_rpm", "threshold": float(m[1]), "side": "above"}
    m = re.fullmatch(r"\[theta_oil > ([\d.]+) degC\]", basis)
    if m:
        return {"shape": "step", "variable": "oil_temp_C", "threshold": float(m[1]), "side": "above"}
    m = re.fullmatch(r"(?:\(T_in/[\d.]+ N\*m\)\^2 )?\[n = ([\d.]+) rpm\]", basis)
    if m:
        x = float(m[1])
        return {"shape": "window", "variable": "speed_rpm", "lower": 0.99 * x, "upper": 1.01 * x}
    m = re.fullmatch(r"\(n/1000 rpm\)(?:\^([\d.]+))?", basis)
    if m:
        return {"shape": "power", "variable": "speed_rpm", "exponent": float(m[1] or 1)}
    m = re.fullmatch(r"\(T_in/[\d.]+ N\*m\)(?:\^([\d.]+))?", basis)
    if m:
        return {"shape": "power", "variable": "torque_Nm", "exponent": float(m[1] or 1)}
    return t


def form_ok(term, truth, rec):
    if term is None:
        return False
    if "shape" not in term:
        term = parse_basis(term.get("basis", ""))
    var = truth["variable"]
    col = {"speed_rpm": "speed_in_rpm", "torque_Nm": "torque_in_Nm", "oil_temp_C": "oil_temp_C"}
    if truth["shape"] == "window":
        return term.get("shape") == "window" and term.get("variable") == var and \
            term.get("lower", -1) < 0.5 * (truth["lower"] + truth["upper"]) < term.get("upper", -1)
    if term.get("variable") == "viscosity_cSt" and "oil_temp_equivalent_C" in term and var == "oil_temp_C":
        # thick oil is cold oil: a viscosity threshold is a temperature threshold the other way
        term = dict(term, variable="oil_temp_C", threshold=term["oil_temp_equivalent_C"],
                    side="below" if term.get("side", "above") == "above" else "above")
    if term.get("variable") != var:
        return False
    if truth["shape"] == "power":
        if term.get("shape") != "power" or abs(term.get("exponent", 99) - truth["exponent"]) > 0.3:
            return False
        if "gate" in truth:
            g = term.get("gate")
            if not g or g["variable"] != truth["gate"]["variable"]:
                return False
            lv = levels([float(r[col[g["variable"]]]) for r in rec], g["variable"] != "oil_temp_C")
            return within_one_step(g["threshold"], truth["gate"]["threshold"], lv)
        return True
    if term.get("shape") not in ("step", "threshold") or "threshold" not in term:
        return False
    if truth["shape"] == "threshold" and term.get("shape") != "threshold":
        return False
    if term.get("side", "above") != truth["side"]:
        return False
    lv = levels([float(r[col[var]]) for r in rec], var != "oil_temp_C")
    return within_one_step(term["threshold"], truth["threshold"], lv)


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("gearloss")
    ap.add_argument("--synth", default=None)
    ap.add_argument("--seeds", type=int, default=2)
    ap.add_argument("--out", default=None)
    ap.add_argument("--cases", default=",".join(CASES))
    a = ap.parse_args()
    synth = a.synth or a.gearloss
    work = a.out or tempfile.mkdtemp(prefix="remainder-")
    os.makedirs(work, exist_ok=True)
    rows = []
    for case in a.cases.split(","):
        base, speeds, torques = CASES[case]
        cfg = os.path.join(ROOT, base)
        base_csv = os.path.join(work, f"{case}-baseline.csv")
        run([synth, "synth", cfg, "--speed", speeds, "--torque", torques, "--noise-loss", "0%", "--noise-temp", "0K",
             "-o", base_csv])
        for name, terms, truth in effects(read_csv(base_csv)):
            tcfg = os.path.join(work, f"{case}-{name}.yaml")
            truth_config(base, terms, tcfg)
            for seed in range(1, a.seeds + 1):
                rec = os.path.join(work, f"{case}-{name}-{seed}.csv")
                js = os.path.join(work, f"{case}-{name}-{seed}.json")
                run([synth, "synth", tcfg, "--speed", speeds, "--torque", torques, "--seed", str(seed), "-o", rec])
                run([a.gearloss, "diagnose", cfg, rec, "--json", js, "--quiet"])
                d = json.load(open(js))
                recs = read_csv(rec)
                loss = [float(r["P_loss_W"]) for r in recs]
                noise_w = NOISE / math.sqrt(sum(1 / x ** 2 for x in loss) / len(loss))  # weighted as the formula's CV
                noise_rms = NOISE * math.sqrt(sum(x * x for x in loss) / len(loss))
                r = d.get("remainder_hypothesis")
                if r:
                    final = r["cv_rmse_after"] / noise_w
                    first = r["terms"][0] if r["terms"] else None
                    ok_first = form_ok(first, truth, recs)
                    ok_any = any(form_ok(t, truth, recs) for t in r["terms"])
                else:
                    final = d["cv_rmse_after"] / noise_rms
                    ok_first = ok_any = False
                if d["verdict"] in ("no_significant_mismatch",):
                    final = d["cv_rmse_after"] / noise_rms
                rows.append((case, name, seed, d["verdict"], bool(r), final, ok_first, ok_any,
                             r["formula"] if r else ""))
                print(f"{case:9} {name:22} {seed} {d['verdict']:24} formula={'y' if r else 'n'} final/noise={final:5.2f} "
                      f"form={'y' if ok_first else 'n'}{'y' if ok_any else 'n'} {r['formula'] if r else ''}", flush=True)
    n = len(rows)
    print(f"\n{n} campaigns: formula {sum(r[4] for r in rows)}/{n}, final <= 1.5 noise {sum(r[5] <= 1.5 for r in rows)}/{n}, "
          f"form (first term) {sum(r[6] for r in rows)}/{n}, form (any term) {sum(r[7] for r in rows)}/{n}")


if __name__ == "__main__":
    main()
