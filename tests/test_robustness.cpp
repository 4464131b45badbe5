// Issue 13 (parts 1 and 2): every loop terminates, a value that is not finite never passes as
// `ok`, and inputs are validated where the model is built. Every hostile input of the issue is
// a regression case here, each run under a time limit so that a hang fails the test (and ends
// the test process) instead of blocking CI.
#include <catch2/catch.hpp>
#include "loss_parts.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <future>
#include <limits>
#include <memory>
#include <numbers>
#include <thread>

#include "gearloss/core/errors.hpp"
#include "gearloss/cycle/simulate.hpp"
#include "gearloss/diagnosis/diagnose.hpp"
#include "gearloss/diagnosis/synth.hpp"
#include "gearloss/case/config.hpp"
#include "gearloss/results/cycle_report.hpp"
#include "gearloss/map/compare.hpp"
#include "gearloss/map/map_runner.hpp"
#include "gearloss/mechanisms/mesh_friction_mechanism.hpp"
#include "gearloss/mesh/ehl_contact.hpp"
#include "gearloss/model/validate.hpp"
#include "gearloss/solver/operating_point.hpp"
#include "test_support.hpp"
#include "gearloss/thermal/equilibrium.hpp"

using namespace gearloss;
using test_support::TempConfig;

namespace {

constexpr double kRpm = std::numbers::pi / 30.0;  // rad/s per rpm
constexpr double kLimit = 5.0;                     // s per case
const double kNaN = std::numeric_limits<double>::quiet_NaN();
const double kInf = std::numeric_limits<double>::infinity();

// Runs f on its own thread and waits at most `seconds`: a hang fails the test and ends the
// process (a detached thread that never returns cannot be joined).
template <class F>
auto within(F&& f, double seconds = kLimit) -> decltype(f()) {
    using R = decltype(f());
    auto task = std::make_shared<std::packaged_task<R()>>(std::forward<F>(f));
    auto done = task->get_future();
    std::thread([task] { (*task)(); }).detach();
    if (done.wait_for(std::chrono::duration<double>(seconds)) != std::future_status::ready) {
        std::fprintf(stderr, "test_robustness: a case did not finish within %.0f s (a hang)\n", seconds);
        std::fflush(nullptr);
        std::_Exit(1);
    }
    return done.get();
}

std::string base(const std::string& file = "transfer-box.yaml") {
    return test_support::read_file(test_support::source_path("configs/" + file));
}

io::Case load(const std::string& text) {
    TempConfig cfg(text);
    return io::load_case(cfg.path);
}

io::Case transfer_box() { return io::load_case(test_support::source_path("configs/transfer-box.yaml")); }

solver::PointResult solve(const solver::Model& m, double rpm, double torque) {
    return within([&] { return solver::solve_point(m, rpm * kRpm, torque, true); });
}

void require_out_of_range(const solver::PointResult& r, const std::string& cause) {
    INFO("status: " << solver::status_text(r));
    REQUIRE(r.status == solver::PointStatus::out_of_range);
    CHECK_FALSE(solver::has_values(r.status));
    CHECK_THAT(r.cause, Catch::Contains(cause));
    CHECK_THAT(solver::status_text(r), Catch::StartsWith("out_of_range: "));
}

// The CSV row of an out-of-range point: inputs, then every numeric cell empty, then the status.
void require_empty_row(const solver::Model& m, const solver::PointResult& r, const std::string& cause) {
    const std::string row = map::csv_row(m, r, true);
    INFO(row);
    CHECK_THAT(row, Catch::Contains(",,,,,,,,,,,,out_of_range: " + cause));
    CHECK_THAT(row, !Catch::Contains("nan") && !Catch::Contains("inf") && !Catch::Contains(",ok"));
}

// The error a case raises when validated as the command line does (map::validate_case).
InputError validation_error(const io::Case& k, const map::CaseOverrides& o = {}) {
    try {
        map::validate_case(k, o);
    } catch (const InputError& e) {
        return e;
    }
    FAIL("no validation error");
    throw std::logic_error("unreachable");
}

}  // namespace

TEST_CASE("robustness: torque 1e7 N m puts bearing B1_RMS11 contact angle out of range (stabilised and fixed oil)",
          "[robustness]") {
    io::Case k = transfer_box();
    const auto r = solve(k.model, 800, 1e7);
    require_out_of_range(r, "bearing B1_RMS11 contact angle");
    require_empty_row(k.model, r, "bearing B1_RMS11 contact angle");
    // --oil-temp 70degC: was an `ok` row with empty totals and efficiency 0.000000.
    k.model.thermal.mode = solver::ThermalMode::fixed;
    k.model.thermal.oil_temperature = 343.15;
    const auto f = solve(k.model, 800, 1e7);
    require_out_of_range(f, "bearing B1_RMS11 contact angle");
    CHECK_FALSE(f.has_efficiency);
    require_empty_row(k.model, f, "bearing B1_RMS11 contact angle");
    // 1e7 N m is within the stated range: not an input error.
    CHECK_NOTHROW(map::validate_point(800 * kRpm, 1e7));
}

TEST_CASE("robustness: speed 1e-300 rpm ends with a located cause and small real speeds stay ok", "[robustness]") {
    const io::Case k = transfer_box();
    require_out_of_range(solve(k.model, 1e-300, 200), "churning gear");
    for (double rpm : {1e-6, 1e-3, 1.0}) {
        const auto r = solve(k.model, rpm, 200);
        INFO(rpm << " rpm: " << solver::status_text(r));
        CHECK(r.status == solver::PointStatus::ok);
        CHECK(std::isfinite(r.losses.total()));
    }
}

TEST_CASE("robustness: speed 1e300 rpm and torque beyond 1e8 N m are input errors or out_of_range", "[robustness]") {
    const io::Case k = transfer_box();
    require_out_of_range(solve(k.model, 1e300, 200), "input speed");
    require_out_of_range(solve(k.model, 800, 1e9), "input torque");
    require_out_of_range(within([&] { return solver::solve_point(k.model, kNaN, 200); }), "input speed");
    require_out_of_range(within([&] { return solver::solve_point(k.model, 100, kInf); }), "input torque");
    CHECK_THROWS_WITH(map::validate_point(1e300 * kRpm, 200), Catch::Contains("--speed") && Catch::Contains("1e+06 rpm"));
    CHECK_THROWS_WITH(map::validate_point(800 * kRpm, -2e8), Catch::Contains("--torque") && Catch::Contains("1e+08 N m"));
    // The limits themselves are valid.
    CHECK_NOTHROW(map::validate_point(1e6 * kRpm * (1 - 1e-12), -1e8));
    // A grid: from the case file it points at operating.speeds; from --speed at the option.
    io::Case g = transfer_box();
    g.grid.speeds = {600 * kRpm, 1e300 * kRpm};
    const auto e = validation_error(g);
    CHECK(e.key == "operating.speeds");
    CHECK(e.line == test_support::line_of(base(), "speeds: [600 rpm"));
    CHECK(validation_error(g, {.speeds = true}).key == "--speed");
}

TEST_CASE("robustness: ambient 5000 degC is an error at its line and out_of_range in code", "[robustness]") {
    // The loader validates the model it built (solver::validate) and points at the line.
    const std::string text = test_support::replace_once(base(), "ambient: 25 degC", "ambient: 5000 degC");
    TempConfig cfg(text);
    InputError e("", 0, 0, "", "");
    try {
        (void)io::load_case(cfg.path);
        FAIL("no error raised");
    } catch (const InputError& err) {
        e = err;
    }
    INFO(e.what());
    CHECK(e.file == cfg.path);
    CHECK(e.key == "thermal.ambient");
    CHECK(e.line == test_support::line_of(text, "ambient: 5000 degC"));
    CHECK_THAT(e.message, Catch::Contains("-100..300 degC"));
    // The same value set in code: validate() names it and every point is out_of_range.
    io::Case k = transfer_box();
    k.model.thermal.ambient = 5273.15;
    CHECK(validation_error(k).key == "thermal.ambient");
    CHECK_FALSE(solver::is_valid(k.model));
    require_out_of_range(solve(k.model, 800, 200), "ambient temperature");
    // The ambient passed to solve_point is checked as well.
    const io::Case t = transfer_box();
    require_out_of_range(within([&] { return solver::solve_point(t.model, 800 * kRpm, 200, false, 5273.15); }),
                         "ambient temperature");
}

TEST_CASE("robustness: deep groove ball bearing with C0 0.1 N is out_of_range at every point and the summary has no ranges",
          "[robustness]") {
    const io::Case k = load(test_support::replace_once(base(), "C0: 22 kN", "C0: 0.1 N"));
    const auto results = within([&] { return map::run_map(k.model, k.grid, {}); });
    REQUIRE(results.size() == 9);
    for (const auto& r : results) require_out_of_range(r, "bearing B1_RMS11 contact angle");
    const std::string json = map::map_summary_json(results, 0.1);
    INFO(json);
    CHECK_THAT(json, Catch::Contains("\"out_of_range\":9") && Catch::Contains("\"ok\":0"));
    CHECK_THAT(json, !Catch::Contains("loss_W") && !Catch::Contains("oil_temp_C") && !Catch::Contains("1e+300"));
}

TEST_CASE("robustness: each command's options are checked where they are used (Ceres-style)", "[robustness]") {
    const auto key_of = [](auto&& f) -> std::string {
        try {
            f();
        } catch (const InputError& e) {
            return e.key;
        }
        return "(no error)";
    };
    const io::Case k = transfer_box();
    map::MapOptions mo;
    mo.threads = 5000;
    CHECK(key_of([&] { map::run_map(k.model, k.grid, mo); }) == "--threads");
    diagnosis::SynthOptions so;
    so.noise_loss = kNaN;
    CHECK(key_of([&] { diagnosis::synthesize(k.model, k.grid, so); }) == "--noise-loss");
    so = {};
    so.noise_temp = -1;
    CHECK(key_of([&] { diagnosis::synthesize(k.model, k.grid, so); }) == "--noise-temp");
    so = {};
    so.effects = {{"windage", kInf}};
    CHECK(key_of([&] { diagnosis::synthesize(k.model, k.grid, so); }) == "--effect");
    diagnosis::DiagnoseOptions d;
    d.stability_min = 1.5;
    CHECK(key_of([&] { d.validate(); }) == "stability_min");
    d = {};
    d.bootstrap = 2;
    CHECK(key_of([&] { d.validate(); }) == "--bootstrap");
    CHECK_NOTHROW(diagnosis::DiagnoseOptions{}.validate());
    io::CycleStudyOptions c;
    CHECK_NOTHROW(c.validate());
    c.start_temperature = 1e300;
    CHECK(key_of([&] { c.validate(); }) == "--start-temp");
    c = {};
    c.ambient = kNaN;
    CHECK(key_of([&] { c.validate(); }) == "--ambient");
    c = {};
    c.prewarm_target = c.start_temperature - 1;
    CHECK(key_of([&] { c.validate(); }) == "--prewarm");
    c = {};
    c.heater_power = kInf;
    CHECK(key_of([&] { c.validate(); }) == "--heater");
}

TEST_CASE("robustness: synth and compare name the cause of an out_of_range point", "[robustness]") {
    // C0 = 0.1 N drives the deep-groove contact angle past 180 deg at every point.
    const io::Case k = load(test_support::replace_once(base(), "C0: 22 kN", "C0: 0.1 N"));
    for (bool raw : {false, true}) {
        diagnosis::SynthOptions o;
        o.raw_log = raw;
        o.test_minutes = o.short_test_minutes = 1;
        try {
            (void)within([&] { return diagnosis::synthesize(k.model, k.grid, o); });
            FAIL("no error raised");
        } catch (const InputError& e) {
            CHECK_THAT(e.message, Catch::Contains("out_of_range") && Catch::Contains("bearing B1_RMS11 contact angle"));
        }
    }
    const auto r = solve(k.model, 800, 200);
    const std::string row = map::compare_row(r, r);
    CHECK_THAT(row, Catch::Contains("out_of_range: bearing B1_RMS11 contact angle"));
    CHECK(std::count(row.begin(), row.end(), ',') == 12);  // the cause keeps the CSV's columns
}

TEST_CASE("robustness: mesh angle 1e308 rev is an input error and a non-finite angle ends shaft placement",
          "[robustness]") {
    TempConfig cfg(test_support::replace_once(base(), "angle: 120 deg", "angle: 1e308 rev"));
    CHECK_THROWS_AS(within([&] { return io::load_case(cfg.path); }), InputError);
    for (double angle : {kInf, kNaN}) {
        io::Case k = transfer_box();
        k.model.gearbox.meshes[0].angle = angle;
        const auto issues = solver::validate(k.model);
        REQUIRE_FALSE(issues.empty());
        CHECK(issues.front().path() == "meshes.m12.angle");
        try {
            within([&] {
                k.model.finalise();
                return 0;
            });
            FAIL("no topology error");
        } catch (const gearbox::TopologyError& e) {
            CHECK_THAT(e.message, Catch::Contains("mesh 'm12': angle is not a finite number"));
            CHECK(e.section == "meshes");
            CHECK(e.item == "m12");
            CHECK(e.key == "angle");
        }
    }
    // A finite but huge angle in radians is a direction like any other.
    io::Case k = transfer_box();
    k.model.gearbox.meshes[0].angle = 1e308;
    CHECK_NOTHROW(within([&] {
        k.model.finalise();
        return 0;
    }));
}

TEST_CASE("robustness: oil temperature 1500 degC (density negative) is an input error and out_of_range in code",
          "[robustness]") {
    io::Case k = transfer_box();
    k.model.thermal.mode = solver::ThermalMode::fixed;
    k.model.thermal.oil_temperature = 1773.15;
    CHECK_THAT(validation_error(k, {.oil_temp = "1500degC"}).key, Catch::Equals("--oil-temp"));
    const auto e = validation_error(k);
    CHECK(e.key == "thermal.oil_temperature");
    CHECK_THAT(e.message, Catch::Contains("density reaches zero at 1485.6 degC"));
    require_out_of_range(solve(k.model, 800, 200), "density");
    // Within the oil's validity the point has values, all of them finite and non-negative.
    k.model.thermal.oil_temperature = 273.15 + 150;
    const auto r = solve(k.model, 800, 200);
    REQUIRE(solver::has_values(r.status));
    CHECK(test::part(r.losses, "churning") >= 0);
    // The oil's validity: the pole of its Vogel law below, the density's zero above.
    const auto v = solver::oil_validity(k.model.oil);
    CHECK(v.T_max == Catch::Detail::Approx(288.15 + 1 / 6.8e-4));
    CHECK(v.T_min > 0);
    CHECK(solver::oil_temperature_fault(k.model.oil, v.T_min));
    CHECK_FALSE(solver::oil_temperature_fault(k.model.oil, 343.15));
}

TEST_CASE("robustness: the thermal equilibrium is bounded and stops at NaN", "[robustness]") {
    thermal::EquilibriumOptions opt;
    // NaN from the start, NaN after a few steps, NaN conductance: no endless loop.
    auto nan_loss = [](double) { return std::numeric_limits<double>::quiet_NaN(); };
    auto G = [](double) { return 1.0; };
    auto eq = within([&] { return thermal::solve_equilibrium(nan_loss, G, 300.0, opt); });
    CHECK(eq.status == thermal::EquilibriumStatus::non_finite);
    auto late_nan = [](double T) { return T < 330 ? 50.0 : std::numeric_limits<double>::quiet_NaN(); };
    eq = within([&] { return thermal::solve_equilibrium(late_nan, G, 300.0, opt); });
    CHECK(eq.status == thermal::EquilibriumStatus::non_finite);
    CHECK(eq.T >= 330);
    auto nan_G = [](double) { return std::numeric_limits<double>::quiet_NaN(); };
    eq = within([&] { return thermal::solve_equilibrium([](double) { return 10.0; }, nan_G, 300.0, opt); });
    CHECK(eq.status == thermal::EquilibriumStatus::non_finite);
    // A loss that never crosses: bounded by max_bracket_steps, not by T_max.
    opt.T_max = 1e12;
    eq = within([&] { return thermal::solve_equilibrium([](double) { return 1e-9; }, G, 300.0, opt); });
    CHECK(eq.status == thermal::EquilibriumStatus::iteration_limit);
    CHECK(eq.evaluations <= opt.max_bracket_steps + 1);
    // An ambient at or above T_max: an answer, not an exception from the root finder.
    opt.T_max = 400;
    eq = within([&] { return thermal::solve_equilibrium([](double T) { return 500.0 - T; }, G, 450.0, opt); });
    CHECK(eq.status == thermal::EquilibriumStatus::no_equilibrium);
    // A regular problem still converges.
    opt = {};
    eq = within([&] { return thermal::solve_equilibrium([](double T) { return 100.0 - (T - 300.0); }, G, 300.0, opt); });
    REQUIRE(eq.status == thermal::EquilibriumStatus::ok);
    CHECK(eq.T == Catch::Detail::Approx(400.0).margin(1e-3));
}

TEST_CASE("robustness: the EHL film-temperature loop terminates on inputs that are not finite", "[robustness]") {
    const io::Case k = transfer_box();
    for (double bad : {kNaN, kInf, 1e300}) {
        mesh::EhlContactInput in{1e5, 0.01, 10.0, 8.0, 2.3e11, 0.5e-6, 353.15, bad};
        CHECK_NOTHROW(within([&] { return mesh::ehl_contact(in, k.model.oil, k.model.oil.traction); }));
        in.film_rise_guess = 0;
        in.w_line = bad;
        CHECK_NOTHROW(within([&] { return mesh::ehl_contact(in, k.model.oil, k.model.oil.traction); }));
    }
    // The local thermal-EHL friction model on the whole gearbox: ok, and out_of_range at 1e7 N m.
    io::Case e = transfer_box();
    for (auto form : {mesh::FrictionModel::ehl_local, mesh::FrictionModel::ehl_maxwell}) {
        mesh::mesh_forms(e.model).friction = form;
        CHECK(solver::has_values(solve(e.model, 800, 200).status));
        require_out_of_range(solve(e.model, 800, 1e7), "contact angle");
    }
}

TEST_CASE("robustness: a cycle of two rows spanning 1e300 s and extreme temperatures are errors and not hangs",
          "[robustness]") {
    const io::Case k = io::load_case(test_support::source_path("configs/manual-6speed.yaml"));
    const auto pt = io::load_powertrain(k, std::nullopt);
    cycle::DriveCycle dc;
    dc.name = "long";
    dc.time = {0.0, 1e300};
    dc.speed = {10 / 3.6, 20 / 3.6};
    CHECK_THROWS_WITH(within([&] { return cycle::simulate_cycle(pt, dc, cycle::uniform(293.15), 293.15); }),
                      Catch::Contains("at most 1e+06 s"));
    dc.time = {0.0, 10.0};
    CHECK_THROWS_WITH(within([&] { return cycle::simulate_cycle(pt, dc, cycle::uniform(273.15 + 3000), 293.15); }),
                      Catch::Contains("start temperature") && Catch::Contains("validity of oil"));
    CHECK_THROWS_WITH(within([&] { return cycle::simulate_cycle(pt, dc, cycle::uniform(293.15), 273.15 + 5000); }),
                      Catch::Contains("ambient") && Catch::Contains("-100..300 degC"));
    CHECK_THROWS_AS(within([&] { return cycle::simulate_cycle(pt, dc, cycle::uniform(kNaN), 293.15); }), InputError);
    dc.speed = {10 / 3.6, kNaN};
    CHECK_THROWS_WITH(within([&] { return cycle::simulate_cycle(pt, dc, cycle::uniform(293.15), 293.15); }),
                      Catch::Contains("vehicle speed"));
    // A short cycle is unaffected: finite temperatures.
    dc.speed = {10 / 3.6, 20 / 3.6};
    const auto r = within([&] { return cycle::simulate_cycle(pt, dc, cycle::uniform(293.15), 293.15); });
    CHECK(std::isfinite(r.totals.end[0]));
    CHECK(r.totals.end[0] > 293.15);
    // Pre-warming: an unreachable or non-finite target is refused up front.
    CHECK_THROWS_AS(within([&] { return cycle::prewarm(pt, cycle::uniform(293.15), kInf, 1000, 293.15); }), InputError);
    CHECK_THROWS_AS(within([&] { return cycle::prewarm(pt, cycle::uniform(293.15), 363.15, kNaN, 293.15); }), InputError);
}

TEST_CASE("robustness: a map above 1e7 points is refused before anything is allocated", "[robustness]") {
    const io::Case k = transfer_box();
    io::OperatingGrid g;
    g.speeds.assign(10000, 800 * kRpm);
    g.torques.assign(10000, 200.0);
    CHECK_THROWS_WITH(within([&] { return map::run_map(k.model, g, {}); }), Catch::Contains("at most 10000000"));
    io::Case big = transfer_box();
    big.grid = g;
    CHECK_THAT(validation_error(big).message, Catch::Contains("1e+08") || Catch::Contains("100000000"));
}

TEST_CASE("robustness: validate accepts the shipped cases and locates issues of models built in code", "[robustness]") {
    for (const char* f : {"transfer-box.yaml", "transfer-box-75W140.yaml", "fzg-c40-paor.yaml", "spur-seed000.yaml",
                          "manual-6speed.yaml", "automatic-6speed.yaml", "planetary-test.yaml", "wind-turbine-2.5MW.yaml"}) {
        const io::Case k = io::load_case(test_support::source_path(std::string("configs/") + f));
        const auto issues = solver::validate(k.model);
        INFO(f << ": " << (issues.empty() ? "" : issues.front().text()));
        CHECK(issues.empty());
        CHECK_NOTHROW(map::validate_case(k));
    }
    io::Case k = transfer_box();
    k.model.gearbox.bearings[1].spec.C0 = kNaN;
    k.model.mechanisms.at("windage").set_parameter("empirical_W_at_1000rpm", kInf);
    k.model.thermal.rejection.model = thermal::HousingSurface{.area = -1};
    const auto issues = solver::validate(k.model);
    std::string all;
    for (const auto& i : issues) all += i.text() + "\n";
    INFO(all);
    CHECK_THAT(all, Catch::Contains("bearings.B1_RMS11.C0: static load rating C0 [N] is not a number"));
    CHECK_THAT(all, Catch::Contains("calibration.windage.empirical_W_at_1000rpm"));
    CHECK_THAT(all, Catch::Contains("thermal.heat_rejection.housing.area"));
    // The first issue points at the line of the bearing's C0 in the case file.
    io::Case c0 = transfer_box();
    c0.model.gearbox.bearings[1].spec.C0 = kNaN;
    const auto e = validation_error(c0);
    CHECK(e.key == "bearings.B1_RMS11.C0");
    CHECK(e.line == test_support::line_of(base(), "{name: B1_RMS11"));
    CHECK_THAT(e.message, Catch::Contains("more:"));
    // solve_point on the unvalidated model: a located cause, never `ok` (the first mechanism
    // in registry order with a fault: the bearing, then the windage's empirical term).
    require_out_of_range(solve(k.model, 800, 200), "bearing B1_RMS11");
    k.model.gearbox.bearings[1].spec.C0 = transfer_box().model.gearbox.bearings[1].spec.C0;
    require_out_of_range(solve(k.model, 800, 200), "windage");
    // Out-of-range indices are topology errors at finalise(), not a crash.
    io::Case bad = transfer_box();
    bad.model.gearbox.bearings[0].shaft = 17;
    CHECK_THROWS_AS(bad.model.finalise(), gearbox::TopologyError);
}

TEST_CASE("robustness: a shaft without a locating bearing names its bearings", "[robustness]") {
    const std::string text = test_support::replace_once(base(), "position: 130 mm, locating: true}\n  - {name: B3",
                                                        "position: 130 mm}\n  - {name: B3");
    TempConfig cfg(text);
    try {
        (void)io::load_case(cfg.path);
        FAIL("no error");
    } catch (const InputError& e) {
        CHECK_THAT(e.message, Catch::Contains("its bearings: B5_NJ309E, B1_RMS11"));
    }
}

TEST_CASE("robustness: the out_of_range status cell carries its cause without commas", "[robustness]") {
    solver::PointResult r;
    r.status = solver::PointStatus::out_of_range;
    r.cause = "bearing \"a,b\" contact angle\n";
    CHECK(solver::status_text(r) == "out_of_range: bearing  a b  contact angle ");
    CHECK(std::string(solver::to_string(r.status)) == "out_of_range");
    r.status = solver::PointStatus::no_equilibrium;
    CHECK(solver::status_text(r) == "no_equilibrium");
    CHECK_FALSE(solver::has_values(solver::PointStatus::out_of_range));
    CHECK(solver::has_values(solver::PointStatus::above_oil_limit));
}

TEST_CASE("errors found after loading point at the line recorded when the case was read", "[robustness]") {
    // The model keeps where each item was written: the file may change or vanish afterwards.
    const std::string text = base();
    io::Case k;
    std::string file;
    {
        test_support::TempConfig cfg(text);
        k = io::load_case(cfg.path);
        file = cfg.path;
        std::ofstream(cfg.path) << "# rewritten after loading\n" << text;  // every line moves down by one
    }
    REQUIRE(k.model.source);
    k.model.gearbox.bearings[1].spec.C0 = kNaN;
    const auto e = validation_error(k);
    CHECK(e.file == file);
    CHECK(e.key == "bearings.B1_RMS11.C0");
    CHECK(e.line == test_support::line_of(text, "{name: B1_RMS11"));
    // A bearing of `count: 2` ("B6_6307.2") is found under its written name.
    io::Case k2 = transfer_box();
    bool found = false;
    for (auto& b : k2.model.gearbox.bearings)
        if (b.name == "B6_6307.2") b.spec.C0 = kNaN, found = true;
    REQUIRE(found);
    const auto e2 = validation_error(k2);
    CHECK(e2.key == "bearings.B6_6307.2.C0");
    CHECK(e2.line == test_support::line_of(text, "{name: B6_6307"));
    // The index itself: key, then item, then section, then the file.
    const auto& src = *k.model.source;
    CHECK(src.find("bearings", "B1_RMS11", "no_such_key").line == test_support::line_of(text, "{name: B1_RMS11"));
    CHECK(src.find("thermal", "", "ambient").line > 0);
    CHECK(src.find("nowhere", "", "").line == 0);
    CHECK(src.find("nowhere", "", "").file == file);
}
