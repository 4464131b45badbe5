// Recordings checked before any fit (issue 37, item 4), and a large campaign fitted on part of
// its points (item 2). Every expected number below is a hand calculation from the power
// balance P_in = P_out + P_loss with P = T omega (omega = n pi / 30).
#include <catch2/catch.hpp>
#include <cmath>
#include <limits>
#include <numbers>
#include <string>

#include "gearloss/core/errors.hpp"
#include "gearloss/diagnosis/diagnose.hpp"
#include "gearloss/diagnosis/recordings.hpp"
#include "gearloss/diagnosis/synth.hpp"
#include "gearloss/io/config.hpp"
#include "test_support.hpp"

using namespace gearloss;
using Catch::Matchers::Contains;

namespace {
constexpr double rpm = std::numbers::pi / 30;

io::Case transfer() { return io::load_case(test_support::source_path("configs/transfer-box.yaml")); }

InputError input_error(const std::function<void()>& f) {
    try {
        f();
    } catch (const InputError& e) {
        return e;
    }
    FAIL("no InputError");
    return InputError("");
}

bool any_contains(const std::vector<std::string>& v, const std::string& what) {
    for (const auto& s : v)
        if (s.find(what) != std::string::npos) return true;
    return false;
}

// 1000 rpm x 100 N m = 10 472 W in; the transfer box's low ratio omega_out / omega_in is
// 23/32 x 17/28 = 0.4364 (configs/transfer-box.yaml, wheels 2-1 and 5-3), so 436.4 rpm out and 220 N m out give
// 220 x 436.4 pi / 30 = 10 054 W out and a balance of 418 W.
const std::string kHeader = "speed_in_rpm,torque_in_Nm,P_loss_W,torque_out_Nm,speed_out_rpm,oil_temp_C,ambient_temp_C\n";
const std::string kGood = "1000,100,418,220,436.4,60,25\n";
}  // namespace

TEST_CASE("a recorded loss above the input power is an error at its cell", "[recordings]") {
    // Line 3 (header, a good row, then the bad one): 20 000 W lost of 10 472 W in.
    const auto e = input_error([] { diagnosis::read_recordings_text(kHeader + kGood + "1000,100,20000,220,436.4,60,25\n", "r.csv"); });
    CHECK(e.line == 3);
    CHECK(e.column == 3);
    CHECK_THAT(e.message, Contains("exceeds the input power 10472 W"));
    // Twice the input power at 600 rpm x 150 N m (9 425 W): 18 850 W.
    const auto e2 = input_error(
        [] { diagnosis::read_recordings_text("speed_in_rpm,torque_in_Nm,P_loss_W\n600,150,18850\n", "r.csv"); });
    CHECK(e2.line == 2);
    CHECK_THAT(e2.message, Contains("exceeds the input power"));
    // At standstill nothing goes in: any loss is more than that.
    const auto e3 = input_error([] { diagnosis::read_recordings_text("speed_in_rpm,torque_in_Nm,P_loss_W\n0,150,30\n", "r.csv"); });
    CHECK(e3.line == 2);
}

TEST_CASE("an output standing still while the input turns is an error at its cell", "[recordings]") {
    const auto e = input_error([] { diagnosis::read_recordings_text(kHeader + kGood + "1000,100,418,220,0,60,25\n", "r.csv"); });
    CHECK(e.line == 3);
    CHECK(e.column == 5);
    CHECK_THAT(e.message, Contains("output speed 0"));
}

TEST_CASE("a loss over half the input power is a finding at its row", "[recordings]") {
    // 600 rpm x 10 N m = 628.3 W in; 400 W lost is 64 %.
    const auto r = diagnosis::read_recordings_text("speed_in_rpm,torque_in_Nm,P_loss_W\n600,150,210\n600,10,400\n", "r.csv");
    REQUIRE(r.warnings.size() == 1);
    CHECK_THAT(r.warnings[0], Contains("r.csv:3:3 (P_loss_W)"));
    CHECK_THAT(r.warnings[0], Contains("64 % of the input power"));
}

TEST_CASE("a loss column contradicting the output torque and speed is a finding at its row", "[recordings]") {
    // Balance 418 W; 300 W recorded: 118 W apart, beyond max(1 % of 10 472 W, 10 % of 300 W) = 105 W.
    const auto r = diagnosis::read_recordings_text(kHeader + kGood + "1000,100,300,220,436.4,60,25\n", "r.csv");
    REQUIRE(r.warnings.size() == 1);
    CHECK_THAT(r.warnings[0], Contains("r.csv:3:3 (P_loss_W)"));
    CHECK_THAT(r.warnings[0], Contains("= 418 W"));
    // 330 W: 88 W apart, within the 105 W: no finding.
    CHECK(diagnosis::read_recordings_text(kHeader + "1000,100,330,220,436.4,60,25\n", "r.csv").warnings.empty());
}

TEST_CASE("oil recorded colder than the ambient is a finding at its row", "[recordings]") {
    const auto r = diagnosis::read_recordings_text(kHeader + kGood + "1000,100,418,220,436.4,20,25\n", "r.csv");
    REQUIRE(r.warnings.size() == 1);
    CHECK_THAT(r.warnings[0], Contains("r.csv:3:6 (oil_temp_C)"));
    CHECK_THAT(r.warnings[0], Contains("colder than the ambient"));
}

TEST_CASE("an output speed contradicting the case's gear ratio is a finding at its row", "[recordings]") {
    const auto c = transfer();
    // 500 rpm out of 1000 in is 0.5, the case's 0.4364 is 14.6 % away; 436.4 rpm matches.
    const auto r = diagnosis::read_recordings_text(kHeader + kGood + "1000,100,418,220,500,60,25\n", "r.csv");
    const auto f = diagnosis::ratio_findings(c.model, r);
    REQUIRE(f.size() == 1);
    CHECK_THAT(f[0], Contains("r.csv:3:5 (speed_out_rpm)"));
    CHECK_THAT(f[0], Contains("0.4364"));
}

TEST_CASE("synthetic recordings pass every check without a finding", "[recordings]") {
    const auto c = transfer();
    io::OperatingGrid g;
    for (double n : {400.0, 800.0, 1200.0}) g.speeds.push_back(n * rpm);
    g.torques = {20, 175, 325};
    for (bool log : {false, true}) {
        diagnosis::SynthOptions so;
        so.raw_log = log;
        so.effects = {{"windage", 25}};
        const auto r = diagnosis::read_recordings_text(diagnosis::synthesize(c.model, g, so), "synth.csv");
        CHECK(r.warnings.empty());
        CHECK(diagnosis::ratio_findings(c.model, r).empty());
    }
}

TEST_CASE("a finding without an uncertainty never prints nan", "[recordings]") {
    diagnosis::Diagnosis d;
    d.verdict = "missing_physics";
    diagnosis::Finding f;
    f.effect = "windage";
    f.parameter = {"windage.empirical_W_at_1000rpm", "W", 25, std::numeric_limits<double>::quiet_NaN(), "", ""};
    d.findings.push_back(f);
    d.candidates.push_back({"windage", 25, 30, ""});
    const std::string text = diagnosis::diagnosis_text(d);
    CHECK(text.find("nan") == std::string::npos);
    CHECK_THAT(text, Contains("uncertainty not determined"));
}

TEST_CASE("a campaign beyond max_fit_points is fitted on an even subset, reported on every point", "[diagnosis][recordings]") {
    const auto c = transfer();
    io::OperatingGrid g;
    for (int k = 0; k < 8; ++k) g.speeds.push_back((400 + 100 * k) * rpm);
    for (int k = 0; k < 8; ++k) g.torques.push_back(60 + 40 * k);
    diagnosis::SynthOptions so;
    so.effects = {{"windage", 30}};
    so.seed = 5;
    const auto rec = diagnosis::read_recordings_text(diagnosis::synthesize(c.model, g, so), "synth.csv");
    REQUIRE(rec.points.size() == 64);
    diagnosis::DiagnoseOptions opt;
    opt.bootstrap = 8;
    const auto whole = diagnosis::diagnose(c.model, rec, opt);
    opt.max_fit_points = 32;
    const auto part = diagnosis::diagnose(c.model, rec, opt);
    CHECK(whole.points == 64);
    CHECK(whole.fit_points == 64);
    CHECK(part.points == 64);
    CHECK(part.fit_points == 32);
    CHECK(part.residuals.size() == 64);  // every point, not the subset
    CHECK(any_contains(part.warnings, "use 32 of them"));
    CHECK_FALSE(any_contains(whole.warnings, "spread evenly"));
    // The concealed 30 W windage is found on half the points too, within the noise of 32 points.
    REQUIRE_FALSE(whole.findings.empty());
    REQUIRE_FALSE(part.findings.empty());
    CHECK(part.findings[0].effect == whole.findings[0].effect);
    CHECK(std::abs(part.findings[0].parameter.value - 30) < 4);
    // The baseline RMSE is over every point in both: the same number.
    CHECK(part.rmse_before == Catch::Detail::Approx(whole.rmse_before).epsilon(1e-12));
}
