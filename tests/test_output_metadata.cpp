// Case::assumed (the values the loader took as defaults) and the sidecar metadata of outputs.
#include <catch2/catch.hpp>
#include <algorithm>

#include "gearloss/case/config.hpp"
#include "gearloss/map/output_metadata.hpp"
#include "test_support.hpp"

using namespace gearloss;

namespace {
const io::AssumedValue* find_assumed(const io::Case& c, const std::string& key) {
    const auto it = std::ranges::find_if(c.assumed, [&](const io::AssumedValue& a) { return a.key == key; });
    return it == c.assumed.end() ? nullptr : &*it;
}
std::string shipped(const std::string& rel) { return test_support::read_file(test_support::source_path(rel)); }
}  // namespace

TEST_CASE("assumed values: a key the case gives is never listed, one it omits is, with its default", "[metadata]") {
    const std::string text = shipped("configs/transfer-box.yaml");
    const auto c = io::load_case_text(text, "transfer-box.yaml", test_support::source_path("configs"));
    // The oil file says "X_L not given: the ISO/TS 6336-20 value for PAO (0.8) applies".
    const auto* xl = find_assumed(c, "oil.X_L");
    REQUIRE(xl != nullptr);
    CHECK(xl->value == "0.8");
    CHECK(xl->location.find("75W90-A.yaml:") != std::string::npos);  // the oil file's block omits it
    // Given by the oil file: thermal_expansion (6.8e-4), piezoviscosity; by the case: thermal mode, name.
    CHECK(find_assumed(c, "oil.thermal_expansion") == nullptr);
    CHECK(find_assumed(c, "oil.piezoviscosity") == nullptr);
    CHECK(find_assumed(c, "thermal.mode") == nullptr);
    CHECK(find_assumed(c, "name") == nullptr);
    // The housing surface gives emissivity, height and air speed but no length (= the height).
    CHECK(find_assumed(c, "thermal.heat_rejection.housing.emissivity") == nullptr);
    const auto* length = find_assumed(c, "thermal.heat_rejection.housing.length");
    REQUIRE(length != nullptr);
    CHECK(length->value == "the height");
    CHECK(c.oil_file.ends_with("oils/75W90-A.yaml"));

    // Removing the name and mode from the case: both become assumed, the mode at the
    // thermal block's line.
    std::string edited = test_support::replace_once(text, "name: Transfer gearbox (seed 001)\n", "");
    edited = test_support::replace_once(edited, "  mode: stabilised\n", "");
    const auto d = io::load_case_text(edited, "box.yaml", test_support::source_path("configs"));
    const auto* name = find_assumed(d, "name");
    REQUIRE(name != nullptr);
    CHECK(name->value == "box");
    const auto* mode = find_assumed(d, "thermal.mode");
    REQUIRE(mode != nullptr);
    CHECK(mode->value == "stabilised");
    CHECK(mode->location == "box.yaml:" + std::to_string(test_support::line_of(edited, "  heat_capacity:")) + ":3");
}

TEST_CASE("assumed values: ISO/TS 6336-20 X_L by base oil and the bearings' mu_ehl follow a replaced oil", "[metadata]") {
    auto c = io::load_case_text(shipped("configs/transfer-box.yaml"), "transfer-box.yaml",
                                test_support::source_path("configs"));
    const size_t bearings = c.model.gearbox.bearings.size();
    const auto count_mu_ehl = [](const io::Case& k) {
        return std::ranges::count_if(k.assumed, [](const io::AssumedValue& a) {
            return a.key.starts_with("bearings.") && a.key.ends_with(".mu_ehl");
        });
    };
    CHECK(static_cast<size_t>(count_mu_ehl(c)) == bearings);  // 75W90-A gives no bearing_friction
    // Another oil file (PAO, no X_L, no bearing_friction): its assumed values replace the first's.
    io::replace_oil_file(c, test_support::source_path("configs/oils/75W140-A.yaml"));
    CHECK(c.oil_file.ends_with("75W140-A.yaml"));
    CHECK(std::ranges::count_if(c.assumed, [](const io::AssumedValue& a) { return a.key == "oil.X_L"; }) <= 1);
    CHECK(static_cast<size_t>(count_mu_ehl(c)) == bearings);
    for (const auto& a : c.assumed)
        if (a.key.starts_with("oil.")) CHECK(a.location.find("75W140-A.yaml") != std::string::npos);
}

TEST_CASE("column units come from the column names", "[metadata]") {
    CHECK(map::column_unit("P_mesh_W") == "W");
    CHECK(map::column_unit("oil_temp_C") == "degC");
    CHECK(map::column_unit("speed_in_rpm") == "rpm");
    CHECK(map::column_unit("torque_in_Nm") == "N*m");
    CHECK(map::column_unit("h_min_m12_um") == "um");
    CHECK(map::column_unit("mu_m12") == "1");
    CHECK(map::column_unit("efficiency") == "1");
    CHECK(map::column_unit("Torque Loss [Nm]") == "N*m");
    CHECK_FALSE(map::column_unit("status").has_value());
    CHECK_FALSE(map::column_unit("status_B").has_value());
}
