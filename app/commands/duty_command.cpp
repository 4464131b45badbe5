// gearloss duty: what a gearbox loses over its duty, a time-at-level load spectrum or a time
// series of input speed and torque (gearloss/duty/duty.hpp).
#include <cstdio>

#include "commands/command.hpp"
#include "commands/common.hpp"
#include "gearloss/duty/duty.hpp"
#include "gearloss/duty/duty_report.hpp"
#include "gearloss/duty/spectrum.hpp"
#include "gearloss/io/interrupt.hpp"
#include "gearloss/io/output_paths.hpp"
#include "gearloss/results/reports.hpp"

namespace gearloss::app {
namespace {

class DutyCommand final : public Command {
public:
    CLI::App* add_to(CLI::App& app) override {
        auto* s = app.add_subcommand("duty", "energy lost over a duty: a time-at-level load spectrum or a time series of "
                                             "input speed and torque (docs/duty.md)");
        add_common_options(*s, common_);
        s->add_option("spectrum", spectrum_, "CSV: speed_in_<unit>,torque_in_<unit> and hours, duration_<unit>, share or "
                                             "share_% (time at level), or time_<unit> (time series)")->required();
        s->add_option("-o,--output", out_, "per-bin (or per-interval) CSV ('-' = stdout, after the summary)");
        s->add_option("--json", json_, "write the summary as JSON to this file");
        s->add_option("--start-temp", start_temp_, "time series: oil (and housing) temperature at the start (default: "
                                                   "the ambient)");
        s->add_option("--ambient", ambient_, "ambient temperature (default: the case's thermal.ambient)");
        total_time_option_ = s->add_option("--total-time", total_time_, "time the shares of a share column are scaled to (default 1h)");
        s->footer("Examples:\n  gearloss duty configs/wind-turbine-2.5MW.yaml configs/spectra/wind-2.5MW-weibull.csv -o duty.csv\n"
                  "  gearloss duty configs/transfer-box.yaml run.csv --start-temp 20degC --json duty.json");
        return s;
    }

    int run() override {
        io::Case k = load_with_options(common_);
        io::require_safe_outputs({{"--output", out_}, sidecar_output("--output", out_), {"--json", json_}},
                                 case_inputs(common_.config, {{"--oil", common_.oil}, {"spectrum", spectrum_}}),
                                 true);  // the summary
        if (!ambient_.empty()) k.model.thermal.ambient = absolute_temperature(ambient_, "--ambient", "25degC");
        const double total = single_value(total_time_, units::dim::time, "--total-time", "8760h");
        const duty::Spectrum s = duty::read_spectrum(spectrum_, total);
        for (const auto& w : s.warnings) std::fprintf(stderr, "gearloss: warning: %s\n", w.c_str());
        if (s.kind == duty::SpectrumKind::time_at_level && !start_temp_.empty())
            throw InputError("", 0, 0, "--start-temp", "a time series' option; a time-at-level spectrum is solved at each "
                                                       "bin's stabilised (or the fixed) oil temperature");
        if (s.kind == duty::SpectrumKind::time_series && total_time_option_->count() > 0)
            throw InputError("", 0, 0, "--total-time", "the shares of a time-at-level spectrum are scaled to it; a time "
                                                       "series has its own times");
        const double ambient = k.model.thermal.ambient;
        const duty::DutyResult d =
            s.kind == duty::SpectrumKind::time_at_level
                ? duty::run_time_at_level(k, s)
                : duty::run_time_series(k, s, start_temp_.empty() ? ambient : absolute_temperature(start_temp_, "--start-temp"),
                                        ambient);
        io::throw_if_interrupted();
        io::write_stdout(duty::duty_summary_text(d, s));
        write_optional_file(json_, duty::duty_summary_json(d, s));
        if (!out_.empty()) {
            nlohmann::ordered_json thermal;
            if (d.kind == duty::SpectrumKind::time_series && d.transient)
                thermal = {{"mode", "transient"}, {"oil_temperature_C", nullptr},
                           {"start_temperature_C", d.start_temperature - 273.15}, {"ambient_C", d.ambient - 273.15}};
            write_csv_file(out_, duty::duty_csv(d), k,
                           {.text_columns = {}, .units = {{"line", "1"}, {"above_oil_limit", "1"}}, .thermal = thermal});
        }
        return kOk;
    }

private:
    CLI::Option* total_time_option_ = nullptr;
    CommonOptions common_;
    std::string spectrum_, out_, json_, start_temp_, ambient_, total_time_ = "1h";
};

}  // namespace

std::unique_ptr<Command> make_duty_command() { return std::make_unique<DutyCommand>(); }

}  // namespace gearloss::app
