// Recordings checked before any fit (issue 37, item 4), and a large campaign fitted on part of
// its points (item 2). Every expected number below is a hand calculation from the power
// balance P_in = P_out + P_loss with P = T omega (omega = n pi / 30).
#include <catch2/catch.hpp>
#include <cmath>
#include <fmt/format.h>
#include <functional>
#include <sstream>
#include <limits>
#include <numbers>
#include <string>

#include "gearloss/core/errors.hpp"
#include "gearloss/diagnosis/diagnose.hpp"
#include "gearloss/diagnosis/recordings.hpp"
#include "gearloss/diagnosis/synth.hpp"
#include "gearloss/case/config.hpp"
#include "gearloss/io/csv_read.hpp"
#include "test_support.hpp"

using namespace gearloss;
using Catch::Matchers::Contains;
using Approx = Catch::Detail::Approx;

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

namespace {
// `csv` with the cells of column `name` passed through `f` on every data row (row index from 1).
std::string with_column(const std::string& csv, const std::string& name,
                        const std::function<std::string(const std::string&, int)>& f) {
    std::istringstream in(csv);
    std::string line, out;
    std::getline(in, line);
    out = line + "\n";
    int col = -1, k = 0;
    for (size_t a = 0;; ++k) {
        const size_t b = line.find(',', a);
        if (line.substr(a, b == std::string::npos ? std::string::npos : b - a) == name) col = k;
        if (b == std::string::npos) break;
        a = b + 1;
    }
    REQUIRE(col >= 0);
    for (int row = 1; std::getline(in, line); ++row) {
        size_t a = 0;
        for (int j = 0; j < col; ++j) a = line.find(',', a) + 1;
        const size_t b = std::min(line.find(',', a), line.size());
        out += line.substr(0, a) + f(line.substr(a, b - a), row) + line.substr(b) + "\n";
    }
    return out;
}

std::string transfer_log(const std::vector<double>& speeds_rpm, const std::vector<double>& torques) {
    diagnosis::SynthOptions so;
    so.raw_log = true;
    return diagnosis::synthesize(transfer().model, test_support::rpm_grid(speeds_rpm, torques), so);
}

std::string times(const std::string& cell, double k) { return fmt::format("{:.6g}", std::stod(cell) * k); }
}  // namespace

TEST_CASE("a raw log's tests are checked as steady points (output at rest, output power above input)", "[recordings][rtrec]") {
    const std::string log = transfer_log({800, 1200}, {100, 300});
    REQUIRE_NOTHROW(diagnosis::read_recordings_text(log, "log.csv"));
    // speed_out 0 in every row while the input turns: an error naming the first test.
    const auto e = input_error([&] {
        diagnosis::read_recordings_text(with_column(log, "speed_out_rpm", [](const std::string&, int) { return "0"; }), "log.csv");
    });
    CHECK_THAT(e.message, Contains("test 1 (lines 2-") && Contains("output speed 0"));
    // torque_out x 3: the output power is 3 x 0.98 = 2.9 times the input (an efficiency near 98 %).
    const auto e3 = input_error([&] {
        diagnosis::read_recordings_text(with_column(log, "torque_out_Nm", [](const std::string& c, int) { return times(c, 3); }),
                                        "log.csv");
    });
    CHECK_THAT(e3.message, Contains("test 1 (lines 2-") && Contains("exceeds the input power") &&
                               Contains("does not make power"));
    CHECK(e3.key == "torque_out_Nm");
}

TEST_CASE("a steady output power far above the input power is an error, a negative loss a finding", "[recordings][rtrec]") {
    // No loss column: 1000 rpm x 100 N m = 10 472 W in; 436.4 rpm = 45.700 rad/s out.
    const std::string header = "speed_in_rpm,torque_in_Nm,torque_out_Nm,speed_out_rpm\n";
    const auto good = diagnosis::read_recordings_text(header + "1000,100,220,436.4\n", "r.csv");
    CHECK(good.warnings.empty());
    // 440 N m out: 440 x 45.700 = 20 107.9 W, 9 636 W (92 % of the input) more than goes in: an error.
    const auto e = input_error([&] { diagnosis::read_recordings_text(header + "1000,100,220,436.4\n1000,100,440,436.4\n", "r.csv"); });
    CHECK(e.line == 3);
    CHECK(e.column == 3);
    CHECK_THAT(e.message, Contains("output power 20107.9 W") && Contains("input power 10472 W") && Contains("does not make power"));
    // 330 N m out (x 1.5): 330 x 45.700 = 15 080.9 W, 44 % over the input; a torque sensor's gain
    // could not do that either, but a finding at the cell is what a steady row gets below 50 %.
    const auto r = diagnosis::read_recordings_text(header + "1000,100,330,436.4\n", "r.csv");
    CHECK(any_contains(r.warnings, "r.csv:2:3 (torque_out_Nm): loss -4608.9"));
    // A recorded loss of -5 W (line 3, column 3): a finding at its cell, not only an outlier.
    const auto n = diagnosis::read_recordings_text(kHeader + kGood + "1000,100,-5,220,436.4,61,25\n", "r.csv");
    CHECK(any_contains(n.warnings, "r.csv:3:3 (P_loss_W): loss -5 W is negative"));
    // -6000 W of 10 472 W in (57 %): an error at the cell.
    const auto e2 = input_error([] { diagnosis::read_recordings_text(kHeader + kGood + "1000,100,-6000,220,436.4,60,25\n", "r.csv"); });
    CHECK(e2.line == 3);
    CHECK(e2.column == 3);
    CHECK_THAT(e2.message, Contains("negative"));
}

TEST_CASE("an output speed of the other sign than the others is a finding at its cell", "[recordings][rtrec]") {
    const auto r = diagnosis::read_recordings_text(
        kHeader + kGood + "1000,100,418,220,436.4,61,25\n1000,100,418,220,-436.4,62,25\n", "r.csv");
    REQUIRE(r.warnings.size() == 1);
    CHECK_THAT(r.warnings[0], Contains("r.csv:4:5 (speed_out_rpm)") && Contains("other way"));
    // In a log: row 7 negated (line 8).
    const std::string log = transfer_log({800, 1200}, {100, 300});
    const auto l = diagnosis::read_recordings_text(
        with_column(log, "speed_out_rpm", [](const std::string& c, int row) { return row == 7 ? times(c, -1) : c; }), "log.csv");
    CHECK(any_contains(l.warnings, "log.csv:8:"));
}

TEST_CASE("recordings headers go through the kind check: an energy is no torque", "[recordings][rtrec]") {
    for (const char* unit : {"J", "kJ", "Wh", "Pa*m^3"}) {
        INFO(unit);
        const std::string header = std::string("speed_in_rpm,torque_in_") + unit + ",P_loss_W\n";
        const auto e = input_error([&] { diagnosis::read_recordings_text(header + "1000,100,418\n", "r.csv"); });
        CHECK(e.line == 1);
        CHECK(e.column == 2);
        CHECK_THAT(e.message, Contains("torque"));
    }
    // In a raw log as well (torque_out_J).
    const std::string log = transfer_log({800}, {100});
    const std::string renamed = "torque_out_J" + log.substr(log.find("torque_out_Nm") + 13);
    const auto e = input_error([&] {
        diagnosis::read_recordings_text(log.substr(0, log.find("torque_out_Nm")) + renamed, "log.csv");
    });
    CHECK_THAT(e.message, Contains("not a torque"));
    // kNm and N*mm are torques: 0.1 kNm = 100 N m.
    const auto r = diagnosis::read_recordings_text("speed_in_rpm,torque_in_kNm,P_loss_W\n1000,0.1,418\n", "r.csv");
    CHECK(r.points.at(0).torque_in == Approx(100));
}

TEST_CASE("a log too short for a diagnosis says which tests it found", "[recordings][rtrec]") {
    const auto e = input_error([] {
        diagnosis::diagnose(transfer().model, diagnosis::read_recordings_text(transfer_log({800}, {100, 300}), "log.csv"));
    });
    CHECK_THAT(e.message, Contains("at least 4 recorded tests") && Contains("(2 usable of 2)") &&
                              Contains("test 1 (lines 2-") && Contains("test 2 (lines"));
}

TEST_CASE("a bidirectional override in a label is refused like a control character", "[recordings][rtrec]") {
    CHECK_FALSE(io::is_printable_utf8("gear\u202Ebox"));
    CHECK_FALSE(io::is_printable_utf8("a\u2066b"));
    CHECK(io::is_printable_utf8("Zahnrad \u00b5m \u2013 ok"));
    const auto e = input_error(
        [] { diagnosis::read_recordings_text("label,speed_in_rpm,torque_in_Nm,P_loss_W\nrun\u202E1,1000,100,418\n", "r.csv"); });
    CHECK(e.column == 1);
}
