// The SKF (2004) bearing model over the whole operating envelope: where the replenishment/
// starvation factor phi_rs applies (not in a flooded bearing), and that past the limit of its
// exponential the loss neither falls with speed nor with colder oil, nor steps with temperature.
#include <catch2/catch.hpp>
#include <algorithm>
#include <cmath>
#include <filesystem>
#include <numbers>
#include <string>
#include <vector>

#include "gearloss/bearings/skf_model.hpp"
#include "gearloss/case/case_plausibility.hpp"
#include "gearloss/case/config.hpp"
#include "gearloss/solver/operating_point.hpp"
#include "loss_parts.hpp"
#include "test_support.hpp"

using namespace gearloss;

namespace {
constexpr double rpm = std::numbers::pi / 30.0;
constexpr double cSt = 1e-6;    // m^2/s
constexpr double Nmm = 1e-3;    // N m

// A 6205 deep groove ball bearing (d 25, D 52 mm, d_m 38.5 mm) with the SKF (2004) constants of
// the 62 series (R1 3.9e-7, S1 3.23e-3, K_Z 3.1), mineral oil (mu_bl 0.15, mu_EHL 0.05).
bearings::BearingSpec bearing_6205() {
    bearings::BearingSpec b;
    b.type = bearings::BearingType::deep_groove_ball;
    b.d = 25e-3;
    b.D = 52e-3;
    b.B = 15e-3;
    b.C0 = 7800;
    b.k.R1 = 3.9e-7;
    b.k.S1 = 3.23e-3;
    b.k.K_Z = 3.1;
    b.mu_bl = 0.15;
    b.mu_ehl = 0.05;
    return b;
}
}  // namespace

// Hand calculation, SKF (2004), 6205, F_r = 1000 N, F_a = 0, n = 3000 r/min:
//   G_rr = R1 d_m^1.96 F_r^0.54 = 3.9e-7 * 38.5^1.96 * 1000^0.54 = 0.020824
//   G_sl = S1 d_m^-0.26 F_r^(5/3) = 3.23e-3 * 38.5^-0.26 * 1000^(5/3) = 125.021
//   phi_ish = 1 / (1 + 1.84e-9 (n d_m)^1.28 nu^0.64)
//   phi_bl = exp(-2.6e-8 (n nu)^1.4 d_m), mu_sl = 0.15 phi_bl + 0.05 (1 - phi_bl)
// (a) flooded (oil bath at the rolling-element centres, phi_rs = 1), nu = 20 cSt:
//   phi_ish = 1 / (1 + 1.84e-9 * 115500^1.28 * 20^0.64) = 0.96357
//   M_rr = 0.96357 * 0.020824 * (20 * 3000)^0.6 = 14.769 N mm
//   phi_bl = exp(-2.6e-8 * 60000^1.4 * 38.5) = 0.0074761, mu_sl = 0.050748, M_sl = 6.3445 N mm
//   M = 21.113 N mm
// (b) starved (low-level bath / splash, K_rs = 3e-8), nu = 20 cSt:
//   K_rs n (d+D) sqrt(K_Z / (2 (D-d))) = 3e-8 * 3000 * 77 * sqrt(3.1 / 54) = 1.66042e-3 per cSt
//   phi_rs = exp(-1.66042e-3 * 20) = 0.96734, M_rr = 14.286 N mm, M = 20.631 N mm
// (c) starved, nu = 1000 cSt: phi_ish phi_rs (nu n)^0.6 is largest where its slope over ln nu,
//   0.6 - 0.64 s - 1.66042e-3 nu with s = A nu^0.64 / (1 + A nu^0.64), A = 1.84e-9 * 115500^1.28
//   = 5.55805e-3, is zero: nu* = 294.132 cSt (A nu*^0.64 = 0.211247, s = 0.174404, 0.64 s = 0.111619,
//   1.66042e-3 nu* = 0.488381, sum 0.600000). Past it the rolling moment is the one at nu*:
//   phi_ish = 1 / 1.211247 = 0.825596, phi_rs = exp(-0.488381) = 0.613619,
//   M_rr = 0.825596 * 0.613619 * 0.020824 * (294.132 * 3000)^0.6 = 38.961 N mm (SKF's exponential
//   extrapolated gives 20.830 N mm, less than at 294 cSt: a loss falling as the oil thickens).
//   M_sl = 0.05 * 125.021 = 6.2510 N mm (phi_bl = 0 at this nu n).
TEST_CASE("SKF (2004) by hand: flooded, starved and past the starvation limit", "[bearings][envelope_bearings]") {
    const double w = 3000 * rpm;
    auto flooded = bearing_6205();
    flooded.K_rs = 0.0;  // lubrication: oil_bath
    const auto a = bearings::skf_moment(flooded, 1000, 0, w, 20 * cSt);
    CHECK(a.phi_rs == 1.0);
    CHECK(a.rolling / Nmm == Approx(14.769).epsilon(1e-4));
    CHECK(a.sliding / Nmm == Approx(6.3445).epsilon(1e-4));
    CHECK(a.total() / Nmm == Approx(21.113).epsilon(1e-4));

    auto starved = bearing_6205();
    starved.K_rs = 3e-8;
    const auto b = bearings::skf_moment(starved, 1000, 0, w, 20 * cSt);
    CHECK(b.phi_rs == Approx(0.96734).epsilon(1e-5));
    CHECK(b.rolling / Nmm == Approx(14.286).epsilon(1e-4));
    CHECK(b.total() / Nmm == Approx(20.631).epsilon(1e-4));
    CHECK_FALSE(b.starvation_held);

    CHECK(bearings::skf_starvation_limit_nu(starved, w) / cSt == Approx(294.132).epsilon(1e-5));
    const auto c = bearings::skf_moment(starved, 1000, 0, w, 1000 * cSt);
    CHECK(c.starvation_held);
    CHECK(c.phi_ish == Approx(0.825596).epsilon(1e-5));
    CHECK(c.phi_rs == Approx(0.613619).epsilon(1e-5));
    CHECK(c.rolling / Nmm == Approx(38.961).epsilon(1e-4));
    CHECK(c.sliding / Nmm == Approx(6.2510).epsilon(1e-4));
    // The per-point path (SkfAtPoint, used by the loss mechanism) agrees with the full evaluation.
    const auto p = bearings::SkfAtPoint::make(starved, 1000, 0, w);
    const double nu = 1000;
    CHECK(p.moment(nu, std::pow(nu, 0.6), std::pow(nu, 0.64), std::pow(nu, 1.4), std::pow(nu, 1.379)) ==
          Approx(c.total()).epsilon(1e-12));
}

// A starved 6205 (splash and grease K_rs) over 10 ... 20000 r/min and 1 ... 1e5 cSt: the rolling
// moment never falls as the oil thickens and its power never falls as the speed rises (the
// properties SKF's exponential loses past its peak; without the hold, at 3000 r/min the moment
// falls from 38.96 N mm at 294 cSt to 20.83 N mm at 1000 cSt).
TEST_CASE("SKF (2004) starved rolling moment: rises with viscosity and its power with speed", "[bearings][envelope_bearings]") {
    for (double K_rs : {3e-8, 6e-8}) {
        auto b = bearing_6205();
        b.K_rs = K_rs;
        for (double n = 10; n <= 20000; n *= 1.25) {
            double prev = 0;
            for (double nu = 1; nu <= 1e5; nu *= 1.1) {
                const double M = bearings::skf_moment(b, 1000, 0, n * rpm, nu * cSt).rolling;
                INFO("K_rs " << K_rs << ", " << n << " r/min, " << nu << " cSt");
                CHECK(M >= prev * (1 - 1e-9));
                prev = M;
            }
        }
        for (double nu = 1; nu <= 1e5; nu *= 1.25) {
            double prev = 0;
            for (double n = 10; n <= 20000; n *= 1.1) {
                const double P = bearings::skf_moment(b, 1000, 0, n * rpm, nu * cSt).rolling * n * rpm;
                INFO("K_rs " << K_rs << ", " << n << " r/min, " << nu << " cSt");
                CHECK(P >= prev * (1 - 1e-9));
                prev = P;
            }
        }
    }
}

// SKF (2004): phi_rs is for a low-level oil bath (level up to the centre of the lowest rolling
// element), splash, oil jet, oil-air and grease; a higher bath floods the rolling elements. 6205:
// rolling-element centre at 0.15 (D - d) = 0.15 * 27 = 4.05 mm above the outer raceway's bottom.
TEST_CASE("SKF (2004): an oil bath up to the rolling-element centres floods the bearing", "[bearings][envelope_bearings]") {
    const double w = 3000 * rpm;
    auto b = bearing_6205();
    b.K_rs = 3e-8;
    b.bath_H = 3e-3;  // below the centres: starved, phi_rs = 0.96734 (hand calculation above)
    CHECK(bearings::skf_moment(b, 1000, 0, w, 20 * cSt).phi_rs == Approx(0.96734).epsilon(1e-5));
    b.bath_H = 5e-3;  // above: flooded
    CHECK(bearings::skf_moment(b, 1000, 0, w, 20 * cSt).phi_rs == 1.0);
    CHECK(bearings::skf_moment(b, 1000, 0, w, 20 * cSt).rolling / Nmm == Approx(14.769).epsilon(1e-4));
    CHECK(std::isinf(bearings::skf_starvation_limit_nu(b, w)));
}

namespace {
// The shipped cases (configs/*.yaml).
std::vector<std::string> shipped_cases() {
    std::vector<std::string> v;
    for (const auto& e : std::filesystem::directory_iterator(test_support::source_path("configs")))
        if (e.path().extension() == ".yaml" && e.path().filename().string().rfind("tmp-test-", 0) != 0)
            v.push_back(e.path().string());
    std::sort(v.begin(), v.end());
    return v;
}
}  // namespace

// Over -30 ... 150 degC (every 3 K) and 0 ... the case's largest input speed (10 steps), at 0.1,
// 0.5 and 1 of its largest torque (4000 rpm and 200 N m for a case without a grid): the bearings' loss is finite, > 0 when turning under load,
// does not fall as the speed rises, and has no step over temperature (the envelope suite's
// definition, docs/envelope.md: the change of ln P over one 3 K interval differs from the mean of
// its neighbours' by more than 0.10 and by more than twice the difference of their slopes).
TEST_CASE("bearing loss over the envelope of every shipped case: no fall with speed, no step", "[bearings][envelope_bearings]") {
    for (const auto& file : shipped_cases()) {
        auto c = io::load_case(file);
        c.model.thermal.mode = solver::ThermalMode::fixed;
        double n_max = 0, T_max = 0;
        for (double s : c.grid.speeds) n_max = std::max(n_max, std::abs(s));
        for (double t : c.grid.torques) T_max = std::max(T_max, std::abs(t));
        // A case with a point list (the wind turbine's 9..16.5 rpm power curve): its points.
        for (const auto& [s, t] : c.grid.points) {
            n_max = std::max(n_max, std::abs(s));
            T_max = std::max(T_max, std::abs(t));
        }
        // A case without an operating grid (vehicle cases, driven by a cycle): 4000 rpm and 200 N m.
        if (!(n_max > 0)) n_max = 4000 * rpm;
        if (!(T_max > 0)) T_max = 200;
        std::vector<double> temps;
        for (double T = -30; T <= 150 + 1e-9; T += 3) temps.push_back(T);
        int falls = 0, steps = 0, bad = 0;
        for (double frac : {0.1, 0.5, 1.0}) {
            const double torque = frac * T_max;
            // P[speed][temperature]
            std::vector<std::vector<double>> P(11, std::vector<double>(temps.size()));
            for (size_t j = 0; j < temps.size(); ++j) {
                c.model.thermal.oil_temperature = temps[j] + 273.15;
                for (size_t i = 0; i <= 10; ++i) {
                    const double n = n_max * static_cast<double>(i) / 10.0;
                    P[i][j] = test::part(solver::solve_point(c.model, n, torque).losses, "bearings");
                    if (!std::isfinite(P[i][j]) || P[i][j] < 0 || (i > 0 && torque > 0 && !(P[i][j] > 0))) {
                        if (bad++ < 3)
                            FAIL_CHECK(file << ": bearing loss " << P[i][j] << " W at " << n / rpm << " rpm, " << torque
                                            << " N m, " << temps[j] << " degC");
                    }
                    if (i > 0 && P[i][j] < P[i - 1][j] * (1 - 1e-9)) {
                        if (falls++ < 3)
                            FAIL_CHECK(file << ": bearing loss falls with speed at " << temps[j] << " degC, " << torque
                                            << " N m: " << P[i - 1][j] << " W at " << n_max * (i - 1) / 10 / rpm << " rpm -> "
                                            << P[i][j] << " W at " << n / rpm << " rpm");
                    }
                }
            }
            for (size_t i = 1; i <= 10; ++i)
                for (size_t j = 1; j + 2 < temps.size(); ++j) {
                    const double d0 = std::log(P[i][j] / P[i][j - 1]), d1 = std::log(P[i][j + 1] / P[i][j]),
                                 d2 = std::log(P[i][j + 2] / P[i][j + 1]);
                    const double trend = 0.5 * (d0 + d2);
                    if (std::abs(d1 - trend) > 0.10 && std::abs(d1 - trend) > 2.0 * std::abs(d2 - d0)) {
                        if (steps++ < 3)
                            FAIL_CHECK(file << ": bearing loss steps between " << temps[j] << " and " << temps[j + 1]
                                            << " degC at " << n_max * i / 10 / rpm << " rpm, " << torque << " N m: "
                                            << P[i][j] << " -> " << P[i][j + 1] << " W");
                    }
                }
        }
        INFO(file);
        CHECK(falls == 0);
        CHECK(steps == 0);
        CHECK(bad == 0);
    }
}

// Not silently: a fixed-temperature run names the bearings past the starvation limit. Transfer
// box, B1_RMS11 (d 35, D 89 mm, d_m 62 mm, 63 series, K_Z 3.1), splash (K_rs 3e-8), 800 rpm:
// a_rs = 3e-8 * 800 * 124 * sqrt(3.1 / 108) = 5.0420e-4 per cSt, A = 1.84e-9 * 49600^1.28 = 1.8838e-3;
// 0.6 - 0.64 s - a_rs nu = 0 at nu* = 1016.5 cSt (a_rs nu* = 0.51252, A nu*^0.64 = 0.15834,
// 0.64 s = 0.08748). 75W90-A is far thicker at -30 degC (about 3e4 mm^2/s), far thinner at 100 degC.
TEST_CASE("a fixed oil temperature past the SKF starvation limit is a note naming the bearings", "[bearings][envelope_bearings][plausibility]") {
    auto cold = test_support::load_shipped("configs/transfer-box.yaml");
    cold.model.thermal.mode = solver::ThermalMode::fixed;
    cold.model.thermal.oil_temperature = 243.15;
    cold.warnings.clear();
    io::check_oil_temperature(cold, "--oil-temp");
    REQUIRE(cold.warnings.size() == 1);
    INFO(cold.warnings[0]);
    CHECK_THAT(cold.warnings[0], Catch::Contains("--oil-temp: note:"));
    CHECK_THAT(cold.warnings[0], Catch::Contains("'B1_RMS11' (limit 1016 mm^2/s at 800 r/min)"));

    auto warm = test_support::load_shipped("configs/transfer-box.yaml");
    warm.model.thermal.mode = solver::ThermalMode::fixed;
    warm.model.thermal.oil_temperature = 373.15;
    warm.warnings.clear();
    io::check_oil_temperature(warm, "--oil-temp");
    CHECK(warm.warnings.empty());
}
