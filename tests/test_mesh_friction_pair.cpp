// The mixed-film friction pair of the mesh (mu_bl, mu_ehl of fernandes_mixed) given by the oil,
// by the case or by default, and the settings of selected forms listed as assumed values.
#include <catch2/catch.hpp>
#include <numbers>
#include <sstream>

#include "gearloss/core/errors.hpp"
#include "gearloss/case/config.hpp"
#include "gearloss/results/reports.hpp"

#include <nlohmann/json.hpp>
#include "gearloss/losses/registry.hpp"
#include "gearloss/map/map_runner.hpp"
#include "gearloss/solver/operating_point.hpp"
#include "test_support.hpp"

using namespace gearloss;

namespace {
constexpr double kRpm = std::numbers::pi / 30;

// transfer-box.yaml with its oil written inline (the temporary case has no oils/ beside it),
// fernandes_mixed selected, and `oil_extra` appended to the oil block.
std::string transfer_box(const std::string& oil_extra = "") {
    std::string oil = test_support::read_file(test_support::source_path("configs/oils/75W90-A.yaml")) + oil_extra;
    std::istringstream lines(oil);
    std::string indented, line;
    while (std::getline(lines, line)) indented += "  " + line + "\n";
    std::string text = test_support::read_file(test_support::source_path("configs/transfer-box.yaml"));
    const auto at = text.find("oil: oils/75W90-A.yaml");
    REQUIRE(at != std::string::npos);
    text.replace(at, text.find('\n', at) - at, "oil:\n" + indented);
    return test_support::replace_once(text, "mesh_friction: schlenk", "mesh_friction: fernandes_mixed");
}

io::Case load_text(const std::string& text) {
    test_support::TempConfig cfg(text);
    return io::load_case(cfg.path);
}

double mesh_loss(const std::string& text) {
    auto c = load_text(text);
    c.model.thermal.mode = solver::ThermalMode::fixed;  // the same film whatever the pair
    c.model.thermal.oil_temperature = 353.15;
    return solver::solve_point(c.model, 1500 * kRpm, 200).losses.power[losses::MechanismSet{}.index("mesh")];
}

InputError load_error(const std::string& text) {
    try {
        (void)load_text(text);
    } catch (const InputError& e) {
        return e;
    }
    FAIL("no error");
    return InputError("", 0, 0, "", "");
}

bool assumed(const io::Case& c, const std::string& key) {
    for (const auto& a : c.assumed)
        if (a.key == key) return true;
    return false;
}
}  // namespace

TEST_CASE("mesh friction pair: an oil's gear_friction is used where the case gives none, the case's value wins",
          "[mechanisms]") {
    // Fernandes et al. (2015) measure mu_bl and mu_EHL per oil. The truth comes by another
    // route: the same pair written in the case's mechanisms block (read before this change).
    const std::string oil_pair = transfer_box("gear_friction: {mu_bl: 0.12, mu_ehl: 0.03}\n");
    const double from_oil = mesh_loss(oil_pair);
    CHECK(from_oil == mesh_loss(transfer_box() + "mechanisms:\n  mesh: {mu_bl: 0.12, mu_ehl: 0.03}\n"));
    CHECK(from_oil != mesh_loss(transfer_box()));  // the oil's key is not ignored (it was)
    // Key by key: the case's mu_bl, the oil's mu_ehl.
    CHECK(mesh_loss(oil_pair + "mechanisms:\n  mesh: {mu_bl: 0.2}\n") ==
          mesh_loss(transfer_box() + "mechanisms:\n  mesh: {mu_bl: 0.2, mu_ehl: 0.03}\n"));
    CHECK(mesh_loss(oil_pair + "mechanisms:\n  mesh: {mu_bl: 0.2}\n") != from_oil);
    // The options spelling wins too, and only for the key it writes.
    CHECK(mesh_loss(test_support::replace_once(oil_pair, "mesh_friction: fernandes_mixed",
                                               "mesh_friction: fernandes_mixed\n  gear_friction: {mu_ehl: 0.05}")) ==
          mesh_loss(transfer_box() + "mechanisms:\n  mesh: {mu_bl: 0.12, mu_ehl: 0.05}\n"));

    // check shows the value in force and its source.
    const auto c = load_text(oil_pair);
    const std::string text = io::check_report(c);
    CHECK_THAT(text, Catch::Contains("mu_bl = 0.12 [from the oil]"));
    CHECK_THAT(text, Catch::Contains("mu_ehl = 0.03 [from the oil]"));
    const auto j = io::check_json_object(c);
    for (const auto& mech : j["mechanisms"])
        if (mech["name"] == "mesh") {
            CHECK(mech["parameters"]["mu_bl"].get<double>() == 0.12);
            CHECK(mech["parameters_from_oil"].size() == 2);
        } else {
            CHECK(!mech.contains("parameters_from_oil"));
        }
}

TEST_CASE("mesh friction pair: out of order or out of range in the oil is an error naming both sources", "[mechanisms]") {
    const std::string reversed = transfer_box("gear_friction: {mu_bl: 0.02, mu_ehl: 0.05}\n");
    auto e = load_error(reversed);
    CHECK(e.line == test_support::line_of(reversed, "gear_friction: {mu_bl: 0.02, mu_ehl: 0.05}"));
    CHECK_THAT(e.message, Catch::Contains("need 0 <= mu_ehl < mu_bl < 1"));
    CHECK_THAT(load_error(transfer_box("gear_friction: {mu_bl: 1.2}\n")).message, Catch::Contains("must be in [0, 1)"));
    CHECK_THAT(load_error(transfer_box("gear_friction: {mu_bl: 0.1, mu_tif: 0.1}\n")).message, Catch::Contains("mu_tif"));
    // The oil's mu_bl 0.01 below the default mu_ehl 0.02: the pair in force is out of order.
    const std::string mixed = transfer_box("gear_friction: {mu_bl: 0.01}\n");
    e = load_error(mixed);
    CHECK(e.line == test_support::line_of(mixed, "gear_friction: {mu_bl: 0.01}"));
    CHECK_THAT(e.message, Catch::Contains("mu_bl 0.01 from the oil"));
    CHECK_THAT(e.message, Catch::Contains("mu_ehl 0.02 from the default"));
    // The same with the case's options key: the error is at that key.
    const std::string opt = test_support::replace_once(transfer_box("gear_friction: {mu_bl: 0.04}\n"),
                                                       "mesh_friction: fernandes_mixed",
                                                       "mesh_friction: fernandes_mixed\n  gear_friction: {mu_ehl: 0.05}");
    e = load_error(opt);
    CHECK(e.line == test_support::line_of(opt, "  gear_friction: {mu_ehl: 0.05}"));
    CHECK_THAT(e.message, Catch::Contains("mu_bl 0.04 from the oil, mu_ehl 0.05 from the case"));
}

TEST_CASE("mesh friction pair: an --oil whose pair is out of order is an error in that oil file, only where it is read",
          "[mechanisms]") {
    const std::string oil_text = test_support::read_file(test_support::source_path("configs/oils/75W90-A.yaml")) +
                                 "gear_friction: {mu_bl: 0.015}\n";  // below the default mu_ehl 0.02
    test_support::TempConfig oil(oil_text);
    // fernandes_mixed reads the pair: the error is at the oil's key, in the --oil file.
    auto c = load_text(transfer_box());
    io::replace_oil_file(c, oil.path);
    try {
        map::validate_case(c, {.oil = oil.path, .grid = false});
        FAIL("no error");
    } catch (const InputError& e) {
        CHECK(e.file == oil.path);
        CHECK(e.line == test_support::line_of(oil_text, "gear_friction: {mu_bl: 0.015}"));
        CHECK_THAT(e.message, Catch::Contains("mu_bl 0.015 from the oil, mu_ehl 0.02 from the default"));
    }
    // schlenk does not read it: the same oil is usable (a measured mu_ehl of 0.1 must not stop it).
    c = io::load_case(test_support::source_path("configs/transfer-box.yaml"));
    io::replace_oil_file(c, oil.path);
    CHECK_NOTHROW(map::validate_case(c, {.oil = oil.path, .grid = false}));
    const std::string text = io::check_report(c);
    CHECK_THAT(text, Catch::Contains("mu_bl = 0.015 [from the oil] [not read: fernandes_mixed is not selected]"));
    // An oil's own pair out of order names both values.
    CHECK_THAT(load_error(transfer_box("gear_friction: {mu_bl: 0.02, mu_ehl: 0.05}\n")).message,
               Catch::Contains("mu_bl 0.02, mu_ehl 0.05, both from the oil"));
}

TEST_CASE("mesh friction pair: settings a selected form reads and nobody gives are assumed values", "[mechanisms]") {
    auto c = load_text(transfer_box());
    CHECK(assumed(c, "mechanisms.mesh.mu_bl"));
    CHECK(assumed(c, "mechanisms.mesh.mu_ehl"));
    CHECK(!assumed(c, "mechanisms.windage.pressure"));  // windage: none
    c = load_text(transfer_box("gear_friction: {mu_bl: 0.12}\n"));
    CHECK(!assumed(c, "mechanisms.mesh.mu_bl"));
    CHECK(assumed(c, "mechanisms.mesh.mu_ehl"));
    c = load_text(transfer_box() + "mechanisms:\n  mesh: {mu_ehl: 0.01}\n  windage: {form: free_disk}\n");
    CHECK(assumed(c, "mechanisms.mesh.mu_bl"));
    CHECK(!assumed(c, "mechanisms.mesh.mu_ehl"));
    REQUIRE(assumed(c, "mechanisms.windage.pressure"));
    CHECK(!assumed(c, "mechanisms.windage.mist_viscosity"));  // read by anderson_loewenthal only
    const std::string text = transfer_box() + "mechanisms:\n  mesh: {mu_ehl: 0.01}\n  windage: {form: free_disk}\n";
    for (const auto& a : c.assumed)
        if (a.key == "mechanisms.windage.pressure") {
            CHECK(a.value == "101325 Pa");
            // At the windage block (file:line:col).
            CHECK_THAT(a.location, Catch::Contains(":" + std::to_string(test_support::line_of(text, "  windage: {form: free_disk}")) + ":"));
            CHECK_THAT(a.reason, Catch::Contains("free_disk"));
        }
    // An oil replaced by --oil that gives the pair: the pair is no longer assumed, and is used.
    c = load_text(transfer_box());
    {
        test_support::TempConfig oil(test_support::read_file(test_support::source_path("configs/oils/75W90-A.yaml")) +
                                     "gear_friction: {mu_bl: 0.12, mu_ehl: 0.03}\n");
        io::replace_oil_file(c, oil.path);
    }
    CHECK(!assumed(c, "mechanisms.mesh.mu_bl"));
    CHECK(!assumed(c, "mechanisms.mesh.mu_ehl"));
    c.model.thermal.mode = solver::ThermalMode::fixed;
    c.model.thermal.oil_temperature = 353.15;
    CHECK(solver::solve_point(c.model, 1500 * kRpm, 200).losses.power[losses::MechanismSet{}.index("mesh")] ==
          mesh_loss(transfer_box() + "mechanisms:\n  mesh: {mu_bl: 0.12, mu_ehl: 0.03}\n"));
    // check lists the assumed values, in text and JSON.
    c = load_text(transfer_box());
    CHECK_THAT(io::check_report(c), Catch::Contains("  mechanisms.mesh.mu_bl = 0.1 (boundary friction of fernandes_mixed"));
    bool listed = false;
    const auto j = io::check_json_object(c);
    for (const auto& a : j["assumed"]) listed = listed || a["key"] == "mechanisms.mesh.mu_ehl";
    CHECK(listed);
    // The published default form reads neither: nothing assumed.
    c = io::load_case(test_support::source_path("configs/transfer-box.yaml"));
    for (const auto& a : c.assumed) CHECK(!a.key.starts_with("mechanisms."));
}
