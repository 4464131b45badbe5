#include "gearloss/gearbox/gearbox.hpp"

#include <Eigen/Dense>
#include <Eigen/Geometry>
#include <cmath>
#include <fmt/format.h>
#include <map>
#include <numbers>
#include <set>

#include "gearloss/gearbox/statics.hpp"
#include "gearloss/mesh/loss_factor.hpp"

namespace gearloss::gearbox {

using detail::GearLoad;
using detail::Reactions;
using detail::Vec3;

namespace {

// Rotating bodies: a shaft with the gears fixed to it, a free gear, or a planet
// (one body for the N identical planets of a set).
int assign_bodies(const Gearbox& gb, Layout& L) {
    L.body_of_shaft.resize(gb.shafts.size());
    for (size_t s = 0; s < gb.shafts.size(); ++s) L.body_of_shaft[s] = static_cast<int>(s);
    int next = static_cast<int>(gb.shafts.size());
    L.body_of_gear.resize(gb.gears.size());
    std::set<int> engaged(gb.engaged.begin(), gb.engaged.end());
    for (size_t g = 0; g < gb.gears.size(); ++g) {
        const Gear& gear = gb.gears[g];
        const bool own_body = gear.is_planet() || (gear.free && !engaged.count(static_cast<int>(g)));
        L.body_of_gear[g] = own_body ? next++ : L.body_of_shaft[gear.shaft];
    }
    return next;
}

std::string body_name(const Gearbox& gb, const Layout& L, int b) {
    for (size_t s = 0; s < gb.shafts.size(); ++s)
        if (L.body_of_shaft[s] == b) return "shaft '" + gb.shafts[s].name + "'";
    for (size_t g = 0; g < gb.gears.size(); ++g)
        if (L.body_of_gear[g] == b) return "gear '" + gb.gears[g].spec.name + "'";
    return "?";
}

// Pitch-line constraint of every mesh, relative to its carrier (ISO 21771; Willis 1841):
//   r_w0 (w_A - w_C) + s r_w1 (w_B - w_C) = 0,  s = +1 external, -1 internal.
// Rows of J; the same rows, transposed, map the tangential mesh forces
// (Lagrange multipliers) to body torques.
Eigen::MatrixXd constraint_matrix(const Gearbox& gb, const Layout& L, int nb) {
    Eigen::MatrixXd J = Eigen::MatrixXd::Zero(static_cast<long>(gb.meshes.size()), nb);
    for (size_t m = 0; m < gb.meshes.size(); ++m) {
        const auto& md = L.meshes[m];
        const double r0 = 0.5 * md.geom.dw[0], r1 = 0.5 * md.geom.dw[1], s = md.geom.sign;
        const int A = L.body_of_gear[gb.meshes[m].gear[0]], B = L.body_of_gear[gb.meshes[m].gear[1]];
        J(static_cast<long>(m), A) += r0;
        J(static_cast<long>(m), B) += s * r1;
        if (md.carrier_body >= 0) J(static_cast<long>(m), md.carrier_body) -= r0 + s * r1;
    }
    return J;
}

// Speeds of all bodies per unit input speed: the mesh constraints, the fixed
// members and the input speed; the train must have exactly one degree of freedom.
void solve_kinematics(const Gearbox& gb, Layout& L, int nb, const Eigen::MatrixXd& J) {
    std::vector<int> fixed;
    for (size_t s = 0; s < gb.shafts.size(); ++s)
        if (gb.shafts[s].fixed) fixed.push_back(L.body_of_shaft[s]);
    const int bin = L.body_of_shaft[gb.input_shaft];
    const long nm = J.rows(), nf = static_cast<long>(fixed.size());
    Eigen::MatrixXd H(nm + nf, nb);  // homogeneous constraints
    H.topRows(nm) = J;
    for (long i = 0; i < nf; ++i) {
        H.row(nm + i).setZero();
        H(nm + i, fixed[static_cast<size_t>(i)]) = 1.0;
    }
    Eigen::FullPivLU<Eigen::MatrixXd> lu(H);
    lu.setThreshold(1e-10);
    const long dof = nb - lu.rank();
    if (dof == 0)
        throw TopologyError("the gear train is locked: no motion satisfies all meshes and fixed members together "
                            "(check which free gears are engaged and which members are fixed)");
    // Solve with the input speed added; a consistent, unique solution is required.
    Eigen::MatrixXd A(nm + nf + 1, nb);
    A.topRows(nm + nf) = H;
    A.row(nm + nf).setZero();
    A(nm + nf, bin) = 1.0;
    Eigen::VectorXd rhs = Eigen::VectorXd::Zero(nm + nf + 1);
    rhs(nm + nf) = 1.0;
    Eigen::FullPivLU<Eigen::MatrixXd> lu2(A);
    lu2.setThreshold(1e-10);
    if (lu2.rank() < nb) {
        // More than one degree of freedom: name a body whose speed is not determined.
        const Eigen::MatrixXd ker = Eigen::FullPivLU<Eigen::MatrixXd>(A).kernel();
        int worst = 0;
        for (int b = 0; b < nb; ++b)
            if (std::abs(ker(b, 0)) > std::abs(ker(worst, 0))) worst = b;
        throw TopologyError(fmt::format(
            "not a single-degree-of-freedom train: the speed of {} is not fixed by the input (a planetary stage needs one "
            "member fixed or driven; a gear may be connected to nothing)",
            body_name(gb, L, worst)));
    }
    const Eigen::VectorXd w = lu2.solve(rhs);
    if ((A * w - rhs).norm() > 1e-8)
        throw TopologyError("the gear train is locked: the input cannot turn (the meshes and fixed members contradict each other)");
    L.body_speed_ratio.assign(w.data(), w.data() + nb);
}

// Tangential mesh forces per N m of input torque: J^T lambda + torque_in e_in
// + torque_out e_out + sum reactions e_fixed = 0 for every body.
void solve_forces(const Gearbox& gb, Layout& L, int nb, const Eigen::MatrixXd& J) {
    std::vector<int> react;  // bodies taking an external torque besides the input
    react.push_back(L.body_of_shaft[gb.output_shaft]);
    for (size_t s = 0; s < gb.shafts.size(); ++s)
        if (gb.shafts[s].fixed) react.push_back(L.body_of_shaft[s]);
    const long nm = J.rows(), nr = static_cast<long>(react.size());
    Eigen::MatrixXd A(nb, nm + nr);
    A.leftCols(nm) = J.transpose();
    A.rightCols(nr).setZero();
    for (long k = 0; k < nr; ++k) A(react[static_cast<size_t>(k)], nm + k) = 1.0;
    Eigen::VectorXd rhs = Eigen::VectorXd::Zero(nb);
    rhs(L.body_of_shaft[gb.input_shaft]) = -1.0;
    Eigen::ColPivHouseholderQR<Eigen::MatrixXd> qr(A);
    qr.setThreshold(1e-10);
    if (qr.rank() < nm + nr)
        throw TopologyError("the power can split between parallel gear paths, so the mesh forces are statically "
                            "indeterminate; disengage one path");
    const Eigen::VectorXd x = qr.solve(rhs);
    if ((A * x - rhs).norm() > 1e-8 * std::max(1.0, rhs.norm()))
        throw TopologyError("no static equilibrium: the input torque cannot be reacted (is the output connected?)");
    L.output_torque_per_Nm = x(nm);
    for (long m = 0; m < nm; ++m) {
        auto& md = L.meshes[static_cast<size_t>(m)];
        md.force_per_Nm = x(m);
        const int A0 = L.body_of_gear[gb.meshes[static_cast<size_t>(m)].gear[0]];
        const double wc = md.carrier_body >= 0 ? L.body_speed_ratio[md.carrier_body] : 0.0;
        md.relative_speed = L.body_speed_ratio[A0] - wc;
        md.rolling_per_W = std::abs(x(m) * 0.5 * md.geom.dw[0] * md.relative_speed);
        md.loaded = std::abs(x(m)) > 1e-9;
    }
}

void place_shafts(const Gearbox& gb, Layout& L) {
    const size_t ns = gb.shafts.size();
    L.shaft_centre.assign(ns, Eigen::Vector2d(std::nan(""), std::nan("")));
    L.shaft_centre[gb.input_shaft] = Eigen::Vector2d::Zero();
    std::vector<int> placed_by(ns, -1);
    // Members of a planetary set (sun, ring, carrier) share one axis.
    auto shaft_of = [&](int g) {
        const Gear& gear = gb.gears[g];
        return gear.is_planet() ? gear.carrier : gear.shaft;
    };
    // A mesh whose angle or centre distance is not a finite number would place a shaft at NaN,
    // which reads as "not placed" and kept the loop below going for ever.
    for (size_t m = 0; m < gb.meshes.size(); ++m) {
        if (!std::isfinite(gb.meshes[m].angle))
            throw TopologyError(fmt::format("mesh '{}': angle is not a finite number", gb.meshes[m].name), "meshes",
                                gb.meshes[m].name, "angle");
        if (L.meshes[m].carrier_body < 0 && !std::isfinite(L.meshes[m].geom.a_w))
            throw TopologyError(fmt::format("mesh '{}': centre distance is not a finite number", gb.meshes[m].name),
                                "meshes", gb.meshes[m].name, "centre_distance");
    }
    // Each pass places at least one more shaft or ends: at most one pass per shaft (plus the last).
    bool progress = true;
    for (size_t pass = 0; progress; ++pass) {
        if (pass > ns) throw TopologyError("shaft placement did not finish (a mesh places a shaft at no finite position)");
        progress = false;
        for (size_t m = 0; m < gb.meshes.size(); ++m) {
            const Mesh& mesh = gb.meshes[m];
            const int s0 = shaft_of(mesh.gear[0]), s1 = shaft_of(mesh.gear[1]);
            const bool planetary = L.meshes[m].carrier_body >= 0;
            const Eigen::Vector2d e(std::cos(mesh.angle), std::sin(mesh.angle));
            const double aw = planetary ? 0.0 : L.meshes[m].geom.a_w;
            const bool k0 = !std::isnan(L.shaft_centre[s0].x()), k1 = !std::isnan(L.shaft_centre[s1].x());
            if (k0 && !k1) {
                L.shaft_centre[s1] = L.shaft_centre[s0] + aw * e;
                placed_by[s1] = static_cast<int>(m);
                progress = true;
            } else if (!k0 && k1) {
                L.shaft_centre[s0] = L.shaft_centre[s1] - aw * e;
                placed_by[s0] = static_cast<int>(m);
                progress = true;
            } else if (k0 && k1 && s0 != s1 && placed_by[s1] != static_cast<int>(m) && placed_by[s0] != static_cast<int>(m)) {
                const Eigen::Vector2d want = L.shaft_centre[s0] + aw * e;
                const double gap = (want - L.shaft_centre[s1]).norm();
                if (gap > 1e-4)
                    throw TopologyError(fmt::format(
                        "mesh '{}' does not fit: shafts '{}' and '{}' are already placed {:.3f} mm from where its centre "
                        "distance ({:.3f} mm) and angle put them; give the meshes between these shafts the same "
                        "centre_distance and angle",
                        mesh.name, gb.shafts[s0].name, gb.shafts[s1].name, gap * 1e3, aw * 1e3),
                        "meshes", mesh.name, "angle");
            }
        }
    }
    for (size_t s = 0; s < ns; ++s)
        if (std::isnan(L.shaft_centre[s].x())) L.shaft_centre[s] = Eigen::Vector2d::Zero();
}

// Forces of every loaded mesh on its two gears for an input torque of +1 or -1 N m.
// Tangential component from the mesh force lambda (torque on the body = lambda r_w
// for gear 0, s lambda r_w for gear 1), radial separating force F_t tan(alpha_wt),
// axial from the helix. Forces on a planet are those of all N planets together;
// on sun and ring the transverse forces of equally spaced planets cancel.
std::vector<std::vector<GearLoad>> gear_forces(const Gearbox& gb, const Layout& L, double T_in) {
    std::vector<std::vector<GearLoad>> out(gb.gears.size());
    const Vec3 z(0, 0, 1);
    for (size_t m = 0; m < gb.meshes.size(); ++m) {
        const auto& md = L.meshes[m];
        if (!md.loaded) continue;
        const Mesh& mesh = gb.meshes[m];
        const double lam = md.force_per_Nm * T_in;
        const double s = md.geom.sign;
        const bool planetary = md.carrier_body >= 0;
        // Planetary sets are laid out with the planet on +x: sun -> planet along +x, planet -> ring along -x.
        Vec3 e(std::cos(mesh.angle), std::sin(mesh.angle), 0.0);
        if (planetary) {
            const bool g0_planet = gb.gears[mesh.gear[0]].is_planet();
            e = g0_planet ? Vec3(-1, 0, 0) : Vec3(1, 0, 0);
        }
        const double rw0 = 0.5 * md.geom.dw[0], rw1 = 0.5 * md.geom.dw[1];
        const double Fr = std::abs(lam) * std::tan(md.geom.alpha_wt);
        const double ax = std::tan(md.geom.beta_b) / std::cos(md.geom.alpha_wt);
        // Contact point relative to each gear centre: external +r0 e / -r1 e;
        // internal (gear 1 a ring around gear 0): -r0 e / -r1 e.
        const Vec3 rel0 = (s > 0 ? 1.0 : -1.0) * rw0 * e, rel1 = -rw1 * e;
        const struct {
            int g;
            double Ftan;
            Vec3 rel;
            double sep;  // separating force direction along e
        } sides[2] = {{mesh.gear[0], lam, rel0, s > 0 ? -1.0 : 1.0}, {mesh.gear[1], s * lam, rel1, s > 0 ? 1.0 : -1.0}};
        for (const auto& sd : sides) {
            const Gear& gear = gb.gears[sd.g];
            const Vec3 et = z.cross(sd.rel).normalized();
            const auto& spec = gear.spec;
            const double hand = spec.hand == geometry::Hand::right ? 1.0 : spec.hand == geometry::Hand::left ? -1.0 : 0.0;
            GearLoad gl;
            const bool cancels = planetary && !gear.is_planet() && md.planets >= 2;
            if (!cancels) gl.F = sd.Ftan * et + sd.sep * Fr * e;
            gl.F.z() = -hand * sd.Ftan * ax;
            gl.r = cancels ? Vec3::Zero() : sd.rel;
            gl.r.z() = gear.position;
            out[sd.g].push_back(gl);
        }
    }
    return out;
}

}  // namespace

// Reactions on one shaft with at most two support positions (statically determinate): the
// radial reaction vector (housing frame) and the signed axial reaction of each bearing.
// `weights`: the loads are weights, not mesh forces: the planets' weights add on the carrier
// (they do not cancel like their mesh forces), a planet's own bearings are left to
// weight_reactions, and one support position takes a weight whole (its bearings take the moment).
void detail::shaft_reactions(const Gearbox& gb, int shaft, const std::vector<std::vector<GearLoad>>& loads,
                             const std::vector<GearLoad>& shaft_loads, bool weights, Reactions& out) {
    std::vector<GearLoad> on_shaft = shaft_loads;
    for (size_t g = 0; g < gb.gears.size(); ++g) {
        const Gear& gear = gb.gears[g];
        if (gear.is_planet()) {
            // N planets on the carrier: their mesh forces on the carrier's axis cancel
            // transversally; their axial forces (and their weights) add.
            if (gear.carrier != shaft) continue;
            if (gear.planets < 2 || weights) {
                for (const auto& gl : loads[g]) on_shaft.push_back(gl);
                continue;
            }
            GearLoad sum;
            for (const auto& gl : loads[g]) sum.F.z() += gl.F.z();
            sum.r.z() = gear.position;
            on_shaft.push_back(sum);
            continue;
        }
        if (gear.shaft == shaft)
            for (const auto& gl : loads[g]) on_shaft.push_back(gl);
    }
    // Pilot bearings whose outer ring is in this shaft: the reaction a pilot puts on its inner
    // shaft (already solved, shafts_inner_first) acts on this one with the opposite sign
    // (Newton's third law), on the common axis at the pilot's place along this shaft.
    for (size_t i = 0; i < gb.bearings.size(); ++i) {
        const Bearing& br = gb.bearings[i];
        if (br.outer_shaft != shaft) continue;
        GearLoad pilot;
        pilot.F = Vec3(-out.R[i].x(), -out.R[i].y(), -out.Z[i]);
        pilot.r.z() = br.outer_position;
        on_shaft.push_back(pilot);
    }
    // Bearings between a free or planet gear and its shaft/carrier carry that gear's
    // transverse load (per planet for a planet set).
    for (size_t i = 0; i < gb.bearings.size(); ++i) {
        const Bearing& br = gb.bearings[i];
        if (br.shaft != shaft || br.under_gear < 0) continue;
        const Gear& gear = gb.gears[br.under_gear];
        if (weights && gear.is_planet()) continue;
        Vec3 sum = Vec3::Zero();
        for (const auto& gl : loads[br.under_gear]) sum += gl.F;
        int n = 0;
        for (const Bearing& o : gb.bearings) n += (o.under_gear == br.under_gear);
        // The reaction of the bearing on the gear: minus the load it takes from the gear.
        out.R[i] = -sum.head<2>() / n / (gear.is_planet() ? gear.planets : 1);
        out.Z[i] = 0.0;  // thrust washers take the gear's axial force
    }
    std::map<double, std::vector<int>> supports;
    for (size_t i = 0; i < gb.bearings.size(); ++i)
        if (gb.bearings[i].shaft == shaft && gb.bearings[i].under_gear < 0)
            supports[gb.bearings[i].position].push_back(static_cast<int>(i));
    Vec3 Fsum = Vec3::Zero();
    for (const auto& gl : on_shaft) Fsum += gl.F;
    // A shaft described without bearings has no bearing loss to compute.
    if (supports.empty()) return;
    // The shaft's support bearings by name, for messages.
    std::string names;
    for (const auto& [pos, ids] : supports)
        for (int i : ids) names += (names.empty() ? "" : ", ") + gb.bearings[i].name;
    const std::string first = gb.bearings[supports.begin()->second.front()].name;
    if (supports.size() > 2)
        throw TopologyError(fmt::format(
            "shaft '{}' has bearings at {} axial positions ({}); gearloss solves statically determinate shafts (two support "
            "positions; paired bearings share one position)",
            gb.shafts[shaft].name, supports.size(), names), "bearings", first, "position");
    if (!weights && supports.size() == 1 && Fsum.head<2>().norm() > 1e-12)
        throw TopologyError(fmt::format("shaft '{}' carries radial gear forces but has bearings at one axial position only ({})",
                                        gb.shafts[shaft].name, names), "bearings", first, "position");
    const double zA = supports.begin()->first;
    Eigen::Vector2d RA = -Fsum.head<2>(), RB(0, 0);
    if (supports.size() == 2) {
        // Lever rule: moment balance about support A gives B's reaction, force balance A's.
        const double zB = std::next(supports.begin())->first;
        const double Lab = zB - zA;
        double Mx = 0, My = 0;
        for (const auto& gl : on_shaft) {
            const Vec3 r(gl.r.x(), gl.r.y(), gl.r.z() - zA);
            const Vec3 M = r.cross(gl.F);
            Mx += M.x();
            My += M.y();
        }
        RB = Eigen::Vector2d(-My / Lab, Mx / Lab);  // (0,0,L) x (Rx,Ry,0) = (-L Ry, L Rx, 0)
        RA = -Fsum.head<2>() - RB;
    }
    auto distribute = [&](const std::vector<int>& ids, const Eigen::Vector2d& R) {
        for (int i : ids) out.R[i] = R / static_cast<double>(ids.size());
    };
    distribute(supports.begin()->second, RA);
    if (supports.size() == 2) distribute(std::next(supports.begin())->second, RB);
    std::vector<int> loc;
    for (const auto& [pos, ids] : supports)
        for (int i : ids)
            if (gb.bearings[i].locating) loc.push_back(i);
    if (std::abs(Fsum.z()) > 1e-9) {
        if (loc.empty())
            throw TopologyError(
                weights ? fmt::format("shaft '{}': housing.gravity has a component along the shafts, so the weights load it "
                                      "axially, but no bearing on it is marked 'locating: true' (its bearings: {})",
                                      gb.shafts[shaft].name, names)
                        : fmt::format("shaft '{}' carries an axial gear force but no bearing on it is marked 'locating: "
                                      "true' (its bearings: {})",
                                      gb.shafts[shaft].name, names),
                "bearings", first, "locating");
        for (int i : loc) out.Z[i] = -Fsum.z() / static_cast<double>(loc.size());
    }
}

// The shafts in an order where every pilot bearing's inner shaft comes before its outer shaft
// (the outer shaft takes the pilot's reaction); a cycle of pilot bearings has no such order.
std::vector<int> detail::shafts_inner_first(const Gearbox& gb) {
    const size_t ns = gb.shafts.size();
    std::vector<int> pending(ns, 0), order;  // pending: pilots in this shaft whose inner shaft is not yet placed
    for (const Bearing& br : gb.bearings)
        if (br.outer_shaft >= 0) ++pending[br.outer_shaft];
    std::vector<bool> placed(ns, false);
    for (bool progress = true; progress;) {
        progress = false;
        for (size_t s = 0; s < ns; ++s) {
            if (placed[s] || pending[s] > 0) continue;
            placed[s] = true;
            order.push_back(static_cast<int>(s));
            for (const Bearing& br : gb.bearings)
                if (br.outer_shaft >= 0 && br.shaft == static_cast<int>(s)) --pending[br.outer_shaft];
            progress = true;
        }
    }
    if (order.size() < ns)
        for (const Bearing& br : gb.bearings)
            if (br.outer_shaft >= 0 && !placed[br.shaft] && !placed[br.outer_shaft])
                throw TopologyError(fmt::format("bearing '{}': pilot bearings form a cycle (shaft '{}' runs in shaft '{}', "
                                                "which runs, through other pilots, in '{}'); one of them must be in the housing",
                                                br.name, gb.shafts[br.shaft].name, gb.shafts[br.outer_shaft].name,
                                                gb.shafts[br.shaft].name),
                                    "bearings", br.name, "outer_shaft");
    return order;
}

Layout analyse(const Gearbox& gb) {
    Layout L;
    if (gb.input_shaft < 0 || gb.output_shaft < 0) throw TopologyError("input and output shafts must be named");
    if (gb.input_shaft == gb.output_shaft) throw TopologyError("input and output shafts are the same shaft");
    if (gb.shafts[gb.input_shaft].fixed || gb.shafts[gb.output_shaft].fixed)
        throw TopologyError("the input and output shafts cannot be fixed to the housing");
    const int nb = assign_bodies(gb, L);
    L.meshes.resize(gb.meshes.size());
    for (size_t m = 0; m < gb.meshes.size(); ++m) {
        const Mesh& mesh = gb.meshes[m];
        const Gear& G0 = gb.gears[mesh.gear[0]];
        const Gear& G1 = gb.gears[mesh.gear[1]];
        if (!G0.is_planet() && !G1.is_planet() && G0.shaft == G1.shaft)
            throw TopologyError(fmt::format("mesh '{}': both gears sit on shaft '{}'", mesh.name, gb.shafts[G0.shaft].name),
                                "meshes", mesh.name, "gears");
        auto& md = L.meshes[m];
        if (G0.is_planet() || G1.is_planet()) {
            const int c0 = G0.is_planet() ? G0.carrier : -1, c1 = G1.is_planet() ? G1.carrier : -1;
            if (c0 >= 0 && c1 >= 0 && c0 != c1)
                throw TopologyError(fmt::format("mesh '{}': the two planets sit on different carriers", mesh.name), "meshes",
                                    mesh.name, "gears");
            const int c = c0 >= 0 ? c0 : c1;
            md.carrier_body = L.body_of_shaft[c];
            md.planets = std::max(G0.planets, G1.planets);
        }
        try {
            md.geom = geometry::pair_geometry(G0.spec, G1.spec, mesh.centre_distance);
            md.H_V_ohlendorf = mesh::loss_factor_ohlendorf(md.geom, G0.spec.z);
            md.H_V_buckingham = mesh::loss_factor_buckingham(md.geom, G0.spec.z);
            const auto sweep = mesh::sweep_contact_lines(md.geom);
            md.H_V_wimmer = sweep.H_V;
            md.L_min = sweep.L_min;
            md.L_mean = sweep.L_mean;
        } catch (const geometry::GeometryError& e) {
            throw TopologyError(fmt::format("mesh '{}': {}", mesh.name, e.message), "meshes", mesh.name, e.key);
        }
    }
    // Planetary sets: every planet's meshes share one planet centre distance, and
    // equally spaced planets need (z_sun + z_ring)/N to be a whole number.
    for (size_t g = 0; g < gb.gears.size(); ++g) {
        const Gear& pl = gb.gears[g];
        if (!pl.is_planet()) continue;
        double aw = -1;
        int z_sum = 0;
        for (size_t m = 0; m < gb.meshes.size(); ++m)
            for (int sd = 0; sd < 2; ++sd)
                if (gb.meshes[m].gear[sd] == static_cast<int>(g)) {
                    const Gear& other = gb.gears[gb.meshes[m].gear[1 - sd]];
                    if (other.is_planet()) continue;
                    const double a = L.meshes[m].geom.a_w;
                    if (aw >= 0 && std::abs(a - aw) > 1e-4)
                        throw TopologyError(fmt::format(
                            "planet '{}': its meshes have different centre distances ({:.3f} and {:.3f} mm); sun, ring and "
                            "carrier must be coaxial (adjust the profile shifts or give the same centre_distance)",
                            pl.spec.name, aw * 1e3, a * 1e3));
                    aw = a;
                    z_sum += other.spec.z;
                }
        if (pl.planets >= 2 && z_sum > 0 && z_sum % pl.planets != 0)
            throw TopologyError(fmt::format("planet '{}': {} planets cannot be equally spaced ((z_sun + z_ring) = {} is not "
                                            "a multiple of {})",
                                            pl.spec.name, pl.planets, z_sum, pl.planets));
    }
    const Eigen::MatrixXd J = constraint_matrix(gb, L, nb);
    solve_kinematics(gb, L, nb, J);
    L.ratio = L.body_speed_ratio[L.body_of_shaft[gb.output_shaft]];
    solve_forces(gb, L, nb, J);
    place_shafts(gb, L);
    // Immersion of each gear.
    L.gear_immersion.assign(gb.gears.size(), 0.0);
    for (size_t g = 0; g < gb.gears.size(); ++g) {
        const Gear& gear = gb.gears[g];
        if (gear.immersion) {
            L.gear_immersion[g] = std::max(0.0, *gear.immersion);
        } else if (gb.oil_level && !gear.is_planet()) {
            double ra = 0.5 * gear.spec.d() + gear.spec.mn * (gear.spec.ha_star + gear.spec.x);
            for (size_t m = 0; m < gb.meshes.size(); ++m)
                for (int s = 0; s < 2; ++s)
                    if (gb.meshes[m].gear[s] == static_cast<int>(g)) ra = 0.5 * L.meshes[m].geom.da[s];
            // (An internal gear reaches down to its root circle; ring gears are given an explicit immersion.)
            if (gear.spec.internal) continue;
            const double lowest = L.shaft_centre[gear.shaft].y() - ra;
            L.gear_immersion[g] = std::max(0.0, *gb.oil_level - lowest);
        }
    }
    L.gear_mass.resize(gb.gears.size());
    for (size_t g = 0; g < gb.gears.size(); ++g) L.gear_mass[g] = detail::gear_mass(gb, L, static_cast<int>(g));
    L.shaft_mass.resize(gb.shafts.size());
    for (size_t s = 0; s < gb.shafts.size(); ++s) L.shaft_mass[s] = detail::shaft_mass(gb, static_cast<int>(s));
    // Ring speeds of bearings and seals.
    L.bearing_speed_ratio.resize(gb.bearings.size());
    L.bearing_Fcf_per_w2.assign(gb.bearings.size(), 0.0);
    for (size_t i = 0; i < gb.bearings.size(); ++i) {
        const Bearing& br = gb.bearings[i];
        const double ws = L.body_speed_ratio[L.body_of_shaft[br.shaft]];
        if (br.under_gear >= 0) {
            const Gear& gear = gb.gears[br.under_gear];
            const double wg = L.body_speed_ratio[L.body_of_gear[br.under_gear]];
            L.bearing_speed_ratio[i] = std::abs(wg - ws);
            if (gear.is_planet()) {
                // Centrifugal force of one planet (its mass, gear_mass) on its bearings:
                // m omega_c^2 a, shared by the bearings under it.
                double a = 0;
                for (size_t m = 0; m < gb.meshes.size(); ++m)
                    if (gb.meshes[m].gear[0] == br.under_gear || gb.meshes[m].gear[1] == br.under_gear) a = L.meshes[m].geom.a_w;
                const double mass = L.gear_mass[br.under_gear];
                int n = 0;
                for (const Bearing& o : gb.bearings) n += (o.under_gear == br.under_gear);
                L.bearing_Fcf_per_w2[i] = mass * ws * ws * a / n;
            }
        } else if (br.outer_shaft >= 0) {
            // A pilot bearing: its rings turn with two shafts, at the difference of their speeds.
            L.bearing_speed_ratio[i] = std::abs(ws - L.body_speed_ratio[L.body_of_shaft[br.outer_shaft]]);
        } else {
            L.bearing_speed_ratio[i] = std::abs(ws);
        }
    }
    L.clutch_slip_ratio.resize(gb.clutches.size());
    for (size_t i = 0; i < gb.clutches.size(); ++i) {
        const int g = gb.clutches[i].gear;
        L.clutch_slip_ratio[i] = std::abs(L.body_speed_ratio[L.body_of_gear[g]] -
                                          L.body_speed_ratio[L.body_of_shaft[gb.gears[g].shaft]]);
    }
    L.seal_speed_ratio.resize(gb.seals.size());
    for (size_t i = 0; i < gb.seals.size(); ++i)
        L.seal_speed_ratio[i] = std::abs(L.body_speed_ratio[L.body_of_shaft[gb.seals[i].shaft]]);
    // Unit bearing loads for +1 and -1 N m.
    const size_t nbr = gb.bearings.size();
    for (double sign : {+1.0, -1.0}) {
        const auto loads = gear_forces(gb, L, sign);
        Reactions R{std::vector<Eigen::Vector2d>(nbr, Eigen::Vector2d::Zero()), std::vector<double>(nbr, 0.0)};
        for (int s : detail::shafts_inner_first(gb)) detail::shaft_reactions(gb, s, loads, {}, false, R);
        std::vector<double> Fr(nbr), Fa(nbr);
        for (size_t i = 0; i < nbr; ++i) {
            Fr[i] = R.R[i].norm();
            Fa[i] = std::abs(R.Z[i]);
        }
        (sign > 0 ? L.bearing_R_pos : L.bearing_R_neg) = R.R;
        (sign > 0 ? L.bearing_Z_pos : L.bearing_Z_neg) = R.Z;
        (sign > 0 ? L.bearing_Fr_pos : L.bearing_Fr_neg) = Fr;
        (sign > 0 ? L.bearing_Fa_pos : L.bearing_Fa_neg) = Fa;
    }
    detail::weight_reactions(gb, L);
    return L;
}

}  // namespace gearloss::gearbox
