#pragma once
// Viscosity–temperature laws. Temperatures in kelvin, kinematic viscosity in
// m^2/s at the interface; each law keeps the unit convention of its source
// internally (°C and mm^2/s for Vogel, K and mm^2/s for ASTM D341).
#include <vector>

namespace gearloss::lubricant {

// Vogel: nu = k * exp(b / (T + c)), T in degC, nu in mm^2/s (Vogel 1921;
// three-point fit as used by Pereira 2017 (seed 001) eq. 2.10).
struct VogelLaw {
    double k_mm2s = 0, b_C = 0, c_C = 0;
    static VogelLaw fit(const double T_C[3], const double nu_mm2s[3]);
    double nu_mm2s(double T_C) const;
    // d ln(nu) / dT [1/K]
    double dlnnu_dT(double T_C) const;
};

// ASTM D341 (Walther 1931): log10 log10(nu + 0.7) = A - B log10(T_K), nu in mm^2/s.
struct WaltherLaw {
    double A = 0, B = 0;
    static WaltherLaw fit(double T1_K, double nu1_mm2s, double T2_K, double nu2_mm2s);
    double nu_mm2s(double T_K) const;
    double dlnnu_dT(double T_K) const;
};

}  // namespace gearloss::lubricant
