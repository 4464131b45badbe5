// Weights of gears and shafts as bearing loads: hand calculations of the lever rule and the
// vector sum with a gear force, the direction of gravity, masses from the geometry, and the
// bearing loss of every shipped case at zero torque.
#include <catch2/catch.hpp>
#include "loss_parts.hpp"
#include <cmath>
#include <filesystem>
#include <numbers>
#include <string>

#include "gearloss/case/config.hpp"
#include "gearloss/solver/operating_point.hpp"
#include "test_support.hpp"

using namespace gearloss;
using Approx = Catch::Detail::Approx;
using test_support::TempConfig;

namespace {
// Pinion z 20, m 3 mm, no shift (d_w = 60 mm, alpha_wt = 20 deg) 20 mm off the middle of its
// shaft's bearings a1 (-50 mm) and a2 (+50 mm); the wheel on its own shaft. PINION and SHAFT
// take the mass keys, GRAVITY the housing's direction of gravity.
const char* kCase = R"(
name: weights on a two-bearing shaft
oil: oils/75W90-A.yaml
shafts: [SHAFT, out]
gears:
  - {name: p, shaft: in,  position: 20 mm, teeth: 20, module: 3 mm, face_width: 20 mm, Ra: 0.4 um PINION}
  - {name: g, shaft: out, position: 0 mm,  teeth: 40, module: 3 mm, face_width: 20 mm, Ra: 0.4 um}
meshes:
  - {name: m, gears: [p, g], angle: 0 deg}
bearings:
  - {name: a1, type: deep_groove_ball, series: "62", d: 30 mm, D: 62 mm, C0: 11.2 kN, shaft: in, position: -50 mm, locating: true}
  - {name: a2, type: deep_groove_ball, series: "62", d: 30 mm, D: 62 mm, C0: 11.2 kN, shaft: in, position: 50 mm}
  - {name: b1, type: deep_groove_ball, series: "62", d: 30 mm, D: 62 mm, C0: 11.2 kN, shaft: out, position: -50 mm, locating: true}
  - {name: b2, type: deep_groove_ball, series: "62", d: 30 mm, D: 62 mm, C0: 11.2 kN, shaft: out, position: 50 mm}
housing: {oil_volume: 1 L, oil_level: -40 mm GRAVITY}
thermal: {ambient: 25 degC, heat_rejection: {resistance: 0.15 K/W}}
gearbox: {input: in, output: out}
operating: {speeds: [1000 rpm], torques: [0 N*m]}
)";

std::string make_case(const std::string& pinion, const std::string& shaft, const std::string& gravity) {
    std::string s = kCase;
    s = test_support::replace_once(s, " PINION", pinion);
    s = test_support::replace_once(s, "SHAFT", shaft);
    return test_support::replace_once(s, " GRAVITY", gravity);
}
// Pinion 2 kg, shaft 3 kg, given.
std::string given_masses(const std::string& gravity = "") {
    return make_case(", mass: 2 kg", "{name: in, mass: 3 kg}", gravity);
}
}  // namespace

TEST_CASE("weights: lever rule and vector sum with the gear force on a two-bearing shaft", "[weights]") {
    // Hand calculation, g = 9.80665 m/s^2, gravity -y (default):
    //   pinion W_p = 2 g = 19.6133 N at z = +20 mm: a1 takes (50 - 20)/100 = 0.3 W_p = 5.88399 N,
    //     a2 takes 0.7 W_p = 13.72931 N; shaft W_s = 3 g = 29.41995 N at its centre z = 0: half each.
    //   Weight reactions (up, +y): a1 20.593965 N, a2 28.439285 N.
    //   T = +10 N m: F_t = T / r_w = 10 / 0.030 = 333.3333 N; the tooth force on the pinion (contact
    //     on +x) turns it back: -y; the separating force F_t tan 20 deg = 121.3234 N pushes it to -x.
    //     Reactions: a1 0.3 (121.3234, 333.3333) = (36.3970, 100.0000),
    //                a2 0.7 (121.3234, 333.3333) = (84.9264, 233.3333).
    //   |(36.3970, 100 + 20.5940)| = 125.96685 N, |(84.9264, 233.3333 + 28.4393)| = 275.20428 N.
    //   T = -10 N m: the tangential force reverses: |(36.3970, -100 + 20.5940)| = 87.35022 N,
    //     |(84.9264, -233.3333 + 28.4393)| = 221.79735 N.
    TempConfig cfg(given_masses());
    const auto c = io::load_case(cfg.path);
    const auto& L = c.model.layout;
    CHECK(L.gear_mass[0] == Approx(2.0));
    CHECK(L.shaft_mass[0] == Approx(3.0));
    CHECK(L.bearing_load(0, 0.0).Fr == Approx(20.593965).epsilon(1e-7));
    CHECK(L.bearing_load(1, 0.0).Fr == Approx(28.439285).epsilon(1e-7));
    CHECK(L.bearing_load(0, 10.0).Fr == Approx(125.96685).epsilon(1e-6));
    CHECK(L.bearing_load(1, 10.0).Fr == Approx(275.20428).epsilon(1e-6));
    CHECK(L.bearing_load(0, -10.0).Fr == Approx(87.35022).epsilon(1e-6));
    CHECK(L.bearing_load(1, -10.0).Fr == Approx(221.79735).epsilon(1e-6));
    // Spur gears, horizontal shafts: no axial load.
    CHECK(L.bearing_load(0, 10.0).Fa == 0.0);
    // The weights alone carry the whole weight: a1 + a2 = W_p + W_s (force balance).
    CHECK(L.bearing_load(0, 0.0).Fr + L.bearing_load(1, 0.0).Fr == Approx(5 * 9.80665).epsilon(1e-9));
}

TEST_CASE("weights: the direction of gravity turns the weight reactions as statics says", "[weights]") {
    // gravity +x: the weight reactions point to -x: a1 (36.3970 - 20.5940, 100) -> 101.24098 N,
    // a2 (84.9264 - 28.4393, 233.3333) -> 240.07340 N at T = +10 N m.
    {
        TempConfig cfg(given_masses(", gravity: [1, 0, 0]"));
        const auto& L = io::load_case(cfg.path).model.layout;
        CHECK(L.bearing_load(0, 10.0).Fr == Approx(101.24098).epsilon(1e-6));
        CHECK(L.bearing_load(1, 10.0).Fr == Approx(240.07340).epsilon(1e-6));
        CHECK(L.bearing_load(0, 0.0).Fr == Approx(20.593965).epsilon(1e-7));
    }
    // An angle in the plane of the mesh angles: -90 deg is the default, straight down; a vector
    // of any length is a direction.
    {
        TempConfig a(given_masses(", gravity: -90 deg")), b(given_masses(", gravity: [0, -9.81, 0]"));
        const auto& La = io::load_case(a.path).model.layout;
        const auto& Lb = io::load_case(b.path).model.layout;
        CHECK(La.bearing_load(0, 10.0).Fr == Approx(125.96685).epsilon(1e-6));
        CHECK(Lb.bearing_load(1, -10.0).Fr == Approx(221.79735).epsilon(1e-6));
    }
    // Vertical shafts (gravity along -z): no radial weight; the locating bearing a1 carries the
    // whole 5 kg axially, 49.03325 N, a2 nothing; at T = +10 N m a1's radial load is the gear
    // force's alone, |(36.3970, 100)| = 106.41778 N.
    {
        TempConfig cfg(given_masses(", gravity: [0, 0, -1]"));
        const auto& L = io::load_case(cfg.path).model.layout;
        CHECK(L.bearing_load(0, 0.0).Fr == Approx(0.0).margin(1e-9));
        CHECK(L.bearing_load(0, 0.0).Fa == Approx(49.03325).epsilon(1e-9));
        CHECK(L.bearing_load(1, 0.0).Fa == 0.0);
        CHECK(L.bearing_load(0, 10.0).Fr == Approx(106.41778).epsilon(1e-6));
    }
}

TEST_CASE("weights: masses from the geometry and the assumed values that say so", "[weights]") {
    // Pinion z 20, m 3 mm, b 20 mm, no shift: d_a = 66 mm, d_f = 60 - 2.5 * 3 = 52.5 mm;
    // d_eq^2 = (66^2 + 52.5^2) / 2 = 3556.125 mm^2. Its shaft (largest bearing bore 30 mm) goes
    // through it: m = 7850 pi/4 (3556.125 - 900) e-6 0.020 = 0.327520 kg.
    // Shaft: 30 mm over the span 100 mm: 7850 pi/4 0.03^2 0.1 = 0.554884 kg.
    TempConfig cfg(make_case("", "in", ""));
    const auto c = io::load_case(cfg.path);
    const auto& L = c.model.layout;
    CHECK(L.gear_mass[0] == Approx(0.327520).epsilon(1e-5));
    CHECK(L.shaft_mass[0] == Approx(0.554884).epsilon(1e-5));
    // Solid (bore 0): 7850 pi/4 3556.125e-6 0.020 = 0.438497 kg; a shaft of 55 mm, outside the
    // root circle (52.5 mm), leaves the pinion solid too.
    TempConfig solid(make_case(", bore: 0 mm", "in", ""));
    CHECK(io::load_case(solid.path).model.layout.gear_mass[0] == Approx(0.438497).epsilon(1e-5));
    TempConfig thick(make_case("", "{name: in, diameter: 55 mm}", ""));
    CHECK(io::load_case(thick.path).model.layout.gear_mass[0] == Approx(0.438497).epsilon(1e-5));
    // A shaft of 40 mm over 250 mm of aluminium (2700 kg/m^3): 2700 pi/4 0.04^2 0.25 = 0.848230 kg.
    TempConfig shaft(make_case("", "{name: in, diameter: 40 mm, length: 250 mm, density: 2700 kg/m^3}", ""));
    CHECK(io::load_case(shaft.path).model.layout.shaft_mass[0] == Approx(0.848230).epsilon(1e-5));
    const auto has = [&](const std::string& key) {
        for (const auto& a : c.assumed)
            if (a.key == key) return true;
        return false;
    };
    CHECK(has("gears.p.mass"));
    CHECK(has("shafts.in.mass"));
    CHECK(has("housing.gravity"));
    TempConfig given(given_masses());
    const auto cg = io::load_case(given.path);
    for (const auto& a : cg.assumed) CHECK(a.key != "gears.p.mass");
}

TEST_CASE("weights: bad gravity and mass keys are input errors at their key", "[weights]") {
    TempConfig zero(given_masses(", gravity: [0, 0, 0]"));
    CHECK_THROWS_WITH(io::load_case(zero.path), Catch::Contains("housing.gravity") && Catch::Contains("zero vector"));
    TempConfig two(given_masses(", gravity: [0, -1]"));
    CHECK_THROWS_WITH(io::load_case(two.path), Catch::Contains("three numbers"));
    // Vertical shafts need a locating bearing on every loaded shaft.
    std::string s = test_support::replace_once(given_masses(", gravity: [0, 0, -1]"), "position: -50 mm, locating: true}", "position: -50 mm}");
    TempConfig unlocated(s);
    CHECK_THROWS_WITH(io::load_case(unlocated.path), Catch::Contains("locating") && Catch::Contains("housing.gravity"));
    TempConfig both(make_case(", mass: 2 kg, bore: 20 mm", "in", ""));
    CHECK_THROWS_WITH(io::load_case(both.path), Catch::Contains("bore") && Catch::Contains("would not be read"));
    TempConfig wide(make_case(", bore: 70 mm", "in", ""));
    CHECK_THROWS_WITH(io::load_case(wide.path), Catch::Contains("bore") && Catch::Contains("tip circle"));
}

TEST_CASE("weights: planets and carrier weigh on the carrier bearings, whose loads sum to that weight", "[weights][planetary]") {
    // Force balance at zero torque: the carrier's two bearings (symmetric about the planets)
    // take 3 planets and the carrier shaft; the sun shaft's two its sun and itself.
    const auto c = test_support::load_shipped("configs/planetary-test.yaml");
    const auto& gb = c.model.gearbox;
    const auto& L = c.model.layout;
    const auto index = [&](const std::string& name) {
        for (size_t i = 0; i < gb.bearings.size(); ++i)
            if (gb.bearings[i].name == name) return i;
        FAIL("no bearing " << name);
        return size_t{0};
    };
    const auto gear = [&](const std::string& name) {
        for (size_t g = 0; g < gb.gears.size(); ++g)
            if (gb.gears[g].spec.name == name) return g;
        FAIL("no gear " << name);
        return size_t{0};
    };
    const double g_n = 9.80665;
    const double carrier = (3 * L.gear_mass[gear("planet")] + L.shaft_mass[1]) * g_n;
    CHECK(L.bearing_load(index("carrier_a"), 0.0).Fr + L.bearing_load(index("carrier_b"), 0.0).Fr ==
          Approx(carrier).epsilon(1e-9));
    const double sun = (L.gear_mass[gear("sun")] + L.shaft_mass[0]) * g_n;
    CHECK(L.bearing_load(index("sun_a"), 0.0).Fr + L.bearing_load(index("sun_b"), 0.0).Fr == Approx(sun).epsilon(1e-9));
    // A planet's needle rows (2 per planet) share its weight, which turns with the carrier.
    CHECK(L.bearing_load(index("planet_pin.1"), 0.0).Fr == Approx(L.gear_mass[gear("planet")] * g_n / 2).epsilon(1e-9));
    CHECK(L.gear_mass[gear("planet")] > 0.0);
}

TEST_CASE("weights: every shipped case that turns has a bearing loss at zero torque", "[weights]") {
    // Before the weights were loads, a spinning gearbox without torque had no rolling moment
    // (SKF (2004): G_rr grows with the load), so the bearings of the transfer box and of the
    // seed-000 box lost exactly 0 W at 0 N m. Every bearing that turns must lose something.
    namespace fs = std::filesystem;
    int cases = 0;
    for (const auto& entry : fs::directory_iterator(test_support::source_path("configs"))) {
        const auto name = entry.path().filename().string();
        if (entry.path().extension() != ".yaml" || name.starts_with("tmp-test-")) continue;
        INFO(name);
        auto c = io::load_case(entry.path().string());
        c.model.thermal.mode = solver::ThermalMode::fixed;
        c.model.thermal.oil_temperature = 333.15;  // 60 degC
        // 1000 rpm, or a case's fastest listed point when it lists points (the wind turbine's rotor
        // at 1000 rpm turns its high-speed bearings beyond any rolling bearing's n d_m).
        double w = 1000 * std::numbers::pi / 30;
        for (const auto& [s, t] : c.grid.points) w = std::min(w, std::abs(s) > 0 ? std::abs(s) : w);
        const auto r = solver::solve_point(c.model, w, 0.0, true);
        REQUIRE(solver::has_values(r.status));
        CHECK(test::part(r.losses, "bearings") > 0.0);
        const auto& L = c.model.layout;
        for (size_t i = 0; i < c.model.gearbox.bearings.size(); ++i) {
            INFO(c.model.gearbox.bearings[i].name);
            if (L.bearing_speed_ratio[i] > 1e-9) CHECK(test::each(r.losses, "bearings", i) > 0.0);
        }
        ++cases;
    }
    CHECK(cases >= 9);
}
