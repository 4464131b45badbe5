"""Small numerical helpers for the independent campaigns, standard library only.

Monotone cubic interpolation (the model table's interpolation in oil temperature), a
bisection root finder (oil viscosity fit, heat balances), a sigmoid, mean and median
that tolerate empty input, and a forgiving float parser for the binary's CSV cells.
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
