#include <catch2/catch.hpp>

#include "gearloss/core/errors.hpp"
#include "gearloss/case/config.hpp"
#include "gearloss/model/validate.hpp"
#include "test_support.hpp"

using namespace gearloss;
using test_support::TempConfig;

namespace {
std::string base(const std::string& file = "transfer-box.yaml") {
    return test_support::read_file(test_support::source_path("configs/" + file));
}

struct Expect {
    std::string from, to;          // mutation of the shipped config
    std::string line_of;           // text whose line the error must name ("" = no check)
    std::string key;               // key path the error must name
    std::string message;           // part of the message
    std::string file = "transfer-box.yaml";
    std::string from2 = {}, to2 = {};  // optional second mutation
};

void expect_error(const Expect& e) {
    std::string text = test_support::replace_once(base(e.file), e.from, e.to);
    if (!e.from2.empty()) text = test_support::replace_once(text, e.from2, e.to2);
    TempConfig cfg(text);
    INFO("mutation: '" << e.from << "' -> '" << e.to << "'");
    try {
        (void)io::load_case(cfg.path);
        FAIL("no error raised");
    } catch (const InputError& err) {
        INFO(err.what());
        CHECK(err.file == cfg.path);
        CHECK_THAT(err.key, Catch::Contains(e.key));
        CHECK_THAT(err.message, Catch::Contains(e.message));
        if (!e.line_of.empty()) CHECK(err.line == test_support::line_of(text, e.line_of));
        CHECK(err.line > 0);
    }
}
}  // namespace

TEST_CASE("bad input names file, line and key", "[config]") {
    // Each class of bad input from the issue, one mutation each.
    expect_error({"options:\n", "options:\n  mesh_friction: ehl_local\n", "mesh_friction: schlenk", "options.mesh_friction",
                  "duplicate key"});
    // Vehicle, clutch-pack and thermal-network blocks (gearloss cycle).
    expect_error({"gears: [g1, g2, g3, g4, g5, g6]", "gears: [g1, g2, g7, g4, g5, g6]", "gears: [g1, g2, g7",
                  "vehicle.gears", "not one of gearbox.ratios", "manual-6speed.yaml"});
    expect_error({"f1: 0.9 N/(km/h)", "f1: 0.9 N", "f1: 0.9 N,", "vehicle.road_load.f1", "dimension",
                  "manual-6speed.yaml"});
    expect_error({"[534, 998, 1462, 1925, 2389, 2853, 3317, 3781, 4244]", "[534, 998, 1462]", "[534, 998, 1462]",
                  "vehicle.engine.fuel_map.fuel_rate", "one value per torque", "manual-6speed.yaml"});
    expect_error({"clearance: 0.3 mm, roughness: 1.5 um", "clearance: 0.003 mm, roughness: 1.5 um",
                  "clearance: 0.003 mm", "clutches[0].clearance", "3x the roughness", "automatic-6speed.yaml"});
    expect_error({"    oil: 3 kJ/K\n    housing: 8 kJ/K\n", "    oil: 3 kJ/K\n", "oil_to_housing: 25 W/K",
                  "thermal.network.oil_to_housing", "needs a 'housing' node", "manual-6speed.yaml"});
    expect_error({"speed_ratio:  [0,", "speed_ratio:  [0.1,", "speed_ratio:  [0.1,",
                  "vehicle.torque_converter.speed_ratio", "starts at stall", "automatic-6speed.yaml"});
    expect_error({"teeth: 32,", "teeth: -3,", "name: w1", "gears[0].teeth", "at least 5"});
    expect_error({"module: 3.5 mm, profile_shift: 0.381", "module: 3.5 furlong, profile_shift: 0.381", "name: w1",
                  "gears[0].module", "unknown unit 'furlong'"});
    expect_error({"face_width: 35 mm,   helix_angle: 20 deg, hand: right, material: 15CrNi6, Ra: 0.5 um}",
                  "face_width: 35 kg,   helix_angle: 20 deg, hand: right, material: 15CrNi6, Ra: 0.5 um}", "name: w1",
                  "gears[0].face_width", "expected m"});
    expect_error({"module: 3.5 mm, profile_shift: 0.381", "module: 3.5, profile_shift: 0.381", "name: w1",
                  "gears[0].module", "has no unit"});
    expect_error({"d: 45 mm, D: 100 mm", "d: 45 mm, D: 40 mm", "B5_NJ309E", "bearings[0].D", "must exceed bore"});
    // yaml-cpp marks a block mapping at its first key: the error points into the housing block.
    expect_error({"  oil_volume: 2 L            # seed 001 §3.6\n", "", "oil_level: -30 mm", "housing",
                  "missing required key 'oil_volume'"});
    expect_error({"ambient: 25 degC", "ambient: 25", "ambient: 25", "thermal.ambient", "not a temperature"});
    expect_error({"face_width: 35 mm,   helix_angle: 20 deg, hand: right, material: 15CrNi6, Ra: 0.5 um}",
                  "faze_width: 35 mm,   helix_angle: 20 deg, hand: right, material: 15CrNi6, Ra: 0.5 um}", "name: w1",
                  "gears[0].faze_width", "did you mean 'face_width'"});
    // Profile shift that makes a pointed tooth (FZG pinion, x = 1.9 with the centre distance
    // free: tip thickness -0.15 mm despite the tip shortening); the mesh line is named.
    expect_error({"profile_shift: 0.1817, face_width: 40 mm", "profile_shift: 1.9, face_width: 40 mm", "name: C40",
                  "meshes[0]", "pointed tooth", "fzg-c40-paor.yaml", ", centre_distance: 91.5 mm", ""});
    // Too large a profile-shift sum at a fixed centre distance: the tips are cut so far
    // back that the path of contact no longer passes the pitch point.
    expect_error({"teeth: 23, module: 3.5 mm, profile_shift: 0.415", "teeth: 23, module: 3.5 mm, profile_shift: 2.4",
                  "name: m12", "meshes[0]", "does not pass the pitch point"});
    expect_error({"type: needle_roller, d: 38 mm", "type: needle_rollr, d: 38 mm", "N_w4", "bearings[6].type",
                  "unknown bearing type 'needle_rollr'"});
    expect_error({"low:  {engage: [w5]", "low:  {engage: [w5, w4]", "input: III", "gearbox", "locked"});
    expect_error({"ratio: low", "ratio: medium", "ratio: medium", "gearbox.ratio", "unknown ratio 'medium'"});
    expect_error({"speeds: [600 rpm, 700 rpm, 800 rpm]", "speeds: [600 N*m]", "speeds:", "operating.speeds[0]",
                  "expected 1/s"});
}

TEST_CASE("every remaining message class names file, line, key and what was expected", "[config]") {
    // Choice from a list: the choices are listed.
    expect_error({"mesh_friction: schlenk", "mesh_friction: coulomb", "mesh_friction: coulomb", "options.mesh_friction",
                  "'coulomb' is not one of: schlenk, iso_6336_20, fernandes_mixed"});
    // References to undefined names.
    expect_error({"gears: [w2, w1], angle: 120 deg", "gears: [w2, w9], angle: 120 deg", "name: m12", "meshes[0].gears[1]",
                  "unknown gear 'w9'"});
    expect_error({"material: 15CrNi6, Ra: 0.5 um}\n  - {name: w2", "material: 16MnCr5, Ra: 0.5 um}\n  - {name: w2",
                  "name: w1", "gears[0].material", "unknown material '16MnCr5'; define it under 'materials'"});
    // A referenced oil file that is not there.
    expect_error({"oil: oils/75W90-A.yaml", "oil: oils/missing.yaml", "oil: oils/missing.yaml", "oil",
                  "does not exist"});
    // Shaft statics: an axial load with no locating bearing; three support positions. Found once
    // the train is assembled, they point at a bearing of that shaft, not at the gearbox block.
    expect_error({"position: 130 mm, locating: true}\n  - {name: B3", "position: 130 mm}\n  - {name: B3",
                  "name: B5_NJ309E", "bearings[0]", "no bearing on it is marked 'locating: true'"});
    expect_error({"shaft: II,  position: 130 mm, locating: true}", "shaft: II,  position: 140 mm, locating: true}\n"
                  "  - {name: B9, type: tapered_roller, series: \"323\", d: 30 mm, D: 72 mm, B: 28.75 mm, Y: 1.9, shaft: II, "
                  "position: 60 mm}", "name: B3_32306", "bearings[2].position", "statically determinate"});
    // Numbers where a number is expected.
    expect_error({"teeth: 32,", "teeth: many,", "name: w1", "gears[0].teeth", "expected a whole number, got 'many'"});
    expect_error({"emissivity: 0.9", "emissivity: 1.9", "emissivity: 1.9", "thermal.heat_rejection.housing.emissivity",
                  "emissivity must be in [0, 1]"});
}

TEST_CASE("YAML syntax errors and missing files are input errors", "[config]") {
    TempConfig cfg(test_support::replace_once(base(), "shafts: [III, II, I]", "shafts: [III, II, I"));
    CHECK_THROWS_AS(io::load_case(cfg.path), InputError);
    CHECK_THROWS_WITH(io::load_case("/nonexistent/case.yaml"), Catch::Contains("cannot open file"));
}

TEST_CASE("value lists from the command line", "[config]") {
    const auto v = io::parse_value_list("600,700,800rpm", units::dim::angular_speed, "--speed", "600rpm");
    REQUIRE(v.size() == 3);
    CHECK(v[2] == Catch::Detail::Approx(800 * 3.14159265358979 / 30));
    const auto t = io::parse_value_list("150 N*m, 0.2 kNm", units::dim::torque, "--torque", "150Nm");
    CHECK(t[1] == Catch::Detail::Approx(200));
    CHECK_THROWS_WITH(io::parse_value_list("600,700kg", units::dim::angular_speed, "--speed", "600rpm"),
                      Catch::Contains("--speed"));
}

// Issue 37, items 3, 5 and 6: values read as they are written, at the key that is wrong.
TEST_CASE("angles need their unit, and the key at fault is blamed", "[config][units37]") {
    // A bare number was read as radians: 'angle: 60' = 3438 deg, 'helix_angle: 0.3' = 17.2 deg.
    expect_error({"gears: [w4, w2], angle: 60 deg", "gears: [w4, w2], angle: 60", "name: m24", "meshes[1].angle",
                  "no angle unit"});
    expect_error({"face_width: 35 mm,   helix_angle: 20 deg, hand: right, material: 15CrNi6, Ra: 0.5 um}",
                  "face_width: 35 mm,   helix_angle: 0.3, hand: right, material: 15CrNi6, Ra: 0.5 um}", "name: w1",
                  "gears[0].helix_angle", "no angle unit"});
    // An angle unit where a plain number is meant, and an angle whose units cancel.
    expect_error({"gears: [w4, w2], angle: 60 deg", "gears: [w4, w2], angle: 60 deg/rad", "name: m24",
                  "meshes[1].angle", "not an angle"});
    // A module of 1e-9 mm: the module is out of range (it was "not a single-degree-of-freedom train").
    expect_error({"module: 3.5 mm, profile_shift: 0.381", "module: 1e-9 mm, profile_shift: 0.381", "name: w1",
                  "gears[0].module", "outside 0.05..100 mm"});
    // An addendum coefficient of 5 is blamed on itself (it was blamed on the profile shift).
    expect_error({"helix_angle: 20 deg, hand: right, material: 15CrNi6, Ra: 0.5 um}",
                  "helix_angle: 20 deg, hand: right, material: 15CrNi6, Ra: 0.5 um, addendum_coefficient: 5}", "name: w1",
                  "gears[0].addendum_coefficient", "addendum coefficient 5 outside"});
    // Ra 1e-300 um gave lambda 7e299 and 'ok'.
    expect_error({"material: 15CrNi6, Ra: 0.5 um}\n  - {name: w2", "material: 15CrNi6, Ra: 1e-300 um}\n  - {name: w2",
                  "name: w1", "gears[0].Ra", "below 0.001 um"});
    // -273.15 degC is absolute zero, not "not a temperature".
    expect_error({"ambient: 25 degC", "ambient: -273.15 degC", "ambient: -273.15", "thermal.ambient", "absolute zero"});
    // A heat capacity per degree Celsius is a heat capacity per kelvin (it was "unknown unit 'degC'").
    const std::string tb = base("manual-6speed.yaml");
    TempConfig per_degC(test_support::replace_once(tb, "    oil: 3 kJ/K\n", "    oil: 3 kJ/degC\n"));
    TempConfig per_K(tb);
    CHECK(io::load_case(per_degC.path).model.thermal.network.C_oil == 3000.0);
    CHECK(io::load_case(per_K.path).model.thermal.network.C_oil == 3000.0);
}

TEST_CASE("YAML tags and control characters are errors at their line", "[config][units37]") {
    // yaml-cpp dropped a tag without a word: '!unit 3.5 mm' read as 3.5 mm, '!!binary' as its text.
    expect_error({"module: 3.5 mm, profile_shift: 0.381", "module: !unit 3.5 mm, profile_shift: 0.381", "name: w1", "",
                  "YAML tag"});
    expect_error({"name: Transfer gearbox", "name: !!binary VHJhbnNmZXI=", "name: !!binary", "", "YAML tag"});
    // A NUL and an ESC written as escapes inside a quoted value (a designation, a file name).
    expect_error({"oil: oils/75W90-A.yaml", "oil: \"oils/75W90-A.yaml\\0.txt\"", "oil: \"oils", "", "control character"});
    expect_error({"name: Transfer gearbox", "name: \"Transfer \\e[31m gearbox\"", "name: \"Transfer", "",
                  "control character"});
}

TEST_CASE("oil tables: a temperature twice or out of order is an error at its line", "[config][units37]") {
    // One temperature twice in the piezoviscosity table divided by zero: alpha_p(40 degC) = -nan.
    const std::string oil = test_support::read_file(test_support::source_path("configs/oils/75W90-A.yaml"));
    const auto expect_oil_error = [](const std::string& text, const std::string& line_of, const std::string& message) {
        TempConfig cfg(text);
        try {
            (void)io::load_oil_file(cfg.path);
            FAIL("no error raised");
        } catch (const InputError& e) {
            INFO(e.what());
            CHECK(e.line == test_support::line_of(text, line_of));
            CHECK_THAT(e.message, Catch::Contains(message));
        }
    };
    expect_oil_error(test_support::replace_once(oil, "[70 degC, 1.194e-8 1/Pa]", "[40 degC, 1.194e-8 1/Pa]"),
                     "[40 degC, 1.194e-8 1/Pa]", "listed twice");
    expect_oil_error(test_support::replace_once(oil, "[70 degC, 1.194e-8 1/Pa]", "[30 degC, 1.194e-8 1/Pa]"),
                     "[30 degC, 1.194e-8 1/Pa]", "ascending order");
    expect_oil_error(test_support::replace_once(oil, "[70 degC, 36.7 cSt]", "[40 degC, 36.7 cSt]"),
                     "[40 degC, 36.7 cSt]", "listed twice");
    expect_oil_error(test_support::replace_once(oil, "[70 degC, 36.7 cSt]", "[120 degC, 36.7 cSt]"),
                     "[100 degC, 16.37 cSt]", "ascending order");
}

TEST_CASE("value lists: one unit rule, kinds checked, the option named", "[config][units37]") {
    using units::dim::angular_speed;
    using units::dim::torque;
    // "1000rpm,5" mixes an item with a unit and one without (5 rad? 5 rpm?).
    CHECK_THROWS_WITH(io::parse_value_list("1000rpm,5", angular_speed, "--speed", "600rpm"),
                      Catch::Contains("--speed: ") && Catch::Contains("mixes items"));
    CHECK_THROWS_WITH(io::parse_value_list("600rpm,700,800rpm", angular_speed, "--speed", "600rpm"),
                      Catch::Contains("mixes items"));
    // A comma separates items; the unit of the last applies to the bare ones (documented).
    CHECK(io::parse_value_list("1000,5rpm", angular_speed, "--speed", "600rpm").size() == 2);
    // 200 Wh has the dimension of a torque (720 000 N m); 1000 rpm/rev that of a speed (159 rpm).
    CHECK_THROWS_WITH(io::parse_value_list("200 Wh", torque, "--torque", "250Nm"), Catch::Contains("not a torque"));
    CHECK_THROWS_WITH(io::parse_value_list("200 J", torque, "--torque", "250Nm"), Catch::Contains("not a torque"));
    CHECK_THROWS_WITH(io::parse_value_list("1000 rpm/rev", angular_speed, "--speed", "600rpm"),
                      Catch::Contains("not a rotational speed"));
    // The message starts with the option, not with "<input>".
    try {
        (void)io::parse_value_list("200 Wh", torque, "--torque", "250Nm");
    } catch (const InputError& e) {
        CHECK(std::string(e.what()).rfind("--torque: ", 0) == 0);
    }
}

TEST_CASE("the stated ambient range includes its ends as written in degC", "[config][units37]") {
    // -100 degC is 173.14999999999998 K after the offset: "-100 degC is outside -100..300 degC".
    CHECK_FALSE(solver::ambient_fault(-100.0 + 273.15));
    CHECK_FALSE(solver::ambient_fault(300.0 + 273.15));
    CHECK(solver::ambient_fault(-100.01 + 273.15));
}

TEST_CASE("the cooler's coolant capacity rate: read with an exchanger, refused elsewhere", "[config][cooler]") {
    const std::string housing = "  heat_rejection:\n";
    auto cooler = [&](const std::string& c) { return "  cooler: " + c + "\n" + housing; };
    // A counterflow exchanger: UA, the coolant's inlet and capacity rate, the oil's flow.
    {
        TempConfig cfg(test_support::replace_once(
            base(), housing,
            cooler("{ua: 5.25 kW/K, coolant_temperature: 35 degC, oil_flow: 100 L/min, coolant_capacity_rate: 3.344 kW/K}")));
        const auto c = io::load_case(cfg.path);
        CHECK(c.model.thermal.cooler.kind == thermal::Cooler::Kind::exchanger);
        CHECK(c.model.thermal.cooler.coolant_capacity_rate == Catch::Detail::Approx(3344.0).epsilon(1e-12));
    }
    const std::string rate = "coolant_capacity_rate: 3 kW/K";
    expect_error({housing, cooler("{ua: 500 W/K, coolant_temperature: 30 degC, " + rate + "}"), rate,
                  "thermal.cooler.coolant_capacity_rate", "needs 'oil_flow'"});
    expect_error({housing, cooler("{oil_flow: 10 L/min, inlet_temperature: 40 degC, " + rate + "}"), rate,
                  "thermal.cooler.coolant_capacity_rate", "needs 'ua'"});
    expect_error({housing, cooler("{duty: 2 kW, " + rate + "}"), "duty: 2 kW", "thermal.cooler", "not both"});
    expect_error({housing, cooler("{ua: 500 W/K, coolant_temperature: 30 degC, oil_flow: 10 L/min, "
                                  "coolant_capacity_rate: 0 W/K}"),
                  "coolant_capacity_rate: 0", "thermal.cooler.coolant_capacity_rate", "must be positive"});
    expect_error({housing, cooler("{ua: 500 W/K, coolant_temperature: 30 degC, oil_flow: 10 L/min, "
                                  "coolant_capacity_rate: 3 kW}"),
                  "coolant_capacity_rate: 3 kW", "thermal.cooler.coolant_capacity_rate", ""});
}
