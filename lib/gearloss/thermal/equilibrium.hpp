#pragma once
// Stabilised oil temperature: the lowest temperature above ambient where the
// losses P(T) equal the heat rejected Q(T) with F = P - Q changing sign from
// + to - (a stable equilibrium: a small excursion is pulled back).
#include <algorithm>
#include <boost/math/tools/toms748_solve.hpp>
#include <cmath>
#include <cstdint>

namespace gearloss::thermal {

// ok; no_equilibrium: F > 0 up to T_max; non_finite: P or Q is not a finite number at T (a
// component out of its range: the caller names it); iteration_limit: the bracketing did not
// finish within max_bracket_steps (never seen with finite data; a bound, not a tolerance).
enum class EquilibriumStatus { ok, no_equilibrium, non_finite, iteration_limit };

struct Equilibrium {
    EquilibriumStatus status = EquilibriumStatus::ok;
    double T = 0;          // K
    double residual = 0;   // P - Q at T [W]
    int evaluations = 0;
};

struct EquilibriumOptions {
    double T_max = 473.15;   // above this no equilibrium is reported [K]
    double tol_K = 1e-3;     // bracket width at convergence
    double max_step = 40.0;  // largest bracketing step [K]
    // Bound on the bracketing steps. With finite data each step advances at least tol_K, so
    // (T_max - T_amb) / tol_K bounds them anyway; this also stops a degenerate F.
    int max_bracket_steps = 100000;
};

// F(T) = P_loss(T) - Q(T). F(T_amb) >= 0 since Q(T_amb) = 0.
// Brackets by fixed-point steps T_{k+1} = T_k + F(T_k)/G_k, G_k the heat
// rejection conductance, capped by max_step so a stable root is not jumped,
// then TOMS 748 (Alefeld, Potra & Shi 1995) from Boost.Math (at most 60 iterations).
// Every loop is bounded, and a value that is not finite (NaN passes clamp and min) ends
// the solve with status non_finite at the temperature where it appeared.
template <class F, class Conductance>
Equilibrium solve_equilibrium(F&& f, Conductance&& conductance, double T_amb, const EquilibriumOptions& opt = {}) {
    Equilibrium r;
    auto non_finite = [&r](double T, double residual) {
        r.status = EquilibriumStatus::non_finite;
        r.T = T;
        r.residual = residual;
        return r;
    };
    double a = T_amb;
    if (!std::isfinite(a)) return non_finite(a, 0.0);
    double fa = f(a);
    ++r.evaluations;
    if (!std::isfinite(fa)) return non_finite(a, fa);
    if (fa <= 0.0) {  // no loss at all: the oil sits at ambient
        r.T = a;
        r.residual = fa;
        return r;
    }
    double b = a, fb = fa;
    for (int steps = 0;; ++steps) {
        if (steps >= opt.max_bracket_steps) {
            r.status = EquilibriumStatus::iteration_limit;
            r.T = a;
            r.residual = fa;
            return r;
        }
        const double Ga = conductance(a);
        if (!std::isfinite(Ga)) return non_finite(a, fa);
        const double G = std::max(Ga, 1e-9);
        const double step = std::clamp(fa / G, opt.tol_K, opt.max_step);
        b = std::min(a + step, opt.T_max);
        fb = f(b);
        ++r.evaluations;
        if (!std::isfinite(fb)) return non_finite(b, fb);
        if (fb <= 0.0) break;
        if (b >= opt.T_max) {
            r.status = EquilibriumStatus::no_equilibrium;
            r.T = b;
            r.residual = fb;
            return r;
        }
        a = b;
        fa = fb;
    }
    if (fb == 0.0) {
        r.T = b;
        return r;
    }
    if (!(b > a)) {  // ambient at or above T_max: no temperature between them to bracket
        r.status = EquilibriumStatus::no_equilibrium;
        r.T = b;
        r.residual = fb;
        return r;
    }
    std::uintmax_t iters = 60;
    const double tol = opt.tol_K;
    auto stop = [tol](double lo, double hi) { return std::abs(hi - lo) <= tol; };
    auto counted = [&](double T) {
        ++r.evaluations;
        return f(T);
    };
    const auto [lo, hi] = boost::math::tools::toms748_solve(counted, a, b, fa, fb, stop, iters);
    r.T = 0.5 * (lo + hi);
    r.residual = f(r.T);
    ++r.evaluations;
    if (!std::isfinite(r.T) || !std::isfinite(r.residual)) return non_finite(r.T, r.residual);
    return r;
}

}  // namespace gearloss::thermal
