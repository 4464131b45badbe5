#include "gearloss/mesh/ehl_path.hpp"

#include <algorithm>
#include <boost/math/quadrature/gauss.hpp>
#include <cmath>
#include <limits>

namespace gearloss::mesh {

namespace {
// Rolling kinematics at xi on the line of action (from T1): reduced radius of curvature
// (radii signed, < 0 for a ring) and the surface speeds of gear 0 and its mate (w0 / u, the
// same sense for an internal pair).
struct Kinematics {
    double R, u1, u2;
    double v_slide() const { return std::abs(u1 - u2); }
};
Kinematics kinematics_at(const geometry::PairGeometry& g, double xi, double w0) {
    const double cb = std::cos(g.beta_b);
    const double rho1 = xi / cb, rho2 = (g.T1T2 - xi) / cb;
    return {std::abs(rho1 * rho2 / (rho1 + rho2)), w0 * xi, w0 / g.u * std::abs(g.T1T2 - xi)};
}

// Local state at xi (shared by the profile and the loss integral).
PathPoint path_point(const geometry::PairGeometry& g, double xi, double L_mean, double w0, double F_bn, double E_prime,
                     double sigma, double T_bulk, const lubricant::Oil& oil, const Rheology& rh, bool heating,
                     const lubricant::OilState& bulk, double film_rise_guess, TractionLaw law, double viscosity_factor) {
    const double cb = std::cos(g.beta_b);
    const bool spur = g.eps_beta == 0.0;
    PathPoint pt;
    pt.xi = xi;
    pt.from_pitch = xi - g.T1C;
    // Rigid load sharing: a spur pair carries it all in the single-pair zone (B..D)
    // and half in the double-pair zones; a helical set has a near-constant line load.
    double w_line;
    if (spur) {
        const bool single = xi >= g.T1B && xi <= g.T1D;
        pt.load_share = single ? 1.0 : 0.5;
        w_line = F_bn * pt.load_share / g.b_eff;
    } else {
        w_line = F_bn / L_mean;
        pt.load_share = g.b_eff / cb / L_mean;
    }
    const Kinematics k = kinematics_at(g, xi, w0);
    pt.u1 = k.u1;
    pt.u2 = k.u2;
    pt.u_e = 0.5 * (pt.u1 + pt.u2);
    pt.v_slide = k.v_slide();
    pt.srr = pt.u_e > 0 ? pt.v_slide / pt.u_e : 0.0;
    EhlContactInput in{w_line, k.R, pt.u1, pt.u2, E_prime, sigma, T_bulk, film_rise_guess, law, viscosity_factor};
    pt.c = ehl_contact(in, oil, rh, {}, heating, &bulk);
    const double v_base = w0 * 0.5 * g.db[0];
    pt.local_efficiency = v_base > 0 ? 1.0 - pt.c.mu * pt.v_slide / v_base : 1.0;
    return pt;
}
}  // namespace

// Mean friction power over one base pitch: (1/p_bt) integral of mu F_pair v_slide d xi
// (a pair spends d xi / v_base at each position and pairs enter every p_bt / v_base); for a
// helical set the face integral is folded into load_share = (b / cos beta_b) / L_mean.
PathProfile ehl_path(const geometry::PairGeometry& g, double L_mean, double omega_rel, double F_bn, int planets,
                     double E_prime, double sigma, double T_bulk, const lubricant::Oil& oil, const Rheology& rh,
                     int positions, bool heating, TractionLaw law, double viscosity_factor) {
    PathProfile prof;
    const double w0 = std::abs(omega_rel);
    const double L = g.T1E - g.T1A;
    const lubricant::OilState bulk = oil.state(T_bulk, viscosity_factor);
    double integral = 0;
    for (int k = 0; k < positions; ++k) {
        const PathPoint pt = path_point(g, g.T1A + L * (k + 0.5) / positions, L_mean, w0, F_bn, E_prime, sigma, T_bulk,
                                        oil, rh, heating, bulk, 0.0, law, viscosity_factor);
        integral += pt.c.mu * F_bn * pt.load_share * pt.v_slide * (L / positions);
        prof.points.push_back(pt);
    }
    prof.loss = planets * integral / g.p_bt;
    return prof;
}

namespace {

// Gauss-Legendre rules on [-1, 1], nodes in increasing order, from Boost.Math's tables of the
// non-negative nodes (x0 < x1 ...) and their weights.
using Gauss3 = boost::math::quadrature::gauss<double, 3>;
using Gauss4 = boost::math::quadrature::gauss<double, 4>;
const double kG3x[3] = {-Gauss3::abscissa()[1], Gauss3::abscissa()[0], Gauss3::abscissa()[1]};
const double kG3w[3] = {Gauss3::weights()[1], Gauss3::weights()[0], Gauss3::weights()[1]};
const double kG4x[4] = {-Gauss4::abscissa()[1], -Gauss4::abscissa()[0], Gauss4::abscissa()[0], Gauss4::abscissa()[1]};
const double kG4w[4] = {Gauss4::weights()[1], Gauss4::weights()[0], Gauss4::weights()[0], Gauss4::weights()[1]};

// Spur pair: the path A-E split at the load-share jumps B, D and the sliding kink C;
// 3-point Gauss-Legendre per segment (12 contact solutions).
double spur_mesh_loss(const geometry::PairGeometry& g, double L_mean, double w0, double F_bn, double E_prime,
                      double sigma, double T_bulk, const lubricant::Oil& oil, const Rheology& rh,
                      std::vector<double>* film_rise, const lubricant::OilState& bulk, TractionLaw law,
                      double viscosity_factor) {
    std::vector<double> knots = {g.T1A};
    for (double x : {g.T1B, g.T1C, g.T1D})
        if (x > knots.back() && x < g.T1E) knots.push_back(x);
    knots.push_back(g.T1E);
    const size_t nodes = 3 * (knots.size() - 1);
    if (film_rise && film_rise->size() != nodes) film_rise->assign(nodes, 0.0);
    double integral = 0;
    for (size_t s = 0; s + 1 < knots.size(); ++s) {
        const double a = knots[s], b = knots[s + 1], h = 0.5 * (b - a), c = 0.5 * (a + b);
        for (int k = 0; k < 3; ++k) {
            double* rise = film_rise ? &(*film_rise)[3 * s + k] : nullptr;
            const PathPoint pt = path_point(g, c + h * kG3x[k], L_mean, w0, F_bn, E_prime, sigma, T_bulk, oil, rh, true,
                                            bulk, rise ? *rise : 0.0, law, viscosity_factor);
            if (rise) *rise = pt.c.T_film - T_bulk;
            integral += kG3w[k] * h * pt.c.mu * F_bn * pt.load_share * pt.v_slide;
        }
    }
    return integral / g.p_bt;
}

// Helical pair: contact lines across the face. A line at phase s lies on xi = s + k p_bt +
// y tan(beta_b), 0 <= y <= b, clipped to the field A-E; its length element is
// dl = dxi / (tan beta_b cos beta_b). With rigid teeth the line load at phase s is
// w = F_bn / L(s), L(s) the total length of the lines in the field, and the friction power
// is w times the sum over lines of the integral of mu v_slide dl; the mesh loss is its mean
// over the phases of one base pitch (the Wimmer sweep of loss_factor.cpp with mu inside).
// mu(xi, w) is solved at 4 Gauss nodes on each side of the pitch point for the smallest
// and the largest line load of the cycle and interpolated (cubic in xi, linear in w), so
// the phase sweep costs no contact solution: 16 solutions per mesh evaluation.
double helical_mesh_loss(const geometry::PairGeometry& g, double w0, double F_bn, double E_prime, double sigma,
                         double T_bulk, const lubricant::Oil& oil, const Rheology& rh, std::vector<double>* film_rise,
                         const lubricant::OilState& bulk, TractionLaw law, double viscosity_factor) {
    constexpr int kPhases = 24;
    const double A = g.T1A, E = g.T1E, C = g.T1C, pbt = g.p_bt, b = g.b_eff;
    const double t = std::tan(g.beta_b), cb = std::cos(g.beta_b);
    const double span = b * t;
    // Lines of each phase as xi intervals; L(s) from their face extent.
    struct Line { double xa, xb; };
    std::vector<std::vector<Line>> lines(kPhases);
    std::vector<double> Ls(kPhases, 0.0);
    for (int j = 0; j < kPhases; ++j) {
        const double s = A + (j + 0.5) / kPhases * pbt;
        const double f0 = std::floor((A - span - s) / pbt), f1 = std::ceil((E - s) / pbt);
        // Bounded line loop (as in sweep_contact_lines): no result for a geometry that is not finite.
        if (!(std::isfinite(f0) && std::isfinite(f1) && f1 - f0 < 1e5)) return std::numeric_limits<double>::quiet_NaN();
        const int k0 = static_cast<int>(f0) - 1;
        const int k1 = static_cast<int>(f1) + 1;
        for (int k = k0; k <= k1; ++k) {
            const double xi0 = s + k * pbt;
            const double y0 = std::max(0.0, (A - xi0) / t), y1 = std::min(b, (E - xi0) / t);
            if (y1 <= y0) continue;
            lines[j].push_back({xi0 + t * y0, xi0 + t * y1});
            Ls[j] += (y1 - y0) / cb;
        }
    }
    const double L_lo = *std::min_element(Ls.begin(), Ls.end()), L_hi = *std::max_element(Ls.begin(), Ls.end());
    if (!(L_lo > 0)) return 0.0;
    // Sides of the pitch point (C may lie outside the field for extreme profile shifts).
    std::vector<std::pair<double, double>> sides;
    if (C > A && C < E) sides = {{A, C}, {C, E}};
    else sides = {{A, E}};
    const bool two_loads = L_hi > L_lo * (1 + 1e-9);
    const size_t n_nodes = 4 * sides.size();
    if (film_rise && film_rise->size() != 2 * n_nodes) film_rise->assign(2 * n_nodes, 0.0);
    // mu at the nodes for w = F_bn / L_hi (light) and F_bn / L_lo (heavy).
    std::vector<double> node_x(n_nodes), mu_light(n_nodes), mu_heavy(n_nodes);
    for (size_t sd = 0; sd < sides.size(); ++sd)
        for (int q = 0; q < 4; ++q) {
            const auto [a, bb] = sides[sd];
            const double xi = 0.5 * (a + bb) + 0.5 * (bb - a) * kG4x[q];
            const size_t n = 4 * sd + q;
            node_x[n] = xi;
            const Kinematics k = kinematics_at(g, xi, w0);
            for (int heavy = 0; heavy < (two_loads ? 2 : 1); ++heavy) {
                double* rise = film_rise ? &(*film_rise)[2 * n + heavy] : nullptr;
                const EhlContactInput in{F_bn / (heavy ? L_lo : L_hi), k.R, k.u1, k.u2, E_prime, sigma, T_bulk,
                                         rise ? *rise : 0.0, law, viscosity_factor};
                const EhlContactResult c = ehl_contact(in, oil, rh, {}, true, &bulk);
                if (rise) *rise = c.T_film - T_bulk;
                (heavy ? mu_heavy : mu_light)[n] = c.mu;
            }
            if (!two_loads) mu_heavy[n] = mu_light[n];
        }
    // Lagrange interpolation of mu on one side at xi.
    auto mu_at = [&](size_t sd, double xi, const std::vector<double>& mu) {
        double v = 0;
        for (int i = 0; i < 4; ++i) {
            double l = 1;
            for (int j = 0; j < 4; ++j)
                if (j != i) l *= (xi - node_x[4 * sd + j]) / (node_x[4 * sd + i] - node_x[4 * sd + j]);
            v += l * mu[4 * sd + i];
        }
        return v;
    };
    double mean_power = 0;
    for (int j = 0; j < kPhases; ++j) {
        const double w = F_bn / Ls[j];
        const double f = two_loads ? (w - F_bn / L_hi) / (F_bn / L_lo - F_bn / L_hi) : 0.0;  // 0 light .. 1 heavy
        double integral = 0;  // sum over lines of the integral of mu v_slide dxi
        for (const Line& ln : lines[j])
            for (size_t sd = 0; sd < sides.size(); ++sd) {
                const double a = std::max(ln.xa, sides[sd].first), bb = std::min(ln.xb, sides[sd].second);
                if (bb <= a) continue;
                for (int q = 0; q < 4; ++q) {  // exact for the cubic mu times the linear v_slide
                    const double xi = 0.5 * (a + bb) + 0.5 * (bb - a) * kG4x[q];
                    const double mu = (1 - f) * mu_at(sd, xi, mu_light) + f * mu_at(sd, xi, mu_heavy);
                    const double v_slide = std::abs(w0 * xi - w0 / g.u * std::abs(g.T1T2 - xi));  // as kinematics_at
                    integral += 0.5 * (bb - a) * kG4w[q] * std::max(mu, 0.0) * v_slide;
                }
            }
        mean_power += w * integral / (t * cb);
    }
    return mean_power / kPhases;
}

}  // namespace

double ehl_mesh_loss(const geometry::PairGeometry& g, double L_mean, double omega_rel, double F_bn, int planets,
                     double E_prime, double sigma, double T_bulk, const lubricant::Oil& oil, const Rheology& rh,
                     std::vector<double>* film_rise, TractionLaw law, double viscosity_factor) {
    const double w0 = std::abs(omega_rel);
    const lubricant::OilState bulk = oil.state(T_bulk, viscosity_factor);
    const double per_mesh = g.eps_beta == 0.0
                                ? spur_mesh_loss(g, L_mean, w0, F_bn, E_prime, sigma, T_bulk, oil, rh, film_rise, bulk, law,
                                                 viscosity_factor)
                                : helical_mesh_loss(g, w0, F_bn, E_prime, sigma, T_bulk, oil, rh, film_rise, bulk, law, viscosity_factor);
    return planets * per_mesh;
}

}  // namespace gearloss::mesh
