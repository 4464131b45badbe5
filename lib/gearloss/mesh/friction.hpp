#pragma once
// Mean coefficient of friction of the mesh and the pitch-point film
// (Schlenk 1994, ISO/TS 6336-20, Doleschel 2003; films: Grubin 1949, Dowson & Higginson 1966).

namespace gearloss::mesh {

// ehl_local: local thermal EHL with the Eyring / limiting-shear traction; ehl_maxwell: the same
// with the viscoelastic Maxwell-Eyring traction (Johnson & Tevaarwerk 1977), as seed 000.
enum class FrictionModel { schlenk, iso_6336_20, fernandes_mixed, ehl_local, ehl_maxwell };
enum class ThermalFilmCorrection { gupta, simplified, none };

// Schlenk (1994) = ISO/TR 14179-2: mu = 0.048 (w/(v_sum rho))^0.2 eta^-0.05 Ra^0.25 X_L,
// in the source's units: w [N/mm], v_sum [m/s], rho_redC [mm], eta [mPa s], Ra [um].
double mean_friction_schlenk(double w_N_per_mm, double v_sum, double rho_mm, double eta_mPas, double Ra_um,
                             double X_L);
// ISO/TS 6336-20: mu = 0.060 (w/(v_sum rho))^0.2 X_L X_R, X_L = eta^-0.05, X_R = Ra^0.25,
// v_t capped at 50 m/s (passed in v_sum already); load factors = 1 for efficiency work.
double mean_friction_iso_6336_20(double w_N_per_mm, double v_sum, double rho_mm, double eta_mPas, double Ra_um,
                                 double X_L);
// Doleschel (2003) share of boundary friction: xi = (1 - Lambda/Lambda_on)^2 for Lambda < Lambda_on,
// else 0, with Doleschel's onset Lambda_on = 2. Where asperity contact ends depends on the
// surfaces' texture (Johnson, Greenwood & Poon 1972: the asperities carry load up to Lambda
// of about 3 to 4), so the onset is a setting of the surface pair, not a constant.
double boundary_share_doleschel(double lambda, double onset = 2.0);

// Pitch-point line contact.
struct LineContact {
    double w_line = 0;   // normal load per unit contact length [N/m]
    double u_e = 0;      // mean entrainment speed [m/s]
    double R = 0;        // reduced radius [m]
    double E_prime = 0;  // 2 / ((1-v1^2)/E1 + (1-v2^2)/E2) [Pa]
    double SRR = 0;      // slide-to-roll ratio
};

struct Film {
    double h_c = 0;     // central, thermally corrected [m]
    double h_min = 0;   // minimum, thermally corrected [m]
    double phi_T = 1;   // thermal reduction factor
    double p_hertz = 0; // maximum Hertz pressure [Pa]
};

// Hertz maximum pressure of a line contact: p0 = sqrt(w E*/(pi R)), E* = E'/2.
double hertz_pressure(double w_line, double R, double E_prime);

// Thermal reduction factor of Gupta et al. (1992) (full form):
// phi_T = [1 - 13.2 (p_H/E') L^0.42] / [1 + 0.213 (1 + 2.23 SRR^0.83) L^0.64],
// L = beta eta0 u_e^2 / k. Beyond the turning point L* (gupta_turning_point) the correlation
// would thin the film of a thickening oil down to zero; there the load term is held at L*.
// p_ratio = p_H / E'.
double gupta_thermal_factor(double L, double p_ratio, double SRR);
// L* where d ln(phi_T)/d ln L = -8/11: the Ertel-Grubin film phi_T H_c (H_c ~ eta0^(8/11)) is
// largest there at a fixed pressure-viscosity coefficient.
double gupta_turning_point(double p_ratio, double SRR);

// Ertel-Grubin central film H_c = 1.95 (GU)^(8/11) W^(-1/11) and Dowson-Higginson
// minimum H_min = 2.65 U^0.70 G^0.54 W^-0.13, both with E'; thermal reduction by
// Gupta et al. (1992) (full form, L = beta eta u_e^2 / k) or the simplified form of
// seed 001 eq. 4.3 (L with the sum speed).
Film line_contact_film(const LineContact& c, double eta0, double alpha_p, double beta_T, double k_oil,
                       ThermalFilmCorrection corr);

}  // namespace gearloss::mesh
