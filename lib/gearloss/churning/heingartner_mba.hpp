#pragma once
// Churning of the toothed surface of a dipping gear: Heingartner & Mba (2003), as quoted
// by Gillot, Picarelli & Dempsey (seed 003, §3.5, "The churning losses for tooth
// surface are given by"):
//
//     P = 7.37 f_g mu n^3 D^4.7 b (R_f / sqrt(tan beta)) / (A_g 10^23)
//
// f_g dip factor ("the ratio of the gear dipping into oil"), mu dynamic viscosity of the
// oil, n speed, D outside diameter, b face width, beta helix angle, R_f roughness factor,
// A_g arrangement constant. The quote gives neither the units nor values of R_f and A_g.
// Units used here (the reading whose magnitude is that of Changenet & Velex 2007 for the
// same gear, docs/config.md "Churning forms"): n [min^-1], D and b [mm], mu [mPa s],
// P [W] -- the same numbers as mu [Pa s] with P [kW]. The companion formulae of the
// source for smooth outside diameters and disc sides are not quoted and not included.
// The expression diverges for spur teeth (tan beta = 0); for those gears the churning
// mechanism keeps its default form (see churning_mechanism.cpp).

namespace gearloss::churning {

struct ToothSurfaceGear {
    double tip_diameter = 0;  // D [m]
    double b = 0;             // face width [m]
    double helix = 0;         // beta [rad], > 0
    double dip_factor = 0;    // f_g: immersion depth of the tip circle over the tip diameter, 0..1
};

// The dip factor f_g read as the immersed fraction of the outside diameter, h / D (0..1).
double dip_factor(double immersion, double tip_diameter);

// Whether the quoted expression has a value for the gear (a helical gear that dips).
bool heingartner_mba_defined(const ToothSurfaceGear& g);

// P / mu [W / (Pa s)] at speed omega [rad/s], so that P = coefficient * mu with mu the
// dynamic viscosity in Pa s (SI in, SI out; the source's units are converted inside).
double heingartner_mba_coefficient(const ToothSurfaceGear& g, double omega, double roughness_factor,
                                   double arrangement_constant);

// The churning power [W] of the tooth surface at speed omega [rad/s] and dynamic viscosity
// mu [Pa s]; 0 where the expression has no value.
double heingartner_mba_power(const ToothSurfaceGear& g, double omega, double mu, double roughness_factor,
                             double arrangement_constant);

}  // namespace gearloss::churning
