#include <catch2/catch.hpp>
#include <cmath>
#include <nlohmann/json.hpp>
#include <numbers>

#include "gearloss/core/errors.hpp"
#include "gearloss/case/config.hpp"
#include "gearloss/map/co2mpas_fit.hpp"
#include "gearloss/map/loss_table.hpp"
#include "gearloss/solver/operating_point.hpp"
#include "test_support.hpp"

using namespace gearloss;
using Approx = Catch::Detail::Approx;

namespace {
constexpr double kRadPerRpm = std::numbers::pi / 30.0;

// A sample generated the way CO2MPAS computes the engine-side torque (JRC 2019, thermal.py,
// _evaluate_gear_box_torque_in), written here from the Python source, not from the fit:
// given the output torque T_gb (drive: referred to the input speed; overrun: at the output
// shaft) the input torque follows, and the loss is P_in - P_out.
map::Co2mpasSample co2mpas_sample(const map::Co2mpasParameters& p, double n_in, double T_gb, double k) {
    const double n_out = k * n_in, w_in = n_in * kRadPerRpm, w_out = n_out * kRadPerRpm;
    double T_in, P_out;
    if (T_gb >= 0) {
        T_in = (T_gb - p.gbp10 * n_in - p.gbp00) / p.gbp01;
        P_out = T_gb * w_in;
    } else {
        T_in = (p.gbp01 * T_gb - p.gbp10 * n_out - p.gbp00) * n_out / n_in;
        P_out = T_gb * w_out;
    }
    return {n_in, T_in, T_in * w_in - P_out, k};
}
}  // namespace

TEST_CASE("CO2MPAS fit recovers the coefficients of samples generated from its form", "[co2mpas]") {
    // The manual-gearbox hot defaults of CO2MPAS (defaults.py, automatic = False; engine max
    // torque 300 N m: gbp00 = -0.3 - 0.0034 * 300, gbp10 = -0.1/2000 - 0.0034/2000 * 300).
    const map::Co2mpasParameters truth{-0.3 - 0.0034 * 300, -0.1 / 2000 - 0.0034 / 2000 * 300, 0.975};
    std::vector<map::Co2mpasSample> s;
    for (double k : {0.3, 1.4})
        for (double n : {800.0, 1500.0, 2500.0, 4000.0})
            for (double T : {-120.0, -40.0, -5.0, 3.0, 60.0, 180.0}) s.push_back(co2mpas_sample(truth, n, T, k));
    const auto fit = map::fit_co2mpas(s);
    CHECK(fit.gbp00 == Approx(truth.gbp00).epsilon(1e-9));
    CHECK(fit.gbp10 == Approx(truth.gbp10).epsilon(1e-9));
    CHECK(fit.gbp01 == Approx(truth.gbp01).epsilon(1e-12));
    const auto e = map::co2mpas_fit_error(fit, s);
    CHECK(e.points == s.size());
    CHECK(e.max_Nm < 1e-9);
    // Every sample loses power (the form with negative gbp00, gbp10 and gbp01 < 1 is a loss).
    for (const auto& x : s) CHECK(x.loss > 0);
    // The prediction of the truth is the sample's own input torque in both branches.
    for (const auto& x : s) CHECK(map::co2mpas_torque_in(truth, x) == Approx(x.torque_in).margin(1e-9));
}

TEST_CASE("CO2MPAS fit: an error of known size, and too few speeds refused", "[co2mpas]") {
    const map::Co2mpasParameters p{-1.0, -2e-4, 0.97};
    auto s = map::Co2mpasSample{2000, 100, 0, 0.5};
    // Loss such that the input torque of the form differs from the sample's by 0.5 N m: the
    // drive prediction (T_gb - gbp10 n - gbp00)/gbp01 with T_gb = T_in - P_loss/omega_in.
    const double w = 2000 * kRadPerRpm, T_gb = 0.97 * (100 - 0.5) - 2e-4 * 2000 - 1.0;
    s.loss = (100 - T_gb) * w;
    const auto e = map::co2mpas_fit_error(p, {s});
    CHECK(e.max_Nm == Approx(0.5).epsilon(1e-9));
    CHECK(e.rms_rel == Approx(0.5 / (100 - T_gb)).epsilon(1e-9));
    std::vector<map::Co2mpasSample> one_speed;
    // Drive only, one speed: gbp00 and gbp10 n_in are one column (overrun rows would separate
    // them, since the form takes the output speed there).
    for (double T : {10.0, 80.0, 150.0}) one_speed.push_back(co2mpas_sample(p, 1500, T, 0.5));
    CHECK_THROWS_AS(map::fit_co2mpas(one_speed), InputError);
}

TEST_CASE("Temperature list: units, order and bad items", "[table]") {
    const auto T = map::parse_temperature_list("20, 40,60degC", "--oil-temps");
    REQUIRE(T.size() == 3);
    CHECK(T[0] == Approx(293.15));
    CHECK(T[2] == Approx(333.15));
    CHECK(map::parse_temperature_list("300K,320 K", "--oil-temps")[1] == Approx(320));
    for (const char* bad : {"", "20,40", "20,,40degC", "40,20degC", "20,40rpm", "abc", "20,40,40degC", "-300degC"})
        CHECK_THROWS_AS(map::parse_temperature_list(bad, "--oil-temps"), InputError);
}

TEST_CASE("Loss table: shape, both torque signs, total = sum of mechanisms, values of solve_point", "[table]") {
    io::Case k = test_support::load_shipped("configs/manual-6speed.yaml");
    k.grid.speeds = {1500 * kRadPerRpm, 3000 * kRadPerRpm};
    k.grid.torques = {40, 120};
    const auto axes = map::loss_table_axes(k, {"g2", "g5"}, {313.15, 353.15, 373.15});
    CHECK(axes.torques == std::vector<double>{-120, -40, 0, 40, 120});
    REQUIRE(axes.size() == 2 * 2 * 5 * 3);
    std::string csv;
    const auto t = map::run_loss_table(k.model, axes, {}, [&](std::string_view s) { csv += s; });
    CHECK(std::count(csv.begin(), csv.end(), '\n') == 60);
    CHECK(t.holes() == 0);
    for (size_t r = 0; r < 2; ++r)
        for (size_t iT = 0; iT < 3; ++iT) {
            // Another route: the model with the ratio selected and the oil held at T, one point.
            solver::Model m = k.model.with_ratio(axes.ratios[r]);
            m.thermal.mode = solver::ThermalMode::fixed;
            m.thermal.oil_temperature = axes.oil_temperatures[iT];
            for (size_t s = 0; s < 2; ++s)
                for (size_t q = 0; q < 5; ++q) {
                    const size_t i = t.index(r, s, q, iT);
                    const auto p = solver::solve_point(m, axes.speeds[s], axes.torques[q]);
                    CHECK(t.total[i] == Approx(p.losses.total()).epsilon(1e-12));
                    double sum = 0;
                    for (const auto& col : t.power) sum += col[i];
                    CHECK(t.total[i] == Approx(sum).epsilon(1e-12));
                }
        }
    // The JSON arrays: dimensions equal the breakpoint vectors, in the index order.
    const auto j = nlohmann::json::parse(map::loss_table_json(t));
    const auto& a = j["tables"]["P_total_W"];
    REQUIRE(a.size() == 2);
    REQUIRE(a[0].size() == j["breakpoints"]["speed_in_rpm"].size());
    REQUIRE(a[0][0].size() == j["breakpoints"]["torque_in_Nm"].size());
    REQUIRE(a[0][0][0].size() == j["breakpoints"]["oil_temp_C"].size());
    CHECK(a[1][1][4][2].get<double>() == Approx(t.total[t.index(1, 1, 4, 2)]));
    CHECK(j["tables"]["torque_loss_Nm"][1][1][4][2].get<double>() ==
          Approx(t.total[t.index(1, 1, 4, 2)] / (3000 * kRadPerRpm)));
    CHECK(j["tables"].size() == 2 + t.columns.size());
}

TEST_CASE("Loss table axes: point lists, non-positive speeds and temperatures outside the oil's validity refused",
          "[table]") {
    io::Case k = test_support::load_shipped("configs/manual-6speed.yaml");
    CHECK_THROWS_AS(map::loss_table_axes(k, {}, {5000.0}), InputError);
    const auto ok = map::loss_table_axes(k, {}, map::default_table_temperatures(k.model));
    CHECK(ok.ratios.size() == 6);
    CHECK(ok.oil_temperatures.back() == Approx(k.model.oil.max_temperature));
    CHECK(ok.oil_temperatures.front() == Approx(293.15));
    k.grid.speeds.push_back(0.0);
    CHECK_THROWS_AS(map::loss_table_axes(k, {}, {353.15}), InputError);
    k.grid.is_grid = false;
    CHECK_THROWS_AS(map::loss_table_axes(k, {}, {353.15}), InputError);
}
