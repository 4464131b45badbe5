// Weights of gears and shafts as bearing loads: masses from the geometry, reactions by the
// shaft statics of the mesh forces (statics.hpp), and the combined load of every bearing.
#include <algorithm>
#include <cmath>
#include <fmt/format.h>
#include <numbers>
#include <utility>

#include "gearloss/gearbox/statics.hpp"

namespace gearloss::gearbox {

namespace detail {

namespace {

// Standard acceleration of gravity [m/s^2].
constexpr double g_n = 9.80665;

// Support bearings of a shaft (not those under its free gears or planets).
std::vector<int> support_bearings(const Gearbox& gb, int shaft) {
    std::vector<int> out;
    for (size_t i = 0; i < gb.bearings.size(); ++i)
        if (gb.bearings[i].shaft == shaft && gb.bearings[i].under_gear < 0) out.push_back(static_cast<int>(i));
    return out;
}

// A shaft's diameter: given, else the largest bore of its support bearings (the shaft between
// them is at least as thick as its thickest seat); 0 without support bearings.
double shaft_diameter(const Gearbox& gb, int s) {
    if (gb.shafts[s].diameter) return *gb.shafts[s].diameter;
    double bore = 0;
    for (int i : support_bearings(gb, s)) bore = std::max(bore, gb.bearings[i].spec.d);
    return bore;
}

}  // namespace

// Mass of one gear [kg]. The toothed layer between root and tip circles is about half metal
// (tooth and space of equal width at the reference circle, ISO 53 basic rack), so the gear
// weighs as a solid disc of the root-mean-square of its tip and root diameters,
// d_eq = sqrt((d_a^2 + d_f^2) / 2), over its face width, less its bore. The bore is the
// gear's `bore`, else the outer diameter of the bearings a free gear or planet turns on,
// else, for a gear fixed to its shaft, the shaft's diameter (the shaft through it is counted
// with the shaft) when that is inside the root circle; a gear as thick as its shaft or
// thinner (a pinion cut on it, or a shaft whose diameter is taken from the bores of a
// carrier's bearings) is taken solid. An internal gear is a rim of 3 m_n (assumed) outside
// its root circle plus its teeth.
double gear_mass(const Gearbox& gb, const Layout& L, int g) {
    const Gear& gear = gb.gears[g];
    if (gear.mass) return *gear.mass;
    const auto& spec = gear.spec;
    double da = spec.d() + 2 * spec.mn * (spec.ha_star + spec.x), df = spec.d() - 2 * spec.mn * (spec.hf_star - spec.x);
    for (size_t m = 0; m < gb.meshes.size(); ++m)
        for (int s = 0; s < 2; ++s)
            if (gb.meshes[m].gear[s] == g) {
                da = L.meshes[m].geom.da[s];
                df = L.meshes[m].geom.df[s];
            }
    const double d_eq2 = 0.5 * (da * da + df * df);
    const double area = std::numbers::pi / 4 * spec.b;  // times a difference of squared diameters
    if (spec.internal) {
        const double d_rim = df + 2 * 3.0 * spec.mn;
        return spec.material.density * area * (d_rim * d_rim - d_eq2);
    }
    double bore = 0;
    if (gear.bore) bore = *gear.bore;
    else if (gear.free || gear.is_planet())
        for (const Bearing& br : gb.bearings)
            if (br.under_gear == g) bore = std::max(bore, br.spec.D);
    if (!gear.bore && !gear.free && !gear.is_planet()) {
        const double shaft = shaft_diameter(gb, gear.shaft);
        if (shaft < df) bore = shaft;
    }
    if (bore >= da)
        throw TopologyError(fmt::format("gear '{}': its bore ({:.1f} mm{}) is not inside its tip circle ({:.1f} mm)", spec.name,
                                        bore * 1e3, gear.bore ? "" : ", the outer diameter of the bearings under it",
                                        da * 1e3),
                            "gears", spec.name, gear.bore ? "bore" : "");
    // A bore beyond the root circle leaves only part of the teeth (half metal).
    const double metal = bore <= df ? d_eq2 - bore * bore : 0.5 * (da * da - bore * bore);
    return spec.material.density * area * metal;
}

namespace {

// Mass of a shaft [kg] and the axial position of its centre of mass [m]: a solid cylinder of
// its diameter (shaft_diameter) over its length (else the span of its support
// bearings, or the widest bearing when they share one position), centred on that span.
// Gears, carrier plates and hubs are not part of it (an explicit `mass` includes them).
std::pair<double, double> shaft_mass_at(const Gearbox& gb, int s) {
    const Shaft& shaft = gb.shafts[s];
    const auto ids = support_bearings(gb, s);
    if (ids.empty()) return {0.0, 0.0};  // no bearing carries it
    double zmin = 1e300, zmax = -1e300, width = 0;
    for (int i : ids) {
        zmin = std::min(zmin, gb.bearings[i].position);
        zmax = std::max(zmax, gb.bearings[i].position);
        width = std::max(width, gb.bearings[i].spec.B);
    }
    const double centre = 0.5 * (zmin + zmax);
    if (shaft.mass) return {*shaft.mass, centre};
    const double d = shaft_diameter(gb, s);
    const double length = shaft.length.value_or(zmax > zmin ? zmax - zmin : width);
    return {shaft.density * std::numbers::pi / 4 * d * d * length, centre};
}

}  // namespace

double shaft_mass(const Gearbox& gb, int s) { return shaft_mass_at(gb, s).first; }

// Bearing reactions to the weights of gears and shafts (gravity direction gb.gravity):
// the same statics as the mesh forces. A planet's own bearings take its weight, which turns
// with the carrier: its magnitude per bearing, combined in Layout::bearing_load.
void weight_reactions(const Gearbox& gb, Layout& L) {
    const size_t nbr = gb.bearings.size();
    const Vec3 down = gb.gravity.normalized();
    std::vector<std::vector<GearLoad>> loads(gb.gears.size());
    for (size_t g = 0; g < gb.gears.size(); ++g) {
        const Gear& gear = gb.gears[g];
        GearLoad gl;
        gl.F = L.gear_mass[g] * g_n * (gear.is_planet() ? gear.planets : 1) * down;
        gl.r.z() = gear.position;
        loads[g].push_back(gl);
    }
    Reactions W{std::vector<Eigen::Vector2d>(nbr, Eigen::Vector2d::Zero()), std::vector<double>(nbr, 0.0)};
    // Inner shafts first: a pilot bearing's reaction on its inner shaft loads its outer shaft.
    for (int s : shafts_inner_first(gb)) {
        const auto [mass, centre] = shaft_mass_at(gb, s);
        GearLoad own;
        own.F = mass * g_n * down;
        own.r.z() = centre;
        shaft_reactions(gb, s, loads, {own}, true, W);
    }
    L.bearing_R_weight = W.R;
    L.bearing_Z_weight = W.Z;
    L.bearing_W_orbiting.assign(nbr, 0.0);
    for (size_t i = 0; i < nbr; ++i) {
        const int g = gb.bearings[i].under_gear;
        if (g < 0 || !gb.gears[g].is_planet()) continue;
        int n = 0;
        for (const Bearing& o : gb.bearings) n += (o.under_gear == g);
        L.bearing_W_orbiting[i] = L.gear_mass[g] * g_n / n;
    }
}

}  // namespace detail

Layout::BearingLoad Layout::bearing_load(size_t i, double T, double omega_in) const {
    const bool neg = T < 0.0;
    const double t = std::abs(T);
    // Gear forces scale with |T| for each sense of the torque; the weights add as vectors.
    const Eigen::Vector2d R = t * (neg ? bearing_R_neg[i] : bearing_R_pos[i]) + bearing_R_weight[i];
    const double Z = t * (neg ? bearing_Z_neg[i] : bearing_Z_pos[i]) + bearing_Z_weight[i];
    // A planet's bearing: the centrifugal force (radial on the carrier) is perpendicular to the
    // planet's net mesh force (tangential), and its weight turns once per carrier revolution
    // relative to both: the root-mean-square load over a revolution adds it in quadrature.
    const double Fcf = bearing_Fcf_per_w2[i] * omega_in * omega_in;
    const double W = bearing_W_orbiting[i];
    const double Fr = (Fcf > 0.0 || W > 0.0) ? std::sqrt(R.squaredNorm() + Fcf * Fcf + W * W) : R.norm();
    return {Fr, std::abs(Z)};
}

}  // namespace gearloss::gearbox
