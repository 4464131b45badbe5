#include "gearloss/mesh/ehl_contact.hpp"

#include "gearloss/mesh/viscoelastic.hpp"

#include <algorithm>
#include <array>
#include <boost/math/quadrature/gauss.hpp>
#include <boost/math/tools/toms748_solve.hpp>
#include <cmath>
#include <limits>
#include <numbers>
#include <optional>

namespace gearloss::mesh {

namespace {
constexpr double kRoelandsPr = 1.96e8, kLnEtaInf = -9.67;
}

RoelandsLaw::RoelandsLaw(double eta0_, double alpha) : eta0(eta0_), s(std::log(eta0_) - kLnEtaInf) {
    Z = s > 0 ? alpha * kRoelandsPr / s : 0.0;
}

RoelandsLaw RoelandsLaw::with_index(double eta0, double Z) {
    RoelandsLaw law(eta0, 0.0);
    law.Z = law.s > 0 ? Z : 0.0;
    return law;
}

double RoelandsLaw::viscosity(double p) const {
    if (!(s > 0)) return eta0;
    return eta0 * std::exp(s * (std::pow(1.0 + p / kRoelandsPr, Z) - 1.0));
}

namespace {

// 5-point Gauss-Legendre on [-1, 1] (Boost.Math's rule: the nodes 0 <= x0 < x1 < x2 and their
// weights). The Hertz pressure is even in x, so the five nodes give three distinct pressures:
// the centre and two symmetric pairs (weights doubled).
using Gauss5 = boost::math::quadrature::gauss<double, 5>;
const std::array<double, 3> kX = {Gauss5::abscissa()[0], Gauss5::abscissa()[1], Gauss5::abscissa()[2]};
const std::array<double, 3> kW = {Gauss5::weights()[0], 2 * Gauss5::weights()[1], 2 * Gauss5::weights()[2]};

struct Traction {
    double tau_mean = 0, p_mean = 0;
};

// What the traction at the Gauss nodes needs that does not depend on the film temperature:
// the pressures, ln(1 + p/p_r) of the Roelands law, the limiting shear stress, and the
// Eyring argument above which the limiting shear caps the stress (tau_E sinh(tau_L/tau_E)),
// so that a capped node costs no asinh.
struct HertzNodes {
    std::array<double, 3> p{}, ln_q{}, tau_L{}, ln_cap{};
    double p_mean = 0;
    HertzNodes(double p0, const Rheology& rh) {
        double wsum = 0;
        for (size_t i = 0; i < kX.size(); ++i) {
            p[i] = p0 * std::sqrt(1.0 - kX[i] * kX[i]);
            ln_q[i] = std::log1p(p[i] / kRoelandsPr);
            tau_L[i] = rh.limiting_shear_0 + rh.limiting_shear_slope * p[i];
            // ln(tau_E sinh(r)) without overflow for large r = tau_L / tau_E.
            const double r = tau_L[i] / rh.eyring_stress;
            ln_cap[i] = std::log(rh.eyring_stress) + (r > 20 ? r - std::log(2.0) : std::log(std::sinh(r)));
            p_mean += kW[i] * p[i];
            wsum += kW[i];
        }
        p_mean /= wsum;
    }
};

// The Hertz zone in slices for the Maxwell-Eyring law: x = -a cos(theta), theta uniform
// from the inlet (0) to the outlet (pi), so the slices are finer at the edges where the
// pressure and viscosity change fastest. Per slice the pressure at its middle, ln(1 + p/p_r)
// and tau_L; the viscosity and shear modulus follow the film temperature.
struct MaxwellSlices {
    static constexpr int kSlices = 32;  // the stiff limit within 2 % of the Gauss-rule Eyring form (test_viscoelastic)
    std::array<double, kSlices> p{}, ln_q{}, tau_L{}, dx{};
    double p_centre = 0, ln_q_centre = 0;
    MaxwellSlices(double p0, double a, const Rheology& rh) {
        for (int i = 0; i < kSlices; ++i) {
            const double x0 = -std::cos(std::numbers::pi * i / kSlices), x1 = -std::cos(std::numbers::pi * (i + 1) / kSlices);
            const double xm = 0.5 * (x0 + x1);
            dx[i] = a * (x1 - x0);
            p[i] = p0 * std::sqrt(std::max(0.0, 1.0 - xm * xm));
            ln_q[i] = std::log1p(p[i] / kRoelandsPr);
            tau_L[i] = rh.limiting_shear_0 + rh.limiting_shear_slope * p[i];
        }
        p_centre = p0;
        ln_q_centre = std::log1p(p0 / kRoelandsPr);
    }
};

// Mean shear stress over the Hertz zone for the oil state at the film temperature:
// Roelands viscosity, Eyring stress capped by the limiting shear stress.
Traction traction(const lubricant::OilState& s, const Rheology& rh, const HertzNodes& nodes, double gamma_dot) {
    Traction t;
    t.p_mean = nodes.p_mean;
    if (!(gamma_dot > 0)) return t;
    const RoelandsLaw roelands =
        rh.roelands_Z > 0 ? RoelandsLaw::with_index(s.eta, rh.roelands_Z) : RoelandsLaw(s.eta, s.alpha_p);
    const double ln_eta0 = std::log(s.eta), ln_gd = std::log(gamma_dot);
    double wsum = 0;
    for (size_t i = 0; i < kX.size(); ++i) {
        // ln(eta(p) gamma_dot), eta(p) = eta0 exp{s[(1 + p/p_r)^Z - 1]}
        const double ln_eta = roelands.s > 0 ? ln_eta0 + roelands.s * (std::exp(roelands.Z * nodes.ln_q[i]) - 1.0)
                                             : ln_eta0;
        const double ln_arg = ln_eta + ln_gd;
        const double tau = ln_arg >= nodes.ln_cap[i]
                               ? nodes.tau_L[i]
                               : std::min(nodes.tau_L[i], rh.eyring_stress * std::asinh(std::exp(ln_arg) / rh.eyring_stress));
        t.tau_mean += kW[i] * tau;
        wsum += kW[i];
    }
    t.tau_mean /= wsum;
    return t;
}

// Mean shear stress over the Hertz zone with the Maxwell-Eyring law (viscoelastic.hpp): the
// Roelands viscosity and the shear modulus of each slice at the film temperature. Hertz mean
// pressure pi p0 / 4.
Traction maxwell_traction(const lubricant::OilState& s, const Rheology& rh, const MaxwellSlices& sl, double p0,
                          double gamma_dot, double u_e, double* deborah, double a) {
    Traction t;
    t.p_mean = 0.25 * std::numbers::pi * p0;
    const RoelandsLaw roelands =
        rh.roelands_Z > 0 ? RoelandsLaw::with_index(s.eta, rh.roelands_Z) : RoelandsLaw(s.eta, s.alpha_p);
    auto eta_at = [&](double ln_q) {
        return roelands.s > 0 ? s.eta * std::exp(roelands.s * (std::exp(roelands.Z * ln_q) - 1.0)) : s.eta;
    };
    if (deborah) *deborah = eta_at(sl.ln_q_centre) * u_e / (shear_modulus(rh, sl.p_centre, s.T) * a);
    if (!(gamma_dot > 0)) return t;
    // G = (G0 + G_p p) times its temperature factor, the same for every slice.
    const double G_T = shear_modulus(rh, 0.0, s.T) / rh.shear_modulus_0;
    std::array<MaxwellCell, MaxwellSlices::kSlices> cells;
    for (int i = 0; i < MaxwellSlices::kSlices; ++i)
        cells[i] = {sl.dx[i], eta_at(sl.ln_q[i]), (rh.shear_modulus_0 + rh.shear_modulus_slope * sl.p[i]) * G_T,
                    sl.tau_L[i]};
    t.tau_mean = maxwell_eyring_mean_stress(cells, gamma_dot, u_e, rh.eyring_stress);
    return t;
}

}  // namespace

EhlContactResult ehl_contact(const EhlContactInput& in, const lubricant::Oil& oil, const Rheology& rh, const Solid& solid,
                             bool heating, const lubricant::OilState* bulk) {
    EhlContactResult r;
    const double E_star = 0.5 * in.E_prime;
    r.a = std::sqrt(4.0 * in.w_line * in.R / (std::numbers::pi * E_star));
    r.p0 = hertz_pressure(in.w_line, in.R, in.E_prime);
    const double u_e = 0.5 * (std::abs(in.u1) + std::abs(in.u2));
    const double du = std::abs(in.u1 - in.u2);
    LineContact lc{in.w_line, u_e, in.R, in.E_prime, u_e > 0 ? du / u_e : 0.0};
    const lubricant::OilState s0 = bulk ? *bulk : oil.state(in.T_bulk, in.viscosity_factor);
    const Film film = line_contact_film(lc, s0.eta, s0.alpha_p, s0.beta_T, s0.k, ThermalFilmCorrection::gupta);
    r.h_c = film.h_c;
    r.h_min = film.h_min;
    r.lambda = in.sigma > 0 ? r.h_c / in.sigma : 0.0;
    r.f_c = std::exp(-rh.mixed_B * std::pow(std::max(r.lambda, 0.0), rh.mixed_m));
    if (r.h_c <= 0.0 || u_e <= 0.0) {
        r.T_film = in.T_bulk;
        r.mu = r.f_c * rh.mu_boundary;
        return r;
    }
    const double gamma_dot = du / r.h_c;
    const HertzNodes nodes(r.p0, rh);
    const bool maxwell = in.law == TractionLaw::maxwell_eyring;
    std::optional<MaxwellSlices> slices;
    if (maxwell) slices.emplace(r.p0, r.a, rh);
    auto mean_stress = [&](const lubricant::OilState& sT, double* deborah) {
        return maxwell ? maxwell_traction(sT, rh, *slices, r.p0, gamma_dot, u_e, deborah, r.a)
                       : traction(sT, rh, nodes, gamma_dot);
    };
    // Film temperature F(T) produced by the traction at temperature T.
    const double beta1 = std::sqrt(solid.density * solid.specific_heat * solid.conductivity * std::abs(in.u1));
    const double beta2 = std::sqrt(solid.density * solid.specific_heat * solid.conductivity * std::abs(in.u2));
    auto film_temperature = [&](double T, double* flash, double* shear) {
        const lubricant::OilState sT = oil.state(T, in.viscosity_factor);  // one property evaluation per iteration
        const Traction t = mean_stress(sT, nullptr);
        const double q = t.tau_mean * du;  // heat flux into the contact [W/m^2]
        double dT1 = 0, dT2 = 0;
        const double kap = solid.diffusivity();
        if (beta1 + beta2 > 0) {
            // Blok: equal flash temperatures; Jaeger mean rise of a moving band source.
            const double q1 = q * beta1 / (beta1 + beta2), q2 = q - q1;
            if (std::abs(in.u1) > 0) dT1 = 1.064 * q1 * std::sqrt(kap * r.a / std::abs(in.u1)) / solid.conductivity;
            if (std::abs(in.u2) > 0) dT2 = 1.064 * q2 * std::sqrt(kap * r.a / std::abs(in.u2)) / solid.conductivity;
        }
        const double dTs = q * r.h_c / (12.0 * sT.k);  // Couette, mean through the film
        if (flash) *flash = 0.5 * (dT1 + dT2);
        if (shear) *shear = dTs;
        return in.T_bulk + 0.5 * (dT1 + dT2) + dTs;
    };
    double T = in.T_bulk;
    if (heating) {
        // g(T) = T - F(T) rises monotonically (hotter oil, less traction). F is usually a
        // contraction: a damped fixed-point iteration converges in a few steps; the
        // bracketing solver takes over when it does not.
        auto g = [&](double x) { return x - film_temperature(x, nullptr, nullptr); };
        bool converged = false;
        double x = in.T_bulk + std::max(in.film_rise_guess, 0.0);
        for (int it = 0; it < 8 && !converged; ++it) {
            const double fx = film_temperature(x, nullptr, nullptr);
            const double next = x + 0.8 * (fx - x);
            converged = std::abs(next - x) < 0.1;  // |dT| < 0.1 K (numerical tolerance of this loop, not from a source)
            x = next;
        }
        double lo = in.T_bulk, hi = in.T_bulk + 300.0;
        const double glo = converged ? 0.0 : g(lo), ghi = converged ? 0.0 : g(hi);
        if (converged) T = x;
        else if (glo >= 0) T = lo;
        else if (ghi <= 0) T = hi;
        else if (glo < 0 && ghi > 0) {
            std::uintmax_t it = 60;
            const auto [a, b] = boost::math::tools::toms748_solve(
                g, lo, hi, glo, ghi, [](double x, double y) { return std::abs(y - x) < 0.05; }, it);
            T = 0.5 * (a + b);
        } else {
            // g is not a number at the ends (inputs out of range): no film temperature, and the
            // result says so (NaN) instead of the root finder throwing.
            T = std::numeric_limits<double>::quiet_NaN();
        }
        r.residual = std::abs(g(T));
    }
    r.T_film = heating ? film_temperature(T, &r.dT_flash, &r.dT_shear) : in.T_bulk;
    const Traction t = mean_stress(heating ? oil.state(T, in.viscosity_factor) : s0, &r.deborah);
    r.mu_ehl = t.p_mean > 0 ? t.tau_mean / t.p_mean : 0.0;
    r.mu = r.f_c * rh.mu_boundary + (1.0 - r.f_c) * r.mu_ehl;
    return r;
}

}  // namespace gearloss::mesh
