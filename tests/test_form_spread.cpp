// Model-form spread (map --spread): the extremes it reports are reproduced by loading the
// case with those forms written into its YAML (the loader's route, not the spread's), the
// nominal lies between them, and the combinations are the full cartesian product.
#include <catch2/catch.hpp>
#include <cmath>
#include <numbers>
#include <map>
#include <nlohmann/json.hpp>
#include <set>

#include "gearloss/core/errors.hpp"
#include "gearloss/case/config.hpp"
#include "gearloss/map/form_spread.hpp"
#include "gearloss/model/validate.hpp"
#include "gearloss/solver/operating_point.hpp"
#include "test_support.hpp"

using namespace gearloss;
namespace {
constexpr double kRpm = std::numbers::pi / 30;

io::Case load_text(const std::string& text) {
    test_support::TempConfig cfg(text);
    return io::load_case(cfg.path);
}

// The case's text with the forms of a combination label ("mesh.friction=iso_6336_20;
// windage.form=free_disk") written as YAML, as a user would.
std::string with_forms(const std::string& base, const std::string& label) {
    if (label == "nominal") return base;
    std::map<std::string, std::vector<std::string>> by_mechanism;
    size_t a = 0;
    while (a < label.size()) {
        const size_t e = std::min(label.find(';', a), label.size());
        const std::string item = label.substr(a, e - a);
        const size_t dot = item.find('.'), eq = item.find('=');
        by_mechanism[item.substr(0, dot)].push_back(item.substr(dot + 1, eq - dot - 1) + ": " + item.substr(eq + 1));
        a = e + 1;
    }
    std::string yaml = "\nmechanisms:\n";
    for (const auto& [mech, settings] : by_mechanism) {
        yaml += "  " + mech + ": {";
        for (size_t i = 0; i < settings.size(); ++i) yaml += (i ? ", " : "") + settings[i];
        yaml += "}\n";
    }
    return base + yaml;
}
}  // namespace

TEST_CASE("form spread: the extremes are the losses of the cases written with those forms", "[spread]") {
    const std::string base = test_support::read_file(test_support::source_path("configs/transfer-box.yaml"));
    const auto c = load_text(base);
    const auto axes = map::spread_axes(c.model, {});
    // Every axis of every mechanism with alternatives: mesh friction (5), H_V (3), film (3),
    // churning (3), windage (3).
    std::set<std::string> labels;
    for (const auto& a : axes) labels.insert(a.label());
    CHECK(labels == std::set<std::string>{"mesh.friction", "mesh.loss_factor", "mesh.film_correction", "churning.form",
                                          "windage.form"});
    CHECK(map::combination_count(axes) == 5 * 3 * 3 * 3 * 3);
    // Every combination is a distinct choice of forms.
    std::set<std::string> seen;
    for (size_t i = 0; i < map::combination_count(axes); ++i) seen.insert(map::combination_label(axes, i));
    CHECK(seen.size() == 405);
    CHECK(seen.count("nominal") == 1);

    io::OperatingGrid grid;
    grid.is_grid = true;
    grid.speeds = {800 * kRpm, 2500 * kRpm};
    grid.torques = {120, 280};
    map::MapOptions opt;
    opt.threads = 1;
    const auto nominal = map::run_map(c.model, grid, opt);
    const auto result = map::run_spread(c.model, grid, axes, opt);
    CHECK(result.not_applicable.empty());  // every form holds for the transfer box (eps_alpha 1.32..1.49)
    const auto& spread = result.points;
    REQUIRE(spread.size() == grid.size());
    for (size_t p = 0; p < grid.size(); ++p) {
        const auto [w, T] = grid.at(p);
        INFO("point " << p);
        const auto& s = spread[p];
        CHECK(s.solved + s.unsolved == 405);
        REQUIRE(s.solved > 0);
        CHECK(s.P_min <= s.P_max);
        if (solver::has_values(nominal[p].status)) {
            CHECK(s.P_min <= nominal[p].losses.total());
            CHECK(nominal[p].losses.total() <= s.P_max);
        }
        // Re-solve the two extremes from YAML: the same total to the last bit.
        for (auto [at, P] : {std::pair{s.at_min, s.P_min}, std::pair{s.at_max, s.P_max}}) {
            const std::string label = map::combination_label(axes, at);
            INFO(label);
            const auto k = load_text(with_forms(base, label));
            const auto r = solver::solve_point(k.model, w, T, false);
            REQUIRE(solver::has_values(r.status));
            CHECK(r.losses.total() == P);
        }
    }
}

TEST_CASE("form spread: windage forms alone, at a fixed oil temperature, add exactly the windage", "[spread]") {
    // With the oil temperature fixed no other loss depends on the windage form, so the spread
    // is [nominal (form none), nominal + the largest windage of the other forms].
    const std::string text = test_support::read_file(test_support::source_path("configs/transfer-box.yaml"));
    const auto c0 = load_text(text);
    auto fixed = c0.model;
    fixed.thermal.mode = solver::ThermalMode::fixed;
    fixed.thermal.oil_temperature = 273.15 + 70;
    const auto axes = map::spread_axes(fixed, {"windage.form"});
    REQUIRE(axes.size() == 1);
    CHECK(map::combination_count(axes) == 3);
    io::OperatingGrid grid;
    grid.is_grid = true;
    grid.speeds = {3000 * kRpm};
    grid.torques = {150};
    map::MapOptions opt;
    opt.threads = 1;
    const auto s = map::run_spread(fixed, grid, axes, opt).points[0];
    const auto nominal = solver::solve_point(fixed, grid.speeds[0], 150, false);
    REQUIRE(solver::has_values(nominal.status));
    CHECK(s.P_min == nominal.losses.total());
    CHECK(map::combination_label(axes, s.at_min) == "nominal");
    const size_t k = fixed.mechanisms.index("windage");
    double largest = 0;
    for (const char* form : {"anderson_loewenthal", "free_disk"}) {
        auto m = fixed;
        m.mechanisms[k].set_form(m, "form", form);
        largest = std::max(largest, solver::solve_point(m, grid.speeds[0], 150, false).losses.power[k]);
    }
    REQUIRE(largest > 0);
    CHECK(s.P_max == Approx(nominal.losses.total() + largest).epsilon(1e-12));
}

TEST_CASE("form spread: unknown axes are errors naming the option and the known axes", "[spread]") {
    const auto c = load_text(test_support::read_file(test_support::source_path("configs/transfer-box.yaml")));
    try {
        map::spread_axes(c.model, {"mesh.frictoin"});
        FAIL("no error");
    } catch (const InputError& e) {
        CHECK(e.key == "--spread-axes");
        CHECK(e.message.find("mesh.frictoin") != std::string::npos);
        CHECK(e.message.find("mesh.friction") != std::string::npos);
    }
    // A repeated axis counts once.
    CHECK(map::spread_axes(c.model, {"windage.form", "windage.form"}).size() == 1);
}

TEST_CASE("form spread: combinations whose forms do not apply to the case are left out, not unsolved", "[spread]") {
    // eps_alpha = 2.086 (hand calculation in the file): Ohlendorf's and Buckingham's H_V do not
    // apply, Wimmer's (the case's) does.
    const std::string text = test_support::read_file(test_support::source_path("tests/high-contact-ratio.yaml"));
    const auto c = load_text(text);
    REQUIRE(c.model.layout.meshes.at(0).geom.eps_alpha == Approx(2.0862).epsilon(1e-4));
    REQUIRE(solver::validate(c.model).empty());
    // The loader refuses the same case with a closed form, at the line that chose it.
    const std::string ohlendorf = test_support::replace_once(text, "gear_loss_factor: wimmer", "gear_loss_factor: ohlendorf");
    try {
        (void)load_text(ohlendorf);
        FAIL("no error");
    } catch (const InputError& e) {
        CHECK(e.key == "options.gear_loss_factor");
        CHECK(e.line == test_support::line_of(ohlendorf, "gear_loss_factor: ohlendorf"));
        CHECK_THAT(e.message, Catch::Contains("mesh 'm' has eps_alpha = 2.086"));
    }

    const auto axes = map::spread_axes(c.model, {});
    const size_t n = map::combination_count(axes);
    REQUIRE(n == 405);
    // The combinations that do not apply: those with a closed-form H_V, 2 of the 3 forms.
    std::set<size_t> closed_form;
    for (size_t i = 0; i < n; ++i) {
        const std::string label = map::combination_label(axes, i);
        if (label.find("mesh.loss_factor=ohlendorf") != std::string::npos ||
            label.find("mesh.loss_factor=buckingham") != std::string::npos)
            closed_form.insert(i);
    }
    REQUIRE(closed_form.size() == 270);

    io::OperatingGrid grid;
    grid.is_grid = true;
    grid.speeds = {1000 * kRpm, 3000 * kRpm};
    grid.torques = {100};
    map::MapOptions opt;
    opt.threads = 1;
    const auto nominal = map::run_map(c.model, grid, opt);
    const auto spread = map::run_spread(c.model, grid, axes, opt);  // does not throw
    std::set<size_t> skipped;
    for (const auto& s : spread.not_applicable) {
        skipped.insert(s.combination);
        CHECK_THAT(s.reason, Catch::Contains("mesh 'm' has eps_alpha = 2.086"));
    }
    CHECK(skipped == closed_form);
    CHECK(map::not_applicable_combinations(c.model, axes).size() == 270);
    REQUIRE(spread.points.size() == grid.size());
    for (size_t p = 0; p < grid.size(); ++p) {
        INFO("point " << p);
        const auto& s = spread.points[p];
        // Neither solved nor unsolved: the 135 combinations with Wimmer's H_V are all that count.
        CHECK(s.solved + s.unsolved == 135);
        CHECK(closed_form.count(s.at_min) == 0);
        CHECK(closed_form.count(s.at_max) == 0);
        // The nominal map is the case's own, within the spread.
        const auto direct = solver::solve_point(c.model, grid.at(p).first, grid.at(p).second, false);
        REQUIRE(solver::has_values(nominal[p].status));
        CHECK(nominal[p].losses.total() == direct.losses.total());
        CHECK(s.P_min <= nominal[p].losses.total());
        CHECK(nominal[p].losses.total() <= s.P_max);
    }
    // The line on stderr and the JSON summary name them.
    CHECK_THAT(map::not_applicable_note(axes, spread.not_applicable),
               Catch::StartsWith("270 of 405 form combinations do not apply to this case") &&
                   Catch::Contains("first: mesh.loss_factor=ohlendorf: mesh 'm' has eps_alpha = 2.086"));
    CHECK(map::not_applicable_note(axes, {}).empty());
    nlohmann::ordered_json j;
    map::spread_summary_json(j, axes, spread, nominal);
    CHECK_THAT(j.dump(), Catch::Contains("\"combinations\":405,\"combinations_not_applicable\":270,"
                                        "\"not_applicable\":[\"mesh.loss_factor=ohlendorf\","));
}
