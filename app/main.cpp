// gearloss command-line interface: a thin layer over the library.
#include <CLI/CLI.hpp>
#include <chrono>
#include <csignal>
#include <cstdlib>
#include <functional>
#include <filesystem>
#include <cstdio>
#include <fmt/format.h>
#include <unistd.h>

#include "core/errors.hpp"
#include "diagnosis/diagnose.hpp"
#include "diagnosis/synth.hpp"
#include "io/atomic_file.hpp"
#include "io/interrupt.hpp"
#include "io/case_plausibility.hpp"
#include "io/config.hpp"
#include "io/cycle_report.hpp"
#include "io/reports.hpp"
#include "map/compare.hpp"
#include "io/sweep.hpp"
#include "map/job.hpp"
#include "map/map_runner.hpp"
#include "map/vecto.hpp"
#include "units/units.hpp"

namespace {

// Exit codes (README "Exit codes").
enum Exit : int {
    kOk = 0,
    kUsage = 1,
    kInput = 2,
    kOutput = 3,
    kInternal = 4,  // 130 / 143 on SIGINT / SIGTERM: io::interrupt_exit_code() (io/interrupt.hpp)
};

using gearloss::InputError;
namespace io = gearloss::io;

struct Common {
    std::string config;
    std::string ratio;
    std::string oil_temp;
    std::string oil;
};

// --oil and --oil-temp applied to a loaded case.
void apply_overrides(io::Case& k, const Common& c) {
    if (!c.oil.empty()) io::replace_oil(k, io::load_oil_file(c.oil));
    if (!c.oil_temp.empty()) {
        gearloss::units::Quantity q;
        try {
            q = gearloss::units::parse_quantity(c.oil_temp);
        } catch (const gearloss::units::UnitError& e) {
            throw InputError("", 0, 0, "--oil-temp", e.msg + " (expected e.g. '70degC')");
        }
        if (!q.absolute_temperature || q.value <= 0)
            throw InputError("", 0, 0, "--oil-temp", "'" + io::excerpt(c.oil_temp) + "' is not a temperature (e.g. '70degC')");
        k.model.thermal.mode = gearloss::solver::ThermalMode::fixed;
        k.model.thermal.oil_temperature = q.value;
    }
    gearloss::map::validate_case(k, {.oil_temp = c.oil_temp, .oil = c.oil, .grid = false});  // solver/validate.hpp
}

// `check` lists the plausibility warnings in its report; every other command prints them on stderr.
io::Case load(const Common& c, bool warn_on_stderr = true) {
    std::optional<std::string> ratio;
    if (!c.ratio.empty()) ratio = c.ratio;
    io::Case k = io::load_case(c.config, ratio);
    apply_overrides(k, c);
    io::check_oil_temperature(k, c.oil_temp.empty() ? "" : "--oil-temp");
    if (warn_on_stderr) io::print_warnings(k);
    return k;
}

// "-10degC", "263.15 K": an absolute temperature [K].
double absolute_temperature(const std::string& text, const char* what) {
    gearloss::units::Quantity q;
    try {
        q = gearloss::units::parse_quantity(text);
    } catch (const gearloss::units::UnitError& e) {
        throw InputError("", 0, 0, what, e.msg + " (expected e.g. '-10degC')");
    }
    if (!q.absolute_temperature || !(q.value > 0))
        throw InputError("", 0, 0, what, "'" + io::excerpt(text) + "' is not a temperature (e.g. '-10degC')");
    return q.value;
}

double single_value(const std::string& text, const gearloss::units::Dimension& d, const char* what, const char* ex) {
    const auto v = io::parse_value_list(text, d, what, ex);
    if (v.size() != 1) throw InputError("", 0, 0, what, "expected one value");
    return v[0];
}

// "0.4K", "0.4 degC": a temperature difference (the unit's offset removed).
double temperature_difference(const std::string& text, const char* what) {
    size_t u = 0;
    // The number ends where the unit starts ("1e2K": the exponent belongs to the number).
    const auto exponent = [&](size_t i) {
        return (text[i] == 'e' || text[i] == 'E') && i > 0 && i + 1 < text.size() &&
               (std::isdigit(static_cast<unsigned char>(text[i + 1])) || text[i + 1] == '+' || text[i + 1] == '-');
    };
    while (u < text.size() && (std::isdigit(static_cast<unsigned char>(text[u])) || text[u] == '.' || text[u] == ' ' ||
                               text[u] == '+' || text[u] == '-' || exponent(u)))
        ++u;
    try {
        const auto f = gearloss::units::parse_unit(text.substr(u));
        const auto q = gearloss::units::parse_quantity(text);
        if (f.dim != gearloss::units::dim::temperature) throw gearloss::units::UnitError("not a temperature difference");
        return q.value - f.offset;
    } catch (const gearloss::units::UnitError& e) {
        throw InputError("", 0, 0, what, "'" + io::excerpt(text) + "': " + e.msg + " (expected e.g. '0.4K')");
    }
}

// Progress on stderr for long runs: only on a terminal, only once a run has lasted
// GEARLOSS_PROGRESS_AFTER seconds (default 1), at most 5 updates a second.
class ProgressMeter {
public:
    ProgressMeter() : enabled_(::isatty(STDERR_FILENO) != 0), t0_(std::chrono::steady_clock::now()) {
        if (const char* e = std::getenv("GEARLOSS_PROGRESS_AFTER")) after_ = std::atof(e);
    }
    ~ProgressMeter() {
        if (shown_) std::fputc('\n', stderr);
    }
    std::function<void(size_t, size_t)> callback() {
        if (!enabled_) return {};
        return [this](size_t done, size_t total) { update(done, total); };
    }

private:
    void update(size_t done, size_t total) {
        const double s = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0_).count();
        if (s < after_ || (s - last_ < 0.2 && done < total)) return;
        last_ = s;
        shown_ = true;
        const double rate = s > 0 ? done / s : 0;
        const double eta = rate > 0 ? (total - done) / rate : 0;
        std::fprintf(stderr, "\r%zu/%zu points (%.0f %%), %.0f points/s, ETA %.1f s   ", done, total,
                     total ? 100.0 * done / total : 100.0, rate, eta);
    }
    bool enabled_, shown_ = false;
    std::chrono::steady_clock::time_point t0_;
    double after_ = 1.0, last_ = -1.0;
};

// `map --format vecto`: one torque-loss table per gear (the selected ratio, or every ratio).
int run_vecto(const Common& c, const std::string& out, int threads, const std::string& speeds, const std::string& torques) {
    const io::Case first = load(c);
    std::vector<std::string> ratios;
    if (!c.ratio.empty() || first.ratio_names.empty()) ratios.push_back(c.ratio);
    else ratios = first.ratio_names;
    if (ratios.size() > 1 && out == "-")
        throw InputError("", 0, 0, "--output", "several gears: give -o FILE (written as FILE_<ratio>.vtlm per gear)");
    gearloss::map::MapOptions opt;
    opt.threads = threads;
    for (const auto& ratio : ratios) {
        Common cr = c;
        cr.ratio = ratio;
        io::Case k = load(cr);
        if (!k.grid.is_grid) throw InputError(k.file, 0, 0, "operating", "--format vecto needs a speeds x torques grid");
        std::vector<double> w = k.grid.speeds, T = k.grid.torques;
        if (!speeds.empty()) w = io::parse_value_list(speeds, gearloss::units::dim::angular_speed, "--speed", "0,1000,2000rpm");
        if (!torques.empty()) T = io::parse_value_list(torques, gearloss::units::dim::torque, "--torque", "100,200,400Nm");
        const auto rows = gearloss::map::vecto_loss_map(k.model, w, T, opt);
        io::throw_if_interrupted();
        std::string file = out;
        if (ratios.size() > 1) {
            const std::string stem = out.size() > 5 && out.substr(out.size() - 5) == ".vtlm" ? out.substr(0, out.size() - 5) : out;
            file = stem + "_" + ratio + ".vtlm";
        }
        io::AtomicFile f(file);
        f.write(gearloss::map::vecto_csv(rows));
        f.commit();
    }
    return kOk;
}

// --speed/--torque applied to a case's grid.
void override_grid(io::Case& k, const std::string& speeds, const std::string& torques) {
    if (!speeds.empty() || !torques.empty()) {
        if (!k.grid.is_grid) {
            k.grid.is_grid = true;
            for (const auto& [w, T] : k.grid.points) {
                k.grid.speeds.push_back(w);
                k.grid.torques.push_back(T);
            }
        }
        if (!speeds.empty())
            k.grid.speeds = io::parse_value_list(speeds, gearloss::units::dim::angular_speed, "--speed", "600,700,800rpm");
        if (!torques.empty())
            k.grid.torques = io::parse_value_list(torques, gearloss::units::dim::torque, "--torque", "150,200,250Nm");
    }
    gearloss::map::validate_case(k, {.speeds = !speeds.empty(), .torques = !torques.empty()});
}

void write_json_summary(const std::string& file, const std::string& json) {
    if (file.empty()) return;
    io::AtomicFile f(file);
    f.write(json);
    f.commit();
}

int run_map(const Common& c, const std::string& out, int threads, bool detail, const std::string& speeds,
            const std::string& torques, bool stats, const std::string& shard, const std::string& json_file) {
    io::Case k = load(c);
    override_grid(k, speeds, torques);
    const auto oil_temp = c.oil_temp.empty() ? std::nullopt : std::optional<double>(k.model.thermal.oil_temperature);
    gearloss::map::MapOptions opt;
    opt.threads = threads;
    opt.detail = detail;
    ProgressMeter meter;
    opt.progress = meter.callback();
    if (!k.sweep.empty() || !shard.empty()) {
        // Sweep variants and/or one shard of the job (gearloss merge joins the shards).
        gearloss::map::MapJob job;
        if (k.sweep.empty()) {
            job.variants.push_back({{}, std::move(k)});
        } else {
            for (const auto& a : k.sweep) job.sweep_labels.push_back(a.label);
            for (auto& v : io::expand_sweep(c.config, c.ratio.empty() ? std::nullopt : std::optional<std::string>(c.ratio))) {
                apply_overrides(v.c, c);
                override_grid(v.c, speeds, torques);
                job.variants.push_back({v.values, std::move(v.c)});
            }
        }
        std::optional<gearloss::map::Shard> sh;
        if (!shard.empty()) {
            sh = gearloss::map::parse_shard(shard);
            job.inputs = gearloss::map::input_fingerprint({.config = c.config, .oil_file = c.oil, .oil_temperature = oil_temp,
                                                           .ratio = c.ratio, .format = "csv", .detail = detail});
        }
        const auto t0 = std::chrono::steady_clock::now();
        const auto res = gearloss::map::run_job(job, opt, sh);
        const std::string& csv = res.csv;
        io::throw_if_interrupted();
        const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
        if (stats) {
            const size_t n = res.results.size();
            std::fprintf(stderr, "points %zu of %zu (%zu sweep variants), %.4f s, %.0f points/s\n", n, job.total_points(),
                         job.variants.size(), seconds, n / seconds);
        }
        io::AtomicFile f(out);
        f.write(csv);
        f.commit();
        write_json_summary(json_file, gearloss::map::map_summary_json(res.results, seconds));
        return kOk;
    }
    const auto t0 = std::chrono::steady_clock::now();
    const auto results = gearloss::map::run_map(k.model, k.grid, opt);
    const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    io::throw_if_interrupted();
    if (stats) {
        size_t evals = 0, no_eq = 0;
        for (const auto& r : results) {
            evals += static_cast<size_t>(r.evaluations);
            no_eq += !gearloss::solver::has_values(r.status);
        }
        std::fprintf(stderr, "points %zu, solve %.4f s, %.0f points/s, %.2f loss evaluations/point, %zu without equilibrium\n",
                     results.size(), seconds, results.size() / seconds, double(evals) / results.size(), no_eq);
    }
    io::AtomicFile f(out);
    std::string buf = gearloss::map::csv_header(k.model, detail);
    for (const auto& r : results) {
        buf += gearloss::map::csv_row(k.model, r, detail);
        if (buf.size() > (1u << 20)) {
            f.write(buf);
            buf.clear();
        }
    }
    f.write(buf);
    f.commit();
    write_json_summary(json_file, gearloss::map::map_summary_json(results, seconds));
    return kOk;
}

}  // namespace

int main(int argc, char** argv) {
    std::signal(SIGINT, gearloss::io::on_interrupt_signal);
    std::signal(SIGTERM, gearloss::io::on_interrupt_signal);
    // A file-size limit (or quota) must fail the write (EFBIG) so the partial
    // temporary file is removed, rather than kill the process mid-write.
    std::signal(SIGXFSZ, SIG_IGN);
    std::signal(SIGPIPE, SIG_IGN);  // a closed pipe is EPIPE: stdout ends quietly, files are still written

    CLI::App app{"gearloss — where the power goes in a gearbox: mesh, churning, bearing and seal losses with the\n"
                 "thermally stabilised oil temperature, from a YAML description.\n\n"
                 "Examples:\n"
                 "  gearloss check configs/transfer-box.yaml\n"
                 "  gearloss point configs/transfer-box.yaml --speed 800rpm --torque 250Nm\n"
                 "  gearloss map configs/transfer-box.yaml -o map.csv\n"
                 "  gearloss cycle configs/automatic-6speed.yaml --cycle wltc --start-temp -10degC\n"
                 "  gearloss map configs/fzg-c40-paor.yaml --speed 500,1000,1500rpm --torque 100,200Nm --oil-temp 90degC"};
    app.footer("Exit codes: 0 success, 1 usage error, 2 input error (file:line:column: key: message), 3 output not "
               "writable, 4 internal error, 130/143 interrupted (no output written).\nEvery command: gearloss COMMAND --help");
    app.set_version_flag("--version", std::string("gearloss ") + GEARLOSS_VERSION);
    app.require_subcommand(1);

    Common common;
    std::string out = "-", speeds, torques, speed1, torque1;
    int threads = 0;
    bool detail = false, json = false, stats = false;

    auto add_common = [&](CLI::App* s) {
        s->add_option("config", common.config, "gearbox case (YAML)")->required();
        s->add_option("--ratio", common.ratio, "select a ratio defined under gearbox.ratios");
        s->add_option("--oil-temp", common.oil_temp, "fixed oil temperature (e.g. 70degC): no thermal solve");
        s->add_option("--oil", common.oil, "replace the case's oil by this oil file (YAML)");
    };

    auto* map = app.add_subcommand("map", "all operating points of the grid to CSV (parallel, written atomically)");
    add_common(map);
    map->add_option("-o,--output", out, "output CSV file ('-' = stdout)");
    map->add_option("--threads", threads, "threads (default: all cores)")->check(CLI::Range(1, 1024));
    map->add_flag("--detail", detail, "add a column per mesh, gear, bearing and seal");
    map->add_flag("--stats", stats, "print solve time, points per second and loss evaluations per point to stderr");
    map->add_option("--speed", speeds, "override the input speeds, e.g. 600,700,800rpm");
    map->add_option("--torque", torques, "override the input torques, e.g. 150,200,250Nm");
    std::string map_format = "csv", shard, map_json;
    map->add_option("--json", map_json, "also write a JSON summary (counts, efficiency, loss and temperature ranges, time)");
    map->add_option("--shard", shard, "compute only shard K of N of the points (K/N, e.g. 3/16); join with `gearloss merge`");
    map->add_option("--format", map_format, "csv (loss breakdown) or vecto (torque-loss table per gear, negative "
                                            "torques included)")->check(CLI::IsMember({"csv", "vecto"}));
    map->footer("Examples:\n  gearloss map configs/transfer-box.yaml --speed 600,700,800rpm --torque 150,200,250Nm -o out.csv\n"
                "  gearloss map configs/manual-6speed.yaml --format vecto --oil-temp 70degC -o manual.vtlm   "
                "(manual_g1.vtlm ... manual_g6.vtlm)");

    auto* point = app.add_subcommand("point", "one operating point: every component's loss, temperatures and films");
    add_common(point);
    point->add_option("--speed", speed1, "input speed, e.g. 800rpm")->required();
    point->add_option("--torque", torque1, "input torque, e.g. 250Nm")->required();
    point->footer("Example: gearloss point configs/transfer-box.yaml --speed 800rpm --torque 250Nm");

    // diagnose
    std::string recordings, json_out, write_config, residuals_out;
    int bootstrap = 24;
    auto* diag = app.add_subcommand("diagnose", "compare recordings with the model, locate the mismatch, name the missing physics");
    add_common(diag);
    diag->add_option("recordings", recordings, "recordings CSV: steady points or a raw rig log (time_s column)")->required();
    diag->add_option("--json", json_out, "write the diagnosis as JSON to this file");
    diag->add_option("--write-config", write_config, "write the calibrated case file");
    diag->add_option("--residuals", residuals_out, "write per-point residuals before/after (CSV, for scripts/plot-residuals.py)");
    diag->add_option("--bootstrap", bootstrap, "bootstrap resamples for the stability check")->check(CLI::Range(4, 1000));
    diag->add_option("--threads", threads, "threads (default: all cores)")->check(CLI::Range(1, 1024));
    diag->footer("Example: gearloss diagnose configs/transfer-box.yaml recordings.csv --json diag.json --write-config calibrated.yaml");

    // synth
    std::vector<std::string> effects;
    std::string noise_loss = "1.5%", noise_temp = "0.4 K", format = "steady";
    unsigned seed = 1;
    auto* synth = app.add_subcommand("synth", "synthetic recordings from the model with concealed effects and noise");
    add_common(synth);
    synth->add_option("--effect", effects, "concealed effect NAME=VALUE (repeatable), e.g. windage=30W, torque_sensor_gain=1.03, unstabilised_test=2");
    synth->add_option("--noise-loss", noise_loss, "loss noise, one standard deviation (e.g. 1.5%)");
    synth->add_option("--noise-temp", noise_temp, "oil temperature noise (e.g. 0.4K)");
    synth->add_option("--seed", seed, "random seed");
    synth->add_option("--format", format, "steady (points) or log (0.5 Hz rig log)")->check(CLI::IsMember({"steady", "log"}));
    synth->add_option("--speed", speeds, "override the input speeds");
    synth->add_option("--torque", torques, "override the input torques");
    synth->add_option("-o,--output", out, "output CSV ('-' = stdout)");
    synth->footer("Example: gearloss synth configs/transfer-box.yaml --effect windage=25W --seed 3 -o rec.csv");

    // compare
    std::vector<std::string> compare_oils;
    Common cmp;
    auto* compare = app.add_subcommand("compare", "the same map for two oils and their differences per point (B - A)");
    compare->add_option("config", cmp.config, "gearbox case (YAML)")->required();
    compare->add_option("--oil", compare_oils, "oil files A and B (give --oil twice)")->required();
    compare->add_option("--ratio", cmp.ratio, "select a ratio defined under gearbox.ratios");
    compare->add_option("--oil-temp", cmp.oil_temp, "fixed oil temperature (e.g. 70degC): no thermal solve");
    compare->add_option("--speed", speeds, "override the input speeds");
    compare->add_option("--torque", torques, "override the input torques");
    compare->add_option("-o,--output", out, "output CSV ('-' = stdout)");
    compare->add_option("--threads", threads, "threads (default: all cores)")->check(CLI::Range(1, 1024));
    compare->footer("Example: gearloss compare configs/transfer-box.yaml --oil configs/oils/75W90-A.yaml "
                    "--oil configs/oils/75W140-A.yaml -o diff.csv");

    // mesh-profile
    std::string mesh_name;
    int positions = 41;
    auto* profile = app.add_subcommand("mesh-profile", "local thermal-EHL state along the path of contact of one mesh (CSV)");
    add_common(profile);
    profile->add_option("--mesh", mesh_name, "mesh name (see `gearloss check`)")->required();
    profile->add_option("--speed", speed1, "input speed, e.g. 1600rpm")->required();
    profile->add_option("--torque", torque1, "input torque, e.g. 720Nm")->required();
    profile->add_option("--positions", positions, "positions along the path")->check(CLI::Range(3, 2000));
    profile->add_option("-o,--output", out, "output CSV ('-' = stdout)");
    profile->footer("Example: gearloss mesh-profile configs/spur-seed000.yaml --mesh m --speed 1600rpm --torque 720Nm");

    // cycle
    std::string cycle_out, cycle_name, start_temp, ambient_temp, prewarm_temp, heater = "100W", warm_temp = "90degC", cycle_json;
    auto* cyc = app.add_subcommand("cycle", "transient warm-up over a drive cycle from a cold start, against a warm start "
                                            "and (optionally) after pre-warming");
    cyc->add_option("config", common.config, "gearbox case with a 'vehicle' block (YAML)")->required();
    cyc->add_option("--oil", common.oil, "replace the case's oil by this oil file (YAML)");
    cyc->add_option("--cycle", cycle_name, "nedc, wltc, artemis, artemis-urban, artemis-rural, artemis-motorway-130, "
                                           "artemis-motorway-150, or a CSV file (time_s,speed_kmh[,gear])")->required();
    cyc->add_option("--start-temp", start_temp, "temperature of the whole transmission at the start (e.g. -10degC)")->required();
    cyc->add_option("--ambient", ambient_temp, "ambient temperature (default: the start temperature, a cold soak)");
    cyc->add_option("--prewarm", prewarm_temp, "pre-warm the oil to this temperature before the cycle (e.g. 90degC)");
    cyc->add_option("--heater", heater, "pre-warming heater power (default 100W)");
    cyc->add_option("--warm-temp", warm_temp, "temperature of the warm-start reference run (default 90degC)");
    cyc->add_option("-o,--output", cycle_out, "time series CSV of the run from the start temperature ('-' = stdout, "
                                              "after the summary)");
    cyc->add_option("--json", cycle_json, "write the summary as JSON to this file");
    cyc->add_flag("--stats", stats, "print the simulation time of one cycle run to stderr");
    cyc->footer("Example: gearloss cycle configs/automatic-6speed.yaml --cycle nedc --start-temp -10degC --prewarm 90degC "
                "--heater 1kW -o trace.csv");

    // merge
    std::vector<std::string> shard_files;
    std::string merge_out = "-";
    auto* merge = app.add_subcommand("merge", "join the shards of `map --shard K/N` into the file a single run writes");
    merge->add_option("shards", shard_files, "shard CSV files, any order")->required();
    merge->add_option("-o,--output", merge_out, "output CSV ('-' = stdout)");
    merge->footer("Example:\n  for k in 1 2 3 4; do gearloss map configs/transfer-box.yaml --shard $k/4 -o part$k.csv; done\n"
                  "  gearloss merge part*.csv -o map.csv");

    auto* check = app.add_subcommand("check", "validate a case and print derived data (geometry, H_V, speeds, oil)");
    add_common(check);
    check->add_flag("--json", json, "print the derived data as JSON");
    check->footer("Example: gearloss check configs/fzg-c40-paor.yaml --json");

    try {
        app.parse(argc, argv);
    } catch (const CLI::CallForHelp& e) {
        return app.exit(e);
    } catch (const CLI::CallForAllHelp& e) {
        return app.exit(e);
    } catch (const CLI::CallForVersion& e) {
        return app.exit(e);
    } catch (const CLI::ParseError& e) {
        app.exit(e);
        return kUsage;
    }

    try {
        int rc = kOk;
        io::OutputTransaction outputs;  // files renamed together by publish(), discarded on error or signal
        if (map->parsed()) io::require_distinct_outputs({{"--output", out}, {"--json", map_json}});
        if (cyc->parsed()) io::require_distinct_outputs({{"--output", cycle_out}, {"--json", cycle_json}});
        if (diag->parsed()) io::require_distinct_outputs({{"--json", json_out}, {"--residuals", residuals_out}, {"--write-config", write_config}});
        std::vector<std::pair<std::string, std::string>> inputs = {{"config", common.config}, {"--oil", common.oil},
            {"config", cmp.config}, {"recordings", recordings}, {"--cycle", cycle_name}};
        for (const auto& f : compare_oils) inputs.emplace_back("--oil", f);
        for (const auto& f : shard_files) inputs.emplace_back("shards", f);
        io::require_outputs_not_inputs({{"--output", out}, {"--json", map_json}, {"--output", cycle_out}, {"--json", cycle_json},
            {"--json", json_out}, {"--residuals", residuals_out}, {"--write-config", write_config}, {"--output", merge_out}}, inputs);
        if (map->parsed()) {
            if (map_format == "vecto" && !shard.empty())
                throw InputError("", 0, 0, "--shard", "--format vecto writes whole tables per gear; it cannot be sharded");
            rc = map_format == "vecto" ? run_vecto(common, out, threads, speeds, torques)
                                       : run_map(common, out, threads, detail, speeds, torques, stats, shard, map_json);
        } else if (point->parsed()) {
            io::Case k = load(common);
            const double w = single_value(speed1, gearloss::units::dim::angular_speed, "--speed", "800rpm");
            const double T = single_value(torque1, gearloss::units::dim::torque, "--torque", "250Nm");
            gearloss::map::validate_point(w, T);
            const auto r = gearloss::solver::solve_point(k.model, w, T, true);
            io::write_stdout(io::point_report(k, r));
        } else if (diag->parsed()) {
            io::Case k = load(common);
            const auto rec = gearloss::diagnosis::read_recordings(recordings);
            gearloss::diagnosis::DiagnoseOptions dopt;
            dopt.bootstrap = bootstrap;
            dopt.threads = threads;
            gearloss::diagnosis::Diagnosis d;
            try {
                d = gearloss::diagnosis::diagnose(k.model, rec, dopt);
            } catch (const std::invalid_argument& e) {
                throw InputError(recordings, 0, 0, "", e.what());
            }
            io::write_stdout(gearloss::diagnosis::diagnosis_text(d));
            if (!json_out.empty()) {
                io::AtomicFile f(json_out);
                f.write(gearloss::diagnosis::diagnosis_json(d));
                f.commit();
            }
            if (!residuals_out.empty()) {
                io::AtomicFile f(residuals_out);
                f.write(gearloss::diagnosis::residuals_csv(d));
                f.commit();
            }
            if (!write_config.empty()) gearloss::diagnosis::write_calibrated_config(common.config, write_config, d);
        } else if (synth->parsed()) {
            io::Case k = load(common);
            if (!speeds.empty())
                k.grid.speeds = io::parse_value_list(speeds, gearloss::units::dim::angular_speed, "--speed", "600,700rpm");
            if (!torques.empty())
                k.grid.torques = io::parse_value_list(torques, gearloss::units::dim::torque, "--torque", "150,200Nm");
            if ((!speeds.empty() || !torques.empty()) && !k.grid.is_grid)
                throw InputError("", 0, 0, "--speed", "the case lists points; --speed/--torque need a speeds x torques grid");
            gearloss::map::validate_case(k, {.speeds = !speeds.empty(), .torques = !torques.empty()});
            gearloss::diagnosis::SynthOptions so;
            for (const auto& e : effects) so.effects.push_back(gearloss::diagnosis::parse_effect_assignment(e));
            so.noise_loss = single_value(noise_loss, gearloss::units::dim::none, "--noise-loss", "1.5%");
            so.noise_temp = temperature_difference(noise_temp, "--noise-temp");
            so.seed = seed;
            so.raw_log = format == "log";
            const std::string csv = gearloss::diagnosis::synthesize(k.model, k.grid, so);
            io::AtomicFile f(out);
            f.write(csv);
            f.commit();
        } else if (profile->parsed()) {
            io::Case k = load(common);
            const double w = single_value(speed1, gearloss::units::dim::angular_speed, "--speed", "1600rpm");
            const double T = single_value(torque1, gearloss::units::dim::torque, "--torque", "720Nm");
            const auto r = gearloss::solver::solve_point(k.model, w, T);
            if (!gearloss::solver::has_values(r.status))
                throw InputError("", 0, 0, "--speed", gearloss::solver::status_text(r) + " at this point (give --oil-temp)");
            io::AtomicFile f(out);
            f.write(io::mesh_profile_csv(k, mesh_name, w, T, r.oil_temperature, positions));
            f.commit();
        } else if (compare->parsed()) {
            if (compare_oils.size() != 2) throw InputError("", 0, 0, "--oil", "compare needs exactly two oils (--oil A --oil B)");
            io::Case base = load(cmp);
            if (!speeds.empty())
                base.grid.speeds = io::parse_value_list(speeds, gearloss::units::dim::angular_speed, "--speed", "600,700rpm");
            if (!torques.empty())
                base.grid.torques = io::parse_value_list(torques, gearloss::units::dim::torque, "--torque", "150,200Nm");
            io::Case a = base, b = base;
            io::replace_oil(a, io::load_oil_file(compare_oils[0]));
            io::replace_oil(b, io::load_oil_file(compare_oils[1]));
            for (int i : {0, 1})  // each oil with the grid (solver/validate.hpp)
                gearloss::map::validate_case(i ? b : a, {cmp.oil_temp, compare_oils[i], !speeds.empty(), !torques.empty()});
            gearloss::map::MapOptions mo;
            mo.threads = threads;
            ProgressMeter meter;
            mo.progress = meter.callback();
            const auto ra = gearloss::map::run_map(a.model, a.grid, mo);
            io::throw_if_interrupted();  // not the second map
            const auto rb = gearloss::map::run_map(b.model, b.grid, mo);
            if (!io::g_interrupted) {
                io::AtomicFile f(out);
                f.write(gearloss::map::compare_header(a.model.oil.name, b.model.oil.name));
                for (size_t i = 0; i < ra.size(); ++i) f.write(gearloss::map::compare_row(ra[i], rb[i]));
                f.commit();
            }
        } else if (cyc->parsed()) {
            io::Case k = io::load_case(common.config);
            gearloss::map::validate_case(k, {.grid = false});
            const auto pt = io::load_powertrain(k, common.oil.empty() ? std::nullopt : std::optional<std::string>(common.oil));
            std::vector<std::string> dirs = {(std::filesystem::path(common.config).parent_path() / "cycles").string(),
                                             GEARLOSS_CYCLES_DIR};
            const auto dc = gearloss::cycle::resolve_cycle(cycle_name, dirs);
            io::CycleStudyOptions so;
            so.start_temperature = absolute_temperature(start_temp, "--start-temp");
            so.ambient = ambient_temp.empty() ? so.start_temperature : absolute_temperature(ambient_temp, "--ambient");
            so.warm_temperature = absolute_temperature(warm_temp, "--warm-temp");
            if (!prewarm_temp.empty()) so.prewarm_target = absolute_temperature(prewarm_temp, "--prewarm");
            so.heater_power = single_value(heater, gearloss::units::dim::power, "--heater", "100W");
            const auto study = io::run_cycle_study(pt, dc, so);
            io::throw_if_interrupted();
            io::write_stdout(io::cycle_summary_text(pt, study, so));
            if (stats)
                std::fprintf(stderr, "cycle %s: %zu steps simulated in %.2f ms\n", dc.name.c_str(), dc.time.size() - 1,
                             1e3 * study.seconds_per_run);
            if (!cycle_json.empty()) {
                io::AtomicFile f(cycle_json);
                f.write(io::cycle_summary_json(pt, study, so));
                f.commit();
            }
            if (!cycle_out.empty()) {
                io::AtomicFile f(cycle_out);
                f.write(io::cycle_trace_csv(pt, study.cold));
                f.commit();
            }
        } else if (merge->parsed()) {
            const std::string csv = gearloss::map::merge_shards(shard_files);
            io::AtomicFile f(merge_out);
            f.write(csv);
            f.commit();
        } else if (check->parsed()) {
            io::Case k = load(common, false);
            io::write_stdout(json ? io::check_json(k) : io::check_report(k));
        }
        if (io::interrupted()) return io::report_interrupt();
        outputs.publish();
        return rc;
    } catch (const InputError& e) {
        if (io::interrupted()) return io::report_interrupt();  // an error the interrupt caused
        std::fprintf(stderr, "gearloss: error: %s\n", e.what());
        return kInput;
    } catch (const io::IoError& e) {
        if (io::interrupted()) return io::report_interrupt();  // io::Interrupted, or a write the signal stopped
        std::fprintf(stderr, "gearloss: error: %s\n", e.what());
        return kOutput;
    } catch (const std::exception& e) {
        if (io::interrupted()) return io::report_interrupt();
        std::fprintf(stderr, "gearloss: internal error: %s\n", e.what());
        return kInternal;
    }
}
