// gearloss mesh-profile: local thermal-EHL state along the path of contact of one mesh (CSV).
#include "commands/command.hpp"
#include "commands/common.hpp"
#include "commands/grid_overrides.hpp"
#include "gearloss/core/errors.hpp"
#include "gearloss/io/output_paths.hpp"
#include "gearloss/results/reports.hpp"

namespace gearloss::app {
namespace {

class MeshProfileCommand final : public Command {
public:
    CLI::App* add_to(CLI::App& app) override {
        auto* s = app.add_subcommand("mesh-profile", "local thermal-EHL state along the path of contact of one mesh (CSV)");
        add_common_options(*s, common_);
        s->add_option("--mesh", mesh_, "mesh name (see `gearloss check`)")->required();
        s->add_option("--speed", speed_, "input speed, e.g. 1600rpm")->required();
        s->add_option("--torque", torque_, "input torque, e.g. 720Nm")->required();
        s->add_option("--positions", positions_, "positions along the path")->check(CLI::Range(3, 2000));
        s->add_option("-o,--output", out_, "output CSV ('-' = stdout)");
        s->footer("Example: gearloss mesh-profile configs/spur-seed000.yaml --mesh m --speed 1600rpm --torque 720Nm");
        return s;
    }

    int run() override {
        io::require_safe_outputs({{"--output", out_}, sidecar_output("--output", out_)},
                                 case_inputs(common_.config, {{"--oil", common_.oil}}));
        io::Case k = load_with_options(common_);
        const double w = point_speed(speed_, "1600rpm");
        const double T = point_torque(torque_, "720Nm");
        const auto r = solver::solve_point(k.model, w, T);
        if (!solver::has_values(r.status))
            throw InputError("", 0, 0, "--speed", solver::status_text(r) + " at this point (give --oil-temp)");
        write_csv_file(out_, io::mesh_profile_csv(k, mesh_, w, T, r.oil_temperature, positions_), k);
        return kOk;
    }

private:
    CommonOptions common_;
    std::string mesh_, speed_, torque_, out_ = "-";
    int positions_ = 41;
};

}  // namespace

std::unique_ptr<Command> make_mesh_profile_command() { return std::make_unique<MeshProfileCommand>(); }

}  // namespace gearloss::app
