#pragma once
// Bodies of the fuzz targets, shared by the libFuzzer executables (clang,
// ASan + UBSan) and by the regression runner that replays the corpus and
// every saved crash input in the ordinary test suite.
//
// Contract checked: bad input raises gearloss::InputError only; anything
// else (another exception, a crash, a sanitizer report, NaN/inf in a result,
// a negative loss, a broken energy balance) is a finding.
#include <yaml-cpp/yaml.h>

#include <cctype>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <fmt/format.h>
#include <string>
#include <vector>

#include "gearloss/core/errors.hpp"
#include "gearloss/cycle/simulate.hpp"
#include "gearloss/diagnosis/recordings.hpp"
#include "gearloss/case/config.hpp"
#include "gearloss/results/reports.hpp"
#include "gearloss/map/map_runner.hpp"
#include "gearloss/solver/operating_point.hpp"

namespace fuzz {

[[noreturn]] inline void finding(const std::string& what) {
    std::fprintf(stderr, "FUZZ FINDING: %s\n", what.c_str());
    std::abort();
}

// A "nan" or "inf" (any case, as a whole word) in an output text: a value that is not finite
// reached a report, a JSON document or a CSV row.
inline bool has_non_finite_token(const std::string& text) {
    auto word = [](char c) { return std::isalnum(static_cast<unsigned char>(c)) || c == '_'; };
    for (size_t i = 0; i < text.size();) {
        if (!word(text[i])) {
            ++i;
            continue;
        }
        size_t j = i;
        while (j < text.size() && word(text[j])) ++j;
        std::string w = text.substr(i, j - i);
        for (char& c : w) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
        if (w == "nan" || w == "inf" || w == "infinity") return true;
        i = j;
    }
    return false;
}

inline void check_text(const std::string& what, const std::string& text) {
    if (has_non_finite_token(text)) finding("non-finite value in " + what + ": " + text.substr(0, 2000));
}

inline std::string configs_dir() { return std::string(GEARLOSS_SOURCE_DIR) + "/configs"; }

// Every number a solved point reports must be finite, every loss non-negative,
// and the energy balance must hold.
inline void check_result(const gearloss::io::Case& c, const gearloss::solver::PointResult& r) {
    const std::string row = gearloss::map::csv_row(c.model, r, true);
    check_text("CSV row", row);
    check_text("point report", gearloss::io::point_report(c, r));
    if (!gearloss::solver::has_values(r.status)) return;
    const auto& L = r.losses;
    if (L.power.size() != c.model.mechanisms.size()) finding("a loss per mechanism missing: " + row);
    for (double v : L.power)  // every mechanism's loss
        if (!std::isfinite(v)) finding("non-finite result: " + row);
    for (double v : {r.oil_temperature, r.power_out, r.torque_out})
        if (!std::isfinite(v)) finding("non-finite result: " + row);
    for (double v : L.power)
        if (v < 0) finding("negative loss: " + row);
    if (std::abs(r.power_out - (r.power_in - L.total())) > 1e-9 * std::max(1.0, std::abs(r.power_in)))
        finding("energy balance broken: " + row);
    if (r.has_efficiency && !(r.efficiency >= 0 && r.efficiency <= 1)) finding("efficiency outside [0, 1]: " + row);
}

// A case with a vehicle block over a short cold-start cycle (launch, cruise, brake): every
// trace value finite, no negative loss, and the thermal network conserves energy.
inline void check_cycle(const std::string& text, const gearloss::io::Case& c) {
    gearloss::cycle::Powertrain pt;
    pt.vehicle = *c.vehicle;
    pt.torque_converter = c.torque_converter;
    for (const auto& g : c.vehicle->gears)
        pt.gears.push_back(gearloss::io::load_case_text(text, "fuzz.yaml", configs_dir(), g).model);
    gearloss::cycle::DriveCycle dc;
    const double v[] = {0, 0, 3, 8, 14, 20, 26, 30, 32, 32, 32, 25, 15, 5, 0, 0};
    for (int i = 0; i < 16; ++i) {
        dc.time.push_back(i * 2.0);
        dc.speed.push_back(v[i] / 3.6);
    }
    const double T0 = 263.15;
    const auto r = gearloss::cycle::simulate_cycle(pt, dc, gearloss::cycle::uniform(T0), T0, true);
    for (const auto& t : r.trace) {
        for (double x : {t.T_oil, t.T_housing, t.T_clutch, t.P_gearbox, t.P_tc, t.input_torque, t.engine_torque, t.fuel_rate})
            if (!std::isfinite(x)) finding(fmt::format("non-finite cycle trace value at t = {}", t.time));
        for (double x : t.P_mech)
            if (!(x >= 0)) finding(fmt::format("negative or non-finite mechanism loss at t = {}", t.time));
    }
    const auto& k = r.totals;
    for (double x : k.E_mech)
        if (!(x >= 0)) finding("negative or non-finite cycle loss energy");
    if (!(k.E_tc >= 0)) finding("negative or non-finite converter loss energy");
    const double in = k.gearbox_loss() + k.E_tc + k.E_heater, out = k.E_ambient + k.stored_end - k.stored_start;
    if (std::abs(in - out) > 1e-6 * std::max(1.0, std::abs(in) + std::abs(k.E_ambient)))
        finding(fmt::format("cycle energy balance broken: {} vs {}", in, out));
}

inline int config_one(const uint8_t* data, size_t size) {
    const std::string text(reinterpret_cast<const char*>(data), size);
    try {
        const auto c = gearloss::io::load_case_text(text, "fuzz.yaml", configs_dir());
        check_text("check report", gearloss::io::check_report(c));
        check_text("check --json", gearloss::io::check_json(c));
        if (c.grid.size() > 0) {
            const auto [w, T] = c.grid.at(0);
            check_result(c, gearloss::solver::solve_point(c.model, w, T, true));
        }
        if (c.vehicle) check_cycle(text, c);
    } catch (const gearloss::InputError&) {
    }
    return 0;
}

inline int recordings_one(const uint8_t* data, size_t size) {
    const std::string text(reinterpret_cast<const char*>(data), size);
    try {
        const auto r = gearloss::diagnosis::read_recordings_text(text, "fuzz.csv");
        for (const auto& p : r.points)
            if (!std::isfinite(p.loss) || !std::isfinite(p.speed_in) || !std::isfinite(p.torque_in))
                finding("non-finite recorded value");
    } catch (const gearloss::InputError&) {
    }
    return 0;
}

// Arbitrary-but-valid cases: a shipped case with its numbers replaced by
// values drawn from wide physical ranges, then solved at drawn points.
class Draw {
public:
    Draw(const uint8_t* d, size_t n) : d_(d), n_(n) {}
    double unit() {  // [0, 1]
        uint16_t v = 0;
        for (int i = 0; i < 2; ++i) v = static_cast<uint16_t>((v << 8) | next());
        return v / 65535.0;
    }
    double range(double lo, double hi) { return lo + (hi - lo) * unit(); }
    // Log-uniform magnitude in [1e-300, 1e300] with a random sign.
    double extreme() { return (flag() ? -1.0 : 1.0) * std::pow(10.0, range(-300, 300)); }
    bool flag() { return next() & 1; }
    int pick(int n) { return static_cast<int>(next() % n); }

private:
    uint8_t next() { return i_ < n_ ? d_[i_++] : 0; }
    const uint8_t* d_;
    size_t n_, i_ = 0;
};

inline int map_one(const uint8_t* data, size_t size) {
    static const char* kCases[] = {"transfer-box.yaml", "fzg-c40-paor.yaml", "planetary-test.yaml",
                                   "wind-turbine-2.5MW.yaml"};
    Draw dr(data, size);
    YAML::Node root = YAML::LoadFile(configs_dir() + "/" + kCases[dr.pick(4)]);
    bool geometry_changed = false;
    for (auto g : root["gears"]) {
        if (dr.flag()) { g["teeth"] = 6 + dr.pick(140); geometry_changed = true; }
        if (dr.flag()) { g["profile_shift"] = dr.range(-0.8, 1.6); geometry_changed = true; }
        if (dr.flag()) g["face_width"] = fmt::format("{} mm", dr.range(0.5, 250));
        if (dr.flag()) g["Ra"] = fmt::format("{} um", dr.range(0.02, 5));
        if (dr.flag()) g["immersion"] = fmt::format("{} mm", dr.range(0, 400));
    }
    if (geometry_changed)
        for (auto m : root["meshes"]) m.remove("centre_distance");
    YAML::Node cal;
    if (dr.flag()) cal["windage"] = fmt::format("{} W", dr.range(0, 500));
    if (dr.flag()) cal["viscosity_factor"] = dr.range(0.05, 20);
    if (dr.flag()) cal["heat_rejection_factor"] = dr.range(0.05, 20);
    if (dr.flag()) cal["mesh_friction_factor"] = dr.range(0.05, 20);
    if (dr.flag()) cal["churning_factor"] = dr.range(0, 100);
    if (cal.size() > 0) root["calibration"] = cal;
    if (dr.flag()) root["housing"]["oil_level"] = fmt::format("{} mm", dr.range(-600, 600));
    if (dr.flag()) root["housing"]["oil_volume"] = fmt::format("{} L", dr.range(0.001, 200));
    auto th = root["thermal"];
    th["ambient"] = fmt::format("{} degC", dr.pick(16) == 0 ? dr.range(-300, 5000) : dr.range(-50, 60));
    if (dr.flag()) {
        th["mode"] = "fixed";
        th["oil_temperature"] = fmt::format("{} degC", dr.pick(16) == 0 ? dr.range(-300, 5000) : dr.range(-45, 250));
    }
    if (dr.flag()) {
        YAML::Node hr;
        hr["resistance"] = fmt::format("{} K/W", dr.range(1e-4, 20));
        th["heat_rejection"] = hr;
    }
    YAML::Node op;
    YAML::Node pts;
    const int n = 1 + dr.pick(6);
    for (int i = 0; i < n; ++i) {
        YAML::Node p;
        // One point in eight is hostile (a speed or torque of any magnitude): it must be an
        // input error or an out_of_range point, never a hang or a value that is not finite.
        const bool hostile = dr.pick(8) == 0;
        const double speed = hostile ? dr.extreme() : dr.flag() ? dr.range(0, 40000) : dr.range(0, 3);
        p.push_back(fmt::format("{} rpm", speed));
        p.push_back(fmt::format("{} N*m", hostile ? dr.extreme() : dr.range(-5000, 5000)));
        pts.push_back(p);
    }
    op["points"] = pts;
    root["operating"] = op;
    YAML::Emitter em;
    em << root;
    try {
        const auto c = gearloss::io::load_case_text(em.c_str(), "fuzz-map.yaml", configs_dir());
        std::vector<gearloss::solver::PointResult> results;
        for (size_t i = 0; i < c.grid.size(); ++i) {
            const auto [w, T] = c.grid.at(i);
            results.push_back(gearloss::solver::solve_point(c.model, w, T, true));
            check_result(c, results.back());
        }
        check_text("map --json summary", gearloss::map::map_summary_json(results, 0.1));
    } catch (const gearloss::InputError&) {
    }
    return 0;
}

}  // namespace fuzz
