#include "gearloss/churning/changenet_velex.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace gearloss::churning {

namespace {
constexpr double g_acc = 9.80665;
constexpr double Re_low = 6000.0, Re_high = 9000.0;
}  // namespace

const char* to_string(Regime r) {
    switch (r) {
        case Regime::none: return "none";
        case Regime::low_reynolds: return "Re_c<6000";
        case Regime::transition: return "6000<Re_c<9000";
        case Regime::high_reynolds: return "Re_c>9000";
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
    const double Sm = submerged_surface(g);
    if (Sm <= 0.0 || c.omega <= 0.0) return c;
    const double D = 2.0 * g.Rp;
    const double hD = std::min(g.h, D) / D;
    const double VD = V0 / (D * D * D);
    const double Fr = c.omega * c.omega * g.Rp / g_acc;
    const double pre = 0.5 * c.omega * c.omega * Sm * std::pow(g.Rp, 3);
    // Re = Omega Rp^2 / nu, so Re^-0.21 = (Omega Rp^2)^-0.21 * nu^0.21.
    const double Re_nu = c.omega * g.Rp * g.Rp;
    c.coef_low = pre * 1.366 * std::pow(hD, 0.45) * std::pow(VD, 0.1) * std::pow(Fr, -0.6) * std::pow(Re_nu, -0.21);
    c.coef_high = pre * 3.644 * std::pow(hD, 0.1) * std::pow(VD, -0.35) * std::pow(Fr, -0.88) *
                  std::pow(g.b / D, 0.85);
    return c;
}

double ChurningAtSpeed::torque(double rho, double nu, double nu_pow_021, Regime* regime) const {
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
        const double f = (ReC - Re_low) / (Re_high - Re_low);
        Cm_part = (1.0 - f) * low + f * high;
        if (regime) *regime = Regime::transition;
    }
    return rho * Cm_part;
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

}  // namespace gearloss::churning
