// START:STOP:STEP ranges (units/ranges.hpp), products of units written with a dot or a space,
// and the p-value text of the diagnosis. The expected values are counted by hand.
#include <catch2/catch.hpp>

#include "gearloss/diagnosis/p_value_text.hpp"
#include "gearloss/units/ranges.hpp"
#include "gearloss/units/units.hpp"

using namespace gearloss;
using Approx = Catch::Detail::Approx;

TEST_CASE("a range lists START to STOP inclusive in steps", "[units][ranges]") {
    // (3000 - 300) / 10 + 1 = 271 values.
    const auto v = units::expand_range("300:3000:10rpm", "");
    REQUIRE(v.size() == 271);
    CHECK(v.front() == "300 rpm");
    CHECK(v[1] == "310 rpm");
    CHECK(v.back() == "3000 rpm");
    // Ten steps of 0.1 are 0.9999999999999999 or 1.0000000000000002 in binary: STOP is kept,
    // and every value is the number as typed (0.3, not 0.30000000000000004).
    const auto f = units::expand_range("0:1:0.1", "mm");
    REQUIRE(f.size() == 11);
    CHECK(f[3] == "0.3 mm");
    CHECK(f.back() == "1.0 mm");
    CHECK(units::parse_quantity(f[3]).value == units::parse_quantity("0.3 mm").value);
    // STOP between two steps: the last value below it. 0.5, 0.75, ..., 2.0 and 0, 0.4, 0.8.
    CHECK(units::expand_range("0.5:2:0.25 mm", "").size() == 7);
    CHECK(units::expand_range("0:1:0.4", "m") == std::vector<std::string>{"0.0 m", "0.4 m", "0.8 m"});
    // The unit on every part; a range of temperatures counts degrees of its own scale.
    CHECK(units::expand_range("-20degC:40degC:20degC", "") ==
          std::vector<std::string>{"-20 degC", "0 degC", "20 degC", "40 degC"});
    CHECK(units::parse_quantity(units::expand_range("20:100:20degF", "").back()).value == Approx(310.9278).epsilon(1e-6));
    CHECK(units::expand_range("5:5:1Nm", "") == std::vector<std::string>{"5 Nm"});
    CHECK(units::expand_range("1e3:3e3:1e3", "rpm").size() == 3);
}

TEST_CASE("a range that is empty, endless or huge is an error that says so", "[units][ranges]") {
    using Catch::Contains;
    CHECK_THROWS_WITH(units::expand_range("3000:300:10rpm", ""), Contains("empty range"));
    CHECK_THROWS_WITH(units::expand_range("300:3000:0rpm", ""), Contains("STEP is zero"));
    CHECK_THROWS_WITH(units::expand_range("3000:300:-10rpm", ""), Contains("STEP is negative"));
    CHECK_THROWS_WITH(units::expand_range("1:1e9:1rpm", ""), Contains("at most 1000000"));
    CHECK_THROWS_WITH(units::expand_range("1:1e300:1e-300rpm", ""), Contains("at most 1000000"));
    CHECK_THROWS_WITH(units::expand_range("1:10:1rpm", "", 5), Contains("10 items") && Contains("at most 5"));
    CHECK_THROWS_WITH(units::expand_range("300rpm:3000:10rpm", ""), Contains("one unit"));
    CHECK_THROWS_WITH(units::expand_range("300:3000", "rpm"), Contains("not a range"));
    CHECK_THROWS_WITH(units::expand_range("1:inf:1", "rpm"), Contains("finite"));
    CHECK(units::kMaxListItems == 1000000);
}

TEST_CASE("only three numbers make a range (file paths are none)", "[units][ranges]") {
    CHECK(units::is_range("300:3000:10rpm"));
    CHECK(units::is_range(" -30 : -10 : 10 mm "));
    CHECK_FALSE(units::is_range("oils/a:b:c.yaml"));
    CHECK_FALSE(units::is_range("C:/oils/x.yaml"));
    CHECK_FALSE(units::is_range("1:2"));
    CHECK_FALSE(units::is_range("1:2:3:4"));
    CHECK(units::range_unit("300:3000:10 rpm") == "rpm");
    CHECK(units::range_unit("300:3000:10") == "");
}

TEST_CASE("a product of units may be written with a dot or a space", "[units]") {
    for (const char* t : {"150 N·m", "150 N⋅m", "150 N m", "150 N  m", "150 N.m", "150N·m", "0.15 kN m"}) {
        INFO(t);
        const auto q = units::parse_quantity(t);
        CHECK(q.dim == units::dim::torque);
        CHECK(q.value == Approx(150));
        CHECK(units::checked_value(q, units::dim::torque, t) == Approx(150));
    }
    // 2 kg m^2 = 2 kg*m^2 (a moment of inertia), 3 W/(m^2 K) a heat transfer coefficient.
    CHECK(units::parse_quantity("2 kg m^2").dim == units::make_dim(2, 1, 0, 0));
    CHECK(units::parse_quantity("3 W/(m^2 K)").dim == units::dim::heat_transfer_coefficient);
    CHECK_THROWS_AS(units::parse_quantity("150 N·"), units::UnitError);
    CHECK_THROWS_AS(units::parse_quantity("150 ·m"), units::UnitError);
    CHECK_THROWS_AS(units::parse_quantity("150 N m q"), units::UnitError);
}

TEST_CASE("p-values below 1e-16 print as a bound", "[diagnosis]") {
    CHECK(diagnosis::p_value_text(4.9e-324) == "p < 1e-16");
    CHECK(diagnosis::p_value_text(0.0) == "p < 1e-16");
    CHECK(diagnosis::p_value_text(3e-17) == "p < 1e-16");
    CHECK(diagnosis::p_value_text(1e-16) == "p = 1e-16");
    CHECK(diagnosis::p_value_text(0.034) == "p = 0.034");
    CHECK(diagnosis::p_value_text(2.1e-5) == "p = 2.1e-05");
    CHECK(diagnosis::p_value_text(1.0) == "p = 1");
}
