#include "gearloss/mesh/friction.hpp"

#include <algorithm>
#include <boost/math/tools/toms748_solve.hpp>
#include <cmath>
#include <cstdint>
#include <limits>
#include <numbers>

namespace gearloss::mesh {

namespace {
// The turning point of the corrected film: -d ln(phi_T)/d ln L there. At fixed alpha, beta and k
// the Ertel-Grubin film (~ eta0^(8/11)) would turn at 8/11; in a cold oil beta rises (as 1/ln nu
// for a Walther oil) and so L ~ beta eta0 / k grows faster than eta0, and the shipped oils' films
// as published already thin (by up to 0.1 % per K) before that slope. The load term is held from
// a slope of 1/2: a margin of this implementation, not of the correlation's source.
constexpr double kGuptaTurningSlope = 0.5;
}  // namespace

double mean_friction_schlenk(double w, double v_sum, double rho_mm, double eta_mPas, double Ra_um, double X_L) {
    if (w <= 0.0) return 0.0;
    return 0.048 * std::pow(w / (v_sum * rho_mm), 0.2) * std::pow(eta_mPas, -0.05) * std::pow(Ra_um, 0.25) * X_L;
}

double mean_friction_iso_6336_20(double w, double v_sum, double rho_mm, double eta_mPas, double Ra_um, double X_L) {
    if (w <= 0.0) return 0.0;
    return 0.060 * std::pow(w / (v_sum * rho_mm), 0.2) * X_L * std::pow(eta_mPas, -0.05) * std::pow(Ra_um, 0.25);
}

double boundary_share_doleschel(double lambda, double onset) {
    if (!(lambda < onset)) return 0.0;
    const double s = 1.0 - std::max(lambda, 0.0) / onset;
    return s * s;
}

double hertz_pressure(double w_line, double R, double E_prime) {
    return std::sqrt(w_line * 0.5 * E_prime / (std::numbers::pi * R));
}

double gupta_turning_point(double p_ratio, double SRR) {
    const double c = 13.2 * p_ratio, b = 0.213 * (1.0 + 2.23 * std::pow(SRR, 0.83));
    if (!(c > 0)) return std::numeric_limits<double>::infinity();
    if (!std::isfinite(c) || !std::isfinite(b)) return 0.0;
    // d ln(phi_T)/d ln L of the full form + the turning slope:
    // falls monotonically with L (both terms of d ln phi_T/d ln L grow in magnitude), > 0 at
    // L -> 0 and -> -infinity where the numerator reaches 0, L0 = (1/c)^(1/0.42).
    auto excess = [&](double lnL) {
        const double x = c * std::exp(0.42 * lnL), y = b * std::exp(0.64 * lnL);
        return kGuptaTurningSlope - 0.42 * x / (1.0 - x) - 0.64 * y / (1.0 + y);
    };
    const double lnL0 = -std::log(c) / 0.42;
    // excess(lo) > 0 (x and y negligible there) > excess(hi) (x just below 1)
    double lo = std::min(-50.0, lnL0 - 60.0), hi = lnL0 - 1e-9;
    std::uintmax_t it = 100;
    const auto [a, z] = boost::math::tools::toms748_solve(
        excess, lo, hi, excess(lo), excess(hi), [](double u, double v) { return std::abs(v - u) < 1e-10; }, it);
    return std::exp(0.5 * (a + z));
}

double gupta_thermal_factor(double L, double p_ratio, double SRR) {
    if (std::isnan(L) || std::isnan(p_ratio) || std::isnan(SRR)) return std::numeric_limits<double>::quiet_NaN();
    if (!(L > 0)) return 1.0;
    const double c = 13.2 * p_ratio;
    if (!std::isfinite(L) || !std::isfinite(c)) return 0.0;  // the inlet heating or the load term without bound
    const double b = 0.213 * (1.0 + 2.23 * std::pow(SRR, 0.83));
    // Gupta et al. (1992), full form: the load term in the numerator. Past the
    // turning point L* of the film it predicts (kGuptaTurningSlope),
    // the correlation has the film thinning as the oil thickens and reaching zero at
    // 13.2 (p_H/E') L^0.42 = 1 (a cold oil at speed): outside the range it was fitted on. There
    // the load term is held at its value at L* and the denominator (the inlet shear heating,
    // phi_T ~ L^-0.64 at large L) goes on: phi_T continuous, the film still thickening
    // with the oil (slowly, as the inlet heating caps it).
    auto denominator = [&](double l) { return 1.0 + b * std::pow(l, 0.64); };
    const double x = c * std::pow(L, 0.42), y = b * std::pow(L, 0.64);
    const bool beyond = !(x < 1.0) || kGuptaTurningSlope - 0.42 * x / (1.0 - x) - 0.64 * y / (1.0 + y) < 0.0;
    if (!beyond) return (1.0 - x) / denominator(L);
    const double L_star = gupta_turning_point(p_ratio, SRR);
    return (1.0 - c * std::pow(L_star, 0.42)) / denominator(L);
}

Film line_contact_film(const LineContact& c, double eta0, double alpha_p, double beta_T, double k_oil,
                       ThermalFilmCorrection corr) {
    Film f;
    f.p_hertz = hertz_pressure(c.w_line, c.R, c.E_prime);
    if (c.u_e <= 0.0) return f;  // no entrainment, no hydrodynamic film
    const double U = eta0 * c.u_e / (c.E_prime * c.R);
    const double G = alpha_p * c.E_prime;
    // An unloaded contact still separates; a tiny floor load keeps W finite.
    const double W = std::max(c.w_line, 1.0) / (c.E_prime * c.R);
    const double Hc = 1.95 * std::pow(G * U, 8.0 / 11.0) * std::pow(W, -1.0 / 11.0);
    const double Hmin = 2.65 * std::pow(U, 0.70) * std::pow(G, 0.54) * std::pow(W, -0.13);
    switch (corr) {
        case ThermalFilmCorrection::gupta: {
            const double L = beta_T * eta0 * c.u_e * c.u_e / k_oil;
            f.phi_T = gupta_thermal_factor(L, f.p_hertz / c.E_prime, c.SRR);
            break;
        }
        case ThermalFilmCorrection::simplified: {
            const double us = 2.0 * c.u_e;
            const double L = beta_T * eta0 * us * us / k_oil;
            f.phi_T = 1.0 / (1.0 + 0.1 * (1.0 + 14.8 * std::pow(c.SRR, 0.83)) * std::pow(L, 0.64));
            break;
        }
        case ThermalFilmCorrection::none: f.phi_T = 1.0; break;
    }
    f.h_c = f.phi_T * Hc * c.R;
    f.h_min = f.phi_T * Hmin * c.R;
    return f;
}

}  // namespace gearloss::mesh
