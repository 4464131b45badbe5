#pragma once
// Heat flow from the oil to the surroundings (convection: Incropera et al. 2007, ch. 7 and 9; Churchill 1977).
#include <variant>

namespace gearloss::thermal {

// Equivalent thermal resistance from a rig, optionally falling with speed as
// air is stirred by rotating parts: R(n) = R0 (n/n_ref)^-b for n > n_ref.
struct ThermalResistance {
    double R0 = 0.1;       // K/W
    double n_ref = 0;      // rad/s; 0 = no speed dependence
    double exponent = 0;   // b
    double resistance(double omega_in) const;
    // R falls with speed above n_ref (both n_ref and b given); else R = R0 at every speed.
    bool depends_on_speed() const { return n_ref > 0.0 && exponent != 0.0; }
};

// Housing surface: convection (free/forced, mixed by the cube rule) and
// radiation; housing wall assumed at oil temperature (splash-lubricated box).
struct HousingSurface {
    double area = 0.5;          // m^2
    double emissivity = 0.9;    // painted housing
    double height = 0.3;        // characteristic vertical length for free convection [m]
    double length = 0.3;        // flow length for forced convection [m]
    double air_speed = 0.0;     // m/s
    double convection_coefficient(double T_wall, double T_amb) const;  // W/(m^2 K)
    double radiation_coefficient(double T_wall, double T_amb) const;   // W/(m^2 K)
};

struct HeatRejection {
    std::variant<ThermalResistance, HousingSurface> model;
    // Heat flow [W] at oil temperature T_oil, ambient T_amb (K), input speed omega. A
    // housing surface sees at least `air_speed` [m/s] (e.g. the under-body flow of a moving
    // vehicle) when it exceeds its own.
    double heat_flow(double T_oil, double T_amb, double omega_in, double air_speed = 0.0) const;
    // Whether the heat flow at a given oil temperature changes with the input speed (a
    // resistance falling with speed); a housing surface's air speed is imposed from outside.
    bool depends_on_speed() const;
};

}  // namespace gearloss::thermal
