#include "gearloss/clutch/wet_clutch.hpp"

#include <boost/math/tools/toms748_solve.hpp>
#include <cmath>
#include <numbers>

namespace gearloss::clutch {

double shear_stress_factor(double H) {
    if (!(H > 0) || H >= 7.0) return 0.0;
    return 11.1 * std::pow(H, 2.31) * std::exp(-2.38 * H + 0.11 * H * H);
}

namespace {
// Centrifugal outflow capacity of a film wetted from r_i to r [m^3/s].
double outflow(const WetClutchPack& c, double eta, double rho, double w, double r) {
    const double h3 = c.clearance * c.clearance * c.clearance;
    const double ln = std::log(r / c.r_inner);
    if (!(ln > 0)) return 0.0;
    return std::numbers::pi * h3 * rho * w * w * (r * r - c.r_inner * c.r_inner) / (40.0 * eta * ln);
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
    const double H = c.roughness > 0 ? c.clearance / c.roughness : 1e9;
    const double factor = 1.0 + shear_stress_factor(H);
    const double rw2 = d.wetted_radius * d.wetted_radius, ri2 = c.r_inner * c.r_inner;
    const double r4 = rw2 * rw2 - ri2 * ri2;
    d.torque = c.interfaces * std::numbers::pi * eta * w * r4 / (2.0 * c.clearance) * factor;
    d.power = d.torque * w;
    return d;
}

}  // namespace gearloss::clutch
