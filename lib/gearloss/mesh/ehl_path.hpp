#pragma once
// Local thermal-EHL friction along the path of contact of one mesh: at each
// position the load share, Hertz contact, rolling and sliding speeds, film,
// traction (ehl_contact) and the local loss; the mesh loss is the integral of
// mu F v_slide over one base pitch (the H_V definition with mu inside).
#include <vector>

#include "gearloss/geometry/gear_geometry.hpp"
#include "gearloss/mesh/ehl_contact.hpp"

namespace gearloss::mesh {

struct PathPoint {
    double xi = 0;            // position from T1 along the line of action [m]
    double from_pitch = 0;    // signed distance from the pitch point [m] (< 0 approach)
    double load_share = 0;    // share of the normal force carried at this position
    double u1 = 0, u2 = 0, u_e = 0, v_slide = 0, srr = 0;
    EhlContactResult c;
    double local_efficiency = 1;  // 1 - mu v_slide / v_base (power lost per power carried)
};

struct PathProfile {
    std::vector<PathPoint> points;
    double loss = 0;          // mesh friction power [W] for the whole gear set
};

// omega_rel: speed of gear 0 relative to the carrier (or housing) [rad/s];
// F_bn: normal force per mesh [N]; planets: identical meshes; sigma: roughness;
// viscosity_factor: the case's calibration of the oil's viscosity (Oil::state), as every
// other mechanism sees it through Model::oil_state.
PathProfile ehl_path(const geometry::PairGeometry& g, double L_mean, double omega_rel, double F_bn, int planets,
                     double E_prime, double sigma, double T_bulk, const lubricant::Oil& oil, const Rheology& rh,
                     int positions = 21, bool heating = true, TractionLaw law = TractionLaw::eyring,
                     double viscosity_factor = 1.0);

// Mesh friction power only. Spur pair: the path split at the load-share jumps B, D and the
// sliding kink C, 3-point Gauss-Legendre per segment (12 contact solutions). Helical pair:
// the contact lines across the face swept over one base pitch with the line load
// F_bn / L(t) of each phase (16 contact solutions, interpolated along the lines).
// `film_rise` (optional, in/out): the film temperature rise of each node from the previous
// call, used to start its thermal loop (successive calls of a thermal solve differ little).
double ehl_mesh_loss(const geometry::PairGeometry& g, double L_mean, double omega_rel, double F_bn, int planets,
                     double E_prime, double sigma, double T_bulk, const lubricant::Oil& oil, const Rheology& rh,
                     std::vector<double>* film_rise = nullptr, TractionLaw law = TractionLaw::eyring,
                     double viscosity_factor = 1.0);

}  // namespace gearloss::mesh
