#pragma once
// Drag of an open (disengaged) wet multi-plate clutch or brake: laminar Couette
// shear in the oil film of each friction interface (seed 003 §3.4, after Dempsey et al. 2012),
// with the Patir & Cheng (1979) shear-stress factor of rough surfaces. When the supplied oil
// cannot fill the gap against the centrifugal outflow, a full film is held out to the wetted
// radius of Yuan et al. (2007) and the rest of the gap is a two-phase region of oil streaks and
// air whose oil fraction follows from the flow balance (the model's own assumption, stated at
// open_pack_drag below and in docs/config.md).
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

// Centrifugal outflow capacity [m^3/s] of a full film between radii a < b with ambient pressure at
// both ends: pi h^3 rho w^2 (b^2 - a^2) / (40 eta ln(b/a)) (radial Poiseuille flow with the mean
// centrifugal head of a linear Couette profile; Yuan et al. 2007). Tends to pi h^3 rho w^2 a^2 /
// (20 eta) as b -> a; rises with a and with b.
double outflow_capacity(const WetClutchPack& c, double eta, double rho, double slip_speed, double a, double b);

// Outer radius of the full film [m]: r_outer when the supply fills the gap, else the radius r_w
// at which the capacity of the film r_inner..r_w equals the supply (Yuan et al. 2007); r_inner
// when not even the narrowest film is fed.
double wetted_outer_radius(const WetClutchPack& c, double eta, double rho, double slip_speed);

// Oil fraction of the two-phase region r_w..r_outer beyond the full film: the supply over the
// capacity of that region as a full film, at most 1 (see open_pack_drag). 1 while the full film
// reaches r_outer.
double streak_oil_fraction(const WetClutchPack& c, double eta, double rho, double slip_speed, double wetted_radius);

// State of the oil film of an open pack at a slip speed:
//   full_film    the supply fills the gap out to r_outer: the drag rises with slip speed;
//   breaking_up  the supply no longer fills the gap: beyond the full film (r_inner <= r_w < r_outer)
//                the oil runs as streaks over a fraction of the plate, and the oil's shear in the
//                gap is still at least that of the air: the drag peaks and falls gradually;
//   broken       the oil left in the gap shears less than the air beside it (oil fraction below
//                eta_air / (eta_oil_eff + eta_air) over the whole plate): the gap drags mostly air.
enum class FilmRegime { full_film, breaking_up, broken };
std::string_view to_string(FilmRegime r);

struct ClutchDrag {
    double torque = 0;         // N m
    double power = 0;          // W (= torque x slip speed, heat released in the oil)
    double wetted_radius = 0;  // outer radius of the full film [m]
    double oil_fraction = 1;   // oil fraction of the two-phase region beyond it
    double oil_torque = 0;     // of which carried by oil (full film and streaks) [N m]
    double air_torque = 0;     // and by the air in the gaps [N m]
    FilmRegime regime = FilmRegime::full_film;
};

// Drag of an open pack at slip speed |dw| [rad/s], oil dynamic viscosity eta [Pa s] and
// density rho, isothermal and without the air's shear: over the full film
// T = n pi eta dw (r_w^4 - r_i^4) / (2 h) (phi_f + phi_fs), phi_f = 1 (H >= 3), plus the
// oil fraction times the same over r_w..r_o.
ClutchDrag open_pack_drag(const WetClutchPack& c, double eta, double rho, double slip_speed);

}  // namespace gearloss::clutch
