#include "mesh/ehl_path.hpp"

#include <algorithm>
#include <cmath>

namespace gearloss::mesh {

PathProfile ehl_path(const geometry::PairGeometry& g, double L_mean, double omega_rel, double F_bn, int planets,
                     double E_prime, double sigma, double T_bulk, const lubricant::Oil& oil, const Rheology& rh,
                     int positions, bool heating) {
    PathProfile prof;
    const double w0 = std::abs(omega_rel);
    const double w1 = w0 / g.u;  // mate relative speed, same sense for an internal pair
    const double cb = std::cos(g.beta_b);
    const bool spur = g.eps_beta == 0.0;
    const double L = g.T1E - g.T1A;
    double integral = 0;
    for (int k = 0; k < positions; ++k) {
        PathPoint pt;
        pt.xi = g.T1A + L * (k + 0.5) / positions;  // midpoints: integrates over A..E
        pt.from_pitch = pt.xi - g.T1C;
        // Rigid load sharing: a spur pair carries it all in the single-pair zone (B..D)
        // and half in the double-pair zones; a helical set has a near-constant line load.
        double w_line;
        if (spur) {
            const bool single = pt.xi >= g.T1B && pt.xi <= g.T1D;
            pt.load_share = single ? 1.0 : 0.5;
            w_line = F_bn * pt.load_share / g.b_eff;
        } else {
            w_line = F_bn / L_mean;
            pt.load_share = g.b_eff / cb / L_mean;
        }
        const double rho1 = pt.xi / cb, rho2 = (g.T1T2 - pt.xi) / cb;  // signed: < 0 for a ring
        const double R = rho1 * rho2 / (rho1 + rho2);
        pt.u1 = w0 * pt.xi;
        pt.u2 = w1 * std::abs(g.T1T2 - pt.xi);
        pt.u_e = 0.5 * (pt.u1 + pt.u2);
        pt.v_slide = std::abs(pt.u1 - pt.u2);
        pt.srr = pt.u_e > 0 ? pt.v_slide / pt.u_e : 0.0;
        EhlContactInput in{w_line, std::abs(R), pt.u1, pt.u2, E_prime, sigma, T_bulk};
        pt.c = ehl_contact(in, oil, rh, {}, heating);
        const double v_base = w0 * 0.5 * g.db[0];
        pt.local_efficiency = v_base > 0 ? 1.0 - pt.c.mu * pt.v_slide / v_base : 1.0;
        // Friction power of the pair(s) at this position: mu F v_slide.
        integral += pt.c.mu * F_bn * pt.load_share * (spur ? 1.0 : 1.0) * pt.v_slide * (L / positions);
        prof.points.push_back(pt);
    }
    // Average over one base pitch; for a helical set the face integral is folded into
    // load_share = (b / cos beta_b) / L_mean along the transverse path.
    prof.loss = planets * integral / g.p_bt;
    return prof;
}

}  // namespace gearloss::mesh
