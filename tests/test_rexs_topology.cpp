// The gear-train topology of the REXS import (lib/gearloss/rexs/case_mapper.cpp, planetary.cpp):
// planetary stages, idlers, several stages, two gears on one shaft and the names of older REXS
// versions, on the hand-made models of tests/data/rexs (handmade_*.rexs, documented in their
// header comments and the folder's README). Each imported case is loaded by the case loader and
// its kinematics compared with a ratio worked out by hand below from the tooth numbers; hostile
// forms of the models give errors naming the component.
#include <catch2/catch.hpp>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>
#include <unistd.h>

#include "gearloss/core/errors.hpp"
#include "gearloss/case/config.hpp"
#include "rexs_test_support.hpp"
#include "gearloss/rexs/case_mapper.hpp"
#include "gearloss/rexs/reader.hpp"

using namespace gearloss;
using namespace rexs_test;

namespace {

// The imported case loaded as gearloss loads a hand-written one (case and oil in a temporary folder).
io::Case imported(const rexs::ImportResult& r, const std::string& tag) {
    const auto dir = std::filesystem::temp_directory_path() / ("gearloss-rexs-" + tag + "-" + std::to_string(::getpid()));
    std::filesystem::create_directories(dir);
    std::ofstream(dir / "case.yaml") << r.case_yaml;
    std::ofstream(dir / "case.oil.yaml") << r.oil_yaml;
    auto c = io::load_case((dir / "case.yaml").string());
    std::filesystem::remove_all(dir);
    return c;
}

rexs::ImportResult import_text(const std::string& xml, const std::string& name) {
    rexs::ImportOptions o;
    o.oil_reference = "case.oil.yaml";
    return rexs::map_to_case(rexs::parse_xml(xml, name), o);
}

// Speed of shaft `name` per unit input speed (signed) in the loaded case.
double speed_of(const io::Case& c, const std::string& name) {
    const auto& gb = c.model.gearbox;
    for (size_t s = 0; s < gb.shafts.size(); ++s)
        if (gb.shafts[s].name == name) return c.model.layout.body_speed_ratio[c.model.layout.body_of_shaft[s]];
    FAIL("no shaft " << name);
    return 0;
}

}  // namespace

TEST_CASE("rexs: a planetary stage maps onto gearloss's planetary set", "[rexs]") {
    const auto r = import_text(slurp(data("handmade_planetary_1-4.rexs")), "handmade_planetary_1-4.rexs");
    INFO(r.case_yaml);
    CHECK(r.case_yaml.find("carrier: shaft_12") != std::string::npos);
    CHECK(r.case_yaml.find("planets: 3") != std::string::npos);
    CHECK(r.case_yaml.find("{name: shaft_13, fixed: true}") != std::string::npos);
    CHECK(r.case_yaml.find("under_gear: gear_24") != std::string::npos);
    const auto c = imported(r, "planetary");
    const auto& gb = c.model.gearbox;
    // Sun 16, ring 62, ring held: n_carrier / n_sun = z_s / (z_s + z_r) = 16 / 78 = 0.2051282
    // (ratio 1 + z_r / z_s = 4.875), carrier turning the same way as the sun.
    CHECK(c.model.layout.ratio == Approx(16.0 / 78.0).epsilon(1e-12));
    CHECK(speed_of(c, "shaft_13") == Approx(0).margin(1e-12));
    // Planet relative to the carrier: (n_p - n_c) = -(z_s / z_p)(n_s - n_c) = -(16/23)(1 - 16/78) = -0.553289.
    int planet = -1;
    for (size_t g = 0; g < gb.gears.size(); ++g)
        if (gb.gears[g].is_planet()) planet = static_cast<int>(g);
    REQUIRE(planet >= 0);
    CHECK(gb.gears[static_cast<size_t>(planet)].planets == 3);
    const double np = c.model.layout.body_speed_ratio[c.model.layout.body_of_gear[static_cast<size_t>(planet)]];
    CHECK(np - 16.0 / 78.0 == Approx(-(16.0 / 23.0) * (1 - 16.0 / 78.0)).epsilon(1e-12));
    // One needle bearing per planet, listed once and run in each of the three planets.
    int planet_bearings = 0;
    for (const auto& b : gb.bearings)
        if (b.under_gear == planet) {
            ++planet_bearings;
            CHECK(b.multiplicity == 3);
        }
    CHECK(planet_bearings == 1);
    CHECK(gb.bearings.size() == 5);  // two on the sun shaft, two on the carrier, the planets'
}

TEST_CASE("rexs: the planetary stage in REXS 1.2 names gives the same case", "[rexs]") {
    const auto a = import_text(slurp(data("handmade_planetary_1-4.rexs")), "p.rexs");
    const auto b = import_text(slurp(data("handmade_planetary_1-2.rexs")), "p.rexs");
    const auto body = [](const std::string& y) { return y.substr(y.find('\n') + 1); };
    CHECK(body(a.case_yaml) == body(b.case_yaml));
}

TEST_CASE("rexs: an idler, three stages and two gears on one shaft", "[rexs]") {
    for (const char* file : {"handmade_idler_3stage_1-4.rexs", "handmade_idler_3stage_1-2.rexs", "handmade_idler_3stage_1-0.rexs"}) {
        INFO(file);
        const auto r = import_text(slurp(data(file)), file);
        const auto c = imported(r, "idler");
        // A (20) -> idler B (31) -> C (40); D (18) on C's shaft -> E (45):
        // n_B = -20/31, n_C = (-20/31)(-31/40) = +0.5, n_E = 0.5 (-18/45) = -0.2 (three external meshes: reversed).
        CHECK(speed_of(c, "shaft_12") == Approx(-20.0 / 31.0).epsilon(1e-12));
        CHECK(speed_of(c, "shaft_13") == Approx(0.5).epsilon(1e-12));
        CHECK(c.model.layout.ratio == Approx(-0.2).epsilon(1e-12));
        CHECK(c.model.gearbox.meshes.size() == 3);
    }
    // REXS 1.2 (flank_geometry) and 1.4 (cylindrical_gear_flank) name the flanks differently: the same case.
    const auto a = import_text(slurp(data("handmade_idler_3stage_1-4.rexs")), "i.rexs");
    const auto b = import_text(slurp(data("handmade_idler_3stage_1-2.rexs")), "i.rexs");
    CHECK(a.case_yaml.substr(a.case_yaml.find('\n')) == b.case_yaml.substr(b.case_yaml.find('\n')));
    CHECK(a.case_yaml.find("REXS flanks 211/212 normal_pressure_angle") != std::string::npos);
    // REXS 1.0 calls the bearing's catalogue designation 'name': the same bearings (6206 from the catalogue).
    const auto z = import_text(slurp(data("handmade_idler_3stage_1-0.rexs")), "i.rexs");
    std::string z14 = a.case_yaml.substr(a.case_yaml.find('\n'));
    for (size_t q; (q = z14.find(" catalogue_designation (catalogue row")) != std::string::npos;) z14.replace(q, 22, " name");
    CHECK(z.case_yaml.substr(z.case_yaml.find('\n')) == z14);
    CHECK(z.case_yaml.find("designation: \"6206\"   ") != std::string::npos);
}

TEST_CASE("rexs: planetary stages gearloss cannot represent are refused at the component", "[rexs]") {
    const std::string xml = slurp(data("handmade_planetary_1-4.rexs"));
    const auto err = [&](const std::string& text) { return error_of([&] { (void)import_text(text, "h.rexs"); }); };
    // The stage without its carrier relation: the planets are carried by nothing.
    std::string no_carrier = xml;
    const auto p = no_carrier.find("type=\"planet_carrier_shaft\"");
    REQUIRE(p != std::string::npos);
    no_carrier.replace(p, 27, "type=\"no_such_relation_type\"");
    CHECK_THAT(err(no_carrier), Catch::Matches("h\\.rexs:[0-9]+: component 5 \\(planetary_stage 'Planetary stage'\\): no planet_carrier_shaft.*"));
    // The ring as an external cylindrical gear (positive teeth, not a ring_gear): named as a misplaced ring.
    std::string external_ring = xml;
    for (size_t q; (q = external_ring.find("ring_gear")) != std::string::npos;) external_ring.replace(q, 9, "cylindrical_gear");
    CHECK_THAT(err(external_ring), Catch::Matches(".*component 23 \\(cylindrical_gear 'Ring'\\): .*external gear \\(number_of_teeth 62\\).*"));
    // A stepped planet: a second gear (planet 2's) on planet shaft 14.
    const std::string stepped = replaced(xml, "<ref hint=\"shaft\" id=\"16\" role=\"assembly\"/>\n      <ref hint=\"cylindrical_gear\" id=\"25\"",
                                         "<ref hint=\"shaft\" id=\"14\" role=\"assembly\"/>\n      <ref hint=\"cylindrical_gear\" id=\"25\"");
    CHECK_THAT(err(stepped), Catch::Contains("component 14 (shaft 'Planet shaft 1')") && Catch::Contains("stepped planet"));
    // Planets not equally spaced: planet shaft 16 and its pin moved to another angle on the same circle.
    const std::string moved = replaced(replaced(xml, "<c>-24.375</c>\n          <c>42.218738</c>", "<c>0</c>\n          <c>48.75</c>"),
                                       "<c>-24.375</c>\n          <c>42.218738</c>", "<c>0</c>\n          <c>48.75</c>");
    CHECK_THAT(err(moved), Catch::Contains("component 5 (planetary_stage") && Catch::Contains("not equally spaced"));
    // A ring of 63 teeth: z_sun + z_ring = 79 is no multiple of the 3 planets (the stage is named).
    const std::string phase = replaced(xml, "<attribute id=\"number_of_teeth\" unit=\"\">62</attribute>", "<attribute id=\"number_of_teeth\" unit=\"\">63</attribute>");
    CHECK_THAT(err(phase), Catch::Contains("component 5 (planetary_stage") && Catch::Contains("z_sun + z_ring = 79"));
    // A planet whose teeth differ from the others'.
    const std::string odd = replaced(xml, "<component id=\"25\" name=\"Planet 2\" type=\"cylindrical_gear\">\n      <attribute id=\"number_of_teeth\" unit=\"\">23",
                                     "<component id=\"25\" name=\"Planet 2\" type=\"cylindrical_gear\">\n      <attribute id=\"number_of_teeth\" unit=\"\">24");
    CHECK_THAT(err(odd), Catch::Contains("component 25 (cylindrical_gear 'Planet 2')") && Catch::Contains("differs from planet 24"));
}

TEST_CASE("rexs: the held member and the direction of a planetary stage", "[rexs]") {
    const std::string xml = slurp(data("handmade_planetary_1-4.rexs"));
    // The carrier held (REXS rotational_speed 0 on its shaft) and the ring the output: a stationary
    // train, n_ring / n_sun = -z_s / z_r = -16 / 62 = -0.258065 (Willis: the ring turns against the sun).
    std::string held = replaced(xml, "<component id=\"12\" name=\"Carrier shaft\" type=\"shaft\">",
                                "<component id=\"12\" name=\"Carrier shaft\" type=\"shaft\">\n      <attribute id=\"rotational_speed\" "
                                "unit=\"1 / min\">0</attribute>");
    held = replaced(held, "<ref hint=\"shaft\" id=\"12\" role=\"assembly\"/>\n      <ref hint=\"external_load\" id=\"42\"",
                    "<ref hint=\"shaft\" id=\"13\" role=\"assembly\"/>\n      <ref hint=\"external_load\" id=\"42\"");
    const auto r = import_text(held, "held.rexs");
    CHECK(r.case_yaml.find("{name: shaft_12, fixed: true}") != std::string::npos);
    CHECK(r.case_yaml.find("REXS 12 rotational_speed 0: held by the housing") != std::string::npos);
    const auto c = imported(r, "held");
    CHECK(c.model.layout.ratio == Approx(-16.0 / 62.0).epsilon(1e-12));
    // A torque-transmitting load on the ring too: three driven members (a summing stage), refused at the stage.
    const std::string summing =
        replaced(xml, "<ref hint=\"shaft\" id=\"12\" role=\"assembly\"/>\n      <ref hint=\"external_load\" id=\"42\"",
                 "<ref hint=\"shaft\" id=\"12\" role=\"assembly\"/>\n      <ref hint=\"external_load\" id=\"42\" role=\"part\"/>\n    "
                 "</relation>\n    <relation id=\"998\" type=\"assembly\">\n      <ref hint=\"shaft\" id=\"13\" role=\"assembly\"/>\n      "
                 "<ref hint=\"external_load\" id=\"42\"");
    CHECK_THAT(error_of([&] { (void)import_text(summing, "s.rexs"); }),
               Catch::Contains("component 5 (planetary_stage 'Planetary stage')") && Catch::Contains("three driven members"));
}

TEST_CASE("rexs: two planetary stages in series", "[rexs]") {
    const auto r = import_text(slurp(data("handmade_planetary_two_stage_1-4.rexs")), "two.rexs");
    const auto c = imported(r, "two");
    // Stage 5: n_c / n_s = 16 / (16 + 62); stage 7 on its carrier: 19 / (19 + 71).
    // n_out / n_in = (16 / 78)(19 / 90) = 0.0433048 (i = 4.875 x 4.736842 = 23.0921).
    CHECK(c.model.layout.ratio == Approx((16.0 / 78.0) * (19.0 / 90.0)).epsilon(1e-12));
    CHECK(speed_of(c, "shaft_12") == Approx(16.0 / 78.0).epsilon(1e-12));
    CHECK(speed_of(c, "shaft_13") == Approx(0).margin(1e-12));
    CHECK(speed_of(c, "shaft_53") == Approx(0).margin(1e-12));
}

namespace {

// The speed of bearing `name` per unit input speed in the loaded case (the ring speed its
// friction is taken at).
double bearing_speed_of(const io::Case& c, const std::string& name) {
    const auto& gb = c.model.gearbox;
    for (size_t i = 0; i < gb.bearings.size(); ++i)
        if (gb.bearings[i].name == name) return c.model.layout.bearing_speed_ratio[i];
    FAIL("no bearing " << name);
    return 0;
}

bool warned_about(const rexs::ImportResult& r, const std::string& component, const std::string& text) {
    for (const auto& w : r.warnings)
        if (w.find("component " + component + " ") != std::string::npos && w.find(text) != std::string::npos) return true;
    return false;
}

}  // namespace

TEST_CASE("rexs: a pilot bearing between two coaxial shafts runs at their relative speed", "[rexs][pilot]") {
    // handmade_coaxial_pilot_1-4.rexs: input shaft 11 (z 20) -> layshaft 12 (z 40 | z 20) -> output
    // shaft 13 (z 40), coaxial with the input. n_12 / n_11 = -20/40 = -0.5 and
    // n_13 / n_11 = (-20/40)(-20/40) = +0.25 (two external meshes: the same sense as the input).
    // Pilot bearing 117 (inner ring on shaft 11, outer ring in shaft 13's hub) turns at
    // |1 - 0.25| = 0.75 of the input speed; the input shaft's speed (1.0) or the output's (0.25)
    // would be wrong.
    const auto r = import_text(slurp(data("handmade_coaxial_pilot_1-4.rexs")), "pilot.rexs");
    INFO(r.case_yaml);
    CHECK(r.case_yaml.find("outer_shaft: shaft_13") != std::string::npos);
    // Its place along the output shaft, in that shaft's own u (u_coordinate_on_shaft_outer_side
    // = 15 mm), where its reaction loads the output shaft; 115 mm is its place on the input shaft.
    CHECK(r.case_yaml.find("outer_position: 15 mm") != std::string::npos);
    CHECK_FALSE(warned_about(r, "117", "against the housing"));
    const auto c = imported(r, "pilot");
    CHECK(speed_of(c, "shaft_13") == Approx(0.25).epsilon(1e-12));
    CHECK(bearing_speed_of(c, "bearing_117") == Approx(0.75).epsilon(1e-12));
    CHECK(bearing_speed_of(c, "bearing_115") == Approx(1.0).epsilon(1e-12));
    CHECK(bearing_speed_of(c, "bearing_135") == Approx(0.25).epsilon(1e-12));
}

TEST_CASE("rexs: a pilot bearing between the sun and the carrier runs at their relative speed", "[rexs][pilot]") {
    // Sun bearing B (116) with its outer ring in the carrier shaft 12 instead of the casing. Sun 16,
    // ring 62 held, carrier the output: n_c / n_s = 16 / (16 + 62) = 0.205128, so the bearing turns
    // at 1 - 16/78 = 62/78 = 0.794872 of the input speed.
    const std::string xml =
        replaced(slurp(data("handmade_planetary_1-4.rexs")),
                 "<ref hint=\"rolling_bearing_with_catalog_geometry\" id=\"116\" role=\"assembly\"/>\n      <ref hint=\"shaft\" id=\"11\" "
                 "role=\"inner_part\"/>\n      <ref hint=\"gear_casing\" id=\"2\" role=\"outer_part\"/>",
                 "<ref hint=\"rolling_bearing_with_catalog_geometry\" id=\"116\" role=\"assembly\"/>\n      <ref hint=\"shaft\" id=\"11\" "
                 "role=\"inner_part\"/>\n      <ref hint=\"shaft\" id=\"12\" role=\"outer_part\"/>");
    const auto r = import_text(xml, "pilot.rexs");
    INFO(r.case_yaml);
    CHECK_FALSE(warned_about(r, "116", "against the housing"));
    CHECK(r.case_yaml.find("under_gear: gear_21") == std::string::npos);
    CHECK(r.case_yaml.find("outer_shaft: shaft_12") != std::string::npos);
    const auto c = imported(r, "sunpilot");
    CHECK(bearing_speed_of(c, "bearing_116") == Approx(62.0 / 78.0).epsilon(1e-12));
}
