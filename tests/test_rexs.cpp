// The REXS reader (lib/gearloss/rexs/reader.hpp) and mapper (case_mapper.hpp) on the FVA example
// models (tests/data/rexs, Apache-2.0): XML and JSON of the same gearbox give the same model
// values and the same case; hostile files give InputErrors naming the file and the component.
// The numbers expected below are read off the files by eye (gear 15: 27 teeth, m_n 4.5 mm,
// beta +21 deg; stage 19: a = 190 mm), not computed by the code under test.
#include <catch2/catch.hpp>
#include <fstream>
#include <iterator>
#include <numbers>
#include <string>

#include "gearloss/core/errors.hpp"
#include "rexs_test_support.hpp"
#include "gearloss/rexs/case_mapper.hpp"
#include "gearloss/rexs/reader.hpp"
#include "gearloss/rexs/units.hpp"

using namespace gearloss;
using namespace rexs_test;

namespace {

// The case text without the header line that names the model file.
std::string body(const std::string& yaml) { return yaml.substr(yaml.find('\n') + 1); }

}  // namespace

TEST_CASE("rexs: the FVA two-stage gearbox read from XML and JSON", "[rexs]") {
    const auto x = rexs::read_model(data("FVA-Industriegetriebe_2stufig_1-4.rexs"));
    const auto j = rexs::read_model(data("FVA-Industriegetriebe_2stufig_1-4.rexsj"));
    CHECK(x.version == "1.4");
    CHECK(j.version == "1.4");
    CHECK(x.components.size() == j.components.size());
    CHECK(x.relations.size() == j.relations.size());
    CHECK(x.load_cases.size() == 4);
    for (const auto* m : {&x, &j}) {
        const auto& g = m->at(15);
        CHECK(g.type == "cylindrical_gear");
        CHECK(rexs::integer(*m, g, "number_of_teeth") == 27);
        CHECK(rexs::quantity(*m, g, "normal_module", rexs::Quantity::length).value() == Approx(4.5e-3));
        CHECK(rexs::quantity(*m, g, "helix_angle_reference_diameter", rexs::Quantity::angle).value() ==
              Approx(21 * std::numbers::pi / 180));
        const auto& lub = m->at(56);
        // 0.88 kg/dm^3 = 880 kg/m^3; 100 mm^2/s = 1e-4 m^2/s.
        CHECK(rexs::quantity(*m, lub, "density_at_15_degree_celsius", rexs::Quantity::density).value() == Approx(880));
        CHECK(rexs::quantity(*m, lub, "viscosity_at_40_degree_celsius", rexs::Quantity::kinematic_viscosity).value() ==
              Approx(1e-4));
        CHECK(rexs::boolean(*m, m->at(12), "defines_speed") == true);
        CHECK(rexs::text(*m, m->at(33), "catalogue_designation") == "6210-2Z");
        CHECK(rexs::numbers(*m, m->at(13), "support_vector").value() == std::vector<double>{-25, 0, -190});
    }
    rexs::ImportOptions o;
    o.oil_reference = "fva.oil.yaml";
    const auto cx = rexs::map_to_case(x, o);
    const auto cj = rexs::map_to_case(j, o);
    CHECK(body(cx.case_yaml) == body(cj.case_yaml));
    CHECK(body(cx.oil_yaml) == body(cj.oil_yaml));
    CHECK(cx.case_yaml.find("centre_distance: 190 mm") != std::string::npos);
    CHECK(cx.case_yaml.find("hand: right") != std::string::npos);
}

TEST_CASE("rexs: REXS 1.6 and the zipped example read", "[rexs]") {
    const auto m = rexs::read_model(data("FVA-Industriegetriebe_2_stufig_1-6.rexs"));  // with a byte-order mark
    CHECK(m.version == "1.6");
    CHECK(m.of_type("cylindrical_gear").size() == 4);
    const auto z = rexs::read_model(data("example_xml.rexs.zip"));
    CHECK(z.file.find("example_xml.rexs.zip:example.rexs") != std::string::npos);
    CHECK(!z.components.empty());
}

TEST_CASE("rexs: the worm stage is refused naming its component", "[rexs]") {
    const auto m = rexs::read_model(data("FVA_worm_stage_1-4.rexs"));
    const std::string e = error_of([&] { (void)rexs::map_to_case(m, {}); });
    CHECK_THAT(e, Catch::Matches(".*FVA_worm_stage_1-4\\.rexs:[0-9]+: component 3 \\(worm_stage 'Schneckenstufe.*'\\): .*not represented.*"));
}

TEST_CASE("rexs: hostile files give clean errors with the file and the component", "[rexs]") {
    const std::string xml = slurp(data("FVA-Industriegetriebe_2stufig_1-4.rexs"));
    const std::string json = slurp(data("FVA-Industriegetriebe_2stufig_1-4.rexsj"));
    CHECK_THAT(error_of([&] { (void)rexs::parse_xml(xml.substr(0, xml.size() / 2), "half.rexs"); }),
               Catch::Matches("half\\.rexs:[0-9]+: not well-formed XML.*"));
    CHECK_THAT(error_of([&] { (void)rexs::parse_json(json.substr(0, json.size() / 2), "half.rexsj"); }),
               Catch::StartsWith("half.rexsj: not valid JSON"));
    CHECK_THAT(error_of([&] { (void)rexs::parse_xml(replaced(xml, "version=\"1.4\"", "version=\"2.0\""), "v.rexs"); }),
               Catch::Contains("v.rexs: model.version: REXS version '2.0' is not read"));
    CHECK_THAT(error_of([&] { (void)rexs::parse_json(replaced(json, "\"version\": \"1.4\"", "\"version\": \"0.9\""), "v.rexsj"); }),
               Catch::Contains("REXS version '0.9'"));
    CHECK_THAT(error_of([&] {
                   (void)rexs::parse_xml(replaced(xml, "<ref hint=\"cylindrical_gear\" id=\"15\" role=\"part\"/>",
                                                  "<ref hint=\"cylindrical_gear\" id=\"999\" role=\"part\"/>"),
                                         "r.rexs");
               }),
               Catch::Matches("r\\.rexs:[0-9]+: relation 5 \\(assembly\\): .*component 999.*"));
    CHECK_THAT(error_of([&] { (void)rexs::parse_xml(replaced(xml, "<component id=\"14\"", "<component id=\"13\""), "d.rexs"); }),
               Catch::Contains("duplicate component id 13"));
    // Nesting: 100 levels inside <components> (XML) and inside an attribute (JSON).
    std::string open, close;
    for (int i = 0; i < 100; ++i) open += "<x>", close += "</x>";
    CHECK_THAT(error_of([&] { (void)rexs::parse_xml(replaced(xml, "<components>", "<components>" + open + close), "n.rexs"); }),
               Catch::Contains("nested deeper than"));
    CHECK_THAT(error_of([&] {
                   (void)rexs::parse_json(replaced(json, "\"model\": {", "\"deep\": " + std::string(100, '[') +
                                                                          std::string(100, ']') + ", \"model\": {"),
                                          "n.rexsj");
               }),
               Catch::Contains("nested deeper than"));
    // A bearing outside its shaft and a centre distance the shafts' axes contradict.
    const auto outside = rexs::parse_xml(
        replaced(xml, "<attribute id=\"u_coordinate_on_shaft_inner_side\" unit=\"mm\">65</attribute>",
                 "<attribute id=\"u_coordinate_on_shaft_inner_side\" unit=\"mm\">650</attribute>"),
        "o.rexs");
    CHECK_THAT(error_of([&] { (void)rexs::map_to_case(outside, {}); }),
               Catch::Matches("o\\.rexs:[0-9]+: component 33 .*outside shaft 12.*"));
    const auto apart = rexs::parse_xml(replaced(xml, "<attribute id=\"center_distance\" unit=\"mm\">190</attribute>",
                                                "<attribute id=\"center_distance\" unit=\"mm\">200</attribute>"),
                                       "a.rexs");
    CHECK_THAT(error_of([&] { (void)rexs::map_to_case(apart, {}); }),
               Catch::Matches("a\\.rexs:[0-9]+: component 19 .*center_distance 200 mm.*190 mm apart.*"));
}

TEST_CASE("rexs: units are converted from each attribute's unit", "[rexs]") {
    // 1 / min -> rad/s: 60 rpm = 2 pi rad/s; C -> K; mum -> m; kg / dm^3 -> kg/m^3; a length in deg is no length.
    CHECK(rexs::to_si(60, "1 / min", rexs::Quantity::rotational_speed).value() == Approx(2 * std::numbers::pi));
    CHECK(rexs::to_si(70, "C", rexs::Quantity::temperature).value() == Approx(343.15));
    CHECK(rexs::to_si(0.4, "mum", rexs::Quantity::length).value() == Approx(0.4e-6));
    CHECK(rexs::to_si(0.88, "kg / dm^3", rexs::Quantity::density).value() == Approx(880));
    CHECK(!rexs::to_si(20, "deg", rexs::Quantity::length));
}

TEST_CASE("rexs: coded arrays decode", "[rexs]") {
    // Encoded by hand (Python: base64.b64encode(struct.pack('<d', 1.0)) and so on).
    CHECK(rexs::decode_coded_array("float64", "AAAAAAAA8D8=").value() == std::vector<double>{1.0});
    CHECK(rexs::decode_coded_array("int32", "AQAAAP7///8=").value() == std::vector<double>{1.0, -2.0});
    CHECK(rexs::decode_coded_array("float32", "AAAAPw==").value() == std::vector<double>{0.5});
    CHECK(!rexs::decode_coded_array("float64", "AQAAAP7///8="));  // these 8 bytes as a float64 are a NaN
    CHECK(!rexs::decode_coded_array("int64", "AAAAAAAA8D8="));     // not a REXS code
    CHECK(!rexs::decode_coded_array("int32", "AQAAAP7///"));       // 10 characters, 7 bytes: not whole values
    CHECK(!rexs::decode_coded_array("int32", "AQ*AAP7///8="));     // not base64
}

TEST_CASE("rexs: an attribute written without a value reads as absent", "[rexs]") {
    // FVA-Workbench writes attributes it has no value for as an empty XML element or a JSON null
    // (its worm-stage export: `"enum": null`); REXS gives them no value, so they read as absent,
    // as if not written. Gear 16's tip_diameter (1 mm in the file) emptied both ways:
    const std::string xml = slurp(data("FVA-Industriegetriebe_2stufig_1-4.rexs"));
    const std::string json = slurp(data("FVA-Industriegetriebe_2stufig_1-4.rexsj"));
    const auto x = rexs::parse_xml(replaced(xml, "<attribute id=\"tip_diameter\" unit=\"mm\">1</attribute>",
                                            "<attribute id=\"tip_diameter\" unit=\"mm\"/>"),
                                   "e.rexs");
    const auto j = rexs::parse_json(replaced(json, "\"id\": \"tip_diameter\",\n                        \"unit\": \"mm\",\n"
                                                   "                        \"floating_point\": 1.0",
                                             "\"id\": \"tip_diameter\", \"unit\": \"mm\", \"floating_point\": null"),
                                    "e.rexsj");
    for (const auto* m : {&x, &j}) {
        CHECK(!rexs::number(*m, m->at(16), "tip_diameter"));
        CHECK(!rexs::text(*m, m->at(16), "tip_diameter"));
        // The case is mapped without the tip diameter (no warning about the 1 mm).
        const auto r = rexs::map_to_case(*m, {});
        for (const auto& w : r.warnings) CHECK(w.find("tip_diameter") == std::string::npos);
    }
    // The worm stage in JSON (null enums on its materials) is read and refused at its stage.
    const auto w = rexs::read_model(data("FVA_worm_stage_1-4.rexsj"));
    CHECK_THAT(error_of([&] { (void)rexs::map_to_case(w, {}); }),
               Catch::Matches(".*FVA_worm_stage_1-4\\.rexsj: component [0-9]+ \\(worm_stage 'Schneckenstufe.*'\\): .*not represented.*"));
}
