#include "geometry/gear_geometry.hpp"

#include <algorithm>
#include <boost/math/tools/roots.hpp>
#include <cmath>
#include <fmt/format.h>
#include <numbers>

namespace gearloss::geometry {

double GearSpec::mt() const { return mn / std::cos(beta); }
double GearSpec::alpha_t() const { return std::atan(std::tan(alpha_n) / std::cos(beta)); }
double GearSpec::d() const { return z * mt(); }
double GearSpec::db() const { return d() * std::cos(alpha_t()); }

double involute(double a) { return std::tan(a) - a; }

double inverse_involute(double inv) {
    // inv is monotone on (0, pi/2); bisection-safe Newton from Boost.Math.
    if (!(inv >= 0.0)) throw GeometryError("negative involute function value (profile shift sum too negative)");
    const double guess = std::cbrt(3.0 * inv);  // inv(a) ~ a^3/3 for small a
    const auto f = [inv](double a) {
        const double t = std::tan(a);
        return std::make_pair(t - a - inv, t * t);
    };
    boost::uintmax_t it = 60;
    return boost::math::tools::newton_raphson_iterate(f, std::min(guess, 1.4), 0.0, 1.5, 52, it);
}

PairGeometry pair_geometry(const GearSpec& g1, const GearSpec& g2, std::optional<double> a_w_given) {
    using std::cos, std::sin, std::tan, std::sqrt;
    if (std::abs(g1.mn - g2.mn) > 1e-9 * g1.mn)
        throw GeometryError(fmt::format("normal modules differ ({} mm vs {} mm)", g1.mn * 1e3, g2.mn * 1e3));
    if (std::abs(g1.alpha_n - g2.alpha_n) > 1e-9)
        throw GeometryError("normal pressure angles differ");
    if (std::abs(g1.beta - g2.beta) > 1e-9)
        throw GeometryError("helix angles differ");
    if (g1.beta > 0 && g1.hand == g2.hand)
        throw GeometryError("external helical gears in mesh need opposite hands (one left, one right)");

    PairGeometry p;
    const double mn = g1.mn, an = g1.alpha_n, beta = g1.beta;
    const double z1 = g1.z, z2 = g2.z;
    p.u = z2 / z1;
    p.alpha_t = g1.alpha_t();
    p.beta_b = std::asin(sin(beta) * cos(an));
    p.d[0] = g1.d();
    p.d[1] = g2.d();
    p.db[0] = g1.db();
    p.db[1] = g2.db();
    p.a = 0.5 * (p.d[0] + p.d[1]);
    if (a_w_given) {
        p.a_w = *a_w_given;
        const double c = p.a * cos(p.alpha_t) / p.a_w;
        if (!(c > 0 && c < 1)) throw GeometryError("centre distance incompatible with the gear sizes");
        p.alpha_wt = std::acos(c);
    } else {
        const double inv_wt = involute(p.alpha_t) + 2.0 * tan(an) * (g1.x + g2.x) / (z1 + z2);
        p.alpha_wt = inverse_involute(inv_wt);
        p.a_w = p.a * cos(p.alpha_t) / cos(p.alpha_wt);
    }
    p.dw[0] = 2.0 * p.a_w / (1.0 + p.u);
    p.dw[1] = p.u * p.dw[0];
    p.y = (p.a_w - p.a) / mn;
    // ISO 21771: k = y - (x1 + x2) <= 0; keeps the nominal tip clearance.
    p.k = std::min(0.0, p.y - (g1.x + g2.x));
    const GearSpec* g[2] = {&g1, &g2};
    for (int i = 0; i < 2; ++i) {
        p.da[i] = p.d[i] + 2.0 * mn * (g[i]->ha_star + g[i]->x + p.k);
        p.df[i] = p.d[i] - 2.0 * mn * (g[i]->hf_star - g[i]->x);
        if (!(p.df[i] > 0)) throw GeometryError(fmt::format("gear '{}' has a negative root diameter", g[i]->name));
        if (p.da[i] <= p.db[i])
            throw GeometryError(fmt::format("gear '{}': tip circle inside the base circle", g[i]->name));
        // Transverse tooth thickness at the tip (involute tooth thickness relation).
        const double mt = g[i]->mt();
        const double s_t = mt * (std::numbers::pi / 2.0 + 2.0 * g[i]->x * tan(p.alpha_t));
        const double a_at = std::acos(p.db[i] / p.da[i]);
        p.tip_thickness[i] = p.da[i] * (s_t / p.d[i] + involute(p.alpha_t) - involute(a_at));
        if (!(p.tip_thickness[i] > 0))
            throw GeometryError(fmt::format(
                "gear '{}': profile shift x = {} makes a pointed tooth (tip thickness {:.3f} mm)", g[i]->name,
                g[i]->x, p.tip_thickness[i] * 1e3));
    }
    p.tip_clearance[0] = p.a_w - 0.5 * p.da[0] - 0.5 * p.df[1];
    p.tip_clearance[1] = p.a_w - 0.5 * p.da[1] - 0.5 * p.df[0];
    for (int i = 0; i < 2; ++i)
        if (p.tip_clearance[i] < 0)
            throw GeometryError(fmt::format("tip of gear '{}' interferes with the root of its mate (clearance {:.3f} mm)",
                                            g[i]->name, p.tip_clearance[i] * 1e3));

    p.p_bt = std::numbers::pi * g1.mt() * cos(p.alpha_t);
    const double rb1 = 0.5 * p.db[0], rb2 = 0.5 * p.db[1];
    const double ra1 = 0.5 * p.da[0], ra2 = 0.5 * p.da[1];
    p.T1T2 = p.a_w * sin(p.alpha_wt);
    p.T1C = rb1 * tan(p.alpha_wt);
    p.T1E = sqrt(ra1 * ra1 - rb1 * rb1);
    p.T1A = p.T1T2 - sqrt(ra2 * ra2 - rb2 * rb2);
    if (p.T1A < 0)
        throw GeometryError(fmt::format("tip of gear '{}' reaches below the base circle of '{}' (involute interference)",
                                        g2.name, g1.name));
    if (p.T1E > p.T1T2)
        throw GeometryError(fmt::format("tip of gear '{}' reaches below the base circle of '{}' (involute interference)",
                                        g1.name, g2.name));
    const double ga1 = p.T1E - p.T1C;  // recess (pinion addendum) segment
    const double ga2 = p.T1C - p.T1A;  // approach segment
    p.eps1 = ga1 / p.p_bt;
    p.eps2 = ga2 / p.p_bt;
    p.eps_alpha = p.eps1 + p.eps2;
    if (p.eps_alpha < 1.0)
        throw GeometryError(fmt::format("transverse contact ratio {:.3f} < 1: the pair does not mesh continuously",
                                        p.eps_alpha));
    p.T1B = p.T1E - p.p_bt;
    p.T1D = p.T1A + p.p_bt;
    p.b_eff = std::min(g1.b, g2.b);
    p.eps_beta = p.b_eff * sin(beta) / (std::numbers::pi * mn);
    p.eps_gamma = p.eps_alpha + p.eps_beta;
    p.rho_redC = p.a_w * sin(p.alpha_wt) * p.u / ((1.0 + p.u) * (1.0 + p.u) * cos(p.beta_b));
    return p;
}

}  // namespace gearloss::geometry
