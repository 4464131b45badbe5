#include "gearloss/geometry/gear_geometry.hpp"

#include <algorithm>
#include <boost/math/tools/roots.hpp>
#include <cmath>
#include <fmt/format.h>
#include <numbers>
#include <stdexcept>

namespace gearloss::geometry {

double GearSpec::mt() const { return mn / std::cos(beta); }
double GearSpec::alpha_t() const { return std::atan(std::tan(alpha_n) / std::cos(beta)); }
double GearSpec::d() const { return z * mt(); }
double GearSpec::db() const { return d() * std::cos(alpha_t()); }

const char* to_string(TipSource s) {
    switch (s) {
        case TipSource::given_tip_alteration: return "given tip alteration factor";
        case TipSource::given_tip_diameter: return "given tip diameter";
        case TipSource::iso_tip_alteration: break;
    }
    return "ISO 21771 tip alteration";
}

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

double iso286_tolerance(double size, int grade) {
    // ISO 286-1:2010, clause 5 and Annex A: IT5..IT11 = 7, 10, 16, 25, 40, 64, 100 times the
    // standard tolerance factor i = 0.45 D^(1/3) + 0.001 D [um, D in mm] (D <= 500 mm), or
    // I = 0.004 D + 2.1 above 500 mm.
    static constexpr double kMultiplier[] = {7, 10, 16, 25, 40, 64, 100};
    if (grade < 5 || grade > 11) throw std::invalid_argument("ISO 286-1 grade outside IT5..IT11");
    const double D = std::abs(size) * 1e3;
    const double i_um = D <= 500.0 ? 0.45 * std::cbrt(D) + 0.001 * D : 0.004 * D + 2.1;
    return kMultiplier[grade - 5] * i_um * 1e-6;
}

// js7 (DIN 3964: centre-distance allowances of gearbox housings): +/- IT7 / 2.
double centre_distance_tolerance(double a_w) { return 0.5 * iso286_tolerance(a_w, 7); }

CentreDistanceFit centre_distance_fit(const GearSpec& g1, const GearSpec& g2, std::optional<double> a_w_given) {
    using std::cos, std::tan;
    // ISO 21771 signed convention: an internal gear's z, d and a are negative, so that one
    // set of formulas serves external and internal pairs.
    const double sg = g2.internal ? -1.0 : 1.0;
    const double z_sum = g1.z + sg * g2.z;
    const double an = g1.alpha_n, at = g1.alpha_t();
    const double beta_b = std::asin(std::sin(g1.beta) * cos(an));
    CentreDistanceFit f;
    f.given = a_w_given.has_value();
    f.sum_x = g1.x + g2.x;
    // ISO 21771:2007 (gear pair): a = m_n (z1 + z2) / (2 cos beta) = m_t (z1 + z2) / 2;
    // inv alpha_wt = inv alpha_t + 2 (x1 + x2) tan alpha_n / (z1 + z2); a_w = a cos alpha_t / cos alpha_wt.
    const double a = 0.5 * (g1.d() + sg * g2.d());
    f.alpha_wt_shifts = inverse_involute(involute(at) + 2.0 * tan(an) * (g1.x + g2.x) / z_sum);
    const double aw_shifts = a * cos(at) / cos(f.alpha_wt_shifts);
    double aw = aw_shifts;
    f.alpha_wt = f.alpha_wt_shifts;
    if (a_w_given) {
        aw = sg * *a_w_given;
        const double c = a * cos(at) / aw;
        if (!(c > 0 && c < 1))
            throw GeometryError("centre_distance", fmt::format("centre distance {:.3f} mm is incompatible with the gear sizes "
                                                               "(a = {:.3f} mm, base circles {:.3f} mm apart)",
                                                               *a_w_given * 1e3, std::abs(a) * 1e3,
                                                               std::abs(a * cos(at)) * 1e3));
        f.alpha_wt = std::acos(c);
    }
    // The same relation solved for the sum of the shifts that meshes without backlash at a_w.
    f.sum_x_implied = (involute(f.alpha_wt) - involute(at)) * z_sum / (2.0 * tan(an));
    // Backlash on the working pitch circle, j_wt = p_wt - s_w1 - s_w2 with the tooth thickness
    // s_w = d_w (s/d + inv alpha_t - inv alpha_wt) and s = m_t (pi/2 + 2 x tan alpha_n)
    // (ISO 21771:2007, tooth thickness at any diameter), gives with d_w/d = a_w/a:
    // j_wt = 2 a_w (inv alpha_wt - inv alpha_wt(x1 + x2)); signed a_w, so that moving an internal
    // pair apart takes backlash away. Its first-order form is DIN 3967 (1978)'s
    // j_t = 2 delta_a tan alpha_wt. Normal backlash j_bn = j_wt cos alpha_wt cos beta_b (ISO/TR 10064-2:1996, clause 4).
    f.j_wt = 2.0 * aw * (involute(f.alpha_wt) - involute(f.alpha_wt_shifts));
    f.j_bn = f.j_wt * cos(f.alpha_wt) * cos(beta_b);
    f.a = std::abs(a);
    f.a_w = std::abs(aw);
    f.a_w_shifts = std::abs(aw_shifts);
    f.tolerance = centre_distance_tolerance(aw);
    return f;
}

std::string describe_fit(const CentreDistanceFit& f) {
    const double d = f.excess();
    return fmt::format("centre distance {:.3f} mm is {:.3f} mm {} the {:.3f} mm at which the profile shifts x1 + x2 = {:.4f} "
                       "mesh without backlash (ISO 21771); {:.3f} mm implies x1 + x2 = {:.4f}, circumferential backlash "
                       "j_wt = {:.3f} mm (normal j_bn = {:.3f} mm); a gearbox housing holds its centre distance to "
                       "+/-{:.3f} mm (ISO 286-1 js7, DIN 3964)",
                       f.a_w * 1e3, std::abs(d) * 1e3, d < 0 ? "below" : "above", f.a_w_shifts * 1e3, f.sum_x,
                       f.a_w * 1e3, f.sum_x_implied, f.j_wt * 1e3, f.j_bn * 1e3, f.tolerance * 1e3);
}

PairGeometry pair_geometry(const GearSpec& g1, const GearSpec& g2, std::optional<double> a_w_given) {
    using std::cos, std::sin, std::tan, std::sqrt, std::abs;
    if (abs(g1.mn - g2.mn) > 1e-9 * g1.mn)
        throw GeometryError(fmt::format("normal modules differ ({:.6g} mm vs {:.6g} mm)", g1.mn * 1e3, g2.mn * 1e3));
    if (abs(g1.alpha_n - g2.alpha_n) > 1e-9) throw GeometryError("normal pressure angles differ");
    if (abs(g1.beta - g2.beta) > 1e-9) throw GeometryError("helix angles differ");
    if (g1.internal) throw GeometryError(fmt::format("gear '{}' is internal: name the external gear first in the mesh", g1.name));
    const bool internal = g2.internal;
    if (g1.beta > 0 && !internal && g1.hand == g2.hand)
        throw GeometryError("external helical gears in mesh need opposite hands (one left, one right)");
    if (g1.beta > 0 && internal && g1.hand != g2.hand)
        throw GeometryError("a helical gear and its internal mate need the same hand");
    if (internal && g2.z - g1.z < 10)
        throw GeometryError(fmt::format("internal gear '{}' needs at least 10 teeth more than its mate (tip interference)", g2.name));

    PairGeometry p;
    p.internal = internal;
    p.sign = internal ? -1.0 : 1.0;
    const double sg = p.sign;
    const double mn = g1.mn, an = g1.alpha_n, beta = g1.beta;
    // Signed (ISO 21771): the internal gear's z, d, a are negative.
    const double z1 = g1.z, z2 = sg * g2.z;
    p.u = g2.z / static_cast<double>(g1.z);
    p.alpha_t = g1.alpha_t();
    p.beta_b = std::asin(sin(beta) * cos(an));
    const double d1 = g1.d(), d2 = sg * g2.d();
    const double db1 = g1.db(), db2 = sg * g2.db();
    const double a = 0.5 * (d1 + d2);
    p.fit = centre_distance_fit(g1, g2, a_w_given);
    if (p.fit.overlaps())
        throw GeometryError("centre_distance", describe_fit(p.fit) + ": the flanks would overlap; give the centre distance "
                                               "the shifts give, or the shifts the centre distance implies");
    // With a_w given, the working pressure angle follows from it (a backlash within the
    // tolerance does not move the line of action).
    p.alpha_wt = p.fit.alpha_wt;
    const double a_w = sg * p.fit.a_w;
    const double y = (a_w - a) / mn;
    // ISO 21771: k = y - (x1 + x2) <= 0 keeps the nominal tip clearance (external pairs).
    const double k = internal ? 0.0 : std::min(0.0, y - (g1.x + g2.x));
    const double dw1 = 2.0 * a_w / (1.0 + z2 / z1);
    // Tip diameter (ISO 21771, signed for the internal gear): d_a = d + 2 m_n (h*_a + x + k).
    const auto tip = [&](const GearSpec& g, double d, double s, int i) {
        const double nominal = d + 2.0 * mn * (g.ha_star + g.x);
        double da = nominal + 2.0 * mn * k;
        p.tip_source[i] = TipSource::iso_tip_alteration;
        if (g.tip_diameter) {
            da = s * *g.tip_diameter;
            p.tip_source[i] = TipSource::given_tip_diameter;
        } else if (g.tip_alteration_factor) {
            da = nominal + 2.0 * mn * *g.tip_alteration_factor;
            p.tip_source[i] = TipSource::given_tip_alteration;
        }
        p.k_applied[i] = (da - nominal) / (2.0 * mn);
        return da;
    };
    const double da1 = tip(g1, d1, 1.0, 0), df1 = d1 - 2.0 * mn * (g1.hf_star - g1.x);
    const double da2 = tip(g2, d2, sg, 1), df2 = d2 - 2.0 * mn * (g2.hf_star - g2.x);
    p.a = abs(a);
    p.a_w = abs(a_w);
    p.y = sg * y;
    p.k = k;
    p.d[0] = d1;
    p.d[1] = abs(d2);
    p.db[0] = db1;
    p.db[1] = abs(db2);
    p.dw[0] = dw1;
    p.dw[1] = abs(dw1 * z2 / z1);
    p.da[0] = da1;
    p.da[1] = abs(da2);
    p.df[0] = df1;
    p.df[1] = abs(df2);
    const GearSpec* g[2] = {&g1, &g2};
    for (int i = 0; i < 2; ++i) {
        if (!(p.df[i] > 0)) throw GeometryError(fmt::format("gear '{}' has a negative root diameter", g[i]->name));
        const bool inner = i == 1 && internal;
        if (!inner && p.da[i] <= p.db[i])
            throw GeometryError(fmt::format("gear '{}': tip circle inside the base circle", g[i]->name));
        if (inner && p.da[i] <= p.db[i])
            throw GeometryError(fmt::format("internal gear '{}': tip circle inside the base circle (involute undefined)", g[i]->name));
        // Transverse tooth thickness at the tip (involute tooth thickness relation).
        const double mt = g[i]->mt();
        const double s_t = mt * (std::numbers::pi / 2.0 + 2.0 * g[i]->x * tan(p.alpha_t));
        const double a_at = std::acos(p.db[i] / p.da[i]);
        p.tip_thickness[i] = inner ? p.da[i] * (s_t / p.d[i] - involute(p.alpha_t) + involute(a_at))
                                   : p.da[i] * (s_t / p.d[i] + involute(p.alpha_t) - involute(a_at));
        if (!(p.tip_thickness[i] > 0))
            throw GeometryError(fmt::format(
                "gear '{}': profile shift x = {} makes a pointed tooth (tip thickness {:.3f} mm)", g[i]->name,
                g[i]->x, p.tip_thickness[i] * 1e3));
    }
    // Tip clearance: radial gap between a tip circle and the mate's root circle.
    p.tip_clearance[0] = internal ? 0.5 * p.df[1] - p.a_w - 0.5 * p.da[0] : p.a_w - 0.5 * p.da[0] - 0.5 * p.df[1];
    p.tip_clearance[1] = internal ? 0.5 * p.da[1] - p.a_w - 0.5 * p.df[0] : p.a_w - 0.5 * p.da[1] - 0.5 * p.df[0];
    for (int i = 0; i < 2; ++i)
        if (p.tip_clearance[i] < 0)
            throw GeometryError(fmt::format("tip of gear '{}' interferes with the root of its mate (clearance {:.3f} mm)",
                                            g[i]->name, p.tip_clearance[i] * 1e3));

    p.p_bt = std::numbers::pi * g1.mt() * cos(p.alpha_t);
    const double rb1 = 0.5 * db1, rb2 = 0.5 * abs(db2);
    const double ra1 = 0.5 * da1, ra2 = 0.5 * abs(da2);
    // Along the line of action from T1 towards the pitch point; T2 lies behind T1
    // for an internal pair (signed T1T2 < 0).
    p.T1T2 = a_w * sin(p.alpha_wt);
    p.T1C = rb1 * tan(p.alpha_wt);
    p.T1E = sqrt(ra1 * ra1 - rb1 * rb1);
    p.T1A = p.T1T2 - sg * sqrt(ra2 * ra2 - rb2 * rb2);
    if (p.T1A < 0)
        throw GeometryError(fmt::format("tip of gear '{}' reaches below the base circle of '{}' (involute interference)",
                                        g2.name, g1.name));
    if (!internal && p.T1E > p.T1T2)
        throw GeometryError(fmt::format("tip of gear '{}' reaches below the base circle of '{}' (involute interference)",
                                        g1.name, g2.name));
    const double ga1 = p.T1E - p.T1C;  // recess (pinion addendum) segment
    const double ga2 = p.T1C - p.T1A;  // approach segment
    if (!(ga1 > 0 && ga2 > 0)) throw GeometryError("the path of contact does not pass the pitch point (check profile shifts)");
    p.eps1 = ga1 / p.p_bt;
    p.eps2 = ga2 / p.p_bt;
    p.eps_alpha = p.eps1 + p.eps2;
    p.T1B = p.T1E - p.p_bt;
    p.T1D = p.T1A + p.p_bt;
    p.b_eff = std::min(g1.b, g2.b);
    p.eps_beta = p.b_eff * sin(beta) / (std::numbers::pi * mn);
    p.eps_gamma = p.eps_alpha + p.eps_beta;
    // Continuous meshing needs a total contact ratio of 1 (ISO 21771); a helical
    // pair may have eps_alpha < 1 when the overlap makes up the difference.
    if (p.eps_gamma < 1.0)
        throw GeometryError(fmt::format("total contact ratio eps_gamma = {:.3f} < 1 (eps_alpha {:.3f} + eps_beta {:.3f}): "
                                        "the pair does not mesh continuously",
                                        p.eps_gamma, p.eps_alpha, p.eps_beta));
    p.transverse_gap = p.eps_alpha < 1.0;
    // rho_redC = a_w sin(alpha_wt) u / ((u + 1)^2 cos beta_b) with signed a_w and u.
    const double us = z2 / z1;
    p.rho_redC = a_w * sin(p.alpha_wt) * us / ((1.0 + us) * (1.0 + us) * cos(p.beta_b));
    return p;
}

}  // namespace gearloss::geometry
