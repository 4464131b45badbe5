#include "commands/map_table.hpp"

#include <chrono>
#include <cstdio>

#include "gearloss/core/errors.hpp"
#include "gearloss/io/atomic_file.hpp"
#include "gearloss/io/interrupt.hpp"
#include "gearloss/io/output_paths.hpp"
#include "gearloss/map/co2mpas_fit.hpp"
#include "gearloss/map/fingerprint.hpp"
#include "gearloss/map/loss_table.hpp"

#include <nlohmann/json.hpp>

namespace gearloss::app {
namespace {

constexpr GridOverrides::Examples kTableExamples{"1000,2000,3000rpm", "50,100,200Nm"};
// CO2MPAS's cold and hot reference temperatures (JRC 2019, defaults.py:
// gear_box_temperature_references = (40, 80) degC).
constexpr double kCo2mpasCold_K = 313.15, kCo2mpasHot_K = 353.15;

// The oil-temperature axis: --oil-temps, else --oil-temp (one temperature), else the default.
std::vector<double> temperature_axis(const TableRequest& q, const io::Case& k) {
    const bool co2mpas = q.format == "co2mpas";
    if (q.oil_temps_given && !q.common.oil_temp.empty())
        throw InputError("", 0, 0, "--oil-temp", "give --oil-temps (the table's axis) or --oil-temp, not both");
    if (co2mpas && !q.common.oil_temp.empty())
        throw InputError("", 0, 0, "--oil-temp", "--format co2mpas fits at two reference temperatures: give --oil-temps COLD,HOT");
    if (q.oil_temps_given) {
        if (q.oil_temps.empty()) throw InputError("", 0, 0, "--oil-temps", "empty: give e.g. 20,40,60,80degC");
        auto T = map::parse_temperature_list(q.oil_temps, "--oil-temps");
        if (co2mpas && T.size() != 2)
            throw InputError("", 0, 0, "--oil-temps",
                             "--format co2mpas takes exactly two temperatures, the cold and the hot reference (e.g. 40,80degC)");
        return T;
    }
    if (co2mpas) return {kCo2mpasCold_K, kCo2mpasHot_K};
    if (!q.common.oil_temp.empty()) return {k.model.thermal.oil_temperature};
    return map::default_table_temperatures(k.model);
}

}  // namespace

int run_table_format(const TableRequest& q) {
    const bool co2mpas = q.format == "co2mpas";
    if (co2mpas && !q.json.empty())
        throw InputError("", 0, 0, "--json", "--format co2mpas writes its JSON to -o; --json is the table's (--format table)");
    io::Case k = load_with_options(q.common);
    if (!k.sweep.empty()) {
        const SourceLocation at = io::case_location(k, "sweep");
        throw InputError(at.file, at.line, at.column, "sweep",
                         "--format " + q.format +
                             ": the case has a sweep; a table per variant is not written (set the variant's values in the case)");
    }
    {
        io::NamedFiles outputs{{"--output", q.out}, {"--json", q.json}};
        if (!co2mpas) outputs.push_back(sidecar_output("--output", q.out));
        io::require_safe_outputs(outputs, case_inputs(q.common.config, {{"--oil", q.common.oil}}));
    }
    q.grid.apply_checked(k, kTableExamples, map::kMaxTablePoints);
    std::vector<std::string> ratios;
    if (!q.common.ratio.empty()) ratios.push_back(k.model.ratio);
    const map::LossTableAxes axes = map::loss_table_axes(k, ratios, temperature_axis(q, k));
    // As --oil-temp does (case plausibility): a temperature above the oil's permissible one is
    // computed, but said.
    for (double T : axes.oil_temperatures)
        if (q.oil_temps_given && T > k.model.oil.max_temperature)
            std::fprintf(stderr, "warning: --oil-temps: %g degC is above the permissible oil temperature %g degC of oil '%s' "
                                 "(its 'max_temperature'); the table's rows there are extrapolated\n",
                         T - 273.15, k.model.oil.max_temperature - 273.15, k.model.oil.name.c_str());
    map::MapOptions opt;
    opt.threads = q.threads;
    ProgressMeter meter;
    opt.progress = meter.callback();
    const auto t0 = std::chrono::steady_clock::now();
    if (co2mpas) {
        const map::LossTable t = map::run_loss_table(k.model, axes, opt);
        write_file(q.out, map::co2mpas_json(t));
    } else {
        io::AtomicFile f(q.out);
        const std::string header = map::loss_table_csv_header(k.model);
        f.write(header);
        const map::LossTable t = map::run_loss_table(k.model, axes, opt, [&f](std::string_view s) { f.write(s); });
        f.commit();
        // The sidecar: the oil temperature is an axis of the table (fixed at each of its values).
        nlohmann::ordered_json thermal{{"mode", "fixed"}, {"oil_temperature_C", nullptr}, {"oil_temperatures_C", nlohmann::ordered_json::array()}};
        for (double T : axes.oil_temperatures) thermal["oil_temperatures_C"].push_back(T - 273.15);
        write_csv_sidecar(q.out, k, header, {.text_columns = {"ratio"}, .thermal = std::move(thermal), .ratios = axes.ratios});
        write_optional_file(q.json, map::loss_table_json(t));
    }
    io::throw_if_interrupted();
    if (q.stats) {
        const double s = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
        std::fprintf(stderr, "points %zu (%zu ratios x %zu speeds x %zu torques x %zu oil temperatures), %.4f s, %.0f points/s\n",
                     axes.size(), axes.ratios.size(), axes.speeds.size(), axes.torques.size(), axes.oil_temperatures.size(),
                     s, axes.size() / s);
    }
    return kOk;
}

}  // namespace gearloss::app
