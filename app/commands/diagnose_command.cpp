// gearloss diagnose: recordings against the model, the mismatch located and the missing
// physics named.
#include <cstdio>
#include <filesystem>
#include <stdexcept>
#include <unistd.h>

#include "commands/command.hpp"
#include "commands/common.hpp"
#include "gearloss/core/errors.hpp"
#include "gearloss/diagnosis/diagnose.hpp"
#include "gearloss/io/atomic_file.hpp"
#include "gearloss/io/output_paths.hpp"
#include "gearloss/units/units.hpp"

namespace gearloss::app {
namespace {

class DiagnoseCommand final : public Command {
public:
    CLI::App* add_to(CLI::App& app) override {
        auto* s = app.add_subcommand("diagnose", "compare recordings with the model, locate the mismatch, name the missing physics");
        add_common_options(*s, common_);
        s->add_option("recordings", recordings_, "recordings CSV: steady points or a raw rig log (time_s column)")->required();
        s->add_option("--json", json_, "write the diagnosis as JSON to this file");
        s->add_option("--write-config", write_config_, "write the calibrated case file");
        s->add_option("--residuals", residuals_, "write per-point residuals before/after (CSV, for scripts/plot.sh diagnose)");
        s->add_option("--bootstrap", bootstrap_, "bootstrap resamples for the stability check")->check(CLI::Range(4, 1000));
        s->add_option("--threads", threads_, "threads (default: all cores)")->check(threads_check());
        s->add_option("--loss-uncertainty", loss_uncertainty_,
                      "measurement noise of the loss, one standard deviation (e.g. 1.5%); default: estimated from the "
                      "recordings (replicates or neighbouring points)");
        s->add_option("--temp-uncertainty", temp_uncertainty_,
                      "measurement noise of the oil temperature, one standard deviation (e.g. 0.4K); default: estimated");
        s->add_flag("--quiet", quiet_, "no progress messages on a terminal");
        s->footer("Example: gearloss diagnose configs/transfer-box.yaml recordings.csv --json diag.json --write-config calibrated.yaml");
        return s;
    }

    int run() override {
        io::Case k = load_with_options(common_);
        const auto rec = diagnosis::read_recordings(recordings_);
        // Every file read (the case and the files it names, --oil, the recordings and the oil
        // files of their `oil` column) is kept from the outputs, before the fit.
        NamedPaths inputs = case_inputs(common_.config, {{"--oil", common_.oil}, {"recordings", recordings_}});
        const std::filesystem::path dir = std::filesystem::path(recordings_).parent_path();
        for (const auto& p : rec.points)
            if (!p.oil.empty())  // relative to the recordings file, as diagnosis::campaign_oils reads it
                inputs.emplace_back("named in the recordings' oil column (line " + std::to_string(p.line) + ")",
                                    std::filesystem::path(p.oil).is_absolute() ? p.oil : (dir / p.oil).string());
        io::require_safe_outputs({{"--json", json_}, {"--residuals", residuals_}, sidecar_output("--residuals", residuals_),
                                  {"--write-config", write_config_}},
                                 inputs, true);  // the diagnosis text
        diagnosis::DiagnoseOptions opt;
        opt.bootstrap = bootstrap_;
        opt.threads = threads_;
        if (!loss_uncertainty_.empty())
            opt.loss_uncertainty = single_value(loss_uncertainty_, units::dim::none, "--loss-uncertainty", "1.5%");
        if (!temp_uncertainty_.empty()) opt.temp_uncertainty = temperature_difference(temp_uncertainty_, "--temp-uncertainty");
        // Progress on a terminal only: scripts and files get the result alone.
        const bool tty = !quiet_ && ::isatty(STDERR_FILENO);
        if (tty)
            opt.progress = [](const std::string& what) {
                std::fputs(("\r\033[K" + what).c_str(), stderr);
                std::fflush(stderr);
            };
        diagnosis::Diagnosis d;
        try {
            d = diagnosis::diagnose(k.model, rec, opt);
        } catch (const InputError& e) {
            if (!e.file.empty() || e.where().known()) throw;
            throw InputError(recordings_, 0, 0, e.key, e.message);  // about the recordings as a whole
        }
        if (tty) std::fputs("\r\033[K", stderr);
        // On stderr too, as every command warns: the report's own list is at its end, after the
        // candidates, where a script piping stdout would never see an ignored column.
        for (const auto& w : d.warnings) std::fprintf(stderr, "gearloss: warning: %s\n", w.c_str());
        io::write_stdout(diagnosis::diagnosis_text(d));
        write_optional_file(json_, diagnosis::diagnosis_json(d));
        if (!residuals_.empty()) write_csv_file(residuals_, diagnosis::residuals_csv(d), k);
        if (!write_config_.empty()) diagnosis::write_calibrated_config(common_.config, write_config_, d);
        return kOk;
    }

private:
    CommonOptions common_;
    std::string recordings_, json_, write_config_, residuals_;
    std::string loss_uncertainty_, temp_uncertainty_;
    int bootstrap_ = 24, threads_ = 0;
    bool quiet_ = false;
};

}  // namespace

std::unique_ptr<Command> make_diagnose_command() { return std::make_unique<DiagnoseCommand>(); }

}  // namespace gearloss::app
