#include <catch2/catch.hpp>
#include <cmath>
#include <string>

#include "gearloss/case/config.hpp"
#include "gearloss/core/errors.hpp"
#include "gearloss/solver/operating_point.hpp"
#include "test_support.hpp"
#include "gearloss/thermal/equilibrium.hpp"
#include "gearloss/thermal/heat_rejection.hpp"

using namespace gearloss;
using Approx = Catch::Detail::Approx;

namespace {
// A calibration block outside a key's bounds: an InputError naming the key and its bounds.
void check_calibration_rejected(const std::string& calibration, const std::string& key, const std::string& bounds) {
    const std::string base = test_support::read_file(test_support::source_path("configs/transfer-box.yaml"));
    test_support::TempConfig bad(base + "calibration:\n" + calibration);
    try {
        io::load_case(bad.path);
        FAIL("no error for " + calibration);
    } catch (const InputError& e) {
        CHECK(std::string(e.what()).find(key) != std::string::npos);
        CHECK(std::string(e.what()).find("must be in " + bounds) != std::string::npos);
    }
}
}  // namespace

TEST_CASE("constant loss through a thermal resistance: T = Ta + P R", "[thermal]") {
    thermal::HeatRejection h{thermal::ThermalResistance{0.1, 0, 0}};
    const double Ta = 298.15;
    auto F = [&](double T) { return 300.0 - h.heat_flow(T, Ta, 0); };
    auto G = [&](double) { return 10.0; };
    const auto eq = thermal::solve_equilibrium(F, G, Ta);
    REQUIRE(eq.status == thermal::EquilibriumStatus::ok);
    CHECK(eq.T == Approx(Ta + 30.0).margin(1e-3));
    CHECK(std::abs(eq.residual) < 0.02);
}

TEST_CASE("losses growing faster than heat rejection have no equilibrium", "[thermal]") {
    // P = 200 + 5 (T - Ta) W against Q = 4 (T - Ta) W: P - Q > 0 at every temperature.
    const double Ta = 298.15;
    auto F = [&](double T) { return 200.0 + 5.0 * (T - Ta) - 4.0 * (T - Ta); };
    auto G = [&](double) { return 4.0; };
    const auto eq = thermal::solve_equilibrium(F, G, Ta);
    CHECK(eq.status == thermal::EquilibriumStatus::no_equilibrium);
}

TEST_CASE("the first stable root is found when two exist", "[thermal]") {
    // F = 60 - 4x + 0.05 x^2 (x = T - Ta): roots x = 20 (stable, F falls through zero)
    // and x = 60 (unstable).
    const double Ta = 298.15;
    auto F = [&](double T) {
        const double x = T - Ta;
        return 60.0 - 4.0 * x + 0.05 * x * x;
    };
    auto G = [&](double) { return 4.0; };
    const auto eq = thermal::solve_equilibrium(F, G, Ta);
    REQUIRE(eq.status == thermal::EquilibriumStatus::ok);
    CHECK(eq.T - Ta == Approx(20.0).margin(1e-3));
}

TEST_CASE("housing radiation and free convection coefficients", "[thermal]") {
    thermal::HousingSurface s;
    s.emissivity = 0.9;
    // 0.9 * 5.670374e-8 * (348.15^2 + 298.15^2) * (348.15 + 298.15) = 6.92976 W/(m^2 K)
    CHECK(s.radiation_coefficient(348.15, 298.15) == Approx(6.92976).epsilon(1e-5));
    // Free convection of air on a 0.3 m wall at dT = 50 K: the laminar shortcut
    // 1.42 (dT/L)^0.25 = 5.09 W/(m^2 K); the full correlation must agree within 10 %.
    s.height = 0.3;
    CHECK(s.convection_coefficient(348.15, 298.15) == Approx(5.09).epsilon(0.10));
}

TEST_CASE("stabilised points satisfy the heat balance, fixed mode skips the solve", "[thermal][solver]") {
    auto c = io::load_case(test_support::source_path("configs/transfer-box.yaml"));
    const auto& m = c.model;
    for (size_t i = 0; i < c.grid.size(); ++i) {
        const auto [w, T] = c.grid.at(i);
        const auto r = solver::solve_point(m, w, T);
        REQUIRE(r.status == solver::PointStatus::ok);
        const double Q = m.heat_flow(r.oil_temperature, r.ambient, w);
        // Residual at the solution: the bracket is 1e-3 K wide, the conductance ~8 W/K.
        CHECK(std::abs(r.losses.total() - Q) < 0.05);
        CHECK(r.oil_temperature > r.ambient);
    }
    c.model.thermal.mode = solver::ThermalMode::fixed;
    c.model.thermal.oil_temperature = 343.15;
    const auto r = solver::solve_point(c.model, 83.7758, 250);
    CHECK(r.oil_temperature == 343.15);
    CHECK(r.losses.total() ==
          Approx(solver::total_loss(c.model, solver::prepare_point(c.model, 83.7758, 250), 343.15)).epsilon(1e-12));
}

TEST_CASE("forced cooling grows as the fitted power of speed", "[thermal]") {
    // calibration cooling_per_1000rpm a and cooling_speed_exponent q: the heat flow to ambient
    // times (1 + a (n/1000 rpm)^q). Hand check at 4000 rpm, a = 0.2: q = 0.5 gives
    // 1 + 0.2 x 2 = 1.4, q = 1 (the default) 1 + 0.2 x 4 = 1.8; at 1000 rpm both give 1.2.
    auto c = test_support::load_shipped("configs/transfer-box.yaml");
    auto& m = c.model;
    const double Ta = 298.15, T = 348.15, w4000 = 4000 * M_PI / 30, w1000 = 1000 * M_PI / 30;
    const double Q4000 = m.surface_heat_flow(T, Ta, w4000, 0), Q1000 = m.surface_heat_flow(T, Ta, w1000, 0);
    REQUIRE(Q4000 > 0);
    m.calibration.cooling_per_1000rpm = 0.2;
    CHECK(m.surface_heat_flow(T, Ta, w4000, 0) == Approx(1.8 * Q4000).epsilon(1e-12));
    m.calibration.cooling_speed_exponent = 0.5;
    CHECK(m.surface_heat_flow(T, Ta, w4000, 0) == Approx(1.4 * Q4000).epsilon(1e-12));
    CHECK(m.surface_heat_flow(T, Ta, w1000, 0) == Approx(1.2 * Q1000).epsilon(1e-12));
    // A calibration key with bounds: out of them, an error at its key; in them, read.
    const std::string base = test_support::read_file(test_support::source_path("configs/transfer-box.yaml"));
    {
        test_support::TempConfig cfg(base + "calibration:\n  cooling_per_1000rpm: 0.1\n  cooling_speed_exponent: 0.65\n");
        CHECK(io::load_case(cfg.path).model.calibration.cooling_speed_exponent == 0.65);
    }
    check_calibration_rejected("  cooling_speed_exponent: 5\n", "cooling_speed_exponent", "[0.2, 2]");
}

TEST_CASE("the heat flow bends with the oil's rise over ambient by the calibrated slope", "[thermal]") {
    // calibration heat_rejection_rise_slope s: the heat flow to ambient times
    // (1 + s (dT - 50 K)/50 K), dT the surface's rise over ambient. Hand check: at a 50 K rise
    // any s leaves it; at 80 K, s = 0.1 gives 1 + 0.1 x 30/50 = 1.06; at 20 K, s = -0.15 gives
    // 1 - 0.15 x (-30)/50 = 1.09. With forced cooling and a factor the three multiply.
    auto c = test_support::load_shipped("configs/transfer-box.yaml");
    auto& m = c.model;
    const double Ta = 298.15, w = 2000 * M_PI / 30;
    const double Q50 = m.surface_heat_flow(Ta + 50, Ta, w, 0), Q80 = m.surface_heat_flow(Ta + 80, Ta, w, 0),
                 Q20 = m.surface_heat_flow(Ta + 20, Ta, w, 0);
    REQUIRE(Q20 > 0);
    m.calibration.heat_rejection_rise_slope = 0.1;
    CHECK(m.surface_heat_flow(Ta + 50, Ta, w, 0) == Approx(Q50).epsilon(1e-12));
    CHECK(m.surface_heat_flow(Ta + 80, Ta, w, 0) == Approx(1.06 * Q80).epsilon(1e-12));
    m.calibration.heat_rejection_rise_slope = -0.15;
    CHECK(m.surface_heat_flow(Ta + 20, Ta, w, 0) == Approx(1.09 * Q20).epsilon(1e-12));
    CHECK_FALSE(m.calibration.neutral());
    // Beyond the rises it is valid for (0 to 150 K) the factor is held at its end: at a 200 K
    // rise with s = -0.2 it is 1 - 0.2 x 100/50 = 0.6 (not 1 - 0.2 x 150/50 = 0.4), at a surface
    // 10 K below ambient with s = 0.15 it is 1 + 0.15 x (-50)/50 = 0.85.
    {
        auto held = m;
        held.calibration.heat_rejection_rise_slope = 0;
        const double Q200 = held.surface_heat_flow(Ta + 200, Ta, w, 0), Qcold = held.surface_heat_flow(Ta - 10, Ta, w, 0);
        held.calibration.heat_rejection_rise_slope = -0.2;
        CHECK(held.surface_heat_flow(Ta + 200, Ta, w, 0) == Approx(0.6 * Q200).epsilon(1e-12));
        held.calibration.heat_rejection_rise_slope = 0.15;
        CHECK(held.surface_heat_flow(Ta - 10, Ta, w, 0) == Approx(0.85 * Qcold).epsilon(1e-12));
    }
    // 1.09 x 0.8 x (1 + 0.2 x 2) at 2000 rpm with a factor 0.8 and a linear forced cooling 0.2.
    m.calibration.heat_rejection_factor = 0.8;
    m.calibration.cooling_per_1000rpm = 0.2;
    CHECK(m.surface_heat_flow(Ta + 20, Ta, w, 0) == Approx(1.09 * 0.8 * 1.4 * Q20).epsilon(1e-12));
    // Read with its bounds: beyond |s| = 0.2 the heat flow could fall as the oil heats.
    const std::string base = test_support::read_file(test_support::source_path("configs/transfer-box.yaml"));
    {
        test_support::TempConfig cfg(base + "calibration:\n  heat_rejection_rise_slope: -0.12\n");
        CHECK(io::load_case(cfg.path).model.calibration.heat_rejection_rise_slope == -0.12);
    }
    for (const char* s : {"-0.2", "0.2"}) {
        test_support::TempConfig cfg(base + "calibration:\n  heat_rejection_rise_slope: " + s + "\n");
        CHECK(io::load_case(cfg.path).model.calibration.heat_rejection_rise_slope == std::stod(s));
    }
    check_calibration_rejected("  heat_rejection_rise_slope: 0.3\n", "heat_rejection_rise_slope", "[-0.2, 0.2]");
    check_calibration_rejected("  heat_rejection_rise_slope: -0.3\n", "heat_rejection_rise_slope", "[-0.2, 0.2]");
}
