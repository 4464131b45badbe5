// A pilot bearing between two shafts (`outer_shaft`, docs/config.md "Pilot bearings"): its
// frictional moment is taken at the relative speed of the two shafts, checked against a hand
// calculation of the SKF (2004) seal moment, which does not depend on speed or load, so the
// bearing's power is that moment times the relative speed alone. Bad `outer_shaft` values give
// errors naming the file, line and key.
#include <catch2/catch.hpp>
#include <numbers>
#include <string>

#include "gearloss/case/config.hpp"
#include "gearloss/core/errors.hpp"
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
std::string coaxial_case(const std::string& pilot_extra = "outer_shaft: out") {
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
    const std::string own = message(coaxial_case("outer_shaft: in"));
    CHECK_THAT(own, Catch::Contains("pilot.yaml:") && Catch::Contains("outer_shaft") && Catch::Contains("own shaft 'in'"));
    // A shaft the case does not have.
    const std::string unknown = message(coaxial_case("outer_shaft: hub"));
    CHECK_THAT(unknown, Catch::Contains("pilot.yaml:") && Catch::Contains("outer_shaft") && Catch::Contains("unknown shaft 'hub'"));
    // With under_gear (a bearing under a free gear or planet is not a pilot bearing).
    auto free_gear = test_support::replace_once(coaxial_case("outer_shaft: out, under_gear: A"), "face_width: 30 mm, mass",
                                                "face_width: 30 mm, mount: free, mass");
    const std::string both = message(free_gear);
    CHECK_THAT(both, Catch::Contains("pilot.yaml:") && Catch::Contains("outer_shaft") && Catch::Contains("not both"));
}
