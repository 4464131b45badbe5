#include "gearloss/lubricant/oil.hpp"

#include <algorithm>
#include <cmath>

namespace gearloss::lubricant {

const char* to_string(BaseOil b) {
    switch (b) {
        case BaseOil::mineral: return "mineral";
        case BaseOil::pao: return "PAO";
        case BaseOil::ester: return "ester";
        case BaseOil::pag: return "PAG";
        case BaseOil::pag_water_soluble: return "PAG_water_soluble";
        case BaseOil::phosphate_ester: return "phosphate_ester";
        case BaseOil::traction_fluid: return "traction_fluid";
        case BaseOil::transmission_fluid: return "transmission_fluid";
    }
    return "?";
}

double default_max_temperature(BaseOil b) {
    switch (b) {
        case BaseOil::mineral: return 273.15 + 95.0;
        case BaseOil::pao:
        case BaseOil::ester:
        case BaseOil::pag:
        case BaseOil::pag_water_soluble: return 273.15 + 110.0;
        case BaseOil::transmission_fluid: return 273.15 + 120.0;
        case BaseOil::phosphate_ester:
        case BaseOil::traction_fluid: return 273.15 + 100.0;
    }
    return 273.15 + 95.0;
}

std::optional<double> default_XL(BaseOil b) {
    // ISO/TS 6336-20 (2017) lubricant factor X_L table.
    switch (b) {
        case BaseOil::mineral: return 1.0;
        case BaseOil::transmission_fluid: return 1.0;
        case BaseOil::pao: return 0.8;
        case BaseOil::pag: return 0.7;
        case BaseOil::pag_water_soluble: return 0.6;
        case BaseOil::phosphate_ester: return 1.3;
        case BaseOil::traction_fluid: return 1.5;
        case BaseOil::ester: return std::nullopt;
    }
    return std::nullopt;
}

TractionProperties default_traction(BaseOil b) {
    TractionProperties t;  // mineral gear oil: tau_E 5 MPa, tau_L = 1 MPa + 0.07 p (assumed), mu_bl 0.11 (seed 000, before its Table 3)
    switch (b) {
        case BaseOil::mineral:
        case BaseOil::transmission_fluid: break;
        case BaseOil::pao: t.eyring_stress = 4e6; t.limiting_shear_slope = 0.065; break;
        case BaseOil::ester:
        case BaseOil::phosphate_ester: t.eyring_stress = 3e6; t.limiting_shear_slope = 0.055; break;
        case BaseOil::pag:
        case BaseOil::pag_water_soluble: t.eyring_stress = 3e6; t.limiting_shear_slope = 0.05; break;
        case BaseOil::traction_fluid: t.eyring_stress = 10e6; t.limiting_shear_slope = 0.10; break;
    }
    return t;
}

std::pair<double, double> gold_constants(BaseOil b) {
    // Gold et al. (2001), J. Synth. Lubr. 18; s [1/Pa], t [-].
    switch (b) {
        case BaseOil::pao: return {0.7382e-8, 0.1335};
        case BaseOil::ester:
        case BaseOil::phosphate_ester: return {0.6605e-8, 0.1360};
        case BaseOil::pag:
        case BaseOil::pag_water_soluble: return {0.5489e-8, 0.1485};
        default: return {0.9904e-8, 0.1390};
    }
}

double Oil::nu_mm2s(double T_K) const {
    // Far outside the measured range the laws break down (Vogel has a pole at
    // T = -c, D341 overflows): bounded to [0.5, 1e7] mm^2/s, beyond which the
    // oil is practically solid or no longer a lubricant.
    constexpr double nu_min = 0.5, nu_max = 1e7;
    double nu;
    if (const auto* v = std::get_if<VogelLaw>(&viscosity)) {
        const double s = T_K - 273.15 + v->c_C;
        nu = s <= 0.0 ? nu_max : v->nu_mm2s(T_K - 273.15);
    } else {
        nu = std::get<WaltherLaw>(viscosity).nu_mm2s(T_K);
    }
    if (!(nu < nu_max)) return nu_max;  // also catches inf/NaN from overflow
    return std::max(nu, nu_min);
}

double Oil::density(double T_K) const { return rho15 * (1.0 - expansion * (T_K - 288.15)); }

double Oil::pressure_viscosity(double T_K, double nu_cSt) const {
    if (piezo_table.empty()) {
        auto [s, t] = gold_constants(base);
        return s * std::pow(nu_cSt, t);
    }
    if (piezo_table.size() == 1) return piezo_table.front().alpha;
    // Measured values are interpolated linearly in ln(alpha) and extrapolated
    // with the end slopes: alpha falls roughly exponentially with temperature.
    auto it = std::upper_bound(piezo_table.begin(), piezo_table.end(), T_K,
                               [](double t, const PiezoPoint& p) { return t < p.T_K; });
    size_t i = it == piezo_table.begin() ? 0 : static_cast<size_t>(it - piezo_table.begin()) - 1;
    i = std::min(i, piezo_table.size() - 2);
    const auto& a = piezo_table[i];
    const auto& b = piezo_table[i + 1];
    const double f = (T_K - a.T_K) / (b.T_K - a.T_K);
    return std::exp(std::log(a.alpha) + f * (std::log(b.alpha) - std::log(a.alpha)));
}

OilState Oil::state(double T_K, double viscosity_factor) const {
    OilState s;
    s.T = T_K;
    s.nu_cSt = nu_mm2s(T_K) * viscosity_factor;
    s.nu = s.nu_cSt * 1e-6;
    s.rho = density(T_K);
    s.eta = s.nu * s.rho;
    s.alpha_p = pressure_viscosity(T_K, s.nu_cSt);
    double dlnnu = 0;
    if (const auto* v = std::get_if<VogelLaw>(&viscosity)) dlnnu = v->dlnnu_dT(T_K - 273.15);
    else dlnnu = std::get<WaltherLaw>(viscosity).dlnnu_dT(T_K);
    // eta = nu * rho: both fall with temperature.
    s.beta_T = -dlnnu + expansion / (1.0 - expansion * (T_K - 288.15));
    const double T_C = T_K - 273.15;
    const double SG15 = rho15 / 999.1;
    if (k_fixed) {
        s.k = *k_fixed;
    } else if (base == BaseOil::mineral || base == BaseOil::transmission_fluid) {
        s.k = (0.1172 / SG15) * (1.0 - 0.00054 * T_C);  // Cragoe (petroleum oils)
    } else {
        // Synthetic base stocks conduct ~15 % better than mineral oils
        // (PAO 0.15-0.16, esters/PAG 0.15-0.17 W/(m K); typical data-sheet values, no single source).
        s.k = 0.158 * (1.0 - 0.00054 * T_C);
    }
    s.cp = cp_fixed ? *cp_fixed : 1000.0 * (1.684 + 0.00339 * T_C) / std::sqrt(SG15);  // Cragoe
    return s;
}

}  // namespace gearloss::lubricant
