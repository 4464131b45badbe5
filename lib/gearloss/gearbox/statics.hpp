#pragma once
// Shaft statics shared by the mesh forces (gearbox.cpp) and the weights (weights.cpp).
#include <Eigen/Core>
#include <vector>

#include "gearloss/gearbox/gearbox.hpp"

namespace gearloss::gearbox::detail {

using Vec3 = Eigen::Vector3d;

struct GearLoad {
    Vec3 F = Vec3::Zero();
    Vec3 r = Vec3::Zero();  // application point: (x, y) from the shaft axis, z along the shaft
};

// Radial reaction vector (housing frame) and signed axial reaction of every bearing.
struct Reactions {
    std::vector<Eigen::Vector2d> R;
    std::vector<double> Z;
};

// Reactions on one shaft with at most two support positions (statically determinate); `loads`
// per gear, `shaft_loads` on the shaft itself, `weights` for weights rather than mesh forces;
// the reactions of pilot bearings in this shaft are taken from `out` (their inner shafts solved first).
void shaft_reactions(const Gearbox& gb, int shaft, const std::vector<std::vector<GearLoad>>& loads,
                     const std::vector<GearLoad>& shaft_loads, bool weights, Reactions& out);

// The shafts, every pilot bearing's inner shaft before its outer shaft (solve them in this
// order: the outer shaft takes the pilot's reaction from `out`); a cycle of pilots is an error.
std::vector<int> shafts_inner_first(const Gearbox& gb);

// Mass of one gear and of one shaft (0 without support bearings) [kg] (weights.cpp).
double gear_mass(const Gearbox& gb, const Layout& L, int g);
double shaft_mass(const Gearbox& gb, int s);

// Bearing reactions to the weights of gears and shafts into L (bearing_R_weight, ...).
void weight_reactions(const Gearbox& gb, Layout& L);

}  // namespace gearloss::gearbox::detail
