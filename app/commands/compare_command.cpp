// gearloss compare: the same map for two oils and their differences per point (B - A).
#include "commands/command.hpp"
#include "commands/common.hpp"
#include "commands/grid_overrides.hpp"
#include "gearloss/core/errors.hpp"
#include "gearloss/io/atomic_file.hpp"
#include "gearloss/io/interrupt.hpp"
#include "gearloss/io/output_paths.hpp"
#include "gearloss/map/compare.hpp"
#include "gearloss/map/map_runner.hpp"

namespace gearloss::app {
namespace {

class CompareCommand final : public Command {
public:
    CLI::App* add_to(CLI::App& app) override {
        auto* s = app.add_subcommand("compare", "the same map for two oils and their differences per point (B - A)");
        s->add_option("config", common_.config, "gearbox case (YAML)")->required();
        s->add_option("--oil", oils_, "oil files A and B (give --oil twice)")->required();
        s->add_option("--ratio", common_.ratio, "select a ratio defined under gearbox.ratios");
        s->add_option("--oil-temp", common_.oil_temp, "fixed oil temperature (e.g. 70degC): no thermal solve");
        grid_.add_to(*s, "override the input speeds", "override the input torques");
        s->add_option("-o,--output", out_, "output CSV ('-' = stdout)");
        s->add_option("--threads", threads_, "threads (default: all cores)")->check(CLI::Range(1, 1024));
        s->footer("Example: gearloss compare configs/transfer-box.yaml --oil configs/oils/75W90-A.yaml "
                  "--oil configs/oils/75W140-A.yaml -o diff.csv");
        return s;
    }

    int run() override {
        std::vector<std::pair<std::string, std::string>> inputs = {{"config", common_.config}};
        for (const auto& f : oils_) inputs.emplace_back("--oil", f);
        io::require_outputs_not_inputs({{"--output", out_}}, inputs);
        if (oils_.size() != 2) throw InputError("", 0, 0, "--oil", "compare needs exactly two oils (--oil A --oil B)");
        io::Case base = load_with_options(common_);  // common_.oil stays empty: the two oils are --oil A and B
        grid_.apply(base, {"600,700rpm", "150,200Nm"});  // a point list with --speed/--torque: as map
        io::Case a = base, b = base;
        io::replace_oil(a, io::load_oil_file(oils_[0]));
        io::replace_oil(b, io::load_oil_file(oils_[1]));
        for (int i : {0, 1}) {  // each oil with the grid (gearloss/model/validate.hpp)
            map::CaseOverrides o = grid_.case_overrides();
            o.oil_temp = common_.oil_temp;
            o.oil = oils_[i];
            map::validate_case(i ? b : a, o);
        }
        map::MapOptions mo;
        mo.threads = threads_;
        ProgressMeter meter;
        mo.progress = meter.callback();
        const auto ra = map::run_map(a.model, a.grid, mo);
        io::throw_if_interrupted();  // not the second map
        const auto rb = map::run_map(b.model, b.grid, mo);
        if (!io::g_interrupted) {
            io::AtomicFile f(out_);
            f.write(map::compare_header(a.model.oil.name, b.model.oil.name));
            for (size_t i = 0; i < ra.size(); ++i) f.write(map::compare_row(ra[i], rb[i]));
            f.commit();
        }
        return kOk;
    }

private:
    CommonOptions common_;
    GridOverrides grid_;
    std::vector<std::string> oils_;
    std::string out_ = "-";
    int threads_ = 0;
};

}  // namespace

std::unique_ptr<Command> make_compare_command() { return std::make_unique<CompareCommand>(); }

}  // namespace gearloss::app
