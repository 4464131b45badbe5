// A pilot bearing between two shafts (`outer_shaft`, docs/config.md "Pilot bearings"): its
// frictional moment is taken at the relative speed of the two shafts, checked against a hand
// calculation of the SKF (2004) seal moment, which does not depend on speed or load, so the
// bearing's power is that moment times the relative speed alone. Bad `outer_shaft` values give
// errors naming the file, line and key.
#include <Eigen/Core>
#include <catch2/catch.hpp>
#include <numbers>
#include <string>

#include "gearloss/case/config.hpp"
#include "gearloss/core/errors.hpp"
#include "gearloss/gearbox/gearbox.hpp"
#include "gearloss/solver/operating_point.hpp"
#include "loss_parts.hpp"
#include "test_support.hpp"

using namespace gearloss;

namespace {

// A coaxial two-stage spur reducer: input shaft `in` (A, z 20) drives the layshaft (B, z 40),
// whose pinion C (z 20) drives D (z 40) on the output shaft `out`, coaxial with the input; m 3 mm,
// both centre distances 3 (20 + 40)/2 = 90 mm. The input shaft's end runs in a 6206-size pilot
// bearing with RS1 contact seals whose outer ring is in the output shaft (`pilot`). Every gear and
// shaft weighs 1 mg (`mass:`): at zero torque the bearings carry no load to speak of, so the SKF
// rolling and sliding moments (which grow with the load) vanish beside the seal moment.
std::string coaxial_case(const std::string& pilot_extra = "outer_shaft: out, outer_position: 50 mm") {
    return R"(name: coaxial reducer with a pilot bearing
oil: oils/75W90-syn-A.yaml
shafts:
  - {name: in, mass: 0.000001 kg}
  - {name: lay, mass: 0.000001 kg}
  - {name: out, mass: 0.000001 kg}
gears:
  - {name: A, shaft: in,  position: 0 mm,   teeth: 20, module: 3 mm, face_width: 30 mm, mass: 0.000001 kg}
  - {name: B, shaft: lay, position: 0 mm,   teeth: 40, module: 3 mm, face_width: 30 mm, mass: 0.000001 kg}
  - {name: C, shaft: lay, position: 100 mm, teeth: 20, module: 3 mm, face_width: 30 mm, mass: 0.000001 kg}
  - {name: D, shaft: out, position: 100 mm, teeth: 40, module: 3 mm, face_width: 30 mm, mass: 0.000001 kg}
meshes:
  - {name: m1, gears: [A, B], angle: 90 deg}
  - {name: m2, gears: [C, D], angle: -90 deg}
bearings:
  - {name: in_a,  type: deep_groove_ball, series: "62", d: 30 mm, D: 62 mm, B: 16 mm, C0: 11.2 kN, shaft: in,  position: -50 mm, locating: true}
  - {name: pilot, type: deep_groove_ball, series: "62", d: 30 mm, D: 62 mm, B: 16 mm, C0: 11.2 kN, shaft: in,  position: 50 mm, seals: RS1, seal_counterface: 36 mm, )" +
           pilot_extra + R"(}
  - {name: lay_a, type: deep_groove_ball, series: "62", d: 30 mm, D: 62 mm, B: 16 mm, C0: 11.2 kN, shaft: lay, position: -50 mm, locating: true}
  - {name: lay_b, type: deep_groove_ball, series: "62", d: 30 mm, D: 62 mm, B: 16 mm, C0: 11.2 kN, shaft: lay, position: 150 mm}
  - {name: out_a, type: deep_groove_ball, series: "62", d: 40 mm, D: 80 mm, B: 18 mm, C0: 19 kN, shaft: out, position: 60 mm, locating: true}
  - {name: out_b, type: deep_groove_ball, series: "62", d: 40 mm, D: 80 mm, B: 18 mm, C0: 19 kN, shaft: out, position: 150 mm}
housing:
  oil_volume: 1.5 L
thermal:
  mode: fixed
  oil_temperature: 80 degC
  ambient: 20 degC
gearbox:
  input: in
  output: out
operating:
  speeds: [3000 rpm]
  torques: [0 N*m]
)";
}

io::Case load(const std::string& text) {
    return io::load_case_text(text, "pilot.yaml", test_support::source_path("configs"));
}

size_t bearing_index(const io::Case& c, const std::string& name) {
    const auto& b = c.model.gearbox.bearings;
    for (size_t i = 0; i < b.size(); ++i)
        if (b[i].name == name) return i;
    FAIL("no bearing " << name);
    return 0;
}

}  // namespace

TEST_CASE("pilot bearing: the SKF seal moment at the two shafts' relative speed, by hand", "[bearings][pilot]") {
    // Kinematics: n_lay / n_in = -20/40, n_out / n_in = (-20/40)(-20/40) = +0.25 (two external
    // meshes), so the pilot's rings turn at |1 - 0.25| = 0.75 of the input speed:
    //   n_in = 3000 r/min, n_rel = 2250 r/min, omega_rel = 2250 pi / 30 = 235.6194 rad/s.
    // SKF (2004) seal moment of a deep groove ball bearing with RS1 seals, D = 62 mm (the
    // 52 < D <= 62 row): M_seal = K_S1 d_s^beta + K_S2 with K_S1 = 0.023, beta = 2.25, K_S2 = 2,
    // d_s = 36 mm (seal_counterface):
    //   36^2.25 = 36^2 x 36^0.25 = 1296 x 2.449490 = 3174.539
    //   M_seal = 0.023 x 3174.539 + 2 = 75.0144 N mm
    //   P = M_seal omega_rel = 0.0750144 N m x 235.6194 rad/s = 17.6748 W.
    // At the input shaft's speed (the bearing against the housing) it would be 23.566 W. With
    // 1 mg gears and shafts the rolling and sliding moments are below 1e-4 of the seal moment.
    const auto c = load(coaxial_case());
    const size_t pilot = bearing_index(c, "pilot");
    CHECK(c.model.gearbox.bearings[pilot].outer_shaft >= 0);
    CHECK(c.model.layout.bearing_speed_ratio[pilot] == Approx(0.75).epsilon(1e-12));
    CHECK(c.model.layout.bearing_speed_ratio[bearing_index(c, "in_a")] == Approx(1.0).epsilon(1e-12));
    CHECK(c.model.layout.bearing_speed_ratio[bearing_index(c, "out_a")] == Approx(0.25).epsilon(1e-12));
    const auto r = solver::solve_point(c.model, 3000 * std::numbers::pi / 30, 0.0, true);
    REQUIRE(solver::has_values(r.status));
    CHECK(test::each(r.losses, "bearings", pilot) == Approx(17.6748).epsilon(2e-4));
}

TEST_CASE("pilot bearing: a bad outer_shaft names the file, line and key", "[bearings][pilot][config]") {
    const auto message = [](const std::string& text) {
        try {
            load(text);
        } catch (const InputError& e) {
            return std::string(e.what());
        }
        return std::string();
    };
    // The bearing's own shaft.
    const std::string own = message(coaxial_case("outer_shaft: in, outer_position: 50 mm"));
    CHECK_THAT(own, Catch::Contains("pilot.yaml:") && Catch::Contains("outer_shaft") && Catch::Contains("own shaft 'in'"));
    // A shaft the case does not have.
    const std::string unknown = message(coaxial_case("outer_shaft: hub, outer_position: 50 mm"));
    CHECK_THAT(unknown, Catch::Contains("pilot.yaml:") && Catch::Contains("outer_shaft") && Catch::Contains("unknown shaft 'hub'"));
    // With under_gear (a bearing under a free gear or planet is not a pilot bearing).
    auto free_gear = test_support::replace_once(coaxial_case("outer_shaft: out, outer_position: 50 mm, under_gear: A"), "face_width: 30 mm, mass",
                                                "face_width: 30 mm, mount: free, mass");
    const std::string both = message(free_gear);
    CHECK_THAT(both, Catch::Contains("pilot.yaml:") && Catch::Contains("outer_shaft") && Catch::Contains("not both"));
    // Without its place along the outer shaft, and that place without an outer shaft.
    const std::string no_place = message(coaxial_case("outer_shaft: out"));
    CHECK_THAT(no_place, Catch::Contains("pilot.yaml:") && Catch::Contains("outer_position"));
    const std::string no_outer = message(coaxial_case("outer_position: 50 mm"));
    CHECK_THAT(no_outer, Catch::Contains("pilot.yaml:") && Catch::Contains("outer_position") && Catch::Contains("outer_shaft"));
    // A cycle of pilots: `out` also runs in `in` (its bearing out_b a pilot in the input shaft).
    const std::string cycle = message(test_support::replace_once(coaxial_case(), "shaft: out, position: 150 mm}",
                                                                 "shaft: out, position: 150 mm, outer_shaft: in, outer_position: 20 mm}"));
    CHECK_THAT(cycle, Catch::Contains("pilot.yaml:") && Catch::Contains("cycle") && Catch::Contains("bearing '"));
}

namespace {

// Radial reaction of a bearing per N m of input torque (+ sense), housing frame [N].
Eigen::Vector2d unit_reaction(const io::Case& c, const std::string& name) {
    return c.model.layout.bearing_R_pos[bearing_index(c, name)];
}

// Bearings in the housing: neither pilots nor under a gear.
bool in_housing(const gearbox::Bearing& b) { return b.outer_shaft < 0 && b.under_gear < 0; }

}  // namespace

TEST_CASE("pilot bearing: its reaction carried to the outer shaft's bearings, by hand", "[bearings][pilot][statics]") {
    // Input torque +1 N m (counter-clockwise about z; x, y the housing frame, y up), spur gears,
    // alpha = 20 deg, m 3 mm, r_w = 30 mm (z 20) and 60 mm (z 40), tan 20 deg = 0.363970.
    // Mesh m1 (B above A): on A the tangential force must give -1 N m about A's axis from the
    // contact point (0, +30 mm): F_x = 1 / 0.03 = 33.3333 N; the separating force pushes A down,
    // 33.3333 tan 20 = 12.1323 N: F_A = (33.3333, -12.1323) N at z = 0.
    // The layshaft takes -F_A at (0, -60 mm) from its axis: -2 N m, so mesh m2 (D below C) gives C
    // +2 N m from (0, -30 mm): F_C,x = 2 / 0.03 = 66.6667 N, separation up 24.2647 N; on D the
    // opposite: F_D = (-66.6667, -24.2647) N at z = 100 mm (+4 N m on the output shaft).
    // Input shaft, supports in_a (z = -50) and the pilot (z = +50), A midway: each takes half,
    //   R_pilot = -F_A / 2 = (-16.6667, 6.0662) N.
    // The pilot pushes the output shaft with P = -R_pilot = (16.6667, -6.0662) N at z = 50 mm, outside
    // its supports out_a (z = 60) and out_b (z = 150), L = 90 mm. Lever rule, moments about out_a:
    //   R_out_b = -(P (50 - 60) + F_D (100 - 60)) / 90 = (10 P - 40 F_D) / 90
    //           = ((166.667 + 2666.667) / 90, (-60.662 + 970.587) / 90) = (31.4815, 10.1103) N
    //   R_out_a = -(P + F_D) - R_out_b = (50 - 31.4815, 30.3309 - 10.1103) = (18.5185, 20.2206) N.
    // Without the pilot's load (the outer shaft on its own gear force only) they would be
    // (29.6296, 10.7843) and (37.0370, 13.4804) N.
    const auto c = load(coaxial_case());
    const Eigen::Vector2d pilot = unit_reaction(c, "pilot"), a = unit_reaction(c, "out_a"), b = unit_reaction(c, "out_b");
    CHECK(pilot.x() == Approx(-16.6667).epsilon(1e-5));
    CHECK(pilot.y() == Approx(6.0662).epsilon(1e-4));
    CHECK(b.x() == Approx(31.4815).epsilon(1e-5));
    CHECK(b.y() == Approx(10.1103).epsilon(1e-4));
    CHECK(a.x() == Approx(18.5185).epsilon(1e-5));
    CHECK(a.y() == Approx(20.2206).epsilon(1e-4));
    // The opposite torque sense reverses every gear force and reaction.
    const auto& L = c.model.layout;
    CHECK(L.bearing_R_neg[bearing_index(c, "out_a")].x() == Approx(-18.5185).epsilon(1e-5));
}

TEST_CASE("pilot bearing: the outer position is along the outer shaft, in its own frame", "[bearings][pilot][statics]") {
    // The output shaft's axial frame moved by 1000 mm (its gear, bearings and the pilot's place on
    // it all 1000 mm further): the same gearbox, so the same reactions.
    const auto c = load(coaxial_case());
    std::string moved = coaxial_case("outer_shaft: out, outer_position: 1050 mm");
    moved = test_support::replace_once(moved, "shaft: out, position: 100 mm", "shaft: out, position: 1100 mm");
    moved = test_support::replace_once(moved, "shaft: out, position: 60 mm", "shaft: out, position: 1060 mm");
    moved = test_support::replace_once(moved, "shaft: out, position: 150 mm", "shaft: out, position: 1150 mm");
    const auto m = load(moved);
    for (const char* name : {"out_a", "out_b", "pilot", "in_a"}) {
        INFO(name);
        CHECK((unit_reaction(m, name) - unit_reaction(c, name)).norm() < 1e-9);
    }
}

TEST_CASE("pilot bearing: the housing bearings balance the gear forces and the weights", "[bearings][pilot][statics]") {
    // Force balance of the whole gearbox: input and output torques are couples, and the mesh forces
    // and the pilot's reaction are internal, so the housing's bearings take no net gear force; the
    // weights of all gears and shafts they take whole. Gears and shafts of 2 kg each here (g_n =
    // 9.80665 m/s^2, gravity -y): 4 gears and 3 shafts, so sum R_y = 7 x 2 x 9.80665 = 137.2931 N.
    std::string text = coaxial_case();
    for (size_t at; (at = text.find("mass: 0.000001 kg")) != std::string::npos;) text.replace(at, 17, "mass: 2 kg");
    const auto c = load(text);
    const auto& gb = c.model.gearbox;
    const auto& L = c.model.layout;
    Eigen::Vector2d gear_sum = Eigen::Vector2d::Zero(), weight_sum = Eigen::Vector2d::Zero();
    for (size_t i = 0; i < gb.bearings.size(); ++i)
        if (in_housing(gb.bearings[i])) {
            gear_sum += L.bearing_R_pos[i];
            weight_sum += L.bearing_R_weight[i];
        }
    CHECK(gear_sum.norm() < 1e-9);
    CHECK(std::abs(weight_sum.x()) < 1e-9);
    CHECK(weight_sum.y() == Approx(7 * 2 * 9.80665).epsilon(1e-12));
}
