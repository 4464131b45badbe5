#include "gearbox/gearbox.hpp"

#include <Eigen/Geometry>
#include <cmath>
#include <fmt/format.h>
#include <functional>
#include <map>
#include <queue>
#include <set>

#include "mesh/loss_factor.hpp"

namespace gearloss::gearbox {

namespace {

using Vec3 = Eigen::Vector3d;

// Rotating bodies: a shaft with the gears fixed to it, or a free gear.
void assign_bodies(const Gearbox& gb, Layout& L) {
    L.body_of_shaft.resize(gb.shafts.size());
    for (size_t s = 0; s < gb.shafts.size(); ++s) L.body_of_shaft[s] = static_cast<int>(s);
    int next = static_cast<int>(gb.shafts.size());
    L.body_of_gear.resize(gb.gears.size());
    std::set<int> engaged(gb.engaged.begin(), gb.engaged.end());
    for (size_t g = 0; g < gb.gears.size(); ++g) {
        const Gear& gear = gb.gears[g];
        const bool own_body = gear.free && !engaged.count(static_cast<int>(g));
        L.body_of_gear[g] = own_body ? next++ : L.body_of_shaft[gear.shaft];
    }
    L.body_speed_ratio.assign(static_cast<size_t>(next), std::nan(""));
}

// Speeds from the input by breadth-first search over the meshes; a loop must
// close with the same speed, and the meshes must form a tree for the torque
// path to be defined.
void solve_kinematics(const Gearbox& gb, Layout& L, std::vector<std::pair<int, int>>& parent) {
    const size_t nb = L.body_speed_ratio.size();
    parent.assign(nb, {-1, -1});  // (mesh, previous body)
    std::vector<std::vector<std::pair<int, int>>> adj(nb);  // body -> (mesh, side)
    for (size_t m = 0; m < gb.meshes.size(); ++m)
        for (int s = 0; s < 2; ++s) adj[L.body_of_gear[gb.meshes[m].gear[s]]].push_back({static_cast<int>(m), s});
    const int b0 = L.body_of_shaft[gb.input_shaft];
    L.body_speed_ratio[b0] = 1.0;
    std::queue<int> q;
    q.push(b0);
    std::vector<char> used(gb.meshes.size(), 0);
    while (!q.empty()) {
        const int b = q.front();
        q.pop();
        for (auto [m, side] : adj[b]) {
            if (used[m]) continue;
            used[m] = 1;
            const Mesh& mesh = gb.meshes[m];
            const auto& ga = gb.gears[mesh.gear[side]].spec;
            const auto& gbb = gb.gears[mesh.gear[1 - side]].spec;
            const int other = L.body_of_gear[mesh.gear[1 - side]];
            const double w = -L.body_speed_ratio[b] * ga.z / gbb.z;  // external mesh
            if (std::isnan(L.body_speed_ratio[other])) {
                L.body_speed_ratio[other] = w;
                parent[other] = {m, b};
                q.push(other);
            } else if (std::abs(L.body_speed_ratio[other] - w) > 1e-9 * std::abs(w)) {
                throw TopologyError(fmt::format(
                    "the gear train is locked: mesh '{}' imposes a speed on '{}' that differs from the other path "
                    "({:.6g} vs {:.6g} x input); check which free gears are engaged",
                    mesh.name, gb.gears[mesh.gear[1 - side]].spec.name, w, L.body_speed_ratio[other]));
            } else {
                throw TopologyError(fmt::format(
                    "meshes form a closed loop through '{}' (power can split between two paths, which gearloss does "
                    "not solve); disengage one path",
                    mesh.name));
            }
        }
    }
    for (size_t g = 0; g < gb.gears.size(); ++g)
        if (std::isnan(L.body_speed_ratio[L.body_of_gear[g]]))
            throw TopologyError(fmt::format("gear '{}' is not connected to the input shaft '{}', so its speed is undefined",
                                            gb.gears[g].spec.name, gb.shafts[gb.input_shaft].name));
    for (size_t s = 0; s < gb.shafts.size(); ++s)
        if (std::isnan(L.body_speed_ratio[L.body_of_shaft[s]]))
            throw TopologyError(fmt::format("shaft '{}' is not connected to the input shaft", gb.shafts[s].name));
}

void place_shafts(const Gearbox& gb, Layout& L) {
    const size_t ns = gb.shafts.size();
    L.shaft_centre.assign(ns, Eigen::Vector2d(std::nan(""), std::nan("")));
    L.shaft_centre[gb.input_shaft] = Eigen::Vector2d::Zero();
    std::vector<int> placed_by(ns, -1);
    bool progress = true;
    while (progress) {
        progress = false;
        for (size_t m = 0; m < gb.meshes.size(); ++m) {
            const Mesh& mesh = gb.meshes[m];
            const int s0 = gb.gears[mesh.gear[0]].shaft, s1 = gb.gears[mesh.gear[1]].shaft;
            const Eigen::Vector2d e(std::cos(mesh.angle), std::sin(mesh.angle));
            const double aw = L.meshes[m].geom.a_w;
            const bool k0 = !std::isnan(L.shaft_centre[s0].x()), k1 = !std::isnan(L.shaft_centre[s1].x());
            if (k0 && !k1) {
                L.shaft_centre[s1] = L.shaft_centre[s0] + aw * e;
                placed_by[s1] = static_cast<int>(m);
                progress = true;
            } else if (!k0 && k1) {
                L.shaft_centre[s0] = L.shaft_centre[s1] - aw * e;
                placed_by[s0] = static_cast<int>(m);
                progress = true;
            } else if (k0 && k1 && placed_by[s1] != static_cast<int>(m) && placed_by[s0] != static_cast<int>(m)) {
                const Eigen::Vector2d want = L.shaft_centre[s0] + aw * e;
                const double gap = (want - L.shaft_centre[s1]).norm();
                if (gap > 1e-4)
                    throw TopologyError(fmt::format(
                        "mesh '{}' does not fit: shafts '{}' and '{}' are already placed {:.3f} mm from where its centre "
                        "distance ({:.3f} mm) and angle put them; give the meshes between these shafts the same "
                        "centre_distance and angle",
                        mesh.name, gb.shafts[s0].name, gb.shafts[s1].name, gap * 1e3, aw * 1e3));
            }
        }
    }
    for (size_t s = 0; s < ns; ++s)
        if (std::isnan(L.shaft_centre[s].x())) L.shaft_centre[s] = Eigen::Vector2d::Zero();  // no mesh: on the axis
}

// Forces on every gear for an input torque of +1 or -1 N*m: gear -> (force, point relative to shaft axis).
struct GearLoad {
    Vec3 F = Vec3::Zero();
    Vec3 r = Vec3::Zero();  // application point: (x, y) from the shaft axis, z along the shaft
};

std::vector<std::vector<GearLoad>> gear_forces(const Gearbox& gb, const Layout& L, double T_in) {
    std::vector<std::vector<GearLoad>> out(gb.gears.size());
    const double omega_in = 1.0;  // forces do not depend on the speed magnitude
    const double P = T_in * omega_in;
    for (size_t m = 0; m < gb.meshes.size(); ++m) {
        const auto& md = L.meshes[m];
        if (!md.loaded) continue;
        const Mesh& mesh = gb.meshes[m];
        const int ga = mesh.gear[0], gbi = mesh.gear[1];
        const int drv = md.driver_forward;  // for P > 0
        // Power from gear 0 into gear 1 through this mesh.
        const double P01 = (drv == 0 ? P : -P);
        const double wa = L.body_speed_ratio[L.body_of_gear[ga]] * omega_in;
        const double wb = L.body_speed_ratio[L.body_of_gear[gbi]] * omega_in;
        const double Ta = -P01 / wa, Tb = P01 / wb;  // torque of the mesh on each gear
        const Vec3 e(std::cos(mesh.angle), std::sin(mesh.angle), 0.0);
        const Vec3 z(0, 0, 1);
        const double rwa = 0.5 * md.geom.dw[0], rwb = 0.5 * md.geom.dw[1];
        const double Ft = std::abs(Ta / rwa);
        const double Fr = Ft * std::tan(md.geom.alpha_wt);
        const double ax = std::tan(md.geom.beta_b) / std::cos(md.geom.alpha_wt);
        const struct {
            int g;
            double T, rw;
            Vec3 rel;
            double sep;
        } sides[2] = {{ga, Ta, rwa, rwa * e, -1.0}, {gbi, Tb, rwb, -rwb * e, +1.0}};
        for (const auto& s : sides) {
            const Vec3 et = z.cross(s.rel).normalized();
            const double Ftan = s.T / s.rw;  // component along e_theta
            const auto& spec = gb.gears[s.g].spec;
            const double hand = spec.hand == geometry::Hand::right ? 1.0 : spec.hand == geometry::Hand::left ? -1.0 : 0.0;
            GearLoad gl;
            gl.F = Ftan * et + s.sep * Fr * e;
            gl.F.z() = -hand * Ftan * ax;
            gl.r = s.rel;
            gl.r.z() = gb.gears[s.g].position;
            out[s.g].push_back(gl);
        }
    }
    return out;
}

// Reactions on one shaft with two support positions (statically determinate).
void shaft_reactions(const Gearbox& gb, int shaft, const std::vector<std::vector<GearLoad>>& loads,
                     std::vector<double>& Fr, std::vector<double>& Fa) {
    std::vector<GearLoad> on_shaft;
    for (size_t g = 0; g < gb.gears.size(); ++g)
        if (gb.gears[g].shaft == shaft)
            for (const auto& gl : loads[g]) on_shaft.push_back(gl);
    // Bearings between a free gear and the shaft carry that gear's transverse load.
    for (size_t i = 0; i < gb.bearings.size(); ++i) {
        const Bearing& br = gb.bearings[i];
        if (br.shaft != shaft || br.under_gear < 0) continue;
        Vec3 sum = Vec3::Zero();
        for (const auto& gl : loads[br.under_gear]) sum += gl.F;
        int n = 0;
        for (const Bearing& o : gb.bearings) n += (o.under_gear == br.under_gear);
        Fr[i] = std::hypot(sum.x(), sum.y()) / n;
        Fa[i] = 0.0;  // thrust washers take the free gear's axial force
    }
    std::map<double, std::vector<int>> supports;
    for (size_t i = 0; i < gb.bearings.size(); ++i)
        if (gb.bearings[i].shaft == shaft && gb.bearings[i].under_gear < 0)
            supports[gb.bearings[i].position].push_back(static_cast<int>(i));
    Vec3 Fsum = Vec3::Zero();
    for (const auto& gl : on_shaft) Fsum += gl.F;
    const bool loaded = Fsum.norm() > 0 || !on_shaft.empty();
    if (supports.empty()) {
        if (loaded && Fsum.norm() > 1e-12)
            throw TopologyError(fmt::format("shaft '{}' carries gear forces but has no bearings", gb.shafts[shaft].name));
        return;
    }
    if (supports.size() > 2)
        throw TopologyError(fmt::format(
            "shaft '{}' has bearings at {} axial positions; gearloss solves statically determinate shafts (two support "
            "positions; paired bearings share one position)",
            gb.shafts[shaft].name, supports.size()));
    if (supports.size() == 1) {
        if (Fsum.head<2>().norm() > 1e-12)
            throw TopologyError(fmt::format("shaft '{}' carries radial gear forces but has bearings at one axial position only",
                                            gb.shafts[shaft].name));
    }
    const double zA = supports.begin()->first;
    Eigen::Vector2d RA(0, 0), RB(0, 0);
    if (supports.size() == 2) {
        const double zB = std::next(supports.begin())->first;
        const double Lab = zB - zA;
        // Moment balance about support A (x and y components of r x F).
        double Mx = 0, My = 0;
        for (const auto& gl : on_shaft) {
            const Vec3 r(gl.r.x(), gl.r.y(), gl.r.z() - zA);
            const Vec3 M = r.cross(gl.F);
            Mx += M.x();
            My += M.y();
        }
        // (0,0,Lab) x (Rx, Ry, 0) = (-Lab Ry, Lab Rx, 0)
        RB = Eigen::Vector2d(-My / Lab, Mx / Lab);
        RA = -Fsum.head<2>() - RB;
    }
    auto distribute = [&](const std::vector<int>& ids, const Eigen::Vector2d& R) {
        for (int i : ids) Fr[i] = R.norm() / static_cast<double>(ids.size());
    };
    distribute(supports.begin()->second, RA);
    if (supports.size() == 2) distribute(std::next(supports.begin())->second, RB);
    std::vector<int> loc;
    for (const auto& [pos, ids] : supports)
        for (int i : ids)
            if (gb.bearings[i].locating) loc.push_back(i);
    if (std::abs(Fsum.z()) > 1e-9) {
        if (loc.empty())
            throw TopologyError(fmt::format(
                "shaft '{}' carries an axial gear force but no bearing on it is marked 'locating: true'",
                gb.shafts[shaft].name));
        for (int i : loc) Fa[i] = std::abs(Fsum.z()) / static_cast<double>(loc.size());
    }
}

}  // namespace

Layout analyse(const Gearbox& gb) {
    Layout L;
    if (gb.input_shaft < 0 || gb.output_shaft < 0) throw TopologyError("input and output shafts must be named");
    if (gb.input_shaft == gb.output_shaft) throw TopologyError("input and output shafts are the same shaft");
    L.meshes.resize(gb.meshes.size());
    for (size_t m = 0; m < gb.meshes.size(); ++m) {
        const Mesh& mesh = gb.meshes[m];
        const auto& g0 = gb.gears[mesh.gear[0]].spec;
        const auto& g1 = gb.gears[mesh.gear[1]].spec;
        if (gb.gears[mesh.gear[0]].shaft == gb.gears[mesh.gear[1]].shaft)
            throw TopologyError(fmt::format("mesh '{}': both gears sit on shaft '{}'", mesh.name,
                                            gb.shafts[gb.gears[mesh.gear[0]].shaft].name));
        try {
            auto& md = L.meshes[m];
            md.geom = geometry::pair_geometry(g0, g1, mesh.centre_distance);
            md.H_V_ohlendorf = mesh::loss_factor_ohlendorf(md.geom, g0.z);
            md.H_V_buckingham = mesh::loss_factor_buckingham(md.geom, g0.z);
            const auto sweep = mesh::sweep_contact_lines(md.geom);
            md.H_V_wimmer = sweep.H_V;
            md.L_min = sweep.L_min;
        } catch (const geometry::GeometryError& e) {
            throw TopologyError(fmt::format("mesh '{}': {}", mesh.name, e.msg));
        }
    }
    assign_bodies(gb, L);
    std::vector<std::pair<int, int>> parent;
    solve_kinematics(gb, L, parent);
    const int bin = L.body_of_shaft[gb.input_shaft], bout = L.body_of_shaft[gb.output_shaft];
    L.ratio = L.body_speed_ratio[bout];
    // Torque path: walk back from the output to the input along the BFS tree.
    for (int b = bout; b != bin;) {
        const auto [m, prev] = parent[b];
        if (m < 0) throw TopologyError("no gear path from the input shaft to the output shaft");
        auto& md = L.meshes[m];
        md.loaded = true;
        md.driver_forward = (L.body_of_gear[gb.meshes[m].gear[0]] == prev) ? 0 : 1;
        b = prev;
    }
    place_shafts(gb, L);
    // Immersion of each gear.
    L.gear_immersion.assign(gb.gears.size(), 0.0);
    for (size_t g = 0; g < gb.gears.size(); ++g) {
        const Gear& gear = gb.gears[g];
        if (gear.immersion) {
            L.gear_immersion[g] = std::max(0.0, *gear.immersion);
        } else if (gb.oil_level) {
            double ra = 0.5 * gear.spec.d() + gear.spec.mn * (gear.spec.ha_star + gear.spec.x);
            for (size_t m = 0; m < gb.meshes.size(); ++m)
                for (int s = 0; s < 2; ++s)
                    if (gb.meshes[m].gear[s] == static_cast<int>(g)) ra = 0.5 * L.meshes[m].geom.da[s];
            const double lowest = L.shaft_centre[gear.shaft].y() - ra;
            L.gear_immersion[g] = std::max(0.0, *gb.oil_level - lowest);
        }
    }
    // Ring speeds of bearings and seals.
    L.bearing_speed_ratio.resize(gb.bearings.size());
    for (size_t i = 0; i < gb.bearings.size(); ++i) {
        const Bearing& br = gb.bearings[i];
        const double ws = L.body_speed_ratio[L.body_of_shaft[br.shaft]];
        if (br.under_gear >= 0) {
            const double wg = L.body_speed_ratio[L.body_of_gear[br.under_gear]];
            L.bearing_speed_ratio[i] = std::abs(wg - ws);
        } else {
            L.bearing_speed_ratio[i] = std::abs(ws);
        }
    }
    L.seal_speed_ratio.resize(gb.seals.size());
    for (size_t i = 0; i < gb.seals.size(); ++i)
        L.seal_speed_ratio[i] = std::abs(L.body_speed_ratio[L.body_of_shaft[gb.seals[i].shaft]]);
    // Unit bearing loads for +1 and -1 N*m.
    for (double sign : {+1.0, -1.0}) {
        const auto loads = gear_forces(gb, L, sign);
        std::vector<double> Fr(gb.bearings.size(), 0.0), Fa(gb.bearings.size(), 0.0);
        for (size_t s = 0; s < gb.shafts.size(); ++s) shaft_reactions(gb, static_cast<int>(s), loads, Fr, Fa);
        (sign > 0 ? L.bearing_Fr_pos : L.bearing_Fr_neg) = Fr;
        (sign > 0 ? L.bearing_Fa_pos : L.bearing_Fa_neg) = Fa;
    }
    return L;
}

}  // namespace gearloss::gearbox
