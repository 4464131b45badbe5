#pragma once
// A lubricant described by datasheet values, and its state at a temperature.
#include <optional>
#include <string>
#include <utility>
#include <variant>
#include <vector>

#include "gearloss/lubricant/viscosity.hpp"

namespace gearloss::lubricant {

enum class BaseOil { mineral, pao, ester, pag, pag_water_soluble, phosphate_ester, traction_fluid, transmission_fluid };
const char* to_string(BaseOil b);

// Sliding friction pair of the SKF 2004 model for one rolling-element family.
struct BearingFrictionPair {
    double mu_bl = 0.15;  // boundary; SKF 2004 text
    std::optional<double> mu_ehl;  // full film; default by bearing type (see bearings/)
};

// Traction (rheology) properties for the local thermal-EHL friction model.
// Defaults come per base oil from default_traction(); measure per oil.
struct TractionProperties {
    double eyring_stress = 5e6;          // tau_E [Pa]
    double limiting_shear_0 = 1e6;       // tau_L0 [Pa]
    double limiting_shear_slope = 0.07;  // Lambda_L: tau_L = tau_L0 + Lambda_L p
    double mu_boundary = 0.11;           // boundary friction of the mesh
    double mixed_B = 1.0, mixed_m = 2.0; // asperity share f_c = exp(-B Lambda^m)
    // Roelands pressure index Z of the in-contact viscosity; 0: derived from the
    // pressure-viscosity coefficient, Z = alpha p_r / (ln eta0 + 9.67).
    double roelands_Z = 0;
    // Shear modulus of the viscoelastic (Maxwell-Eyring) traction, read only by that form:
    // G = (G0 + G_p p) exp(-beta_G (T - T_ref)). Seed 000 (text at its Figure 1) uses a Deborah number
    // with G but gives neither a value nor a law for it; these defaults are assumed (docs/config.md).
    double shear_modulus_0 = 1e9;            // G0 [Pa]
    double shear_modulus_slope = 0;          // G_p = dG/dp [-]
    double shear_modulus_beta = 0;           // beta_G [1/K]
    double shear_modulus_T_ref = 313.15;     // T_ref [K]
};

// Typical traction properties by base oil (assumed order-of-magnitude values, documented in
// docs/config.md): traction fluids shear hardest, esters and PAGs least.
TractionProperties default_traction(BaseOil b);

// Properties at one temperature, SI units, with the powers of the kinematic
// viscosity that several loss models share precomputed once.
struct OilState {
    double T = 0;          // K
    double nu = 0;         // m^2/s
    double nu_cSt = 0;     // mm^2/s (the unit of most empirical loss formulas)
    double rho = 0;        // kg/m^3
    double eta = 0;        // Pa*s
    double alpha_p = 0;    // pressure-viscosity coefficient, 1/Pa
    double beta_T = 0;     // thermoviscosity -d ln(eta)/dT, 1/K
    double k = 0;          // thermal conductivity, W/(m K)
    double cp = 0;         // J/(kg K)
};

class Oil {
public:
    struct PiezoPoint { double T_K; double alpha; };
    std::string name = "oil";
    BaseOil base = BaseOil::mineral;
    std::variant<VogelLaw, WaltherLaw> viscosity;
    double rho15 = 870.0;          // kg/m^3 at 15 degC
    double expansion = 6.5e-4;     // 1/K, rho(T) = rho15 (1 - expansion (T - 15 degC))
    std::vector<PiezoPoint> piezo_table;  // empty -> Gold et al. (2001) from base oil
    std::optional<double> k_fixed;   // W/(m K); else from base oil
    std::optional<double> cp_fixed;  // J/(kg K); else Cragoe
    double X_L = 1.0;               // lubricant factor of the mean gear friction
    double max_temperature = 368.15;  // K, permissible bulk (sump) temperature; from the datasheet or per base oil
    BearingFrictionPair bearing_ball, bearing_roller;
    // Boundary and full-film friction of the mixed-film mesh model (Fernandes et al. 2015),
    // measured per oil; unset: the mesh mechanism's settings.
    std::optional<double> gear_mu_bl, gear_mu_ehl;
    TractionProperties traction;

    // The state at T_K; viscosity_factor scales the kinematic viscosity of the data (a
    // calibration: the oil in the gearbox is thicker or thinner than its datasheet), and with
    // it the dynamic viscosity and the pressure-viscosity coefficient taken from it; its
    // temperature slope beta_T is unchanged (a factor does not move d ln nu / dT).
    OilState state(double T_K, double viscosity_factor = 1.0) const;
    double nu_mm2s(double T_K) const;
    double density(double T_K) const;
    double pressure_viscosity(double T_K, double nu_mm2s) const;
};

// Permissible sump temperature [K] when the oil file gives none: mineral oils 95 degC
// (the sump temperature at which ISO/TR 14179-1 rates thermal capacity), synthetic
// gear oils and ATF 110-120 degC (typical datasheet limits for continuous service, assumed).
double default_max_temperature(BaseOil b);

// X_L default by base oil (ISO/TS 6336-20 table); nullopt where the table has none.
std::optional<double> default_XL(BaseOil b);

// Gold et al. (2001) alpha = s * nu^t (nu in mm^2/s), constants as consolidated
// in Fernandes (2015), PhD thesis, Table 2.7 (its title in seed 002's list of tables; the
// values are not in the seed's shipped text).
std::pair<double, double> gold_constants(BaseOil b);

}  // namespace gearloss::lubricant
