#include <catch2/catch.hpp>
#include "loss_parts.hpp"
#include <cmath>
#include <numbers>

#include "gearloss/case/config.hpp"
#include "gearloss/map/map_runner.hpp"
#include "gearloss/solver/operating_point.hpp"
#include "test_support.hpp"

using namespace gearloss;
using Approx = Catch::Detail::Approx;
using test_support::TempConfig;

namespace {
// A single spur stage: pinion z 20 and wheel z 40, m 3 mm, no shift, each gear
// midway between two bearings 100 mm apart.
const char* kSpurPair = R"(
name: spur pair
oil: oils/75W90-A.yaml
shafts: [in, out]
gears:
  - {name: p, shaft: in,  position: 0 mm, teeth: 20, module: 3 mm, face_width: 20 mm, HELIX}
  - {name: g, shaft: out, position: 0 mm, teeth: 40, module: 3 mm, face_width: 20 mm, HELIX2}
meshes:
  - {name: m, gears: [p, g], angle: 0 deg}
bearings:
  - {name: a1, type: deep_groove_ball, series: "62", d: 30 mm, D: 62 mm, C0: 11.2 kN, shaft: in, position: -50 mm, locating: true}
  - {name: a2, type: deep_groove_ball, series: "62", d: 30 mm, D: 62 mm, C0: 11.2 kN, shaft: in, position: 50 mm}
  - {name: b1, type: deep_groove_ball, series: "62", d: 30 mm, D: 62 mm, C0: 11.2 kN, shaft: out, position: -50 mm, locating: true}
  - {name: b2, type: deep_groove_ball, series: "62", d: 30 mm, D: 62 mm, C0: 11.2 kN, shaft: out, position: 50 mm}
housing: {oil_volume: 1 L, oil_level: -40 mm}
thermal: {ambient: 25 degC, heat_rejection: {resistance: 0.15 K/W}}
gearbox: {input: in, output: out}
operating: {speeds: [1000 rpm, 3000 rpm], torques: [50 N*m, 100 N*m, -100 N*m]}
)";

std::string spur(bool helical) {
    std::string s = kSpurPair;
    s = test_support::replace_once(s, "HELIX2", helical ? "helix_angle: 15 deg, hand: left" : "Ra: 0.4 um");
    s = test_support::replace_once(s, "HELIX", helical ? "helix_angle: 15 deg, hand: right" : "Ra: 0.4 um");
    return s;
}
}  // namespace

TEST_CASE("shaft statics: a gear midway between bearings loads each with half the tooth force", "[gearbox]") {
    TempConfig cfg(spur(false));
    const auto c = io::load_case(cfg.path);
    const auto& L = c.model.layout;
    // d_w1 = 60 mm (no shift): F_t = T / 0.030 m, F_n,transverse = F_t / cos 20 deg.
    // Per N m of input torque each bearing carries 0.5 / (0.030 cos 20 deg) = 17.7363 N.
    const double per_Nm = 0.5 / (0.030 * std::cos(20 * std::numbers::pi / 180));
    for (size_t i = 0; i < 4; ++i) {
        CHECK(L.bearing_Fr_pos[i] == Approx(per_Nm).epsilon(1e-9));
        CHECK(L.bearing_Fr_neg[i] == Approx(per_Nm).epsilon(1e-9));
        CHECK(L.bearing_Fa_pos[i] == 0.0);
    }
    CHECK(L.ratio == Approx(-0.5));
    // Both gears dip: tip radius 33 mm (pinion) and 63 mm (wheel), axes 0 and 0 mm, level -40 mm
    // -> pinion not immersed, wheel immersed 63 - 40 = 23 mm.
    CHECK(L.gear_immersion[0] == 0.0);
    CHECK(L.gear_immersion[1] * 1e3 == Approx(23.0).epsilon(1e-9));
}

TEST_CASE("shaft statics: helical axial force goes to the locating bearing", "[gearbox]") {
    TempConfig cfg(spur(true));
    const auto c = io::load_case(cfg.path);
    const auto& L = c.model.layout;
    // F_a = F_t tan(beta) with F_t = T / (d1/2), d1 = 20 * 3 / cos 15 deg = 62.117 mm.
    const double d1 = 20 * 3e-3 / std::cos(15 * std::numbers::pi / 180);
    const double Fa_per_Nm = std::tan(15 * std::numbers::pi / 180) / (0.5 * d1);
    CHECK(L.bearing_Fa_pos[0] == Approx(Fa_per_Nm).epsilon(1e-9));
    CHECK(L.bearing_Fa_pos[1] == 0.0);
    CHECK(L.bearing_Fa_pos[2] == Approx(Fa_per_Nm).epsilon(1e-9));
    // Radial reactions balance the transverse tooth force: their vector sum's magnitude
    // bounds; the sum of magnitudes is at least the resultant F_t / cos(alpha_t).
    const double alpha_t = std::atan(std::tan(20 * std::numbers::pi / 180) / std::cos(15 * std::numbers::pi / 180));
    const double Fres = 1.0 / (0.5 * d1) / std::cos(alpha_t);
    CHECK(L.bearing_Fr_pos[0] + L.bearing_Fr_pos[1] >= Fres * (1 - 1e-9));
}

TEST_CASE("energy balance at every point: P_out = P_in - sum of losses", "[solver]") {
    for (const char* f : {"configs/transfer-box.yaml", "configs/fzg-c40-paor.yaml"}) {
        const auto c = io::load_case(test_support::source_path(f));
        for (size_t i = 0; i < c.grid.size(); ++i) {
            const auto [w, T] = c.grid.at(i);
            const auto r = solver::solve_point(c.model, w, T, true);
            REQUIRE(solver::has_values(r.status));
            double sum = 0;
            // Every component of every mechanism (a mechanism without components counts its total).
            for (size_t k = 0; k < r.losses.power.size(); ++k) {
                const auto& d = r.losses.detail[k];
                if (d.values.empty()) sum += r.losses.power[k];
                for (size_t c2 = 0; c2 < d.values.size(); c2 += d.quantities) sum += d.values[c2];
            }
            CHECK(r.power_out == Approx(r.power_in - sum).epsilon(1e-9));
            // Output torque times output speed gives the same power (torque balance).
            CHECK(r.torque_out * std::abs(r.omega_out) == Approx(r.power_out).epsilon(1e-9));
            CHECK(r.efficiency > 0.9);
            CHECK(r.efficiency < 1.0);
        }
    }
}

TEST_CASE("transfer gearbox kinematics: both ratios and the idle pair", "[gearbox]") {
    const auto lo = io::load_case(test_support::source_path("configs/transfer-box.yaml"), std::string("low"));
    const auto hi = io::load_case(test_support::source_path("configs/transfer-box.yaml"), std::string("high"));
    // low: wheels 5-3 and 2-1: (17/28)(23/32) = 0.436384; high: 4-2 and 2-1: (27/23)(23/32) = 0.84375.
    CHECK(lo.model.layout.ratio == Approx(17.0 / 28 * 23.0 / 32).epsilon(1e-12));
    CHECK(hi.model.layout.ratio == Approx(27.0 / 32).epsilon(1e-12));
    // In 'low' the pair 2-4 is idle (no load) but wheel 4 turns at 23/27 of shaft II's speed.
    const auto& L = lo.model.layout;
    CHECK_FALSE(L.meshes[1].loaded);
    CHECK(L.meshes[0].loaded);
    CHECK(L.meshes[2].loaded);
    CHECK(std::abs(L.body_speed_ratio[L.body_of_gear[3]]) == Approx(17.0 / 28 * 23.0 / 27).epsilon(1e-12));
    // The idle wheel churns: it is immersed and has a churning loss.
    const auto r = solver::solve_point(lo.model, 800 * std::numbers::pi / 30, 250, true);
    CHECK(test::each(r.losses, "churning", 3) > 0.0);
    CHECK(test::each(r.losses, "mesh", 1) == 0.0);
}

TEST_CASE("more torque at fixed speed and oil temperature means more loss", "[solver]") {
    auto c = io::load_case(test_support::source_path("configs/transfer-box.yaml"));
    c.model.thermal.mode = solver::ThermalMode::fixed;
    c.model.thermal.oil_temperature = 343.15;
    double prev = -1;
    for (double T = 0; T <= 400; T += 25) {
        const auto r = solver::solve_point(c.model, 700 * std::numbers::pi / 30, T);
        CHECK(r.losses.total() > prev);
        prev = r.losses.total();
    }
}

TEST_CASE("map results do not depend on the thread count", "[map]") {
    auto c = io::load_case(test_support::source_path("configs/transfer-box.yaml"));
    c.grid.speeds = {31.4, 62.8, 83.7, 104.7, 125.6};
    c.grid.torques = {10, 100, 200, 300};
    map::MapOptions one, two;
    one.threads = 1;
    two.threads = 2;
    one.detail = two.detail = true;
    const auto a = map::run_map(c.model, c.grid, one);
    const auto b = map::run_map(c.model, c.grid, two);
    REQUIRE(a.size() == 20);
    for (size_t i = 0; i < a.size(); ++i) {
        CHECK(map::csv_row(c.model, a[i], true) == map::csv_row(c.model, b[i], true));
        // Grid order: speed outer, torque inner.
        CHECK(a[i].speed_in == c.grid.speeds[i / 4]);
        CHECK(a[i].torque_in == c.grid.torques[i % 4]);
    }
}
