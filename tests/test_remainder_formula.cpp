// The remainder formula (diagnosis/hypothesis.hpp) on hand-made residuals with a known form,
// the empirical loss term that holds it in a case (mechanisms/empirical_mechanism.hpp), and
// the round trip: diagnose, write the calibrated case, and the written case reproduces the
// recorded loss within the noise.
#include <catch2/catch.hpp>

#include <cmath>
#include <filesystem>
#include <numbers>
#include <random>
#include <string>
#include <vector>

#include "gearloss/diagnosis/diagnose.hpp"
#include "gearloss/diagnosis/hypothesis.hpp"
#include "gearloss/diagnosis/recordings.hpp"
#include "gearloss/diagnosis/synth.hpp"
#include "gearloss/case/config.hpp"
#include "gearloss/case/empirical_config.hpp"
#include "gearloss/mechanisms/empirical_mechanism.hpp"
#include "gearloss/solver/operating_point.hpp"
#include "test_support.hpp"

using namespace gearloss;
using namespace gearloss::diagnosis::hypothesis;

namespace {

struct Campaign {
    std::vector<double> residual, scale;
    Features f;
};

// A 5 x 5 grid, speeds 400-1600 rpm, torques 50-250 N*m, recorded in a shuffled order. The oil
// temperature theta = 50 degC + 0.01 n/rpm + 0.05 T/(N*m) takes 25 distinct values:
//   56.5 59.0 59.5 61.5 62.0 62.5 64.0 64.5 65.0 65.5 66.5 67.0 67.5 68.0 68.5 69.5 70.0 70.5
//   71.0 72.5 73.0 73.5 75.5 76.0 78.5 degC.
// residual = truth(n, T, theta) + Gaussian noise of sigma; scale 100 W everywhere.
template <class Truth>
Campaign grid(std::uint64_t seed, double sigma, Truth truth) {
    std::vector<std::pair<double, double>> ops;
    for (double n : {400.0, 700.0, 1000.0, 1300.0, 1600.0})
        for (double t : {50.0, 100.0, 150.0, 200.0, 250.0}) ops.emplace_back(n, t);
    std::mt19937_64 rng(seed);
    std::shuffle(ops.begin(), ops.end(), rng);
    std::normal_distribution<double> noise(0.0, sigma);
    Campaign c;
    for (const auto& [n, t] : ops) {
        const double theta = 50 + 0.01 * n + 0.05 * t;
        c.f.speed_rpm.push_back(n);
        c.f.torque_Nm.push_back(t);
        c.f.oil_temp_C.push_back(theta);
        c.f.viscosity_cSt.push_back(80 * std::exp(-0.025 * (theta - 40)));
        c.residual.push_back(truth(n, t, theta) + noise(rng));
        c.scale.push_back(100);
    }
    return c;
}

// The exponent of a power of speed in a basis "(n/1000 rpm)^a ...", or NaN.
double speed_exponent(const std::string& basis) {
    const std::string head = "(n/1000 rpm)";
    if (basis.rfind(head, 0) != 0) return std::nan("");
    if (basis.size() == head.size() || basis[head.size()] != '^') return 1.0;
    return std::stod(basis.substr(head.size() + 1));
}

// The transfer box as shipped with one concealed empirical loss term of `coefficient` W times
// `factor` (the truth of a campaign outside the library).
io::Case transfer_box_with(double coefficient, const losses::EmpiricalFactor& factor) {
    auto truth = test_support::load_shipped("configs/transfer-box.yaml");
    auto* emp = dynamic_cast<losses::EmpiricalMechanism*>(truth.model.mechanisms.find("empirical"));
    REQUIRE(emp);
    losses::EmpiricalTerm term;
    term.coefficient = coefficient;
    term.factors = {factor};
    emp->set_terms({term});
    return truth;
}

// The transfer box as shipped diagnosed against recordings synthesised (`synth`, 1.5 % loss
// noise, `seed`) from it with a concealed W (n/1000 rpm)^exponent on the grid speeds x torques
// [rpm, N*m]: an effect outside the library, whose loss also heats the oil.
diagnosis::Diagnosis diagnose_speed_power(double W, double exponent, const std::vector<double>& speeds,
                                          const std::vector<double>& torques, std::uint64_t seed) {
    losses::EmpiricalFactor power;
    power.variable = losses::EmpiricalVariable::speed;
    power.shape = losses::EmpiricalShape::power;
    power.reference = 1000 * std::numbers::pi / 30;
    power.exponent = exponent;
    const auto truth = transfer_box_with(W, power);
    diagnosis::SynthOptions so;
    so.seed = seed;
    const auto rec = diagnosis::read_recordings_text(
        diagnosis::synthesize(truth.model, test_support::rpm_grid(speeds, torques), so), "rec.csv");
    const auto c = test_support::load_shipped("configs/transfer-box.yaml");
    return diagnosis::diagnose(c.model, rec, {});
}

}  // namespace

TEST_CASE("a loss switching on above 70.2 degC is found as the step at the midpoint 70.25 degC", "[remainder]") {
    // Truth: dP = 30 W [theta > 70.2 degC]; the recorded temperatures around it are 70.0 and
    // 70.5 degC, so the step lies at their midpoint, 70.25 degC (8 of 25 points above). Noise 1 W.
    const auto c = grid(3, 1.0, [](double, double, double th) { return th > 70.2 ? 30.0 : 0.0; });
    const Proposal p = propose(c.residual, c.scale, c.f);
    INFO(p.formula);
    REQUIRE(p.found);
    REQUIRE(!p.terms.empty());
    CHECK(p.terms[0].basis == "[theta_oil > 70.25 degC]");
    CHECK(std::fabs(p.terms[0].coefficient - 30) < 3 * p.terms[0].uncertainty + 1);
    // Predicting zero misses 30 W on 8 of 25 points: RMS 30 sqrt(8/25) = 17 W; the formula
    // leaves about the 1 W noise.
    CHECK(p.cv_rmse_before > 15);
    CHECK(p.cv_rmse_after < 2);
}

TEST_CASE("a loss present only in cold oil is found as a step below 63.25 degC", "[remainder]") {
    // Truth: dP = 25 W [theta <= 63 degC]; recorded 62.5 and 64.0 degC around it: midpoint
    // 63.25 degC (6 of 25 points at or below). Noise 1 W. A step up at 63.25 degC with a
    // constant would need two terms; the cold-oil step is one, found first.
    const auto c = grid(4, 1.0, [](double, double, double th) { return th <= 63 ? 25.0 : 0.0; });
    const Proposal p = propose(c.residual, c.scale, c.f);
    INFO(p.formula);
    REQUIRE(p.found);
    CHECK(p.terms[0].basis == "[theta_oil <= 63.25 degC]");
    CHECK(std::fabs(p.terms[0].coefficient - 25) < 3 * p.terms[0].uncertainty + 1);
}

TEST_CASE("a speed power with exponent 1.6 is recovered within 0.3", "[remainder]") {
    // Truth: dP = 8 W (n/1000 rpm)^1.6: 1.8 W at 400 rpm to 17.7 W at 1600 rpm
    // (1.6^1.6 = exp(1.6 ln 1.6) = exp(0.752) = 2.12). Noise 0.3 W. The fixed powers 1, 2, 3
    // miss it by 0.4 or more.
    const auto c = grid(5, 0.3, [](double n, double, double) { return 8.0 * std::pow(n / 1000, 1.6); });
    const Proposal p = propose(c.residual, c.scale, c.f);
    INFO(p.formula);
    REQUIRE(p.found);
    const double a = speed_exponent(p.terms[0].basis);
    CHECK(std::fabs(a - 1.6) <= 0.3);
    CHECK(p.cv_rmse_after < 0.6);
    // Its 95 % interval holds the truth and is narrow at 0.3 W noise on 25 points (a change of
    // 0.1 in the exponent moves the 1600 rpm point by 8 x 2.12 x 0.1 x ln 1.6 = 0.8 W, and the
    // 400 rpm point the other way, relative to a fit through the middle).
    CHECK(p.terms[0].exponent_low <= 1.6 + 1e-9);
    CHECK(p.terms[0].exponent_high >= 1.6 - 1e-9);
    CHECK(p.terms[0].exponent_high - p.terms[0].exponent_low <= 0.45);
}

TEST_CASE("a speed-squared loss gated by the oil temperature is one gated term", "[remainder]") {
    // Truth: dP = 20 W (n/1000 rpm)^2 [theta > 70.2 degC] (a bypass opening in hot oil, its
    // loss growing with speed): at the 8 points above 70.25 degC, 20 (1.6)^2 = 51 W at
    // 1600 rpm down to 20 W at 1000 rpm. Noise 1 W.
    const auto c = grid(6, 1.0, [](double n, double, double th) { return th > 70.2 ? 20.0 * (n / 1000) * (n / 1000) : 0.0; });
    const Proposal p = propose(c.residual, c.scale, c.f);
    INFO(p.formula);
    REQUIRE(p.found);
    CHECK(p.terms[0].basis == "(n/1000 rpm)^2 [theta_oil > 70.25 degC]");
    CHECK(std::fabs(p.terms[0].coefficient - 20) < 3 * p.terms[0].uncertainty + 0.5);
}

TEST_CASE("the terms carry their form for the report and a calibration term", "[remainder]") {
    // The gated case above: shape power of speed, exponent 2, gate above 70.25 degC; the
    // calibration term evaluates to the basis: at 1600 rpm and 75 degC, (1.6)^2 = 2.56.
    const auto c = grid(6, 1.0, [](double n, double, double th) { return th > 70.2 ? 20.0 * (n / 1000) * (n / 1000) : 0.0; });
    const Proposal p = propose(c.residual, c.scale, c.f);
    REQUIRE(p.found);
    const Term& t = p.terms[0];
    CHECK(t.shape == "power");
    CHECK(t.variable == "speed_rpm");
    CHECK(t.exponent == Approx(2.0));
    REQUIRE(t.gate);
    CHECK(t.gate->variable == "oil_temp_C");
    CHECK(t.gate->threshold == Approx(70.25));
    REQUIRE(t.empirical);
    losses::EmpiricalTerm e = *t.empirical;
    e.coefficient = 1;
    const double w1600 = 1600 * std::numbers::pi / 30;
    CHECK(e.basis(w1600, 100, 273.15 + 75, 50e-6) == Approx(2.56));
    CHECK(e.basis(w1600, 100, 273.15 + 70, 50e-6) == 0.0);
}

TEST_CASE("empirical terms are read with their units and evaluated by the mechanism", "[remainder]") {
    // 40 W [theta > 80 degC] + 5 W (n/1000 rpm)^2 + 2 W max(0, T - 100 N*m)/(50 N*m)
    // + 3 W max(0, theta - 85 degC)/(10 K):
    // at 1500 rpm, 200 N*m, 90 degC: 40 + 5 x 2.25 + 2 x 2 + 3 x 0.5 = 56.75 W; at 70 degC: 15.25 W.
    const auto doc = io::YamlNode::load_text(R"(terms:
  - {coefficient: 40 W, factors: [{variable: oil_temperature, shape: step, above: 80 degC}]}
  - {coefficient: 5 W, factors: [{variable: speed, shape: power, reference: 1000 rpm, exponent: 2}]}
  - {coefficient: 2 W, factors: [{variable: torque, shape: threshold, above: 100 N*m, reference: 50 N*m}]}
  - {coefficient: 3 W, factors: [{variable: oil_temperature, shape: threshold, above: 85 degC, reference: 10 K}]}
)",
                                             "terms.yaml");
    const auto terms = io::read_empirical_terms(doc.at("terms"));
    REQUIRE(terms.size() == 4);
    const double w = 1500 * std::numbers::pi / 30;
    double hot = 0, cold = 0;
    for (const auto& t : terms) {
        hot += t.coefficient * t.basis(w, 200, 273.15 + 90, 30e-6);
        cold += t.coefficient * t.basis(w, 200, 273.15 + 70, 60e-6);
    }
    CHECK(hot == Approx(56.75));
    CHECK(cold == Approx(15.25));
    // Written and read again: the same terms.
    YAML::Node root;
    root["terms"] = io::empirical_terms_yaml(terms);
    YAML::Emitter em;
    em << root;
    const auto again = io::read_empirical_terms(io::YamlNode::load_text(em.c_str(), "again.yaml").at("terms"));
    REQUIRE(again.size() == 4);
    double hot2 = 0;
    for (const auto& t : again) hot2 += t.coefficient * t.basis(w, 200, 273.15 + 90, 30e-6);
    CHECK(hot2 == Approx(56.75).epsilon(1e-5));
}

TEST_CASE("a bad empirical term names its key", "[remainder]") {
    auto fails = [](const std::string& yaml, const std::string& part) {
        INFO(yaml);
        const auto doc = io::YamlNode::load_text(yaml, "bad.yaml");
        CHECK_THROWS_WITH(io::read_empirical_terms(doc.at("terms")), Catch::Contains(part));
    };
    fails("terms: [{coefficient: 4 W, factors: [{variable: pressure, shape: step, above: 3 bar}]}]", "variable");
    fails("terms: [{coefficient: 4 W, factors: [{variable: speed, shape: step, above: 30 degC}]}]", "above");
    fails("terms: [{coefficient: 4, factors: []}]", "coefficient");
    fails("terms: [{coefficient: 4 W, factors: [{variable: speed, shape: step}]}]", "above");
    fails("terms: [{coefficient: 4 W, factors: [{variable: torque, shape: window, lower: 90 N*m, upper: 50 N*m}]}]", "upper");
    fails("terms: [{coefficient: 4 W, factors: [{variable: oil_temperature, shape: threshold, above: 80 degC, reference: 10 degC}]}]",
          "temperature difference");
    fails("terms: [{coefficient: 4 W, factors: [{variable: oil_temperature, shape: power, reference: 10 K, exponent: 2}]}]",
          "power of the oil temperature");
}

TEST_CASE("the written calibration reproduces recordings with a hot-oil loss within the noise", "[remainder]") {
    // Truth: the transfer box with an extra 40 W once the oil is above 70 degC, no candidate of
    // the library (a step in oil temperature), synthesised by the coupled model (the extra
    // loss heats the oil), 1.5 % loss noise. Diagnosed against the case without it, the
    // calibrated case written, reloaded and evaluated at the recorded points: its loss RMSE
    // is within 1.5 x the noise RMS (0.015 x the RMS recorded loss).
    losses::EmpiricalFactor hot;
    hot.variable = losses::EmpiricalVariable::oil_temperature;
    hot.shape = losses::EmpiricalShape::step;
    hot.threshold = 273.15 + 70;
    const auto truth = transfer_box_with(40, hot);
    diagnosis::SynthOptions so;
    so.seed = 7;
    const auto rec = diagnosis::read_recordings_text(
        diagnosis::synthesize(truth.model, test_support::rpm_grid({500, 600, 700, 800, 900}, {100, 150, 200, 250}), so), "rec.csv");
    const auto c = test_support::load_shipped("configs/transfer-box.yaml");
    diagnosis::DiagnoseOptions opt;
    opt.loss_uncertainty = so.noise_loss;
    opt.temp_uncertainty = so.noise_temp;
    const auto d = diagnosis::diagnose(c.model, rec, opt);
    INFO(diagnosis::diagnosis_text(d));
    REQUIRE(d.remainder);
    const std::string out = (std::filesystem::temp_directory_path() / "gearloss-remainder-roundtrip.yaml").string();
    diagnosis::write_calibrated_config(test_support::source_path("configs/transfer-box.yaml"), out, d);
    const auto c2 = io::load_case(out);
    std::filesystem::remove(out);
    const auto d2 = diagnosis::diagnose(c2.model, rec, opt);
    double ss = 0;
    for (const auto& p : rec.points) ss += p.loss * p.loss;
    const double noise_rms = so.noise_loss * std::sqrt(ss / static_cast<double>(rec.points.size()));
    INFO(diagnosis::diagnosis_text(d2));
    CHECK(d2.rmse_before <= 1.5 * noise_rms);
    CHECK(d.rmse_before > 3 * noise_rms);  // the effect was there to model
}

TEST_CASE("windage standing in for a fourth power of speed on 12 points is not named with confidence", "[remainder]") {
    // Truth: the transfer box with 54 W (n/1000 rpm)^4, outside the library (its windage goes
    // as n^2.9), synthesised by the coupled model on a 4 x 3 grid (400-1200 rpm, 200-300 N*m),
    // 1.5 % loss noise, seed 1. Windage (and, before the prior on a scale factor below nominal,
    // a second finding) fits part of it, but one power of speed predicts better under cross-
    // validation and leaves no structure: the verdict must not be a
    // confident missing_physics, the formula must carry a power of speed whose 95 % exponent
    // interval holds 4 (12 points at 12 W noise do not fix the exponent to 0.3: at 880 rpm
    // n^4 and n^4.7 scaled to agree at 1200 rpm differ by 6 W), and the summary must say why
    // (not "the main finding is confident").
    const auto d = diagnose_speed_power(54, 4, {400, 720, 880, 1200}, {200, 250, 300}, 1);
    INFO(diagnosis::diagnosis_text(d));
    CHECK(d.verdict == "partly_explained");
    CHECK(d.main_finding.confidence == "tentative");
    CHECK(!d.remaining_structure);
    REQUIRE(d.remainder);
    REQUIRE(!d.remainder->terms.empty());
    const auto& t = d.remainder->terms[0];
    CHECK(t.variable == "speed_rpm");
    CHECK(t.exponent_low <= 4.0 + 1e-9);
    CHECK(t.exponent_high >= 4.0 - 1e-9);
    CHECK(t.exponent_high - t.exponent_low <= 1.5);
    CHECK(d.summary.find("partial explanations, not the cause of the whole mismatch") != std::string::npos);
    CHECK(d.summary.find("predicts the recordings better than the findings") != std::string::npos);
    CHECK(d.summary.find("The main finding is confident") == std::string::npos);
    CHECK(d.summary.find(": .") == std::string::npos);
}

TEST_CASE("a speed power with exponent 4.4 beyond windage's is recovered within 0.3", "[remainder]") {
    // Truth: dP = 3 W (n/1000 rpm)^4.4: 0.53 W at 400 rpm (0.4^4.4 = exp(4.4 ln 0.4) =
    // exp(-4.03) = 0.0177) to 23.6 W at 1600 rpm (1.6^4.4 = exp(4.4 x 0.470) = 7.88). Noise
    // 0.3 W. A grid of exponents ending at 4 misses it by 0.4.
    const auto c = grid(8, 0.3, [](double n, double, double) { return 3.0 * std::pow(n / 1000, 4.4); });
    const Proposal p = propose(c.residual, c.scale, c.f);
    INFO(p.formula);
    REQUIRE(p.found);
    CHECK(std::fabs(speed_exponent(p.terms[0].basis) - 4.4) <= 0.3);
}

TEST_CASE("a running-in share of the loss fading along the run order is a relative order term", "[remainder]") {
    // Truth: the first runs lose 25 % more than the model, fading as exp(-k/6) along the run
    // order k = 0..24 (a running-in), on a model loss that grows with speed and load:
    // P_model = 50 W + 0.2 W n T / (1000 rpm N*m) = 54 W at 400 rpm, 50 N*m to 130 W at
    // 1600 rpm, 250 N*m. Recorded in a shuffled order of the operating points (the grid), so the
    // decay is not a law of speed or load. Noise 0.5 W. The term found must be along the order,
    // in proportion to the model's loss, with a share of 0.25 +- 0.05 and a decay of 6 +- 3 runs
    // (the candidates' decays are 0.1 to 0.6 x 25 points = 2.5 to 15 runs).
    auto c = grid(9, 0.0, [](double, double, double) { return 0.0; });
    std::mt19937_64 rng(1009);  // not the grid's seed: its draws made the shuffle
    std::normal_distribution<double> noise(0.0, 0.5);
    for (std::size_t k = 0; k < c.residual.size(); ++k) {
        const double model = 50 + 0.2 * c.f.speed_rpm[k] * c.f.torque_Nm[k] / 1000;
        c.f.order.push_back(static_cast<double>(k + 1));
        c.f.model_loss_W.push_back(model);
        c.residual[k] = 0.25 * std::exp(-static_cast<double>(k) / 6) * model + noise(rng);
    }
    const Proposal p = propose(c.residual, c.scale, c.f);
    INFO(p.formula);
    REQUIRE(p.found);
    REQUIRE(!p.terms.empty());
    CHECK(p.terms[0].variable == "order");
    CHECK(p.terms[0].relative);
    CHECK(std::fabs(p.terms[0].coefficient - 0.25) <= 0.05);
    const std::string b = p.terms[0].basis;  // "exp(-k/7.5) P_model"
    REQUIRE(b.rfind("exp(-k/", 0) == 0);
    CHECK(std::fabs(std::stod(b.substr(7)) - 6) <= 3);
}

TEST_CASE("a constant parasitic loss plus a seal friction standing in for n^0.5 is not named with confidence", "[remainder]") {
    // Truth: the transfer box with 60 W (n/1000 rpm)^0.5, outside the library (no mechanism
    // goes as the square root of speed), synthesised by the coupled model on a 5 x 4 grid
    // (400-1200 rpm, 150-300 N*m), 1.5 % loss noise, seed 2. Over 400-1200 rpm a constant plus
    // a term in n fit a square root within the noise (sqrt(x) against its chord through 0.4
    // and 1.2: at most 0.03 of 1.1, below the 1.5 % noise), so two findings fit it; one power of
    // speed with one term is the simpler account predicting as well. The verdict must not be a
    // confident missing_physics, and the formula must carry the exponent 0.5 +- 0.3.
    const auto d = diagnose_speed_power(60, 0.5, {400, 600, 800, 1000, 1200}, {150, 200, 250, 300}, 2);
    INFO(diagnosis::diagnosis_text(d));
    CHECK(d.verdict != "missing_physics");
    REQUIRE(d.remainder);
    REQUIRE(!d.remainder->terms.empty());
    CHECK(std::fabs(speed_exponent(d.remainder->terms[0].basis) - 0.5) <= 0.3);
}
