"""One case's shared setup, the campaign plan, and the synthesis of one campaign.

prepare_case maps the model table, reads the oil and chooses the heat path (the derived
case's resistance R0); the case then maps, on demand and once per run, the same case with
another form (form campaigns) or another oil (multi-oil campaigns). plan lists the
campaigns (single, two, three, outside-library, form, form + effect, multi-oil, null).
build_campaign draws a rig-like sub-grid, sizes the concealed effects on the null state,
solves each point's steady temperature with the effects, adds noise, ambient drift and
sensor artefacts, and writes recordings.csv (the `diagnose` CSV format) and truth.json.
The multi-oil campaigns are built in multi_oil.py.
"""
import json
import math
import random

from .cases import CASES, OILS_DIR, ROOT, Oil, derive_case, oil_family, oil_path, read_thermal
from .effects import ACCEPT, EFFECTS, LIBRARY, ORDERED, OUTSIDE, THERMAL_ONLY, Ctx
from .forms import AXES, alternatives, case_forms, checked_forms, expected_id, rewrite_case
from .heat_balance import T_MAX_NULL, Heat, heat_check, noiseless_point, steady_temperature
from .identifiability import hidden_effect
from .model_table import ModelTable
from .numerics import mean

# An effect must show on its own at least this many noise standard deviations per point (below_noise).
DETECTABLE = 1.0
# A pair is a test of naming both only when neither effect hides behind the other refitted alone
# (identifiability.py); --no-pair-gate scores every pair on naming both.
PAIR_GATE = True
CHECK_PAIR_FIT = False  # --check-pair-fit: also fit each effect to its own recordings (fit_check_chi2)
CATEGORIES = ["single", "outside", "two", "three", "form", "form_effect", "multi_oil", "null",
              "synth_own", "order", "outliers"]  # the last three: issue 38 (synth_own.py, robustness.py)
MULTI_OIL_KINDS = ["common", "per_oil", "both"]


class PreparedCase:
    """What every campaign of a case shares, and the case's other-form / other-oil tables."""

    def __init__(self, model, config, heat, oil, ambient, info):
        self.model, self.config, self.heat, self.oil, self.ambient = model, config, heat, oil, ambient
        self.info = info  # the heat path, for the tables
        self.tables = {}  # (kind, name) -> (ModelTable or None, why): maps per case + form / case + oil

    def _table(self, key, write_case):
        if key not in self.tables:
            cfg = write_case()
            wd = self.out / "maps" / self.cname / f"{key[0]}_{key[1]}"
            wd.mkdir(parents=True, exist_ok=True)
            try:
                t = ModelTable(self.binary, cfg, CASES[self.cname], wd, self.log)
                self.tables[key] = (t, None) if t.failed == 0 else \
                    (None, f"{t.failed} failed points on the {key[0]} map's grid")
            except RuntimeError as e:
                self.tables[key] = (None, f"map failed: {str(e).strip().splitlines()[-1][:200]}")
        return self.tables[key]

    def form_table(self, axis, form):
        """The model table of this case with `form` selected on `axis` (derived case in OUT/cases)."""
        def write():
            dst = self.out / "cases" / f"{self.cname}__{axis}_{form}.yaml"
            rewrite_case(self.config, dst, f"Form campaign truth: {self.cname} with {axis} = {form} "
                         "(scripts/independent-campaigns.py; diagnose never sees this file)", form=(axis, form))
            got = checked_forms(self.binary, dst).get(axis)
            if got != form:
                raise RuntimeError(f"gearloss check reports {axis} = {got} in {dst}, not {form}")
            return dst
        return self._table(("form", f"{axis}_{form}"), write)

    def oil_table(self, oil_name):
        """The model table of this case with its `oil:` replaced (derived case in OUT/cases)."""
        def write():
            dst = self.out / "cases" / f"{self.cname}__oil_{oil_name}.yaml"
            rewrite_case(self.config, dst, f"Multi-oil campaign truth: {self.cname} with oil {oil_name} "
                         "(scripts/independent-campaigns.py; diagnose never sees this file)",
                         oil=OILS_DIR / f"{oil_name}.yaml")
            return dst
        if oil_name == oil_path(self.config).stem:
            return self.model, None
        return self._table(("oil", oil_name), write)


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
    c = PreparedCase(model, cfg, heat, oil, ambient, info)
    c.binary, c.cname, c.out, c.log = binary, cname, out, log
    c.forms = case_forms(cfg)  # the forms `diagnose` receives (options / mechanisms, documented defaults)
    checked = checked_forms(binary, cfg)
    if checked and checked != c.forms:
        raise RuntimeError(f"{cfg}: forms read from the text {c.forms} differ from gearloss check's {checked}")
    c.family = oil_family(cfg)
    return c


def plan(case_names, seeds, quick, categories=None):
    """The campaigns to run: per case and seed, single in-library effects, effects outside the
    library, two pairs and two triples of effects (drawn so that no name is acceptable for two of
    them), one campaign per form axis (the case's alternative forms in turn over the seeds) and
    one form change with a small effect, one multi-oil campaign per kind, and two nulls.
    categories: the subset of CATEGORIES to plan (default all)."""
    cats = set(categories or CATEGORIES)
    specs = []
    for cname in case_names:
        case = CASES[cname]
        fixed = case["heat"] == "fixed"
        lib = [e for e in LIBRARY if not (fixed and e in THERMAL_ONLY)]
        out = [e for e in OUTSIDE if not (fixed and e in THERMAL_ONLY)]
        forms = case_forms(ROOT / case["config"])  # derived cases keep the shipped options
        for s in range(seeds):
            if quick:
                singles = ["aero_drag", "visc_shift", "sensor_offset"] + ([] if fixed else ["heat_factor"])
                outside = ["speed_step", "torque2_band"]
                pairs = [("aero_drag", "sensor_offset")]
                triples = [("aero_drag", "sensor_gain", "pump_loss" if fixed else "heat_factor")]
                form_axes = ["friction", "loss_factor"]
                oil_kinds = ["both"]
            else:
                singles, outside, pairs, triples = lib, out, [], []
                rng = random.Random(f"{cname}|pairs|{s}")
                for _ in range(2):
                    a, b = rng.sample(lib, 2)
                    while ACCEPT[a] & ACCEPT[b]:
                        a, b = rng.sample(lib, 2)
                    pairs.append((a, b))
                rng = random.Random(f"{cname}|three|{s}")
                for _ in range(2):
                    t = rng.sample(lib, 3)
                    while ACCEPT[t[0]] & ACCEPT[t[1]] or ACCEPT[t[0]] & ACCEPT[t[2]] or ACCEPT[t[1]] & ACCEPT[t[2]]:
                        t = rng.sample(lib, 3)
                    triples.append(tuple(t))
                form_axes = list(AXES)
                oil_kinds = MULTI_OIL_KINDS
            add = lambda cat, **kw: specs.append(dict(case=cname, seed=s, category=cat, **kw)) if cat in cats else None
            for e in singles:
                add("single", effects=[e], tag=e)
            for e in outside:
                add("outside", effects=[e], tag=e)
            for p, (a, b) in enumerate(pairs):
                add("two", effects=[a, b], tag=f"pair{p}_{a}+{b}")
            for p, t in enumerate(triples):
                add("three", effects=list(t), tag=f"three{p}_" + "+".join(t))
            for axis in form_axes:
                alts = alternatives(forms, axis)
                form = alts[s % len(alts)]  # over the seeds, every alternative form in turn
                add("form", effects=[], tag=f"form_{axis}_{form}", form=(axis, form))
            if not quick:
                # a form change of mesh friction or load-loss factor (the axes whose change shows on the
                # shipped cases; film correction and windage form stay below the noise) + a small effect
                rng = random.Random(f"{cname}|form_effect|{s}")
                axis = rng.choice(["friction", "loss_factor"])
                form = rng.choice(alternatives(forms, axis))
                e = rng.choice(["sensor_offset", "aero_drag"])
                add("form_effect", effects=[e], tag=f"formfx_{axis}_{form}+{e}", form=(axis, form))
            for k, kind in enumerate(oil_kinds):
                add("multi_oil", effects=[], tag=f"oils{k}_{kind}", kind=kind)
            for z in range(2):
                add("null", effects=[], tag=f"null{z}")
    return specs


def choose_points(model, rng, max_points=30):
    """A rig-like sub-grid of 3-5 speeds x 3-6 torques with 9..max_points points (indices of model)."""
    ns, ts = model.speeds, model.torques
    while True:
        a, b = rng.randint(3, min(5, len(ns))), rng.randint(3, len(ts))
        if 9 <= a * b <= max_points:
            break
    sn = sorted(rng.sample(range(len(ns)), a))
    st = sorted(rng.sample(range(len(ts)), b))
    return [si * len(ts) + ti for si in sn for ti in st]


# Multiplies the drawn noise levels (--noise-scale): the same campaigns with less noise tell a
# miss the noise causes from one the truth's form causes (a perturbed form closer to another
# candidate's); the draws themselves are unchanged.
NOISE_SCALE = 1.0


def draw_conditions(rng):
    """Ambient drift over the campaign (half of them), loss and temperature noise, recorded format."""
    drift = rng.uniform(-4, 4) if rng.random() < 0.5 else 0.0
    s_loss = rng.uniform(0.01, 0.03) * NOISE_SCALE
    s_temp = rng.uniform(0.3, 0.5) * NOISE_SCALE
    fmt = "torques" if rng.random() < 0.3 else "ploss"
    return drift, s_loss, s_temp, fmt


def record_point(ctx, i, ta, effects, k, nrows, s_loss, s_temp, rng):
    """Point i as the rig records it in row k: the steady oil temperature with the effects, the
    true loss, the sensor artefacts on the input torque, noise. Returns (row, truth_row), row
    None when the point has no equilibrium."""
    m = ctx.m
    point = noiseless_point(ctx, i, ta, effects, k, nrows)
    if point is None:
        return None, {"speed_rpm": ctx.n[i], "torque_Nm": ctx.tq[i], "dropped": "no equilibrium"}
    t, p_model, p_true, tq_rec, p_rec = point
    w_in = ctx.omega(i)
    p_rec *= 1 + rng.gauss(0, s_loss)
    t_rec = t + rng.gauss(0, s_temp)
    ta_rec = ta + rng.gauss(0, 0.1)
    p_out_m, t_out_m = m.get("power_out_W", i, t), m.get("torque_out_Nm", i, t)
    w_out = abs(p_out_m / t_out_m) if t_out_m else 0.0
    row = {"speed_in_rpm": f"{ctx.n[i]:g}", "torque_in_Nm": f"{tq_rec:.4f}", "P_loss_W": f"{p_rec:.3f}",
           "torque_out_Nm": f"{(tq_rec * w_in - p_rec) / w_out:.5f}" if w_out > 0 else None,
           "speed_out_rpm": f"{w_out * 60 / (2 * math.pi):.5f}" if w_out > 0 else None,
           "oil_temp_C": f"{t_rec:.3f}", "ambient_temp_C": f"{ta_rec:.3f}"}
    return row, {"speed_rpm": ctx.n[i], "torque_Nm": ctx.tq[i], "oil_temp_C": t, "ambient_C": ta,
                 "P_model_W": p_model, "P_true_W": p_true, "P_recorded_noiseless_W": p_true + (tq_rec - ctx.tq[i]) * w_in}


def write_recordings(outdir, rows, fmt, lead=()):
    """recordings.csv in the `diagnose` format (columns `lead` first). Returns (format used, whether
    an identical file was already there); the loss column is used where an output speed is unknown."""
    if any(r["torque_out_Nm"] is None for r in rows):
        fmt = "ploss"
    outdir.mkdir(parents=True, exist_ok=True)
    cols = list(lead) + ["speed_in_rpm", "torque_in_Nm"] \
        + (["P_loss_W"] if fmt == "ploss" else ["torque_out_Nm", "speed_out_rpm"]) + ["oil_temp_C", "ambient_temp_C"]
    text = ",".join(cols) + "\n" + "".join(",".join(r[c] for c in cols) + "\n" for r in rows)
    rec = outdir / "recordings.csv"
    unchanged = rec.exists() and rec.read_text().replace("\r\n", "\n") == text
    if not unchanged:
        rec.write_text(text)
    return fmt, unchanged


def visible_size(kept, fixed):
    """What the diagnosis can see, noise aside: the loss residual at the measured oil temperature
    (against the model `diagnose` uses) and the oil temperature residual against the null balance."""
    size_loss = mean(abs(x["P_recorded_noiseless_W"] / x.get("P_case_model_W", x["P_model_W"]) - 1) for x in kept)
    size_temp = math.sqrt(mean((x["oil_temp_C"] - x["null_oil_temp_C"]) ** 2 for x in kept
                               if x["null_oil_temp_C"] is not None)) if not fixed else 0.0
    return size_loss, size_temp


def below_noise(ctx, effects, truth_rows, order, ambient, drift, s_loss, s_temp, fixed):
    """Why the campaign is not a test of the diagnosis, or None: an effect is a test only when it
    shows on its own at least DETECTABLE x the noise per point, in the recorded loss (its own loss
    and torque artefact at the point's oil temperature, mean over the points, relative to the model)
    or, stabilised, in the oil temperature (RMS change of the balance with that effect alone). No
    method can name an effect the noise hides; the multi-oil campaigns gate their per-oil effects
    the same way (multi_oil.VISIBLE)."""
    nrows = len(order)
    for e in effects:
        dl, dt = [], []
        for k, (i, x) in enumerate(zip(order, truth_rows)):  # truth_rows[k] is row k's point, order[k]
            if "dropped" in x:
                continue
            t = x["oil_temp_C"]
            artefact = (e.torque_rec(ctx, i, ctx.tq[i], k, nrows) - ctx.tq[i]) * ctx.omega(i)
            own = (e.dloss(ctx, i, t, k) if e.heats else 0.0) + artefact
            dl.append(abs(own) / x["P_model_W"])
            if not fixed:
                ta = ambient + drift * (k / max(nrows - 1, 1) - 0.5)
                t_alone, t_null = steady_temperature(ctx, i, ta, [e], k), steady_temperature(ctx, i, ta, [], k)
                if t_alone is not None and t_null is not None:
                    dt.append(t_alone - t_null)
        v_loss = mean(dl) if dl else 0.0
        v_temp = math.sqrt(mean(d * d for d in dt)) if dt else 0.0
        e.params["visible_loss_rel"], e.params["visible_temp_rms_K"] = v_loss, v_temp
        if v_loss < DETECTABLE * s_loss and v_temp < DETECTABLE * s_temp:
            return (f"{e.name} below the noise on its own: loss {100 * v_loss:.2f} % vs {100 * s_loss:.2f} %, "
                    f"oil temperature {v_temp:.2f} K vs {s_temp:.2f} K (RMS)")
    return None


def build_campaign(spec, model, oil, heat, ambient, outdir, case_model=None):
    """spec: dict(case, effects=[names], seed, tag[, form]). Writes recordings.csv + truth.json.
    model: the truth's model part; case_model: the one `diagnose` compares with, when it differs
    (form campaigns: model is the case with another form). Returns (truth, None) or (None, why)."""
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
        if spec["category"] == "three":
            r = rng.uniform(0.04, 0.08)
        elif spec["category"] == "form_effect":
            r = rng.uniform(0.04, 0.06)  # a small effect beside the form change
        else:
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
    drift, s_loss, s_temp, fmt = draw_conditions(rng)
    # conditions a category fixes (order, outliers): the draws above are made all the same, so
    # the other campaigns' recordings do not change
    fix = spec.get("conditions", {})
    drift, s_loss, fmt = fix.get("drift", drift), fix.get("noise_loss", s_loss), fix.get("format", fmt)
    form = None
    if case_model is not None:  # form change: detectable against the noise, else not built
        d = mean(abs(model.get("P_total_W", i, ctx.t0[i]) / case_model.get("P_total_W", i, ctx.t0[i]) - 1)
                 for i in pts)
        axis, name = spec["form"]
        form = {"axis": axis, "form": name, "expected": expected_id(axis, name),
                "mean_abs_rel_change_at_null": d, "noise_loss": s_loss}
        if d < 3 * s_loss:
            return None, (f"form change {axis}:{name} not detectable: mean |P_form/P_case - 1| = {100 * d:.2f} % "
                          f"< 3 x loss noise {100 * s_loss:.2f} %")
    null_ctx = ctx if case_model is None else Ctx(case_model, oil, pts, heat, rng)
    rows, truth_rows = [], []
    for k, i in enumerate(order):
        ta = ambient + drift * (k / max(nrows - 1, 1) - 0.5)
        row, trow = record_point(ctx, i, ta, effects, k, nrows, s_loss, s_temp, rng)
        truth_rows.append(trow)
        if row is None:
            continue
        row["run"] = str(k + 1)  # the test order (written only where a `run` column is recorded)
        rows.append(row)
        trow["null_oil_temp_C"] = steady_temperature(null_ctx, i, ta, [], k)  # the balance `diagnose` expects
        if case_model is not None:  # what `diagnose` compares with: the case's own form
            trow["P_case_model_W"] = case_model.get("P_total_W", i, trow["oil_temp_C"])
    if len(rows) < 9:
        return None, "fewer than 9 points with an equilibrium"
    why = below_noise(ctx, effects, truth_rows, order, ambient, drift, s_loss, s_temp, heat.kind == "fixed")
    if why:
        return None, why
    # a pair where one effect hides behind the other refitted alone still tests the top finding,
    # not the naming of both (scoring.py)
    hidden = hidden_effect(ctx, effects, truth_rows, order, ambient, drift, s_loss, s_temp, heat.kind == "fixed",
                           check=CHECK_PAIR_FIT) if spec["category"] == "two" and PAIR_GATE else None
    # effects along the run order are recorded with a `run` column (issue 38: row order is not run order);
    # `shuffle_file` writes the rows in another order than the run's, so only that column tells it
    ordered = any(e.name in ORDERED for e in effects)
    if ordered and fix.get("shuffle_file"):
        rows = list(rows)
        random.Random(f"{spec['case']}|{spec['tag']}|{spec['seed']}|file order").shuffle(rows)
    fmt, unchanged = write_recordings(outdir, rows, fmt, lead=("run",) if ordered else ())
    size_loss, size_temp = visible_size([x for x in truth_rows if "dropped" not in x], heat.kind == "fixed")
    truth = {"case": spec["case"], "tag": spec["tag"], "seed": spec["seed"], "category": spec["category"],
             "effects": [{"name": e.name, "params": e.params, "truth_parameter": e.truth(ctx)} for e in effects],
             "points": len(rows), "dropped_points": len(truth_rows) - len(rows) + len(dropped),
             "noise_loss": s_loss, "noise_temp_K": s_temp, "ambient_drift_K": drift, "order": order_kind,
             "format": fmt, "heat": heat.kind, "size_loss_rel": size_loss, "size_temp_rms_K": size_temp,
             "recordings_unchanged": unchanged, "rows": truth_rows, "run_column": ordered,
             "noise_loss_W": math.sqrt(mean((s_loss * x["P_recorded_noiseless_W"]) ** 2
                                            for x in truth_rows if "dropped" not in x))}
    if form:
        truth["form"] = form
    if hidden:
        truth["pair_hidden"] = hidden
    (outdir / "truth.json").write_text(json.dumps(truth, indent=1))
    return truth, None
