// The verdict keeps two questions apart (is an effect present, is it the whole cause), the noise
// it is judged against is stated and bounded below on a small campaign, the run order is taken
// only from a column that records it, and outliers are outliers against the noise in use.
#include <catch2/catch.hpp>
#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <numbers>
#include <sstream>
#include <unistd.h>

#include "gearloss/core/errors.hpp"
#include "gearloss/diagnosis/diagnose.hpp"
#include "gearloss/diagnosis/recordings.hpp"
#include "gearloss/diagnosis/run_order.hpp"
#include "gearloss/diagnosis/synth.hpp"
#include "gearloss/case/config.hpp"
#include "test_support.hpp"

using namespace gearloss;
constexpr double rpm = std::numbers::pi / 30;

namespace {
io::Case transfer() { return io::load_case(test_support::source_path("configs/transfer-box.yaml")); }

// A synth_own campaign of scripts/independent-campaigns.py diagnosed blind: the shipped case as
// it is (synth's own heat path), the recordings' rows after the header
// speed_in_rpm,torque_in_Nm,P_loss_W,oil_temp_C,ambient_temp_C.
diagnosis::Diagnosis diagnose_synth_own(const std::string& config, const std::string& rows) {
    return diagnosis::diagnose(test_support::load_shipped(config).model,
                               diagnosis::read_recordings_text(
                                   "speed_in_rpm,torque_in_Nm,P_loss_W,oil_temp_C,ambient_temp_C\n" + rows, "rec.csv"));
}

io::OperatingGrid grid(std::vector<double> speeds_rpm, std::vector<double> torques) {
    io::OperatingGrid g;
    for (double n : speeds_rpm) g.speeds.push_back(n * rpm);
    g.torques = std::move(torques);
    return g;
}

std::string synth(const io::Case& c, const io::OperatingGrid& g, std::vector<std::pair<std::string, double>> effects,
                  double noise, unsigned seed) {
    diagnosis::SynthOptions so;
    so.effects = std::move(effects);
    so.noise_loss = noise;
    so.seed = seed;
    return diagnosis::synthesize(c.model, g, so);
}

// The CSV's rows (header first) and its cells.
std::vector<std::vector<std::string>> cells_of(const std::string& csv) {
    std::vector<std::vector<std::string>> rows;
    std::istringstream in(csv);
    for (std::string line; std::getline(in, line);) {
        if (line.empty()) continue;
        std::vector<std::string> r;
        std::istringstream l(line);
        for (std::string cell; std::getline(l, cell, ',');) r.push_back(cell);
        rows.push_back(r);
    }
    return rows;
}

std::string csv_of(const std::vector<std::vector<std::string>>& rows) {
    std::string s;
    for (const auto& r : rows) {
        for (size_t k = 0; k < r.size(); ++k) s += (k ? "," : "") + r[k];
        s += "\n";
    }
    return s;
}

bool contains(const std::string& s, const std::string& what) { return s.find(what) != std::string::npos; }
}  // namespace

TEST_CASE("a small synth campaign names its single effect with confidence, against a stated noise", "[diagnosis][verdict]") {
    // The 3 x 3 grid of the transfer gearbox, mesh friction 20 % high, 1.5 % loss noise, nothing
    // declared. The effect is plain (the loss RMSE falls from ~56 W to ~8 W, the noise's size):
    // it is present and nothing else is, so `missing_physics`. A noise estimated from 9 points'
    // neighbour differences can come out far below 1.5 % (0.3 % for some seeds): the noise used
    // is then the stated floor (1 %), never below it, and no false lead (a resonance) is proposed.
    const auto c = transfer();
    const auto g = grid({600, 700, 800}, {150, 200, 250});
    int confident = 0, floored = 0;
    for (unsigned seed = 1; seed <= 4; ++seed) {
        const auto rec = diagnosis::read_recordings_text(synth(c, g, {{"mesh_friction", 1.2}}, 0.015, seed), "t.csv");
        const auto d = diagnosis::diagnose(c.model, rec);
        REQUIRE_FALSE(d.findings.empty());
        CHECK(d.findings.front().effect == "mesh_friction");
        CHECK(d.noise_used.loss_relative >= 0.01);  // the floor bounds the 9-point estimate
        CHECK_FALSE(d.noise_used.why.empty());
        floored += d.noise_used.source == "floor";
        if (d.verdict == "missing_physics") {
            ++confident;
            CHECK(d.main_finding.effect == "mesh_friction");
            CHECK(d.main_finding.confidence == "confident");
        }
        const std::string json = diagnosis::diagnosis_json(d);
        CHECK_FALSE(contains(json, "resonance"));
        CHECK(contains(json, "\"noise_used\""));
    }
    CHECK(confident == 4);
    CHECK(floored >= 1);
}

TEST_CASE("a confident main finding, and a smaller structure left apart from it", "[diagnosis][verdict]") {
    // Mesh friction 20 % high (loss RMSE ~60 W -> the noise, oil ~8 K too hot -> the noise),
    // and the oil 1.5 K hotter at every test at 800 rpm than any candidate makes it (a rig
    // effect at one speed). The loss is at the noise after the finding; what is left is a
    // structure in the oil temperature along speed, 4 of 20 points 1.5 K off: RMS sqrt(4/20)
    // x 1.5 = 0.67 K, about 1.5 times the noise beyond it. The verdict names the main finding
    // with confidence and reports that structure apart, sized and located, with or without a
    // declared noise.
    const auto c = transfer();
    const auto g = grid({400, 600, 800, 1000, 1200}, {100, 175, 250, 325});
    auto rows = cells_of(synth(c, g, {{"mesh_friction", 1.2}}, 0.015, 6));
    for (size_t k = 1; k < rows.size(); ++k)
        if (std::abs(std::stod(rows[k][0]) - 800) < 1) rows[k][3] = std::to_string(std::stod(rows[k][3]) + 1.5);
    const auto rec = diagnosis::read_recordings_text(csv_of(rows), "band.csv");
    diagnosis::DiagnoseOptions declared;
    declared.loss_uncertainty = 0.015;
    declared.temp_uncertainty = 0.4;
    for (const auto& opt : {diagnosis::DiagnoseOptions{}, declared}) {
        const auto d = diagnosis::diagnose(c.model, rec, opt);
        CHECK(d.verdict == "missing_physics");
        CHECK(d.main_finding.effect == "mesh_friction");
        CHECK(d.main_finding.confidence == "confident");
        REQUIRE(d.remaining_structure);
        CHECK(d.remaining_structure->channel == "oil_temperature");
        CHECK(d.remaining_structure->along == "speed");
        CHECK(d.remaining_structure->rms_over_noise > 1.0);
        CHECK(d.remaining_structure->rms_over_noise < 3.0);
        CHECK(contains(diagnosis::diagnosis_json(d), "\"remaining_structure\""));
    }
}

TEST_CASE("run order: a run, date or time cell as a number that grows with the order", "[diagnosis][verdict]") {
    using diagnosis::run_order_key;
    CHECK(*run_order_key("run", "17") == 17);
    // 2026-11-27 is 20 784 days after 1970-01-01 (date -d 2026-11-27 +%s = 1795737600).
    CHECK(*run_order_key("date", "2026-11-27") == 1795737600.0);
    CHECK(*run_order_key("date", "2026-11-27 13:05") == 1795737600.0 + 13 * 3600 + 5 * 60);
    CHECK(*run_order_key("time", "2026-11-27T13:05:30.5") == 1795737600.0 + 13 * 3600 + 5 * 60 + 30.5);
    CHECK(*run_order_key("time", "7:05") == 7 * 3600 + 5 * 60);
    CHECK_FALSE(run_order_key("date", "27/11/2026"));
    CHECK_FALSE(run_order_key("run", "first"));
    CHECK_FALSE(run_order_key("time", "13h05"));
    // In a recordings file: a bad cell is an error at its line and column.
    const std::string bad = "speed_in_rpm,torque_in_Nm,P_loss_W,run\n600,150,500,1\n700,150,520,second\n";
    try {
        diagnosis::read_recordings_text(bad, "r.csv");
        FAIL("no error");
    } catch (const InputError& e) {
        CHECK(contains(e.what(), "r.csv:3:4"));
    }
    const auto rec = diagnosis::read_recordings_text("speed_in_rpm,torque_in_Nm,P_loss_W,date,time\n600,150,500,2026-11-27,"
                                                     "09:00\n700,150,520,2026-11-26,17:30\n", "r.csv");
    CHECK(rec.run_order_column == "date");
    CHECK(*rec.points[0].run_order > *rec.points[1].run_order);
    CHECK(diagnosis::read_recordings_text("speed_in_rpm,torque_in_Nm,P_loss_W\n600,150,500\n", "r.csv").run_order_column.empty());
}

TEST_CASE("no drift or running-in hypothesis without a recorded run order", "[diagnosis][verdict]") {
    // A running-in: the loss 25 % high on the first test, decaying over the campaign (tau = 3
    // tests), the tests in an order unrelated to the operating point (a shuffle of the grid,
    // fixed here). Written in that order without a `run` column, the rows' order is not known
    // to be the run order: nothing may speak of drift or running-in, and no test runs along it.
    // With the `run` column the same decay is seen along the run order.
    const auto c = transfer();
    const auto g = grid({400, 600, 800, 1000, 1200}, {100, 175, 250, 325});
    auto rows = cells_of(synth(c, g, {}, 0.01, 5));
    std::vector<std::vector<std::string>> body(rows.begin() + 1, rows.end());
    const size_t n = body.size();
    std::vector<size_t> perm(n);
    for (size_t k = 0; k < n; ++k) perm[k] = (7 * k + 3) % n;  // 7 and 20 coprime: a fixed shuffle
    std::vector<std::vector<std::string>> shuffled{rows[0]}, with_run{rows[0]};
    with_run[0].push_back("run");
    for (size_t k = 0; k < n; ++k) {
        auto r = body[perm[k]];
        const double loss = std::stod(r[2]) * (1 + 0.25 * std::exp(-static_cast<double>(k) / 3));
        r[2] = std::to_string(loss);
        shuffled.push_back(r);
        r.push_back(std::to_string(k + 1));
        with_run.push_back(r);
    }
    const auto d = diagnosis::diagnose(c.model, diagnosis::read_recordings_text(csv_of(shuffled), "shuffled.csv"));
    CHECK_FALSE(d.run_order.recorded);
    const std::string text = diagnosis::diagnosis_text(d) + diagnosis::diagnosis_json(d);
    CHECK_FALSE(contains(text, "running-in or drift"));
    CHECK(d.adequacy_loss.structure_along != "run order");
    CHECK(d.adequacy_temp.structure_along != "run order");
    CHECK(contains(text, "run order: not recorded"));
    CHECK(contains(text, "\"run_order\":{\"recorded\":false,\"column\":null}"));
    const auto r = diagnosis::diagnose(c.model, diagnosis::read_recordings_text(csv_of(with_run), "run.csv"));
    CHECK(r.run_order.recorded);
    CHECK(r.run_order.column == "run");
    CHECK(r.verdict != "no_significant_mismatch");
}

TEST_CASE("outliers are outliers against the noise in use", "[diagnosis][verdict]") {
    // A campaign recorded with 0.1 % noise, declared at 1.5 %: one row 2.5 % high is 1.7 times
    // the noise (no outlier, though it is 25 times the campaign's own scatter), one row 12 % high
    // is 8 times it (an outlier, with its deviation over the noise).
    const auto c = transfer();
    const auto g = grid({400, 600, 800, 1000, 1200}, {100, 175, 250, 325});
    auto rows = cells_of(synth(c, g, {}, 0.001, 3));
    rows[4][2] = std::to_string(std::stod(rows[4][2]) * 1.025);  // data row 4
    rows[12][2] = std::to_string(std::stod(rows[12][2]) * 1.12);  // data row 12
    diagnosis::DiagnoseOptions opt;
    opt.loss_uncertainty = 0.015;
    const auto d = diagnosis::diagnose(c.model, diagnosis::read_recordings_text(csv_of(rows), "o.csv"), opt);
    bool row4 = false, row12 = false;
    for (const auto& o : d.outliers) {
        row4 |= o.row == 4;
        if (o.row == 12) {
            row12 = true;
            REQUIRE(o.loss_deviation_over_noise);
            CHECK(*o.loss_deviation_over_noise > 4.5);
        }
        if (o.loss_deviation_over_noise) CHECK(std::abs(*o.loss_deviation_over_noise) > 4.5);
    }
    CHECK_FALSE(row4);
    CHECK(row12);
}

TEST_CASE("two forms of one mechanism sharing the resamples name the mechanism with confidence", "[diagnose_verdict]") {
    // A campaign of scripts/independent-campaigns.py (synth_own, transfer seed 0): `gearloss synth`
    // of the shipped transfer box with mesh_friction = 1.117, 3 x 3 points, 2.9 % loss noise, no
    // declared uncertainty. On nine points the mesh friction level and its mixed-film rise (the
    // onset fitted at the top of its grid stands in for a level) split the resamples 54/46:
    // the mesh friction is certain, which of its forms is not. Named with confidence, the level
    // first (the truth, within 3 %), the rise listed as equally good.
    const auto d = diagnose_synth_own(
        "configs/transfer-box.yaml",
            "720,100,200.7602,51.0872,25\n720,150,299.9055,62.1793,25\n720,200,406.7665,74.6726,25\n"
            "880,100,244.2140,55.9454,25\n880,150,346.0366,68.8608,25\n880,200,451.3993,82.8589,25\n"
            "1200,100,316.4878,66.2045,25\n1200,150,455.2381,80.8631,25\n1200,200,637.6298,98.7775,25\n");
    INFO(d.summary);
    REQUIRE_FALSE(d.findings.empty());
    const auto& f = d.findings.front();
    CHECK(f.effect == "mesh_friction");
    CHECK(f.parameter.value == Approx(1.117).epsilon(0.03));
    CHECK(d.verdict == "missing_physics");
    CHECK(d.main_finding.confidence == "confident");
    CHECK(std::find(f.equivalent.begin(), f.equivalent.end(), "mesh_friction_mixed") != f.equivalent.end());
    CHECK(f.mechanism_stability >= 0.6);
    CHECK(f.mechanism_stability > f.stability);
    CHECK(d.remaining.find("the main finding's mechanism is certain, its form is not") != std::string::npos);
}

TEST_CASE("a viscosity error on 3 x 3 synth points is named once its rivals pay for their shapes", "[diagnose_verdict]") {
    // A campaign of scripts/independent-campaigns.py (synth_own, FZG seed 0): `gearloss synth` of the
    // shipped FZG box with the oil's viscosity x 1.882, 3 x 3 points, 1.9 % loss noise. The
    // viscosity leads by a delta BIC of 14 over a constant parasitic loss. It won 54 % of 24
    // resamples while a rival with a profiled shape paid a whole parameter or nothing in them;
    // with the shape's prior paid in each resample as in the whole campaign it wins 15 of 24
    // (62.5 %) and is named with confidence, the truth within 5 %. (This campaign exercised the
    // rule that a rival winning a quarter of the resamples is an alternative, not a veto; the
    // rule itself is unchanged.)
    const auto d = diagnose_synth_own(
        "configs/fzg-c40-paor.yaml",
            "640,98.8,104.3362,52.5648,25\n640,265,191.0303,69.1605,25\n640,319.2,210.4097,74.4526,25\n"
            "1320,98.8,206.2222,73.2669,25\n1320,265,359.8527,99.8183,25\n1320,319.2,410.3941,106.5358,25\n"
            "1660,98.8,267.7259,83.6639,25\n1660,265,430.6174,112.4956,25\n1660,319.2,499.1108,121.6962,25\n");
    INFO(d.summary);
    REQUIRE_FALSE(d.findings.empty());
    const auto& f = d.findings.front();
    CHECK(f.effect == "oil_viscosity");
    CHECK(f.parameter.value == Approx(1.882).epsilon(0.05));
    CHECK(f.stability >= 0.6);
    CHECK(d.verdict == "missing_physics");
}
