// The remainder hypothesis (diagnosis/hypothesis.hpp) against residuals built from a known
// formula plus known noise: the truth is the construction, written next to each campaign.
#include <catch2/catch.hpp>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <limits>
#include <numeric>
#include <random>
#include <stdexcept>
#include <string>
#include <vector>

#include "gearloss/diagnosis/hypothesis.hpp"

using namespace gearloss::diagnosis::hypothesis;

namespace {

const std::vector<double> speeds = {400, 700, 1000, 1300, 1600};  // rpm; levels midway: 550, 850, 1150, 1450
const std::vector<double> torques = {50, 100, 150, 200, 250};     // N m; T_max = 250

struct Campaign {
    std::vector<double> residual, scale;
    Features f;
};

bool contains(const std::vector<std::string>& v, const std::string& part) {
    return std::any_of(v.begin(), v.end(), [&](const std::string& s) { return s.find(part) != std::string::npos; });
}

// A 5 x 5 grid (each operating point `copies` times) recorded in a shuffled order, order = row
// number. The oil warms with speed, load and over the run, as on a rig; the viscosity follows.
// residual = truth(speed, torque, row) + Gaussian noise of sigma; scale 100 W everywhere.
template <class Truth>
Campaign grid(std::uint64_t seed, double sigma, Truth truth, int copies = 1) {
    std::vector<std::pair<double, double>> ops;
    for (int c = 0; c < copies; ++c)
        for (double n : speeds)
            for (double t : torques) ops.emplace_back(n, t);
    std::mt19937_64 rng(seed);
    std::shuffle(ops.begin(), ops.end(), rng);
    std::normal_distribution<double> noise(0.0, sigma);
    Campaign c;
    for (std::size_t k = 0; k < ops.size(); ++k) {
        const auto [n, t] = ops[k];
        const double theta = 50 + 0.01 * n + 0.05 * t + 5 * (1 - std::exp(-static_cast<double>(k) / 10));
        c.f.speed_rpm.push_back(n);
        c.f.torque_Nm.push_back(t);
        c.f.oil_temp_C.push_back(theta);
        c.f.viscosity_cSt.push_back(80 * std::exp(-0.025 * (theta - 40)));
        c.f.order.push_back(static_cast<double>(k));
        c.residual.push_back(truth(n, t, static_cast<double>(k)) + noise(rng));
        c.scale.push_back(100);
    }
    return c;
}

const Term* find_term(const Proposal& p, const std::string& basis) {
    for (const auto& t : p.terms)
        if (t.basis == basis) return &t;
    return nullptr;
}

}  // namespace

TEST_CASE("a speed step of 40 W above 1100 rpm is found as the step between 1000 and 1300 rpm", "[hypothesis]") {
    // Truth: dP = 40 W [n > 1100 rpm]; the recorded levels around it are 1000 and 1300 rpm,
    // so the library's step is at their midpoint, 1150 rpm. Noise 2 W.
    const auto c = grid(11, 2.0, [](double n, double, double) { return n > 1100 ? 40.0 : 0.0; });
    const Proposal p = propose(c.residual, c.scale, c.f);
    INFO(p.formula);
    REQUIRE(p.found);
    REQUIRE(!p.terms.empty());
    CHECK(p.terms[0].basis == "[n > 1150 rpm]");
    CHECK(p.terms[0].uncertainty > 0);
    CHECK(std::fabs(p.terms[0].coefficient - 40) < 3 * p.terms[0].uncertainty);
    CHECK(contains(p.nearest, "switches on above a speed"));
    CHECK(p.formula.rfind("dP = ", 0) == 0);
    CHECK(p.formula.find('-') == std::string::npos);  // a positive coefficient, no sign
    CHECK(p.formula.find(" W [n > 1150 rpm]") != std::string::npos);
    // Predicting zero misses 40 W on 10 of 25 points: RMS 40 sqrt(10/25) = 25.3 W; the formula
    // leaves the 2 W noise (plus what the fold fits add).
    CHECK(p.cv_rmse_before > 20);
    CHECK(p.cv_rmse_after < 4);
}

TEST_CASE("the step is found first over 50 noise draws, its coefficient within 3 SE", "[hypothesis]") {
    // Truth: dP = 40 W [n > 1100 rpm], noise 2 W, 50 seeds. Within 3 standard errors holds
    // for 99.7 % of draws if the error bars are right; allow 5 misses of 50.
    int first = 0, covered = 0;
    for (std::uint64_t s = 0; s < 50; ++s) {
        const auto c = grid(5000 + s, 2.0, [](double n, double, double) { return n > 1100 ? 40.0 : 0.0; });
        const Proposal p = propose(c.residual, c.scale, c.f);
        if (p.found && p.terms[0].basis == "[n > 1150 rpm]") {
            ++first;
            covered += std::fabs(p.terms[0].coefficient - 40) < 3 * p.terms[0].uncertainty ? 1 : 0;
        }
    }
    CHECK(first == 50);
    CHECK(covered >= 45);
}

TEST_CASE("a negative step is written with its sign", "[hypothesis]") {
    // Truth: dP = -40 W [n > 1100 rpm] (a loss the model over-predicts above the step).
    const auto c = grid(12, 2.0, [](double n, double, double) { return n > 1100 ? -40.0 : 0.0; });
    const Proposal p = propose(c.residual, c.scale, c.f);
    INFO(p.formula);
    REQUIRE(p.found);
    CHECK(p.terms[0].basis == "[n > 1150 rpm]");
    CHECK(p.formula.rfind("dP = -", 0) == 0);
    CHECK(p.terms[0].coefficient < 0);
}

namespace {
// The first term is `basis`, its coefficient within 20 % of `truth`, and `nearest` names `physics`.
void check_first_term(const Proposal& p, const std::string& basis, double truth, const std::string& physics) {
    INFO(p.formula);
    REQUIRE(p.found);
    CHECK(p.terms[0].basis == basis);
    const Term* t = find_term(p, basis);
    REQUIRE(t != nullptr);
    CHECK(std::fabs(t->coefficient - truth) < 0.2 * std::fabs(truth));
    CHECK(contains(p.nearest, physics));
}
}  // namespace

TEST_CASE("a T^2 band at one speed level is recovered within 20 %", "[hypothesis]") {
    // Truth: dP = 30 W (T_in/250 N*m)^2 at 1000 rpm only (a resonance), noise 1 W.
    const auto c = grid(21, 1.0, [](double n, double t, double) { return n == 1000 ? 30.0 * (t / 250) * (t / 250) : 0.0; });
    check_first_term(propose(c.residual, c.scale, c.f), "(T_in/250 N*m)^2 [n = 1000 rpm]", 30, "resonance");
}

TEST_CASE("running-in over the run order is found as a run-order term", "[hypothesis]") {
    // Truth: dP = 30 W exp(-k/5) over the row number k of 25 rows (tau = 0.2 N), the operating
    // points shuffled so the decay is no law of speed or load. Noise 1 W.
    // The decays searched are 0.08-0.6 N on a grid 0.03-0.1 N apart (0.18, 0.2, 0.21 N = 4.5, 5,
    // 5.25 rows around the truth): the one found within one grid step of 5 rows, 4 to 6 rows.
    const auto c = grid(31, 1.0, [](double, double, double k) { return 30.0 * std::exp(-k / 5); });
    const Proposal p = propose(c.residual, c.scale, c.f);
    INFO(p.formula);
    REQUIRE(p.found);
    const std::string b = p.terms[0].basis;
    REQUIRE(b.rfind("exp(-k/", 0) == 0);
    CHECK(p.terms[0].variable == "order");
    CHECK(std::fabs(std::stod(b.substr(7)) - 5) <= 1.0);
    CHECK(std::fabs(p.terms[0].coefficient - 30) < 0.2 * 30);
    CHECK(contains(p.nearest, "running-in"));
}

TEST_CASE("a windage-like 5 W (n/1000)^3 is found as a speed power", "[hypothesis]") {
    // Truth: dP = 5 W (n/1000 rpm)^3, 0.3 W at 400 rpm to 20.5 W at 1600 rpm; noise 0.3 W.
    const auto c = grid(41, 0.3, [](double n, double, double) { return 5.0 * std::pow(n / 1000, 3); });
    const Proposal p = propose(c.residual, c.scale, c.f);
    INFO(p.formula);
    REQUIRE(p.found);
    // The exponent is searched on a grid of 0.1: within 0.3 of the truth, as the issue asks.
    CHECK(p.terms[0].basis.rfind("(n/1000 rpm)^", 0) == 0);
    CHECK(p.terms[0].variable == "speed_rpm");
    CHECK(std::fabs(p.terms[0].exponent - 3) <= 0.3);
    // The coefficient trades against the exponent: at the mid speed 1000 rpm the term is the
    // coefficient itself, 5 W within 10 %.
    CHECK(std::fabs(p.terms[0].coefficient - 5) < 0.5);
    CHECK(contains(p.nearest, "windage"));
}

TEST_CASE("pure noise is found in at most 10 % of 100 campaigns", "[hypothesis]") {
    // Truth: dP = 0, noise 2 W. A proposal on noise is a false alarm.
    int found = 0;
    for (std::uint64_t s = 0; s < 100; ++s) {
        const auto c = grid(1000 + s, 2.0, [](double, double, double) { return 0.0; });
        found += propose(c.residual, c.scale, c.f).found ? 1 : 0;
    }
    INFO("found in " << found << " of 100");
    CHECK(found <= 10);
}

TEST_CASE("too few points, zero residuals, bad sizes and non-finite input", "[hypothesis]") {
    Features f5;
    f5.speed_rpm = {400, 700, 1000, 1300, 1600};
    const std::vector<double> r5 = {0, 0, 40, 40, 40}, s5(5, 100.0);
    CHECK_FALSE(propose(r5, s5, f5).found);  // n = 5 < 6
    CHECK_FALSE(propose({}, {}, Features{}).found);

    auto c = grid(51, 2.0, [](double n, double, double) { return n > 1100 ? 40.0 : 0.0; });
    std::vector<double> zero(c.residual.size(), 0.0);
    CHECK_FALSE(propose(zero, c.scale, c.f).found);

    auto short_scale = c.scale;
    short_scale.pop_back();
    CHECK_THROWS_AS(propose(c.residual, short_scale, c.f), std::invalid_argument);
    auto bad_feature = c.f;
    bad_feature.oil_temp_C.pop_back();
    CHECK_THROWS_AS(propose(c.residual, c.scale, bad_feature), std::invalid_argument);
    auto nan_residual = c.residual;
    nan_residual[3] = std::numeric_limits<double>::quiet_NaN();
    CHECK_THROWS_AS(propose(nan_residual, c.scale, c.f), std::invalid_argument);
    auto inf_speed = c.f;
    inf_speed.speed_rpm[2] = std::numeric_limits<double>::infinity();
    CHECK_THROWS_AS(propose(c.residual, c.scale, inf_speed), std::invalid_argument);
    auto zero_scale = c.scale;
    zero_scale[0] = 0;
    CHECK_THROWS_AS(propose(c.residual, zero_scale, c.f), std::invalid_argument);
}

TEST_CASE("absent optional features are accepted", "[hypothesis]") {
    // Truth: the 40 W step of the first case; only the speed is given.
    auto c = grid(61, 2.0, [](double n, double, double) { return n > 1100 ? 40.0 : 0.0; });
    Features only_speed;
    only_speed.speed_rpm = c.f.speed_rpm;
    const Proposal p = propose(c.residual, c.scale, only_speed);
    INFO(p.formula);
    REQUIRE(p.found);
    CHECK(p.terms[0].basis == "[n > 1150 rpm]");
    // No feature at all: only the constant is available, and a step is no constant.
    const Proposal none = propose(c.residual, c.scale, Features{});
    for (const auto& t : none.terms) CHECK(t.basis == "1");
}

TEST_CASE("the same seed gives the same proposal", "[hypothesis]") {
    const auto c = grid(71, 2.0, [](double n, double t, double) { return 3.0 * n / 1000 + 10 * (t / 250); });
    const Proposal a = propose(c.residual, c.scale, c.f, 3, 7);
    const Proposal b = propose(c.residual, c.scale, c.f, 3, 7);
    CHECK(a.formula == b.formula);
    CHECK(a.cv_rmse_after == b.cv_rmse_after);
    CHECK(static_cast<int>(a.terms.size()) <= 3);
}

TEST_CASE("1000 points take well under a second", "[hypothesis]") {
    // Truth: the 40 W step on a grid repeated 40 times (1000 points), noise 2 W.
    const auto c = grid(81, 2.0, [](double n, double, double) { return n > 1100 ? 40.0 : 0.0; }, 40);
    REQUIRE(c.residual.size() == 1000);
    const auto t0 = std::chrono::steady_clock::now();
    const Proposal p = propose(c.residual, c.scale, c.f);
    const double s = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    INFO("1000 points in " << s << " s; " << p.formula);
    CHECK(s < 0.5);
    REQUIRE(p.found);
    CHECK(p.terms[0].basis == "[n > 1150 rpm]");
}

TEST_CASE("a viscous drag is found as a power of the viscosity, not a threshold of the oil temperature", "[hypothesis]") {
    // Truth: dP = 20 W (nu/100 cSt)^1.2, an oil of 220 cSt at 40 degC, nu = 220 exp(-0.03 (theta
    // - 40 degC)) cSt, the oil at theta = 30 degC + 0.03 n/rpm + 0.12 T/(N*m): 48-108 degC,
    // nu 173-29 cSt, dP 39-2.4 W; noise 5 W; 100 draws. Hinges of the oil temperature and of the
    // viscosity (hundreds of locations) come close to a power over such a range; the power, with
    // no location to choose, is the form when it predicts within one standard error of them. The
    // exponent is searched on a grid of 0.1 and is scored within 0.3 of the truth, as the issue
    // asks. Before that preference: a viscosity power first in 84 and within 0.3 in 76 of the 100.
    int first = 0, within = 0;
    for (std::uint64_t s = 0; s < 100; ++s) {
        auto c = grid(7000 + s, 0.0, [](double, double, double) { return 0.0; });
        std::mt19937_64 rng(s);
        std::normal_distribution<double> noise(0.0, 5.0);
        for (std::size_t i = 0; i < c.residual.size(); ++i) {
            const double theta = 30 + 0.03 * c.f.speed_rpm[i] + 0.12 * c.f.torque_Nm[i];
            c.f.oil_temp_C[i] = theta;
            c.f.viscosity_cSt[i] = 220 * std::exp(-0.03 * (theta - 40));
            c.residual[i] = 20.0 * std::pow(c.f.viscosity_cSt[i] / 100, 1.2) + noise(rng);
        }
        const Proposal p = propose(c.residual, c.scale, c.f);
        if (p.found && p.terms[0].variable == "viscosity_cSt" && p.terms[0].shape == "power") {
            ++first;
            within += std::fabs(p.terms[0].exponent - 1.2) <= 0.3;
        } else {
            UNSCOPED_INFO(p.formula);
        }
    }
    CHECK(first >= 92);
    CHECK(within >= 85);
}
