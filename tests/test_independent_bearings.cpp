// Rolling-bearing drag against a hand calculation of the published SKF (2013) oil-bath
// drag formula for a roller bearing (the ball-bearing form is checked against the
// reference values in test_components.cpp). Kills mutation B2 of scripts/mutation-check.sh.
#include <catch2/catch.hpp>
#include <numbers>

#include "gearloss/bearings/skf_model.hpp"

using namespace gearloss;
using Approx = Catch::Detail::Approx;

TEST_CASE("independent: SKF oil-bath drag of a cylindrical roller bearing, by hand", "[independent][bearings]") {
    // NU 206 size: d 30, D 62, B 16 mm, d_m 46 mm; SKF series-2 constants K_Z 5.1, K_L 0.65;
    // oil level H = 23 mm (half of d_m), V_M 5e-4 (read from the SKF diagram), n 3000 r/min, nu 20 mm^2/s.
    // SKF (2013): M_drag = 4 V_M K_roll C_w B d_m^4 n^2 + 1.093e-7 n^2 d_m^3 (n d_m^2 f_t / nu)^-1.379 R_s
    //   K_roll = K_L K_Z (d + D)/(D - d) 1e-12 = 0.65 x 5.1 x 92/32 x 1e-12 = 9.530625e-12
    //   l_D = 5 K_L B/d_m = 5 x 0.65 x 16/46 = 1.130435
    //   C_w = 2.789e-10 l_D^3 - 2.786e-4 l_D^2 + 0.0195 l_D + 0.6439 = 0.665587
    //   first = 4 x 5e-4 x 9.530625e-12 x 0.665587 x 16 x 46^4 x 3000^2
    //         = 4 x 5e-4 x 9.530625e-12 x 0.665587 x 16 x 4 477 456 x 9e6 = 8.17994 N mm
    //   t = 2 acos((0.6 d_m - H)/(0.6 d_m)) = 2 acos(4.6/27.6) = 2.806696; f_t = sin(t/2) = 0.986013
    //   f_A = 0.05 K_Z (D + d)/(D - d) = 0.05 x 5.1 x 92/32 = 0.733125
    //   R_s = 0.36 d_m^2 (t - sin t) f_A = 0.36 x 2116 x (2.806696 - 0.328671) x 0.733125 = 1383.891
    //   second = 1.093e-7 x 9e6 x 97 336 x (3000 x 2116 x 0.986013 / 20)^-1.379 x 1383.891 = 3.49911 N mm
    //   M_drag = 11.67906 N mm.
    // The model takes SI: the hand values above are converted explicitly.
    constexpr double mm = 1e-3, rpm = std::numbers::pi / 30.0, cSt = 1e-6, Nmm = 1e-3;
    bearings::BearingSpec b;
    b.type = bearings::BearingType::cylindrical_roller;
    b.d = 30 * mm;
    b.D = 62 * mm;
    b.B = 16 * mm;
    b.k = *bearings::skf_constants(b.type, "2");
    REQUIRE(b.k.K_Z == 5.1);
    REQUIRE(b.k.K_L == 0.65);
    b.bath_H = 23.0 * mm;
    b.bath_VM = 0.0;
    CHECK(bearings::skf_drag_moment(b, 3000 * rpm, 20 * cSt) == Approx(3.49911 * Nmm).epsilon(1e-4));
    b.bath_VM = 5e-4;
    CHECK(bearings::skf_drag_moment(b, 3000 * rpm, 20 * cSt) == Approx((8.17994 + 3.49911) * Nmm).epsilon(1e-4));
    // The drag is in the full moment too, unchanged by load: M(Fr) - M_without_bath(Fr) = M_drag.
    // Both flooded (K_rs = 0, lubrication: oil_bath): a 23 mm bath is above the rolling-element
    // centres, where SKF's starvation factor phi_rs does not apply, so only the drag differs.
    b.K_rs = 0.0;
    auto dry = b;
    dry.bath_H.reset();
    CHECK(bearings::skf_moment(b, 2000, 0, 3000 * rpm, 20 * cSt).total() -
              bearings::skf_moment(dry, 2000, 0, 3000 * rpm, 20 * cSt).total() ==
          Approx(11.67906 * Nmm).epsilon(1e-4));
}
