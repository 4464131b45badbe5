"""The concealed effects, in perturbed forms written here, and what counts as naming them.

Each Effect adds a loss that heats the oil (dloss), scales the heat rejection (qmult) or
falsifies the recorded input torque (torque_rec), sized against the campaign's null loss,
and states the library parameter it is comparable to (truth). None has the exact form
of a `diagnose` candidate. ACCEPT maps each to the library names that count as correct;
the effects OUTSIDE the library have none.
"""
import math

from .numerics import mean, median, sigmoid

# ----------------------------------------------------------------------------------------
# Acceptance: perturbed effect -> library names (`diagnose` effect ids) that count as
# correct. Outside-library effects and null campaigns have no acceptable library name.
# ----------------------------------------------------------------------------------------
ACCEPT = {
    "aero_drag": {"windage"},
    "churning_speed": {"churning"},
    "bearing_visc_drag": {"bearing_drag"},
    "seal_extra": {"seal_friction"},
    # a uniform friction factor, or the friction rise that follows the film (mixed lubrication)
    "mesh_low_film": {"mesh_friction", "mesh_friction_mixed"},
    "visc_shift": {"oil_viscosity"},
    "heat_factor": {"thermal_resistance"},
    "forced_convection": {"speed_dependent_cooling"},
    "sensor_gain": {"torque_sensor_gain"},
    "sensor_offset": {"torque_sensor_offset"},
    "pump_loss": {"constant_parasitic"},
    # outside the library: correct = a non-confident verdict (unexplained / partly)
    "speed_step": set(),
    "hot_loss": set(),
    "torque2_band": set(),
    "running_in": set(),
    "speed_power": set(),
    "visc_loss": set(),
    # a loss drifting linearly over the recorded run order (order campaigns, with a `run` column)
    "loss_drift": set(),
    # per-oil effects of the multi-oil campaigns (multi_oil.py): named for that oil only
    "oil_visc_factor": {"oil_viscosity"},
    "oil_mesh_friction": {"mesh_friction"},
}
LIBRARY = ["aero_drag", "churning_speed", "bearing_visc_drag", "seal_extra", "mesh_low_film", "visc_shift",
           "heat_factor", "forced_convection", "sensor_gain", "sensor_offset", "pump_loss"]
OUTSIDE = ["speed_step", "hot_loss", "torque2_band", "running_in", "speed_power", "visc_loss"]
# effects acting along the row (test) order: their campaigns carry a `run` column giving that order
ORDERED = {"running_in", "loss_drift"}
THERMAL_ONLY = {"heat_factor", "forced_convection", "hot_loss", "visc_loss"}  # need a stabilised heat path
# A refit of one effect alone (identifiability.py) may take up to this many times its drawn amplitude.
AMPLITUDE_SPAN = 6.0


# ----------------------------------------------------------------------------------------
# Concealed effects (perturbed forms, written here)
# ----------------------------------------------------------------------------------------
class Ctx:
    """A campaign under construction: its points, the model, the heat path, the null state."""

    def __init__(self, model, oil, pts, heat, rng):
        self.m, self.oil, self.pts, self.heat, self.rng = model, oil, pts, heat, rng
        self.n = {i: model.points[i][0] for i in pts}
        self.tq = {i: model.points[i][1] for i in pts}
        self.n_med = median(self.n.values())
        self.t0, self.p0 = {}, {}  # null steady state at nominal ambient (for sizing)

    def omega(self, i):
        return self.n[i] * 2 * math.pi / 60


class Effect:
    name = "?"
    heats = True

    def __init__(self, rng):
        self.rng = rng
        self.params = {}

    def setup(self, ctx, r):
        pass

    def dloss(self, ctx, i, t, k):  # extra loss that heats the oil [W]
        return 0.0

    def qmult(self, ctx, i, t):  # multiplier on heat rejection
        return 1.0

    def torque_rec(self, ctx, i, tq, k, nrows):  # recorded input torque
        return tq

    def truth(self, ctx):  # (comparable library parameter value) or None
        return None

    def fit_space(self):
        """(attribute, low, high) of the family's parameters, for a refit of this effect alone
        (identifiability.py): shape parameters over the ranges drawn here, the amplitude free up
        to AMPLITUDE_SPAN x the drawn one."""
        raise NotImplementedError(self.name)

    @staticmethod
    def amplitude_span(shape_mean, now, ends):
        """How much more amplitude the same size needs at the ends of a shape parameter's range
        (shape_mean(x): the shape's mean over the campaign at parameter x; at least 1)."""
        return max([1.0] + [shape_mean(now) / shape_mean(x) for x in ends if shape_mean(x) > 0])

    def size_to(self, ctx, shape, r):
        """Amplitude A such that mean_i A*shape(i)/P0_i = r."""
        s = mean(shape(i) / ctx.p0[i] for i in ctx.pts)
        return r / s if s > 0 else 0.0

    @staticmethod
    def null_share(ctx, col):
        """Mean share of a loss column in the null loss over the campaign."""
        return mean(ctx.m.get(col, i, ctx.t0[i]) / ctx.p0[i] for i in ctx.pts)

    @staticmethod
    def column_weighted(ctx, col, factor):
        """factor(i) averaged with the column's null loss as weight: the one library factor
        on that column that gives the same extra loss over the campaign."""
        w = [ctx.m.get(col, i, ctx.t0[i]) for i in ctx.pts]
        f = [factor(i) for i in ctx.pts]
        return sum(a * b for a, b in zip(w, f)) / sum(w)


class AeroDrag(Effect):
    """Air/oil-mist drag of the whole box, P = A (n/1000 rpm)^a, a in [2.5, 3.2]."""
    name = "aero_drag"

    def setup(self, ctx, r):
        self.a = self.rng.uniform(2.5, 3.2)
        self.A = self.size_to(ctx, lambda i: (ctx.n[i] / 1000) ** self.a, r)
        self.params = {"exponent": self.a, "W_at_1000rpm": self.A}
        self.n_k = [ctx.n[i] / 1000 for i in ctx.pts]

    def fit_space(self):  # the amplitude is that at 1000 rpm: far from it, the exponent moves the size
        span = self.amplitude_span(lambda a: mean(v ** a for v in self.n_k), self.a, (2.5, 3.2))
        return [("A", 0.0, AMPLITUDE_SPAN * span * self.A), ("a", 2.5, 3.2)]

    def dloss(self, ctx, i, t, k):
        return self.A * (ctx.n[i] / 1000) ** self.a

    def truth(self, ctx):  # least-squares equivalent C of C (n/1000)^2.9 over the campaign
        x = [ctx.n[i] / 1000 for i in ctx.pts]
        return self.A * sum(v ** (self.a + 2.9) for v in x) / sum(v ** 5.8 for v in x)


class SpeedFactorOnColumn(Effect):
    """A loss column of the model off by a factor that varies with speed:
    P_col (1 + k (n/n_med)^c), c drawn from c_range; applicable where the column's share of
    the null loss exceeds min_share."""
    col, c_range, min_share, label = None, None, None, None

    def speed(self, ctx, i):
        return (ctx.n[i] / ctx.n_med) ** self.c

    def setup(self, ctx, r):
        self.c = self.rng.uniform(*self.c_range)
        self.k = self.size_to(ctx, lambda i: ctx.m.get(self.col, i, ctx.t0[i]) * self.speed(ctx, i), r)
        self.params = {"k": self.k, "speed_exponent": self.c}

    def fit_space(self):
        return [("k", 0.0, AMPLITUDE_SPAN * self.k), ("c", *self.c_range)]

    def applicable(self, ctx):
        share = self.null_share(ctx, self.col)
        return share > self.min_share, f"{self.label} share {100 * share:.1f} %"

    def dloss(self, ctx, i, t, k):
        return self.k * ctx.m.get(self.col, i, t) * self.speed(ctx, i)

    def truth(self, ctx):
        return self.column_weighted(ctx, self.col, lambda i: 1 + self.k * self.speed(ctx, i))


class ChurningSpeed(SpeedFactorOnColumn):
    """Churning level off by a factor that varies with speed: P_ch (1 + k (n/n_med)^c)."""
    name = "churning_speed"
    col, c_range, min_share, label = "P_churn_W", (-0.4, 0.6), 0.04, "churning"


class SealExtra(SpeedFactorOnColumn):
    """Lip-seal friction off by a factor varying with speed: P_seal (1 + k (n/n_med)^c)."""
    name = "seal_extra"
    col, c_range, min_share, label = "P_seal_W", (-0.3, 0.3), 0.015, "seal"


class BearingViscDrag(Effect):
    """Load-independent viscous drag, M ~ (nu n)^b with b in [0.45, 0.85] (Palmgren: 2/3)."""
    name = "bearing_visc_drag"

    def setup(self, ctx, r):
        self.b = self.rng.uniform(0.45, 0.85)
        self.nu_n = {i: ctx.oil.nu(ctx.t0[i]) * ctx.n[i] / 1e5 for i in ctx.pts}
        self.A = self.size_to(ctx, lambda i: self.shape(ctx, i, ctx.t0[i]), r)
        self.params = {"exponent_b": self.b}

    def fit_space(self):  # the same size at the other ends of the exponent's range takes another amplitude
        span = self.amplitude_span(lambda b: mean(v ** b for v in self.nu_n.values()), self.b, (0.45, 0.85))
        return [("A", 0.0, AMPLITUDE_SPAN * span * self.A), ("b", 0.45, 0.85)]

    def shape(self, ctx, i, t):
        return (ctx.oil.nu(t) * ctx.n[i] / 1e5) ** self.b * ctx.n[i] / 1000

    def dloss(self, ctx, i, t, k):
        return self.A * self.shape(ctx, i, t)


class MeshLowFilm(Effect):
    """Mesh friction x (1 + k) only where the film is thin: weight sigmoid((L* - Lambda)/(0.15 L*)),
    L* the campaign's median Lambda (low speed, high torque, hot oil)."""
    name = "mesh_low_film"

    def w(self, ctx, i, t):
        lam = ctx.m.get("lambda_min", i, t)
        if lam is None:
            return 0.0
        return sigmoid((self.lstar - lam) / (0.15 * self.lstar))

    def applicable(self, ctx):
        lams = [ctx.m.get("lambda_min", i, ctx.t0[i]) for i in ctx.pts]
        share = self.null_share(ctx, "P_mesh_W")
        ok = all(v is not None and v > 0 for v in lams) and share > 0.1
        return ok, f"mesh share {100 * share:.0f} %, lambda {'ok' if ok else 'missing'}"

    def setup(self, ctx, r):
        self.lstar = median(ctx.m.get("lambda_min", i, ctx.t0[i]) for i in ctx.pts)
        self.k = self.size_to(ctx, lambda i: ctx.m.get("P_mesh_W", i, ctx.t0[i]) * self.w(ctx, i, ctx.t0[i]), r)
        self.params = {"k": self.k, "lambda_threshold": self.lstar}

    def fit_space(self):
        return [("k", 0.0, AMPLITUDE_SPAN * self.k)]

    def dloss(self, ctx, i, t, k):
        return self.k * ctx.m.get("P_mesh_W", i, t) * self.w(ctx, i, t)

    def truth(self, ctx):
        return self.column_weighted(ctx, "P_mesh_W", lambda i: 1 + self.k * self.w(ctx, i, ctx.t0[i]))


class ViscShift(Effect):
    """The real oil at T behaves as the model's oil at T - d (d = +-5..12 K): every loss column
    taken at the shifted temperature (not a factor on nu)."""
    name = "visc_shift"

    def setup(self, ctx, r):
        self.d = self.rng.choice([-1, 1]) * self.rng.uniform(5, 12)
        self.params = {"shift_K": self.d}

    def fit_space(self):
        return [("d", -12.0, 12.0)]

    def dloss(self, ctx, i, t, k):
        ts = t - self.d
        ts = max(ts, ctx.m.trange[i][0])
        return ctx.m.get("P_total_W", i, ts) - ctx.m.get("P_total_W", i, t)

    def truth(self, ctx):
        tm = median(ctx.t0.values())
        return ctx.oil.nu(tm - self.d) / ctx.oil.nu(tm)


class HeatFactor(Effect):
    """Heat path off: Q f (1 + c (T - T_mid)/50 K), f in [0.72, 0.85] or [1.18, 1.35]."""
    name = "heat_factor"

    def setup(self, ctx, r):
        self.f = self.rng.uniform(0.72, 0.85) if self.rng.random() < 0.5 else self.rng.uniform(1.18, 1.35)
        self.c = self.rng.uniform(-0.15, 0.15)
        self.tmid = median(ctx.t0.values())
        self.params = {"factor": self.f, "temperature_slope": self.c}

    def fit_space(self):
        return [("f", 0.6, 1.5), ("c", -0.15, 0.15)]

    def qmult(self, ctx, i, t):
        return self.f * (1 + self.c * (t - self.tmid) / 50)

    def truth(self, ctx):
        return self.f


class ForcedConvection(Effect):
    """Cooling grows with speed as Q (1 + a (n/1000 rpm)^p), p in [0.5, 0.8] (library: p = 1)."""
    name = "forced_convection"

    def setup(self, ctx, r):
        self.p = self.rng.uniform(0.5, 0.8)
        gain = self.rng.uniform(0.15, 0.45)  # mean extra cooling over the campaign
        self.a = gain / mean((ctx.n[i] / 1000) ** self.p for i in ctx.pts)
        self.params = {"a": self.a, "exponent": self.p}
        self.n_k = [ctx.n[i] / 1000 for i in ctx.pts]

    def fit_space(self):  # as AeroDrag's: the amplitude is that at 1000 rpm
        span = self.amplitude_span(lambda p: mean(v ** p for v in self.n_k), self.p, (0.5, 0.8))
        return [("a", 0.0, AMPLITUDE_SPAN * span * self.a), ("p", 0.5, 0.8)]

    def qmult(self, ctx, i, t):
        return 1 + self.a * (ctx.n[i] / 1000) ** self.p

    def truth(self, ctx):
        x = [ctx.n[i] / 1000 for i in ctx.pts]
        return self.a * sum(v ** (self.p + 1) for v in x) / sum(v * v for v in x)


class SensorGain(Effect):
    """Input torque sensor gain with a small quadratic non-linearity; does not heat the oil."""
    name = "sensor_gain"
    heats = False

    def setup(self, ctx, r):
        pin = mean(ctx.tq[i] * ctx.omega(i) for i in ctx.pts)
        self.g = 1 + self.rng.choice([-1, 1]) * r * mean(ctx.p0.values()) / pin
        self.u = self.rng.uniform(-0.3, 0.3)  # the quadratic term relative to the gain error
        self.tmax = max(ctx.tq.values())
        self.params = {"gain": self.g, "quadratic": self.q}

    @property
    def q(self):
        return self.u * (self.g - 1)

    def fit_space(self):
        d = AMPLITUDE_SPAN * abs(self.g - 1)
        return [("g", 1 - d, 1 + d), ("u", -0.3, 0.3)]

    def torque_rec(self, ctx, i, tq, k, nrows):
        return tq * self.g + self.q * tq * tq / self.tmax

    def truth(self, ctx):
        return mean(self.torque_rec(ctx, i, ctx.tq[i], 0, 1) / ctx.tq[i] for i in ctx.pts)


class SensorOffset(Effect):
    """Input torque sensor offset drifting linearly over the campaign; does not heat the oil."""
    name = "sensor_offset"
    heats = False

    def setup(self, ctx, r):
        w = mean(ctx.omega(i) for i in ctx.pts)
        self.t0_ = self.rng.choice([-1, 1]) * r * mean(ctx.p0.values()) / w
        self.drift = self.rng.uniform(-0.3, 0.3)
        self.params = {"offset_Nm": self.t0_, "relative_drift": self.drift}

    def fit_space(self):
        d = AMPLITUDE_SPAN * abs(self.t0_)
        return [("t0_", -d, d), ("drift", -0.3, 0.3)]

    def torque_rec(self, ctx, i, tq, k, nrows):
        return tq + self.t0_ * (1 + self.drift * (k / max(nrows - 1, 1) - 0.5))

    def truth(self, ctx):
        return self.t0_


class PumpLoss(Effect):
    """Parasitic pump loss, nearly constant: A (1 + beta (n/n_med - 1)), beta in [-0.2, 0.3]."""
    name = "pump_loss"

    def setup(self, ctx, r):
        self.beta = self.rng.uniform(-0.2, 0.3)
        self.A = self.size_to(ctx, lambda i: 1 + self.beta * (ctx.n[i] / ctx.n_med - 1), r)
        self.params = {"W": self.A, "beta": self.beta}

    def fit_space(self):
        return [("A", 0.0, AMPLITUDE_SPAN * self.A), ("beta", -0.2, 0.3)]

    def dloss(self, ctx, i, t, k):
        return self.A * (1 + self.beta * (ctx.n[i] / ctx.n_med - 1))

    def truth(self, ctx):
        return mean(self.dloss(ctx, i, 0, 0) for i in ctx.pts)


class SpeedStep(Effect):
    """OUTSIDE: a loss that switches on above a speed threshold (e.g. a regime change)."""
    name = "speed_step"

    def setup(self, ctx, r):
        levels = sorted(set(ctx.n.values()))
        cut = self.rng.randint(1, len(levels) - 1)
        self.nstar = 0.5 * (levels[cut - 1] + levels[cut])
        self.A = self.size_to(ctx, lambda i: 1.0 if ctx.n[i] > self.nstar else 0.0, r)
        self.params = {"W": self.A, "above_rpm": self.nstar}

    def dloss(self, ctx, i, t, k):
        return self.A if ctx.n[i] > self.nstar else 0.0


class HotLoss(Effect):
    """OUTSIDE: a load-independent loss appearing above an oil temperature (2 K wide)."""
    name = "hot_loss"

    def setup(self, ctx, r):
        ts = sorted(ctx.t0.values())
        self.tstar = ts[len(ts) // 2]
        self.A = self.rng.uniform(1.5, 2.5) * r * mean(ctx.p0.values())
        self.params = {"W": self.A, "above_degC": self.tstar}

    def dloss(self, ctx, i, t, k):
        return self.A * sigmoid((t - self.tstar) / 2.0)


class Torque2Band(Effect):
    """OUTSIDE: a loss ~ torque^2 in one speed band (a resonance)."""
    name = "torque2_band"

    def setup(self, ctx, r):
        levels = sorted(set(ctx.n.values()))
        j = self.rng.randint(0, len(levels) - 1)
        self.band = (levels[j] - 1e-6, levels[min(j + self.rng.randint(0, 1), len(levels) - 1)] + 1e-6)
        inband = [i for i in ctx.pts if self.band[0] <= ctx.n[i] <= self.band[1]]
        tmax = max(ctx.tq[i] for i in inband)
        imax = max(inband, key=lambda i: ctx.tq[i])
        self.k = self.rng.uniform(0.2, 0.35) * ctx.p0[imax] / tmax ** 2
        self.params = {"k_W_per_Nm2": self.k, "band_rpm": list(self.band)}

    def dloss(self, ctx, i, t, k):
        return self.k * ctx.tq[i] ** 2 if self.band[0] <= ctx.n[i] <= self.band[1] else 0.0


class RunningIn(Effect):
    """OUTSIDE: running-in, the loss decays over the campaign: P (1 + r0 exp(-k/tau))."""
    name = "running_in"

    def setup(self, ctx, r):
        self.r0 = self.rng.uniform(0.15, 0.3)
        self.tau_frac = self.rng.uniform(0.2, 0.4)
        self.nrows = len(ctx.pts)
        self.params = {"r0": self.r0, "tau_rows": self.tau_frac * self.nrows}

    def dloss(self, ctx, i, t, k):
        return self.r0 * math.exp(-k / (self.tau_frac * self.nrows)) * ctx.m.get("P_total_W", i, t)


class SpeedPower(Effect):
    """OUTSIDE: a load-independent loss A (n/n_med)^p with an exponent no candidate has:
    p in [0.3, 0.6] (below the seals' n^1) or [3.9, 4.6] (above windage's n^2.9)."""
    name = "speed_power"

    def setup(self, ctx, r):
        self.p = self.rng.uniform(0.3, 0.6) if self.rng.random() < 0.5 else self.rng.uniform(3.9, 4.6)
        self.A = self.size_to(ctx, lambda i: (ctx.n[i] / ctx.n_med) ** self.p, r)
        self.params = {"W_at_n_med": self.A, "n_med_rpm": ctx.n_med, "speed_exponent": self.p}

    def dloss(self, ctx, i, t, k):
        return self.A * (ctx.n[i] / ctx.n_med) ** self.p


class ViscLoss(Effect):
    """OUTSIDE: a speed- and load-independent viscous loss A (nu/nu_med)^p, p in [0.8, 1.2]
    (a viscous pump or a throttled oil supply; the library's viscous drags all rise with speed)."""
    name = "visc_loss"

    def setup(self, ctx, r):
        self.p = self.rng.uniform(0.8, 1.2)
        self.nu_med = median(ctx.oil.nu(t) for t in ctx.t0.values())
        self.A = self.size_to(ctx, lambda i: (ctx.oil.nu(ctx.t0[i]) / self.nu_med) ** self.p, r)
        self.params = {"W_at_nu_med": self.A, "nu_med_cSt": self.nu_med, "viscosity_exponent": self.p}

    def dloss(self, ctx, i, t, k):
        return self.A * (ctx.oil.nu(t) / self.nu_med) ** self.p


class LossDrift(Effect):
    """ORDER: the loss drifts linearly over the campaign's run order, P (1 + d (k/(N-1) - 1/2)),
    d = +-(0.12..0.25) from the first to the last test (a seal bedding in, a sensor warming)."""
    name = "loss_drift"

    def setup(self, ctx, r):
        self.d = self.rng.choice([-1, 1]) * self.rng.uniform(0.12, 0.25)
        self.nrows = len(ctx.pts)
        self.params = {"relative_drift": self.d}

    def dloss(self, ctx, i, t, k):
        return self.d * (k / max(self.nrows - 1, 1) - 0.5) * ctx.m.get("P_total_W", i, t)


EFFECTS = {c.name: c for c in [AeroDrag, ChurningSpeed, BearingViscDrag, SealExtra, MeshLowFilm, ViscShift,
                               HeatFactor, ForcedConvection, SensorGain, SensorOffset, PumpLoss,
                               SpeedStep, HotLoss, Torque2Band, RunningIn, SpeedPower, ViscLoss, LossDrift]}
