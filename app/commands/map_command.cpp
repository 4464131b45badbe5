// gearloss map: every operating point of the grid to CSV (sweeps, shards), or VECTO
// torque-loss tables per gear (--format vecto).
#include <algorithm>
#include <chrono>
#include <cstdio>
#include <optional>
#include <fmt/format.h>

#include "commands/command.hpp"
#include "commands/common.hpp"
#include "commands/grid_overrides.hpp"
#include "commands/map_table.hpp"
#include "gearloss/core/errors.hpp"
#include "gearloss/io/atomic_file.hpp"
#include "gearloss/io/interrupt.hpp"
#include "gearloss/io/output_paths.hpp"
#include "gearloss/case/sweep.hpp"
#include "gearloss/map/form_spread.hpp"
#include "gearloss/map/job.hpp"
#include "gearloss/map/map_runner.hpp"
#include "gearloss/map/map_stream.hpp"
#include "gearloss/map/vecto.hpp"

namespace gearloss::app {
namespace {

constexpr GridOverrides::Examples kMapExamples{"600,700,800rpm", "150,200,250Nm"};
constexpr GridOverrides::Examples kVectoExamples{"0,1000,2000rpm", "100,200,400Nm"};

double seconds_since(std::chrono::steady_clock::time_point t0) {
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
}

class MapCommand final : public Command {
public:
    CLI::App* add_to(CLI::App& app) override {
        auto* s = app.add_subcommand("map", "all operating points of the grid to CSV (parallel, written atomically)");
        add_common_options(*s, common_);
        s->add_option("-o,--output", out_, "output CSV file ('-' = stdout)");
        s->add_option("--threads", threads_, "threads (default: all cores)")->check(threads_check());
        s->add_flag("--detail", detail_, "add a column per mesh, gear, bearing and seal");
        s->add_flag("--stats", stats_, "print the map's time (solved, formatted and written), points per second and loss evaluations per point to stderr");
        grid_.add_to(*s, "override the input speeds, e.g. 600,700,800rpm", "override the input torques, e.g. 150,200,250Nm");
        s->add_option("--json", json_, "also write a JSON summary (counts, efficiency, loss and temperature ranges, the map's time)");
        s->add_option("--shard", shard_, "compute only shard K of N of the points (K/N, e.g. 3/16); join with `gearloss merge`");
        s->add_flag("--spread", spread_,
                    "also solve every combination of the mechanisms' alternative forms and add, per point, "
                    "P_total_min_W, P_total_max_W and the forms giving each");
        // One argument split here: CLI11's delimiter takes the next argument when the list is empty.
        spread_axes_option_ = s->add_option("--spread-axes", spread_axes_text_, "restrict --spread to these form axes, e.g. "
                                                          "mesh.friction,windage.form (see `gearloss check`)");
        s->add_option("--format", format_, "csv (loss breakdown), vecto (torque-loss table per gear, negative "
                                           "torques included), table (every ratio x speed x torque x oil temperature, "
                                           "CSV, and its lookup arrays with --json FILE) or co2mpas (the CO2MPAS "
                                           "gearbox-loss coefficients fitted to the map, JSON); docs/tables.md")
            ->check(CLI::IsMember({"csv", "vecto", "table", "co2mpas"}));
        oil_temps_option_ = s->add_option("--oil-temps", oil_temps_, "oil temperatures of --format table (default: 20 degC "
                                                                     "to the oil's limit in 20 K steps) or the cold and hot "
                                                                     "references of --format co2mpas (default 40,80degC); a list "
                                                                     "or a range, e.g. 20:120:20degC");
        s->footer("Examples:\n  gearloss map configs/transfer-box.yaml --speed 600,700,800rpm --torque 150,200,250Nm -o out.csv\n"
                  "  gearloss map configs/manual-6speed.yaml --format vecto --oil-temp 70degC -o manual.vtlm   "
                  "(manual_g1.vtlm ... manual_g6.vtlm)");
        return s;
    }

    int run() override {
        // --format vecto's per-gear files are checked once the case names its gears (run_vecto).
        io::require_safe_outputs(outputs(), case_inputs(common_.config, {{"--oil", common_.oil}}));
        const bool axes_given = spread_axes_option_ && spread_axes_option_->count() > 0;
        if (axes_given && spread_axes_text_.empty())
            throw InputError("", 0, 0, "--spread-axes", "empty: name the axes, e.g. mesh.friction,windage.form");
        spread_axes_ = split_axes(spread_axes_text_);
        if (axes_given && !spread_)
            throw InputError("", 0, 0, "--spread-axes", "give --spread as well");
        if (spread_ && format_ == "vecto")
            throw InputError("", 0, 0, "--spread", "--format vecto writes loss tables; the form spread is a csv column");
        if (spread_ && !shard_.empty())
            throw InputError("", 0, 0, "--spread", "a spread map cannot be sharded (every shard would solve every form)");
        if (format_ == "vecto" && !json_.empty())
            throw InputError("", 0, 0, "--json", "--format vecto writes loss tables only; the summary is a csv map's");
        if (format_ == "vecto" && !shard_.empty())
            throw InputError("", 0, 0, "--shard", "--format vecto writes whole tables per gear; it cannot be sharded");
        if (format_ == "table" || format_ == "co2mpas") return run_table();
        if (oil_temps_option_->count() > 0)
            throw InputError("", 0, 0, "--oil-temps", "an axis of --format table or co2mpas; give --oil-temp for one temperature");
        return format_ == "vecto" ? run_vecto() : run_csv();
    }

private:
    CommonOptions common_;
    GridOverrides grid_;
    std::string out_ = "-", json_, shard_, format_ = "csv";
    int threads_ = 0;
    bool detail_ = false, stats_ = false, spread_ = false;
    std::string spread_axes_text_;
    CLI::Option* spread_axes_option_ = nullptr;
    std::vector<std::string> spread_axes_;
    std::vector<std::pair<std::string, std::string>> named_;  // files the case names (key path, file)
    std::string oil_temps_;
    CLI::Option* oil_temps_option_ = nullptr;

    // --format table / co2mpas (commands/map_table.cpp): whole tables at fixed oil temperatures.
    int run_table() {
        for (const auto& [given, option] : {std::pair{spread_, "--spread"}, {!shard_.empty(), "--shard"}, {detail_, "--detail"}})
            if (given)
                throw InputError("", 0, 0, option, "--format " + format_ + " writes whole tables of totals and mechanisms; " +
                                                       option + " is a csv map's");
        return run_table_format({.common = common_, .grid = grid_, .format = format_, .out = out_, .json = json_,
                                 .oil_temps = oil_temps_, .oil_temps_given = oil_temps_option_->count() > 0,
                                 .threads = threads_, .stats = stats_});
    }

    // The files written: the CSV, its sidecar FILE.meta.json, the summary.
    std::vector<std::pair<std::string, std::string>> outputs() const {
        return {{"--output", out_}, sidecar_output("--output", out_), {"--json", json_}};
    }

    // "mesh.friction,windage.form" -> its axes; an empty name is an error naming the option.
    static std::vector<std::string> split_axes(const std::string& text) {
        std::vector<std::string> out;
        if (text.empty()) return out;
        for (size_t a = 0; a <= text.size();) {
            const size_t e = std::min(text.find(',', a), text.size());
            if (e == a)
                throw InputError("", 0, 0, "--spread-axes",
                                 fmt::format("'{}': an empty axis name (e.g. mesh.friction,windage.form)", text));
            out.push_back(text.substr(a, e - a));
            a = e + 1;
        }
        return out;
    }

    // One torque-loss table per gear (the selected ratio, or every ratio), from one loaded case.
    int run_vecto() {
        io::Case k = load_with_options(common_);
        if (!k.sweep.empty())
            throw InputError(k.file, 0, 0, "--format vecto", "the case has a sweep: a table per variant is not written "
                                                           "(set the variant's values in the case)");
        grid_.apply(k, kVectoExamples);  // a point list with --speed/--torque becomes a grid, as for csv
        if (!k.grid.is_grid) throw InputError(k.file, 0, 0, "operating", "--format vecto needs a speeds x torques grid");
        std::vector<std::string> ratios;
        if (!common_.ratio.empty() || k.model.gearbox.ratios.empty()) ratios.push_back(k.model.ratio);
        else ratios = k.model.ratio_names();
        if (ratios.size() > 1 && out_ == "-")
            throw InputError("", 0, 0, "--output", "several gears: give -o FILE (written as FILE_<ratio>.vtlm per gear)");
        // The files written, FILE_<ratio>.vtlm per gear and their sidecars, checked before the first table.
        std::vector<std::string> files;
        io::NamedFiles outputs;
        for (const auto& ratio : ratios) {
            std::string file = out_;
            if (ratios.size() > 1) {
                const bool vtlm = out_.size() > 5 && out_.substr(out_.size() - 5) == ".vtlm";
                const std::string stem = vtlm ? out_.substr(0, out_.size() - 5) : out_;
                file = stem + "_" + ratio + ".vtlm";
            }
            const std::string option = ratios.size() > 1 ? "--output (gear " + ratio + ")" : "--output";
            outputs.emplace_back(option, file);
            outputs.push_back(sidecar_output(option, file));
            files.push_back(file);
        }
        io::require_safe_outputs(outputs, case_inputs(common_.config, {{"--oil", common_.oil}}));
        map::MapOptions opt;
        opt.threads = threads_;
        for (size_t g = 0; g < ratios.size(); ++g) {
            const std::string& ratio = ratios[g];
            const std::string& file = files[g];
            if (!ratio.empty()) k.model.select_ratio(ratio);
            io::AtomicFile f(file);
            f.write(map::vecto_provenance(k));  // '#' lines, skipped by VECTO's reader
            std::string header;
            map::write_vecto_table(k.model, k.grid.speeds, k.grid.torques, opt, [&](std::string_view s) {
                if (header.empty()) header = map::header_line(s);
                f.write(s);
            });
            f.commit();
            write_csv_sidecar(file, k, header);
        }
        return kOk;
    }

    // The variants of the case's sweep, loaded one at a time with the command line's options
    // (`k`: the case itself, loaded with them). Unless an axis sets the operating points and
    // the command line does not fix them, every variant has k's grid: the job's rows are
    // counted and keyed without loading a variant.
    map::MapJob sweep_job(const io::Case& k, const std::shared_ptr<io::Sweep>& sweep) {
        const map::SweepOverrides given{.oil = common_.oil.empty() ? nullptr : "--oil",
                                        .oil_temperature = common_.oil_temp.empty() ? nullptr : "--oil-temp",
                                        .ratio = common_.ratio.empty() ? nullptr : "--ratio",
                                        .speeds = grid_.speeds_given() ? "--speed" : nullptr,
                                        .torques = grid_.torques_given() ? "--torque" : nullptr};
        return map::sweep_job(sweep, k, [this](io::Case c) {
            // Each variant's plausibility warnings too (io::print_warnings prints a text once).
            c = with_options(std::move(c), common_);
            grid_.apply_checked(c, kMapExamples, map::kMaxStreamedPoints);
            return c;
        }, given);
    }

    // The map streamed to its file: the case's grid, every sweep variant, or one shard of
    // the job (gearloss merge joins the shards).
    int run_job(io::Case k, const std::shared_ptr<io::Sweep>& sweep, const map::MapOptions& opt,
                std::optional<double> oil_temp) {
        io::Case described = k;  // the sidecar's case: the first variant, with the sweep's axes
        described.sweep = sweep->axes();
        std::optional<map::MapJob> job;
        if (sweep->axes().empty()) {
            std::vector<map::MapJob::Variant> one;
            one.push_back({{}, std::move(k)});
            job.emplace(std::vector<std::string>{}, std::move(one));
        } else {
            job.emplace(sweep_job(k, sweep));
        }
        std::optional<map::Shard> sh;
        if (!shard_.empty()) {
            sh = map::parse_shard(shard_);
            auto [document, sweep_block] = sweep->as_written();  // walked, not parsed again
            job->inputs = map::input_fingerprint({.config = common_.config, .oil_file = common_.oil, .oil_temperature = oil_temp,
                                                 .ratio = common_.ratio, .format = "csv", .detail = detail_,
                                                 .parsed = {{"", document}, {"sweep", sweep_block}}, .files = named_});
        }
        io::AtomicFile f(out_);
        map::MapSummary summary;
        const auto t0 = std::chrono::steady_clock::now();
        map::run_job(*job, opt, sh, [&f](std::string_view s) { f.write(s); }, &summary);
        io::throw_if_interrupted();
        const double seconds = seconds_since(t0);
        if (stats_) {
            const size_t n = summary.points();
            std::string of;
            if (sh || job->variant_count() > 1)
                of = fmt::format(" of {} ({} sweep variants)", job->total_points(), job->variant_count());
            std::fprintf(stderr, "points %zu%s, %.4f s (solved and written), %.0f points/s, %.2f loss evaluations/point, "
                         "%zu without equilibrium\n", n, of.c_str(), seconds, n / seconds,
                         n ? double(summary.evaluations()) / n : 0.0, summary.no_equilibrium());
        }
        f.commit();
        write_csv_sidecar(out_, described, job->header(detail_));
        write_optional_file(json_, summary.json(seconds));
        return kOk;
    }

    int run_csv() {
        // Parsed once: the case is the sweep's first variant (the case itself without a sweep),
        // and a sweep's variants and the job's fingerprint are built from the same document.
        const auto ratio = common_.ratio.empty() ? std::nullopt : std::optional<std::string>(common_.ratio);
        const auto sweep = std::make_shared<io::Sweep>(common_.config, ratio);
        auto [document, sweep_block] = sweep->as_written();
        named_ = map::named_files({.config = common_.config, .parsed = {{"", document}, {"sweep", sweep_block}}});
        io::Case k = with_options(sweep->variant(0), common_);
        grid_.apply_checked(k, kMapExamples, spread_ ? map::kMaxGridPoints : map::kMaxStreamedPoints);
        const auto oil_temp = common_.oil_temp.empty() ? std::nullopt : std::optional<double>(k.model.thermal.oil_temperature);
        map::MapOptions opt;
        opt.threads = threads_;
        opt.detail = detail_;
        ProgressMeter meter;
        opt.progress = meter.callback();
        if (spread_ && !sweep->axes().empty())
            throw InputError(k.file, 0, 0, "--spread", "a spread map of a sweep is not supported: spread one variant");
        if (!spread_) return run_job(std::move(k), sweep, opt, oil_temp);
        return run_spread(k, opt);
    }

    // The nominal map and, per point, the range over every form combination: the spread
    // solves each combination of each point, so the map is held whole, not streamed.
    int run_spread(const io::Case& k, const map::MapOptions& opt) {
        const auto axes = map::spread_axes(k.model, spread_axes_);
        if (axes.empty()) throw InputError(k.file, 0, 0, "--spread", "no mechanism of this case has alternative forms");
        map::require_spread_size(axes);  // before the nominal map, not after it
        const auto note = map::not_applicable_note(axes, map::not_applicable_combinations(k.model, axes));
        if (!note.empty()) std::fprintf(stderr, "gearloss: map --spread: %s\n", note.c_str());
        const auto t0 = std::chrono::steady_clock::now();
        const auto results = map::run_map(k.model, k.grid, opt);
        const double seconds = seconds_since(t0);
        io::throw_if_interrupted();
        map::MapSummary summary;
        for (const auto& r : results) summary.add(r);
        if (stats_)
            std::fprintf(stderr, "points %zu, solve %.4f s, %.0f points/s, %.2f loss evaluations/point, %zu without equilibrium\n",
                         results.size(), seconds, results.size() / seconds, double(summary.evaluations()) / results.size(),
                         summary.no_equilibrium());
        const map::SpreadResult spread = map::run_spread(k.model, k.grid, axes, opt);
        io::throw_if_interrupted();
        // The spread's cells go after the map's, before the row's end.
        auto with_spread = [](std::string line, const std::string& cells) {
            line.pop_back();
            return line + "," + cells + "\n";
        };
        io::AtomicFile f(out_);
        const std::string header = with_spread(map::csv_header(k.model, detail_), map::spread_csv_header());
        f.write(header);
        std::string buf;
        for (size_t i = 0; i < results.size(); ++i) {
            if ((i & 4095) == 0) io::throw_if_interrupted();
            buf += with_spread(map::csv_row(k.model, results[i], detail_), map::spread_csv_cells(axes, spread.points[i]));
            if (buf.size() >= (size_t{1} << 20)) {
                f.write(buf);
                buf.clear();
            }
        }
        f.write(buf);
        f.commit();
        write_csv_sidecar(out_, k, header, {.text_columns = {"forms_at_min", "forms_at_max"}, .units = {{"combinations_unsolved", "1"}}});
        write_optional_file(json_, summary.json(seconds, [&](nlohmann::ordered_json& j) { map::spread_summary_json(j, axes, spread, results); }));
        return kOk;
    }
};

}  // namespace

std::unique_ptr<Command> make_map_command() { return std::make_unique<MapCommand>(); }

}  // namespace gearloss::app
