#!/usr/bin/env python3
"""Operating-envelope property suite (docs/envelope.md): every shipped
case (configs/*.yaml) and seeded generated gearboxes, swept over oil temperature -30..150 degC,
speed 0..max and torque -max..max through the command line, checked for
  runs          every valid point and cycle is computed (exit 0, finite values)
  turning       losses > 0 whenever the box turns (per mechanism where its physics says so)
  warming       dP/dT_oil <= 0 for the losses that must fall or stay as the oil warms
  speed         dP/dn >= 0
  load          dP/d|torque| as each mechanism's physics requires
  step          no step between neighbouring grid points without a regime change the tool names
  thermal       the stabilised oil temperature is above the ambient and rises with load and speed
  cold_start    on every shipped cycle, a cold start costs more than the warm start
  oil_ranking   the loss difference of two shipped oils changes sign only continuously
Exit 1 when any property fails; the report lists case, mechanism, property and the values.

    run_envelope.py --binary build/app/gearloss --source . [--quick] [--property P ...]
                    [--report failures.json] [--generated N] [--seed S]
"""
import argparse
import concurrent.futures as cf
import glob
import json
import math
import os
import shutil
import sys
import time

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from gearloss_cli import Gearloss, ToolFailure  # noqa: E402
from generate_cases import write_cases  # noqa: E402
from properties import (PHYSICS, WARMING_RISE_PER_2K, Findings, find_steps, regime_changes,  # noqa: E402
                        regimes_in)
import envelope_cycles  # noqa: E402

PROPERTIES = ["runs", "turning", "warming", "speed", "load", "step", "thermal", "cold_start",
              "oil_ranking"]


def case_axes(gl, case):
    """The largest speed and torque of the case's own operating block (grid or point list)."""
    rows = gl.map(case, 60, None, None)
    return max(r["speed_in_rpm"] for r in rows), max(r["torque_in_Nm"] for r in rows)


def sweep(gl, case, temps, speeds, torques, pool):
    """{T: rows} of `map --detail` at each fixed oil temperature (one map per temperature)."""
    futures = {T: pool.submit(gl.map, case, T, speeds, torques) for T in temps}
    out, errors = {}, []
    for T, f in futures.items():
        try:
            out[T] = f.result()
        except ToolFailure as e:
            errors.append((T, str(e)))
    return out, errors


def columns_of(mech_list):
    return [(name, col, comps) for name, col, comps in mech_list]


def check_case(gl, case, label, quick, pool, F, props):
    n_max, t_max = case_axes(gl, case)
    speeds = [0.0] + [round(n_max * k / 10.0, 6) for k in range(1, 11)]
    fr = [-1.0, -0.5, -0.25, 0.0] + [k / 10.0 for k in range(1, 11)]
    torques = [round(t_max * f, 6) for f in fr]
    temps = list(range(-30, 151, 6 if quick else 3))
    mechs = gl.mechanisms(case)
    if "thermal" in props:
        envelope_cycles.check_thermal(gl, case, label, speeds, torques, F, mechs)
    if not props - {"thermal"}:
        return n_max, t_max
    data, errors = sweep(gl, case, temps, speeds, torques, pool)
    F.count("runs", len(temps))
    for T, e in errors:
        F.fail("runs", label, "-", f"map at {T} degC: {e}", 1.0)
    temps = [T for T in temps if T in data]
    # index rows by (T, n, M)
    P = {}
    for T in temps:
        for r in data[T]:
            P[(T, r["speed_in_rpm"], r["torque_in_Nm"])] = r
    speeds = sorted({k[1] for k in P})
    torques = sorted({k[2] for k in P})

    def val(T, n, M, col):
        v = P[(T, n, M)].get(col, float("nan"))
        return v if isinstance(v, float) else float("nan")

    for name, col, comps in mechs:
        phys = PHYSICS.get(name, {})
        cols = [col] + [c for c in comps]
        # runs: no empty value where the point's status is ok
        if "runs" in props:
            bad = [(k, c) for k, r in P.items() for c in cols
                   if r["status"] == "ok" and not math.isfinite(val(*k, c))]
            if bad:
                (T, n, M), c = bad[0]
                F.fail("runs", label, name, f"{len(bad)} empty/non-finite values, e.g. {c} at "
                       f"{n:g} rpm {M:g} N*m {T} degC", 1.0)
        if "turning" in props:
            check_turning(F, label, name, col, phys, temps, speeds, torques, val)
        if "warming" in props and phys.get("warming") == -1:
            for c in cols:
                check_warming(F, label, name, c, temps, speeds, torques, val)
        if "speed" in props and phys.get("speed") == +1:
            check_monotone(F, "speed", label, name, col, temps, speeds, torques, val, axis="n",
                           excuse=speed_fall_excuse(gl, case, name, phys, pool))
        if "load" in props and phys.get("load"):
            check_load(F, label, name, col, phys["load"], temps, speeds, torques, val)
        if "step" in props:
            check_steps(gl, F, case, label, name, col, temps, speeds, torques, val)
    if "turning" in props:
        check_turning(F, label, "total", "P_total_W", dict(turning=True), temps, speeds, torques,
                      val, any_torque=True)
    return n_max, t_max


def check_turning(F, label, name, col, phys, temps, speeds, torques, val, any_torque=False):
    """Turning means losing power: P_total > 0 at every point with n > 0 (any torque, sign
    included); a mechanism whose physics does not hang on the load (drag, seals, bearings under
    their shafts' weights) and that loses power at some torque at a speed and oil temperature
    loses power at every torque there."""
    if not (phys.get("turning") or any_torque):
        return
    F.count("turning")
    for T in temps:
        for n in speeds:
            if n <= 0:
                continue
            vs = [(M, val(T, n, M, col)) for M in torques]
            if any_torque:
                zero = [(M, v) for M, v in vs if not v > 0]
            else:
                if not any(v > 0 for _, v in vs):
                    continue
                zero = [(M, v) for M, v in vs if not v > 0]
            if zero:
                live = max(v for _, v in vs)
                F.fail("turning", label, name, f"{col} = {zero[0][1]:g} W at {n:g} rpm, "
                       f"{zero[0][0]:g} N*m, {T} degC (up to {live:.4g} W at other torques; "
                       f"{len(zero)} torques)", live)


def check_warming(F, label, name, col, temps, speeds, torques, val):
    F.count("warming")
    for n in speeds:
        for M in torques:
            for T0, T1 in zip(temps, temps[1:]):
                p0, p1 = val(T0, n, M, col), val(T1, n, M, col)
                if not (p0 > 0 and p1 > 0):
                    continue
                allowed = (1.0 + WARMING_RISE_PER_2K) ** ((T1 - T0) / 2.0)
                if p1 > p0 * allowed:
                    rise = p1 / p0 - 1.0
                    F.fail("warming", label, name, f"{col} rises {100 * rise:.1f} % from {T0} to "
                           f"{T1} degC ({p0:.4g} -> {p1:.4g} W) at {n:g} rpm, {M:g} N*m "
                           f"(allowed {100 * (allowed - 1):.1f} %)", rise)


def speed_fall_excuse(gl, case, name, phys, pool=None):
    """For a mechanism whose physics names regimes in which its loss may fall with speed
    (PHYSICS speed_falls_in, e.g. an open clutch pack whose film breaks up): a function
    (T, n0, n1, M) -> the reason a fall there is physics (components in such a regime at either
    end, as `point` names them), or None. A load-free mechanism is queried once per (T, n)."""
    wanted = phys.get("speed_falls_in")
    if not wanted:
        return None
    seen = {}

    def key_of(T, n, M):
        return (T, n) if phys.get("load") == "none" else (T, n, M)

    def regimes(T, n, M):
        key = key_of(T, n, M)
        if key not in seen:
            seen[key] = gl.point_regimes(case, n, M, T)
        return seen[key]

    def prefetch(points):
        """Query the distinct points of `points` [(T, n, M)] side by side (the pool's jobs)."""
        todo = {key_of(*p): p for p in points if key_of(*p) not in seen}
        if pool is None or not todo:
            return
        futures = {k: pool.submit(gl.point_regimes, case, p[1], p[2], p[0]) for k, p in todo.items()}
        for k, f in futures.items():
            seen[k] = f.result()

    across = phys.get("speed_falls_across")

    def excuse(T, n0, n1, M):
        r0, r1 = regimes(T, n0, M), regimes(T, n1, M)
        named = sorted(set(regimes_in(r0, name, wanted)) | set(regimes_in(r1, name, wanted)))
        if named:
            return f"{', '.join(named)} in {'/'.join(wanted)}"
        if across:
            passed = [k for k in regimes_in(r0, name, (across[0],)) if r1.get(k) == across[1]]
            if passed:
                return f"{', '.join(passed)} {across[0]} -> {across[1]}"
        return None
    excuse.prefetch = prefetch
    return excuse


def check_monotone(F, prop, label, name, col, temps, speeds, torques, val, axis, excuse=None):
    F.count(prop)
    if excuse is not None:
        ends = []
        for T in temps:
            for M in torques:
                seq = [(n, val(T, n, M, col)) for n in speeds]
                ends += [p for (n0, p0), (n1, p1) in zip(seq, seq[1:])
                         if p1 < p0 * (1 - 1e-6) - 1e-9 for p in ((T, n0, M), (T, n1, M))]
        excuse.prefetch(ends)
    for T in temps:
        for M in torques:
            seq = [(n, val(T, n, M, col)) for n in speeds]
            for (n0, p0), (n1, p1) in zip(seq, seq[1:]):
                if p1 < p0 * (1 - 1e-6) - 1e-9:
                    drop = (p0 - p1) / p0
                    where = (f"{col} falls {100 * drop:.2f} % from {n0:g} to {n1:g} rpm "
                             f"({p0:.4g} -> {p1:.4g} W) at {M:g} N*m, {T} degC")
                    why = excuse(T, n0, n1, M) if excuse else None
                    if why:
                        F.named.append(f"{label}: {name}: {where}: regime {why}")
                        continue
                    F.fail(prop, label, name, where, drop)


def check_load(F, label, name, col, kind, temps, speeds, torques, val):
    F.count("load")
    pos = [M for M in torques if M >= 0]
    neg = sorted((M for M in torques if M <= 0), reverse=True)   # 0, -0.25, -0.5, -1 of max
    for T in temps:
        for n in speeds:
            if n <= 0:
                continue
            if kind == "none":
                ref = val(T, n, 0.0, col)
                for M in torques:
                    v = val(T, n, M, col)
                    if abs(v - ref) > 1e-6 * max(abs(ref), 1e-3):
                        F.fail("load", label, name, f"{col} depends on torque: {ref:.6g} W at 0 "
                               f"and {v:.6g} W at {M:g} N*m ({n:g} rpm, {T} degC)",
                               abs(v - ref) / max(ref, 1e-9))
                continue
            chains = [pos, neg] if kind == "abs" else [pos, [0.0, neg[-1]]]
            for chain in chains:
                seq = [(M, val(T, n, M, col)) for M in chain]
                for (M0, p0), (M1, p1) in zip(seq, seq[1:]):
                    if p1 < p0 * (1 - 1e-6) - 1e-9:
                        drop = (p0 - p1) / p0
                        F.fail("load", label, name, f"{col} falls {100 * drop:.2f} % from {M0:g} "
                               f"to {M1:g} N*m ({p0:.4g} -> {p1:.4g} W) at {n:g} rpm, {T} degC",
                               drop)


def check_steps(gl, F, case, label, name, col, temps, speeds, torques, val, max_queries=40):
    """Steps along oil temperature (ln P over T), speed (ln P over ln n) and positive torque
    (ln P over ln M). A step is excused when `point` names a different regime (or status) of
    this mechanism at its two ends."""
    F.count("step")
    found = []
    for n in speeds:
        for M in torques:
            for i, ex in find_steps(temps, [val(T, n, M, col) for T in temps]):
                found.append((ex, (temps[i], n, M), (temps[i + 1], n, M), "oil temperature"))
    ln_n = [math.log(n) for n in speeds if n > 0]
    sp = [n for n in speeds if n > 0]
    mp = [M for M in torques if M > 0]
    ln_m = [math.log(M) for M in mp]
    for T in temps:
        for M in torques:
            for i, ex in find_steps(ln_n, [val(T, n, M, col) for n in sp]):
                found.append((ex, (T, sp[i], M), (T, sp[i + 1], M), "speed"))
        for n in sp:
            for i, ex in find_steps(ln_m, [val(T, n, M, col) for M in mp]):
                found.append((ex, (T, n, mp[i]), (T, n, mp[i + 1]), "torque"))
    found.sort(key=lambda f: -f[0])
    # A load-free mechanism steps alike at every torque: one query per distinct step.
    unique, seen = [], set()
    for f in found:
        key = (f[3], f[1][0], f[2][0], f[1][1], f[2][1], round(val(*f[1], col), 9),
               round(val(*f[2], col), 9))
        if key not in seen:
            seen.add(key)
            unique.append(f)
    found = unique
    for k, (ex, a, b, axis) in enumerate(found):
        pa, pb = val(*a, col), val(*b, col)
        where = (f"{col} {pa:.4g} -> {pb:.4g} W between ({a[1]:g} rpm, {a[2]:g} N*m, {a[0]} degC) "
                 f"and ({b[1]:g} rpm, {b[2]:g} N*m, {b[0]} degC) along {axis}, "
                 f"{100 * (math.exp(ex) - 1):.0f} % beyond the neighbours' trend")
        if k < max_queries:
            ra = gl.point_regimes(case, a[1], a[2], a[0])
            rb = gl.point_regimes(case, b[1], b[2], b[0])
            changed = regime_changes(ra, rb, name)
            if changed:
                F.named.append(f"{label}: {name}: {where}: regime {', '.join(f'{c} {ra.get(c)} -> {rb.get(c)}' for c in changed)}")
                continue
            F.fail("step", label, name, where + " (no regime change named)", ex)
        else:
            F.fail("step", label, name, where + " (not queried)", ex)


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--binary", required=True)
    ap.add_argument("--source", required=True)
    ap.add_argument("--quick", action="store_true", help="coarser grids, fewer cases and cycles")
    ap.add_argument("--property", action="append", choices=PROPERTIES)
    ap.add_argument("--case", action="append", help="only these case files (default: every shipped case)")
    ap.add_argument("--generated", type=int, default=None, help="number of generated cases")
    ap.add_argument("--seed", type=int, default=2024)
    ap.add_argument("--report", help="write the failures as JSON to this file")
    ap.add_argument("--jobs", type=int, default=2)
    a = ap.parse_args()
    props = set(a.property or PROPERTIES)
    src = os.path.abspath(a.source)
    gl = Gearloss(os.path.abspath(a.binary))
    shipped = a.case or sorted(glob.glob(os.path.join(src, "configs", "*.yaml")))
    n_gen = a.generated if a.generated is not None else (3 if a.quick else 6)
    generated = write_cases(src, os.path.join(gl.workdir, "generated"), a.seed, n_gen)
    F = Findings()
    t0 = time.time()
    with cf.ThreadPoolExecutor(max_workers=a.jobs) as pool:
        grid_props = props & {"runs", "turning", "warming", "speed", "load", "step", "thermal"}
        if grid_props:
            for case in shipped + generated:
                label = os.path.relpath(case, src) if case.startswith(src) else os.path.basename(case)
                try:
                    check_case(gl, case, label, a.quick, pool, F, grid_props)
                except ToolFailure as e:
                    F.fail("runs", label, "-", str(e), 1.0)
                print(f"  {label}: grid checked ({time.time() - t0:.0f} s)", flush=True)
        if "cold_start" in props:
            envelope_cycles.check_cold_start(gl, src, shipped, a.quick, pool, F)
            print(f"  cycles checked ({time.time() - t0:.0f} s)", flush=True)
        if "oil_ranking" in props:
            envelope_cycles.check_oil_ranking(gl, src, shipped, a.quick, pool, F, case_axes)
            print(f"  oil rankings checked ({time.time() - t0:.0f} s)", flush=True)
    shutil.rmtree(gl.workdir, ignore_errors=True)
    return report(F, props, a.report, time.time() - t0)


KNOWN_OPEN = os.path.join(os.path.dirname(os.path.abspath(__file__)), "known_open.json")


def known_open_entry(row, entries):
    """The entry of known_open.json a failure group matches (property, case, and the mechanism
    or a text of its worst detail), or None."""
    for e in entries:
        if e["property"] != row["property"] or e["case"] != row["case"]:
            continue
        if "mechanism" in e and e["mechanism"] != row["mechanism"]:
            continue
        if "detail" in e and e["detail"] not in row["detail"]:
            continue
        return e
    return None


def report(F, props, path, seconds):
    with open(KNOWN_OPEN) as f:
        entries = json.load(f)["open"]
    all_rows = F.worst_per_key()
    known = [(r, known_open_entry(r, entries)) for r in all_rows]
    rows = [r for r, e in known if e is None]
    known = [(r, e) for r, e in known if e is not None]
    print(f"\noperating envelope: {sum(r['n'] for r in rows)} failures in {len(rows)} (property, case, mechanism) "
          f"groups, {seconds:.0f} s")
    for p in PROPERTIES:
        if p not in props:
            continue
        mine = [r for r in rows if r["property"] == p]
        print(f"\n[{p}] {'FAIL' if mine else 'pass'} ({F.checked.get(p, 0)} curves/families checked)")
        for r in mine:
            print(f"  {r['case']} | {r['mechanism']} | x{r['n']} | worst: {r['detail']}")
    if known:
        print(f"\nknown open defects (tests/envelope/known_open.json), not counted as failures ({len(known)} groups):")
        for r, e in known:
            print(f"  [{r['property']}] {r['case']} | {r['mechanism']} | x{r['n']}: {e['reason']}; worst: {r['detail']}")
    seen = [e for _, e in known]
    for e in entries:
        if e["property"] in props and e not in seen and any(e["case"] == r.get("case") for r in all_rows + [dict(case=e["case"])]):
            print(f"  no longer seen (remove it from known_open.json when a full run agrees): [{e['property']}] {e['case']}")
    if F.named:
        print(f"\nsteps explained by a named regime change ({len(F.named)}):")
        for s in F.named[:20]:
            print("  " + s)
    if path:
        with open(path, "w") as f:
            json.dump(dict(failures=rows, known_open=[dict(r, reason=e["reason"]) for r, e in known],
                           named_regime_steps=F.named), f, indent=1)
    return 1 if rows else 0


if __name__ == "__main__":
    sys.exit(main())
