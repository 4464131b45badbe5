#include "gearloss/windage/gear_windage.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace gearloss::windage {

// Anderson & Loewenthal (1980): windage power [W] of one gear; R, b [m], omega [rad/s],
// mist viscosity mu [Pa s].
double anderson_loewenthal_power(double R, double b, double omega, double mu) {
    const double n = std::abs(omega) * 30.0 / std::numbers::pi;  // rpm
    const double mu_cP = mu * 1e3;
    return 1e3 * 2.82e-7 * (1.0 + 2.3 * b / R) * std::pow(n, 2.8) * std::pow(R, 4.6) * std::pow(0.028 * mu_cP + 0.019, 0.2);
}

// Free rotating disk, both faces (von Karman 1921; Cochran 1934): power [W] for radius R [m],
// speed omega [rad/s] in a gas of density rho [kg/m^3] and kinematic viscosity nu [m^2/s].
double free_disk_power(double R, double omega, double rho, double nu) {
    const double w = std::abs(omega);
    if (w == 0.0) return 0.0;
    const double Re = w * R * R / nu;
    const double C_M = std::max(3.87 / std::sqrt(Re), 0.146 * std::pow(Re, -0.2));
    return C_M * 0.5 * rho * w * w * std::pow(R, 5) * w;
}

}  // namespace gearloss::windage
