"""Multi-oil campaigns: one gearbox tested with two or three oils of one family.

Every oil runs the same speed x torque grid (9-20 points, oil by oil, as a rig changes oil
between test series). The model part of each oil is the binary's map of a derived case whose
`oil:` is that oil (mapped once per case + oil). The recordings carry a column `oil` naming
the oil file by a path relative to the recordings (the oil files are copied to OUT/.../oils/).

Concealed truths, drawn per campaign: a COMMON effect acting for every oil (the in-library
effects of effects.py that do not depend on the oil: windage-like drag, torque-sensor offset,
seal friction, a pump loss, the heat path), a PER-OIL effect acting on one oil only (its
viscosity f times its datasheet's at every temperature, or its mesh friction level off by
15-30 %), or one of each; a per-oil truth is built only where it shows on its oil's points
(its own loss >= 2x the loss noise, or its oil-temperature change >= 2x the temperature noise).
`diagnose` should scope a common effect to all oils ("oil": null) and a per-oil one to that
oil ("oil": the column's text).
"""
import json
import math
import random
import shutil

from .campaigns import choose_points, draw_conditions, record_point, visible_size, write_recordings
from .cases import OILS_DIR, Oil
from .effects import EFFECTS, THERMAL_ONLY, Ctx, Effect
from .heat_balance import T_MAX_NULL, steady_temperature
from .numerics import bisect_root, mean, median

VISIBLE = 2.0  # a per-oil truth must show at least this many noise standard deviations on its oil (per point)
COMMON = ["aero_drag", "sensor_offset", "seal_extra", "pump_loss", "heat_factor"]


class OilStack:
    """The per-oil model tables side by side: index k * n + j is grid point j run with oil k.
    Offers what Ctx, the effects and steady_temperature use of a ModelTable."""

    def __init__(self, tables):
        self.tables, self.n = tables, len(tables[0].points)
        self.points = [p for t in tables for p in t.points]
        self.trange = [r for t in tables for r in t.trange]
        self.speeds, self.torques = tables[0].speeds, tables[0].torques

    def oil_of(self, i):
        return i // self.n

    def get(self, col, i, t):
        return self.tables[i // self.n].get(col, i % self.n, t)


class OilViscosity(Effect):
    """PER-OIL: the oil's viscosity is f times its datasheet's at every temperature, f in
    [1.3, 1.6] or its inverse. Every loss column of that oil is taken at the temperature T'
    where the datasheet oil has f nu(T) (a temperature map, not a factor inside the model)."""
    name = "oil_visc_factor"

    def __init__(self, rng, oil_k, oil):
        super().__init__(rng)
        self.oil_k, self.oil = oil_k, oil

    def setup(self, ctx, r):
        self.f = self.rng.uniform(1.3, 1.6)
        if self.rng.random() < 0.5:
            self.f = 1 / self.f
        self.params = {"viscosity_factor": self.f}

    def t_equiv(self, ctx, i, t):
        target = self.f * self.oil.nu(t)
        lo, hi = ctx.m.trange[i]
        if self.oil.nu(lo) <= target:
            return lo
        if self.oil.nu(hi) >= target:
            return hi
        return bisect_root(lambda x: self.oil.nu(x) - target, lo, hi, 1e-6)

    def dloss(self, ctx, i, t, k):
        if ctx.m.oil_of(i) != self.oil_k:
            return 0.0
        return ctx.m.get("P_total_W", i, self.t_equiv(ctx, i, t)) - ctx.m.get("P_total_W", i, t)

    def truth(self, ctx):
        return self.f


class OilMeshFriction(Effect):
    """PER-OIL: the oil's mesh friction level off by 15-30 % (either sign), varying mildly
    with load: P_mesh (1 + k (T_in/T_med)^c), c in [-0.2, 0.2], for that oil only."""
    name = "oil_mesh_friction"

    def __init__(self, rng, oil_k, oil):
        super().__init__(rng)
        self.oil_k, self.oil = oil_k, oil

    def mine(self, ctx):
        return [i for i in ctx.pts if ctx.m.oil_of(i) == self.oil_k]

    def applicable(self, ctx):
        share = mean(ctx.m.get("P_mesh_W", i, ctx.t0[i]) / ctx.p0[i] for i in self.mine(ctx))
        return share > 0.1, f"mesh share {100 * share:.0f} %"

    def setup(self, ctx, r):
        self.k = self.rng.choice([-1, 1]) * self.rng.uniform(0.15, 0.30)
        self.c = self.rng.uniform(-0.2, 0.2)
        self.tmed = median(ctx.tq[i] for i in self.mine(ctx))
        self.params = {"k": self.k, "torque_exponent": self.c}

    def factor(self, ctx, i):
        return self.k * (ctx.tq[i] / self.tmed) ** self.c

    def dloss(self, ctx, i, t, k):
        if ctx.m.oil_of(i) != self.oil_k:
            return 0.0
        return ctx.m.get("P_mesh_W", i, t) * self.factor(ctx, i)

    def truth(self, ctx):  # the mesh-loss-weighted mean factor over that oil's points
        w = [(ctx.m.get("P_mesh_W", i, ctx.t0[i]), 1 + self.factor(ctx, i)) for i in self.mine(ctx)]
        return sum(a * b for a, b in w) / sum(a for a, _ in w)


def build_multi_oil_campaign(spec, c, outdir):
    """spec: dict(case, seed, tag, kind = common | per_oil | both); c: the PreparedCase.
    Writes recordings.csv (with the `oil` column), oils/*.yaml and truth.json."""
    rng = random.Random(f"{spec['case']}|{spec['tag']}|{spec['seed']}")
    if not c.family:
        return None, "no other oil of the case's oil family in configs/oils"
    names = rng.sample(c.family, rng.choice([2, 3]))
    tables = []
    for nm in names:
        t, why = c.oil_table(nm)
        if t is None:
            return None, f"oil {nm}: {why}"
        tables.append(t)
    stack = OilStack(tables)
    oils = [Oil(OILS_DIR / f"{nm}.yaml") for nm in names]
    column = [f"oils/{nm}.yaml" for nm in names]
    grid = choose_points(stack, rng, max_points=20)
    allp = [k * stack.n + j for k in range(len(names)) for j in grid]
    ctx = Ctx(stack, c.oil, allp, c.heat, rng)
    bad = set()
    for i in allp:  # a grid point is run only if every oil reaches a null equilibrium below the limit
        t = steady_temperature(ctx, i, c.ambient, [], 0)
        if t is None or t > T_MAX_NULL:
            bad.add(i % stack.n)
            continue
        ctx.t0[i], ctx.p0[i] = t, stack.get("P_total_W", i, t)
    grid = [j for j in grid if j not in bad]
    if len(grid) < 9:
        return None, "fewer than 9 points per oil with a null equilibrium for every oil"
    ctx.pts = pts = [k * stack.n + j for k in range(len(names)) for j in grid]
    ctx.t0, ctx.p0 = {i: ctx.t0[i] for i in pts}, {i: ctx.p0[i] for i in pts}
    ctx.n_med = median(ctx.n[i] for i in pts)
    # the concealed truths
    kind, fixed = spec["kind"], c.heat.kind == "fixed"
    effects, scope = [], []
    if kind in ("common", "both"):
        e = None
        for name in rng.sample(COMMON, len(COMMON)):  # the first applicable one in a drawn order
            if fixed and name in THERMAL_ONLY:
                continue
            cand = EFFECTS[name](random.Random(f"{spec['case']}|{spec['tag']}|{spec['seed']}|{name}"))
            if not hasattr(cand, "applicable") or cand.applicable(ctx)[0]:
                e = cand
                break
        if e is None:
            return None, "no common effect applicable"
        r = rng.uniform(0.06, 0.12) if kind == "common" else rng.uniform(0.05, 0.10)
        e.setup(ctx, r)
        e.params["size_r"] = r
        effects.append(e)
        scope.append(None)
    if kind in ("per_oil", "both"):
        k = rng.randrange(len(names))
        sub = random.Random(f"{spec['case']}|{spec['tag']}|{spec['seed']}|per_oil")
        e = OilMeshFriction(sub, k, oils[k]) if rng.random() < 0.5 else OilViscosity(sub, k, oils[k])
        if hasattr(e, "applicable") and not e.applicable(ctx)[0]:
            e = OilViscosity(sub, k, oils[k])
        e.setup(ctx, None)
        effects.append(e)
        scope.append(column[k])
    # test order: oil by oil; inside an oil speed outer / torque inner, or shuffled
    shuffled = rng.random() < 0.5
    order = []
    for k in range(len(names)):
        block = [k * stack.n + j for j in grid]
        if shuffled:
            rng.shuffle(block)
        order += block
    nrows = len(order)
    drift, s_loss, s_temp, fmt = draw_conditions(rng)
    rows, truth_rows = [], []
    visible = [([], []) for _ in effects]  # per-oil effects: own |dP|/P and T - T_null on that oil's rows
    for k, i in enumerate(order):
        ta = c.ambient + drift * (k / max(nrows - 1, 1) - 0.5)
        oil_col = column[stack.oil_of(i)]
        row, trow = record_point(ctx, i, ta, effects, k, nrows, s_loss, s_temp, rng)
        truth_rows.append(dict(oil=oil_col, **trow))
        if row is None:
            continue
        rows.append(dict(oil=oil_col, **row))
        t, t_null = trow["oil_temp_C"], steady_temperature(ctx, i, ta, [], k)
        truth_rows[-1]["null_oil_temp_C"] = t_null
        for j, e in enumerate(effects):
            if scope[j] == oil_col:
                visible[j][0].append(abs(e.dloss(ctx, i, t, k)) / trow["P_model_W"])
                if t_null is not None:
                    visible[j][1].append(t - t_null)
    per_oil = {col: sum(1 for r in rows if r["oil"] == col) for col in column}
    if min(per_oil.values()) < 9:
        return None, "fewer than 9 points with an equilibrium for one oil"
    # a per-oil truth is built only when it shows on its oil's points: its own loss >= VISIBLE x the loss
    # noise (mean), or (stabilised) its oil temperature change >= VISIBLE x the temperature noise (RMS)
    for j, e in enumerate(effects):
        if scope[j] is None:
            continue
        dl = mean(visible[j][0])
        dt = math.sqrt(mean(x * x for x in visible[j][1])) if visible[j][1] and not fixed else 0.0
        e.params["visible_loss_rel"], e.params["visible_temp_rms_K"] = dl, dt
        if dl < VISIBLE * s_loss and dt < VISIBLE * s_temp:
            return None, (f"per-oil {e.name} on {scope[j]} below {VISIBLE:g}x the noise (loss {100 * dl:.1f} % vs "
                          f"{100 * s_loss:.1f} %, oil temperature {dt:.2f} K vs {s_temp:.2f} K)")
    fmt, unchanged = write_recordings(outdir, rows, fmt, lead=["oil"])
    (outdir / "oils").mkdir(exist_ok=True)
    for nm in names:
        shutil.copyfile(OILS_DIR / f"{nm}.yaml", outdir / "oils" / f"{nm}.yaml")
    size_loss, size_temp = visible_size([x for x in truth_rows if "dropped" not in x], fixed)
    truth = {"case": spec["case"], "tag": spec["tag"], "seed": spec["seed"], "category": spec["category"],
             "kind": kind, "oils": [{"name": nm, "column": col} for nm, col in zip(names, column)],
             "effects": [{"name": e.name, "oil": sc, "params": e.params, "truth_parameter": e.truth(ctx)}
                         for e, sc in zip(effects, scope)],
             "points": len(rows), "points_per_oil": per_oil, "dropped_points": len(truth_rows) - len(rows),
             "noise_loss": s_loss, "noise_temp_K": s_temp, "ambient_drift_K": drift,
             "order": "oil by oil, " + ("shuffled" if shuffled else "speed outer, torque inner"),
             "format": fmt, "heat": c.heat.kind, "size_loss_rel": size_loss, "size_temp_rms_K": size_temp,
             "recordings_unchanged": unchanged, "rows": truth_rows}
    (outdir / "truth.json").write_text(json.dumps(truth, indent=1))
    return truth, None
