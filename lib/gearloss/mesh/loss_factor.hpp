#pragma once
// Gear loss factor H_V: the ratio of the mesh friction power to mu * P_in
// (Ohlendorf 1958; Wimmer 2006, numerical H_VL).
#include "gearloss/geometry/gear_geometry.hpp"

namespace gearloss::mesh {

enum class LossFactorModel { ohlendorf, buckingham, wimmer };
const char* to_string(LossFactorModel m);

// Ohlendorf (1958): H_V = pi (u+1)/(z1 u cos beta_b) (1 - eps_a + eps1^2 + eps2^2).
double loss_factor_ohlendorf(const geometry::PairGeometry& g, int z1);
// Single-pair kinematic average (Buckingham 1949): (eps1^2 + eps2^2)/eps_a instead of the bracket.
double loss_factor_buckingham(const geometry::PairGeometry& g, int z1);

// Contact lines swept over one base pitch on the plane of action, with the
// load shared in proportion to contact length (rigid teeth; Wimmer 2006 H_VL
// with F'_N = F_bn / L_total). Also yields the minimum total contact length. The last
// few results of each thread are kept: the same inputs return the same numbers at once.
struct ContactSweep {
    double H_V = 0;
    double L_min = 0;   // minimum total contact-line length [m]
    double L_mean = 0;
};
ContactSweep sweep_contact_lines(const geometry::PairGeometry& g, int phases = 2000);

}  // namespace gearloss::mesh
