// Heat rejection and oil thermal properties against independent values: textbook air
// properties with the published convection correlations worked by hand, and Cragoe's
// correlations in their original US units. Each test names the mutation of
// scripts/mutation-check.sh it is there to kill.
#include <catch2/catch.hpp>
#include <cmath>

#include "gearloss/lubricant/oil.hpp"
#include "gearloss/thermal/heat_rejection.hpp"

using namespace gearloss;
using Approx = Catch::Detail::Approx;

namespace {
// Dry air at 1 atm, Incropera & DeWitt, Fundamentals of Heat and Mass Transfer, Table A.4:
//   300 K: nu 15.89e-6 m^2/s, k 26.3e-3 W/(m K), Pr 0.707;  350 K: nu 20.92e-6, k 30.0e-3, Pr 0.700.
// Linear interpolation to the film temperature T_f = (348.15 + 298.15)/2 = 323.15 K (weight 0.463):
//   nu = 18.219e-6 m^2/s, k = 28.013e-3 W/(m K), Pr = 0.70376.
// (gearloss computes its own air properties from Sutherland's law, the ideal gas and a power law
// for k: 17.88e-6, 27.62e-3, 0.71. Together they move h by -0.3 %: tolerance 1.5 %.)
constexpr double kNu = 18.219e-6, kK = 28.013e-3, kPr = 0.70376, kTf = 323.15;
}  // namespace

TEST_CASE("independent: free convection on a vertical housing wall, Nu = 0.59 Ra^1/4 by hand", "[independent][thermal]") {
    // Wall 75 degC, air 25 degC, height 0.3 m, no air flow; beta = 1/T_f (ideal gas):
    //   Ra = g beta dT L^3 Pr / nu^2 = 9.80665 x (1/323.15) x 50 x 0.027 x 0.70376 / (18.219e-6)^2
    //      = 8.686e7 (< 1e9: laminar)
    //   Nu = 0.59 Ra^0.25 = 0.59 x 96.540 = 56.959;  h = Nu k / L = 56.959 x 0.028013 / 0.3 = 5.3186 W/(m^2 K)
    // Kills T1 (0.59 -> 0.62: h +5.1 %).
    const double Ra = 9.80665 / kTf * 50.0 * 0.3 * 0.3 * 0.3 * kPr / (kNu * kNu);
    CHECK(Ra == Approx(8.686e7).epsilon(1e-3));
    thermal::HousingSurface s;
    s.height = 0.3;
    s.air_speed = 0.0;
    CHECK(s.convection_coefficient(348.15, 298.15) == Approx(5.3186).epsilon(0.015));
}

TEST_CASE("independent: forced convection over the housing, flat plate mixed with free convection, by hand",
          "[independent][thermal]") {
    // Same wall with 2 m/s of air along 0.3 m:
    //   Re = u L / nu = 2 x 0.3 / 18.219e-6 = 32 933 (< 5e5: laminar)
    //   Nu = 0.664 Re^0.5 Pr^(1/3) = 0.664 x 181.474 x 0.88951 = 107.18;  h_forced = 107.18 x 0.028013/0.3 = 10.008
    //   Churchill's cube-root mixing with h_free = 5.3186 (above):
    //   h = (5.3186^3 + 10.008^3)^(1/3) = (150.45 + 1002.5)^(1/3) = 10.486 W/(m^2 K)
    // Kills T2 (0.664 -> 0.697: h +4.2 %).
    thermal::HousingSurface s;
    s.height = 0.3;
    s.length = 0.3;
    s.air_speed = 2.0;
    CHECK(s.convection_coefficient(348.15, 298.15) == Approx(10.486).epsilon(0.015));
    // The heat flow is (h_conv + h_rad) A dT with the radiation of a grey body (5.670374e-8, CODATA):
    //   h_rad = 0.9 x 5.670374e-8 x (348.15^2 + 298.15^2)(348.15 + 298.15) = 6.92976; 0.5 m^2, 50 K:
    //   Q = (10.486 + 6.930) x 0.5 x 50 = 435.4 W.
    s.area = 0.5;
    s.emissivity = 0.9;
    thermal::HeatRejection h{s};
    CHECK(h.heat_flow(348.15, 298.15, 0.0) == Approx(435.4).epsilon(0.01));
}

TEST_CASE("independent: Cragoe's oil conductivity and specific heat in their original US units", "[independent][lubricant]") {
    // Cragoe (1929, NBS Misc. Publ. 97), petroleum oils, d = specific gravity (60/60 degF), t in degF:
    //   k = (0.813/d)(1 - 0.0003 (t - 32))  BTU in/(h ft^2 degF);  1 BTU in/(h ft^2 degF) = 0.1442279 W/(m K)
    //   c = (0.388 + 0.00045 t)/sqrt(d)      BTU/(lb degF);         1 BTU/(lb degF) = 4186.8 J/(kg K)
    // Mineral oil of 870 kg/m^3 at 15 degC: d = 870/999.1 = 0.870784; 80 degC = 176 degF:
    //   k = 0.813/0.870784 x (1 - 0.0003 x 144) = 0.933647 x 0.9568 = 0.893308 -> 0.128840 W/(m K)
    //   c = (0.388 + 0.00045 x 176)/sqrt(0.870784) = 0.4672/0.933158 = 0.500666 -> 2096.19 J/(kg K)
    // Kills L2 (0.1172 -> 0.1127: k -3.8 %).
    lubricant::Oil oil;
    oil.base = lubricant::BaseOil::mineral;
    oil.rho15 = 870;
    const double T[3] = {40, 70, 100}, nu[3] = {68, 20, 8.6};
    oil.viscosity = lubricant::VogelLaw::fit(T, nu);
    const auto s = oil.state(353.15);
    CHECK(s.k == Approx(0.128840).epsilon(0.005));
    CHECK(s.cp == Approx(2096.19).epsilon(0.005));
}
