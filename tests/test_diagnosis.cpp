#include <catch2/catch.hpp>
#include "loss_parts.hpp"
#include <cmath>
#include <filesystem>
#include <fstream>
#include <numbers>

#include "gearloss/core/errors.hpp"
#include "gearloss/diagnosis/diagnose.hpp"
#include "gearloss/diagnosis/recordings.hpp"
#include "gearloss/diagnosis/synth.hpp"
#include "gearloss/case/config.hpp"
#include "gearloss/solver/operating_point.hpp"
#include "test_support.hpp"

using namespace gearloss;
using Approx = Catch::Detail::Approx;
constexpr double rpm = std::numbers::pi / 30;

namespace {
struct TempFile {
    std::string path;
    explicit TempFile(const std::string& text) {
        static int k = 0;
        path = (std::filesystem::temp_directory_path() / ("gearloss-test-" + std::to_string(::getpid()) + "-" +
                                                          std::to_string(k++) + ".csv")).string();
        std::ofstream(path) << text;
    }
    ~TempFile() { std::filesystem::remove(path); }
};

io::Case transfer() { return io::load_case(test_support::source_path("configs/transfer-box.yaml")); }

io::OperatingGrid campaign_grid() {
    io::OperatingGrid g;
    for (double n : {400.0, 600.0, 800.0, 1000.0, 1200.0}) g.speeds.push_back(n * rpm);
    g.torques = {100, 175, 250, 325};
    return g;
}

// A synthetic campaign on the standard grid, through the recordings reader.
diagnosis::Recordings campaign(const io::Case& c, std::vector<std::pair<std::string, double>> effects, unsigned seed) {
    diagnosis::SynthOptions so;
    so.effects = std::move(effects);
    so.seed = seed;
    TempFile f(diagnosis::synthesize(c.model, campaign_grid(), so));
    return diagnosis::read_recordings(f.path);
}

diagnosis::Diagnosis run(const io::Case& c, std::vector<std::pair<std::string, double>> effects, unsigned seed) {
    return diagnosis::diagnose(c.model, campaign(c, std::move(effects), seed));
}
}  // namespace

TEST_CASE("calibration terms act inside the loss model and the thermal solve", "[diagnosis]") {
    auto c = transfer();
    auto& m = c.model;
    m.thermal.mode = solver::ThermalMode::fixed;
    m.thermal.oil_temperature = 343.15;
    const double w = 1200 * rpm, T = 250;
    const double base = solver::solve_point(m, w, T).losses.total();
    // Windage adds exactly C (n/1000 rpm)^2.9: 10 W * 1.2^2.9 = 16.975 W.
    m.mechanisms.at("windage").set_parameter("empirical_W_at_1000rpm", 10);
    const auto rw = solver::solve_point(m, w, T);
    CHECK(rw.losses.total() - base == Approx(10 * std::pow(1.2, 2.9)).epsilon(1e-9));
    // In the windage column, not churning's.
    CHECK(test::part(rw.losses, "windage") == Approx(10 * std::pow(1.2, 2.9)).epsilon(1e-9));
    m.mechanisms = {};
    m.mechanisms.at("auxiliary").set_parameter("power", 40);
    CHECK(solver::solve_point(m, w, T).losses.total() - base == Approx(40).epsilon(1e-9));
    m.mechanisms = {};
    m.mechanisms.at("seals").set_parameter("factor", 3);
    const auto r0 = solver::solve_point(c.model, w, T);
    CHECK(test::part(r0.losses, "seals") == Approx(3 * (7.69e-6 * 45 * 45 * 1200 + 7.69e-6 * 40 * 40 * 1200 * (17.0 / 28 * 23.0 / 32))).epsilon(1e-9));

    // A real extra loss heats the oil: in stabilised mode the solution still
    // balances P = Q, now at a higher temperature.
    m.mechanisms = {};
    m.thermal.mode = solver::ThermalMode::stabilised;
    const auto cold = solver::solve_point(m, w, T);
    m.mechanisms.at("auxiliary").set_parameter("power", 100);
    const auto hot = solver::solve_point(m, w, T);
    CHECK(hot.oil_temperature > cold.oil_temperature + 3);
    CHECK(std::abs(hot.losses.total() - m.heat_flow(hot.oil_temperature, m.thermal.ambient, w)) < 0.05);
    // Halving the heat rejection with a constant loss doubles the temperature rise
    // (resistance model: Q = (T - Ta)/R).
    auto r = transfer();
    for (const char* name : {"mesh", "bearings", "churning", "seals"}) r.model.mechanisms.at(name).set_enabled(false);
    r.model.mechanisms.at("auxiliary").set_parameter("power", 200);
    r.model.thermal.rejection.model = thermal::ThermalResistance{0.1, 0, 0};
    const double rise1 = solver::solve_point(r.model, w, T).oil_temperature - r.model.thermal.ambient;
    r.model.calibration.heat_rejection_factor = 0.5;
    const double rise2 = solver::solve_point(r.model, w, T).oil_temperature - r.model.thermal.ambient;
    CHECK(rise1 == Approx(20.0).margin(2e-3));
    CHECK(rise2 == Approx(40.0).margin(2e-3));
}

TEST_CASE("recordings: steady points, warnings and errors with line numbers", "[diagnosis]") {
    TempFile ok("speed_in_rpm,torque_in_Nm,P_loss_W,oil_temp_C,colour\n600,150,210.5,52.1,red\n700,150,240,55\n");
    SECTION("malformed rows are errors naming the line") {
        // (the second data row above has a missing cell)
        try {
            diagnosis::read_recordings(ok.path);
            FAIL("no error");
        } catch (const InputError& e) {
            CHECK(e.line == 3);
            CHECK_THAT(e.message, Catch::Contains("cells"));
        }
    }
    SECTION("unknown columns are warned about, values converted to SI") {
        TempFile f("speed_in_rpm,torque_in_Nm,P_loss_W,oil_temp_C,colour\n600,150,210.5,52.1,red\n");
        const auto r = diagnosis::read_recordings(f.path);
        REQUIRE(r.points.size() == 1);
        CHECK(r.points[0].speed_in == Approx(600 * rpm));
        CHECK(*r.points[0].oil_temp == Approx(325.25));
        REQUIRE(r.warnings.size() == 1);
        CHECK_THAT(r.warnings[0], Catch::Contains("unknown column 'colour'"));
    }
    SECTION("non-numbers and missing columns") {
        TempFile bad("speed_in_rpm,torque_in_Nm,P_loss_W\n600,150,210\n700,abc,240\n");
        CHECK_THROWS_WITH(diagnosis::read_recordings(bad.path), Catch::Contains(":3:2: torque_in_Nm: 'abc' is not a number"));
        TempFile miss("speed_in_rpm,P_loss_W\n600,210\n");
        CHECK_THROWS_WITH(diagnosis::read_recordings(miss.path), Catch::Contains("required column 'torque_in_Nm' is missing"));
        // A log whose time goes backwards.
        TempFile back("time_s,speed_in_rpm,speed_out_rpm,torque_in_Nm,torque_out_Nm,oil_temp_C,room_temp_C\n"
                      "0,600,261,150,340,40,25\n2,600,261,150,340,40,25\n1,600,261,150,340,40,25\n");
        CHECK_THROWS_WITH(diagnosis::read_recordings(back.path), Catch::Contains(":4: time_s: time must increase"));
    }
}

TEST_CASE("raw rig log: split into tests, stabilisation criterion, averaged window", "[diagnosis]") {
    auto c = transfer();
    io::OperatingGrid g;
    g.speeds = {600 * rpm, 800 * rpm};
    g.torques = {150, 250};
    diagnosis::SynthOptions so;
    so.raw_log = true;
    so.noise_loss = so.noise_temp = 0;
    so.effects = {{"unstabilised_test", 1}};
    so.seed = 3;
    TempFile f(diagnosis::synthesize(c.model, g, so));
    const auto r = diagnosis::read_recordings(f.path);
    REQUIRE(r.from_log);
    REQUIRE(r.points.size() == 4);
    int unstable = 0;
    for (size_t i = 0; i < 4; ++i) {
        const auto& p = r.points[i];
        const auto [w, T] = g.at(i);
        CHECK(p.speed_in == Approx(w).epsilon(1e-3));
        CHECK(p.torque_in == Approx(T).epsilon(2e-3));
        unstable += !p.stabilised;
        if (p.stabilised) {
            // A stabilised test (240 min, time constant ~50 min) averages to the
            // model's equilibrium within a fraction of a kelvin and ~1 % in loss.
            const auto eq = solver::solve_point(c.model, w, T);
            CHECK(*p.oil_temp == Approx(eq.oil_temperature).margin(0.5));
            CHECK(p.loss == Approx(eq.losses.total()).epsilon(0.01));
            CHECK(p.stabilisation_drift < 0.5);
        }
    }
    CHECK(unstable == 1);
    CHECK(r.warnings.size() == 1);
}

TEST_CASE("diagnose names a concealed windage and recovers its size", "[diagnosis]") {
    const auto c = transfer();
    const auto d = run(c, {{"windage", 25.0}}, 11);
    REQUIRE(d.verdict == "missing_physics");
    REQUIRE(!d.findings.empty());
    const auto& f = d.findings[0];
    CHECK(f.effect == "windage");
    // The concealed value lies within 4 standard uncertainties of the estimate.
    CHECK(std::abs(f.parameter.value - 25.0) < 4 * f.parameter.uncertainty);
    CHECK(f.rmse_after < 0.5 * f.rmse_before);
    CHECK(f.cv_rmse_after < 0.5 * f.cv_rmse_before);
    CHECK(f.stability >= 0.6);
    CHECK_THAT(d.summary, Catch::Contains("grows with speed"));
}

TEST_CASE("a finding is named with confidence only at the stricter confidence level", "[diagnosis]") {
    const auto c = transfer();
    const auto rec = campaign(c, {{"windage", 25.0}}, 11);
    // Default: what the windage finding leaves passes the combined test at 5 % (the four
    // p-values are 0.35, 1, 0.99 and 0.026: Fisher's X = 9.4 on 8 dof, p = 0.31; the
    // structure tests run along speed, torque and oil temperature, the file records no run order).
    diagnosis::DiagnoseOptions opt;
    const auto d = diagnosis::diagnose(c.model, rec, opt);
    REQUIRE(d.verdict == "missing_physics");
    // Demanding that the combination passes at 49 %: p = 0.31 fails, so the same finding is
    // no longer confident, and the report says what is left; the finding itself does not change.
    opt.confidence_level = 0.49;
    const auto strict = diagnosis::diagnose(c.model, rec, opt);
    CHECK(strict.verdict == "partly_explained");
    REQUIRE(!strict.findings.empty());
    CHECK(strict.findings[0].effect == "windage");
    // No single test fails at 1 % (0.026 is the smallest; Holm holds it to 1 %/4): the report
    // names the combination.
    CHECK_THAT(strict.remaining, Catch::Contains("no single test fails at 0.01 (Holm over 4 tests), but together they do"));
    CHECK_THAT(strict.remaining, Catch::Contains("oil temperature structure p = 0.026"));
    // The confidence level cannot be laxer than the level at which a mismatch is claimed.
    opt.confidence_level = 0.005;
    CHECK_THROWS_WITH(diagnosis::diagnose(c.model, rec, opt), Catch::Contains("confidence_level"));
}

TEST_CASE("diagnose finds nothing in data without a concealed effect", "[diagnosis]") {
    const auto c = transfer();
    for (unsigned seed : {21u, 22u, 23u}) {
        const auto d = run(c, {}, seed);
        CHECK(d.verdict == "no_significant_mismatch");
        CHECK(d.findings.empty());
    }
}

TEST_CASE("temperature is evidence: sensor gain and mesh friction are told apart", "[diagnosis]") {
    // Both raise the recorded loss with torque and speed; only the real friction heats the oil.
    const auto c = transfer();
    CHECK(run(c, {{"torque_sensor_gain", 1.006}}, 31).findings.at(0).effect == "torque_sensor_gain");
    CHECK(run(c, {{"mesh_friction", 1.2}}, 32).findings.at(0).effect == "mesh_friction");
}

TEST_CASE("unstabilised points are found and listed as outliers", "[diagnosis]") {
    const auto c = transfer();
    const auto d = run(c, {{"unstabilised_test", 2}}, 41);
    REQUIRE(d.findings.size() >= 1);
    CHECK(d.findings[0].effect == "unstabilised_test");
    CHECK(d.findings[0].rows.size() == 2);
    int flagged = 0;
    for (const auto& o : d.outliers) flagged += o.reason.find("unstabilised") != std::string::npos;
    CHECK(flagged == 2);
}

TEST_CASE("a residual no candidate has the shape of is never named with confidence", "[diagnosis]") {
    // +30 W (T/250 N m)(600 rpm/n): falls with speed, grows with torque, does not heat the oil.
    const auto c = transfer();
    auto rec = campaign(c, {}, 5);
    for (auto& p : rec.points) p.loss += 30 * (p.torque_in / 250) * (600 * rpm / p.speed_in);
    const auto d = diagnosis::diagnose(c.model, rec);
    // A candidate may take part of it (partly_explained), but what it leaves is not noise.
    CHECK((d.verdict == "unexplained_mismatch" || d.verdict == "partly_explained"));
    CHECK_THAT(d.summary, Catch::Contains("falls with speed"));
    CHECK_THAT(d.summary, Catch::Contains("not measurement noise") || Catch::Contains("no candidate effect explains it"));
}

TEST_CASE("without temperatures, heat-free and heating look-alikes are named together", "[diagnosis]") {
    const auto c = transfer();
    auto rec = campaign(c, {{"seal_friction", 3}}, 8);
    for (auto& p : rec.points) p.oil_temp.reset();
    // 20 points without temperatures, the noise estimated from them: the fit test sees a
    // remainder only above about 1.1 times the noise. The pair is present (its evidence is
    // plain and what it leaves passes the tests): named with confidence, and the report says
    // apart that these points cannot show it to be the whole cause. With the rig's noise
    // declared (synth's 1.5 %), chi-squared on 19 dof sees a remainder of 0.79 times it half
    // the time (tables: 30.14 / 18.34 = 1 + 0.79^2): shown to be the whole cause too.
    const auto weak = diagnosis::diagnose(c.model, rec);
    INFO(weak.remaining);
    CHECK(weak.verdict == "missing_physics");
    CHECK(weak.main_finding.confidence == "confident");
    CHECK_THAT(weak.completeness, Catch::Contains("on 20 points") && Catch::Contains("--loss-uncertainty"));
    CHECK(weak.detectable > 1.0);
    diagnosis::DiagnoseOptions opt;
    opt.loss_uncertainty = 0.015;
    const auto d = diagnosis::diagnose(c.model, rec, opt);
    REQUIRE(d.verdict == "missing_physics");
    CHECK_THAT(d.detectable, Catch::Matchers::WithinAbs(0.80, 0.02));
    CHECK_THAT(d.completeness, Catch::Contains("would have seen a remainder of the noise's size"));
    const auto& fd = d.findings.at(0);
    const bool pair = (fd.effect == "seal_friction" && fd.equivalent.size() == 1 && fd.equivalent[0] == "torque_sensor_offset") ||
                      (fd.effect == "torque_sensor_offset" && fd.equivalent.size() == 1 && fd.equivalent[0] == "seal_friction");
    CHECK(pair);
    CHECK_THAT(fd.separating_measurement, Catch::Contains("oil temperature"));
}

TEST_CASE("the calibrated config reproduces the recordings", "[diagnosis]") {
    // Diagnose, write the calibrated case, reload it: diagnosing the same recordings
    // against it finds nothing left to explain.
    const auto c = transfer();
    const auto rec = campaign(c, {{"constant_parasitic", 30.0}}, 12);
    const auto d = diagnosis::diagnose(c.model, rec);
    REQUIRE(d.findings.at(0).effect == "constant_parasitic");
    const std::string out = (std::filesystem::temp_directory_path() / "gearloss-calibrated-test.yaml").string();
    diagnosis::write_calibrated_config(test_support::source_path("configs/transfer-box.yaml"), out, d);
    const auto c2 = io::load_case(out);
    std::filesystem::remove(out);
    CHECK(c2.model.mechanisms.at("auxiliary").parameter("power") == Approx(d.findings[0].parameter.value).epsilon(1e-5));
    // The noise synth put in is known (1.5 % on loss, 0.4 K): declared, the verdict does not
    // hang on how well 20 points estimate it (their neighbour differences give 0.67 % for this
    // seed, one campaign in a hundred, which the exact test then rightly calls a remainder).
    diagnosis::DiagnoseOptions known_noise;
    known_noise.loss_uncertainty = diagnosis::SynthOptions{}.noise_loss;
    known_noise.temp_uncertainty = diagnosis::SynthOptions{}.noise_temp;
    const auto d2 = diagnosis::diagnose(c2.model, rec, known_noise);
    INFO(d2.summary);
    CHECK(d2.verdict == "no_significant_mismatch");
}
