#include <catch2/catch.hpp>
#include <cmath>
#include <numbers>

#include "gearloss/case/config.hpp"
#include "gearloss/map/vecto.hpp"
#include "test_support.hpp"

using namespace gearloss;
using Approx = Catch::Detail::Approx;

TEST_CASE("VECTO torque axis: both signs and zero", "[vecto]") {
    const auto a = map::vecto_torque_axis({100, 50, -100});
    REQUIRE(a.size() == 5);
    CHECK(a == std::vector<double>{-100, -50, 0, 50, 100});
}

TEST_CASE("VECTO loss map: T_out = (T_in - T_loss) r_gear reproduces the model in both power-flow directions",
          "[vecto]") {
    // The gearbox driven from its input (T_in > 0) and from its output (coasting, T_in < 0):
    // VECTO's formula with the exported loss torque must give the model's output torque, and
    // the loss torque is positive both ways (power balance P_out = P_in - P_loss).
    auto c = io::load_case(test_support::source_path("configs/manual-6speed.yaml"), std::string("g2"));
    c.model.thermal.mode = solver::ThermalMode::fixed;
    c.model.thermal.oil_temperature = 273.15 + 70;
    const double w = 2000 * std::numbers::pi / 30;
    const auto rows = map::vecto_loss_map(c.model, {w}, {80, 160}, {});
    REQUIRE(rows.size() == 5);
    const double r_gear = 1.0 / std::abs(c.model.layout.ratio);
    for (const auto& row : rows) {
        INFO("T_in " << row.torque);
        CHECK(row.loss_torque > 0);
        const auto p = solver::solve_point(c.model, w, row.torque);
        CHECK((row.torque - row.loss_torque) * r_gear == Approx(p.torque_out).epsilon(1e-9).margin(1e-9));
        CHECK(p.power_out == Approx(p.power_in - p.losses.total()).epsilon(1e-12).margin(1e-9));
        if (row.torque < 0) {
            // Driven from the output: more power enters at the output than leaves at the input.
            CHECK(p.power_in < 0);
            CHECK(std::abs(p.power_out) > std::abs(p.power_in));
            CHECK(p.efficiency == Approx(std::abs(p.power_in) / std::abs(p.power_out)).epsilon(1e-12));
        }
    }
    // The 0 rpm row is the 1 rpm limit of the loss torque.
    const auto zero = map::vecto_loss_map(c.model, {0.0}, {80}, {});
    CHECK(zero[0].speed == 0.0);
    CHECK(zero[1].loss_torque > 0);
    CHECK(map::vecto_csv(zero).rfind("Input Speed [rpm],Input Torque [Nm],Torque Loss [Nm]\n0.00,-80.00,", 0) == 0);
}
