// The splash form of Mauz (1987) as quoted for ISO/TR 14179-2 (churning form mauz_1987, issue 36):
// against hand calculations in the quoted form's own units (mm, m/s, N m), on a gear pair and
// on the 23/67 reducer; its range (pitch-line speed) as a finding; and what check says of the
// range of the selected form, the default's included.
#include <catch2/catch.hpp>
#include <cmath>
#include <numbers>
#include <string>

#include "gearloss/churning/fitted_range.hpp"
#include "gearloss/churning/mauz_1987.hpp"
#include "gearloss/results/reports.hpp"
#include "gearloss/solver/operating_point.hpp"
#include "gearloss/solver/plausibility.hpp"
#include "loss_parts.hpp"
#include "test_support.hpp"

using namespace gearloss;
using Approx = Catch::Detail::Approx;

namespace {

constexpr double degC = 273.15;
constexpr double rpm = std::numbers::pi / 30.0;

double churning_at(const solver::Model& m, double omega_in, double T) {
    const auto p = solver::prepare_point(m, omega_in, 100.0);
    return test::part(solver::evaluate_losses(m, p, m.oil_state(T), false), "churning");
}

}  // namespace

TEST_CASE("churning mauz_1987: the quoted form by hand in its own units", "[churning][forms][mauz]") {
    // T_VZ0 = C_Sp C_1 exp(C_2 v_t/v_t0), C_1 = 0.063 (e_1+e_2)/e_0 + 0.0128 (b/b_0)^3,
    // C_2 = (e_1+e_2)/(80 e_0) + 0.2, e_0 = b_0 = 10 mm, v_t0 = 10 m/s. e_1 = 20 mm, e_2 = 10 mm,
    // b = 20 mm, v_t = 15 m/s: C_1 = 0.063 x 3 + 0.0128 x 8 = 0.2914 N m, C_2 = 30/800 + 0.2 = 0.2375,
    // exp(0.2375 x 1.5) = 1.4279645, T_VZ0 = 0.41610885 N m at C_Sp = 1.
    const churning::SplashPair pair{0.020, 0.010, 0.020, 15.0};
    CHECK(churning::mauz_splash_torque(pair, 1.0) == Approx(0.41610885).epsilon(1e-7));
    // C_Sp = (4 e_max/(3 h_c))^1.5 (2 h_c/l_h) with e_max = 20 mm, h_c = 40 mm, l_h = 100 mm:
    // (80/120)^1.5 x 0.8 = 0.54433105 x 0.8 = 0.43546484.
    const double Csp = churning::mauz_splash_factor(0.020, {0.040, 0.100});
    CHECK(Csp == Approx(0.43546484).epsilon(1e-7));
    CHECK(churning::mauz_splash_torque(pair, Csp) == Approx(0.18120078).epsilon(1e-7));
    // h_c or l_h not given: C_Sp = 1; a pair that does not dip: no torque; the sign of v_t does not matter.
    CHECK(churning::mauz_splash_factor(0.020, {}) == 1.0);
    CHECK(churning::mauz_splash_factor(0.020, {0.040, 0.0}) == 1.0);
    CHECK(churning::mauz_splash_torque({0, 0, 0.020, 15.0}, 1.0) == 0.0);
    CHECK(churning::mauz_splash_torque({0.020, 0.010, 0.020, -15.0}, 1.0) == churning::mauz_splash_torque(pair, 1.0));
}

TEST_CASE("churning mauz_1987: the reducer's wheel by hand, the same at every oil temperature", "[churning][forms][mauz]") {
    // 23/67 reducer (tests/test_support.hpp), only the wheel dips, e_1 = 0 (pinion), e_2 = 9 mm,
    // b = 30 mm. At 2000 rpm input the wheel turns at 686.56716 min^-1 = 71.897145 rad/s; its
    // reference diameter 67 x 3 / cos 15 deg = 208.09051 mm gives v_t = 7.4805569 m/s.
    // C_1 = 0.063 x 0.9 + 0.0128 x 27 = 0.4023 N m, C_2 = 9/800 + 0.2 = 0.21125,
    // exp(0.21125 x 0.74805569) = 1.1711975, T_VZ0 = 0.47117277 N m, all on the wheel (the only
    // gear that dips): P = 0.47117277 x 71.897145 = 33.875977 W.
    const test_support::TempConfig file(test_support::reducer_23_67("mechanisms:\n  churning: {form: mauz_1987}\n"));
    const auto c = io::load_case(file.path);
    REQUIRE(c.model.mechanisms.at("churning").form(c.model, "form") == "mauz_1987");
    CHECK(churning_at(c.model, 2000 * rpm, degC + 80) == Approx(33.875977).epsilon(1e-6));
    // No oil property in the quoted form: the same power from -20 to 140 degC.
    for (double T : {-20.0, 40.0, 140.0}) CHECK(churning_at(c.model, 2000 * rpm, degC + T) == Approx(33.875977).epsilon(1e-6));
    // Its sump settings scale it by C_Sp: e_max = 9 mm, h_c = 24 mm, l_h = 24 mm give
    // (36/72)^1.5 x (48/24) = 0.35355339 x 2 = 0.70710678.
    const test_support::TempConfig sump(test_support::reducer_23_67(
        "mechanisms:\n  churning: {form: mauz_1987, splash_height: 24 mm, splash_length: 24 mm}\n"));
    const auto cs = io::load_case(sump.path);
    CHECK(churning_at(cs.model, 2000 * rpm, degC + 80) == Approx(0.70710678 * 33.875977).epsilon(1e-6));
    // The calibration factor scales it as every other form.
    const test_support::TempConfig scaled(test_support::reducer_23_67(
        "mechanisms:\n  churning: {form: mauz_1987}\ncalibration:\n  churning: {factor: 1.5}\n"));
    CHECK(churning_at(io::load_case(scaled.path).model, 2000 * rpm, degC + 80) == Approx(1.5 * 33.875977).epsilon(1e-6));
    // The point report names the form in the wheel's regime column.
    const auto r = solver::solve_point(c.model, 2000 * rpm, 50, true);
    CHECK_THAT(io::point_report(c, r), Catch::Contains("mauz_1987"));
    // The settings it reads and the case leaves at their nominal value are listed as assumed.
    std::string assumed;
    for (const auto& a : c.assumed) assumed += a.key + "\n";
    CHECK_THAT(assumed, Catch::Contains("splash_height") && Catch::Contains("splash_length"));
}

TEST_CASE("churning mauz_1987: the pair's torque is shared by immersion when both gears dip", "[churning][forms][mauz]") {
    // FZG C40 (both gears dip, the same pitch-line speed): the two shares add up to T_VZ0 of the
    // pair, T_VZ0 = P_1/Omega_1 + P_2/Omega_2 (each share at its own speed), whatever the split.
    auto c = test_support::load_shipped("configs/fzg-c40-paor.yaml");
    c.model.mechanisms.at("churning").set_form(c.model, "form", "mauz_1987");
    const auto& L = c.model.layout;
    const auto& gb = c.model.gearbox;
    REQUIRE(gb.meshes.size() == 1);
    const int g0 = gb.meshes[0].gear[0], g1 = gb.meshes[0].gear[1];
    REQUIRE(L.gear_immersion[g0] > 0);
    REQUIRE(L.gear_immersion[g1] > 0);
    const double w_in = 1500 * rpm;
    const double w0 = std::abs(L.body_speed_ratio[L.body_of_gear[g0]] * w_in), w1 = std::abs(L.body_speed_ratio[L.body_of_gear[g1]] * w_in);
    const auto p = solver::prepare_point(c.model, w_in, 100.0);
    const auto r = solver::evaluate_losses(c.model, p, c.model.oil_state(degC + 80), true);
    const double P = test::part(r, "churning");
    const double e0 = L.gear_immersion[g0], e1 = L.gear_immersion[g1];
    const double vt = w0 * 0.5 * gb.gears[g0].spec.d();
    const int deep = e1 > e0 ? g1 : g0;
    const double T = churning::mauz_splash_torque({e0, e1, gb.gears[deep].spec.b, vt}, 1.0);
    // Shares e_i/(e_0+e_1) of T at Omega_i.
    CHECK(P == Approx(T * (e0 * w0 + e1 * w1) / (e0 + e1)).epsilon(1e-9));
}

TEST_CASE("churning mauz_1987: outside its speed range is a finding, and check says what is known of each range",
          "[churning][forms][mauz]") {
    const auto r = churning::fitted_range("mauz_1987");
    CHECK(r.fitted);
    CHECK(churning::describe_limits(r) == "pitch-line speed 0-60 m/s");
    CHECK_THAT(r.provenance, Catch::Contains("not checked against the ISO/TR text"));
    CHECK(churning::outside_range(r, {{"pitch-line speed", 5, 75}}) == "pitch-line speed 5-75 m/s given, fitted 0-60 m/s");
    CHECK(churning::outside_range(r, {{"pitch-line speed", 5, 59}}).empty());
    CHECK_THAT(churning::coefficient_provenance("mauz_1987"), Catch::Contains("not checked against the ISO/TR text"));
    // The default form: no limit is checked, and that is said.
    const auto cv = churning::fitted_range("changenet_velex_2007");
    CHECK(cv.limits.empty());
    CHECK(churning::describe_limits(cv) == "none checked");
    CHECK_THAT(cv.provenance, Catch::Contains("not stated in a verified source"));

    // FZG C40 at 20 000 rpm input: pitch-line speeds far above 60 m/s, one note per dipping gear.
    auto c = test_support::load_shipped("configs/fzg-c40-paor.yaml");
    c.model.mechanisms.at("churning").set_form(c.model, "form", "mauz_1987");
    const auto notes = solver::check_churning_speed_range(c.model, {1000 * rpm, 20000 * rpm});
    REQUIRE(notes.size() == 2);
    for (const auto& f : notes) {
        CHECK(f.severity == solver::PlausibilityFinding::Severity::note);
        CHECK_THAT(f.message, Catch::Contains("churning form mauz_1987 outside its fitted range for gear") &&
                                  Catch::Contains("fitted 0-60 m/s") && Catch::Contains("secondary sources"));
    }
    CHECK(solver::check_churning_speed_range(c.model, {1000 * rpm, 3000 * rpm}).empty());
    // The default form has no speed limit: no note at any speed.
    const auto base = test_support::load_shipped("configs/fzg-c40-paor.yaml");
    CHECK(solver::check_churning_speed_range(base.model, {1000 * rpm, 20000 * rpm}).empty());
    // check (text and JSON) states the range of the selected form and where it comes from.
    CHECK_THAT(io::check_report(base), Catch::Contains("churning form changenet_velex_2007: fitted range: none checked "
                                                       "(not stated in a verified source"));
    CHECK_THAT(io::check_json(base), Catch::Contains("\"churning_range\":{\"form\":\"changenet_velex_2007\"") &&
                                         Catch::Contains("not stated in a verified source"));
    CHECK_THAT(io::check_report(c), Catch::Contains("churning form mauz_1987: fitted range: pitch-line speed 0-60 m/s") &&
                                        Catch::Contains("coefficients as quoted in secondary sources"));
}
