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

TEST_CASE("kinds beyond the dimension: angles, torques, speeds, temperatures", "[units][units37]") {
    constexpr double pi = std::numbers::pi;
    const auto value = [](const std::string& s, const Dimension& d, Kind k = Kind::plain) {
        return checked_value(parse_quantity(s), d, s, k);
    };
    // An angle is written with its unit: 60 deg = pi/3; '60' alone is refused (not 60 rad).
    CHECK(value("60 deg", dim::angle, Kind::angle) == Approx(pi / 3));
    CHECK(value("0.5 rev", dim::angle, Kind::angle) == Approx(pi));
    CHECK_THROWS_WITH(value("60", dim::angle, Kind::angle), Catch::Contains("no angle unit"));
    CHECK_THROWS_WITH(value("2 deg*rad", dim::angle, Kind::angle), Catch::Contains("not an angle"));
    // An angle unit where a plain ratio is meant.
    CHECK_THROWS_WITH(value("5 deg", dim::none), Catch::Contains("angle unit"));
    CHECK(value("5 %", dim::none) == Approx(0.05));
    // Energy and power units are never a torque; N*m, Nm and kNm are.
    CHECK(value("0.2 kNm", dim::torque) == Approx(200));
    CHECK(value("250 N*m", dim::torque) == Approx(250));
    for (const char* s : {"200 Wh", "200 J", "1 kW*s"}) CHECK_THROWS_WITH(value(s, dim::torque), Catch::Contains("not a torque"));
    // rpm/rev: the angles cancel; rad^2/s has two. 1000 rev/min = 104.72 rad/s is fine.
    CHECK(value("1000 rev/min", dim::angular_speed) == Approx(1000 * pi / 30));
    CHECK_THROWS_WITH(value("1000 rpm/rev", dim::angular_speed), Catch::Contains("cancel"));
    CHECK_THROWS_WITH(value("1 rad^2/s", dim::angular_speed), Catch::Contains("not a rotational speed"));
    // A missing unit on a dimensioned value.
    CHECK_THROWS_WITH(value("3.5", dim::length), Catch::Contains("has no unit"));
    // degC inside an expression is a kelvin-sized difference: 3 kJ/degC = 3000 J/K; degF 5/9 K.
    CHECK(value("3 kJ/degC", dim::heat_capacity) == Approx(3000));
    CHECK(value("9 W/degF", make_dim(2, 1, -3, -1)) == Approx(16.2));
    // Temperatures: '70C' is 70 degC (documented, as the recordings' oil_temp_C); absolute zero
    // and below are named as such.
    CHECK(absolute_temperature(parse_quantity("70C"), "70C") == Approx(343.15));
    CHECK_THROWS_WITH(absolute_temperature(parse_quantity("-273.15degC"), "-273.15degC"), Catch::Contains("absolute zero"));
    CHECK_THROWS_WITH(absolute_temperature(parse_quantity("-300degC"), "-300degC"), Catch::Contains("below absolute zero"));
    CHECK_THROWS_WITH(absolute_temperature(parse_quantity("70"), "70"), Catch::Contains("not a temperature"));
}

TEST_CASE("the kind check does not depend on spelling: torques, Hz, repeated angles, percent", "[units][units37][rtrec]") {
    constexpr double pi = std::numbers::pi;
    const auto value = [](const std::string& s, const Dimension& d, Kind k = Kind::plain) {
        return checked_value(parse_quantity(s), d, s, k);
    };
    // A torque names a force times a length: 0.1 kN*m = 100 N m, 2000 N*mm = 2 N m. Pa*m^3 (a
    // pressure times a volume, an energy) and kg*m^2/s^2 share its dimension but name no force.
    CHECK(value("0.1 kN*m", dim::torque) == Approx(100));
    CHECK(value("2000 N*mm", dim::torque) == Approx(2));
    for (const char* s : {"100 Pa*m^3", "100 kg*m^2/s^2", "100 MPa*cm^3"})
        CHECK_THROWS_WITH(value(s, dim::torque), Catch::Contains("does not name a force"));
    // Hz counts revolutions as rpm does: no length or speed written with it ("20 m*rpm" is refused
    // already); as a rotational speed 10 Hz = 10 rev/s = 62.83 rad/s.
    CHECK_THROWS_WITH(value("20 Hz*mm*s", dim::length), Catch::Contains("Hz"));
    CHECK_THROWS_WITH(value("20 Hz*m", dim::velocity), Catch::Contains("Hz"));
    CHECK_THROWS_WITH(value("20 m*rpm", dim::velocity), Catch::Contains("angle unit"));
    CHECK(value("10 Hz", dim::angular_speed) == Approx(20 * pi));
    CHECK(value("72 km/h", dim::velocity) == Approx(20));  // h is a time, not a revolution
    // Angles that repeat, or that Hz repeats, are refused like rpm/rev and rad^2/s.
    for (const char* s : {"800 rpm^2/rpm", "800 rev*rpm/rev", "10 Hz*rev", "10 Hz*rpm/rpm", "10 Hz^2/Hz"})
        CHECK_THROWS_WITH(value(s, dim::angular_speed), Catch::Contains("not a rotational speed"));
    CHECK_THROWS_WITH(value("20 deg^2/deg", dim::angle, Kind::angle), Catch::Contains("not an angle"));
    CHECK(value("800 rpm", dim::angular_speed) == Approx(800 * pi / 30));
    // '%' only alone, a plain ratio: "20 mm*%" would be 0.2 mm.
    CHECK(value("5 %", dim::none) == Approx(0.05));
    CHECK(value("5 percent", dim::none) == Approx(0.05));
    for (const char* s : {"20 mm*%", "100 N*m*%", "3 %/K", "2 percent*m"})
        CHECK_THROWS_WITH(parse_quantity(s), Catch::Contains("'%' stands alone"));
}
