#include "gearloss/rating/thermal_rating.hpp"

#include <algorithm>
#include <boost/math/tools/toms748_solve.hpp>
#include <cmath>
#include <cstdint>

#include "gearloss/core/errors.hpp"

namespace gearloss::rating {

const char* to_string(RatingStatus s) {
    switch (s) {
        case RatingStatus::limit: return "limit";
        case RatingStatus::no_limit_below: return "no_limit_below";
        case RatingStatus::above_at_zero_torque: return "above_limit_at_zero_torque";
        case RatingStatus::out_of_range: return "out_of_range";
    }
    return "?";
}

namespace {

// The stabilised point at `torque` and its excess over the limit [K]: +(T_max - limit) when no
// equilibrium exists up to the search ceiling (the oil runs away: certainly above the limit).
struct Excess {
    solver::PointResult r;
    double dT = 0;
    bool out_of_range = false;
};

Excess excess(const solver::Model& m, double omega, double torque, const RatingOptions& o, bool detail) {
    Excess e;
    e.r = solver::solve_point(m, omega, torque, detail, o.ambient);
    switch (e.r.status) {
        case solver::PointStatus::ok:
        case solver::PointStatus::above_oil_limit: e.dT = e.r.oil_temperature - o.oil_limit; break;
        case solver::PointStatus::no_equilibrium:
            e.dT = std::max(m.thermal.equilibrium.T_max - o.oil_limit, 1.0);
            break;
        case solver::PointStatus::out_of_range: e.out_of_range = true; break;
    }
    return e;
}

void finish(const solver::Model& m, RatingPoint& p, const RatingOptions& o) {
    if (solver::has_values(p.point.status)) {
        p.housing_heat = m.housing_heat_flow(p.point.oil_temperature, o.ambient, p.omega);
        p.cooler_heat = m.cooler_heat_flow(p.point.oil_temperature);
    }
}

}  // namespace

RatingPoint rate_speed(const solver::Model& m, double omega, const RatingOptions& o) {
    if (m.thermal.mode != solver::ThermalMode::stabilised)
        throw InputError("", 0, 0, "thermal.mode", "a thermal rating needs the stabilised oil temperature (mode: stabilised)");
    RatingPoint p;
    p.omega = omega;
    auto out_of_range = [&](const Excess& e) {
        p.status = RatingStatus::out_of_range;
        p.torque = e.r.torque_in;
        p.cause = e.r.cause;
        p.point = e.r;
        return p;
    };
    // No load first: above the limit there, no torque is admissible.
    Excess lo = excess(m, omega, 0.0, o, false);
    ++p.solves;
    if (lo.out_of_range) return out_of_range(lo);
    if (lo.dT >= 0) {
        p.status = RatingStatus::above_at_zero_torque;
        p.point = excess(m, omega, 0.0, o, true).r;
        finish(m, p, o);
        return p;
    }
    // Upper bracket: doubling from the start torque up to max_torque.
    double t_lo = 0.0, t_hi = std::min(std::max(o.start_torque, 1e-3), o.max_torque);
    Excess hi;
    for (;;) {
        hi = excess(m, omega, t_hi, o, false);
        ++p.solves;
        if (hi.out_of_range) return out_of_range(hi);
        if (hi.dT >= 0) break;
        if (t_hi >= o.max_torque) {
            p.status = RatingStatus::no_limit_below;
            p.torque = o.max_torque;
            p.point = excess(m, omega, o.max_torque, o, true).r;
            finish(m, p, o);
            return p;
        }
        t_lo = t_hi;
        lo = hi;
        t_hi = std::min(2.0 * t_hi, o.max_torque);
    }
    // T(torque) - limit changes sign in [t_lo, t_hi]: TOMS 748 to a torque bracket of 1e-7
    // relative (the oil temperature then within ~1e-3 K, the equilibrium's own tolerance).
    bool left_range = false;
    Excess bad;
    auto f = [&](double t) {
        if (left_range) return 1.0;
        Excess e = excess(m, omega, t, o, false);
        ++p.solves;
        if (e.out_of_range) {
            left_range = true;
            bad = e;
            return 1.0;
        }
        return e.dT;
    };
    std::uintmax_t iters = 100;
    const auto stop = [](double a, double b) { return std::abs(b - a) <= 1e-7 * std::max(1.0, std::abs(b)); };
    double root = t_hi;
    if (hi.dT == 0.0) {
        root = t_hi;
    } else {
        const auto [a, b] = boost::math::tools::toms748_solve(f, t_lo, t_hi, lo.dT, hi.dT, stop, iters);
        (void)b;
        root = a;  // the lower end: the oil at or just below the limit, so the point is admissible
    }
    if (left_range) return out_of_range(bad);
    p.status = RatingStatus::limit;
    p.torque = root;
    p.point = excess(m, omega, root, o, true).r;
    ++p.solves;
    if (!solver::has_values(p.point.status)) return out_of_range(Excess{p.point, 0.0, true});
    finish(m, p, o);
    return p;
}

CoolerDutyPoint cooler_duty(const solver::Model& m, double omega, double torque, double T_target, double ambient) {
    solver::Model held = m;
    held.thermal.mode = solver::ThermalMode::fixed;
    held.thermal.oil_temperature = T_target;
    CoolerDutyPoint c;
    c.omega = omega;
    c.torque = torque;
    c.point = solver::solve_point(held, omega, torque, true, ambient);
    if (solver::has_values(c.point.status)) {
        c.housing_heat = m.housing_heat_flow(T_target, ambient, omega);
        c.duty = std::max(0.0, c.point.losses.total() - c.housing_heat);
    }
    return c;
}

}  // namespace gearloss::rating
