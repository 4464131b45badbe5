"""Small numerical helpers for the independent campaigns, standard library only.

Monotone cubic interpolation (the model table's interpolation in oil temperature), a
bisection root finder (oil viscosity fit, heat balances), a sigmoid, mean and median
that tolerate empty input, a forgiving float parser for the binary's CSV cells, and two small
minimisers on the unit box (Nelder-Mead; scan + golden section) for identifiability.py.
Kept apart because every other module uses them and they depend on nothing else.
"""
import bisect
import math


class Pchip:
    """Monotone piecewise-cubic Hermite interpolation (Fritsch-Carlson) on a 1-D grid."""

    def __init__(self, xs, ys):
        self.x, self.y = list(xs), list(ys)
        n = len(xs)
        h = [xs[k + 1] - xs[k] for k in range(n - 1)]
        d = [(ys[k + 1] - ys[k]) / h[k] for k in range(n - 1)]
        m = [0.0] * n
        if n == 2:
            m = [d[0], d[0]]
        elif n > 2:
            for k in range(1, n - 1):
                if d[k - 1] * d[k] <= 0:
                    m[k] = 0.0
                else:
                    w1, w2 = 2 * h[k] + h[k - 1], h[k] + 2 * h[k - 1]
                    m[k] = (w1 + w2) / (w1 / d[k - 1] + w2 / d[k])
            m[0] = self._end(h[0], h[1], d[0], d[1])
            m[-1] = self._end(h[-1], h[-2], d[-1], d[-2])
        self.m = m

    @staticmethod
    def _end(h0, h1, d0, d1):
        v = ((2 * h0 + h1) * d0 - h0 * d1) / (h0 + h1)
        if v * d0 <= 0:
            return 0.0
        if d0 * d1 <= 0 and abs(v) > abs(3 * d0):
            return 3 * d0
        return v

    def lo(self):
        return self.x[0]

    def hi(self):
        return self.x[-1]

    def __call__(self, t):
        x = self.x
        if t < x[0] - 1e-9 or t > x[-1] + 1e-9:
            raise ValueError("outside the mapped temperature range")
        if len(x) == 1:
            return self.y[0]
        k = min(max(bisect.bisect_right(x, t) - 1, 0), len(x) - 2)
        h = x[k + 1] - x[k]
        s = (t - x[k]) / h
        h00 = (1 + 2 * s) * (1 - s) ** 2
        h10 = s * (1 - s) ** 2
        h01 = s * s * (3 - 2 * s)
        h11 = s * s * (s - 1)
        return h00 * self.y[k] + h10 * h * self.m[k] + h01 * self.y[k + 1] + h11 * h * self.m[k + 1]


def bisect_root(f, lo, hi, tol=1e-4):
    flo = f(lo)
    for _ in range(100):
        mid = 0.5 * (lo + hi)
        fm = f(mid)
        if (fm > 0) == (flo > 0):
            lo, flo = mid, fm
        else:
            hi = mid
        if hi - lo < tol:
            break
    return 0.5 * (lo + hi)


def sigmoid(z):
    if z > 40:
        return 1.0
    if z < -40:
        return 0.0
    return 1.0 / (1.0 + math.exp(-z))


def mean(v):
    v = list(v)
    return sum(v) / len(v) if v else float("nan")


def median(v):
    v = sorted(v)
    if not v:
        return float("nan")
    k = len(v) // 2
    return v[k] if len(v) % 2 else 0.5 * (v[k - 1] + v[k])


def num(s):
    try:
        v = float(s)
        return v if math.isfinite(v) else None
    except (TypeError, ValueError):
        return None


def nelder_mead(f, x0, step=0.15, max_eval=160):
    """Minimise f over the unit box (points clipped into it) from x0."""
    clip = lambda x: [min(1.0, max(0.0, v)) for v in x]
    n = len(x0)
    x0 = clip(x0)
    # each vertex a step off the start along one axis, inwards (a start on the upper bound
    # clipped back onto itself would freeze that axis)
    simplex = [x0] + [[v + ((step if v + step <= 1.0 else -step) if j == d else 0.0) for j, v in enumerate(x0)]
                      for d in range(n)]
    vals = [f(x) for x in simplex]
    evals = len(vals)
    while evals < max_eval:
        order = sorted(range(n + 1), key=lambda j: vals[j])
        simplex, vals = [simplex[j] for j in order], [vals[j] for j in order]
        if abs(vals[-1] - vals[0]) <= 1e-6 * (1 + abs(vals[0])):
            break
        c = [sum(x[d] for x in simplex[:-1]) / n for d in range(n)]
        move = lambda a: clip([c[d] + a * (simplex[-1][d] - c[d]) for d in range(n)])
        xr = move(-1.0)
        fr = f(xr)
        evals += 1
        if fr < vals[0]:
            xe = move(-2.0)
            fe = f(xe)
            evals += 1
            simplex[-1], vals[-1] = (xe, fe) if fe < fr else (xr, fr)
        elif fr < vals[-2]:
            simplex[-1], vals[-1] = xr, fr
        else:
            xc = move(0.5)
            fc = f(xc)
            evals += 1
            if fc < vals[-1]:
                simplex[-1], vals[-1] = xc, fc
            else:  # shrink towards the best
                simplex = [simplex[0]] + [clip([simplex[0][d] + 0.5 * (x[d] - simplex[0][d]) for d in range(n)])
                                          for x in simplex[1:]]
                vals = [vals[0]] + [f(x) for x in simplex[1:]]
                evals += n
    j = min(range(n + 1), key=lambda j: vals[j])
    return simplex[j], vals[j]


def scan_then_golden(f, n_scan=9, iters=24):
    """Minimise f over [0, 1]: the best of n_scan even points, then golden section around it."""
    xs = [j / (n_scan - 1) for j in range(n_scan)]
    vals = [f(x) for x in xs]
    j = min(range(n_scan), key=lambda j: vals[j])
    a, b = xs[max(j - 1, 0)], xs[min(j + 1, n_scan - 1)]
    g = (math.sqrt(5) - 1) / 2
    c, d = b - g * (b - a), a + g * (b - a)
    fc, fd = f(c), f(d)
    for _ in range(iters):
        if fc < fd:
            b, d, fd = d, c, fc
            c = b - g * (b - a)
            fc = f(c)
        else:
            a, c, fc = c, d, fd
            d = a + g * (b - a)
            fd = f(d)
    best = min([(vals[j], xs[j]), (fc, c), (fd, d)])
    return best[1], best[0]
