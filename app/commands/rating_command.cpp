// gearloss rating: the thermal power limit per input speed (ISO/TR 14179-1/-2), and the heat a
// cooler must remove to hold a target oil temperature.
#include "commands/command.hpp"
#include "commands/common.hpp"
#include "commands/grid_overrides.hpp"
#include "gearloss/io/atomic_file.hpp"
#include "gearloss/io/output_paths.hpp"
#include "gearloss/results/rating_report.hpp"
#include "gearloss/map/map_runner.hpp"
#include "gearloss/model/validate.hpp"

namespace gearloss::app {
namespace {

class RatingCommand final : public Command {
public:
    CLI::App* add_to(CLI::App& app) override {
        auto* s = app.add_subcommand("rating", "thermal power limit per input speed, and the cooler duty at a target "
                                               "oil temperature");
        s->add_option("config", common_.config, "gearbox case (YAML) with a stabilised thermal block")->required();
        s->add_option("--ratio", common_.ratio, "select a ratio defined under gearbox.ratios");
        s->add_option("--oil", common_.oil, "replace the case's oil by this oil file (YAML)");
        grid_.add_to(*s, "input speeds of the curve (or of the cooler duty) instead of the case's",
                     "input torques of the cooler duty instead of the case's");
        s->add_option("--oil-limit", oil_limit_, "permissible oil temperature (default: the oil's, as the map's "
                                                 "above_oil_limit uses)");
        s->add_option("--ambient", ambient_, "ambient temperature (default: the case's)");
        s->add_option("--max-torque", max_torque_, "highest input torque searched (default: 10 x the grid's largest)");
        s->add_option("--target-oil-temp", target_, "instead of the limit curve: at each grid point, the heat a cooler "
                                                    "must remove to hold the oil at this temperature");
        s->add_option("-o,--output", out_, "CSV of the curve (or of the cooler duty) ('-' = stdout)");
        s->add_option("--json", json_, "write the result as JSON to this file ('-' = stdout)");
        s->footer("Example: gearloss rating configs/transfer-box.yaml --oil-limit 95degC -o rating.csv\n"
                  "         gearloss rating configs/transfer-box.yaml --speed 300:3000:100rpm\n"
                  "         gearloss rating configs/wind-turbine-2.5MW.yaml --target-oil-temp 60degC");
        return s;
    }

    int run() override {
        io::Case k = load_with_options(common_);
        grid_.apply_checked(k, {"300:3000:100rpm", "50:400:50Nm"});
        const bool text = out_ != "-" && json_ != "-";
        io::require_safe_outputs({{"--output", out_}, sidecar_output("--output", out_), {"--json", json_}},
                                 case_inputs(common_.config, {{"--oil", common_.oil}}), text);
        io::RatingStudy s;
        auto& o = s.options;
        o.oil_limit = oil_limit_.empty() ? k.model.oil.max_temperature : absolute_temperature(oil_limit_, "--oil-limit", "95degC");
        o.ambient = ambient_.empty() ? k.model.thermal.ambient : absolute_temperature(ambient_, "--ambient", "25degC");
        const double largest = io::largest_torque(k.grid);
        o.start_torque = largest > 0 ? largest : 100.0;
        o.max_torque = max_torque_.empty() ? std::min(10.0 * o.start_torque, solver::kMaxTorque_Nm)
                                           : single_value(max_torque_, units::dim::torque, "--max-torque", "5000Nm");
        if (!(o.max_torque > 0 && o.max_torque <= solver::kMaxTorque_Nm))
            throw InputError("", 0, 0, "--max-torque", "must be positive and at most 1e8 N m");
        if (!(o.oil_limit > o.ambient))
            throw InputError("", 0, 0, "--oil-limit", "the permissible oil temperature must be above the ambient");
        if (!target_.empty()) {
            s.target = absolute_temperature(target_, "--target-oil-temp", "60degC");
            for (size_t i = 0; i < k.grid.size(); ++i) {
                const auto [w, t] = k.grid.at(i);
                s.duty.push_back(rating::cooler_duty(k.model, w, t, s.target, o.ambient));
            }
        } else {
            if (k.model.thermal.mode != solver::ThermalMode::stabilised)
                throw InputError(k.file, 0, 0, "thermal.mode",
                                 "a thermal rating needs the stabilised oil temperature (mode: stabilised); "
                                 "--target-oil-temp gives the cooler duty of a case at a fixed temperature");
            for (double w : io::rating_speeds(k.grid)) s.curve.push_back(rating::rate_speed(k.model, w, o));
        }
        if (text) io::write_stdout(io::rating_text(k, s));
        if (!out_.empty()) {
            map::MetadataRequest meta;
            meta.command = "rating";
            meta.command_line = command_line();
            meta.text_columns = {"rating"};
            write_csv_file(out_, io::rating_csv(k, s), k, std::move(meta));
        }
        write_optional_file(json_, io::rating_json(k, s));
        return kOk;
    }

private:
    CommonOptions common_;
    GridOverrides grid_;
    std::string oil_limit_, ambient_, max_torque_, target_, out_, json_;
};

}  // namespace

std::unique_ptr<Command> make_rating_command() { return std::make_unique<RatingCommand>(); }

}  // namespace gearloss::app
