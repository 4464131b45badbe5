"""The heat path re-implemented here, and the steady oil temperature.

Q(T) from a case's `thermal.heat_rejection`: a thermal resistance with the documented
speed dependence R = R0 (n/n_ref)^-b above n_ref, or a textbook housing-surface model
(+ the network's oil-housing conductance in series). steady_temperature solves
P_heat(T) = Q(T) as a rig warming up from ambient would settle. heat_check and
housing_check compare this balance with the binary's own stabilised map.
"""
import math

from .cases import CASES, ROOT, read_thermal
from .effects import Ctx
from .model_table import run_map
from .numerics import bisect_root, mean, median, num

T_MAX_NULL = 125.0  # degC: points whose null oil temperature exceeds this are not run (a rig's limit)


def q_resistance(t_oil, t_amb, n, r0, n_ref=None, b=0.0):
    r = r0
    if n_ref and n > n_ref:
        r = r0 * (n / n_ref) ** (-b)
    return (t_oil - t_amb) / r


def q_housing_textbook(t_oil, t_amb, hs):
    """Housing surface at oil temperature: radiation (emissivity) + mixed convection,
    natural from the vertical-wall correlation README.md documents (Nu = 0.59 Ra^1/4 laminar,
    0.10 Ra^1/3 above Ra = 1e9), forced from the laminar flat plate over the same length,
    combined as (h_n^3 + h_f^3)^(1/3). Air properties at the film temperature (power laws
    fitted to handbook values, not the binary's). Churchill & Chu's correlation, used here
    before, gives 1.5-2 % more heat flow: a heat-path form difference, not a null."""
    a, eps, hgt, v = hs["area"], hs.get("emissivity", 0.9), hs.get("height", 0.3), hs.get("air_speed", 0.0)
    tw, ta = t_oil + 273.15, t_amb + 273.15
    if tw <= ta:
        return 0.0
    tf = 0.5 * (tw + ta)
    k_air = 0.0263 * (tf / 300.0) ** 0.83
    nu_air = 1.589e-5 * (tf / 300.0) ** 1.72
    pr = 0.707
    ra = 9.81 * (1 / tf) * (tw - ta) * hgt ** 3 / (nu_air * nu_air / pr)
    nu_n = 0.59 * ra ** 0.25 if ra < 1e9 else 0.10 * ra ** (1 / 3)
    h_n = nu_n * k_air / hgt
    h_f = 0.664 * math.sqrt(v * hgt / nu_air) * pr ** (1 / 3) * k_air / hgt if v > 0 else 0.0
    h_c = (h_n ** 3 + h_f ** 3) ** (1 / 3)
    h_r = eps * 5.670374e-8 * (tw * tw + ta * ta) * (tw + ta)
    return a * (h_c + h_r) * (tw - ta)


def q_housing_network(t_oil, t_amb, hs, g_oil_housing):
    """Oil -> housing conductance in series with the housing surface: G (T_oil - T_w) = Q_h(T_w)."""
    if g_oil_housing is None:
        return q_housing_textbook(t_oil, t_amb, hs)
    if t_oil <= t_amb:
        return 0.0
    tw = bisect_root(lambda x: g_oil_housing * (t_oil - x) - q_housing_textbook(x, t_amb, hs), t_amb, t_oil, 1e-6)
    return g_oil_housing * (t_oil - tw)


class Heat:
    """The heat path of a case: fixed oil temperature, resistance or housing surface."""

    def __init__(self, case, resistance=None, fixed=None, housing=None, g_oil_housing=None):
        self.kind = "fixed" if fixed is not None else ("housing" if housing else "resistance")
        self.fixed, self.r0, self.housing, self.g = fixed, resistance, housing, g_oil_housing
        self.n_ref, self.b = case.get("ref_speed"), case.get("speed_exponent", 0.0)

    def q(self, t, ta, n):
        if self.kind == "housing":
            return q_housing_network(t, ta, self.housing, self.g)
        return q_resistance(t, ta, n, self.r0, self.n_ref, self.b)


def steady_temperature(ctx, i, ta, effects, k):
    """Oil temperature of point i: the first crossing P_heat(T) = Q(T) when warming up from
    the ambient (the stable state a rig reaches), or the fixed temperature."""
    m = ctx.m
    if ctx.heat.kind == "fixed":
        return ctx.heat.fixed

    def f(t):
        p = m.get("P_total_W", i, t) + sum(e.dloss(ctx, i, t, k) for e in effects if e.heats)
        q = ctx.heat.q(t, ta, ctx.n[i])
        for e in effects:
            q *= e.qmult(ctx, i, t)
        return p - q
    lo, hi = m.trange[i]
    t = max(ta + 0.05, lo)
    ft = f(t)
    if ft <= 0:
        return None
    while t < hi:
        t2 = min(t + 1.0, hi)
        f2 = f(t2)
        if f2 <= 0:
            return bisect_root(f, t, t2)
        t = t2
    return None  # no equilibrium inside the mapped range


def noiseless_point(ctx, i, ta, effects, k, nrows):
    """Point i in row k without noise: (oil temperature, model loss, true loss, recorded input
    torque, recorded loss), or None without an equilibrium. The recorded loss is the true loss
    plus what the torque artefacts add to in - out power."""
    t = steady_temperature(ctx, i, ta, effects, k)
    if t is None:
        return None
    p_model = ctx.m.get("P_total_W", i, t)
    p_true = p_model + sum(e.dloss(ctx, i, t, k) for e in effects if e.heats)
    tq_rec = ctx.tq[i]
    for e in effects:
        tq_rec = e.torque_rec(ctx, i, tq_rec, k, nrows)
    return t, p_model, p_true, tq_rec, p_true + (tq_rec - ctx.tq[i]) * ctx.omega(i)


def heat_check(binary, config, case, model, oil, heat, ambient, out_csv, log):
    """The binary's own stabilised map of the (derived) case against the null balance solved
    here; logs the comparison and returns max |T_here - T_binary| over the points <= T_MAX_NULL."""
    rows = run_map(binary, config, case["speeds"], case["torques"], out_csv)
    ctx = Ctx(model, oil, list(range(len(model.points))), heat, None)
    errs = []
    for i, row in enumerate(rows):
        tb = num(row.get("oil_temp_C"))
        tm = steady_temperature(ctx, i, ambient, [], 0)
        if tb is not None and tm is not None and tb <= T_MAX_NULL:
            errs.append(tm - tb)
    e = max(abs(x) for x in errs) if errs else float("nan")
    temps = [num(r.get("oil_temp_C")) for r in rows if num(r.get("oil_temp_C")) is not None]
    log(f"  heat balance check ({len(errs)} of {len(rows)} points with oil <= {T_MAX_NULL:g} degC): "
        f"max |T_here - T_binary| = {e:.3f} K, "
        f"mean {mean(errs):+.3f} K; binary's stabilised oil {min(temps):.0f}-{max(temps):.0f} degC")
    return e


def housing_check(binary, case_names, out, log):
    """How far the textbook housing model lands from the binary's own stabilised map."""
    for cname in case_names:
        case = CASES[cname]
        th = read_thermal(ROOT / case["config"])
        if "housing" not in th or th.get("mode") != "stabilised":
            log(f"{cname}: no housing heat path in stabilised mode")
            continue
        rows = run_map(binary, ROOT / case["config"], case["speeds"], case["torques"], out / f"housing_{cname}.csv")
        rel = []
        for row in rows:
            t, p = num(row.get("oil_temp_C")), num(row.get("P_total_W"))
            if t is None or p is None:
                continue
            q = q_housing_network(t, th["ambient"], th["housing"], th.get("oil_to_housing"))
            rel.append((q / p - 1, t, p))
        if rel:
            print(f"{cname}: textbook housing Q / binary's balance P at its stabilised temperature: "
                  f"median {100 * median(r[0] for r in rel):+.1f} %, range {100 * min(r[0] for r in rel):+.1f} .. "
                  f"{100 * max(r[0] for r in rel):+.1f} % over {len(rel)} points "
                  f"({min(r[1] for r in rel):.0f}-{max(r[1] for r in rel):.0f} degC)")
