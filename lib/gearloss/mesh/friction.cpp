#include "gearloss/mesh/friction.hpp"

#include <cmath>
#include <numbers>

namespace gearloss::mesh {

double mean_friction_schlenk(double w, double v_sum, double rho_mm, double eta_mPas, double Ra_um, double X_L) {
    if (w <= 0.0) return 0.0;
    return 0.048 * std::pow(w / (v_sum * rho_mm), 0.2) * std::pow(eta_mPas, -0.05) * std::pow(Ra_um, 0.25) * X_L;
}

double mean_friction_iso_6336_20(double w, double v_sum, double rho_mm, double eta_mPas, double Ra_um, double X_L) {
    if (w <= 0.0) return 0.0;
    return 0.060 * std::pow(w / (v_sum * rho_mm), 0.2) * X_L * std::pow(eta_mPas, -0.05) * std::pow(Ra_um, 0.25);
}

double boundary_share_doleschel(double lambda) {
    if (!(lambda < 2.0)) return 0.0;
    const double s = 1.0 - 0.5 * std::max(lambda, 0.0);
    return s * s;
}

double hertz_pressure(double w_line, double R, double E_prime) {
    return std::sqrt(w_line * 0.5 * E_prime / (std::numbers::pi * R));
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
            const double num = 1.0 - 13.2 * (f.p_hertz / c.E_prime) * std::pow(L, 0.42);
            const double den = 1.0 + 0.213 * (1.0 + 2.23 * std::pow(c.SRR, 0.83)) * std::pow(L, 0.64);
            f.phi_T = std::max(num, 0.0) / den;
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
