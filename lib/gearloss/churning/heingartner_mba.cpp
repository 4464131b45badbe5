#include "gearloss/churning/heingartner_mba.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace gearloss::churning {

double dip_factor(double immersion, double tip_diameter) {
    if (!(immersion > 0) || !(tip_diameter > 0)) return 0.0;
    return std::min(immersion / tip_diameter, 1.0);
}

bool heingartner_mba_defined(const ToothSurfaceGear& g) {
    return g.dip_factor > 0 && g.helix > 0 && std::tan(g.helix) > 0 && g.tip_diameter > 0 && g.b > 0;
}

double heingartner_mba_coefficient(const ToothSurfaceGear& g, double omega, double roughness_factor,
                                   double arrangement_constant) {
    if (!heingartner_mba_defined(g) || !(arrangement_constant > 0)) return 0.0;
    // The source's units (docs/config.md): n [min^-1], D and b [mm], mu [mPa s], P [W].
    const double n_rpm = std::abs(omega) * 30.0 / std::numbers::pi;
    const double D_mm = g.tip_diameter * 1e3, b_mm = g.b * 1e3;
    const double mPas_per_Pas = 1e3;
    // Heingartner & Mba (2003) via seed 003: P = 7.37 f_g mu n^3 D^4.7 b (R_f/sqrt(tan beta)) / (A_g 1e23).
    return 7.37 * g.dip_factor * mPas_per_Pas * n_rpm * n_rpm * n_rpm * std::pow(D_mm, 4.7) * b_mm *
           (roughness_factor / std::sqrt(std::tan(g.helix))) / (arrangement_constant * 1e23);
}

double heingartner_mba_power(const ToothSurfaceGear& g, double omega, double mu, double roughness_factor,
                             double arrangement_constant) {
    return heingartner_mba_coefficient(g, omega, roughness_factor, arrangement_constant) * mu;
}

}  // namespace gearloss::churning
