// The ratio as a run-time argument of the model (Model::select_ratio): a drive cycle and the
// VECTO tables select each gear on one loaded case. The reference is the other route: the
// loader selecting the ratio from the text (load_case(file, ratio)), which parses the case
// again; both must give the same model to the last bit.
#include <catch2/catch.hpp>
#include <numbers>
#include <string>

#include "gearloss/core/errors.hpp"
#include "gearloss/case/config.hpp"
#include "loss_parts.hpp"
#include "gearloss/solver/operating_point.hpp"
#include "test_support.hpp"

using namespace gearloss;

namespace {
constexpr double kRpm = std::numbers::pi / 30;

// Bitwise comparison of what a gear's model gives: the kinematics and a coupled solve.
void require_same_model(const solver::Model& a, const solver::Model& b) {
    REQUIRE(a.ratio == b.ratio);
    REQUIRE(a.gearbox.engaged == b.gearbox.engaged);
    REQUIRE(a.layout.ratio == b.layout.ratio);
    REQUIRE(a.layout.body_speed_ratio == b.layout.body_speed_ratio);
    REQUIRE(a.layout.bearing_speed_ratio == b.layout.bearing_speed_ratio);
    for (const auto& [n, T] : {std::pair{1500.0, 120.0}, std::pair{3000.0, 40.0}}) {
        const auto ra = solver::solve_point(a, n * kRpm, T, true);
        const auto rb = solver::solve_point(b, n * kRpm, T, true);
        REQUIRE(ra.status == rb.status);
        REQUIRE(ra.oil_temperature == rb.oil_temperature);
        REQUIRE(ra.losses.total() == rb.losses.total());
        REQUIRE(ra.omega_out == rb.omega_out);
    }
}
}  // namespace

TEST_CASE("ratio selected at run time equals the loader's selection, for every ratio of every shipped case",
          "[ratio]") {
    for (const char* file : {"configs/manual-6speed.yaml", "configs/automatic-6speed.yaml", "configs/transfer-box.yaml"}) {
        INFO(file);
        const auto path = test_support::source_path(file);
        const io::Case base = io::load_case(path);
        const auto names = base.model.ratio_names();
        REQUIRE(names.size() >= 2);
        solver::Model moving = base.model;  // one model walked through every gear, as a cycle does
        for (const auto& r : names) {
            INFO(r);
            const io::Case reference = io::load_case(path, r);
            require_same_model(base.model.with_ratio(r), reference.model);
            moving.select_ratio(r);
            require_same_model(moving, reference.model);
        }
        // Back to the case's own ratio: nothing of the others is left behind.
        moving.select_ratio(base.model.ratio);
        require_same_model(moving, base.model);
    }
}

TEST_CASE("transfer box: low and high selected at run time give the published gear ratios", "[ratio]") {
    const auto m = io::load_case(test_support::source_path("configs/transfer-box.yaml")).model;
    // low: wheels 5-3 and 2-1: (17/28)(23/32); high: 4-2 and 2-1: (27/23)(23/32) = 27/32.
    CHECK(m.with_ratio("low").layout.ratio == Approx(17.0 / 28 * 23.0 / 32).epsilon(1e-12));
    CHECK(m.with_ratio("high").layout.ratio == Approx(27.0 / 32).epsilon(1e-12));
}

TEST_CASE("an unknown ratio at run time is an input error naming the defined ones", "[ratio]") {
    const auto m = io::load_case(test_support::source_path("configs/manual-6speed.yaml")).model;
    try {
        (void)m.with_ratio("g9");
        FAIL("no error");
    } catch (const InputError& e) {
        CHECK(e.key == "gearbox.ratio");
        CHECK_THAT(e.message, Catch::Contains("unknown ratio 'g9'") && Catch::Contains("g1, g2, g3, g4, g5, g6"));
    }
    const auto fixed = io::load_case(test_support::source_path("configs/fzg-c40-paor.yaml")).model;
    CHECK(fixed.ratio.empty());
    CHECK_THROWS_WITH(fixed.with_ratio("low"), Catch::Contains("defines no 'gearbox.ratios'"));
}

TEST_CASE("a ratio that is not selected is still checked at load, at its own line", "[ratio]") {
    // 'high' engages both free wheels of shaft II: the train locks. The case selects 'low',
    // which is sound; the load must fail anyway, so a later run-time selection cannot.
    const std::string text = test_support::replace_once(
        test_support::read_file(test_support::source_path("configs/transfer-box.yaml")), "high: {engage: [w4]",
        "high: {engage: [w4, w5]");
    const test_support::TempConfig cfg(text);  // beside the shipped case: its oil file resolves
    try {
        (void)io::load_case(cfg.path);
        FAIL("no error");
    } catch (const InputError& e) {
        CHECK_THAT(e.message, Catch::Contains("ratio 'high'") && Catch::Contains("locked"));
        CHECK(e.line == test_support::line_of(text, "high: {engage"));
    }
}
