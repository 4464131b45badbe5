#pragma once
// Windage: the drag of the air (or air/oil mist) on one rotating gear, from its geometry and
// speed (the loss mechanism using it: gearloss/mechanisms/windage_mechanism.cpp).

namespace gearloss::windage {

// Anderson & Loewenthal (1980), NASA TP-1622: windage power [W] of one gear,
// P = 2.82e-7 (1 + 2.3 b/R) n^2.8 R^4.6 (0.028 mu + 0.019)^0.2 [kW] with n [rpm] and mu [cP];
// R pitch radius, b face width [m], omega [rad/s], mist viscosity mu [Pa s].
double anderson_loewenthal_power(double R, double b, double omega, double mu);

// Free rotating disk, both faces (von Karman 1921; Cochran 1934): power [W] for radius R [m],
// speed omega [rad/s] in a gas of density rho [kg/m^3] and kinematic viscosity nu [m^2/s].
double free_disk_power(double R, double omega, double rho, double nu);

}  // namespace gearloss::windage
