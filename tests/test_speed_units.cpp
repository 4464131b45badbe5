// Rotational speed units (black-box, from the specification; independent values by hand):
// Hz = rev/s, 1/min = min^-1 = rev/min = rpm, rad/s as written, deg/s, kHz = 1000 Hz;
// a bare 1/s (or s^-1) is ambiguous and rejected with a hint at rad/s or Hz.
//
// Hand values: 10 Hz = 10 rev/s = 10 * 2 pi rad/s = 62.831853 rad/s = 600 rev/min.
//              600 rpm = 600 * 2 pi / 60 rad/s = 62.831853 rad/s.
//              3600 deg/s = 3600 * pi/180 rad/s = 62.831853 rad/s (= 10 rev/s).
//              0.01 kHz = 10 Hz.
#include <catch2/catch.hpp>

#include <cmath>
#include <string>

#include "gearloss/core/errors.hpp"
#include "gearloss/case/config.hpp"
#include "test_support.hpp"
#include "gearloss/units/units.hpp"

using namespace gearloss;
using test_support::TempConfig;

namespace {
constexpr double kPi = 3.14159265358979323846;
const double w600 = 600.0 * 2.0 * kPi / 60.0;  // 62.83185307 rad/s

double rot(const std::string& text) { return units::as_rotational_speed(units::parse_quantity(text), text); }

std::string transfer_box() { return test_support::read_file(test_support::source_path("configs/transfer-box.yaml")); }
}  // namespace

TEST_CASE("rotational speed: every revolution spelling gives 600 rpm", "[units][speed]") {
    for (const char* t : {"10 Hz", "10Hz", "600 rpm", "600rpm", "600 1/min", "600 min^-1", "600 rev/min",
                          "10 rev/s", "0.01 kHz", "3600 deg/s"}) {
        INFO(t);
        CHECK(rot(t) == Approx(w600).epsilon(1e-12));
    }
    // rad/s is taken as written.
    CHECK(rot("62.8319 rad/s") == Approx(62.8319).epsilon(1e-12));
    CHECK(rot("1 rad/s") == Approx(1.0).epsilon(1e-12));
    // 1 Hz is one revolution per second: 2 pi rad/s, not 1 rad/s.
    CHECK(rot("1 Hz") == Approx(2.0 * kPi).epsilon(1e-12));
    // 1 1/min = 1/60 rev/s = 2 pi / 60 rad/s = 0.10471976 rad/s.
    CHECK(rot("1 1/min") == Approx(0.10471975511965977).epsilon(1e-12));
    // 1 kHz = 1000 rev/s = 60 000 rpm = 6283.185 rad/s.
    CHECK(rot("1 kHz") == Approx(6283.185307179586).epsilon(1e-12));
}

TEST_CASE("rotational speed: parse_quantity flags", "[units][speed]") {
    const auto one_over_s = units::make_dim(0, 0, -1, 0);
    // Hz: a frequency, SI value 10 1/s, no explicit angle, but a rotation (frequency unit).
    auto hz = units::parse_quantity("10 Hz");
    CHECK(hz.dim == one_over_s);
    CHECK(hz.value == Approx(10.0));
    CHECK(hz.rotation);
    CHECK_FALSE(hz.explicit_angle);
    // 600 1/min: 10 per second in SI, a rotation (a time other than the second).
    auto pm = units::parse_quantity("600 1/min");
    CHECK(pm.dim == one_over_s);
    CHECK(pm.value == Approx(10.0));
    CHECK(pm.rotation);
    CHECK_FALSE(pm.explicit_angle);
    // rpm and rad/s name an angle.
    auto rpm = units::parse_quantity("600 rpm");
    CHECK(rpm.dim == one_over_s);
    CHECK(rpm.explicit_angle);
    CHECK(rpm.value == Approx(w600));
    auto rs = units::parse_quantity("5 rad/s");
    CHECK(rs.explicit_angle);
    CHECK(rs.value == Approx(5.0));
    // A bare 1/s names neither an angle nor a rotation.
    auto s = units::parse_quantity("10 1/s");
    CHECK(s.dim == one_over_s);
    CHECK_FALSE(s.explicit_angle);
    CHECK_FALSE(s.rotation);
}

TEST_CASE("rotational speed: a bare 1/s is ambiguous", "[units][speed]") {
    for (const char* t : {"10 1/s", "10 s^-1", "600 s^-1"}) {
        INFO(t);
        try {
            (void)rot(t);
            FAIL("accepted");
        } catch (const units::UnitError& e) {
            INFO(e.message);
            CHECK_THAT(e.message, Catch::Contains("rad/s"));
            CHECK_THAT(e.message, Catch::Contains("Hz"));
        }
    }
}

TEST_CASE("case file: operating speeds in Hz, 1/min, min^-1, rad/s", "[units][speed][config]") {
    std::string text = test_support::replace_once(
        transfer_box(), "speeds: [600 rpm, 700 rpm, 800 rpm]",
        "speeds: [10 Hz, 600 1/min, 600 min^-1, 62.83185307 rad/s, 600 rev/min, 3600 deg/s]");
    TempConfig cfg(text);
    auto c = io::load_case(cfg.path);
    REQUIRE(c.grid.is_grid);
    REQUIRE(c.grid.speeds.size() == 6);
    for (double w : c.grid.speeds) CHECK(w == Approx(w600).epsilon(1e-9));

    // {from, to, count} in Hz: 5, 10, 15 Hz = 300, 600, 900 rpm = 31.416, 62.832, 94.248 rad/s.
    TempConfig cfg2(test_support::replace_once(transfer_box(), "speeds: [600 rpm, 700 rpm, 800 rpm]",
                                               "speeds: {from: 5 Hz, to: 15 Hz, count: 3}"));
    auto c2 = io::load_case(cfg2.path);
    REQUIRE(c2.grid.speeds.size() == 3);
    CHECK(c2.grid.speeds[0] == Approx(0.5 * w600));
    CHECK(c2.grid.speeds[1] == Approx(w600));
    CHECK(c2.grid.speeds[2] == Approx(1.5 * w600));
}

TEST_CASE("case file: operating points in Hz and 1/min", "[units][speed][config]") {
    std::string text = test_support::replace_once(
        transfer_box(), "  speeds: [600 rpm, 700 rpm, 800 rpm]\n  torques: [150 N*m, 200 N*m, 250 N*m]\n",
        "  points: [[10 Hz, 150 N*m], [700 1/min, 200 N*m], [800 min^-1, 250 N*m]]\n");
    TempConfig cfg(text);
    auto c = io::load_case(cfg.path);
    REQUIRE_FALSE(c.grid.is_grid);
    REQUIRE(c.grid.points.size() == 3);
    CHECK(c.grid.points[0].first == Approx(w600));                // 10 Hz = 600 rpm
    CHECK(c.grid.points[1].first == Approx(700.0 * 2 * kPi / 60));  // 73.304 rad/s
    CHECK(c.grid.points[2].first == Approx(800.0 * 2 * kPi / 60));  // 83.776 rad/s
    CHECK(c.grid.points[0].second == Approx(150.0));
}

TEST_CASE("case file: a bare 1/s speed is an error naming file, line and key", "[units][speed][config]") {
    struct Bad {
        std::string from, to, line_text, key;
    };
    const Bad cases[] = {
        {"speeds: [600 rpm, 700 rpm, 800 rpm]", "speeds: [600 rpm, 10 1/s, 800 rpm]", "speeds: [600 rpm, 10 1/s",
         "operating.speeds"},
        {"speeds: [600 rpm, 700 rpm, 800 rpm]", "speeds: [10 s^-1]", "speeds: [10 s^-1]", "operating.speeds"},
        {"  speeds: [600 rpm, 700 rpm, 800 rpm]\n  torques: [150 N*m, 200 N*m, 250 N*m]\n",
         "  points: [[600 rpm, 150 N*m], [10 1/s, 200 N*m]]\n", "points: [[600 rpm", "operating.points"},
    };
    for (const auto& b : cases) {
        std::string text = test_support::replace_once(transfer_box(), b.from, b.to);
        TempConfig cfg(text);
        INFO(b.to);
        try {
            (void)io::load_case(cfg.path);
            FAIL("accepted a bare 1/s");
        } catch (const InputError& e) {
            INFO(e.what());
            CHECK(e.file == cfg.path);
            CHECK(e.line == test_support::line_of(text, b.line_text));
            CHECK_THAT(e.key, Catch::Contains(b.key));
            CHECK_THAT(e.message, Catch::Contains("rad/s"));
            CHECK_THAT(e.message, Catch::Contains("Hz"));
        }
    }
}
