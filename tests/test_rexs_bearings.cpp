// REXS bearings (lib/gearloss/rexs/bearing_mapper.cpp) and the values an imported case declares
// assumed (its `assumed:` list, lib/gearloss/case/declared_assumptions.hpp), on the FVA two-stage
// example (tests/data/rexs). The expected codes and sizes are read off the SKF (2018) designation
// system and the ISO 15 boundary dimensions by hand, as each comment says.
#include <catch2/catch.hpp>
#include <fstream>
#include <iterator>
#include <string>

#include "gearloss/bearings/designation_suffix.hpp"
#include "gearloss/core/errors.hpp"
#include "gearloss/case/config.hpp"
#include "rexs_test_support.hpp"
#include "gearloss/rexs/case_mapper.hpp"
#include "gearloss/rexs/reader.hpp"
#include "test_support.hpp"

using namespace gearloss;
using namespace rexs_test;

namespace {

std::string fva_xml() {
    std::ifstream f(std::string(GEARLOSS_SOURCE_DIR) + "/tests/data/rexs/FVA-Industriegetriebe_2stufig_1-4.rexs", std::ios::binary);
    return {std::istreambuf_iterator<char>(f), std::istreambuf_iterator<char>()};
}


// The codes of a designation's suffix as "code:kind" words.
std::string codes(const std::string& designation) {
    std::string s;
    for (const auto& c : bearings::decode_suffix(*bearings::designation_key(designation)))
        s += (s.empty() ? "" : " ") + c.code + ":" + bearings::to_string(c.kind);
    return s;
}

// The YAML block of bearing `name` in an imported case (up to the next item).
std::string bearing_block(const std::string& yaml, const std::string& name) {
    const auto p = yaml.find("- name: " + name);
    REQUIRE(p != std::string::npos);
    const auto e = yaml.find("\n  - name:", p + 1);
    const auto end = std::min(e, yaml.find("\nseals:", p));
    return yaml.substr(p, end - p);
}

std::string all_warnings(const rexs::ImportResult& r) {
    std::string s;
    for (const auto& w : r.warnings) s += w + "\n";
    return s;
}

rexs::ImportResult import_text(const std::string& xml) {
    rexs::ImportOptions o;
    o.oil_reference = "x.oil.yaml";
    return rexs::map_to_case(rexs::parse_xml(xml, "x.rexs"), o);
}

// FVA bearing 33 (6210-2Z on shaft 12) as a bearing with detailed geometry: `attributes` replace
// its designation (the file has CRLF line ends); one row (id 901) with a rolling element (id 902) of `element` attributes.
std::string detailed_33(const std::string& attributes, const std::string& row, const std::string& element) {
    std::string x = fva_xml();
    x = replaced(x, "<component id=\"33\" name=\"6210-2Z (Rolling bearing [33])\" type=\"rolling_bearing_with_catalog_geometry\">",
                 "<component id=\"33\" name=\"detailed [33]\" type=\"rolling_bearing_with_detailed_geometry\">");
    x = replaced(x, "<attribute id=\"catalogue_designation\" unit=\"\">6210-2Z</attribute>\r\n      <attribute id=\"bearing_type\" "
                    "unit=\"\">radial_grooved_ball_bearing</attribute>",
                 attributes);
    x = replaced(x, "<ref hint=\"rolling_bearing_with_catalog_geometry\" id=\"33\"", "<ref hint=\"rolling_bearing_with_detailed_geometry\" id=\"33\"");
    x = replaced(x, "  </components>",
                 "    <component id=\"901\" name=\"row\" type=\"rolling_bearing_row\">" + row +
                     "</component>\n    <component id=\"902\" name=\"element\" type=\"rolling_element\">" + element +
                     "</component>\n  </components>");
    x = replaced(x, "  </relations>",
                 "    <relation id=\"901\" order=\"1\" type=\"ordered_assembly\"><ref hint=\"rolling_bearing_with_detailed_geometry\" "
                 "id=\"33\" role=\"assembly\"/><ref hint=\"rolling_bearing_row\" id=\"901\" role=\"part\"/></relation>\n"
                 "    <relation id=\"902\" order=\"1\" type=\"ordered_assembly\"><ref hint=\"rolling_bearing_row\" id=\"901\" "
                 "role=\"assembly\"/><ref hint=\"rolling_element\" id=\"902\" role=\"part\"/></relation>\n  </relations>");
    return x;
}

}  // namespace

TEST_CASE("bearing designation suffixes: codes split and named", "[rexs][bearings]") {
    // SKF (2018) designation system: 2Z two shields, C3 clearance > Normal; EC optimised design +
    // P polyamide cage; 7308 B (40 deg, kept in the key) E design, CB universally matchable, P cage;
    // Schaeffler E design, XL X-life, TVP2 polyamide cage; tapered J2 pressed steel cage, Q contact
    // geometry; 2RS1 contact seals, TN9 polyamide cage.
    CHECK(codes("6210-2Z/C3") == "2Z:shield C3:clearance");
    CHECK(codes("NJ 309 ECP") == "EC:internal design P:cage");
    CHECK(codes("7308 BECBP") == "E:internal design CB:matching P:cage");
    CHECK(codes("6207-E-XL-TVP2") == "E:internal design XL:internal design TVP2:cage");
    CHECK(codes("32306 J2/Q") == "J2:cage Q:internal design");
    CHECK(codes("6306-2RS1-TN9/C3") == "2RS1:contact seal TN9:cage C3:clearance");
    CHECK(codes("6210-2Z-BRG") == "2Z:shield BRG:not understood");
    CHECK(codes("6210").empty());
}

TEST_CASE("rexs: every dropped suffix code is a warning at the component and a comment", "[rexs][bearings]") {
    // 6210-2Z/C3 resolves to catalogue row 6210; 2Z (shields) reaches the case loader with the
    // designation; C3 (clearance) and J (cage) have no term in SKF (2004): named, not dropped silently.
    const auto r = import_text(replaced(fva_xml(), ">6210-2Z<", ">6210-2Z-J/C3<"));
    const std::string w = all_warnings(r);
    CHECK_THAT(w, Catch::Contains("component 33 ") && Catch::Contains("J (pressed steel cage)") &&
                      Catch::Contains("C3 (radial internal clearance larger than Normal)"));
    CHECK_THAT(w, !Catch::Contains("2Z (shields"));
    const std::string b = bearing_block(r.case_yaml, "bearing_33");
    CHECK_THAT(b, Catch::Contains("designation: \"6210-2Z-J/C3\""));
    CHECK_THAT(b, Catch::Contains("# suffix 2Z: shields on both sides; no contact"));
    CHECK_THAT(b, Catch::Contains("# suffix C3: radial internal clearance larger than Normal; clearance: no term"));
    // A code nobody knows is reported as not understood.
    const auto q = import_text(replaced(fva_xml(), ">6210-2Z<", ">6210-2Z-BRG<"));
    CHECK_THAT(all_warnings(q), Catch::Contains("component 33 ") && Catch::Contains("BRG (not understood)"));
}

TEST_CASE("rexs: contact seals of a designation not in the catalogue are counted", "[rexs][bearings]") {
    // 6299 is no catalogue row: a bearing of the shaft's bore; its 2RS1 contact seals become
    // `seals: RS1` (the SKF (2004) seal moment of a deep groove ball bearing).
    const auto r = import_text(replaced(fva_xml(), ">6210-2Z<", ">6299-2RS1<"));
    const std::string b = bearing_block(r.case_yaml, "bearing_33");
    CHECK_THAT(b, Catch::Contains("seals: RS1"));
    CHECK_THAT(all_warnings(r), Catch::Contains("component 33 ") && Catch::Contains("'6299-2RS1' is not in the bearing catalogue"));
}

TEST_CASE("rexs: a bearing with detailed geometry keeps its size and finds its series", "[rexs][bearings]") {
    // d = 50, D = 90, B = 20 mm is ISO 15 dimension series 02: a 62 series deep groove ball
    // bearing (6210); the lightest row of that bore, 16010 (50 x 80 x 10), is not it.
    // dm = (d + D)/2 = (50 + 90)/2 = 70 mm; the row's pitch diameter 80 mm is 14 % away: warned.
    // C0 = 25 kN as REXS gives it (the catalogue's 6210 has 23.2 kN).
    const auto r = import_text(detailed_33(
        "<attribute id=\"bearing_type\" unit=\"\">radial_grooved_ball_bearing</attribute>"
        "<attribute id=\"inner_diameter\" unit=\"mm\">50</attribute><attribute id=\"outer_diameter\" unit=\"mm\">90</attribute>"
        "<attribute id=\"width\" unit=\"mm\">20</attribute><attribute id=\"radial_static_load_rating\" unit=\"kN\">25</attribute>",
        "<attribute id=\"number_of_rolling_elements\" unit=\"none\">10</attribute><attribute id=\"reference_diameter\" unit=\"mm\">80</attribute>",
        "<attribute id=\"diameter_of_rolling_element\" unit=\"mm\">12.7</attribute>"));
    const std::string b = bearing_block(r.case_yaml, "bearing_33");
    CHECK_THAT(b, Catch::Contains("type: deep_groove_ball"));
    CHECK_THAT(b, Catch::Contains("d: 50 mm") && Catch::Contains("D: 90 mm") && Catch::Contains("B: 20 mm"));
    CHECK_THAT(b, Catch::Contains("series: \"62\""));
    CHECK_THAT(b, Catch::Contains("C0: 25 kN"));
    CHECK_THAT(b, Catch::Contains("10 rolling elements, diameter 12.7 mm, pitch diameter 80 mm; the friction model takes dm = (d + D)/2 = 70 mm"));
    CHECK_THAT(all_warnings(r), Catch::Contains("component 33 ") && Catch::Contains("pitch diameter 80 mm of row 901"));
    // No bearing_type, rollers (a length): a cylindrical roller bearing; 50 x 90 x 23 is the 22
    // series (NU 2210), not the 2 series (NU 210, B = 20 mm).
    const auto c = import_text(detailed_33(
        "<attribute id=\"inner_diameter\" unit=\"mm\">50</attribute><attribute id=\"outer_diameter\" unit=\"mm\">90</attribute>"
        "<attribute id=\"width\" unit=\"mm\">23</attribute>",
        "<attribute id=\"number_of_rolling_elements\" unit=\"none\">14</attribute>",
        "<attribute id=\"diameter_of_rolling_element\" unit=\"mm\">11</attribute><attribute id=\"length_of_rolling_element\" unit=\"mm\">12</attribute>"));
    const std::string cb = bearing_block(c.case_yaml, "bearing_33");
    CHECK_THAT(cb, Catch::Contains("type: cylindrical_roller") && Catch::Contains("series: \"22\""));
}

TEST_CASE("rexs: a bearing of a designation not in the catalogue takes the designation's series", "[rexs][bearings]") {
    // 6299 is not a bearing (bore code 99), but its series digits are those of the 62 series (ISO 15:
    // deep groove ball, diameter series 2): on shaft 12's 50 mm bore the 62 row is 6210
    // (50 x 90 x 20 mm, C0 23.2 kN), not the lightest row of that bore, 16010 (50 x 80 x 10 mm).
    const auto r = import_text(replaced(fva_xml(), ">6210-2Z<", ">6299-2RS1<"));
    const std::string b = bearing_block(r.case_yaml, "bearing_33");
    CHECK_THAT(b, Catch::Contains("D: 90 mm") && Catch::Contains("B: 20 mm") && Catch::Contains("C0: 23.2 kN"));
    CHECK_THAT(b, Catch::Contains("series: \"62\"") && Catch::Contains("series 62 of the designation"));
}

TEST_CASE("rexs: a scaled bearing row is of the designation's series, else the lightest, said so", "[rexs][bearings]") {
    // A 43.2 mm bore has no catalogue deep groove ball row; the nearest bore is 45 mm
    // (k = 43.2/45 = 0.96). Designation "63" (the series alone): 6309 (45 x 100 x 25 mm, C0 31.5 kN)
    // scaled: D = 96 mm, B = 24 mm, C0 = 31.5 x 0.96^2 = 29.0304 kN.
    const std::string attrs = "<attribute id=\"bearing_type\" unit=\"\">radial_grooved_ball_bearing</attribute>"
                              "<attribute id=\"inner_diameter\" unit=\"mm\">43.2</attribute>";
    const std::string row = "<attribute id=\"number_of_rolling_elements\" unit=\"none\">8</attribute>";
    const std::string ball = "<attribute id=\"diameter_of_rolling_element\" unit=\"mm\">15</attribute>";
    const auto r = import_text(detailed_33("<attribute id=\"catalogue_designation\" unit=\"\">63</attribute>" + attrs, row, ball));
    const std::string b = bearing_block(r.case_yaml, "bearing_33");
    CHECK_THAT(b, Catch::Contains("D: 96 mm") && Catch::Contains("B: 24 mm") && Catch::Contains("C0: 29.0304 kN"));
    CHECK_THAT(b, Catch::Contains("series: \"63\"") && Catch::Contains("row of series 63 of the designation"));
    CHECK_THAT(all_warnings(r), Catch::Contains("assumed as 6309 x 0.96 (bore 45 mm) (series 63 of the designation)"));
    // No designation: the lightest row at 45 mm, 16009 (45 x 75 x 10 mm, C0 10.8 kN), scaled:
    // D = 72 mm, B = 9.6 mm, C0 = 10.8 x 0.9216 = 9.95328 kN; the reason says the model gave no series.
    const auto q = import_text(detailed_33(attrs, row, ball));
    const std::string qb = bearing_block(q.case_yaml, "bearing_33");
    CHECK_THAT(qb, Catch::Contains("D: 72 mm") && Catch::Contains("B: 9.6 mm") && Catch::Contains("C0: 9.95328 kN"));
    CHECK_THAT(qb, Catch::Contains("the nearest bore's lightest row, REXS gives no designation"));
    CHECK_THAT(all_warnings(q), Catch::Contains("assumed as 16009 x 0.96 (bore 45 mm) (the lightest row at the nearest bore: "
                                                "REXS gives no designation)"));
    // No bearing_type either: the designation's series gives the type. NU 2299: series NU 22, a
    // cylindrical roller bearing; at 50 mm its row is NU 2210 ECP (50 x 90 x 23 mm).
    const auto t = import_text(replaced(fva_xml(), ">6210-2Z</attribute>\r\n      <attribute id=\"bearing_type\" unit=\"\">radial_grooved_ball_bearing</attribute>",
                                        ">NU 2299</attribute>"));
    const std::string tb = bearing_block(t.case_yaml, "bearing_33");
    CHECK_THAT(tb, Catch::Contains("type: cylindrical_roller") && Catch::Contains("the designation's series NU 22 is of this type"));
    CHECK_THAT(tb, Catch::Contains("D: 90 mm") && Catch::Contains("B: 23 mm") && Catch::Contains("series: \"22\""));
}

TEST_CASE("rexs: what REXS does not carry is declared assumed and listed by the loader", "[rexs][assumed]") {
    const auto r = import_text(fva_xml());
    test_support::TempDir dir;
    dir.write("x.oil.yaml", r.oil_yaml);
    const io::Case c = io::load_case_text(r.case_yaml, "x.yaml", dir.path.string());
    const auto find = [&](const std::string& key) -> const io::AssumedValue* {
        for (const auto& a : c.assumed)
            if (a.key == key) return &a;
        return nullptr;
    };
    for (const char* key : {"housing.oil_level", "housing.oil_volume", "thermal.ambient", "thermal.heat_rejection.housing",
                            "seals.seal_shaft_12", "bearings.bearing_36.D"}) {
        INFO(key);
        const auto* a = find(key);
        REQUIRE(a);
        CHECK(a->source == "REXS import");
        CHECK(!a->reason.empty());
    }
    CHECK(find("thermal.ambient")->value == "20 degC");
    // The value is the case's own, as written: the oil level line of the case.
    const auto* level = find("housing.oil_level");
    CHECK_THAT(r.case_yaml, Catch::Contains("oil_level: " + level->value));
    // A gear without a pressure angle in REXS: the case omits it and the loader assumes the ISO 53 rack.
    CHECK(find("gears.gear_15.pressure_angle") == nullptr);
}

TEST_CASE("case: an `assumed:` list names values of the case", "[config][assumed]") {
    std::ifstream f(std::string(GEARLOSS_SOURCE_DIR) + "/configs/spur-seed000.yaml");
    const std::string base{std::istreambuf_iterator<char>(f), std::istreambuf_iterator<char>()};
    const std::string dir = std::string(GEARLOSS_SOURCE_DIR) + "/configs";
    const auto c = io::load_case_text(base + "\nassumed:\n  - {key: housing.oil_volume, reason: \"guessed from a photo\", source: the test}\n",
                                      "s.yaml", dir);
    const auto& a = c.assumed.back();
    CHECK(a.key == "housing.oil_volume");
    CHECK(a.reason == "guessed from a photo");
    CHECK(a.source == "the test");
    CHECK(!a.value.empty());
    CHECK_THROWS_WITH(io::load_case_text(base + "\nassumed:\n  - {key: housing.no_such_key, reason: x}\n", "s.yaml", dir),
                      Catch::Contains("assumed") && Catch::Contains("names no value of the case"));
}
