"""Whether the two effects of a pair can be told apart from one of them alone.

below_noise (campaigns.py) asks whether each effect shows on its own. A pair can pass that
and still not be a test of naming both: one effect, its own parameters refitted, may imitate
the pair to within the noise (a seal loss whose torque falls with speed beside a bearing drag
whose exponent is free; a heat path whose factor changes with temperature beside a constant
parasitic loss). Then no method can name the second effect: the recordings do not hold it.

The check uses only this generator's forms, never the library's: for each effect X of the
pair, the other effect Y alone, with the parameters of its family (the ranges the generator
draws from, its amplitude free), is fitted to the pair's noiseless recordings (recorded loss
and steady oil temperature of every row, by least squares weighted by the noise). The
chi-square left is the noncentrality lambda of adding X back: on noisy recordings the fit with
X (its k parameters free) improves chi-square by lambda + k on average, so the expected
Bayesian information criterion gain of naming X is lambda + k - k ln(N), N the recorded values.
X is hidden when that is below 10, the "very strong" evidence of Kass & Raftery (1995): even a
method that knew both families exactly would not name X in most such campaigns. (The per-point
rule of below_noise is too lenient for this: 20 rows each 0.7 sigma off give lambda ~ 20.)
"""
import copy
import math

from .heat_balance import noiseless_point
from .numerics import mean, nelder_mead, scan_then_golden

def predict(ctx, effects, rows, nrows):
    """Noiseless (recorded loss, steady oil temperature) of each row (k, i, ambient), or None
    where the point has no equilibrium."""
    pts = (noiseless_point(ctx, i, ta, effects, k, nrows) for k, i, ta in rows)
    return [None if x is None else (x[4], x[0]) for x in pts]


def mismatch(pred, target, s_loss, s_temp, fixed):
    """(chi-square, mean |relative loss residual|, RMS temperature residual) of pred against
    target; the loss weighted as record_point draws its noise, relative to the recorded loss."""
    chi2, dl, dt = 0.0, [], []
    for a, b in zip(pred, target):
        if b is None:
            continue
        if a is None:
            return math.inf, math.inf, math.inf
        rl, rt = (a[0] - b[0]) / b[0], (0.0 if fixed else a[1] - b[1])
        chi2 += (rl / s_loss) ** 2 + (rt / s_temp) ** 2
        dl.append(abs(rl))
        dt.append(rt * rt)
    return chi2, mean(dl), math.sqrt(mean(dt))


def fit_alone(ctx, effect, rows, nrows, target, s_loss, s_temp, fixed):
    """The effect alone, its family's parameters fitted to target: (chi2, loss, temp, params).
    The first parameter of fit_space is the amplitude: for each of 5 values of the shape
    parameter (if any) the amplitude is scanned and refined by golden section, then Nelder-Mead
    refines both from the best (a start at amplitude 0 would leave the shape undetermined)."""
    e = copy.copy(effect)
    space = effect.fit_space()

    def apply(u):
        for (attr, lo, hi), v in zip(space, u):
            setattr(e, attr, lo + v * (hi - lo))

    def cost(u):
        apply(u)
        return mismatch(predict(ctx, [e], rows, nrows), target, s_loss, s_temp, fixed)[0]

    shapes = [[]] if len(space) == 1 else [[j / 4] for j in range(5)]
    best = None
    for sh in shapes:
        a, v = scan_then_golden(lambda x: cost([x] + sh))
        if best is None or v < best[1]:
            best = ([a] + sh, v)
    u = best[0]
    if len(space) > 1:
        u, _ = nelder_mead(cost, u, step=0.1)
        u, _ = nelder_mead(cost, u, step=0.03)  # restart: a collapsed simplex stops early
    apply(u)
    chi2, v_loss, v_temp = mismatch(predict(ctx, [e], rows, nrows), target, s_loss, s_temp, fixed)
    return chi2, v_loss, v_temp, {a: getattr(e, a) for a, _, _ in space}


STRONG_EVIDENCE = 10.0  # a BIC difference (Kass & Raftery 1995)


def check_fit(ctx, effects, rows, nrows, s_loss, s_temp, fixed):
    """The fit on itself: each effect alone fitted to its own noise-free recordings, its
    amplitude cap set from half and from twice the drawn amplitude; the largest chi-square
    left (near 0 when the fit finds the known optimum)."""
    worst = 0.0
    for e in effects:
        target = predict(ctx, [e], rows, nrows)
        attr, lo, _ = e.fit_space()[0]
        for scale in ((0.5, 2.0) if lo == 0.0 else (1.0,)):
            z = copy.copy(e)
            setattr(z, attr, getattr(e, attr) * scale)
            worst = max(worst, fit_alone(ctx, z, rows, nrows, target, s_loss, s_temp, fixed)[0])
    return worst


def hidden_effect(ctx, effects, truth_rows, order, ambient, drift, s_loss, s_temp, fixed, check=False):
    """Why the pair is not a test of naming both (one effect hidden behind the other refitted
    alone), or None. Records on each effect what the other, refitted alone, leaves of the pair
    (beside_other_*); check: also the fit on itself (check_fit), as fit_check_chi2."""
    if len(effects) != 2:
        return None
    nrows = len(order)
    rows = [(k, i, ambient + drift * (k / max(nrows - 1, 1) - 0.5))
            for k, (i, x) in enumerate(zip(order, truth_rows)) if "dropped" not in x]
    target = predict(ctx, effects, rows, nrows)
    why = None
    for x, y in ((effects[0], effects[1]), (effects[1], effects[0])):
        chi2, v_loss, v_temp, _ = fit_alone(ctx, y, rows, nrows, target, s_loss, s_temp, fixed)
        k = len(x.fit_space())
        gain = chi2 + k - k * math.log(len(rows) * (1 if fixed else 2))
        x.params.update({"beside_other_loss_rel": v_loss, "beside_other_temp_rms_K": v_temp,
                         "beside_other_lambda": chi2, "beside_other_expected_dbic": gain})
        if why is None and gain < STRONG_EVIDENCE:
            why = (f"{x.name} hidden behind {y.name} refitted alone: lambda {chi2:.1f}, expected BIC gain "
                   f"{gain:.1f} < {STRONG_EVIDENCE:g} (loss {100 * v_loss:.2f} % vs {100 * s_loss:.2f} %, "
                   f"oil temperature {v_temp:.2f} K vs {s_temp:.2f} K RMS)")
    if check:
        worst = check_fit(ctx, effects, rows, nrows, s_loss, s_temp, fixed)
        for e in effects:
            e.params["fit_check_chi2"] = worst
    return why
