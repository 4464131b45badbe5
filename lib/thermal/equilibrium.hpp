#pragma once
// Stabilised oil temperature: the lowest temperature above ambient where the
// losses P(T) equal the heat rejected Q(T) with F = P - Q changing sign from
// + to - (a stable equilibrium: a small excursion is pulled back).
#include <algorithm>
#include <boost/math/tools/toms748_solve.hpp>
#include <cmath>
#include <cstdint>

namespace gearloss::thermal {

enum class EquilibriumStatus { ok, no_equilibrium };

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
};

// F(T) = P_loss(T) - Q(T). F(T_amb) >= 0 since Q(T_amb) = 0.
// Brackets by fixed-point steps T_{k+1} = T_k + F(T_k)/G_k, G_k the heat
// rejection conductance, capped by max_step so a stable root is not jumped,
// then TOMS 748 (Alefeld, Potra & Shi 1995) from Boost.Math.
template <class F, class Conductance>
Equilibrium solve_equilibrium(F&& f, Conductance&& conductance, double T_amb, const EquilibriumOptions& opt = {}) {
    Equilibrium r;
    double a = T_amb;
    double fa = f(a);
    ++r.evaluations;
    if (fa <= 0.0) {  // no loss at all: the oil sits at ambient
        r.T = a;
        r.residual = fa;
        return r;
    }
    double b = a, fb = fa;
    for (;;) {
        const double G = std::max(conductance(a), 1e-9);
        const double step = std::clamp(fa / G, opt.tol_K, opt.max_step);
        b = std::min(a + step, opt.T_max);
        fb = f(b);
        ++r.evaluations;
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
    return r;
}

}  // namespace gearloss::thermal
