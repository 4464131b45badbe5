// gearloss synth: synthetic recordings from the model with concealed effects and noise.
#include <fmt/format.h>

#include "commands/command.hpp"
#include "commands/common.hpp"
#include "commands/grid_overrides.hpp"
#include "gearloss/diagnosis/synth.hpp"
#include "gearloss/io/output_paths.hpp"

namespace gearloss::app {
namespace {

class SynthCommand final : public Command {
public:
    CLI::App* add_to(CLI::App& app) override {
        auto* s = app.add_subcommand("synth", "synthetic recordings from the model with concealed effects and noise");
        add_common_options(*s, common_);
        s->add_option("--effect", effects_, "concealed effect NAME=VALUE (repeatable), e.g. windage=30W, torque_sensor_gain=1.03, unstabilised_test=2");
        s->add_option("--noise-loss", noise_loss_, "loss noise, one standard deviation (default " + noise_loss_ + ")");
        s->add_option("--noise-temp", noise_temp_, "oil temperature noise, one standard deviation (default " + noise_temp_ + ")");
        s->add_option("--seed", seed_, "random seed");
        s->add_option("--format", format_, "steady (points) or log (0.5 Hz rig log)")->check(CLI::IsMember({"steady", "log"}));
        grid_.add_to(*s, "override the input speeds", "override the input torques");
        s->add_option("-o,--output", out_, "output CSV ('-' = stdout)");
        s->footer(diagnosis::effects_help() +
                  "\nExample: gearloss synth configs/transfer-box.yaml --effect windage=25W --seed 3 -o rec.csv");
        return s;
    }

    int run() override {
        io::require_safe_outputs({{"--output", out_}, sidecar_output("--output", out_)},
                                 case_inputs(common_.config, {{"--oil", common_.oil}}));
        io::Case k = load_with_options(common_);
        grid_.apply_checked(k, {"600,700rpm", "150,200Nm"});  // a point list with --speed/--torque: as map
        diagnosis::SynthOptions so;
        for (const auto& e : effects_) so.effects.push_back(diagnosis::parse_effect_assignment(k.model, e));
        so.noise_loss = single_value(noise_loss_, units::dim::none, "--noise-loss", "1.5%");
        so.noise_temp = temperature_difference(noise_temp_, "--noise-temp");
        so.seed = seed_;
        so.raw_log = format_ == "log";
        write_csv_file(out_, diagnosis::synthesize(k.model, k.grid, so), k);
        return kOk;
    }

private:
    CommonOptions common_;
    GridOverrides grid_;
    std::vector<std::string> effects_;
    std::string noise_loss_ = fmt::format("{:g}%", 100 * diagnosis::SynthOptions{}.noise_loss),
                noise_temp_ = fmt::format("{:g} K", diagnosis::SynthOptions{}.noise_temp), format_ = "steady", out_ = "-";
    unsigned seed_ = 1;
};

}  // namespace

std::unique_ptr<Command> make_synth_command() { return std::make_unique<SynthCommand>(); }

}  // namespace gearloss::app
