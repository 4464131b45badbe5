// Gear windage (lib/gearloss/windage/gear_windage.cpp and its mechanism, lib/gearloss/mechanisms/windage_mechanism.cpp)
// against published values and hand calculations.
#include <catch2/catch.hpp>
#include <cmath>
#include <numbers>

#include "gearloss/case/config.hpp"
#include "gearloss/map/map_runner.hpp"
#include "gearloss/solver/operating_point.hpp"
#include "gearloss/thermal/air.hpp"
#include "test_support.hpp"
#include "gearloss/windage/gear_windage.hpp"

using namespace gearloss;
namespace {
constexpr double kRpm = std::numbers::pi / 30;
}

TEST_CASE("windage: Anderson & Loewenthal (1980) by hand", "[windage]") {
    // R = 0.15 m, b = 0.05 m, 10 000 rpm, mu = 0: n^2.8 = 1.58489e11, R^4.6 = 1.62188e-4,
    // 1 + 2.3 b/R = 1.76667, 0.019^0.2 = 0.452638 -> 2.82e-7 x ... = 5.797 kW.
    CHECK(windage::anderson_loewenthal_power(0.15, 0.05, 10000 * kRpm, 0.0) == Approx(5797).epsilon(2e-4));
    // mu = 10 cP: (0.28 + 0.019)^0.2 = 0.785 -> 10.06 kW; no face width: 5.797 / 1.76667 = 3.281 kW.
    CHECK(windage::anderson_loewenthal_power(0.15, 0.05, 10000 * kRpm, 10e-3) == Approx(10059).epsilon(3e-4));
    CHECK(windage::anderson_loewenthal_power(0.15, 0.0, 10000 * kRpm, 0.0) == Approx(3281).epsilon(3e-4));
    // Scaling: twice the speed, 2^2.8 = 6.964 times the power, whatever the constant.
    CHECK(windage::anderson_loewenthal_power(0.1, 0.03, 6000 * kRpm, 1.8e-5) /
              windage::anderson_loewenthal_power(0.1, 0.03, 3000 * kRpm, 1.8e-5) ==
          Approx(std::pow(2.0, 2.8)).epsilon(1e-12));
}

TEST_CASE("windage: a free disk matches Cochran's laminar solution and the air data", "[windage]") {
    // Laminar: Cochran's (1934) solution of Kármán's similarity equations gives the wall shear
    // tau = -G'(0) rho nu^1/2 w^3/2 r with -G'(0) = 0.6159; integrated over one face,
    // M = int_0^R tau r 2 pi r dr = 0.6159 (pi/2) rho nu^1/2 w^3/2 R^4; both faces, P = 2 M w.
    // Schlichting's C_M = 3.87 Re^-1/2 is the same number rounded: agree to 0.03 %.
    const double R = 0.05, w = 100.0, rho = 1.2, nu = 1.5e-5;  // Re = 16 700, laminar
    const double M_face = 0.6159 * std::numbers::pi / 2 * rho * std::sqrt(nu) * std::pow(w, 1.5) * std::pow(R, 4);
    const double cochran = 2 * M_face * w;
    CHECK(windage::free_disk_power(R, w, rho, nu) == Approx(cochran).epsilon(3e-4));
    // Turbulent (Re = 1.7e7): grows with w^2.8, far above the laminar law.
    const double Pt = windage::free_disk_power(0.5, 1000.0, rho, nu);
    CHECK(Pt / windage::free_disk_power(0.5, 500.0, rho, nu) == Approx(std::pow(2.0, 2.8)).epsilon(1e-9));
    // Air at 20 degC and 1 atm: 1.204 kg/m^3, 18.13 uPa s (handbook values: 1.2041, 18.13e-6).
    CHECK(thermal::air_density(293.15, 101325) == Approx(1.2041).epsilon(1e-3));
    CHECK(thermal::air_viscosity(293.15) == Approx(18.13e-6).epsilon(3e-3));
}

TEST_CASE("windage: a mechanism of its own, off unless a form is chosen", "[windage]") {
    const std::string base = test_support::read_file(test_support::source_path("configs/transfer-box.yaml"));
    auto load = [](const std::string& text) {
        test_support::TempConfig cfg(text);
        return io::load_case(cfg.path);
    };
    const auto nominal = load(base);
    const size_t k = nominal.model.mechanisms.index("windage");
    REQUIRE(k < nominal.model.mechanisms.size());
    CHECK(map::csv_header(nominal.model, false).find(",P_windage_W,") != std::string::npos);
    const auto r0 = solver::solve_point(nominal.model, 3000 * kRpm, 100, true);
    CHECK(r0.losses.power[k] == 0.0);
    for (const char* form : {"anderson_loewenthal", "free_disk"}) {
        INFO(form);
        const auto c = load(base + "mechanisms:\n  windage: {form: " + form + "}\n");
        const auto r = solver::solve_point(c.model, 3000 * kRpm, 100, true);
        REQUIRE(solver::has_values(r.status));
        // Per gear: the sum of the gears, each from its own speed and size.
        const auto& d = r.losses.detail[k];
        double sum = 0;
        for (double v : d.values) sum += v;
        CHECK(r.losses.power[k] == Approx(sum).epsilon(1e-12));
        CHECK(r.losses.power[k] > 0);
        // A real loss: it heats the oil.
        CHECK(r.oil_temperature > r0.oil_temperature);
        // The calibration factor scales it.
        const auto c2 = load(base + "mechanisms:\n  windage: {form: " + form + "}\ncalibration:\n  windage: {factor: 2}\n");
        const auto r2 = solver::solve_point(c2.model, 3000 * kRpm, 100, true);
        CHECK(solver::evaluate_losses(c2.model, solver::prepare_point(c2.model, 3000 * kRpm, 100),
                                      c2.model.oil_state(r.oil_temperature), false)
                  .power[k] == Approx(2 * r.losses.power[k]).epsilon(1e-12));
        (void)r2;
    }
}
