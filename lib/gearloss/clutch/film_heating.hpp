#pragma once
// Viscous heating of the oil film of an open wet clutch: thermal Couette flow with an
// exponential viscosity law (Nahme 1940; Gavis & Laurence 1968). In cold, thick oil at
// high slip the film's own heat lowers its viscosity and caps the drag, which the
// isothermal film of wet_clutch.hpp does not.
#include "gearloss/clutch/wet_clutch.hpp"
#include "gearloss/lubricant/oil.hpp"

namespace gearloss::clutch {

// Nahme number of a sheared film, Na = beta eta0 U^2 / k: the viscous heat of the film
// against what conduction to the walls removes, in units of the oil's thermoviscosity
// beta = -d ln(eta)/dT (Nahme 1940; Gavis & Laurence 1968). 0 without thermoviscosity.
double nahme_number(double beta, double eta0, double U, double k);

// Shear stress of plane Couette flow with viscous heating, both walls at the oil temperature,
// eta = eta0 exp(-beta (T - T0)), against the isothermal eta0 U / h:
// tau / tau_iso = 2x / sinh(2x), sinh(x) = sqrt(Na / 8) (closed form of k T'' = -tau du/dz,
// Nahme 1940; Gavis & Laurence 1968). 1 - Na/12 for a small Na; 1 at Na = 0.
double thermal_shear_factor(double nahme);

// The closed form takes the viscosity as exponential about the plates' temperature; it is kept
// within its range while the film's core stays within 1/beta of the plates: 2 ln cosh x <= 1,
// i.e. Na <= 8 (cosh^2 x - 1) = 8 (e - 1) = 13.75. Beyond it the drag is an extrapolation
// (reported as a plausibility note, gearloss/solver/plausibility.hpp).
inline constexpr double film_heating_nahme_limit = 8.0 * (2.718281828459045 - 1.0);

// Drag of an open pack with the film's viscous heating: the local shear stress eta dw r / h
// is reduced by thermal_shear_factor(Na(r)), Na(r) = beta eta (dw r)^2 / k, and integrated
// over the full film and, times the oil fraction, over the two-phase region beyond it (times
// 1 + phi_fs of Patir & Cheng 1979); the air between the streaks shears at its own viscosity.
// The outflow that sets the wetted radius (Yuan et al. 2007) and the oil fraction uses the
// film's apparent viscosity at the pack's mean radius. The plates are taken at the oil
// temperature (the supply cools them): hotter plates would lower the drag further, so this is
// the upper bound of the heated film.
ClutchDrag open_pack_drag(const WetClutchPack& c, const lubricant::OilState& oil, double slip_speed);

}  // namespace gearloss::clutch
