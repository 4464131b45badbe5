#pragma once
// Thermal EHL traction of one line contact (Hertz: Johnson 1985, ch. 4; after
// Olver & Spikes 1998 and Evans & Johnson 1986): Roelands viscosity at the film
// temperature, Eyring shear capped by a limiting shear stress, integrated over
// the Hertz pressure; flash temperature (Jaeger 1942 band source, Blok 1937 partition) and
// Couette shear heating, converged by bracketing; mixed friction through Lambda.
// Traction law: Eyring capped by tau_L (the stress in equilibrium with the shear rate at
// every x), or viscoelastic Maxwell-Eyring (Johnson & Tevaarwerk 1977; viscoelastic.hpp),
// the stress building up elastically from the inlet.
#include "gearloss/lubricant/oil.hpp"
#include "gearloss/mesh/friction.hpp"

namespace gearloss::mesh {

using Rheology = lubricant::TractionProperties;

enum class TractionLaw { eyring, maxwell_eyring };

struct Solid {
    double density = 7850, specific_heat = 460, conductivity = 46;  // steel
    double diffusivity() const { return conductivity / (density * specific_heat); }
};

struct EhlContactInput {
    double w_line = 0;     // load per unit length [N/m]
    double R = 0;          // reduced radius [m]
    double u1 = 0, u2 = 0; // surface speeds along the rolling direction [m/s]
    double E_prime = 0;    // [Pa]
    double sigma = 0;      // composite roughness for Lambda [m]
    double T_bulk = 0;     // oil / surface bulk temperature [K]
    double film_rise_guess = 0;  // start of the film-temperature loop above T_bulk [K] (warm start)
    TractionLaw law = TractionLaw::eyring;
    double viscosity_factor = 1.0;  // the case's calibration of the oil's viscosity (Oil::state)
};

struct EhlContactResult {
    double p0 = 0, a = 0;          // Hertz maximum pressure [Pa], half-width [m]
    double h_c = 0, h_min = 0;     // film thickness (thermal inlet correction) [m]
    double lambda = 0;
    double T_film = 0;             // mean film temperature [K]
    double dT_flash = 0, dT_shear = 0;
    double mu_ehl = 0, f_c = 0, mu = 0;
    double residual = 0;           // |T - F(T)| at the solution [K]
    // Deborah number eta(p0) u_e / (G a) at the centre of the contact (film temperature);
    // computed by the Maxwell-Eyring law only (0 otherwise).
    double deborah = 0;
};

// `heating = false` gives the isothermal solution (film at T_bulk).
// `bulk` may pass the oil state at T_bulk when the caller already has it (many
// contacts at one oil temperature).
EhlContactResult ehl_contact(const EhlContactInput& in, const lubricant::Oil& oil, const Rheology& rh,
                             const Solid& solid = {}, bool heating = true, const lubricant::OilState* bulk = nullptr);

// Roelands (1966): eta(p) = eta0 exp{(ln eta0 + 9.67)[(1 + p/p_r)^Z - 1]}, p_r = 1.96e8 Pa,
// Z from the pressure-viscosity coefficient: Z = alpha p_r / (ln eta0 + 9.67). The terms
// fixed by eta0 and alpha are computed once for evaluation at many pressures.
struct RoelandsLaw {
    RoelandsLaw(double eta0, double alpha);
    // With a given pressure index Z (> 0) instead of alpha.
    static RoelandsLaw with_index(double eta0, double Z);
    double viscosity(double p) const;
    double eta0, s, Z;  // s = ln eta0 + 9.67
};

}  // namespace gearloss::mesh
