"""Properties over whole runs: cold against warm start on the shipped drive cycles, and the
ranking of two shipped oils along oil-temperature sweeps."""
import glob
import os

from gearloss_cli import ToolFailure
from properties import find_steps

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
    """Along an oil-temperature sweep, the difference of two oils' total loss may change sign,
    but only where both curves are smooth: a sign change at an interval where either oil's
    curve steps is a ranking flipped by a regime artefact. Every pair of shipped oils, on every
    shipped case (half and full of the case's largest torque, at a quarter and all of its speed)."""
    oils = sorted(glob.glob(os.path.join(src, "configs", "oils", "*.yaml")))
    names = [os.path.splitext(os.path.basename(o))[0] for o in oils]
    temps = list(range(-30, 151, 6 if quick else 3))
    cases = list(shipped)
    if quick:
        cases = cases[:2]
    for case in cases:
        label = os.path.relpath(case, src)
        n_max, t_max = case_axes(gl, case)
        speeds, torques = [n_max / 4, n_max], [t_max / 2, t_max]
        args = ["compare", case]
        for o in oils:
            args += ["--oil", o]
        args += ["--speed", ",".join(f"{s:g}" for s in speeds) + "rpm",
                 "--torque", ",".join(f"{t:g}" for t in torques) + "Nm", "--threads", "1", "--detail"]

        def run(T):
            import io, csv
            out = gl.run(args + ["--oil-temp", f"{T}degC", "-o", "-"]).stdout
            return list(csv.DictReader(io.StringIO(out)))
        futures = {T: pool.submit(run, T) for T in temps}
        table = {}
        for T, f in futures.items():
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
        got = sorted({k[0] for k in table})
        for n in speeds:
            for M in torques:
                def key(T, nm, part="P_total"):
                    return table.get((T, float(f"{n:g}"), float(f"{M:g}"), nm, part), float("nan"))

                def stepping(nm, j):
                    """The mechanism of oil nm whose change over interval j is largest."""
                    parts = sorted({k[4] for k in table if k[3] == nm and k[4] != "P_total"})
                    return max(parts, key=lambda c: abs(key(got[j + 1], nm, c) - key(got[j], nm, c)))
                steps = {nm: {i for i, _ in find_steps(got, [key(T, nm) for T in got], tol=0.05)}
                         for nm in names}
                F.count("oil_ranking", len(names) * (len(names) - 1) // 2)
                for i, a in enumerate(names):
                    for b in names[i + 1:]:
                        D = [key(T, a) - key(T, b) for T in got]
                        for j in range(len(got) - 1):
                            if D[j] * D[j + 1] < 0 and (j in steps[a] or j in steps[b]):
                                F.fail("oil_ranking", label, f"{a} vs {b}",
                                       f"ranking flips between {got[j]} and {got[j + 1]} degC at "
                                       f"{n:g} rpm, {M:g} N*m where "
                                       f"{a if j in steps[a] else b} steps (most in "
                                       f"{stepping(a if j in steps[a] else b, j)}) "
                                       f"({a}: {key(got[j], a):.4g} -> {key(got[j + 1], a):.4g} W, "
                                       f"{b}: {key(got[j], b):.4g} -> {key(got[j + 1], b):.4g} W)",
                                       abs(D[j]) + abs(D[j + 1]))


def check_thermal(gl, case, label, speeds, torques, F):
    """The stabilised oil temperature (the case's own thermal solve, no --oil-temp): at least
    the ambient wherever the box turns (its losses heat it, nothing cools it below the air);
    not lower at a larger torque >= 0 (every loss is then at least as large at every oil
    temperature, so the balance P_loss(T) = Q(T) settles no lower); not lower at a higher speed
    unless the case's heat rejection grows with speed (reference_speed, cooling_per_1000rpm)."""
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
                F.fail("thermal", label, "oil temperature",
                       f"stabilised oil {ra['oil_temp_C']:.2f} -> {rb['oil_temp_C']:.2f} degC from "
                       f"({a[0]:g} rpm, {a[1]:g} N*m) to ({b[0]:g} rpm, {b[1]:g} N*m): more load or "
                       f"speed, cooler oil", ra["oil_temp_C"] - rb["oil_temp_C"])
