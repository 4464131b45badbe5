#include "gearloss/thermal/heat_rejection.hpp"

#include "gearloss/thermal/air.hpp"

#include <algorithm>

#include <cmath>

namespace gearloss::thermal {

namespace {
constexpr double sigma_SB = 5.670374419e-8;

// Dry air at atmospheric pressure (gearloss/thermal/air.hpp), conductivity ~T^0.81 (fits 250-400 K
// within 2 %), Pr = 0.71.
struct Air {
    double nu, k, Pr = 0.71;
    explicit Air(double T) {
        nu = air_viscosity(T) / air_density(T);
        k = 0.0241 * std::pow(T / 273.15, 0.81);
    }
};
}  // namespace

bool HeatRejection::depends_on_speed() const {
    const auto* r = std::get_if<ThermalResistance>(&model);
    return r && r->depends_on_speed();
}

double ThermalResistance::resistance(double omega) const {
    const double w = std::abs(omega);
    if (!depends_on_speed() || w <= n_ref) return R0;
    return R0 * std::pow(w / n_ref, -exponent);
}

double HousingSurface::convection_coefficient(double Tw, double Ta) const {
    const double Tf = 0.5 * (Tw + Ta);
    const Air air(Tf);
    const double dT = std::abs(Tw - Ta);
    // Free convection on vertical walls: Nu = 0.59 Ra^1/4 (laminar), 0.10 Ra^1/3 (turbulent).
    const double Ra = 9.80665 * (1.0 / Tf) * dT * height * height * height / (air.nu * air.nu) * air.Pr;
    const double Nu_free = Ra < 1e9 ? 0.59 * std::pow(Ra, 0.25) : 0.10 * std::cbrt(Ra);
    double Nu_forced = 0.0;
    if (air_speed > 0.0) {
        // Flat plate: Nu = 0.664 Re^1/2 Pr^1/3 (laminar), 0.037 Re^0.8 Pr^1/3 (turbulent).
        const double Re = air_speed * length / air.nu;
        Nu_forced = Re < 5e5 ? 0.664 * std::sqrt(Re) * std::cbrt(air.Pr) : 0.037 * std::pow(Re, 0.8) * std::cbrt(air.Pr);
    }
    const double h_free = Nu_free * air.k / height;
    const double h_forced = air_speed > 0.0 ? Nu_forced * air.k / length : 0.0;
    // Mixed convection: cube-root sum of the two mechanisms (Churchill).
    return std::cbrt(h_free * h_free * h_free + h_forced * h_forced * h_forced);
}

double HousingSurface::radiation_coefficient(double Tw, double Ta) const {
    return emissivity * sigma_SB * (Tw * Tw + Ta * Ta) * (Tw + Ta);
}

double HeatRejection::heat_flow(double T, double Ta, double omega, double air_speed) const {
    if (const auto* r = std::get_if<ThermalResistance>(&model)) return (T - Ta) / r->resistance(omega);
    HousingSurface h = std::get<HousingSurface>(model);
    h.air_speed = std::max(h.air_speed, air_speed);
    return (h.convection_coefficient(T, Ta) + h.radiation_coefficient(T, Ta)) * h.area * (T - Ta);
}

}  // namespace gearloss::thermal
