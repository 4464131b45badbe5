"""Properties over whole runs: cold against warm start on the shipped drive cycles, and the
ranking of two shipped oils along oil-temperature sweeps."""
import csv
import glob
import io
import math
import os

from gearloss_cli import ToolFailure
from properties import PHYSICS, find_steps, regime_changes

# Soaked starts (the whole transmission and the ambient at the start temperature) and two tepid
# starts in a 25 degC ambient: every one is colder than the 90 degC warm-start reference, so its
# oil is thicker during the whole cycle and its drag losses larger.
COLD_STARTS = [(-30, None), (-10, None), (10, None), (50, 25), (70, 25)]
QUICK_STARTS = [(-10, None), (50, 25)]


def vehicle_cases(shipped):
    out = []
    for c in shipped:
        with open(c) as f:
            if any(line.startswith("vehicle:") for line in f):
                out.append(c)
    return out


def check_cold_start(gl, src, shipped, quick, pool, F):
    """A cold start costs more transmission loss than the warm start (gearbox_loss_kJ of the
    cycle JSON's 'start' against 'warm_start'), on every shipped cycle, with the case's oil and
    (full run) every shipped oil. A cycle that stops with an error fails too."""
    cycles = sorted(glob.glob(os.path.join(src, "configs", "cycles", "*.csv")))
    oils = sorted(glob.glob(os.path.join(src, "configs", "oils", "*.yaml")))
    jobs = []
    for case in vehicle_cases(shipped):
        for cyc in cycles:
            for start, amb in (QUICK_STARTS if quick else COLD_STARTS):
                jobs.append((case, cyc, start, amb, None))
            if not quick:
                for oil in oils:
                    for start, amb in COLD_STARTS:
                        jobs.append((case, cyc, start, amb, oil))
    futures = [(j, pool.submit(gl.cycle, j[0], j[1], j[2], j[3], j[4])) for j in jobs]
    F.count("cold_start", len(jobs))
    for (case, cyc, start, amb, oil), f in futures:
        label = os.path.relpath(case, src)
        what = (f"cycle {os.path.basename(cyc)}, start {start} degC"
                + (f" (ambient {amb} degC)" if amb is not None else " (soaked)")
                + (f", oil {os.path.basename(oil)}" if oil else ""))
        try:
            d = f.result()
        except ToolFailure as e:
            F.fail("cold_start", label, "-", f"{what}: the cycle did not run: {e}", 1.0)
            continue
        cold, warm = d["start"], d["warm_start"]
        # The transmission's loss as `cycle` states it ("cold start costs ... more transmission
        # loss"): the gearbox's mechanisms plus the torque converter where there is one.
        lc = cold["gearbox_loss_kJ"] + cold.get("converter_kJ", 0.0)
        lw = warm["gearbox_loss_kJ"] + warm.get("converter_kJ", 0.0)
        if not lc > lw:
            parts = ", ".join(f"{k[:-3]} {cold[k] - warm[k]:+.2f}" for k in cold
                              if k.endswith("_kJ") and k != "gearbox_loss_kJ"
                              and k != "heat_to_ambient_kJ" and cold[k] != warm[k])
            F.fail("cold_start", label, "total",
                   f"{what}: cold {lc:.2f} kJ <= warm {lw:.2f} kJ "
                   f"(cold - warm by mechanism, kJ: {parts})", (lw - lc) / lw)


def check_oil_ranking(gl, src, shipped, quick, pool, F, case_axes):
    """Along an oil-temperature sweep (ln P over T) and a speed sweep (ln P over ln n), the
    difference of two oils' total loss may change sign, but only where both curves are smooth:
    a sign change at an interval where either oil's curve steps is a ranking flipped by a regime
    artefact. Every pair of shipped oils, on every shipped case: the temperature sweep at half
    and all of the case's largest torque, at a quarter and all of its largest speed; the speed
    sweep (a tenth to all of the largest speed) at -10, 20, 60 and 100 degC."""
    oils = sorted(glob.glob(os.path.join(src, "configs", "oils", "*.yaml")))
    names = [os.path.splitext(os.path.basename(o))[0] for o in oils]
    temps = list(range(-30, 151, 6 if quick else 3))
    cases = list(shipped)[:2] if quick else list(shipped)
    for case in cases:
        label = os.path.relpath(case, src)
        n_max, t_max = case_axes(gl, case)
        torques = [t_max / 2, t_max]
        runs = [(T, [n_max / 4, n_max]) for T in temps]
        runs += [(T, [n_max * k / 10 for k in range(1, 11)]) for T in (-10, 20, 60, 100)]
        table = {}
        explain = _regime_explainer(gl, case, dict(zip(names, oils)))
        futures = [(T, pool.submit(_compare, gl, case, oils, T, sp, torques)) for T, sp in runs]
        for T, f in futures:
            try:
                for r in f.result():
                    for col, v in r.items():
                        for nm in names:
                            if col.startswith("P_") and col.endswith(f"_{nm}_W"):
                                table[(T, float(r["speed_in_rpm"]), float(r["torque_in_Nm"]), nm,
                                       col[:-len(f"_{nm}_W")])] = (
                                    float(v) if v not in ("", None) else float("nan"))
            except ToolFailure as e:
                F.fail("oil_ranking", label, "-", f"compare at {T} degC did not run: {e}", 1.0)
        for M in torques:
            for n in runs[0][1]:
                pts = [(T, n, M) for T in temps if (T, n, M, names[0], "P_total") in table]
                _flips(F, label, table, names, pts, [p[0] for p in pts], "degC", explain)
            for T in (-10, 20, 60, 100):
                pts = sorted(k[:3] for k in table if k[0] == T and k[2] == M and k[3] == names[0]
                             and k[4] == "P_total" and k[1] > 0)
                _flips(F, label, table, names, pts, [math.log(p[1]) for p in pts], "rpm", explain)


def _compare(gl, case, oils, T, speeds, torques):
    args = ["compare", case]
    for o in oils:
        args += ["--oil", o]
    args += ["--speed", ",".join(f"{s:g}" for s in speeds) + "rpm",
             "--torque", ",".join(f"{t:g}" for t in torques) + "Nm", "--threads", "1", "--detail",
             "--oil-temp", f"{T}degC", "-o", "-"]
    return list(csv.DictReader(io.StringIO(gl.run(args).stdout)))


# Mechanisms whose loss steps or falls where a regime that `point` names changes (PHYSICS
# speed_falls_in: an open clutch pack whose film breaks up, Yuan et al. 2007): a ranking flip
# or a fall of the stabilised oil temperature that such a change explains is physics.
REGIME_MECHANISMS = {"clutch_drag": "P_clutch"}
assert all(PHYSICS[m].get("speed_falls_in") for m in REGIME_MECHANISMS)


def _regime_explainer(gl, case, oil_paths):
    """A function (oil name, part, point a, point b) -> the regime change of that part's mechanism
    that `point` names between a and b (points (T degC, n rpm, M N*m)), or None."""
    def explain(nm, part, a, b):
        for mech, prefix in REGIME_MECHANISMS.items():
            if not part.startswith(prefix):
                continue
            ra = gl.point_regimes(case, a[1], a[2], a[0], oil_paths.get(nm))
            rb = gl.point_regimes(case, b[1], b[2], b[0], oil_paths.get(nm))
            changed = regime_changes(ra, rb, mech, with_status=False)
            if changed:
                return ", ".join(f"{c} {ra.get(c)} -> {rb.get(c)}" for c in changed)
        return None
    return explain


def _flips(F, label, table, names, pts, xs, unit, explain=None):
    """Sign changes of P_a - P_b between neighbouring points where a or b steps (5 %). A flip is
    excused where every stepping oil steps most in a mechanism whose named regime changes there
    (`explain`, _regime_explainer): in the interval itself or in one of its two neighbours, the
    intervals whose slopes find_steps takes as the trend (a kink there, e.g. the peak of an open
    pack's drag, makes the trend predict a change the interval does not have)."""
    def P(p, nm, part="P_total"):
        return table.get((p[0], p[1], p[2], nm, part), float("nan"))

    def stepping(nm, j):
        """The mechanism of oil nm that steps most at interval j (else: changes most there)."""
        parts = sorted({k[4] for k in table if k[3] == nm and k[4] != "P_total"})
        excess = {c: dict(find_steps(xs, [P(p, nm, c) for p in pts], tol=0.05)).get(j, 0.0)
                  for c in parts}
        best = max(parts, key=lambda c: excess[c])
        if excess[best] > 0:
            return best

        def off_trend(c):   # |change at j - mean change of its neighbours| [W]
            v = [P(pts[k], nm, c) for k in range(max(j - 1, 0), min(j + 3, len(pts)))]
            d = [b - a for a, b in zip(v, v[1:])]
            mid = 1 if j > 0 else 0
            others = [x for k, x in enumerate(d) if k != mid] or [0.0]
            return abs(d[mid] - sum(others) / len(others)) if len(d) > mid else 0.0
        return max(parts, key=off_trend)

    def where(p):
        return f"({p[1]:g} rpm, {p[2]:g} N*m, {p[0]} degC)"
    steps = {nm: {i for i, _ in find_steps(xs, [P(p, nm) for p in pts], tol=0.05)} for nm in names}
    F.count("oil_ranking", len(names) * (len(names) - 1) // 2)
    for i, a in enumerate(names):
        for b in names[i + 1:]:
            D = [P(p, a) - P(p, b) for p in pts]
            for j in range(len(pts) - 1):
                if D[j] * D[j + 1] < 0 and (j in steps[a] or j in steps[b]):
                    s = a if j in steps[a] else b
                    if explain:
                        def regime_near(o):
                            part = stepping(o, j)
                            for k in (j, j - 1, j + 1):
                                if 0 <= k < len(pts) - 1:
                                    w = explain(o, part, pts[k], pts[k + 1])
                                    if w:
                                        return w if k == j else f"{w} (neighbouring interval)"
                            return None
                        why = [regime_near(o) for o in (a, b) if j in steps[o]]
                        if all(why):
                            F.named.append(f"{label}: {a} vs {b}: ranking flips between "
                                           f"{where(pts[j])} and {where(pts[j + 1])}: regime "
                                           f"{'; '.join(why)}")
                            continue
                    F.fail("oil_ranking", label, f"{a} vs {b}",
                           f"ranking flips between {where(pts[j])} and {where(pts[j + 1])} where "
                           f"{s} steps (most in {stepping(s, j)}) ({a}: {P(pts[j], a):.4g} -> "
                           f"{P(pts[j + 1], a):.4g} W, {b}: {P(pts[j], b):.4g} -> "
                           f"{P(pts[j + 1], b):.4g} W)", abs(D[j]) + abs(D[j + 1]))


def check_thermal(gl, case, label, speeds, torques, F, mechs=()):
    """The stabilised oil temperature (the case's own thermal solve, no --oil-temp): at least
    the ambient wherever the box turns (its losses heat it, nothing cools it below the air);
    not lower at a larger torque >= 0 (every loss is then at least as large at every oil
    temperature, so the balance P_loss(T) = Q(T) settles no lower); not lower at a higher speed
    unless the case's heat rejection grows with speed (reference_speed, cooling_per_1000rpm).
    A lower oil temperature is excused only where a mechanism of REGIME_MECHANISMS among the
    case's `mechs` names a regime change between the two points, each at its own stabilised oil
    temperature (an open pack's film breaking up sheds its drag, so the balance settles lower)."""
    with open(case) as f:
        text = f.read()
    rows = gl.map(case, None, speeds, torques)
    T = {(r["speed_in_rpm"], r["torque_in_Nm"]): r for r in rows}
    temps = {r["oil_temp_C"] for r in rows if isinstance(r["oil_temp_C"], float)}
    if len(temps) <= 1:
        return   # a fixed-temperature case: nothing is solved
    F.count("thermal")
    ok = lambda r: r["status"] in ("ok", "above_oil_limit")
    for (n, M), r in T.items():
        if n > 0 and ok(r) and not r["oil_temp_C"] >= r["ambient_temp_C"] - 1e-6:
            F.fail("thermal", label, "oil temperature",
                   f"{r['oil_temp_C']:.3f} degC below the ambient {r['ambient_temp_C']:.2f} degC at "
                   f"{n:g} rpm, {M:g} N*m", r["ambient_temp_C"] - r["oil_temp_C"])
    speed_cooled = "reference_speed" in text or "cooling_per_1000rpm" in text
    ns = sorted({k[0] for k in T if k[0] > 0})
    ms = sorted({k[1] for k in T if k[1] >= 0})
    chains = [[(n, M) for M in ms] for n in ns]
    if not speed_cooled:
        chains += [[(n, M) for n in ns] for M in ms]
    for chain in chains:
        for a, b in zip(chain, chain[1:]):
            ra, rb = T[a], T[b]
            if ok(ra) and ok(rb) and rb["oil_temp_C"] < ra["oil_temp_C"] - 0.01:
                why = _thermal_regime_change(gl, case, mechs, a, ra["oil_temp_C"], b, rb["oil_temp_C"])
                if why:
                    F.named.append(f"{label}: oil temperature: stabilised {ra['oil_temp_C']:.2f} -> "
                                   f"{rb['oil_temp_C']:.2f} degC from ({a[0]:g} rpm, {a[1]:g} N*m) to "
                                   f"({b[0]:g} rpm, {b[1]:g} N*m): regime {why}")
                    continue
                F.fail("thermal", label, "oil temperature",
                       f"stabilised oil {ra['oil_temp_C']:.2f} -> {rb['oil_temp_C']:.2f} degC from "
                       f"({a[0]:g} rpm, {a[1]:g} N*m) to ({b[0]:g} rpm, {b[1]:g} N*m): more load or "
                       f"speed, cooler oil", ra["oil_temp_C"] - rb["oil_temp_C"])


def _thermal_regime_change(gl, case, mechs, a, Ta, b, Tb):
    names = [m[0] for m in mechs if m[0] in REGIME_MECHANISMS]
    if not names:
        return None
    ra = gl.point_regimes(case, a[0], a[1], Ta)
    rb = gl.point_regimes(case, b[0], b[1], Tb)
    for mech in names:
        changed = regime_changes(ra, rb, mech, with_status=False)
        if changed:
            return ", ".join(f"{c} {ra.get(c)} -> {rb.get(c)}" for c in changed)
    return None
