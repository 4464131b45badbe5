// gearloss point: one operating point, every component's loss, temperatures and films.
#include "commands/command.hpp"
#include "commands/common.hpp"
#include "commands/grid_overrides.hpp"
#include "gearloss/io/atomic_file.hpp"
#include "gearloss/results/reports.hpp"
#include "gearloss/map/map_runner.hpp"
#include "gearloss/map/point_json.hpp"

namespace gearloss::app {
namespace {

class PointCommand final : public Command {
public:
    CLI::App* add_to(CLI::App& app) override {
        auto* s = app.add_subcommand("point", "one operating point: every component's loss, temperatures and films");
        add_common_options(*s, common_);
        s->add_option("--speed", speed_, "input speed, e.g. 800rpm")->required();
        s->add_option("--torque", torque_, "input torque, e.g. 250Nm")->required();
        s->add_option("--json", json_, "write the point as JSON to this file ('-' = stdout, instead of the text)");
        s->footer("Example: gearloss point configs/transfer-box.yaml --speed 800rpm --torque 250Nm --json point.json");
        return s;
    }

    int run() override {
        io::Case k = load_with_options(common_);  // first: its reader bounds what a hostile case can cost
        io::require_safe_outputs({{"--json", json_}}, case_inputs(common_.config, {{"--oil", common_.oil}}), json_ != "-");
        const double w = point_speed(speed_, "800rpm");
        const double T = point_torque(torque_, "250Nm");
        map::validate_point(w, T);
        const auto r = solver::solve_point(k.model, w, T, true);
        if (json_ != "-") io::write_stdout(io::point_report(k, r));
        if (!json_.empty()) {
            map::MetadataRequest meta;
            meta.command = "point";
            meta.command_line = command_line();
            write_file(json_, map::json_text(map::point_json(k, r, map::output_metadata(k, meta))));
        }
        return kOk;
    }

private:
    CommonOptions common_;
    std::string speed_, torque_, json_;
};

}  // namespace

std::unique_ptr<Command> make_point_command() { return std::make_unique<PointCommand>(); }

}  // namespace gearloss::app
