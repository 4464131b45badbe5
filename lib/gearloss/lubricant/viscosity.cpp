#include "gearloss/core/errors.hpp"
#include "gearloss/lubricant/viscosity.hpp"

#include <cmath>
#include <stdexcept>

namespace gearloss::lubricant {

VogelLaw VogelLaw::fit(const double T[3], const double nu[3]) {
    // Vogel (1921) law through three points: closed-form solution (derived, not from a source).
    const double l1 = std::log(nu[0]), l2 = std::log(nu[1]), l3 = std::log(nu[2]);
    if (!(l2 != l3)) throw InputError("Vogel fit needs distinct viscosities");
    const double R = (l1 - l2) / (l2 - l3);
    const double den = R * (T[2] - T[1]) - (T[1] - T[0]);
    if (den == 0.0) throw InputError("Vogel fit is singular for these points");
    VogelLaw v;
    v.c_C = ((T[1] - T[0]) * T[2] - R * (T[2] - T[1]) * T[0]) / den;
    v.b_C = (l1 - l2) / (1.0 / (T[0] + v.c_C) - 1.0 / (T[1] + v.c_C));
    v.k_mm2s = nu[0] * std::exp(-v.b_C / (T[0] + v.c_C));
    if (!(v.b_C > 0) || !std::isfinite(v.k_mm2s) || !(v.k_mm2s > 0))
        throw InputError("Vogel fit gives a non-physical law (viscosity must fall with temperature)");
    return v;
}

double VogelLaw::nu_mm2s(double T_C) const { return k_mm2s * std::exp(b_C / (T_C + c_C)); }

double VogelLaw::dlnnu_dT(double T_C) const {
    const double s = T_C + c_C;
    return -b_C / (s * s);
}

namespace {
double walther_W(double nu) { return std::log10(std::log10(nu + 0.7)); }
}  // namespace

WaltherLaw WaltherLaw::fit(double T1, double nu1, double T2, double nu2) {
    WaltherLaw w;
    const double dl = std::log10(T2) - std::log10(T1);
    if (dl == 0.0) throw InputError("ASTM D341 fit needs two distinct temperatures");
    w.B = (walther_W(nu1) - walther_W(nu2)) / dl;
    w.A = walther_W(nu1) + w.B * std::log10(T1);
    if (!(w.B > 0)) throw InputError("ASTM D341 fit gives viscosity rising with temperature");
    return w;
}

double WaltherLaw::nu_mm2s(double T_K) const {
    return std::pow(10.0, std::pow(10.0, A - B * std::log10(T_K))) - 0.7;
}

double WaltherLaw::dlnnu_dT(double T_K) const {
    // d/dT of ln(nu) with Z = nu + 0.7 = 10^(10^w), w = A - B log10 T:
    // dZ/dT = Z ln10 * 10^w ln10 * (-B/(T ln10)) = -Z ln10 10^w B / T
    const double w = A - B * std::log10(T_K);
    const double p = std::pow(10.0, w);
    const double Z = std::pow(10.0, p);
    const double dZ = -Z * std::log(10.0) * p * B / T_K;
    return dZ / (Z - 0.7);
}

}  // namespace gearloss::lubricant
