#pragma once
// Viscoelastic (Maxwell-Eyring) shear of the film through a line contact: Johnson &
// Tevaarwerk (1977), in the form of Evans & Johnson (1986) and Olver & Spikes (1998):
//
//   gamma_dot = (u_e / G) d tau / dx + (tau_E / eta) sinh(tau / tau_E),   tau <= tau_L,
//
// the film entering at x = -a unstressed (tau = 0) and carried through the Hertz zone at the
// entrainment speed u_e. The Deborah number De = eta u_e / (G a) of each part of the zone says
// whether the elastic term matters: De << 1 gives the Eyring stress tau_E asinh(eta gamma_dot
// / tau_E) at every x; De >> 1 the elastic stress G gamma_dot (x + a) / u_e; both are capped
// by the limiting shear stress tau_L (Bair & Winer 1979).
#include <span>

#include "gearloss/lubricant/oil.hpp"

namespace gearloss::mesh {

// One slice of the Hertz zone, of width dx [m], with uniform viscosity eta [Pa s], shear
// modulus G [Pa] and limiting shear stress tau_L [Pa].
struct MaxwellCell {
    double dx = 0, eta = 0, G = 0, tau_L = 0;
};

// Stress after a slice of length dx when it enters at tau0: the exact solution of the
// Maxwell-Eyring equation for uniform properties (Johnson & Tevaarwerk 1977). With
// z = exp(tau / tau_E) and S = eta gamma_dot / tau_E the equation is
//   dz / dx = (G / (2 u_e eta)) (1 + 2 S z - z^2),
// whose roots z+ = S + sqrt(S^2 + 1) (the Eyring stress) and z- = -1 / z+ give
//   phi(x) = (z+ - z) / (z - z-) = phi0 exp(-G sqrt(S^2 + 1) dx / (u_e eta)),
// unconditionally stable for any Deborah number (the stiff Eyring limit is phi -> 0).
// Not capped by tau_L (the caller caps).
double maxwell_eyring_step(double tau0, double dx, double gamma_dot, double u_e, double eta, double G, double tau_E);

// Mean shear stress over the slices (weighted by their widths), the film entering the first
// slice unstressed: per slice the exact step to its middle and its end, the stress capped
// by tau_L; the mean over the slice by Simpson's rule, or, for a slice longer than two
// relaxation lengths (viscous), by the exponential approach to the Eyring stress.
double maxwell_eyring_mean_stress(std::span<const MaxwellCell> cells, double gamma_dot, double u_e, double tau_E);

// Shear modulus of the oil at pressure p [Pa] and temperature T [K]:
// G = (G0 + G_p p) exp(-beta_G (T - T_ref)) (the `rheology:` block of the oil file).
double shear_modulus(const lubricant::TractionProperties& rh, double p, double T);

}  // namespace gearloss::mesh
