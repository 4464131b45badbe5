#include "commands/common.hpp"

#include <algorithm>
#include <cctype>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <optional>
#include <unistd.h>

#include "gearloss/core/errors.hpp"
#include "gearloss/io/atomic_file.hpp"
#include "gearloss/case/case_plausibility.hpp"
#include "gearloss/io/csv_read.hpp"
#include "gearloss/io/data_dir.hpp"
#include "gearloss/io/interrupt.hpp"
#include "gearloss/map/fingerprint.hpp"
#include "gearloss/map/map_runner.hpp"

namespace gearloss::app {

void add_common_options(CLI::App& sub, CommonOptions& c) {
    sub.add_option("config", c.config, "gearbox case (YAML)")->required();
    sub.add_option("--ratio", c.ratio, "select a ratio defined under gearbox.ratios");
    sub.add_option("--oil-temp", c.oil_temp, "fixed oil temperature (e.g. 70degC): no thermal solve");
    sub.add_option("--oil", c.oil, "replace the case's oil by this oil file (YAML)");
}

void apply_case_options(io::Case& k, const CommonOptions& c) {
    if (!c.oil.empty()) io::replace_oil_file(k, c.oil);
    if (!c.oil_temp.empty()) {
        const double t = absolute_temperature(c.oil_temp, "--oil-temp", "70degC");
        k.model.thermal.mode = solver::ThermalMode::fixed;
        k.model.thermal.oil_temperature = t;
    }
    map::validate_case(k, {.oil_temp = c.oil_temp, .oil = c.oil, .grid = false});  // gearloss/model/validate.hpp
}

io::Case load_with_options(const CommonOptions& c, bool warn_on_stderr) {
    std::optional<std::string> ratio;
    if (!c.ratio.empty()) ratio = c.ratio;
    return with_options(io::load_case(c.config, ratio), c, warn_on_stderr);
}

io::Case with_options(io::Case k, const CommonOptions& c, bool warn_on_stderr) {
    apply_case_options(k, c);
    io::check_oil_temperature(k, c.oil_temp.empty() ? "" : "--oil-temp");
    if (warn_on_stderr) io::print_warnings(k);
    return k;
}

double absolute_temperature(const std::string& text, const char* what, const char* example) {
    try {
        return units::absolute_temperature(units::parse_quantity(text), text);
    } catch (const units::UnitError& e) {
        throw InputError("", 0, 0, what, e.message + " (expected e.g. '" + example + "')");
    }
}

double single_value(const std::string& text, const units::Dimension& d, const char* what, const char* example) {
    const auto v = io::parse_value_list(text, d, what, example);
    if (v.size() != 1) throw InputError("", 0, 0, what, "expected one value");
    return v[0];
}

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
        const auto f = units::parse_unit(text.substr(u));
        const auto q = units::parse_quantity(text);
        if (f.dim != units::dim::temperature) throw units::UnitError("not a temperature difference");
        return q.value - f.offset;
    } catch (const units::UnitError& e) {
        throw InputError("", 0, 0, what, "'" + io::excerpt(text) + "': " + e.message + " (expected e.g. '0.4K')");
    }
}

void check_option_values(const CLI::App& sub) {
    for (const CLI::Option* o : sub.get_options()) {
        if (o->count() == 0 || o->get_expected_min() == 0) continue;  // not given, or a flag
        std::string name = o->get_name(false, true);
        if (name.empty()) name = o->get_name();
        for (const std::string& v : o->results()) {
            // "--shard ''" would otherwise read as "not given" and do the whole job.
            if (v.empty()) throw InputError("", 0, 0, name, "an empty value; give one or leave the option out (see --help)");
            if (!io::is_printable_utf8(v))
                throw InputError("", 0, 0, name,
                                 "'" + io::excerpt(v) + "' contains a control character or bytes that are not UTF-8");
        }
    }
}

std::string usage_error_line(const CLI::Error& e) {
    // CLI11 names an option in its own words ("Value 0 not in range [1 - 1024]"), on a line of
    // its own followed by a second one; one line, with what is expected.
    std::string m = e.what();
    std::replace(m.begin(), m.end(), '\n', ' ');
    while (!m.empty() && m.back() == ' ') m.pop_back();
    return m;
}

CLI::Validator threads_check() {
    return CLI::Validator(
        [](std::string& v) -> std::string {
            const bool digits = !v.empty() && v.size() <= 5 && v.find_first_not_of("0123456789") == std::string::npos;
            const int n = digits ? std::stoi(v) : 0;
            if (digits && n >= 1 && n <= 1024) return {};
            return "'" + io::excerpt(v) + "' is not a whole number of threads 1 to 1024";
        },
        "1..1024");
}

namespace {
std::vector<std::string>& command_line_storage() {
    static std::vector<std::string> args;
    return args;
}
}  // namespace

void set_command_line(int argc, char** argv) { command_line_storage().assign(argv, argv + argc); }

const std::vector<std::string>& command_line() { return command_line_storage(); }

void write_csv_sidecar(const std::string& csv, const io::Case& k, std::string_view header_line,
                       map::MetadataRequest r) {
    if (!map::wants_sidecar(csv)) return;
    const auto& argv = command_line();
    r.command = argv.size() > 1 ? argv[1] : "";
    r.command_line = argv;
    r.columns = map::header_columns(header_line);
    map::write_sidecar(csv, map::output_metadata(k, r));
}

NamedPaths case_inputs(const std::string& config, const NamedPaths& more) {
    NamedPaths inputs{{"config", config}};
    try {
        for (const auto& [key, file] : map::named_files({.config = config}))
            inputs.emplace_back("named by the case at '" + key + "'", file);
    } catch (...) {
        // A case that cannot be read or parsed: loading it reports the error with its line;
        // until then the case file itself is the input to protect.
    }
    // The data gearloss ships (gearloss/io/data_dir.hpp): the bearing catalogue, read for any
    // designation, and the drive cycles, read by name (`--cycle nedc`), whether this run reads
    // them or not: no command damages them.
    if (const auto data = io::find_data_dir().dir) {
        inputs.emplace_back("the shipped bearing catalogue", (*data / "bearings" / "catalogue.yaml").string());
        std::error_code ec;
        for (auto it = std::filesystem::directory_iterator(*data / "cycles", ec);
             !ec && it != std::filesystem::directory_iterator(); it.increment(ec))
            if (it->path().extension() == ".csv")
                inputs.emplace_back("the shipped cycle '" + it->path().stem().string() + "'", it->path().string());
    }
    inputs.insert(inputs.end(), more.begin(), more.end());
    return inputs;
}

void write_csv_file(const std::string& csv, const std::string& text, const io::Case& k, map::MetadataRequest r) {
    write_file(csv, text);
    write_csv_sidecar(csv, k, map::header_line(text), std::move(r));
}

std::pair<std::string, std::string> sidecar_output(const std::string& option, const std::string& csv) {
    if (!map::wants_sidecar(csv)) return {option + " (its metadata)", ""};
    return {option + " (its metadata " + map::sidecar_path(csv) + ")", map::sidecar_path(csv)};
}

void write_file(const std::string& file, const std::string& text) {
    io::AtomicFile f(file);
    f.write(text);
    f.commit();
}

void write_optional_file(const std::string& file, const std::string& text) {
    if (!file.empty()) write_file(file, text);
}

ProgressMeter::ProgressMeter() : enabled_(::isatty(STDERR_FILENO) != 0), t0_(std::chrono::steady_clock::now()) {
    if (const char* e = std::getenv("GEARLOSS_PROGRESS_AFTER")) after_ = std::atof(e);
}

ProgressMeter::~ProgressMeter() {
    if (shown_) std::fputc('\n', stderr);
}

std::function<void(size_t, size_t)> ProgressMeter::callback() {
    if (!enabled_) return {};
    return [this](size_t done, size_t total) { update(done, total); };
}

void ProgressMeter::update(size_t done, size_t total) {
    const double s = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0_).count();
    if (s < after_ || (s - last_ < 0.2 && done < total)) return;
    last_ = s;
    shown_ = true;
    const double rate = s > 0 ? done / s : 0;
    const double eta = rate > 0 ? (total - done) / rate : 0;
    std::fprintf(stderr, "\r%zu/%zu points (%.0f %%), %.0f points/s, ETA %.1f s   ", done, total,
                 total ? 100.0 * done / total : 100.0, rate, eta);
}

namespace {
// An error after part of a direct output was written (a pipe cannot be taken back).
void note_incomplete_stream() {
    if (const std::string s = io::incomplete_stream(); !s.empty())
        std::fprintf(stderr, "gearloss: the output %s stops part-way\n", s.c_str());
}
}  // namespace

int run_command(const std::function<int()>& body) {
    try {
        io::OutputTransaction outputs;  // files renamed together by publish(), discarded on error or signal
        const int rc = body();
        if (io::interrupted()) return io::report_interrupt(io::incomplete_stream());
        outputs.publish();
        return rc;
    } catch (const InputError& e) {
        if (io::interrupted()) return io::report_interrupt(io::incomplete_stream());  // an error the interrupt caused
        std::fprintf(stderr, "gearloss: error: %s\n", e.what());
        note_incomplete_stream();
        return kInput;
    } catch (const io::IoError& e) {
        if (io::interrupted()) return io::report_interrupt(io::incomplete_stream());  // io::Interrupted, or a write the signal stopped
        std::fprintf(stderr, "gearloss: error: %s\n", e.what());
        note_incomplete_stream();
        return kOutput;
    } catch (const std::exception& e) {
        if (io::interrupted()) return io::report_interrupt(io::incomplete_stream());
        std::fprintf(stderr, "gearloss: internal error: %s\n", e.what());
        note_incomplete_stream();
        return kInternal;
    }
}

}  // namespace gearloss::app
