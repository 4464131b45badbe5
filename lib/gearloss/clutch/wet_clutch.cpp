#include "gearloss/clutch/wet_clutch.hpp"

#include "gearloss/clutch/film_heating.hpp"
#include "gearloss/thermal/air.hpp"

#include <boost/math/quadrature/gauss.hpp>
#include <boost/math/tools/toms748_solve.hpp>
#include <cmath>
#include <numbers>

namespace gearloss::clutch {

double shear_stress_factor(double H) {
    if (!(H > 0) || H >= 7.0) return 0.0;
    return 11.1 * std::pow(H, 2.31) * std::exp(-2.38 * H + 0.11 * H * H);
}

double nahme_number(double beta, double eta0, double U, double k) {
    if (!(beta > 0) || !(k > 0)) return 0.0;  // no thermoviscosity (or no data): isothermal film
    return beta * eta0 * U * U / k;
}

double thermal_shear_factor(double nahme) {
    if (!(nahme > 0)) return 1.0;
    // Plane Couette flow, both walls at T0, eta = eta0 exp(-beta theta), constant shear stress tau:
    // k theta'' = -tau^2 / eta0 exp(beta theta). With phi = beta theta the solution symmetric about
    // mid-gap is exp(phi) = cosh^2(x) / cosh^2(x (2z/h - 1)) and gives U = (tau h / eta0)
    // sinh(2x) / (2x) with sinh^2(x) = Na / 8 (Nahme 1940; Gavis & Laurence 1968): hence
    // tau = (eta0 U / h) 2x / sinh(2x). Series 1 - (2x)^2/6 + 7 (2x)^4/360 where 2x is small.
    const double x = std::asinh(std::sqrt(nahme / 8.0));
    const double y = 2.0 * x;
    if (y < 1e-3) return 1.0 - y * y / 6.0 + 7.0 * y * y * y * y / 360.0;
    return y / std::sinh(y);
}

std::string_view to_string(FilmRegime r) {
    switch (r) {
        case FilmRegime::full_film: return "full_film";
        case FilmRegime::breaking_up: return "film_breaking_up";
        case FilmRegime::broken: return "film_broken";
    }
    return "?";
}

FilmRegime film_regime(const WetClutchPack& c, double wetted_radius) {
    // wetted_outer_radius() returns r_outer itself when the supply fills the gap and a root
    // bracketed within 1e-7 m otherwise: a relative margin of 1e-9 separates the two.
    if (wetted_radius >= c.r_outer * (1.0 - 1e-9)) return FilmRegime::full_film;
    if (wetted_radius <= c.r_inner * (1.0 + 1e-9)) return FilmRegime::broken;
    return FilmRegime::breaking_up;
}

namespace {
// Centrifugal outflow capacity of a film wetted from r_i to r [m^3/s].
double outflow(const WetClutchPack& c, double eta, double rho, double w, double r) {
    const double h3 = c.clearance * c.clearance * c.clearance;
    const double ln = std::log(r / c.r_inner);
    if (!(ln > 0)) return 0.0;
    return std::numbers::pi * h3 * rho * w * w * (r * r - c.r_inner * c.r_inner) / (40.0 * eta * ln);
}

double roughness_factor(const WetClutchPack& c) {
    const double H = c.roughness > 0 ? c.clearance / c.roughness : 1e9;
    return 1.0 + shear_stress_factor(H);
}
}  // namespace

double wetted_outer_radius(const WetClutchPack& c, double eta, double rho, double slip_speed) {
    const double w = std::abs(slip_speed);
    if (c.oil_supply <= 0.0 || w == 0.0) return c.r_outer;
    if (outflow(c, eta, rho, w, c.r_outer) <= c.oil_supply) return c.r_outer;
    // The capacity rises monotonically with r (from ~pi h^3 rho w^2 r_i^2 / (20 eta) at r_i).
    auto f = [&](double r) { return outflow(c, eta, rho, w, r) - c.oil_supply; };
    const double lo = c.r_inner * (1 + 1e-9);
    if (f(lo) >= 0.0) return c.r_inner;
    // Oil properties that are not finite (a solver's trial state) give no bracket: the drag
    // is then not finite and the caller reports it instead of the root finder throwing.
    if (!(f(lo) < 0.0 && f(c.r_outer) > 0.0)) return c.r_outer;
    std::uintmax_t it = 60;
    const auto [a, b] = boost::math::tools::toms748_solve(
        f, lo, c.r_outer, [](double x, double y) { return std::abs(y - x) < 1e-7; }, it);
    return 0.5 * (a + b);
}

ClutchDrag open_pack_drag(const WetClutchPack& c, double eta, double rho, double slip_speed) {
    ClutchDrag d;
    const double w = std::abs(slip_speed);
    d.wetted_radius = wetted_outer_radius(c, eta, rho, w);
    if (w == 0.0) return d;
    const double rw2 = d.wetted_radius * d.wetted_radius, ri2 = c.r_inner * c.r_inner;
    const double r4 = rw2 * rw2 - ri2 * ri2;
    d.torque = c.interfaces * std::numbers::pi * eta * w * r4 / (2.0 * c.clearance) * roughness_factor(c);
    d.power = d.torque * w;
    return d;
}

ClutchDrag open_pack_drag(const WetClutchPack& c, const lubricant::OilState& oil, double slip_speed) {
    ClutchDrag d;
    const double w = std::abs(slip_speed);
    const double eta = oil.eta;
    auto nahme_at = [&](double r) { return nahme_number(oil.beta_T, eta, w * r, oil.k); };
    // The radial outflow sees the film's apparent viscosity eta tau/tau_iso; at the mean radius.
    const double r_mean = 0.5 * (c.r_inner + c.r_outer);
    const double eta_apparent = eta * thermal_shear_factor(nahme_at(r_mean));
    d.wetted_radius = wetted_outer_radius(c, eta_apparent, oil.rho, w);
    if (w == 0.0) return d;
    // Torque of one interface: integral of 2 pi r^2 tau(r) dr, tau = (eta w r / h) f(Na(r)).
    auto moment = [&](double r) {
        return 2.0 * std::numbers::pi * r * r * eta * w * r / c.clearance * thermal_shear_factor(nahme_at(r));
    };
    const double film = d.wetted_radius > c.r_inner
                            ? boost::math::quadrature::gauss<double, 15>::integrate(moment, c.r_inner, d.wetted_radius)
                            : 0.0;
    // Beyond the wetted radius the gap holds air (with oil mist, Iqbal et al. 2013): its Couette shear
    // pi eta_air w (r_o^4 - r_w^4) / (2 h), air at the oil temperature (Sutherland 1893). A lower bound
    // of the broken film's drag: the mist's own viscosity is not modelled.
    const double rw2 = d.wetted_radius * d.wetted_radius, ro2 = c.r_outer * c.r_outer;
    const double gas = std::numbers::pi * thermal::air_viscosity(oil.T) * w * (ro2 * ro2 - rw2 * rw2) / (2.0 * c.clearance);
    d.torque = c.interfaces * (film * roughness_factor(c) + gas);
    d.power = d.torque * w;
    return d;
}

}  // namespace gearloss::clutch
