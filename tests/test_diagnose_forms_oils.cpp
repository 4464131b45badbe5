// The diagnosis names a model form (another published friction law) and tells effects common
// to every oil from those of one oil in a multi-oil campaign. The truth is made by another
// route than the diagnosis' candidates: a model whose form, parameters or calibration are set
// directly (as a case file would set them), synthesised without concealed effects.
#include <catch2/catch.hpp>
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <numbers>
#include <sstream>
#include <string>
#include <unistd.h>

#include "gearloss/diagnosis/diagnose.hpp"
#include "gearloss/diagnosis/recordings.hpp"
#include "gearloss/diagnosis/synth.hpp"
#include "gearloss/case/config.hpp"
#include "gearloss/solver/operating_point.hpp"
#include "test_support.hpp"

using namespace gearloss;
namespace fs = std::filesystem;
using test_support::rpm_grid;

namespace {

std::string synth_text(const solver::Model& truth, const io::OperatingGrid& grid, unsigned seed) {
    diagnosis::SynthOptions so;
    so.seed = seed;
    so.noise_loss = 0.01;
    so.noise_temp = 0.3;
    return diagnosis::synthesize(truth, grid, so);
}

// A directory of its own for one test, removed afterwards.
struct TempDir {
    fs::path path;
    TempDir() {
        path = fs::temp_directory_path() / ("gearloss-oils-" + std::to_string(::getpid()) + "-" +
                                            std::to_string(reinterpret_cast<std::uintptr_t>(this)));
        fs::create_directories(path / "oils");
    }
    ~TempDir() {
        std::error_code ec;
        fs::remove_all(path, ec);
    }
};

// Appends an `oil` column with `oil` to every data line of a synthesised CSV (header skipped
// unless `header`).
std::string with_oil(const std::string& csv, const std::string& oil, bool header) {
    std::string out, line;
    std::istringstream in(csv);
    bool first = true;
    while (std::getline(in, line)) {
        if (line.empty() || line[0] == '#') continue;
        if (first) {
            first = false;
            if (header) out += line + ",oil\n";
            continue;
        }
        out += line + "," + oil + "\n";
    }
    return out;
}

}  // namespace

TEST_CASE("a campaign run with another friction law: the form is named and written to the case", "[diagnose_forms]") {
    const auto c = test_support::load_shipped("configs/transfer-box.yaml");
    REQUIRE(c.model.mechanisms.at("mesh").form(c.model, "friction") == "schlenk");
    solver::Model truth = c.model;
    truth.mechanisms.at("mesh").set_form(truth, "friction", "fernandes_mixed");
    const auto grid = rpm_grid({400, 650, 900, 1150}, {100, 175, 250, 300});
    const auto rec = diagnosis::read_recordings_text(synth_text(truth, grid, 7), "rec.csv");
    // The rig's noise declared (synth_text's): 16 points test the form as the whole cause.
    diagnosis::DiagnoseOptions opt;
    opt.loss_uncertainty = 0.01;
    opt.temp_uncertainty = 0.3;
    const auto d = diagnosis::diagnose(c.model, rec, opt);
    REQUIRE_FALSE(d.findings.empty());
    CHECK(d.findings.front().effect == "friction:fernandes_mixed");
    CHECK(d.findings.front().parameter.form == "fernandes_mixed");
    CHECK(d.findings.front().parameter.case_form == "schlenk");
    CHECK(d.verdict == "missing_physics");
    // What the form leaves is the 1 % noise put in (RMSE of about 1 % of a ~500 W loss).
    CHECK(d.rmse_after < 0.25 * d.rmse_before);

    // Written under `mechanisms:`; the calibrated case loads with the form and gives the
    // truth's loss at a point (the same model, so to rounding).
    TempDir dir;
    const std::string out = (dir.path / "calibrated.yaml").string();
    diagnosis::write_calibrated_config(test_support::source_path("configs/transfer-box.yaml"), out, d);
    const auto cal = io::load_case(out);
    CHECK(cal.model.mechanisms.at("mesh").form(cal.model, "friction") == "fernandes_mixed");
    solver::PointState p1, p2;
    solver::prepare_point(cal.model, 900 * std::numbers::pi / 30, 250, p1);
    solver::prepare_point(truth, 900 * std::numbers::pi / 30, 250, p2);
    CHECK(solver::total_loss(cal.model, p1, 353.15) == Approx(solver::total_loss(truth, p2, 353.15)).epsilon(1e-9));
}

TEST_CASE("a friction level lower than the model's is a scale factor, not a form", "[diagnose_forms]") {
    // Every alternative friction law of the transfer box gives more friction than Schlenk's at
    // these points; a level 20 % lower is the friction factor, and no form may claim it.
    const auto c = test_support::load_shipped("configs/transfer-box.yaml");
    solver::Model truth = c.model;
    truth.mechanisms.at("mesh").set_parameter("friction_factor", 0.8);
    const auto rec =
        diagnosis::read_recordings_text(synth_text(truth, rpm_grid({400, 650, 900, 1150}, {100, 175, 250, 300}), 3), "rec.csv");
    const auto d = diagnosis::diagnose(c.model, rec);
    REQUIRE_FALSE(d.findings.empty());
    CHECK(d.findings.front().effect == "mesh_friction");
    CHECK(d.findings.front().parameter.value == Approx(0.8).epsilon(0.15));
    for (const auto& f : d.findings) CHECK(f.effect.find(':') == std::string::npos);
}

TEST_CASE("multi-oil campaign: a common loss fitted once, a viscosity error found for its oil alone", "[diagnose_oils]") {
    // Two oils in the transfer box. Common to both: 25 W of windage at 1000 rpm. Oil 75W140-A
    // only: its viscosity 40 % above its datasheet (the model's calibration set directly).
    const auto c = test_support::load_shipped("configs/transfer-box.yaml");
    TempDir dir;
    for (const char* oil : {"75W90-A.yaml", "75W140-A.yaml"})
        fs::copy_file(test_support::source_path(std::string("configs/oils/") + oil), dir.path / "oils" / oil);
    const auto grid = rpm_grid({400, 700, 1000}, {100, 200, 300});
    std::string csv;
    for (int k = 0; k < 2; ++k) {
        const std::string oil = k == 0 ? "oils/75W90-A.yaml" : "oils/75W140-A.yaml";
        solver::Model truth = c.model;
        truth.oil = io::load_oil_file((dir.path / oil).string());
        truth.mechanisms.at("windage").set_parameter("empirical_W_at_1000rpm", 25.0);
        if (k == 1) truth.calibration.viscosity_factor = 1.4;
        csv += with_oil(synth_text(truth, grid, 11 + k), oil, k == 0);
    }
    std::ofstream(dir.path / "rec.csv") << csv;
    const auto rec = diagnosis::read_recordings((dir.path / "rec.csv").string());
    const auto d = diagnosis::diagnose(c.model, rec);
    REQUIRE(d.oils.size() == 2);
    const diagnosis::Finding *windage = nullptr, *viscosity = nullptr;
    for (const auto& f : d.findings) {
        if (f.effect == "windage" || std::count(f.equivalent.begin(), f.equivalent.end(), "windage")) windage = &f;
        if (f.effect == "oil_viscosity") viscosity = &f;
    }
    REQUIRE(viscosity);
    CHECK(viscosity->oil == "oils/75W140-A.yaml");
    CHECK(viscosity->parameter.value == Approx(1.4).epsilon(0.15));
    REQUIRE(windage);
    CHECK(windage->oil.empty());  // common to both oils
    // The recorded differences between the oils, against the model's before and after.
    REQUIRE(d.oil_differences.size() == 9);
    double before = 0, after = 0;
    for (const auto& x : d.oil_differences) {
        CHECK(x.oil_b == "oils/75W140-A.yaml");
        before += std::pow(x.recorded - x.model_before, 2);
        after += std::pow(x.recorded - x.model_after, 2);
    }
    CHECK(after < 0.5 * before);
    CHECK(diagnosis::residuals_csv(d).find(",oil\n") != std::string::npos);
    CHECK(diagnosis::diagnosis_json(d).find("\"oil\":\"oils/75W140-A.yaml\"") != std::string::npos);
}

TEST_CASE("the oil column: a missing oil file and a raw log are errors naming the file, line and key",
          "[diagnose_oils]") {
    const auto c = test_support::load_shipped("configs/transfer-box.yaml");
    const auto rec = diagnosis::read_recordings_text(
        "speed_in_rpm,torque_in_Nm,P_loss_W,oil\n500,100,200,oils/A.yaml\n600,100,230,no-such-oil.yaml\n", "rec.csv");
    REQUIRE(rec.points.size() == 2);
    CHECK(rec.points[1].oil == "no-such-oil.yaml");
    try {
        diagnosis::diagnose(c.model, rec);
        FAIL("a missing oil file was accepted");
    } catch (const InputError& e) {
        const std::string what = e.what();
        CHECK(what.rfind("rec.csv:2: oil: oil file 'oils/A.yaml'", 0) == 0);
    }
    // synth: a form is chosen or not, nothing in between.
    CHECK(diagnosis::parse_effect_assignment(c.model, "friction:ehl_local=1").second == 1.0);
    CHECK_THROWS_WITH(diagnosis::parse_effect_assignment(c.model, "friction:ehl_local=0.3"),
                      Catch::Contains("a form is chosen (1) or not (0)"));
    CHECK_THROWS_WITH(diagnosis::read_recordings_text("time_s,speed_in_rpm,torque_in_Nm,speed_out_rpm,torque_out_Nm,oil_temp_C,"
                                                      "room_temp_C,oil\n0,500,100,250,190,40,25,a.yaml\n",
                                                      "log.csv"),
                      Catch::Contains("log.csv:1:8: oil: the oil column is read in steady-point recordings"));
}
