// Churning against a hand calculation of Changenet & Velex (2007) with an oil volume that
// is not D^3 (the hand check of test_components.cpp has V0 = D^3, where every power of
// V0/D^3 is 1 and its exponents go untested). Kills mutation C2 of scripts/mutation-check.sh.
#include <catch2/catch.hpp>
#include <numbers>

#include "gearloss/churning/changenet_velex.hpp"

using namespace gearloss;
using Approx = Catch::Detail::Approx;

TEST_CASE("independent: Changenet-Velex churning with V0 = 2 D^3, both regimes, by hand", "[independent][churning]") {
    // Rp 50 mm (D 0.1 m), b 20 mm, z 20, tooth height 6.75 mm, alpha 20 deg, immersion h 20 mm,
    // V0 2 L, Omega 100 rad/s, rho 850 kg/m^3, g 9.80665 m/s^2:
    //   S_m = 5.787263e-3 m^2 (test_components.cpp); h/D = 0.2; V0/D^3 = 2e-3/1e-3 = 2
    //   Fr = Omega^2 Rp / g = 1e4 x 0.05 / 9.80665 = 50.98581
    //   1/2 rho Omega^2 S_m Rp^3 = 0.5 x 850 x 1e4 x 5.787263e-3 x 1.25e-4 = 3.074483 N m
    // nu 50 cSt: Re = Omega Rp^2 / nu = 5000, Re_c = Omega Rp b / nu = 2000 < 6000:
    //   C_m = 1.366 (h/D)^0.45 (V0/D^3)^0.1 Fr^-0.6 Re^-0.21
    //       = 1.366 x 0.4846894 x 1.0717735 x 0.09452146 x 0.1671923 = 1.121409e-2
    //   C_ch = 3.074483 x 1.121409e-2 = 3.447752e-2 N m
    // nu 0.5 cSt: Re_c = 2e5 > 9000:
    //   C_m = 3.644 (h/D)^0.1 (V0/D^3)^-0.35 Fr^-0.88 (b/D)^0.85
    //       = 3.644 x 0.8513399 x 0.7845841 x 0.03143725 x 0.2546100 = 1.948233e-2
    //   C_ch = 3.074483 x 1.948233e-2 = 5.989811e-2 N m
    const churning::DippingGear g{0.05, 0.02, 20, 6.75e-3, 20 * std::numbers::pi / 180, 0.02};
    churning::Regime r;
    CHECK(churning::churning_torque(g, 100, 850, 50e-6, 2e-3, &r) == Approx(3.447752e-2).epsilon(1e-5));
    CHECK(r == churning::Regime::low_reynolds);
    CHECK(churning::published_torque(g, 100, 850, 0.5e-6, 2e-3, &r) == Approx(5.989811e-2).epsilon(1e-5));
    CHECK(r == churning::Regime::high_reynolds);
}
