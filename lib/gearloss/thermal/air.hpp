#pragma once
// Dry air: density as an ideal gas (R = 287.05 J/(kg K)) and dynamic viscosity after
// Sutherland (1893) (mu0 = 1.716e-5 Pa s at 273.15 K, S = 110.4 K). Used by the housing's
// convection and by gear windage.
#include <cmath>

namespace gearloss::thermal {

inline double air_density(double T, double p = 101325.0) { return p / (287.05 * T); }
inline double air_viscosity(double T) { return 1.716e-5 * std::pow(T / 273.15, 1.5) * (273.15 + 110.4) / (T + 110.4); }

}  // namespace gearloss::thermal
