#include "gearloss/clutch/wet_clutch.hpp"

#include "gearloss/clutch/film_heating.hpp"
#include "gearloss/thermal/air.hpp"

#include <boost/math/quadrature/gauss.hpp>
#include <boost/math/tools/toms748_solve.hpp>
#include <algorithm>
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

namespace {
double roughness_factor(const WetClutchPack& c) {
    const double H = c.roughness > 0 ? c.clearance / c.roughness : 1e9;
    return 1.0 + shear_stress_factor(H);
}

// Where the oil is, what fraction of the region beyond it, and the drag of both parts, given the
// moment of the oil's shear over a band, oil_moment(a, b) = integral of 2 pi r^2 tau_oil(r) dr,
// and the air's viscosity (0: air neglected).
//
// The two-phase region (the model's own assumption; no published form of it was found to cite).
// When the supply Q_s cannot fill the gap, the full film ends at r_w (Yuan et al. 2007), where
// its pressure is back at ambient. Beyond it the oil does not vanish: it spreads over the plate
// as streaks (ligaments bridging the gap), air between them connected to the rim (the picture
// reported from flow visualisations of open packs); Iqbal et al. (2013) likewise split the gap
// into an oil film and an oil-air mist that still shears. Let the streaks cover a fraction f of every circle
// between r_w and r_o (f the same at every radius). Each streak spans the gap and has ambient
// pressure at both ends (r_w and the rim), so it carries the same radial flow per unit
// circumference as a full film would: the region passes f Q_cap(r_w, r_o). All the supply
// passes through it (mass conservation), hence
//     f = Q_s / Q_cap(r_w, r_o),   at most 1,
// Q_cap(a, b) = pi h^3 rho w^2 (b^2 - a^2) / (40 eta ln(b/a)) (outflow_capacity). f <= 1 holds
// by itself: Q_s = Q_cap(r_i, r_w) <= Q_cap(r_w, r_o) because (b^2 - a^2)/ln(b/a) (twice the
// logarithmic mean of a^2 and b^2) rises with both radii. The streaks shear oil, the rest air:
//     tau = f tau_oil + (1 - f) tau_air   over r_w..r_o.
// Continuity: at the onset r_w = r_o and the region has no width; once r_w has shrunk to r_i
// the whole plate is two-phase with f = Q_s / Q_cap(r_i, r_o), which meets the narrow-film limit.
// Beyond it f ~ 1/w^2 (Q_cap ~ w^2), so the oil's torque f T_full ~ (1/w^2) w = 1/w: the drag
// falls as the inverse of the slip speed once the film has broken up (the oil's power is flat),
// as measured curves fall gradually from their peak (Pointner-Gabriel, Voelkel & Stahl 2025).
template <class OilMoment>
ClutchDrag two_phase_drag(const WetClutchPack& c, double eta_flow, double rho, double w, OilMoment&& oil_moment,
                          double eta_air) {
    ClutchDrag d;
    d.wetted_radius = wetted_outer_radius(c, eta_flow, rho, w);
    d.oil_fraction = streak_oil_fraction(c, eta_flow, rho, w, d.wetted_radius);
    if (w == 0.0) return d;
    const double rw = d.wetted_radius, f = d.oil_fraction;
    const double film = rw > c.r_inner ? oil_moment(c.r_inner, rw) : 0.0;
    const double streaks = rw < c.r_outer ? f * oil_moment(rw, c.r_outer) : 0.0;
    // Air between the streaks: Couette shear pi eta_air w (r_o^4 - r_w^4) / (2 h) times its share.
    const double rw2 = rw * rw, ro2 = c.r_outer * c.r_outer;
    const double air = (1.0 - f) * std::numbers::pi * eta_air * w * (ro2 * ro2 - rw2 * rw2) / (2.0 * c.clearance);
    d.oil_torque = c.interfaces * (film + streaks) * roughness_factor(c);
    d.air_torque = c.interfaces * air;
    d.torque = d.oil_torque + d.air_torque;
    d.power = d.torque * w;
    // Regimes (wet_clutch.hpp): full film out to the rim; broken once the oil left in the gap drags
    // less than the air there; breaking up in between.
    d.regime = f >= 1.0 && rw >= c.r_outer ? FilmRegime::full_film
               : d.oil_torque < d.air_torque ? FilmRegime::broken
                                             : FilmRegime::breaking_up;
    return d;
}
}  // namespace

double outflow_capacity(const WetClutchPack& c, double eta, double rho, double slip_speed, double a, double b) {
    const double h3 = c.clearance * c.clearance * c.clearance;
    const double k = std::numbers::pi * h3 * rho * slip_speed * slip_speed / (40.0 * eta);
    // (b^2 - a^2)/ln(b/a) = 2 a^2 (1 + x + x^2/6 + ...) with x = (b - a)/a: its series below 1e-6.
    const double x = (b - a) / a;
    if (!(x > 1e-6)) return k * 2.0 * a * a * (1.0 + x + x * x / 6.0);
    return k * (b * b - a * a) / std::log(b / a);
}

double wetted_outer_radius(const WetClutchPack& c, double eta, double rho, double slip_speed) {
    const double w = std::abs(slip_speed);
    if (c.oil_supply <= 0.0 || w == 0.0) return c.r_outer;
    if (outflow_capacity(c, eta, rho, w, c.r_inner, c.r_outer) <= c.oil_supply) return c.r_outer;
    // The capacity rises monotonically with r (from pi h^3 rho w^2 r_i^2 / (20 eta) at r_i).
    auto f = [&](double r) { return outflow_capacity(c, eta, rho, w, c.r_inner, r) - c.oil_supply; };
    if (f(c.r_inner) >= 0.0) return c.r_inner;
    // Oil properties that are not finite (a solver's trial state) give no bracket: the drag
    // is then not finite and the caller reports it instead of the root finder throwing.
    if (!(f(c.r_inner) < 0.0 && f(c.r_outer) > 0.0)) return c.r_outer;
    std::uintmax_t it = 80;
    const auto [a, b] = boost::math::tools::toms748_solve(
        f, c.r_inner, c.r_outer, [](double x, double y) { return std::abs(y - x) < 1e-10; }, it);
    return 0.5 * (a + b);
}

double streak_oil_fraction(const WetClutchPack& c, double eta, double rho, double slip_speed, double wetted_radius) {
    const double w = std::abs(slip_speed);
    if (c.oil_supply <= 0.0 || w == 0.0 || wetted_radius >= c.r_outer) return 1.0;
    const double capacity = outflow_capacity(c, eta, rho, w, wetted_radius, c.r_outer);
    if (!(capacity > 0.0)) return 1.0;  // not finite oil (a solver's trial state): reported by the caller
    return std::min(1.0, c.oil_supply / capacity);
}

ClutchDrag open_pack_drag(const WetClutchPack& c, double eta, double rho, double slip_speed) {
    const double w = std::abs(slip_speed);
    // Smooth-film Couette moment over a..b: pi eta w (b^4 - a^4) / (2 h).
    auto moment = [&](double a, double b) {
        const double a2 = a * a, b2 = b * b;
        return std::numbers::pi * eta * w * (b2 * b2 - a2 * a2) / (2.0 * c.clearance);
    };
    return two_phase_drag(c, eta, rho, w, moment, 0.0);
}

ClutchDrag open_pack_drag(const WetClutchPack& c, const lubricant::OilState& oil, double slip_speed) {
    const double w = std::abs(slip_speed);
    const double eta = oil.eta;
    auto nahme_at = [&](double r) { return nahme_number(oil.beta_T, eta, w * r, oil.k); };
    // The radial outflow sees the film's apparent viscosity eta tau/tau_iso; at the mean radius.
    const double r_mean = 0.5 * (c.r_inner + c.r_outer);
    const double eta_apparent = eta * thermal_shear_factor(nahme_at(r_mean));
    // Moment of the heated film over a..b: integral of 2 pi r^2 tau(r) dr, tau = (eta w r / h) f(Na(r)).
    auto moment = [&](double a, double b) {
        auto dm = [&](double r) {
            return 2.0 * std::numbers::pi * r * r * eta * w * r / c.clearance * thermal_shear_factor(nahme_at(r));
        };
        return boost::math::quadrature::gauss<double, 15>::integrate(dm, a, b);
    };
    // Air between the streaks and beyond the film at the oil temperature (Sutherland 1893); the
    // mist's own viscosity is not modelled, so this part is a lower bound.
    return two_phase_drag(c, eta_apparent, oil.rho, w, moment, thermal::air_viscosity(oil.T));
}

}  // namespace gearloss::clutch
