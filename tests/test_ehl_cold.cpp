#include <catch2/catch.hpp>
#include <algorithm>
#include <cmath>
#include <filesystem>
#include <numbers>
#include <string>
#include <vector>

#include "gearloss/case/config.hpp"
#include "gearloss/losses/mechanism_set.hpp"
#include "gearloss/mechanisms/mesh_friction_mechanism.hpp"
#include "gearloss/mesh/friction.hpp"
#include "gearloss/solver/operating_point.hpp"
#include "test_support.hpp"

using namespace gearloss;

namespace {

std::vector<std::string> shipped_oils() {
    std::vector<std::string> v;
    for (const auto& e : std::filesystem::directory_iterator(test_support::source_path("configs/oils")))
        if (e.path().extension() == ".yaml") v.push_back(e.path().string());
    std::sort(v.begin(), v.end());
    return v;
}

}  // namespace

TEST_CASE("Gupta thermal film factor: the Ertel-Grubin film at -24 degC by hand, no collapse past the turning point",
          "[ehl][film][cold]") {
    // Hand calculation (ESTR, ISO VG 320 ester, at -24 degC = 249.15 K; pitch point of the
    // seed-000 pair at 1600 rpm: r_w = 46 mm, alpha_wt = 20 deg, rho_C = 7.87 mm, 800 N m):
    //   D341: log10 log10(nu + 0.7) = 7.5823 - 2.8802 log10(249.15) = 0.6800 -> nu = 4.785e4 mm^2/s
    //   rho = 915 (1 + 8.1e-4 x 39) = 943.9 kg/m^3 -> eta0 = 45.2 Pa s
    //   Gold (ester): alpha = 0.6605e-8 nu^0.1360 = 2.86e-8 1/Pa
    //   u_e = omega r_w sin(alpha_wt) = 167.55 x 0.046 x 0.3420 = 2.636 m/s
    //   beta = B (nu + 0.7) ln(nu + 0.7) / (nu T) + expansion = 2.8802 x 10.776 / 249.15 + 8.4e-4
    //        = 0.1254 1/K; k = 0.158 (1 + 0.00054 x 24) = 0.1600 W/(m K)
    //   L = beta eta0 u_e^2 / k = 0.1254 x 45.2 x 6.95 / 0.1600 = 246
    //   p_H / E' = 0.0087 (p_H ~ 2 GPa, E' = 230.8 GPa): 13.2 x 0.0087 x 246^0.42 = 1.14 > 1,
    //   so the full Gupta form gives phi_T < 0: a negative film (the old code clamped it to 0,
    //   Lambda = 0, full boundary friction).
    // Turning point L* (d ln phi_T / d ln L = -1/2, where the load term is held), solved by hand
    // by bisection with c = 13.2 x 0.0087 = 0.1148, b = 0.213: L* = 10.47, numerator
    // 1 - c L*^0.42 = 0.692.
    const double p_ratio = 0.0087;
    const double L_star = mesh::gupta_turning_point(p_ratio, 0.0);
    CHECK(L_star == Approx(10.47).epsilon(0.005));
    // Below L* the correlation as published.
    const double L1 = 5.0;
    CHECK(mesh::gupta_thermal_factor(L1, p_ratio, 0.0) ==
          Approx((1 - 13.2 * p_ratio * std::pow(L1, 0.42)) / (1 + 0.213 * std::pow(L1, 0.64))).epsilon(1e-12));
    // At L = 246: 246^0.64 = 33.90, phi_T = 0.692 / (1 + 0.213 x 33.90) = 0.692 / 8.221 = 0.0842
    // (the published form: (1 - 0.1148 x 246^0.42) / 8.221 = -0.0167).
    CHECK(mesh::gupta_thermal_factor(246.0, p_ratio, 0.0) == Approx(0.0842).epsilon(0.005));
    // Continuous at L*.
    CHECK(mesh::gupta_thermal_factor(L_star * (1 - 1e-9), p_ratio, 0.0) ==
          Approx(mesh::gupta_thermal_factor(L_star * (1 + 1e-9), p_ratio, 0.0)).epsilon(1e-6));
    // The Ertel-Grubin film phi_T H_c, H_c ~ eta0^(8/11) (L ~ eta0), never thins as the oil
    // thickens: phi_T(L) L^(8/11) does not fall with L, through L* and far beyond L0 = 173.
    double prev = 0;
    for (double L = 1; L < 1e6; L *= 1.05) {
        const double film = mesh::gupta_thermal_factor(L, p_ratio, 0.0) * std::pow(L, 8.0 / 11.0);
        CHECK(film > 0);
        CHECK(film >= prev * (1 - 1e-9));
        prev = film;
    }
}

TEST_CASE("seed-000 local thermal-EHL mesh over -30..150 degC: every shipped oil, both local forms, continuous",
          "[ehl][envelope][cold]") {
    const auto oils = shipped_oils();
    REQUIRE(oils.size() >= 5);
    const size_t mesh_index = losses::MechanismSet{}.index("mesh");
    const double w = 1600 * std::numbers::pi / 30;  // the case's highest speed
    for (const auto& oil : oils) {
        for (auto form : {mesh::FrictionModel::ehl_local, mesh::FrictionModel::ehl_maxwell}) {
            for (double torque : {800.0, -800.0, 200.0}) {
                auto c = io::load_case(test_support::source_path("configs/spur-seed000.yaml"));
                io::replace_oil_file(c, oil);
                mesh::mesh_forms(c.model).friction = form;
                c.model.thermal.mode = solver::ThermalMode::fixed;
                std::vector<double> T, P, lam;
                for (int tc = -30; tc <= 150; ++tc) {
                    c.model.thermal.oil_temperature = 273.15 + tc;
                    const auto r = solver::solve_point(c.model, w, torque, true);
                    if (r.status != solver::PointStatus::ok && r.status != solver::PointStatus::above_oil_limit) continue;
                    T.push_back(tc);
                    P.push_back(r.losses.power[mesh_index]);
                    lam.push_back(r.losses.lambda_min);
                }
                INFO(oil << (form == mesh::FrictionModel::ehl_local ? " ehl_local " : " ehl_maxwell ") << torque << " N m");
                REQUIRE(T.size() > 100);
                for (size_t i = 0; i < T.size(); ++i) {
                    INFO("T = " << T[i] << " degC, P = " << P[i] << " W, lambda = " << lam[i]);
                    CHECK(std::isfinite(P[i]));
                    CHECK(P[i] > 0);
                    CHECK(lam[i] > 0);
                    if (i == 0) continue;
                    // The film thickens as the oil cools (1 K steps).
                    CHECK(lam[i] <= lam[i - 1] * (1 + 1e-6));
                    // No step: within 1 K the loss changes by no more than the neighbours' trend
                    // predicts (the change from the step before, with 20 % and 1 % of the level
                    // as slack for curvature).
                    if (i >= 2) {
                        const double trend = std::abs(P[i - 1] - P[i - 2]);
                        CHECK(std::abs(P[i] - P[i - 1]) <= 1.2 * trend + 0.01 * P[i - 1]);
                        const double ltrend = std::abs(lam[i - 1] - lam[i - 2]);
                        CHECK(std::abs(lam[i] - lam[i - 1]) <= 1.2 * ltrend + 0.01 * lam[i - 1]);
                    }
                }
            }
        }
    }
}

TEST_CASE("a case whose cold oil is past the thermal film correction's turning point gets a located note",
          "[ehl][cold][plausibility]") {
    const std::string base = test_support::read_file(test_support::source_path("configs/spur-seed000.yaml"));
    // At 25 degC ambient the seed-000 oil stays within the correlation: no note.
    CHECK(io::load_case(test_support::source_path("configs/spur-seed000.yaml")).warnings.size() == 0);
    // At -25 degC ambient the pitch point at 1600 rpm is past L* (75W90-syn-A: beyond below -9 degC).
    const std::string cold = test_support::replace_once(base, "ambient: 25 degC", "ambient: -25 degC");
    test_support::TempConfig cfg(cold);
    const auto c = io::load_case(cfg.path);
    bool found = false;
    for (const auto& w : c.warnings)
        if (w.find("turning point") != std::string::npos) {
            found = true;
            CHECK_THAT(w, Catch::Contains("meshes[0]"));
            CHECK_THAT(w, Catch::Contains("Gupta et al. (1992)"));
            CHECK_THAT(w, Catch::Contains("the local EHL friction"));
        }
    CHECK(found);
}
