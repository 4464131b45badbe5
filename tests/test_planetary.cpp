#include <catch2/catch.hpp>
#include "loss_parts.hpp"
#include <cmath>
#include <numbers>

#include "gearloss/case/config.hpp"
#include "gearloss/solver/operating_point.hpp"
#include "test_support.hpp"

using namespace gearloss;
using Approx = Catch::Detail::Approx;
using test_support::TempConfig;
constexpr double rpm = std::numbers::pi / 30;

namespace {
std::string planetary() { return test_support::read_file(test_support::source_path("configs/planetary-test.yaml")); }

// The same stage with another member fixed and other input/output members.
io::Case variant(const std::string& fixed, const std::string& in, const std::string& out) {
    std::string t = planetary();
    t = test_support::replace_once(t, "  - sun_shaft\n  - carrier\n  - {name: ring_mount, fixed: true}",
                                   "  - {name: sun_shaft, fixed: " + std::string(fixed == "sun_shaft" ? "true" : "false") +
                                       "}\n  - {name: carrier, fixed: " + (fixed == "carrier" ? "true" : "false") +
                                       "}\n  - {name: ring_mount, fixed: " + (fixed == "ring_mount" ? "true" : "false") + "}");
    t = test_support::replace_once(t, "  input: sun_shaft\n  output: carrier", "  input: " + in + "\n  output: " + out);
    TempConfig cfg(t);
    return io::load_case(cfg.path);
}
constexpr double zs = 16, zp = 23, zr = 62, i0 = -zr / zs;  // stationary ratio (n_s - n_c)/(n_r - n_c)
}  // namespace

TEST_CASE("planetary kinematics follow Willis for every fixed member", "[planetary]") {
    struct Case { const char* fixed; const char* in; const char* out; };
    for (const auto& k : {Case{"ring_mount", "sun_shaft", "carrier"}, Case{"carrier", "sun_shaft", "ring_mount"},
                          Case{"sun_shaft", "ring_mount", "carrier"}, Case{"ring_mount", "carrier", "sun_shaft"}}) {
        const auto c = variant(k.fixed, k.in, k.out);
        const auto& L = c.model.layout;
        auto speed = [&](const char* shaft) {
            for (size_t s = 0; s < c.model.gearbox.shafts.size(); ++s)
                if (c.model.gearbox.shafts[s].name == shaft) return L.body_speed_ratio[L.body_of_shaft[s]];
            return std::nan("");
        };
        const double ns = speed("sun_shaft"), nr = speed("ring_mount"), nc = speed("carrier");
        INFO("fixed " << k.fixed << ", input " << k.in);
        // Willis: n_s - i0 n_r - (1 - i0) n_c = 0.
        CHECK(ns - i0 * nr - (1 - i0) * nc == Approx(0).margin(1e-12));
        CHECK(speed(k.fixed) == Approx(0).margin(1e-12));
        CHECK(speed(k.in) == Approx(1).epsilon(1e-12));
        // Planet relative to the carrier: n_p - n_c = -(z_s/z_p)(n_s - n_c).
        const double np = L.body_speed_ratio[L.body_of_gear[1]];
        CHECK(np - nc == Approx(-(zs / zp) * (ns - nc)).epsilon(1e-12));
        // Ideal torques T_s : T_r : T_c = 1 : -i0 : -(1 - i0), sum zero; power balance T_in + T_out w_out = 0.
        const double Tout = L.output_torque_per_Nm;
        const double w_out = speed(k.out);
        CHECK(1.0 * 1.0 + Tout * w_out == Approx(0).margin(1e-12));
    }
    // Ring fixed, sun in: the carrier turns at z_s/(z_s + z_r) with torque 1 - i0 = 4.875 per N m.
    const auto c = variant("ring_mount", "sun_shaft", "carrier");
    CHECK(c.model.layout.ratio == Approx(zs / (zs + zr)).epsilon(1e-12));
    CHECK(std::abs(c.model.layout.output_torque_per_Nm) == Approx(1 - i0).epsilon(1e-12));
}

TEST_CASE("a planetary stage without a fixed member is rejected", "[planetary]") {
    std::string t = test_support::replace_once(planetary(), "{name: ring_mount, fixed: true}", "ring_mount");
    TempConfig cfg(t);
    CHECK_THROWS_WITH(io::load_case(cfg.path), Catch::Contains("not a single-degree-of-freedom"));
    // Planets that cannot be equally spaced: (16 + 62)/4 is not whole.
    TempConfig cfg2(test_support::replace_once(planetary(), "planets: 3", "planets: 4"));
    CHECK_THROWS_WITH(io::load_case(cfg2.path), Catch::Contains("cannot be equally spaced"));
}

TEST_CASE("planetary efficiency: the basic-efficiency formula against the full computation", "[planetary]") {
    // Ring fixed, sun -> carrier: eta = (1 - i0 eta0)/(1 - i0), eta0 = (1 - mu_sp H_sp)(1 - mu_rp H_rp)
    // (carrier-fixed efficiency). Mesh losses only, fixed oil temperature; mu and H_V per mesh
    // taken from the computation, the combination from the formula.
    auto c = variant("ring_mount", "sun_shaft", "carrier");
    auto& m = c.model;
    for (const char* name : {"churning", "bearings", "seals"}) m.mechanisms.at(name).set_enabled(false);
    m.thermal.mode = solver::ThermalMode::fixed;
    m.thermal.oil_temperature = 333.15;
    for (double n : {500.0, 2000.0})
        for (double T : {50.0, 150.0}) {
            const auto r = solver::solve_point(m, n * rpm, T, true);
            const double e_sp = 1 - test::each(r.losses, "mesh", 0, mesh::kMeshMu) * m.layout.meshes[0].H_V_ohlendorf;
            const double e_rp = 1 - test::each(r.losses, "mesh", 1, mesh::kMeshMu) * m.layout.meshes[1].H_V_ohlendorf;
            const double eta = (1 - i0 * e_sp * e_rp) / (1 - i0);
            // Losses on the ideal rolling power: agreement to second order in mu H_V.
            CHECK(r.efficiency == Approx(eta).margin(2e-4));
            // Rolling power of the sun mesh: |i0|/(1 + |i0|) of the input (ring fixed, sun input).
            CHECK(m.layout.meshes[0].rolling_per_W == Approx(std::abs(i0) / (1 + std::abs(i0))).epsilon(1e-12));
        }
}

TEST_CASE("two parallel stages in series: efficiency is the product of the stages' (decoupled losses)", "[planetary]") {
    // Two spur stages 20/40 and 20/50 (m 3 mm), mesh losses only at a fixed oil temperature;
    // each stage alone computed at the torque it carries in the chain.
    const std::string two = R"(
name: two stages
oil: oils/75W90-A.yaml
shafts: [a, b, c]
gears:
  - {name: g1, shaft: a, position: 0 mm, teeth: 20, module: 3 mm, face_width: 20 mm}
  - {name: g2, shaft: b, position: 0 mm, teeth: 40, module: 3 mm, face_width: 20 mm}
  - {name: g3, shaft: b, position: 50 mm, teeth: 20, module: 3 mm, face_width: 20 mm}
  - {name: g4, shaft: c, position: 50 mm, teeth: 50, module: 3 mm, face_width: 20 mm}
meshes:
  - {gears: [g1, g2]}
  - {gears: [g3, g4], angle: 30 deg}
housing: {oil_volume: 1 L}
thermal: {mode: fixed, oil_temperature: 60 degC, ambient: 25 degC}
gearbox: {input: a, output: c}
operating: {speeds: [1000 rpm], torques: [100 N*m]}
options: {losses: {churning: false, bearings: false, seals: false}}
)";
    const std::string one = R"(
name: one stage
oil: oils/75W90-A.yaml
shafts: [a, b]
gears:
  - {name: g1, shaft: a, position: 0 mm, teeth: Z1, module: 3 mm, face_width: 20 mm}
  - {name: g2, shaft: b, position: 0 mm, teeth: Z2, module: 3 mm, face_width: 20 mm}
meshes:
  - {gears: [g1, g2]}
housing: {oil_volume: 1 L}
thermal: {mode: fixed, oil_temperature: 60 degC, ambient: 25 degC}
gearbox: {input: a, output: b}
operating: {speeds: [1000 rpm], torques: [100 N*m]}
options: {losses: {churning: false, bearings: false, seals: false}}
)";
    TempConfig c2(two);
    const auto chain = io::load_case(c2.path);
    auto stage = [&](int z1, int z2) {
        std::string t = test_support::replace_once(one, "Z1", std::to_string(z1));
        TempConfig c(test_support::replace_once(t, "Z2", std::to_string(z2)));
        return io::load_case(c.path);
    };
    const auto s1 = stage(20, 40), s2 = stage(20, 50);
    for (double n : {300.0, 1500.0})
        for (double T : {50.0, 200.0}) {
            const double w = n * rpm;
            const double eta = solver::solve_point(chain.model, w, T).efficiency;
            const double e1 = solver::solve_point(s1.model, w, T).efficiency;
            const double e2 = solver::solve_point(s2.model, w / 2, 2 * T).efficiency;
            CHECK(eta == Approx(e1 * e2).margin(2e-4));
            CHECK(eta < std::min(e1, e2));
        }
}

TEST_CASE("wind-turbine gearbox: torque balance of every stage", "[planetary]") {
    // Stage 1: carrier in, ring fixed, sun out: T_sun1 = T_in / (1 + 99/21).
    // Stage 2: carrier (= sun 1 shaft) in: T_sun2 = T_sun1 / (1 + 90/24).
    // Stage 3: wheel 91 -> pinion 24: T_out = T_sun2 * 24/91. Ideal (lossless) values.
    const auto c = io::load_case(test_support::source_path("configs/wind-turbine-2.5MW.yaml"));
    const auto& L = c.model.layout;
    const double k1 = 1 + 99.0 / 21, k2 = 1 + 90.0 / 24, k3 = 91.0 / 24;
    CHECK(std::abs(L.ratio) == Approx(k1 * k2 * k3).epsilon(1e-12));
    // Sun torque of each stage = mesh force (all planets) x sun working radius.
    CHECK(std::abs(L.meshes[0].force_per_Nm) * 0.5 * L.meshes[0].geom.dw[0] == Approx(1 / k1).epsilon(1e-10));
    CHECK(std::abs(L.meshes[2].force_per_Nm) * 0.5 * L.meshes[2].geom.dw[0] == Approx(1 / (k1 * k2)).epsilon(1e-10));
    // Planet: the sun and ring mesh forces are equal (torque balance of the planet).
    CHECK(std::abs(L.meshes[0].force_per_Nm) == Approx(std::abs(L.meshes[1].force_per_Nm)).epsilon(1e-10));
    CHECK(std::abs(L.meshes[2].force_per_Nm) == Approx(std::abs(L.meshes[3].force_per_Nm)).epsilon(1e-10));
    // Output: power balance T_out omega_out = -T_in omega_in.
    CHECK(std::abs(L.output_torque_per_Nm) == Approx(1 / (k1 * k2 * k3)).epsilon(1e-10));
    // Rolling power of stage 1: sun mesh |P_roll| / P_in = 1 / k1 * (ratio sun-carrier relative speed) = 99/120.
    CHECK(L.meshes[0].rolling_per_W == Approx(99.0 / 120).epsilon(1e-10));
    // The full computation at rated power: 97-98 % class, losses positive.
    const auto r = solver::solve_point(c.model, 16 * rpm, 1492.1e3, true);
    CHECK(r.efficiency > 0.95);
    CHECK(r.efficiency < 0.99);
}
