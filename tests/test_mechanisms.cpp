// Contract tests applied to every registered loss mechanism (Ceres-style: one interface,
// every implementation held to it), and the YAML blocks that set their parameters and forms.
#include <catch2/catch.hpp>
#include <fmt/format.h>
#include <algorithm>
#include <cmath>
#include <numbers>
#include <set>

#include "gearloss/core/errors.hpp"
#include "gearloss/case/config.hpp"
#include "gearloss/losses/loss_mechanism.hpp"
#include "gearloss/losses/registry.hpp"
#include "gearloss/map/map_runner.hpp"
#include "gearloss/mechanisms/empirical_mechanism.hpp"
#include "gearloss/mechanisms/mesh_friction_mechanism.hpp"
#include "gearloss/model/validate.hpp"
#include "gearloss/solver/operating_point.hpp"
#include "test_support.hpp"

using namespace gearloss;


namespace {
constexpr double kRpm = std::numbers::pi / 30;
const char* kCases[] = {"transfer-box.yaml",   "fzg-c40-paor.yaml",    "spur-seed000.yaml",
                        "manual-6speed.yaml",  "automatic-6speed.yaml", "planetary-test.yaml",
                        "wind-turbine-2.5MW.yaml"};
io::Case load(const char* f) { return io::load_case(test_support::source_path(std::string("configs/") + f)); }

// An input speed [rad/s] within the case's own range: a case that lists its points (the wind
// turbine's rotor at 9..16.5 rpm) is not driven faster than its fastest point (1500 rpm at its
// rotor turns the high-speed bearings beyond any rolling bearing's n d_m: out of range).
double within_case(const io::Case& c, double w) {
    double top = 0;
    for (const auto& [s, t] : c.grid.points) top = std::max(top, std::abs(s));
    return top > 0 ? std::min(w, top) : w;
}

// The error of loading a case's text (the test fails when it loads).
InputError load_error(const std::string& text) {
    test_support::TempConfig cfg(text);
    try {
        (void)io::load_case(cfg.path);
    } catch (const InputError& e) {
        return e;
    }
    FAIL("no error");
    return InputError("", 0, 0, "", "");
}
// The case written as `text` solved at a fixed oil temperature, 300 N m, with the loss detail.
std::pair<solver::PointResult, solver::Model> solve_fixed(const std::string& text, double rpm, double T_C) {
    test_support::TempConfig cfg(text);
    auto c = io::load_case(cfg.path);
    c.model.thermal.mode = solver::ThermalMode::fixed;
    c.model.thermal.oil_temperature = T_C + 273.15;
    const auto r = solver::solve_point(c.model, rpm * kRpm, 300, true);
    return {r, c.model};
}
}  // namespace

TEST_CASE("mechanisms: the registry creates each mechanism by its name, once", "[mechanisms]") {
    std::set<std::string> names;
    for (const auto& r : losses::registry()) {
        CHECK(names.insert(r.name).second);
        const auto m = losses::create(r.name);
        CHECK(m->name() == r.name);
        CHECK(m->column().starts_with("P_"));
        CHECK(m->column().ends_with("_W"));
    }
    CHECK(names.count("mesh") == 1);
    CHECK(names.count("churning") == 1);
    CHECK(names.count("bearings") == 1);
    CHECK_THROWS_WITH(losses::create("no_such"), Catch::Contains("registered: mesh, churning"));
    // The default set of a model is the registry, in its order (the order of the CSV columns).
    const losses::MechanismSet set;
    REQUIRE(set.size() == losses::registry().size());
    for (size_t i = 0; i < set.size(); ++i) CHECK(set[i].name() == losses::registry()[i].name);
}

TEST_CASE("mechanisms: every mechanism keeps its contract on every shipped case", "[mechanisms]") {
    for (const char* f : kCases) {
        const io::Case c = load(f);
        const auto& m = c.model;
        for (double n : {0.0, 300.0, 1500.0})
            for (double T : {-120.0, 0.0, 80.0}) {
                const auto p = solver::prepare_point(m, within_case(c, n * kRpm), T);
                REQUIRE(p.fault.empty());
                for (double T_oil : {313.15, 353.15, 383.15}) {
                    const auto s = m.oil_state(T_oil);
                    const auto full = solver::evaluate_losses(m, p, s, true, true);
                    const auto hot = solver::evaluate_losses(m, p, s, false, false);
                    // The hot path and the detailed evaluation agree exactly; so does total_loss.
                    // (The local EHL model warm-starts its film temperatures from the previous
                    // evaluation of the point: equal within its iteration tolerance.)
                    const auto fr = mesh::mesh_forms(m).friction;
                    const double tol = fr == mesh::FrictionModel::ehl_local || fr == mesh::FrictionModel::ehl_maxwell ? 1e-3 : 0.0;
                    CHECK(solver::total_loss(m, p, T_oil) == Approx(full.total()).epsilon(tol));
                    for (size_t i = 0; i < m.mechanisms.size(); ++i) {
                        const auto& mech = m.mechanisms[i];
                        INFO(f << " " << mech.name() << " n " << n << " T " << T << " T_oil " << T_oil);
                        CHECK(hot.power[i] == Approx(full.power[i]).epsilon(tol));
                        CHECK(std::isfinite(full.power[i]));
                        CHECK(full.power[i] >= 0);
                        // Detail: a value per component and quantity, the losses summing to the total.
                        const auto names = mech.components(m);
                        const auto& d = full.detail[i];
                        CHECK(d.values.size() == names.size() * mech.quantities().size());
                        if (!names.empty()) {
                            double sum = 0;
                            for (size_t k = 0; k < names.size(); ++k) sum += d.at(k, 0);
                            CHECK(sum == Approx(full.power[i]).epsilon(1e-12).margin(1e-12));
                        }
                        // At rest nothing turns: no mechanism loses power.
                        if (n == 0) CHECK(full.power[i] == 0);
                        CHECK(mech.loss_fault(m, *p.data[i], d).empty());
                        CHECK(mech.point_fault(m, *p.data[i]).empty());
                    }
                }
                // A copy of the point state evaluates the same (deep copy of each mechanism's terms).
                const solver::PointState q = p;
                CHECK(solver::total_loss(m, q, 353.15) == solver::total_loss(m, p, 353.15));
            }
    }
}

TEST_CASE("mechanisms: parameters have bounds that hold their nominal value and are validated", "[mechanisms]") {
    const io::Case c = load("transfer-box.yaml");
    for (const auto& r : losses::registry()) {
        auto mech = losses::create(r.name);
        INFO(r.name);
        CHECK(mech->parameters_nominal());
        for (const auto& p : mech->parameters()) {
            INFO(p.name);
            CHECK(p.lower <= p.nominal);
            CHECK(p.nominal <= p.upper);
            CHECK(mech->parameter(p.name) == p.nominal);
            mech->set_parameter(p.name, p.upper * 2 + 1);
            std::vector<solver::Issue> issues;
            mech->validate(c.model, issues);
            REQUIRE(issues.size() == 1);
            CHECK(issues[0].key == r.name + "." + p.name);
            mech->set_parameter(p.name, p.nominal);
            CHECK(mech->parameters_nominal());
        }
        CHECK_THROWS_AS(mech->set_parameter("no_such", 1), InputError);
        // A clone carries the parameter values.
        const auto ps = mech->parameters();
        if (!ps.empty()) {
            mech->set_parameter(ps[0].name, ps[0].upper);
            CHECK(mech->clone()->parameter(ps[0].name) == ps[0].upper);
        }
    }
}

TEST_CASE("mechanisms: every alternative form is selectable by name and changes nothing else", "[mechanisms]") {
    io::Case c = load("transfer-box.yaml");
    for (size_t i = 0; i < c.model.mechanisms.size(); ++i) {
        auto& mech = c.model.mechanisms[i];
        for (const auto& axis : mech.forms(c.model)) {
            INFO(mech.name() << " " << axis.axis);
            REQUIRE(!axis.forms.empty());
            const std::string before = mech.form(c.model, axis.axis);
            for (const auto& f : axis.forms) {
                mech.set_form(c.model, axis.axis, f);
                CHECK(mech.form(c.model, axis.axis) == f);
                const auto r = solver::solve_point(c.model, 1500 * kRpm, 200);
                CHECK(solver::has_values(r.status));
            }
            mech.set_form(c.model, axis.axis, before);
            CHECK_THROWS_AS(mech.set_form(c.model, axis.axis, "no_such_form"), InputError);
        }
    }
}

TEST_CASE("mechanisms: calibration per mechanism, the earlier flat keys and the mechanisms block", "[mechanisms]") {
    const std::string base = test_support::read_file(test_support::source_path("configs/transfer-box.yaml"));
    auto solve = [](const std::string& text) {
        test_support::TempConfig cfg(text);
        const auto c = io::load_case(cfg.path);
        return solver::solve_point(c.model, 1500 * kRpm, 200, true);
    };
    const auto nominal = solve(base);
    const auto nested = solve(base + "calibration:\n  churning: {factor: 1.5}\n  seals: {factor: 2}\n"
                                     "  auxiliary: {power: 20 W}\n  mesh: {friction_factor: 1.1}\n");
    const auto flat = solve(base + "calibration:\n  churning_factor: 1.5\n  seal_factor: 2\n  auxiliary: 20 W\n"
                                   "  mesh_friction_factor: 1.1\n");
    CHECK(nested.losses.total() == flat.losses.total());
    CHECK(nested.oil_temperature == flat.oil_temperature);
    // The calibration heats the oil: hotter than the nominal case, and 20 W of auxiliary loss in it.
    CHECK(nested.oil_temperature > nominal.oil_temperature);
    const size_t aux = losses::MechanismSet{}.index("auxiliary");
    CHECK(nested.losses.power[aux] == 20.0);
    // Seals do not depend on the oil: exactly twice the nominal.
    const size_t seals = losses::MechanismSet{}.index("seals");
    CHECK(nested.losses.power[seals] == Approx(2 * nominal.losses.power[seals]).epsilon(1e-14));

    // The empirical windage, in its three spellings (the flat key, churning's block before
    // windage was a mechanism, the windage block): one result, in the windage column;
    // 12 W (1500/1000)^2.9 = 38.71 W at this speed.
    const size_t wind = losses::MechanismSet{}.index("windage");
    const auto w_flat = solve(base + "calibration:\n  windage: 12 W\n");
    const auto w_old = solve(base + "calibration:\n  churning: {windage_W_at_1000rpm: 12 W}\n");
    const auto w_new = solve(base + "calibration:\n  windage: {empirical_W_at_1000rpm: 12 W}\n");
    CHECK(w_flat.losses.power[wind] == Approx(12 * std::pow(1.5, 2.9)).epsilon(1e-12));
    CHECK(w_old.losses.total() == w_flat.losses.total());
    CHECK(w_new.losses.total() == w_flat.losses.total());
    CHECK(w_new.losses.power[wind] == w_flat.losses.power[wind]);

    // A mechanism's form chosen in the mechanisms block equals the options key.
    const auto by_block = solve(base + "mechanisms:\n  mesh: {friction: iso_6336_20}\n");
    const auto by_option = solve(test_support::replace_once(base, "mesh_friction: schlenk", "mesh_friction: iso_6336_20"));
    CHECK(by_block.losses.total() == by_option.losses.total());
    CHECK(by_block.losses.total() != nominal.losses.total());

    // Errors name the file, line and key.
    const std::string bad1 = base + "calibration:\n  churning: {factor: 500}\n";
    auto e = load_error(bad1);
    CHECK(e.line == test_support::line_of(bad1, "  churning: {factor: 500}"));
    CHECK_THAT(e.message, Catch::Contains("must be in [0, 100]"));
    e = load_error(base + "calibration:\n  gearing: {factor: 2}\n");
    CHECK_THAT(e.message, Catch::Contains("unknown calibration key 'gearing'"));
    e = load_error(base + "mechanisms:\n  mesh: {friction: coulomb}\n");
    CHECK_THAT(e.message, Catch::Contains("'coulomb' is not one of: schlenk, iso_6336_20, fernandes_mixed, ehl_local, ehl_maxwell"));
    e = load_error(base + "mechanisms:\n  mesh: {friction_factor: 1.2}\n");
    CHECK_THAT(e.message, Catch::Contains("belongs under 'calibration:'"));
    e = load_error(base + "mechanisms:\n  tyres: {form: x}\n");
    CHECK_THAT(e.message, Catch::Contains("no loss mechanism 'tyres'"));
}

TEST_CASE("mechanisms: the CSV takes its columns from the mechanisms", "[mechanisms]") {
    const io::Case c = load("automatic-6speed.yaml");
    const std::string h = map::csv_header(c.model, true);
    // One total column per mechanism, in registry order, before P_total_W.
    size_t at = h.find("oil_temp_C,");
    for (const auto& r : losses::registry()) {
        const auto col = std::string(losses::create(r.name)->column());
        const size_t next = h.find("," + col + ",", at);
        INFO(col);
        REQUIRE(next != std::string::npos);
        at = next;
    }
    CHECK(h.find(",P_total_W,", at) != std::string::npos);
    // A row has as many cells as the header, whether the point has values or not.
    auto cells = [](const std::string& s) { return std::count(s.begin(), s.end(), ','); };
    const auto ok = solver::solve_point(c.model, 1500 * kRpm, 100, true);
    solver::PointResult bad = ok;
    bad.status = solver::PointStatus::no_equilibrium;
    CHECK(cells(map::csv_row(c.model, ok, true)) == cells(h));
    CHECK(cells(map::csv_row(c.model, bad, true)) == cells(h));
    CHECK(cells(map::csv_row(c.model, bad, false)) == cells(map::csv_header(c.model, false)));
}

TEST_CASE("mechanisms: the drag of open clutch packs heats the clutch-pack node, the rest the oil", "[mechanisms]") {
    // The six-speed automatic in gear 2: the packs that are not engaged slip and drag. Their
    // heat enters the clutch-pack node of the thermal network (C_c dT_c/dt = P_clutch -
    // G_co (T_c - T_oil)), not the oil: what goes straight into the oil is the total less it.
    const io::Case c = io::load_case(test_support::source_path("configs/automatic-6speed.yaml"));
    const auto& m = c.model;
    const size_t k = m.mechanisms.index("clutch_drag");
    const auto p = solver::prepare_point(m, 2000 * kRpm, 50);
    const auto L = solver::evaluate_losses(m, p, m.oil_state(313.15), false);
    REQUIRE(L.power[k] > 1.0);
    CHECK_FALSE(m.mechanisms[k].heats_oil());
    CHECK(L.into_oil(m) == Approx(L.total() - L.power[k]).epsilon(1e-12));
    for (size_t i = 0; i < m.mechanisms.size(); ++i)
        if (i != k) CHECK(m.mechanisms[i].heats_oil());
}

TEST_CASE("mechanisms: a mechanism switched off loses nothing and leaves the others unchanged", "[mechanisms]") {
    std::set<std::string> exercised;  // mechanisms seen losing power, to switch off
    for (const char* f : kCases) {
        io::Case c = load(f);
        auto& m = c.model;
        // Something to lose for every mechanism: a windage form and the calibration's terms.
        m.mechanisms.at("windage").set_form(m, "form", "free_disk");
        m.mechanisms.at("windage").set_parameter("empirical_W_at_1000rpm", 12);
        m.mechanisms.at("auxiliary").set_parameter("power", 20);
        m.mechanisms.at("bearings").set_parameter("drag_f0", 2);
        losses::EmpiricalTerm constant;
        constant.coefficient = 15;  // W, no factor: a constant loss while the input turns
        dynamic_cast<losses::EmpiricalMechanism&>(m.mechanisms.at("empirical")).set_terms({constant});
        const auto s = m.oil_state(353.15);
        const auto on = solver::evaluate_losses(m, solver::prepare_point(m, within_case(c, 1500 * kRpm), 200), s, true, true);
        for (size_t i = 0; i < m.mechanisms.size(); ++i) {
            INFO(f << " " << m.mechanisms[i].name());
            if (on.power[i] > 0) exercised.insert(std::string(m.mechanisms[i].name()));
            auto off = m;
            off.mechanisms[i].set_enabled(false);
            CHECK(m.mechanisms[i].enabled());  // the copy's own state
            const auto p = solver::prepare_point(off, within_case(c, 1500 * kRpm), 200);
            REQUIRE(p.fault.empty());
            const auto r = solver::evaluate_losses(off, p, s, true, true);
            CHECK(r.power[i] == 0);
            for (size_t k = 0; k < m.mechanisms[i].components(m).size(); ++k) CHECK(r.detail[i].at(k, 0) == 0);
            for (size_t j = 0; j < m.mechanisms.size(); ++j)
                if (j != i) CHECK(r.power[j] == on.power[j]);
            CHECK(r.total() == Approx(on.total() - on.power[i]).epsilon(1e-12));
        }
    }
    CHECK(exercised.size() == losses::registry().size());
}

TEST_CASE("mechanisms: the mesh's mixed-film friction pair, in the options and the mechanisms block", "[mechanisms]") {
    const std::string base = test_support::replace_once(
        test_support::read_file(test_support::source_path("configs/transfer-box.yaml")), "mesh_friction: schlenk",
        "mesh_friction: fernandes_mixed");
    const size_t mesh = losses::MechanismSet{}.index("mesh");
    auto mesh_loss = [&](const std::string& text) {
        test_support::TempConfig cfg(text);
        auto c = io::load_case(cfg.path);
        c.model.thermal.mode = solver::ThermalMode::fixed;  // the same films whatever the pair
        c.model.thermal.oil_temperature = 353.15;
        return solver::solve_point(c.model, 1500 * kRpm, 200).losses.power[mesh];
    };
    const std::string options = test_support::replace_once(base, "mesh_friction: fernandes_mixed",
                                                           "mesh_friction: fernandes_mixed\n  gear_friction: {mu_bl: 0.12, mu_ehl: 0.03}");
    CHECK(mesh_loss(options) == mesh_loss(base + "mechanisms:\n  mesh: {mu_bl: 0.12, mu_ehl: 0.03}\n"));
    CHECK(mesh_loss(options) != mesh_loss(base));
    // mu = xi mu_bl + (1 - xi) mu_ehl (Fernandes et al. 2015) with mu_ehl = 0: the loss is
    // proportional to mu_bl at a fixed film.
    CHECK(mesh_loss(base + "mechanisms:\n  mesh: {mu_bl: 0.2, mu_ehl: 0}\n") ==
          Approx(2 * mesh_loss(base + "mechanisms:\n  mesh: {mu_bl: 0.1, mu_ehl: 0}\n")).epsilon(1e-12));
    // A pair out of order is an error at the key that set it.
    const std::string block = base + "mechanisms:\n  mesh: {mu_ehl: 0.5}\n";
    auto e = load_error(block);
    CHECK(e.key == "mechanisms.mesh.mu_ehl");
    CHECK(e.line == test_support::line_of(block, "  mesh: {mu_ehl: 0.5}"));
    CHECK_THAT(e.message, Catch::Contains("need 0 <= mu_ehl < mu_bl < 1"));
    const std::string opt = test_support::replace_once(base, "mesh_friction: fernandes_mixed",
                                                       "mesh_friction: fernandes_mixed\n  gear_friction: {mu_ehl: 0.5}");
    e = load_error(opt);
    CHECK(e.key == "options.gear_friction");
    CHECK(e.line == test_support::line_of(opt, "gear_friction: {mu_ehl: 0.5}"));
    CHECK_THAT(e.message, Catch::Contains("need 0 <= mu_ehl < mu_bl < 1"));
    CHECK_THAT(load_error(base + "mechanisms:\n  mesh: {mu_bl: 1.5}\n").message, Catch::Contains("must be in [0, 1]"));
    // Set in code: validate() names the pair.
    io::Case c = load("transfer-box.yaml");
    c.model.mechanisms.at("mesh").set_parameter("mu_ehl", 0.2);
    // With schlenk the pair is not read, and half of it (the other half the default) is no issue.
    CHECK(solver::validate(c.model).empty());
    c.model.mechanisms.at("mesh").set_form(c.model, "friction", "fernandes_mixed");
    const auto issues = solver::validate(c.model);
    REQUIRE(issues.size() == 1);
    CHECK(issues[0].path() == "options.gear_friction");
    // A whole pair out of order is an issue whatever the form.
    c.model.mechanisms.at("mesh").set_form(c.model, "friction", "schlenk");
    c.model.mechanisms.at("mesh").set_parameter("mu_bl", 0.1);
    CHECK(solver::validate(c.model).size() == 1);
}

TEST_CASE("mechanisms: mesh friction that follows the film rises by k (1 - Lambda/2)^2 below Lambda = 2", "[mechanisms]") {
    // Doleschel's (2003) boundary share xi = (1 - Lambda/2)^2 (0 from Lambda = 2): with
    // mixed_friction_rise = k each mesh loses (1 + k xi(Lambda)) times its loss without it, at
    // the same film (fixed oil temperature). Hand check at Lambda = 0.8: xi = 0.36, k = 0.5 gives
    // x 1.18; at Lambda >= 2 the loss is unchanged. With the onset moved to Lambda = 3
    // (mixed_friction_onset): k (1 - Lambda/3)^2 below 3; hand check at Lambda = 1.2:
    // (1 - 0.4)^2 = 0.36, x 1.18.
    const std::string base = test_support::read_file(test_support::source_path("configs/transfer-box.yaml"));
    // The Lambda of every loaded mesh at the points, each checked against (1 + 0.5 xi(Lambda)).
    auto check_rise = [&](const std::string& calibration, double onset) {
        std::vector<double> lambdas;
        for (const auto& [rpm, T] :
             {std::pair{300.0, 110.0}, {1500.0, 60.0}, {4000.0, 20.0}, {4000.0, 35.0}, {3000.0, 30.0}, {2000.0, 25.0}}) {
            const auto [r0, m0] = solve_fixed(base, rpm, T);
            const auto [r1, m1] = solve_fixed(base + "calibration:\n  mesh: " + calibration + "\n", rpm, T);
            const auto& d0 = r0.losses.detail_of(m0, "mesh");
            const auto& d1 = r1.losses.detail_of(m1, "mesh");
            for (size_t i = 0; i < m0.gearbox.meshes.size(); ++i) {
                const double P0 = d0.at(i, 0), P1 = d1.at(i, 0), lambda = d0.at(i, 2);
                if (!(P0 > 0)) continue;
                INFO(rpm << " rpm, " << T << " degC, mesh " << i << ", Lambda " << lambda);
                CHECK(d1.at(i, 2) == Approx(lambda).epsilon(1e-12));  // the film itself is unchanged
                const double xi = lambda < onset ? (1 - lambda / onset) * (1 - lambda / onset) : 0.0;
                CHECK(P1 == Approx(P0 * (1 + 0.5 * xi)).epsilon(1e-12));
                lambdas.push_back(lambda);
            }
            // Only the mesh column moves.
            CHECK(r1.losses.total() - r1.losses.of(m1, "mesh") ==
                  Approx(r0.losses.total() - r0.losses.of(m0, "mesh")).epsilon(1e-12));
        }
        return lambdas;
    };
    const auto lambdas = check_rise("{mixed_friction_rise: 0.5}", 2.0);
    const auto count = [&](double lo, double hi) {
        return std::count_if(lambdas.begin(), lambdas.end(), [&](double l) { return l >= lo && l < hi; });
    };
    CHECK(count(0, 2) > 0);  // both regimes were visited
    CHECK(count(2, 1e9) > 0);
    check_rise("{mixed_friction_rise: 0.5, mixed_friction_onset: 3}", 3.0);
    CHECK(count(2, 3) > 0);  // a film Doleschel's onset leaves alone and this one does not
    // Calibration terms with bounds: beyond them, an error at the key.
    CHECK_THAT(load_error(base + "calibration:\n  mesh: {mixed_friction_rise: 50}\n").message,
               Catch::Contains("must be in [-0.9, 20]"));
    CHECK_THAT(load_error(base + "calibration:\n  mesh: {mixed_friction_onset: 20}\n").message,
               Catch::Contains("must be in [0.5, 10]"));
}

TEST_CASE("mechanisms: a friction factor confined to thin films fades out around its film limit", "[mechanisms]") {
    // friction_factor f with friction_factor_film_limit L: mu x (1 + (f - 1) / (1 + exp((Lambda - L)
    // / (0.15 L)))) instead of mu x f. Hand check with f = 1.3, L = 1: at Lambda = L the loss is
    // (1 + 0.15) / 1.3 = 0.88462 of the uniform factor's; at Lambda = 1.3 L, exp(2) = 7.389 and
    // 1 + 0.3 / 8.389 = 1.03576; at Lambda = 0.7 L, 1 + 0.3 / (1 + exp(-2)) = 1.26424. The limit's
    // nominal (1000) leaves the uniform factor; the film itself is unchanged.
    const std::string base = test_support::read_file(test_support::source_path("configs/transfer-box.yaml"));
    int thin = 0, thick = 0;
    for (const auto& [rpm, T] : {std::pair{300.0, 110.0}, {1500.0, 60.0}, {4000.0, 20.0}, {2000.0, 40.0}}) {
        const auto [r0, m0] = solve_fixed(base + "calibration:\n  mesh: {friction_factor: 1.3}\n", rpm, T);
        const auto [r1, m1] = solve_fixed(base + "calibration:\n  mesh: {friction_factor: 1.3, friction_factor_film_limit: 1}\n",
                                    rpm, T);
        const auto [r2, m2] =
            solve_fixed(base + "calibration:\n  mesh: {friction_factor: 1.3, friction_factor_film_limit: 1000}\n", rpm, T);
        const auto& d0 = r0.losses.detail_of(m0, "mesh");
        const auto& d1 = r1.losses.detail_of(m1, "mesh");
        CHECK(r2.losses.total() == Approx(r0.losses.total()).epsilon(1e-12));
        for (size_t i = 0; i < m0.gearbox.meshes.size(); ++i) {
            const double P0 = d0.at(i, 0), P1 = d1.at(i, 0), lambda = d0.at(i, 2);
            if (!(P0 > 0)) continue;
            INFO(rpm << " rpm, " << T << " degC, mesh " << i << ", Lambda " << lambda);
            CHECK(d1.at(i, 2) == Approx(lambda).epsilon(1e-12));
            const double share = 1 + 0.3 / (1 + std::exp((lambda - 1.0) / 0.15));
            CHECK(P1 == Approx(P0 * share / 1.3).epsilon(1e-12));
            (lambda < 1 ? thin : thick) += 1;
        }
    }
    CHECK(thin > 0);  // both sides of the limit were visited
    CHECK(thick > 0);
    // The hand values of the fade (the formula above at three films).
    for (const auto& [x, want] : {std::pair{1.0, 1.15}, {1.3, 1.03576}, {0.7, 1.26424}})
        CHECK(1 + 0.3 / (1 + std::exp((x - 1.0) / 0.15)) == Approx(want).epsilon(1e-5));
    CHECK_THAT(load_error(base + "calibration:\n  mesh: {friction_factor_film_limit: 0.01}\n").message,
               Catch::Contains("must be in [0.1, 1000]"));
}

TEST_CASE("mechanisms: the added bearing drag with another power of nu n, anchored at nu n = 2000", "[mechanisms]") {
    // Palmgren (1959): M0 = 1e-7 f0 (nu n)^(2/3) d_m^3 [N mm] (nu in cSt, n in rpm, d_m in mm);
    // with drag_exponent b: M0 = 1e-7 f0 2000^(2/3) (nu n/2000)^b d_m^3, the same at nu n = 2000.
    // Each bearing's added power M0 omega (x planets) is computed here from its d_m, its speed and
    // the oil's nu at 60 degC, and compared with the mechanism's detail with and without the drag.
    const std::string base = test_support::read_file(test_support::source_path("configs/transfer-box.yaml"));
    const auto [r0, m0] = solve_fixed(base, 1500, 60);
    const double nu = m0.oil_state(60 + 273.15).nu_cSt;
    for (const double b : {2.0 / 3.0, 0.45, 0.85}) {
        const auto [r1, m1] =
            solve_fixed(base + fmt::format("calibration:\n  bearings: {{drag_f0: 2, drag_exponent: {}}}\n", b), 1500, 60);
        const auto& d0 = r0.losses.detail_of(m0, "bearings");
        const auto& d1 = r1.losses.detail_of(m1, "bearings");
        for (size_t i = 0; i < m0.gearbox.bearings.size(); ++i) {
            const auto& brg = m0.gearbox.bearings[i];
            const double omega = std::abs(m0.layout.bearing_speed_ratio[i]) * 1500 * kRpm;
            const double n = omega / kRpm, dm = brg.spec.dm() * 1e3;
            const double M0 = 1e-7 * 2 * std::pow(2000.0, 2.0 / 3.0) * std::pow(nu * n / 2000, b) * dm * dm * dm * 1e-3;
            INFO("b " << b << ", bearing " << brg.name << ", nu n " << nu * n);
            CHECK(d1.at(i, 0) - d0.at(i, 0) == Approx(M0 * omega * brg.multiplicity).epsilon(1e-9));
        }
    }
    CHECK_THAT(load_error(base + "calibration:\n  bearings: {drag_exponent: 2}\n").message,
               Catch::Contains("must be in [0.3, 1]"));
}
