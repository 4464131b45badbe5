// gearloss cycle: transient warm-up over a drive cycle from a cold start, against a warm start
// and (optionally) after pre-warming.
#include <cstdio>
#include <filesystem>
#include <optional>

#include "commands/command.hpp"
#include "commands/common.hpp"
#include "gearloss/io/atomic_file.hpp"
#include "gearloss/results/cycle_report.hpp"
#include "gearloss/io/data_dir.hpp"
#include "gearloss/case/drive_cycle_csv.hpp"
#include "gearloss/io/interrupt.hpp"
#include "gearloss/io/output_paths.hpp"
#include "gearloss/map/map_runner.hpp"
#include "gearloss/map/output_metadata.hpp"

namespace gearloss::app {
namespace {

class CycleCommand final : public Command {
public:
    CLI::App* add_to(CLI::App& app) override {
        auto* s = app.add_subcommand("cycle", "transient warm-up over a drive cycle from a cold start, against a warm start "
                                              "and (optionally) after pre-warming");
        s->add_option("config", config_, "gearbox case with a 'vehicle' block (YAML)")->required();
        s->add_option("--oil", oil_, "replace the case's oil by this oil file (YAML)");
        s->add_option("--cycle", cycle_, "nedc, wltc, artemis, artemis-urban, artemis-rural, artemis-motorway-130, "
                                         "artemis-motorway-150, or a CSV file (time_s,speed_kmh[,gear])")->required();
        s->add_option("--start-temp", start_temp_, "temperature of the whole transmission at the start (e.g. -10degC)")->required();
        s->add_option("--ambient", ambient_, "ambient temperature (default: the start temperature, a cold soak)");
        s->add_option("--prewarm", prewarm_, "pre-warm the oil to this temperature before the cycle (e.g. 90degC)");
        s->add_option("--heater", heater_, "pre-warming heater power (default 100W)");
        s->add_option("--warm-temp", warm_temp_, "temperature of the warm-start reference run (default 90degC)");
        s->add_option("-o,--output", out_, "time series CSV of the run from the start temperature, then the warm-start and "
                                           "pre-warmed runs' oil temperature and losses ('-' = stdout, after the summary)");
        s->add_option("--json", json_, "write the summary as JSON to this file");
        s->add_flag("--stats", stats_, "print the simulation time of one cycle run to stderr");
        s->footer("Example: gearloss cycle configs/automatic-6speed.yaml --cycle nedc --start-temp -10degC --prewarm 90degC "
                  "--heater 1kW -o trace.csv");
        return s;
    }

    int run() override {
        io::Case k = io::load_case(config_);
        map::CaseOverrides no_grid;  // a cycle has no operating grid
        no_grid.grid = false;
        map::validate_case(k, no_grid);
        const auto pt = io::load_powertrain(k, oil_.empty() ? std::nullopt : std::optional<std::string>(oil_));
        // A named cycle: the case's own cycles/ folder first, then the cycles gearloss ships,
        // looked up where the program runs (gearloss/io/data_dir.hpp) and only when needed.
        std::vector<std::string> cycle_files;
        const auto dc = io::resolve_cycle(
            cycle_, {(std::filesystem::path(config_).parent_path() / "cycles").string()},
            [&] { return (io::data_dir("--cycle", "'" + cycle_ + "' is a shipped cycle") / "cycles").string(); },
            &cycle_files);
        // Every file read, a named cycle's files (the case's cycles/ folder or the shipped ones)
        // included, is kept from the outputs, before the simulation.
        NamedPaths inputs = case_inputs(config_, {{"--oil", oil_}, {"--cycle", cycle_}});
        for (const auto& f : cycle_files) inputs.emplace_back("--cycle " + cycle_ + " (its file)", f);
        io::require_safe_outputs({{"--output", out_}, sidecar_output("--output", out_), {"--json", json_}}, inputs,
                                 true);  // the summary
        io::CycleStudyOptions so;
        so.start_temperature = absolute_temperature(start_temp_, "--start-temp");
        so.ambient = ambient_.empty() ? so.start_temperature : absolute_temperature(ambient_, "--ambient");
        so.warm_temperature = absolute_temperature(warm_temp_, "--warm-temp");
        if (!prewarm_.empty()) so.prewarm_target = absolute_temperature(prewarm_, "--prewarm");
        so.heater_power = single_value(heater_, units::dim::power, "--heater", "100W");
        so.keep_traces = false;  // -o streams its time series (io::write_cycle_trace)
        const auto study = io::run_cycle_study(pt, dc, so);
        io::throw_if_interrupted();
        // Once on stderr too, for scripts that keep only the files (the run from the start
        // temperature: the warm and pre-warmed runs ask less of a cold converter).
        if (const auto w = io::engine_beyond_map_warning(study.cold.totals.engine_beyond_map); !w.empty())
            std::fprintf(stderr, "gearloss: %s", w.c_str());
        io::write_stdout(io::cycle_summary_text(pt, study, so));
        if (stats_)
            std::fprintf(stderr, "cycle %s: %zu steps simulated in %.2f ms\n", dc.name.c_str(), dc.time.size() - 1,
                         1e3 * study.seconds_per_run);
        write_optional_file(json_, io::cycle_summary_json(pt, study, so));
        if (!out_.empty()) {
            // The sidecar's case: the case with --oil; a cycle's oil temperature is transient.
            io::Case described = k;
            if (!oil_.empty()) io::replace_oil_file(described, oil_);
            // Streamed: the runs simulated again, the rows written as they come (io::write_cycle_trace).
            io::AtomicFile f(out_);
            io::write_cycle_trace(pt, dc, study, so, [&](std::string_view text) { f.write(text); });
            f.commit();
            write_csv_sidecar(out_, described, map::header_line(io::cycle_trace_header(pt, study)),
                              {.thermal = {{"mode", "transient"}, {"oil_temperature_C", nullptr},
                                           {"start_temperature_C", so.start_temperature - 273.15},
                                           {"ambient_C", so.ambient - 273.15}},
                               .ratios = described.model.ratio_names()});
        }
        return kOk;
    }

private:
    std::string config_, oil_, cycle_, start_temp_, ambient_, prewarm_, heater_ = "100W", warm_temp_ = "90degC", out_, json_;
    bool stats_ = false;
};

}  // namespace

std::unique_ptr<Command> make_cycle_command() { return std::make_unique<CycleCommand>(); }

}  // namespace gearloss::app
