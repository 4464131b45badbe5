#include "gearloss/churning/changenet_velex.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>

namespace gearloss::churning {

namespace {
constexpr double g_acc = 9.80665;
constexpr double Re_low = 6000.0, Re_high = 9000.0, band = Re_high - Re_low;
}  // namespace

const char* to_string(Regime r) {
    switch (r) {
        case Regime::none: return "none";
        case Regime::low_reynolds: return "Re_c<6000";
        case Regime::transition: return "6000<Re_c<9000";
        case Regime::high_reynolds: return "Re_c>9000";
        case Regime::capped: return "capped";
    }
    return "?";
}

double submerged_surface(const DippingGear& g) {
    if (g.h <= 0.0) return 0.0;
    // Beyond the full diameter the gear is fully immersed: theta = pi.
    const double h = std::min(g.h, 2.0 * g.Rp);
    const double theta = std::acos(1.0 - h / g.Rp);
    const double R = g.Rp;
    return R * R * (2.0 * theta - std::sin(2.0 * theta)) + 2.0 * R * g.b * theta +
           2.0 * g.z * theta * g.tooth_height * g.b / (std::numbers::pi * std::cos(g.alpha));
}

double critical_reynolds(double omega, double Rp, double b, double nu) { return std::abs(omega) * Rp * b / nu; }

ChurningAtSpeed ChurningAtSpeed::make(const DippingGear& g, double omega, double V0) {
    ChurningAtSpeed c;
    c.omega = std::abs(omega);
    c.ReC_times_nu = c.omega * g.Rp * g.b;
    c.ReC_cap = std::numeric_limits<double>::infinity();
    const double Sm = submerged_surface(g);
    if (Sm <= 0.0 || c.omega <= 0.0) return c;
    const double D = 2.0 * g.Rp;
    const double hD = std::min(g.h, D) / D;
    const double VD = V0 / (D * D * D);
    const double Fr = c.omega * c.omega * g.Rp / g_acc;
    const double pre = 0.5 * c.omega * c.omega * Sm * std::pow(g.Rp, 3);
    // Changenet & Velex (2007), C_m of each regime:
    //   Re_c < 6000: C_m = 1.366 (h/D)^0.45 (V0/D^3)^0.1 Fr^-0.6 Re^-0.21
    //   Re_c > 9000: C_m = 3.644 (h/D)^0.1 (V0/D^3)^-0.35 Fr^-0.88 (b/D)^0.85
    // Re = Omega Rp^2 / nu, so Re^-0.21 = (Omega Rp^2)^-0.21 * nu^0.21.
    const double Re_nu = c.omega * g.Rp * g.Rp;
    c.coef_low = pre * 1.366 * std::pow(hD, 0.45) * std::pow(VD, 0.1) * std::pow(Fr, -0.6) * std::pow(Re_nu, -0.21);
    c.coef_high = pre * 3.644 * std::pow(hD, 0.1) * std::pow(VD, -0.35) * std::pow(Fr, -0.88) *
                  std::pow(g.b / D, 0.85);

    // The running minimum over Re_c (see the header). With nu = K / Re_c (K = Omega Rp b)
    // the low-Re torque is a Re_c^-0.21, a = coef_low K^0.21, and the band blend is
    // g(Re_c) = (1 - f) a Re_c^-0.21 + f coef_high, f = (Re_c - 6000) / 3000, strictly convex.
    const double a = c.coef_low * std::pow(c.ReC_times_nu, 0.21);
    const auto blend = [&](double Re) {
        const double f = (Re - Re_low) / band;
        return (1.0 - f) * a * std::pow(Re, -0.21) + f * c.coef_high;
    };
    const auto slope = [&](double Re) {
        const double f = (Re - Re_low) / band;
        return (c.coef_high - a * std::pow(Re, -0.21)) / band - 0.21 * a * (1.0 - f) * std::pow(Re, -1.21);
    };
    if (slope(Re_high) <= 0.0) return c;  // the published curve falls all the way: no cap
    double lo = Re_low, hi = Re_high;
    if (slope(Re_low) < 0.0) {
        // Bisection on the increasing g' (60 halvings of 3000: below 1e-14 of the band).
        for (int i = 0; i < 60; ++i) {
            const double mid = 0.5 * (lo + hi);
            (slope(mid) < 0.0 ? lo : hi) = mid;
        }
    }
    c.ReC_cap = lo;
    c.coef_cap = blend(lo);
    return c;
}

double ChurningAtSpeed::published(double rho, double nu, double nu_pow_021, Regime* regime) const {
    if (coef_low == 0.0 && coef_high == 0.0) {
        if (regime) *regime = Regime::none;
        return 0.0;
    }
    const double ReC = ReC_times_nu / nu;
    const double low = coef_low * nu_pow_021;
    const double high = coef_high;
    double Cm_part;
    if (ReC < Re_low) {
        Cm_part = low;
        if (regime) *regime = Regime::low_reynolds;
    } else if (ReC > Re_high) {
        Cm_part = high;
        if (regime) *regime = Regime::high_reynolds;
    } else {
        // Seed 000 interpolates linearly on Re_c between the two formulas.
        const double f = (ReC - Re_low) / band;
        Cm_part = (1.0 - f) * low + f * high;
        if (regime) *regime = Regime::transition;
    }
    return rho * Cm_part;
}

double ChurningAtSpeed::torque(double rho, double nu, double nu_pow_021, Regime* regime) const {
    if (coef_low != 0.0 && ReC_times_nu > ReC_cap * nu) {  // Re_c > Re_c*, without a division
        if (regime) *regime = Regime::capped;
        return rho * coef_cap;
    }
    return published(rho, nu, nu_pow_021, regime);
}

double ChurningAtSpeed::transition_excess() const {
    if (coef_low <= 0.0) return 0.0;
    return coef_high / (coef_low * std::pow(ReC_times_nu / Re_low, 0.21));
}

TransitionCap transition_cap(const DippingGear& g, double V0, double omega_reference) {
    const double e0 = ChurningAtSpeed::make(g, omega_reference, V0).transition_excess();
    const double e1 = ChurningAtSpeed::make(g, 2.0 * omega_reference, V0).transition_excess();
    if (!(e0 > 0 && e1 > 0)) return {};
    const double k = std::log(e1 / e0) / std::log(2.0);  // excess ~ Omega^k
    const double threshold = std::pow(Re_low / Re_high, 0.21);
    if (!(k < 0)) return {e0 > threshold ? std::numeric_limits<double>::infinity() : 0.0, e0};
    return {omega_reference * std::pow(threshold / e0, 1.0 / k), e0};
}

double dimensionless_torque(const DippingGear& g, double omega, double nu, double V0, Regime* regime) {
    const ChurningAtSpeed c = ChurningAtSpeed::make(g, omega, V0);
    const double Sm = submerged_surface(g);
    if (Sm <= 0.0 || omega == 0.0) {
        if (regime) *regime = Regime::none;
        return 0.0;
    }
    const double pre = 0.5 * omega * omega * Sm * std::pow(g.Rp, 3);
    return c.torque(1.0, nu, std::pow(nu, 0.21), regime) / pre;
}

double churning_torque(const DippingGear& g, double omega, double rho, double nu, double V0, Regime* regime) {
    return ChurningAtSpeed::make(g, omega, V0).torque(rho, nu, std::pow(nu, 0.21), regime);
}

double published_torque(const DippingGear& g, double omega, double rho, double nu, double V0, Regime* regime) {
    return ChurningAtSpeed::make(g, omega, V0).published(rho, nu, std::pow(nu, 0.21), regime);
}

}  // namespace gearloss::churning
