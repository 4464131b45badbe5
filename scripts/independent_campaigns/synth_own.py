"""synth_own: campaigns made by `gearloss synth` itself, the model's own heat path (issue 38).

The other categories keep their truth away from the tool. This one asks the opposite
question: when the recordings come from the model's own forms and heat balance (`synth`,
9 or 16 points, 1-3 % loss noise, one library effect), does the diagnosis say so with
confidence? Correct = the top finding is the concealed effect AND the verdict is
`missing_physics`; each campaign is diagnosed without a declared uncertainty and, in a
second campaign with the same recordings, with `--loss-uncertainty` = the true noise.

Sizes: a loss effect is sized so that its recorded loss change is r = 6-14 % of the loss
(mean over the points, from a noise-free probe of the same grid scaled linearly); the heat
path is off by a factor 0.75-0.85 or 1.2-1.3, speed-dependent cooling a = 0.15-0.4. An effect
whose noise-free change is below 3x the noise (loss) and 3x 0.4 K (oil temperature) is not
built (the case has no such mechanism to speak of).

Also `mesh3x3`: the 3 x 3 campaign of issue 38, `synth --effect mesh_friction=1.2` at 1.5 %
loss noise, no declared uncertainty. Correct = no false lead (no remainder hypothesis whose
nearest mechanism is a resonance or a local contact), a loss noise used of at least the floor
the report states and at least half the true noise, and the fitted factor within 5 % of 1.2.
"""
import csv
import io
import json
import random
import subprocess

from .cases import CASES, ROOT, read_thermal

SYNTH_EFFECTS = ["windage", "churning", "bearing_drag", "seal_friction", "mesh_friction", "mesh_friction_mixed",
                 "constant_parasitic", "oil_viscosity", "thermal_resistance", "speed_dependent_cooling",
                 "torque_sensor_gain", "torque_sensor_offset"]
THERMAL = {"thermal_resistance", "speed_dependent_cooling"}
# (neutral value, probe value, unit) of the loss effects, scaled linearly to the drawn size
PROBE = {"windage": (0.0, 20.0, "W"), "churning": (1.0, 2.0, ""), "bearing_drag": (1.0, 2.0, ""),
         "seal_friction": (1.0, 2.0, ""), "mesh_friction": (1.0, 1.2, ""), "mesh_friction_mixed": (0.0, 0.5, ""),
         "constant_parasitic": (0.0, 20.0, "W"), "oil_viscosity": (1.0, 1.3, ""),
         "torque_sensor_gain": (1.0, 1.02, ""), "torque_sensor_offset": (0.0, 2.0, "Nm")}
TEMP_NOISE_K = 0.4
MESH3X3 = dict(speeds=[400, 800, 1200], torques=[100, 200, 300], factor=1.2, noise=0.015)
FALSE_LEAD = ("resonance", "local contact")


def synth_configs(case_names):
    """[(case variant, shipped config)]: the first variant of each shipped case file (synth runs the case as shipped)."""
    seen, out = set(), []
    for c in case_names:
        cfg = CASES[c]["config"]
        if cfg not in seen:
            seen.add(cfg)
            out.append((c, cfg))
    return out


def synth_grid(cname):
    """The superset grid synth draws from: that of the variant running the case's own (housing) heat path
    when there is one (manual_housing's lower torques: the shipped manual has no equilibrium at the
    resistance variant's 165 N*m), else the variant's."""
    cfg = CASES[cname]["config"]
    own = [c for c in CASES if CASES[c]["config"] == cfg and CASES[c]["heat"] == "housing"]
    return CASES[own[0]] if own else CASES[cname]


def plan_synth_own(case_names, seeds, quick):
    specs = []
    for cname, cfg in synth_configs(case_names):
        fixed = read_thermal(ROOT / cfg).get("mode") == "fixed"
        effects = [e for e in SYNTH_EFFECTS if not (fixed and e in THERMAL)]
        if quick:  # --quick (and prove-diagnosis.sh --short): the 3 x 3 campaign of issue 38 only
            effects = []
        for s in range(seeds):
            for e in effects:
                for npts in (9, 16):
                    for declared in (False, True):
                        specs.append(dict(case=cname, seed=s, category="synth_own", effects=[], synth_effect=e,
                                          points=npts, declared=declared, config=cfg,
                                          tag=f"own_{e}_{npts}pt" + ("_declared" if declared else "")))
            if cfg == "configs/transfer-box.yaml":
                for k in ([2] if quick else range(3)):
                    specs.append(dict(case=cname, seed=s, category="synth_own", effects=[], kind="mesh3x3",
                                      synth_effect="mesh_friction", points=9, declared=False, config=cfg,
                                      synth_seed=3 * s + k + 1, tag=f"mesh3x3_{k}"))
    return specs


def run_synth(binary, config, speeds, torques, effect, noise, seed, noise_temp=TEMP_NOISE_K):
    cmd = ["nice", "-n", "19", binary, "synth", str(ROOT / config), "--noise-loss", f"{100 * noise:g}%",
           "--noise-temp", f"{noise_temp:g}K", "--seed", str(seed), "--speed", ",".join(f"{x:g}" for x in speeds) + "rpm",
           "--torque", ",".join(f"{x:g}" for x in torques) + "Nm", "-o", "-"]
    if effect:
        cmd[6:6] = ["--effect", effect]
    r = subprocess.run(cmd, capture_output=True, text=True)
    if r.returncode != 0:
        raise RuntimeError(f"{' '.join(cmd)}: {r.stderr.strip()[-300:]}")
    return r.stdout, list(csv.DictReader(io.StringIO(r.stdout)))


def _change(null, rows):
    """Mean relative change of the recorded loss, RMS change of the oil temperature (noise-free runs)."""
    dl = sum(abs(float(b["P_loss_W"]) / float(a["P_loss_W"]) - 1) for a, b in zip(null, rows)) / len(rows)
    dt = (sum((float(b["oil_temp_C"]) - float(a["oil_temp_C"])) ** 2 for a, b in zip(null, rows)) / len(rows)) ** 0.5
    return dl, dt


def build_synth_campaign(spec, binary, cdir):
    """recordings.csv from `gearloss synth` + truth.json; (truth, None) or (None, why)."""
    rng = random.Random(f"{spec['case']}|synth_own|{spec['synth_effect']}|{spec['points']}|{spec['seed']}"
                        + (f"|{spec['synth_seed']}" if "synth_seed" in spec else ""))
    case, e = synth_grid(spec["case"]), spec["synth_effect"]
    if spec.get("kind") == "mesh3x3":
        speeds, torques, noise, value = MESH3X3["speeds"], MESH3X3["torques"], MESH3X3["noise"], MESH3X3["factor"]
        seed = spec["synth_seed"]
    else:
        k = 3 if spec["points"] == 9 else 4
        speeds = [case["speeds"][i] for i in sorted(rng.sample(range(len(case["speeds"])), k))]
        torques = [case["torques"][i] for i in sorted(rng.sample(range(len(case["torques"]) - 1), k))]
        noise = rng.uniform(0.01, 0.03)
        seed = rng.randint(1, 10 ** 6)
        r = rng.uniform(0.06, 0.14)
        try:
            _, null = run_synth(binary, spec["config"], speeds, torques, None, 0.0, 1, 0.0)
            if e in THERMAL:
                value = (rng.uniform(0.75, 0.85) if rng.random() < 0.5 else rng.uniform(1.2, 1.3)) \
                    if e == "thermal_resistance" else rng.uniform(0.15, 0.4)
                unit = ""
            else:
                z, p, unit = PROBE[e]
                _, probe = run_synth(binary, spec["config"], speeds, torques, f"{e}={p:g}{unit}", 0.0, 1, 0.0)
                d1, _ = _change(null, probe)
                if d1 <= 0:
                    return None, f"{e} changes nothing at these points"
                value = z + (p - z) * r / d1
                if e == "oil_viscosity":
                    value = min(max(value, 0.5), 2.0)
                if e in ("torque_sensor_gain", "torque_sensor_offset") and rng.random() < 0.5:
                    value = z - (value - z)  # either sign
            _, eff = run_synth(binary, spec["config"], speeds, torques, f"{e}={value:.6g}{unit}", 0.0, 1, 0.0)
        except RuntimeError as err:
            return None, f"synth failed: {str(err)[-200:]}"
        dl, dt = _change(null, eff)
        if dl < 3 * noise and dt < 3 * TEMP_NOISE_K:
            return None, (f"{e}={value:.4g} below 3x the noise: loss {100 * dl:.2f} % vs {100 * noise:.2f} %, "
                          f"oil temperature {dt:.2f} K vs {TEMP_NOISE_K} K")
        value = f"{value:.6g}{unit}"
    text, rows = run_synth(binary, spec["config"], speeds, torques, f"{e}={value}", noise, seed)
    cdir.mkdir(parents=True, exist_ok=True)
    rec = cdir / "recordings.csv"
    unchanged = rec.exists() and rec.read_text() == text
    if not unchanged:
        rec.write_text(text)
    truth = {"case": spec["case"], "tag": spec["tag"], "seed": spec["seed"], "category": "synth_own",
             "kind": spec.get("kind", "single"), "effects": [{"name": e, "params": {"value": value}}],
             "synth_effect": e, "value": value, "points": len(rows), "noise_loss": noise,
             "noise_temp_K": TEMP_NOISE_K, "declared": spec["declared"], "config": spec["config"],
             "ambient_drift_K": 0.0, "format": "ploss", "heat": "synth", "recordings_unchanged": unchanged,
             "diagnose_args": ["--loss-uncertainty", f"{100 * noise:g}%"] if spec["declared"] else []}
    (cdir / "truth.json").write_text(json.dumps(truth, indent=1))
    return truth, None


def _value(v):
    return float(str(v).rstrip("WNm%"))


def score_synth_own(truth, diag, res):
    """Outcome of a synth_own campaign (res has verdict, names, top, fitted)."""
    e, v = truth["synth_effect"], res["verdict"]
    res["top_ok"] = res["top"] == e
    if truth["kind"] == "mesh3x3":
        rh = diag.get("remainder_hypothesis") or {}
        near = " ".join(str(x) for x in (rh.get("nearest") or [])).lower()
        res["false_lead"] = any(w in near for w in FALSE_LEAD)
        nu = diag.get("noise_used") if isinstance(diag.get("noise_used"), dict) else {}
        used = nu.get("loss_relative")
        if used is None:  # before the contract's key: the adequacy block's noise
            used = ((diag.get("adequacy") or {}).get("loss_relative") or {}).get("noise")
        floor = nu.get("floor")
        res["noise_used"] = used
        res["noise_ok"] = used is not None and used >= 0.5 * truth["noise_loss"] \
            and (not isinstance(floor, (int, float)) or used >= floor - 1e-12)
        f = res["fitted"][1] if res["top_ok"] else None
        res["factor_ok"] = f is not None and abs(f / _value(truth["value"]) - 1) <= 0.05
        ok = not res["false_lead"] and res["noise_ok"] and res["factor_ok"]
        res["outcome"] = "correct" if ok else ("false_lead" if res["false_lead"] else
                                               "noise_underestimated" if not res["noise_ok"] else "factor_off")
        res["confident"] = v == "missing_physics"
        return
    if v == "no_significant_mismatch":
        res["outcome"] = "missed"
    elif res["top_ok"]:
        res["outcome"] = "correct" if v == "missing_physics" else "right_name_not_confident"
    elif res["top"]:
        res["outcome"] = "wrong_name"
    else:
        res["outcome"] = "not_named"


def build_synth_outlier(spec, binary, cdir):
    """outliers, made by synth: a 3 x 3 or 4 x 4 campaign at 1.5 % loss noise (null, or mesh friction x 1.2),
    and its noise-free twin (same grid, noise 0), which gives every row's true noise draw in both channels."""
    rng = random.Random(f"{spec['case']}|synth outliers|{spec['tag']}|{spec['seed']}")
    case = synth_grid(spec["case"])
    k = 3 if spec["points"] == 9 else 4
    speeds = [case["speeds"][i] for i in sorted(rng.sample(range(len(case["speeds"])), k))]
    torques = [case["torques"][i] for i in sorted(rng.sample(range(len(case["torques"]) - 1), k))]
    effect, noise, seed = spec.get("synth_effect"), spec["noise"], rng.randint(1, 10 ** 6)
    try:
        text, rows = run_synth(binary, spec["config"], speeds, torques, effect, noise, seed)
        _, free = run_synth(binary, spec["config"], speeds, torques, effect, 0.0, seed, 0.0)
    except RuntimeError as err:
        return None, f"synth failed: {str(err)[-200:]}"
    cdir.mkdir(parents=True, exist_ok=True)
    rec = cdir / "recordings.csv"
    unchanged = rec.exists() and rec.read_text() == text
    if not unchanged:
        rec.write_text(text)
    z = [(float(a["P_loss_W"]) / float(b["P_loss_W"]) - 1) / noise for a, b in zip(rows, free)]
    zt = [(float(a["oil_temp_C"]) - float(b["oil_temp_C"])) / TEMP_NOISE_K for a, b in zip(rows, free)]
    truth = {"case": spec["case"], "tag": spec["tag"], "seed": spec["seed"], "category": "outliers",
             "kind": "clean", "effects": [{"name": effect or "none", "params": {}}], "synth": True,
             "points": len(rows), "noise_loss": noise, "noise_temp_K": TEMP_NOISE_K, "config": spec["config"],
             "ambient_drift_K": 0.0, "format": "ploss", "heat": "synth", "recordings_unchanged": unchanged,
             "planted_row": None, "noise_z": z, "noise_z_temp": zt}
    (cdir / "truth.json").write_text(json.dumps(truth, indent=1))
    return truth, None
