#include <catch2/catch.hpp>
#include <numbers>

#include "gearloss/units/units.hpp"

using namespace gearloss::units;
using Approx = Catch::Detail::Approx;

TEST_CASE("quantities are converted to SI with their dimension", "[units]") {
    CHECK(parse_quantity("3.5 mm").value == Approx(3.5e-3));
    CHECK(parse_quantity("3.5 mm").dim == dim::length);
    // 800 rev/min = 800 * 2 pi / 60 rad/s
    CHECK(parse_quantity("800 rpm").value == Approx(800 * 2 * std::numbers::pi / 60));
    CHECK(parse_quantity("250 N*m").dim == dim::torque);
    CHECK(parse_quantity("250 Nm").dim == dim::torque);
    CHECK(parse_quantity("40 degC").value == Approx(313.15));
    CHECK(parse_quantity("40 degC").absolute_temperature);
    CHECK(parse_quantity("112.35 cSt").value == Approx(112.35e-6));
    CHECK(parse_quantity("2 L").value == Approx(2e-3));
    CHECK(parse_quantity("885 kg/m^3").dim == dim::density);
    CHECK(parse_quantity("1.387e-8 1/Pa").dim == dim::per_pascal);
    CHECK(parse_quantity("15 W/(m^2*K)").dim == dim::heat_transfer_coefficient);
    CHECK(parse_quantity("0.12 K/W").dim == dim::thermal_resistance);
    CHECK(parse_quantity("20 deg").value == Approx(20 * std::numbers::pi / 180));
    CHECK(parse_quantity("0.5 um").value == Approx(0.5e-6));
    CHECK(parse_quantity("32 degF").value == Approx(273.15));
    CHECK(parse_quantity("0.3").dim == dim::none);
}

TEST_CASE("bad quantities are rejected with a reason", "[units]") {
    CHECK_THROWS_WITH(parse_quantity("3.5 furlong"), Catch::Contains("unknown unit 'furlong'"));
    CHECK_THROWS_WITH(parse_quantity("mm"), Catch::Contains("does not start with a number"));
    CHECK_THROWS_WITH(parse_quantity("3 (mm"), Catch::Contains("missing ')'"));
    CHECK_THROWS(parse_quantity(""));
    CHECK_THROWS(parse_quantity("nan mm"));
}
