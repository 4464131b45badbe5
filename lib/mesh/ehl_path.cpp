#include "mesh/ehl_path.hpp"

#include <algorithm>
#include <cmath>

namespace gearloss::mesh {

namespace {
// Local state at xi (shared by the profile and the loss integral).
PathPoint path_point(const geometry::PairGeometry& g, double xi, double L_mean, double w0, double F_bn, double E_prime,
                     double sigma, double T_bulk, const lubricant::Oil& oil, const Rheology& rh, bool heating,
                     const lubricant::OilState& bulk, double film_rise_guess = 0) {
    const double w1 = w0 / g.u;  // mate relative speed, same sense for an internal pair
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
    const double rho1 = xi / cb, rho2 = (g.T1T2 - xi) / cb;  // signed: < 0 for a ring
    const double R = rho1 * rho2 / (rho1 + rho2);
    pt.u1 = w0 * xi;
    pt.u2 = w1 * std::abs(g.T1T2 - xi);
    pt.u_e = 0.5 * (pt.u1 + pt.u2);
    pt.v_slide = std::abs(pt.u1 - pt.u2);
    pt.srr = pt.u_e > 0 ? pt.v_slide / pt.u_e : 0.0;
    EhlContactInput in{w_line, std::abs(R), pt.u1, pt.u2, E_prime, sigma, T_bulk, film_rise_guess};
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
                     int positions, bool heating) {
    PathProfile prof;
    const double w0 = std::abs(omega_rel);
    const double L = g.T1E - g.T1A;
    const lubricant::OilState bulk = oil.state(T_bulk);
    double integral = 0;
    for (int k = 0; k < positions; ++k) {
        const PathPoint pt = path_point(g, g.T1A + L * (k + 0.5) / positions, L_mean, w0, F_bn, E_prime, sigma, T_bulk,
                                        oil, rh, heating, bulk);
        integral += pt.c.mu * F_bn * pt.load_share * pt.v_slide * (L / positions);
        prof.points.push_back(pt);
    }
    prof.loss = planets * integral / g.p_bt;
    return prof;
}

double ehl_mesh_loss(const geometry::PairGeometry& g, double L_mean, double omega_rel, double F_bn, int planets,
                     double E_prime, double sigma, double T_bulk, const lubricant::Oil& oil, const Rheology& rh,
                     std::vector<double>* film_rise) {
    const double w0 = std::abs(omega_rel);
    std::vector<double> knots = {g.T1A};
    const bool spur = g.eps_beta == 0.0;
    for (double x : spur ? std::vector<double>{g.T1B, g.T1C, g.T1D} : std::vector<double>{g.T1C})
        if (x > knots.back() && x < g.T1E) knots.push_back(x);
    knots.push_back(g.T1E);
    std::sort(knots.begin(), knots.end());
    constexpr double gx[3] = {-0.7745966692414834, 0.0, 0.7745966692414834};
    constexpr double gw[3] = {0.5555555555555556, 0.8888888888888888, 0.5555555555555556};
    const lubricant::OilState bulk = oil.state(T_bulk);
    const size_t nodes = 3 * (knots.size() - 1);
    if (film_rise && film_rise->size() != nodes) film_rise->assign(nodes, 0.0);
    double integral = 0;
    for (size_t s = 0; s + 1 < knots.size(); ++s) {
        const double a = knots[s], b = knots[s + 1], h = 0.5 * (b - a), c = 0.5 * (a + b);
        for (int k = 0; k < 3; ++k) {
            double* rise = film_rise ? &(*film_rise)[3 * s + k] : nullptr;
            const PathPoint pt = path_point(g, c + h * gx[k], L_mean, w0, F_bn, E_prime, sigma, T_bulk, oil, rh, true,
                                            bulk, rise ? *rise : 0.0);
            if (rise) *rise = pt.c.T_film - T_bulk;
            integral += gw[k] * h * pt.c.mu * F_bn * pt.load_share * pt.v_slide;
        }
    }
    return planets * integral / g.p_bt;
}

}  // namespace gearloss::mesh
