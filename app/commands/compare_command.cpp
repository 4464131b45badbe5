// gearloss compare: the same map for two or more oils and their differences per point (oil k - oil A).
#include <fmt/format.h>

#include "commands/command.hpp"
#include "commands/common.hpp"
#include "commands/grid_overrides.hpp"
#include "gearloss/core/errors.hpp"
#include "gearloss/io/atomic_file.hpp"
#include "gearloss/io/interrupt.hpp"
#include "gearloss/io/output_paths.hpp"
#include "gearloss/map/compare_oils.hpp"
#include "gearloss/map/map_runner.hpp"

namespace gearloss::app {
namespace {

// compare streams its CSV a block of points at a time (per oil: ~0.5 kB a point).
constexpr size_t kComparePointsPerBlock = 16384;
// compare --json holds every point of every oil (and writes each): at most this many points.
constexpr size_t kMaxJsonPoints = 1'000'000;

class CompareCommand final : public Command {
public:
    CLI::App* add_to(CLI::App& app) override {
        auto* s = app.add_subcommand("compare", "the same map for two or more oils and their differences per point "
                                                "(oil k - the first oil)");
        s->add_option("config", common_.config, "gearbox case (YAML)")->required();
        s->add_option("--oil", oils_, "oil files: the reference A first, then each oil compared with it (give --oil "
                                      "two or more times)")->required();
        s->add_option("--ratio", common_.ratio, "select a ratio defined under gearbox.ratios");
        s->add_option("--oil-temp", common_.oil_temp, "fixed oil temperature (e.g. 70degC): no thermal solve");
        grid_.add_to(*s, "override the input speeds", "override the input torques");
        s->add_option("-o,--output", out_, "output CSV ('-' = stdout)");
        s->add_option("--threads", threads_, "threads (default: all cores)")->check(threads_check());
        s->add_flag("--detail", detail_, "add each mechanism's loss per oil and its difference to the first oil");
        s->add_option("--json", json_, "also write the comparison as JSON (summary per oil and every point) to this file");
        s->footer("Example: gearloss compare configs/transfer-box.yaml --oil configs/oils/75W90-A.yaml "
                  "--oil configs/oils/75W140-A.yaml -o diff.csv");
        return s;
    }

    int run() override {
        NamedPaths inputs = case_inputs(common_.config);
        for (const auto& f : oils_) inputs.emplace_back("--oil", f);
        const std::vector<std::pair<std::string, std::string>> outputs = {
            {"--output", out_}, sidecar_output("--output", out_), {"--json", json_}};
        io::require_safe_outputs(outputs, inputs);
        if (oils_.size() < 2) throw InputError("", 0, 0, "--oil", "compare needs two or more oils (--oil A --oil B ...)");
        io::Case base = load_with_options(common_);  // common_.oil stays empty: the oils are the --oil files
        grid_.apply(base, {"600,700rpm", "150,200Nm"});  // a point list with --speed/--torque: as map
        std::vector<io::Case> cases(oils_.size(), base);
        for (size_t i = 0; i < oils_.size(); ++i) {
            io::replace_oil_file(cases[i], oils_[i]);
            map::CaseOverrides o = grid_.case_overrides();  // each oil with the grid (gearloss/model/validate.hpp)
            o.oil_temp = common_.oil_temp;
            o.oil = oils_[i];
            map::validate_case(cases[i], o);
        }
        // The CSV is streamed: the oils are solved a block of points at a time (each point is
        // solved on its own, so the rows are those of whole maps), memory holds one block per
        // oil. --json lists every point of every oil: those maps are held, up to kMaxJsonPoints.
        const io::OperatingGrid& grid = cases[0].grid;
        const size_t n = grid.size();
        const bool hold = !json_.empty();
        if (hold && n > kMaxJsonPoints)
            throw InputError("", 0, 0, "--json",
                             fmt::format("{} points: compare --json lists every point of every oil and holds them in "
                                         "memory; give at most {} (the CSV alone streams any grid)",
                                         n, kMaxJsonPoints));
        map::MapOptions mo;
        mo.threads = threads_;
        ProgressMeter meter;
        const auto progress = meter.callback();
        std::vector<std::vector<solver::PointResult>> maps(cases.size());
        std::vector<std::string> names;
        map::MetadataRequest meta;
        for (size_t i = 0; i < cases.size(); ++i) {
            names.push_back(cases[i].model.oil.name);
            meta.oils.push_back({cases[i].model.oil, oils_[i]});
        }
        // The metadata's case: the first oil's (its assumed values); "oils" lists every oil.
        const auto& m = cases[0].model;
        const std::string header = map::compare_oils_header(m, names, detail_);
        io::AtomicFile f(out_);
        f.write(header);
        std::vector<const solver::PointResult*> row(cases.size());
        std::vector<std::vector<solver::PointResult>> part(cases.size());
        std::string text;
        for (size_t b0 = 0; b0 < n; b0 += kComparePointsPerBlock) {
            const size_t b1 = std::min(n, b0 + kComparePointsPerBlock);
            io::OperatingGrid block;
            block.is_grid = false;
            for (size_t i = b0; i < b1; ++i) block.points.push_back(grid.at(i));
            for (size_t k = 0; k < cases.size(); ++k) {
                if (progress)  // a terminal only
                    mo.progress = [&, k, b0, b1](size_t done, size_t) {
                        progress(b0 * cases.size() + k * (b1 - b0) + done, cases.size() * n);
                    };
                part[k] = map::run_map(cases[k].model, block, mo);
                io::throw_if_interrupted();  // not the next oil
            }
            text.clear();
            for (size_t i = 0; i < block.points.size(); ++i) {
                for (size_t k = 0; k < part.size(); ++k) row[k] = &part[k][i];
                text += map::compare_oils_row(m, row, detail_);
            }
            f.write(text);
            if (hold)
                for (size_t k = 0; k < part.size(); ++k) maps[k].insert(maps[k].end(), part[k].begin(), part[k].end());
        }
        f.commit();
        write_csv_sidecar(out_, cases[0], header, meta);
        if (!json_.empty()) {
            meta.command = command_line().size() > 1 ? command_line()[1] : "compare";
            meta.command_line = command_line();
            meta.columns.clear();
            write_file(json_, map::json_text(map::compare_json(m, names, maps, map::output_metadata(cases[0], meta))));
        }
        return kOk;
    }

private:
    CommonOptions common_;
    GridOverrides grid_;
    std::vector<std::string> oils_;
    std::string out_ = "-", json_;
    int threads_ = 0;
    bool detail_ = false;
};

}  // namespace

std::unique_ptr<Command> make_compare_command() { return std::make_unique<CompareCommand>(); }

}  // namespace gearloss::app
