// Contract tests: one generic check applied to every loss component (Ceres-style).
//
// A component is a loss P(n, T_oil, load) [W]; its contract states what physics says:
//   * finite and >= 0 everywhere (standstill and zero load included);
//   * zero at standstill (no relative motion, no friction power), unless stated otherwise;
//   * the sign of dP/dT_oil, dP/dn and dP/dload (load: input torque, or the radial or
//     axial force for a single bearing), each "rises", "falls", "independent" (exactly
//     unchanged) or "unchecked" with the reason written where the contract is declared.
// check_contract() walks a grid and checks all of it for any component; the component
// list below calls it for mesh friction (each mu model and the local EHL), churning,
// bearings (every bearing type), seals, wet-clutch drag, the torque converter and the
// calibration terms (windage, Palmgren drag, auxiliary).
//
// The second half checks that every fast path equals its reference path: the
// per-temperature evaluation of the solver (powers of nu shared across components,
// terms folded once per point) against the direct component formulas, the folded SKF
// form against the direct SKF moment for every bearing type, and the 3-pressure
// symmetric Hertz quadrature of the EHL contact against the plain 5-node Gauss rule.
#include <catch2/catch.hpp>
#include "loss_parts.hpp"
#include <cmath>
#include <functional>
#include <numbers>
#include <optional>
#include <string>
#include <vector>

#include "gearloss/bearings/skf_model.hpp"
#include "gearloss/churning/changenet_velex.hpp"
#include "gearloss/clutch/wet_clutch.hpp"
#include "gearloss/cycle/simulate.hpp"
#include "gearloss/case/config.hpp"
#include "gearloss/results/cycle_report.hpp"
#include "gearloss/mesh/ehl_contact.hpp"
#include "gearloss/mesh/ehl_path.hpp"
#include "gearloss/mesh/friction.hpp"
#include "gearloss/seals/radial_lip_seal.hpp"
#include "gearloss/solver/operating_point.hpp"
#include "test_support.hpp"
#include "gearloss/torque_converter/torque_converter.hpp"

using namespace gearloss;
using Approx = Catch::Detail::Approx;

namespace {
constexpr double rpm = std::numbers::pi / 30;
constexpr double degC = 273.15;

enum class Trend { rises, falls, independent, unchecked };
const char* to_string(Trend t) {
    switch (t) {
        case Trend::rises: return "rises";
        case Trend::falls: return "falls";
        case Trend::independent: return "independent";
        case Trend::unchecked: return "unchecked";
    }
    return "?";
}

struct Contract {
    std::string name;
    Trend with_temperature = Trend::falls;
    Trend with_speed = Trend::rises;
    Trend with_load = Trend::rises;
    bool zero_at_standstill = true;
};

struct Grid {
    std::vector<double> speeds_rpm;    // > 0, ascending (standstill is added by the check)
    std::vector<double> temps_K;       // ascending
    std::vector<double> loads;         // ascending (N m, or N for a single bearing)
};

using Loss = std::function<double(double n_rpm, double T_K, double load)>;

// The one check every component goes through.
void check_trend(Trend t, double before, double after, const std::string& what) {
    INFO(what << ": " << to_string(t) << ", " << before << " W -> " << after << " W");
    switch (t) {
        case Trend::rises: CHECK(after > before); break;
        case Trend::falls: CHECK(after < before); break;
        case Trend::independent: CHECK(after == Approx(before).epsilon(1e-12).margin(1e-12)); break;
        case Trend::unchecked: break;
    }
}

void check_contract(const Contract& c, const Loss& P, const Grid& g) {
    INFO("component: " << c.name);
    // Finite, non-negative; standstill.
    std::vector<double> speeds = {0.0};
    speeds.insert(speeds.end(), g.speeds_rpm.begin(), g.speeds_rpm.end());
    std::vector<double> loads = {0.0};
    loads.insert(loads.end(), g.loads.begin(), g.loads.end());
    for (double n : speeds)
        for (double T : g.temps_K)
            for (double F : loads) {
                const double p = P(n, T, F);
                INFO("n " << n << " rpm, T " << T - degC << " degC, load " << F << ": " << p << " W");
                CHECK(std::isfinite(p));
                CHECK(p >= 0.0);
                if (n == 0.0 && c.zero_at_standstill) CHECK(p == 0.0);
            }
    // Signs of the derivatives, between neighbouring grid values, everywhere else fixed.
    for (double n : g.speeds_rpm)
        for (double F : g.loads)
            for (size_t k = 1; k < g.temps_K.size(); ++k)
                check_trend(c.with_temperature, P(n, g.temps_K[k - 1], F), P(n, g.temps_K[k], F),
                            "dP/dT at " + std::to_string(n) + " rpm, load " + std::to_string(F) + ", T " +
                                std::to_string(g.temps_K[k - 1] - degC) + " -> " + std::to_string(g.temps_K[k] - degC) +
                                " degC");
    for (double T : g.temps_K)
        for (double F : g.loads)
            for (size_t k = 1; k < g.speeds_rpm.size(); ++k)
                check_trend(c.with_speed, P(g.speeds_rpm[k - 1], T, F), P(g.speeds_rpm[k], T, F),
                            "dP/dn at " + std::to_string(T - degC) + " degC, load " + std::to_string(F) + ", n " +
                                std::to_string(g.speeds_rpm[k - 1]) + " -> " + std::to_string(g.speeds_rpm[k]) + " rpm");
    for (double n : g.speeds_rpm)
        for (double T : g.temps_K)
            for (size_t k = 1; k < g.loads.size(); ++k)
                check_trend(c.with_load, P(n, T, g.loads[k - 1]), P(n, T, g.loads[k]),
                            "dP/dload at " + std::to_string(n) + " rpm, " + std::to_string(T - degC) + " degC, load " +
                                std::to_string(g.loads[k - 1]) + " -> " + std::to_string(g.loads[k]));
}

// ---- components evaluated through the solver (the transfer gearbox, ratio 'low') ----
solver::Model transfer_box() {
    auto c = io::load_case(test_support::source_path("configs/transfer-box.yaml"));
    c.model.thermal.mode = solver::ThermalMode::fixed;
    return c.model;
}

// The loss of one component as the solver's per-temperature evaluation gives it.
Loss solver_part(const solver::Model& m, std::function<double(const solver::LossBreakdown&)> part) {
    return [m, part](double n, double T, double load) {
        const auto p = solver::prepare_point(m, n * rpm, load);
        return part(solver::evaluate_losses(m, p, m.oil_state(T), true));
    };
}

solver::Model only(solver::Model m, bool mesh, bool churning, bool bearings, bool seals) {
    m.mechanisms.at("mesh").set_enabled(mesh);
    m.mechanisms.at("churning").set_enabled(churning);
    m.mechanisms.at("bearings").set_enabled(bearings);
    m.mechanisms.at("seals").set_enabled(seals);
    return m;
}

const Grid kBoxGrid{{300, 1000, 3000}, {degC + 40, degC + 70, degC + 100}, {50, 150, 300}};

lubricant::Oil oil_75W90() { return io::load_oil_file(test_support::source_path("configs/oils/75W90-A.yaml")); }

bearings::BearingSpec bearing_of(bearings::BearingType t) {
    bearings::BearingSpec b;
    b.type = t;
    b.d = 40e-3;  // m
    b.D = 80e-3;
    b.B = 18e-3;
    b.C0 = 19e3;
    const auto series = bearings::series_names(t);  // the first series of the type's SKF table
    b.k = *bearings::skf_constants(t, series.empty() ? "" : series.front());
    b.mu_ehl = bearings::default_mu_ehl(t, false, false);
    b.bath_H = 0.3 * b.dm();  // oil-bath drag terms exercised too
    b.bath_VM = 3e-4;
    return b;
}
bool thrust(bearings::BearingType t) {
    return t == bearings::BearingType::thrust_ball || t == bearings::BearingType::cylindrical_roller_thrust;
}
}  // namespace

TEST_CASE("contracts: mesh friction, every mean-friction model and the local EHL", "[contracts]") {
    const auto box = only(transfer_box(), true, false, false, false);
    auto with = [&](mesh::FrictionModel f) {
        auto m = box;
        mesh::mesh_forms(m).friction = f;
        return m;
    };
    const auto mesh_loss = [](const solver::LossBreakdown& L) { return test::part(L, "mesh"); };
    // Schlenk and ISO/TS 6336-20: mu ~ eta^-0.05 rises as the oil thins; P = mu H_V T w with
    // mu ~ v^-0.2 rises with speed (~n^0.8) and with torque (~T^1.2).
    check_contract({"mesh, Schlenk", Trend::rises}, solver_part(with(mesh::FrictionModel::schlenk), mesh_loss), kBoxGrid);
    check_contract({"mesh, ISO/TS 6336-20", Trend::rises}, solver_part(with(mesh::FrictionModel::iso_6336_20), mesh_loss),
                   kBoxGrid);
    // Fernandes mixed: hotter oil, thinner film, larger boundary share xi(Lambda): mu rises
    // (flat once Lambda >= 2 everywhere, which this grid does not reach).
    check_contract({"mesh, Fernandes mixed", Trend::rises},
                   solver_part(with(mesh::FrictionModel::fernandes_mixed), mesh_loss), kBoxGrid);
    // Local thermal EHL: hotter oil lowers the fluid traction (viscosity) but thins the film
    // (more asperity friction f_c(Lambda)): the sign of dP/dT depends on the point (on this
    // grid the thin films of the transfer box make it rise everywhere; a full film falls).
    check_contract({"mesh, local thermal EHL", Trend::unchecked}, solver_part(with(mesh::FrictionModel::ehl_local), mesh_loss),
                   kBoxGrid);
    check_contract({"mesh, local thermal EHL, viscoelastic", Trend::unchecked},
                   solver_part(with(mesh::FrictionModel::ehl_maxwell), mesh_loss), kBoxGrid);
}

TEST_CASE("contracts: churning, seals and the calibration terms through the solver", "[contracts]") {
    const auto box = transfer_box();
    // Churning: independent of the torque. Its temperature trend is checked per regime in the
    // component test below: on this grid wheel 5 crosses the Changenet-Velex transition band
    // 6000 < Re_c < 9000, where the interpolation towards the (here larger) high-Re torque makes
    // churning RISE as the oil thins.
    check_contract({"churning (solver)", Trend::unchecked, Trend::rises, Trend::independent},
                   solver_part(only(box, false, true, false, false), [](const solver::LossBreakdown& L) { return test::part(L, "churning"); }), kBoxGrid);
    // Seals: ISO/TR 14179-2 P = 7.69e-6 d^2 n, neither oil nor load.
    check_contract({"seals (solver)", Trend::independent, Trend::rises, Trend::independent},
                   solver_part(only(box, false, false, false, true), [](const solver::LossBreakdown& L) { return test::part(L, "seals"); }), kBoxGrid);
    // Windage: P = C (n/1000 rpm)^2.9, no oil, no load.
    auto wind = only(box, false, false, false, false);
    wind.mechanisms.at("windage").set_parameter("empirical_W_at_1000rpm", 25);
    check_contract({"windage (calibration)", Trend::independent, Trend::rises, Trend::independent},
                   solver_part(wind, [](const solver::LossBreakdown& L) { return test::part(L, "windage"); }), kBoxGrid);
    // Palmgren no-load drag M0 = 1e-7 f0 (nu n)^(2/3) d_m^3: falls with T, rises with n, no load.
    auto drag = only(box, false, false, false, false);
    drag.mechanisms.at("bearings").set_enabled(true);
    auto no_drag = drag;
    drag.mechanisms.at("bearings").set_parameter("drag_f0", 2);
    const Loss with_drag = solver_part(drag, [](const solver::LossBreakdown& L) { return test::part(L, "bearings"); });
    const Loss without = solver_part(no_drag, [](const solver::LossBreakdown& L) { return test::part(L, "bearings"); });
    check_contract({"Palmgren bearing drag (calibration)", Trend::falls, Trend::rises, Trend::unchecked},
                   [&](double n, double T, double F) { return with_drag(n, T, F) - without(n, T, F); }, kBoxGrid);
    // (the difference of two load-dependent sums: independent of the load to rounding)
    for (double F : {50.0, 300.0})
        CHECK(with_drag(1000, degC + 70, F) - without(1000, degC + 70, F) ==
              Approx(with_drag(1000, degC + 70, 150) - without(1000, degC + 70, 150)).epsilon(1e-9));
    // Auxiliary: a constant parasitic loss while the box turns.
    auto aux = only(box, false, false, false, false);
    aux.mechanisms.at("auxiliary").set_parameter("power", 30);
    check_contract({"auxiliary (calibration)", Trend::independent, Trend::independent, Trend::independent},
                   solver_part(aux, [](const solver::LossBreakdown& L) { return test::part(L, "auxiliary"); }), kBoxGrid);
}

TEST_CASE("contracts: bearings through the solver", "[contracts]") {
    // SKF: the rolling moment falls as the oil thins, the sliding moment rises (phi_bl: less
    // film, more boundary friction): the sign of dP/dT depends on load and speed (checked for
    // the viscous part of every bearing type in the component test below).
    check_contract({"bearings (solver)", Trend::unchecked, Trend::rises, Trend::rises},
                   solver_part(only(transfer_box(), false, false, true, false), [](const solver::LossBreakdown& L) { return test::part(L, "bearings"); }),
                   kBoxGrid);
}

TEST_CASE("contracts: churning of one gear in each Changenet-Velex regime", "[contracts]") {
    // Rp 50 mm, b 20 mm, z 20, h 20 mm, V0 1 L: Re_c = w Rp b / nu = 1e-3 w / nu.
    const churning::DippingGear g{0.05, 0.02, 20, 6.75e-3, 20 * std::numbers::pi / 180, 0.02};
    const auto oil = oil_75W90();
    const Loss P = [&](double n, double T, double) {
        const auto s = oil.state(T);
        return churning::churning_torque(g, n * rpm, s.rho, s.nu, 1e-3) * n * rpm;
    };
    // Low regime (Re_c < 6000 on the whole grid: at most 1e-3 x 52.4 / 36.7e-6 = 1428):
    // C_m ~ Re^-0.21 ~ nu^0.21, and rho falls too: falls with T.
    check_contract({"churning, Re_c < 6000", Trend::falls, Trend::rises, Trend::independent}, P,
                   {{100, 250, 500}, {degC + 40, degC + 55, degC + 70}, {100, 300}});
    // High regime (Re_c > 9000: at least 1e-3 x 314 / 16.37e-6 = 19 200 ... ): C_m independent
    // of nu, only rho falls.
    check_contract({"churning, Re_c > 9000", Trend::falls, Trend::rises, Trend::independent}, P,
                   {{3000, 4000, 6000}, {degC + 100, degC + 110, degC + 120}, {100, 300}});
}

TEST_CASE("contracts: every bearing type (SKF 2004 with oil-bath drag)", "[contracts]") {
    const auto oil = oil_75W90();
    for (const auto& name : bearings::bearing_type_names()) {
        const auto t = *bearings::bearing_type_from_string(name);
        const auto b = bearing_of(t);
        const Loss P = [&](double n, double T, double F) {
            const double Fr = thrust(t) ? 0.0 : F, Fa = thrust(t) ? F : 0.25 * F;
            return bearings::skf_moment(b, Fr, Fa, n * rpm, oil.nu_mm2s(T) * 1e-6).total() * n * rpm;
        };
        // Total: unchecked in T (rolling falls, sliding rises as the film thins: see above).
        check_contract({"bearing " + name, Trend::unchecked, Trend::rises, Trend::rises}, P,
                       {{500, 1500, 4000}, {degC + 50, degC + 75, degC + 100}, {500, 2000, 5000}});
        // The viscous part (rolling with inlet shear and starvation, oil-bath drag) falls with T
        // where the film is not starved (nu below ~300 mm^2/s at these speeds).
        const Loss viscous = [&](double n, double T, double F) {
            const double Fr = thrust(t) ? 0.0 : F, Fa = thrust(t) ? F : 0.25 * F;
            const auto M = bearings::skf_moment(b, Fr, Fa, n * rpm, oil.nu_mm2s(T) * 1e-6);
            return (M.rolling + M.drag) * n * rpm;
        };
        check_contract({"bearing " + name + ", rolling + drag", Trend::falls, Trend::rises, Trend::rises}, viscous,
                       {{500, 1500, 4000}, {degC + 50, degC + 75, degC + 100}, {500, 2000, 5000}});
    }
}

TEST_CASE("contracts: seals, wet-clutch drag, torque converter, local EHL contact", "[contracts]") {
    const auto oil = oil_75W90();
    check_contract({"radial lip seal 45 mm", Trend::independent, Trend::rises, Trend::independent},
                   [](double n, double, double) { return seals::radial_seal_power(0.045, n * rpm); },
                   {{500, 1500, 4000}, {degC + 40, degC + 100}, {100, 300}});
    // Open wet clutch, always fully wetted (supply 0): Couette drag ~ eta w^2, no load.
    const clutch::WetClutchPack pack{"C", 8, 0.06, 0.08, 1e-4, 1e-6, 0.0};
    check_contract({"open wet clutch pack", Trend::falls, Trend::rises, Trend::independent},
                   [&](double n, double T, double) {
                       const auto s = oil.state(T);
                       return clutch::open_pack_drag(pack, s.eta, s.rho, n * rpm).power;
                   },
                   {{300, 1000, 3000}, {degC - 10, degC + 40, degC + 90}, {100, 300}});
    // Torque converter (the shipped automatic): at a standstill of the turbine the pump turns
    // at idle and all its power heats the fluid (not zero, by physics); thicker fluid lowers the
    // efficiency (HI 9.6.7): the loss falls as the fluid warms; more turbine torque at the same
    // turbine speed means more slip and more loss. The speed trend depends on where the point
    // lies on the characteristic (slip falls towards the coupling point): unchecked.
    const auto c = io::load_case(test_support::source_path("configs/automatic-6speed.yaml"));
    const auto pt = io::load_powertrain(c, std::nullopt);
    const auto& tc = *pt.torque_converter;
    const double idle = pt.vehicle.engine.idle_speed;
    check_contract({"torque converter", Trend::falls, Trend::unchecked, Trend::rises, false},
                   [&](double n, double T, double F) {
                       return torque_converter::operate(tc, n * rpm, F, idle, oil.nu_mm2s(T), false).loss;
                   },
                   {{600, 1200, 2000}, {degC - 10, degC + 40, degC + 90}, {50, 100, 200}});
    CHECK(torque_converter::operate(tc, 1200 * rpm, 100, idle, 20, true).loss == 0.0);  // locked
    // Local thermal EHL line contact (friction power per metre of contact line): u_e from n,
    // slide-to-roll 0.4, load per length from `load` [N/mm]. Smooth surfaces (sigma 0.02 um: full
    // film): the fluid traction falls as the oil warms. With rough surfaces the contact is in
    // mixed friction, where mu falls along the Stribeck curve as the film builds up with speed,
    // faster than 1/n at places (then dP/dn < 0), and rises with T as the film thins.
    check_contract({"local EHL contact", Trend::falls, Trend::rises, Trend::rises},
                   [&](double n, double T, double F) {
                       const double ue = 5.0 * n / 1000.0;
                       mesh::EhlContactInput in{F * 1e3, 10e-3, ue * 1.2, ue * 0.8, 2 * 115.4e9, 0.02e-6, T};
                       const auto r = mesh::ehl_contact(in, oil, oil.traction);
                       return r.mu * F * 1e3 * std::abs(in.u1 - in.u2);
                   },
                   {{500, 1500, 4000}, {degC + 40, degC + 70, degC + 100}, {200, 500, 1000}});
}

// ------------------------------ fast path = reference path ------------------------------

TEST_CASE("fast path: the solver's per-temperature evaluation equals the component formulas", "[contracts]") {
    // evaluate_losses folds the temperature-independent terms once per point and shares the
    // powers of nu across all components; here every component is recomputed directly from its
    // own formula with the same inputs (mean roughness (Ra1 + Ra2)/2 of ISO/TR 14179-2, F_bt/b).
    auto m = transfer_box();
    const auto& gb = m.gearbox;
    const auto& L = m.layout;
    for (auto friction : {mesh::FrictionModel::schlenk, mesh::FrictionModel::iso_6336_20})
        for (double n : {100.0, 800.0, 2500.0})
            for (double T_oil : {degC + 20, degC + 70, degC + 110})
                for (double torque : {40.0, 250.0}) {
                    mesh::mesh_forms(m).friction = friction;
                    const double w_in = n * rpm;
                    const auto p = solver::prepare_point(m, w_in, torque);
                    const auto s = m.oil_state(T_oil);
                    const auto r = solver::evaluate_losses(m, p, s, true);
                    INFO(n << " rpm, " << T_oil - degC << " degC, " << torque << " N m");
                    CHECK(solver::total_loss(m, p, T_oil) == Approx(r.total()).epsilon(1e-12));
                    for (size_t i = 0; i < gb.meshes.size(); ++i) {
                        const auto& md = L.meshes[i];
                        double ref = 0;
                        if (md.loaded) {
                            const auto& g0 = gb.gears[gb.meshes[i].gear[0]].spec;
                            const auto& g1 = gb.gears[gb.meshes[i].gear[1]].spec;
                            const double F_bt = std::abs(md.force_per_Nm * torque) / md.planets / std::cos(md.geom.alpha_wt);
                            const double w = F_bt / (md.geom.b_eff * 1e3);
                            const double v = 2 * std::abs(md.relative_speed * w_in) * 0.5 * md.geom.dw[0] * std::sin(md.geom.alpha_wt);
                            const double Ra = 0.5 * (g0.Ra + g1.Ra) * 1e6;
                            const double mu = friction == mesh::FrictionModel::schlenk
                                                  ? mesh::mean_friction_schlenk(w, v, md.geom.rho_redC * 1e3, s.eta * 1e3, Ra, m.oil.X_L)
                                                  : mesh::mean_friction_iso_6336_20(w, v, md.geom.rho_redC * 1e3, s.eta * 1e3, Ra, m.oil.X_L);
                            ref = mu * md.loss_factor(mesh::mesh_forms(m).loss_factor) * std::abs(torque * w_in) * md.rolling_per_W;
                        }
                        CHECK(test::each(r, "mesh", i) == Approx(ref).epsilon(1e-10));
                    }
                    for (size_t g = 0; g < gb.gears.size(); ++g) {
                        double ref = 0;
                        if (L.gear_immersion[g] > 0) {
                            const auto& spec = gb.gears[g].spec;
                            const churning::DippingGear dg{0.5 * spec.d(), spec.b, spec.z, spec.mn * (spec.ha_star + spec.hf_star),
                                                           spec.alpha_t(), L.gear_immersion[g]};
                            const double wg = std::abs(L.body_speed_ratio[L.body_of_gear[g]] * w_in);
                            ref = churning::churning_torque(dg, wg, s.rho, s.nu, gb.oil_volume) * wg;
                        }
                        CHECK(test::each(r, "churning", g) == Approx(ref).epsilon(1e-10));
                    }
                    for (size_t i = 0; i < gb.bearings.size(); ++i) {
                        const double wb = L.bearing_speed_ratio[i] * w_in;
                        // The gear forces vector-added to the weights of gears and shafts.
                        const auto load = L.bearing_load(i, torque, w_in);
                        const double M = bearings::skf_moment(gb.bearings[i].spec, load.Fr, load.Fa, wb, s.nu_cSt * 1e-6)
                                             .total();  // N*m
                        CHECK(test::each(r, "bearings", i) == Approx(M * wb * gb.bearings[i].multiplicity).epsilon(1e-10));
                    }
                    for (size_t i = 0; i < gb.seals.size(); ++i)
                        CHECK(test::each(r, "seals", i) ==
                              Approx(seals::radial_seal_power(gb.seals[i].diameter, L.seal_speed_ratio[i] * w_in)).epsilon(1e-12));
                }
}

TEST_CASE("fast path: the solver's local EHL mesh loss equals a cold-started direct evaluation", "[contracts]") {
    // The solver warm-starts each contact's thermal loop from the previous temperature of the
    // point; the direct call starts from the bulk. Both stop at |dT| < 0.1 K: equal within 0.2 %.
    auto m = transfer_box();
    mesh::mesh_forms(m).friction = mesh::FrictionModel::ehl_local;
    const auto p = solver::prepare_point(m, 1500 * rpm, 200);
    for (double T_oil : {degC + 50, degC + 90, degC + 60}) {
        const auto r = solver::evaluate_losses(m, p, m.oil_state(T_oil), true);
        for (size_t i = 0; i < m.gearbox.meshes.size(); ++i) {
            const auto& md = m.layout.meshes[i];
            const auto& ms = mesh::mesh_friction_point(m, p.data).meshes[i];
            const double ref = ms.power == 0.0 ? 0.0
                                               : mesh::ehl_mesh_loss(md.geom, md.L_mean, ms.omega_rel, ms.F_bn, md.planets,
                                                                     ms.contact.E_prime, ms.sigma, T_oil, m.oil, m.oil.traction);
            CHECK(test::each(r, "mesh", i) == Approx(ref).epsilon(2e-3));
        }
    }
}

TEST_CASE("fast path: the folded SKF form equals the direct SKF moment for every bearing type", "[contracts]") {
    for (const auto& name : bearings::bearing_type_names()) {
        const auto t = *bearings::bearing_type_from_string(name);
        const auto b = bearing_of(t);
        for (double n : {0.0, 700.0, 6000.0})
            for (double nu : {5.0, 40.0, 400.0})
                for (double F : {0.0, 800.0, 8000.0}) {
                    const double Fr = thrust(t) ? 0.0 : F, Fa = thrust(t) ? F : 0.3 * F;
                    // n in rpm, nu in cSt: the folded form takes the powers of nu in cSt.
                    const auto folded = bearings::SkfAtPoint::make(b, Fr, Fa, n * rpm);
                    const double fast = folded.moment(nu, std::pow(nu, 0.6), std::pow(nu, 0.64), std::pow(nu, 1.4),
                                                      std::pow(nu, 1.379));
                    INFO(name << " n " << n << " nu " << nu << " F " << F);
                    CHECK(fast ==
                          Approx(bearings::skf_moment(b, Fr, Fa, n * rpm, nu * 1e-6).total()).epsilon(1e-12).margin(1e-300));
                }
    }
}

TEST_CASE("fast path: the 3-pressure symmetric Hertz quadrature equals the 5-node Gauss rule", "[contracts]") {
    // Reference: mean shear stress over the Hertz zone by the plain 5-point Gauss-Legendre rule
    // at p = p0 sqrt(1 - x^2), Roelands viscosity, Eyring stress capped by the limiting shear
    // stress tau_L = tau_L0 + slope p, computed here node by node without the shortcuts of the
    // code (symmetric pairs merged, the cap tested on logarithms). Isothermal film (no heating).
    const double x[5] = {-0.9061798459386640, -0.5384693101056831, 0.0, 0.5384693101056831, 0.9061798459386640};
    const double wq[5] = {0.2369268850561891, 0.4786286704993665, 0.5688888888888889, 0.4786286704993665,
                          0.2369268850561891};
    const auto oil = oil_75W90();
    for (double Z : {0.0, 0.7})
        for (double w : {50.0, 500.0, 1500.0})
            for (double slide : {0.001, 0.05, 0.5})
                for (double T : {degC + 40, degC + 100}) {
                    auto rh = oil.traction;
                    rh.roelands_Z = Z;
                    mesh::EhlContactInput in{w * 1e3, 10e-3, 5.0 * (1 + slide / 2), 5.0 * (1 - slide / 2), 2 * 115.4e9,
                                             0.2e-6, T};
                    const auto r = mesh::ehl_contact(in, oil, rh, {}, false);
                    const auto s = oil.state(T);
                    const mesh::RoelandsLaw law = Z > 0 ? mesh::RoelandsLaw::with_index(s.eta, Z) : mesh::RoelandsLaw(s.eta, s.alpha_p);
                    const double gamma = std::abs(in.u1 - in.u2) / r.h_c;
                    double tau = 0, p_mean = 0, wsum = 0;
                    for (int k = 0; k < 5; ++k) {
                        const double p = r.p0 * std::sqrt(1 - x[k] * x[k]);
                        const double tau_L = rh.limiting_shear_0 + rh.limiting_shear_slope * p;
                        tau += wq[k] * std::min(tau_L, rh.eyring_stress * std::asinh(law.viscosity(p) * gamma / rh.eyring_stress));
                        p_mean += wq[k] * p;
                        wsum += wq[k];
                    }
                    INFO("Z " << Z << " w " << w << " N/mm, slide " << slide << ", " << T - degC << " degC");
                    CHECK(r.mu_ehl == Approx((tau / wsum) / (p_mean / wsum)).epsilon(1e-9));
                    CHECK(r.mu == Approx(r.f_c * rh.mu_boundary + (1 - r.f_c) * r.mu_ehl).epsilon(1e-12));
                }
}
