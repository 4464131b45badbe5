#pragma once
// Drag of an open (disengaged) wet multi-plate clutch or brake: laminar Couette
// shear in the oil film of each friction interface (seed 003 §3.4, after Dempsey et al. 2012),
// with the Patir & Cheng (1979) shear-stress factor of rough surfaces and a wetted
// outer radius that shrinks when the supplied oil cannot fill the gap against the
// centrifugal outflow (after Yuan et al. 2007).
#include <string>
#include <string_view>

namespace gearloss::clutch {

struct WetClutchPack {
    std::string name;
    int interfaces = 0;      // friction interfaces (oil films) of the pack
    double r_inner = 0;      // m
    double r_outer = 0;      // m
    double clearance = 0;    // oil-film thickness per interface when open [m]
    double roughness = 1e-6; // composite rms roughness of plate and lining [m]
    double oil_supply = 0;   // oil fed to the pack [m^3/s]; 0 = always fully wetted
};

// Patir & Cheng (1979) shear-stress factor phi_fs for isotropic roughness (gamma = 1),
// phi_fs = 11.1 H^2.31 exp(-2.38 H + 0.11 H^2), H = h/sigma < 7 (Patir & Cheng 1979, fit for gamma = 1);
// 0 beyond its range (it is 0.013 at H = 7, against 1 for the smooth-film term).
double shear_stress_factor(double H);

// Outer radius of the wetted annulus [m]: r_outer when the supply fills the gap, else the
// radius at which the film's centrifugal outflow pi h^3 rho w^2 (r^2 - r_i^2) /
// (40 eta ln(r/r_i)) equals the supply (radial Poiseuille flow with the mean centrifugal
// head of a linear Couette profile, both plates' ends at ambient pressure).
double wetted_outer_radius(const WetClutchPack& c, double eta, double rho, double slip_speed);

// State of the oil film of an open pack at a slip speed (Yuan et al. 2007; Iqbal et al. 2013):
//   full_film    the supply fills the gap out to r_outer: the drag rises with slip speed;
//   breaking_up  the centrifugal outflow exceeds the supply, the wetted annulus ends at
//                r_inner < r_w < r_outer and shrinks with speed: the drag peaks and falls;
//   broken       r_w at r_inner: only the air (oil mist) in the gap is sheared.
enum class FilmRegime { full_film, breaking_up, broken };
std::string_view to_string(FilmRegime r);
FilmRegime film_regime(const WetClutchPack& c, double wetted_radius);

struct ClutchDrag {
    double torque = 0;       // N m
    double power = 0;        // W (= torque x slip speed, heat released in the oil)
    double wetted_radius = 0;
};

// Drag of an open pack at slip speed |dw| [rad/s], oil dynamic viscosity eta [Pa s] and
// density rho: T = n pi eta dw (r_w^4 - r_i^4) / (2 h) (phi_f + phi_fs), phi_f = 1 (H >= 3).
ClutchDrag open_pack_drag(const WetClutchPack& c, double eta, double rho, double slip_speed);

}  // namespace gearloss::clutch
