#include <catch2/catch.hpp>
#include <string>

#include "gearloss/case/config.hpp"
#include "gearloss/lubricant/oil.hpp"

using namespace gearloss;
using Approx = Catch::Detail::Approx;

TEST_CASE("Vogel three-point fit reproduces the reference check values", "[lubricant]") {
    // Vogel (1921) law, hand calculation: (40, 68), (70, 20), (100, 8.6) -> k 0.08690, b 888.29, c 93.327
    const double T[3] = {40, 70, 100}, nu[3] = {68, 20, 8.6};
    const auto v = lubricant::VogelLaw::fit(T, nu);
    CHECK(v.k_mm2s == Approx(0.08690).epsilon(2e-4));
    CHECK(v.b_C == Approx(888.29).epsilon(1e-4));
    CHECK(v.c_C == Approx(93.327).epsilon(1e-4));
}

TEST_CASE("ASTM D341 two-point fit reproduces the reference check values", "[lubricant]") {
    // (40 degC, 68), (100 degC, 8.6) -> A 9.3778, B 3.6517, nu(70 degC) = 19.97
    const auto w = lubricant::WaltherLaw::fit(313.15, 68, 373.15, 8.6);
    CHECK(w.A == Approx(9.3778).epsilon(1e-4));
    CHECK(w.B == Approx(3.6517).epsilon(1e-4));
    CHECK(w.nu_mm2s(343.15) == Approx(19.97).epsilon(1e-3));
}

TEST_CASE("shipped oils match seed 001 Table 3.4 within 1 %", "[lubricant]") {
    struct Row { const char* file; double nu40, nu70, nu100, beta40, beta70, beta100; };
    // Viscosity [cSt] and thermoviscosity [1e-3/K] measured at 40/70/100 degC (seed 001 Table 3.4).
    const Row rows[] = {{"75W90-A.yaml", 112.35, 36.7, 16.37, 44.3, 31.3, 23.1},
                        {"75W140-A.yaml", 200.7, 61.86, 26.21, 46.3, 33.2, 24.7}};
    for (const auto& r : rows) {
        const auto oil = io::load_oil_file(std::string(GEARLOSS_SOURCE_DIR) + "/configs/oils/" + r.file);
        INFO(r.file);
        CHECK(oil.nu_mm2s(313.15) == Approx(r.nu40).epsilon(0.01));
        CHECK(oil.nu_mm2s(343.15) == Approx(r.nu70).epsilon(0.01));
        CHECK(oil.nu_mm2s(373.15) == Approx(r.nu100).epsilon(0.01));
        // The thermoviscosity is not an input: it follows from the Vogel law and
        // the expansion; the measured values are an independent check (5 %).
        CHECK(oil.state(313.15).beta_T * 1e3 == Approx(r.beta40).epsilon(0.05));
        CHECK(oil.state(343.15).beta_T * 1e3 == Approx(r.beta70).epsilon(0.05));
        CHECK(oil.state(373.15).beta_T * 1e3 == Approx(r.beta100).epsilon(0.06));
    }
}

TEST_CASE("Gold piezoviscosity and density law", "[lubricant]") {
    lubricant::Oil oil;
    oil.base = lubricant::BaseOil::mineral;
    // 0.9904e-8 * 100^0.139 = 1.88e-8 1/Pa (Gold et al. 2001 law, mineral constants)
    CHECK(oil.pressure_viscosity(313.15, 100.0) == Approx(1.88e-8).epsilon(0.005));
    oil.rho15 = 885;
    oil.expansion = 6.8e-4;
    // rho(75 degC) = 885 (1 - 6.8e-4 * 60) = 848.9
    CHECK(oil.density(348.15) == Approx(848.892).epsilon(1e-6));
}
