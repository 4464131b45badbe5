#include "module_commands.hpp"

#include <pybind11/stl.h>

#include <algorithm>
#include <filesystem>
#include <memory>
#include <type_traits>

#include <fmt/format.h>

#include "gearloss/results/cycle_report.hpp"
#include "gearloss/io/data_dir.hpp"
#include "gearloss/case/drive_cycle_csv.hpp"
#include "gearloss/results/reports.hpp"
#include "gearloss/case/sweep.hpp"
#include "gearloss/map/compare_oils.hpp"
#include "gearloss/map/form_spread.hpp"
#include "gearloss/map/job.hpp"
#include "gearloss/map/map_runner.hpp"
#include "gearloss/map/map_stream.hpp"

namespace py = pybind11;

namespace gearloss::python {
namespace {

// The Python arguments that stand for the CLI's options in the errors of a map-like call.
const KeyNames kGridNames = {{"--speed", "speeds_rpm"}, {"--torque", "torques_Nm"}, {"--threads", "threads"},
                             {"--oil-temp", "oil_temp_C"}, {"--oil", "oils"}, {"--spread-axes", "axes"},
                             {"--spread", "spread"}};

map::CaseOverrides overrides(const PyCase& c, const std::optional<double>& oil_temp_C, const OptionalAxis& speeds_rpm,
                             const OptionalAxis& torques_Nm) {
    return {.oil_temp = oil_temp_C ? "oil_temp_C" : "", .oil = c.oil_file, .speeds = speeds_rpm.has_value(),
            .torques = torques_Nm.has_value()};
}

// The case with the grid and oil temperature of the call, checked as the map command checks it
// (at most `max_points` points).
io::Case map_case(const PyCase& c, const OptionalAxis& speeds_rpm, const OptionalAxis& torques_Nm,
                  const std::optional<double>& oil_temp_C, size_t max_points) {
    io::Case k = at_oil_temperature(c, oil_temp_C);
    k.grid = grid_of(k, speeds_rpm, torques_Nm);
    require_values(speeds_rpm, torques_Nm);
    auto o = overrides(c, oil_temp_C, speeds_rpm, torques_Nm);
    o.max_points = max_points;
    renaming_keys(kGridNames, [&] { map::validate_case(k, o); });
    return k;
}

map::MapOptions map_options(const std::optional<int>& threads, bool detail) {
    map::MapOptions opt;
    opt.threads = threads.value_or(0);
    opt.detail = detail;
    renaming_keys(kGridNames, [&] { opt.validate(); });
    return opt;
}

// Runs `f` with the GIL released, Ctrl-C polled through opt.progress.
template <class F>
auto interruptible(map::MapOptions& opt, F&& f) -> decltype(f()) {
    SignalWatch watch;
    opt.progress = [&watch](size_t, size_t) { watch.poll(); };
    try {
        py::gil_scoped_release free;
        if constexpr (std::is_void_v<decltype(f())>) {
            f();
            io::throw_if_interrupted();
            return;
        } else {
            auto out = f();
            io::throw_if_interrupted();
            return out;
        }
    } catch (const Interrupted&) {
        watch.finish();  // the KeyboardInterrupt, if Ctrl-C caused it
        throw;
    } catch (const IoError&) {
        watch.finish();  // throw_if_interrupted's error after Ctrl-C
        throw;
    }
}

}  // namespace

std::string check(const PyCase& c, bool json) {
    io::Case k = renaming_keys({{"--ratio", "ratio"}}, [&] { return read_case(c.source); });
    if (!c.oil_file.empty()) io::replace_oil_file(k, c.oil_file);
    check_loaded(k, c.oil_file, "");
    return json ? io::check_json(k) : io::check_report(k);
}

std::string compare(const PyCase& c, const std::vector<std::string>& oils, const OptionalAxis& speeds_rpm,
                    const OptionalAxis& torques_Nm, const std::optional<double>& oil_temp_C,
                    const std::optional<int>& threads, bool detail) {
    if (oils.size() < 2) throw InputError("", 0, 0, "oils", "compare needs two or more oils");
    map::MapOptions opt = map_options(threads, false);
    io::Case base = at_oil_temperature(c, oil_temp_C);
    base.grid = grid_of(base, speeds_rpm, torques_Nm);
    require_values(speeds_rpm, torques_Nm);
    std::vector<io::Case> cases(oils.size(), base);
    std::vector<std::string> names;
    for (size_t i = 0; i < oils.size(); ++i) {
        renaming_keys(kGridNames, [&] {
            io::replace_oil_file(cases[i], oils[i]);
            auto o = overrides(c, oil_temp_C, speeds_rpm, torques_Nm);
            o.oil = oils[i];
            map::validate_case(cases[i], o);
        });
        names.push_back(cases[i].model.oil.name);
    }
    const auto& m = cases[0].model;
    std::string text = map::compare_oils_header(m, names, detail);
    std::vector<std::vector<solver::PointResult>> maps(cases.size());
    interruptible(opt, [&] {
        for (size_t k = 0; k < cases.size(); ++k) {
            maps[k] = map::run_map(cases[k].model, cases[k].grid, opt);
            io::throw_if_interrupted();
        }
    });
    std::vector<const solver::PointResult*> row(cases.size());
    for (size_t i = 0; i < maps[0].size(); ++i) {
        for (size_t k = 0; k < maps.size(); ++k) row[k] = &maps[k][i];
        text += map::compare_oils_row(m, row, detail);
    }
    return text;
}

py::dict spread(const PyCase& c, const std::optional<std::vector<std::string>>& axes_only, const OptionalAxis& speeds_rpm,
                const OptionalAxis& torques_Nm, const std::optional<double>& oil_temp_C,
                const std::optional<int>& threads, bool detail) {
    map::MapOptions opt = map_options(threads, detail);
    const io::Case k = map_case(c, speeds_rpm, torques_Nm, oil_temp_C, map::kMaxGridPoints);
    if (axes_only && axes_only->empty())
        throw InputError("", 0, 0, "axes", "empty: name the axes, e.g. ['mesh.friction', 'windage.form']");
    const auto axes = map::spread_axes(k.model, axes_only.value_or(std::vector<std::string>{}), "axes");
    if (axes.empty()) throw InputError(k.file, 0, 0, "spread", "no mechanism of this case has alternative forms");
    renaming_keys(kGridNames, [&] { map::require_spread_size(axes); });
    const std::string note = map::not_applicable_note(axes, map::not_applicable_combinations(k.model, axes));
    std::vector<solver::PointResult> results;
    map::SpreadResult spread;
    interruptible(opt, [&] {
        results = map::run_map(k.model, k.grid, opt);
        io::throw_if_interrupted();
        spread = map::run_spread(k.model, k.grid, axes, opt);
    });
    // The spread's cells go after the map's, before the row's end (as `map --spread`).
    auto with_spread = [](std::string line, const std::string& cells) {
        line.pop_back();
        return line + "," + cells + "\n";
    };
    std::string text = with_spread(map::csv_header(k.model, detail), map::spread_csv_header());
    for (size_t i = 0; i < results.size(); ++i)
        text += with_spread(map::csv_row(k.model, results[i], detail), map::spread_csv_cells(axes, spread.points[i]));
    py::dict out;
    out["csv"] = text;
    out["note"] = note;
    return out;
}

py::dict sweeps(const PyCase& c, const OptionalAxis& speeds_rpm, const OptionalAxis& torques_Nm,
                const std::optional<double>& oil_temp_C, const std::optional<int>& threads, bool detail) {
    map::MapOptions opt = map_options(threads, detail);
    const CaseSource& s = c.source;
    auto sweep = renaming_keys({{"--ratio", "ratio"}}, [&] {
        return s.text ? std::make_shared<io::Sweep>(io::Sweep::from_text(*s.text, s.name, s.base_dir, s.ratio))
                      : std::make_shared<io::Sweep>(s.path, s.ratio);
    });
    auto warnings = std::make_shared<std::vector<std::string>>();
    // A variant with the call's options (the CLI's with_options and --speed/--torque).
    auto load = [c, speeds_rpm, torques_Nm, oil_temp_C, warnings](io::Case v) {
        if (!c.oil_file.empty()) io::replace_oil_file(v, c.oil_file);
        if (oil_temp_C) {
            v.model.thermal.mode = solver::ThermalMode::fixed;
            v.model.thermal.oil_temperature = *oil_temp_C + kZeroCelsius;
        }
        check_loaded(v, c.oil_file, oil_temp_C ? "oil_temp_C" : "");
        v.grid = grid_of(v, speeds_rpm, torques_Nm);
        auto o = overrides(c, oil_temp_C, speeds_rpm, torques_Nm);
        o.max_points = map::kMaxStreamedPoints;
        map::validate_case(v, o);
        for (const auto& w : v.warnings)
            if (std::find(warnings->begin(), warnings->end(), w) == warnings->end()) warnings->push_back(w);
        return v;
    };
    require_values(speeds_rpm, torques_Nm);
    io::Case first = renaming_keys(kGridNames, [&] { return load(sweep->variant(0)); });
    std::optional<map::MapJob> job;
    if (sweep->axes().empty()) {
        std::vector<map::MapJob::Variant> one;
        one.push_back({{}, std::move(first)});
        job.emplace(std::vector<std::string>{}, std::move(one));
    } else {
        // An argument that sets what an axis sets is refused, as the CLI's options are.
        const map::SweepOverrides given{.oil = c.oil_file.empty() ? nullptr : "with_oil",
                                        .oil_temperature = oil_temp_C ? "oil_temp_C" : nullptr,
                                        .ratio = s.ratio ? "ratio" : nullptr,
                                        .speeds = speeds_rpm ? "speeds_rpm" : nullptr,
                                        .torques = torques_Nm ? "torques_Nm" : nullptr};
        job.emplace(map::sweep_job(sweep, first, load, given));
    }
    std::string text;
    interruptible(opt, [&] {
        map::run_job(*job, opt, std::nullopt, [&text](std::string_view t) { text += t; });
    });
    py::dict out;
    out["csv"] = text;
    out["warnings"] = *warnings;
    return out;
}

py::dict cycle(const PyCase& c, const std::string& cycle_name, double start_temp_C,
               const std::optional<double>& ambient_C, const std::optional<double>& prewarm_C, double heater_W,
               double warm_temp_C, bool trace) {
    const KeyNames names = {{"--cycle", "cycle"},         {"--start-temp", "start_temp_C"}, {"--ambient", "ambient_C"},
                            {"--prewarm", "prewarm_C"},   {"--heater", "heater_W"},         {"--warm-temp", "warm_temp_C"},
                            {"--oil", "with_oil"}};
    return renaming_keys(names, [&] {
        const auto pt = io::load_powertrain(c.k, std::nullopt);  // with_oil's oil already in c.k
        // A named cycle: the case's own cycles/ folder first, then the shipped cycles.
        const auto dc = io::resolve_cycle(
            cycle_name, {(std::filesystem::path(c.source.folder()) / "cycles").string()},
            [&] { return (io::data_dir("--cycle", "'" + cycle_name + "' is a shipped cycle") / "cycles").string(); });
        io::CycleStudyOptions so;
        so.start_temperature = start_temp_C + kZeroCelsius;
        so.ambient = ambient_C ? *ambient_C + kZeroCelsius : so.start_temperature;
        so.warm_temperature = warm_temp_C + kZeroCelsius;
        if (prewarm_C) so.prewarm_target = *prewarm_C + kZeroCelsius;
        so.heater_power = heater_W;
        so.keep_traces = false;
        py::dict out;
        io::CycleStudy study;
        std::string csv;
        {
            py::gil_scoped_release free;
            study = io::run_cycle_study(pt, dc, so);
            if (trace) io::write_cycle_trace(pt, dc, study, so, [&csv](std::string_view t) { csv += t; });
        }
        out["warning"] = io::engine_beyond_map_warning(study.cold.totals.engine_beyond_map);
        out["text"] = io::cycle_summary_text(pt, study, so);
        out["json"] = io::cycle_summary_json(pt, study, so);
        out["trace"] = csv;
        return out;
    });
}

}  // namespace gearloss::python
