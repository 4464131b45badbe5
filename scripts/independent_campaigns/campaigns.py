"""One case's shared setup, the campaign plan, and the synthesis of one campaign.

prepare_case maps the model table, reads the oil and chooses the heat path (the derived
case's resistance R0). plan lists the campaigns (single, two, outside-library, null).
build_campaign draws a rig-like sub-grid, sizes the concealed effects on the null state,
solves each point's steady temperature with the effects, adds noise, ambient drift and
sensor artefacts, and writes recordings.csv (the `diagnose` CSV format) and truth.json.
"""
import json
import math
import random

from .cases import CASES, ROOT, Oil, derive_case, oil_path, read_thermal
from .effects import ACCEPT, EFFECTS, LIBRARY, OUTSIDE, THERMAL_ONLY, Ctx
from .heat_balance import T_MAX_NULL, Heat, heat_check, steady_temperature
from .model_table import ModelTable
from .numerics import mean


class PreparedCase:
    """What every campaign of a case shares."""

    def __init__(self, model, config, heat, oil, ambient, info):
        self.model, self.config, self.heat, self.oil, self.ambient = model, config, heat, oil, ambient
        self.info = info  # the heat path, for the tables


def prepare_case(binary, cname, out, log):
    """Map the model table, read the oil, choose the heat path (writing the derived case that
    `diagnose` receives) and check the balance solved here against the binary's."""
    case = CASES[cname]
    log(f"case {cname} ({case['config']}, heat path: {case['heat']})")
    wd = out / "maps" / cname
    wd.mkdir(parents=True, exist_ok=True)
    (out / "cases").mkdir(exist_ok=True)
    th = read_thermal(ROOT / case["config"])
    ambient = th.get("ambient", 25.0)
    cfg = derive_case(case, cname, out / "cases", resistance=0.1)
    model = ModelTable(binary, cfg, case, wd, log)
    oil = Oil(oil_path(ROOT / case["config"]))
    if case["heat"] == "fixed":
        t_fix = case.get("oil_temp", th.get("oil_temperature"))
        heat = Heat(case, fixed=t_fix)
        info = f"fixed {t_fix:g} degC"
    elif case["heat"] == "housing":
        cfg = ROOT / case["config"]  # the shipped case itself
        heat = Heat(case, housing=th["housing"], g_oil_housing=th.get("oil_to_housing"))
        info = "housing (textbook)" + (" + oil-housing conductance" if th.get("oil_to_housing") else "")
    else:
        # R0: the hottest superset point settles about 75 K above ambient (null)
        pmax = max(model.get("P_total_W", i, ambient + 75) for i in range(len(model.points)) if model.trange[i])
        r0 = 75.0 / pmax
        if case.get("ref_speed"):  # the resistance is that at n_ref; the hottest point runs faster
            r0 *= (max(case["speeds"]) / case["ref_speed"]) ** case["speed_exponent"]
        cfg = derive_case(case, cname, out / "cases", resistance=r0)
        heat = Heat(case, resistance=r0)
        info = f"R0 {r0:.4g} K/W" + (f", (n/{case['ref_speed']:g})^-{case['speed_exponent']:g}" if case.get("ref_speed") else "")
    if case["heat"] != "fixed":
        e = heat_check(binary, cfg, case, model, oil, heat, ambient, wd / "stabilised.csv", log)
        info += f"; check {e:.2f} K"
    return PreparedCase(model, cfg, heat, oil, ambient, info)


def plan(case_names, seeds, quick):
    """The campaigns to run: per case and seed, single in-library effects, effects outside the
    library, two pairs of effects (drawn so that no name is acceptable for both) and two nulls."""
    specs = []
    for cname in case_names:
        case = CASES[cname]
        fixed = case["heat"] == "fixed"
        lib = [e for e in LIBRARY if not (fixed and e in THERMAL_ONLY)]
        out = [e for e in OUTSIDE if not (fixed and e in THERMAL_ONLY)]
        for s in range(seeds):
            if quick:
                singles = ["aero_drag", "visc_shift", "sensor_offset"] + ([] if fixed else ["heat_factor"])
                outside = ["speed_step", "torque2_band"]
                pairs = [("aero_drag", "sensor_offset")]
            else:
                singles, outside, pairs = lib, out, []
                rng = random.Random(f"{cname}|pairs|{s}")
                for _ in range(2):
                    a, b = rng.sample(lib, 2)
                    while ACCEPT[a] & ACCEPT[b]:
                        a, b = rng.sample(lib, 2)
                    pairs.append((a, b))
            for e in singles:
                specs.append(dict(case=cname, effects=[e], seed=s, tag=e, category="single"))
            for e in outside:
                specs.append(dict(case=cname, effects=[e], seed=s, tag=e, category="outside"))
            for p, (a, b) in enumerate(pairs):
                specs.append(dict(case=cname, effects=[a, b], seed=s, tag=f"pair{p}_{a}+{b}", category="two"))
            for z in range(2):
                specs.append(dict(case=cname, effects=[], seed=s, tag=f"null{z}", category="null"))
    return specs


def choose_points(model, rng):
    ns, ts = model.speeds, model.torques
    while True:
        a, b = rng.randint(3, min(5, len(ns))), rng.randint(3, len(ts))
        if 9 <= a * b <= 30:
            break
    sn = sorted(rng.sample(range(len(ns)), a))
    st = sorted(rng.sample(range(len(ts)), b))
    return [si * len(ts) + ti for si in sn for ti in st]


def build_campaign(spec, model, oil, heat, ambient, outdir):
    """spec: dict(case, effects=[names], seed, tag). Writes recordings.csv + truth.json."""
    rng = random.Random(f"{spec['case']}|{spec['tag']}|{spec['seed']}")
    pts = choose_points(model, rng)
    ctx = Ctx(model, oil, pts, heat, rng)
    # null steady state at the nominal ambient (sizes the effects)
    dropped = []
    for i in list(pts):
        t = steady_temperature(ctx, i, ambient, [], 0)
        if t is None or t > T_MAX_NULL:
            dropped.append(i)
            continue
        ctx.t0[i], ctx.p0[i] = t, model.get("P_total_W", i, t)
    ctx.pts = pts = [i for i in pts if i not in dropped]
    if len(pts) < 9:
        return None, "fewer than 9 points with a null equilibrium"
    effects = []
    for name in spec["effects"]:
        e = EFFECTS[name](random.Random(f"{spec['case']}|{spec['tag']}|{spec['seed']}|{name}"))
        if hasattr(e, "applicable"):
            ok, why = e.applicable(ctx)
            if not ok:
                return None, f"{name} not applicable ({why})"
        r = rng.uniform(0.06, 0.14) if len(spec["effects"]) == 1 else rng.uniform(0.05, 0.10)
        e.setup(ctx, r)
        e.params["size_r"] = r
        effects.append(e)
    # test order, ambient (drift), noise
    order = list(pts)
    if rng.random() < 0.5:
        rng.shuffle(order)
        order_kind = "shuffled"
    else:
        order_kind = "speed outer, torque inner"
    nrows = len(order)
    drift = rng.uniform(-4, 4) if rng.random() < 0.5 else 0.0
    s_loss = rng.uniform(0.01, 0.03)
    s_temp = rng.uniform(0.3, 0.5)
    fmt = "torques" if rng.random() < 0.3 else "ploss"
    rows, truth_rows = [], []
    for k, i in enumerate(order):
        ta = ambient + drift * (k / max(nrows - 1, 1) - 0.5)
        t = steady_temperature(ctx, i, ta, effects, k)
        if t is None:
            truth_rows.append({"speed_rpm": ctx.n[i], "torque_Nm": ctx.tq[i], "dropped": "no equilibrium"})
            continue
        p_model = model.get("P_total_W", i, t)
        p_true = p_model + sum(e.dloss(ctx, i, t, k) for e in effects if e.heats)
        tq_rec = ctx.tq[i]
        for e in effects:
            tq_rec = e.torque_rec(ctx, i, tq_rec, k, nrows)
        w_in = ctx.omega(i)
        p_rec = p_true + (tq_rec - ctx.tq[i]) * w_in  # what in - out power gives with that torque
        p_rec *= 1 + rng.gauss(0, s_loss)
        t_rec = t + rng.gauss(0, s_temp)
        ta_rec = ta + rng.gauss(0, 0.1)
        p_out_m, t_out_m = model.get("power_out_W", i, t), model.get("torque_out_Nm", i, t)
        w_out = abs(p_out_m / t_out_m) if t_out_m else 0.0
        rows.append({"speed_in_rpm": f"{ctx.n[i]:g}", "torque_in_Nm": f"{tq_rec:.4f}", "P_loss_W": f"{p_rec:.3f}",
                     "torque_out_Nm": f"{(tq_rec * w_in - p_rec) / w_out:.5f}" if w_out > 0 else None,
                     "speed_out_rpm": f"{w_out * 60 / (2 * math.pi):.5f}" if w_out > 0 else None,
                     "oil_temp_C": f"{t_rec:.3f}", "ambient_temp_C": f"{ta_rec:.3f}"})
        t_null = steady_temperature(ctx, i, ta, [], k)
        truth_rows.append({"speed_rpm": ctx.n[i], "torque_Nm": ctx.tq[i], "oil_temp_C": t, "ambient_C": ta,
                           "P_model_W": p_model, "P_true_W": p_true, "P_recorded_noiseless_W":
                           p_true + (tq_rec - ctx.tq[i]) * w_in, "null_oil_temp_C": t_null})
    if any(r["torque_out_Nm"] is None for r in rows):
        fmt = "ploss"  # the output speed is unknown somewhere: record the loss column
    if len(rows) < 9:
        return None, "fewer than 9 points with an equilibrium"
    outdir.mkdir(parents=True, exist_ok=True)
    cols = ["speed_in_rpm", "torque_in_Nm"] + (["P_loss_W"] if fmt == "ploss" else ["torque_out_Nm", "speed_out_rpm"]) \
        + ["oil_temp_C", "ambient_temp_C"]
    text = ",".join(cols) + "\n" + "".join(",".join(r[c] for c in cols) + "\n" for r in rows)
    rec = outdir / "recordings.csv"
    unchanged = rec.exists() and rec.read_text().replace("\r\n", "\n") == text
    if not unchanged:
        rec.write_text(text)
    kept = [x for x in truth_rows if "dropped" not in x]
    # what the diagnosis can see, noise aside: the loss residual at the measured oil temperature
    # and the oil temperature residual against the null balance at the same ambient
    size_loss = mean(abs(x["P_recorded_noiseless_W"] / x["P_model_W"] - 1) for x in kept)
    size_temp = math.sqrt(mean((x["oil_temp_C"] - x["null_oil_temp_C"]) ** 2 for x in kept
                               if x["null_oil_temp_C"] is not None)) if heat.kind != "fixed" else 0.0
    truth = {"case": spec["case"], "tag": spec["tag"], "seed": spec["seed"], "category": spec["category"],
             "effects": [{"name": e.name, "params": e.params, "truth_parameter": e.truth(ctx)} for e in effects],
             "points": len(rows), "dropped_points": len(truth_rows) - len(rows) + len(dropped),
             "noise_loss": s_loss, "noise_temp_K": s_temp, "ambient_drift_K": drift, "order": order_kind,
             "format": fmt, "heat": heat.kind, "size_loss_rel": size_loss, "size_temp_rms_K": size_temp,
             "recordings_unchanged": unchanged, "rows": truth_rows}
    (outdir / "truth.json").write_text(json.dumps(truth, indent=1))
    return truth, None
