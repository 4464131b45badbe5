#pragma once
// Pieces shared by the subcommands: exit codes, the common case options (config, --ratio,
// --oil-temp, --oil), value parsing for single options, output helpers, the progress meter
// and the translation of errors into exit codes.
#include <CLI/CLI.hpp>
#include <chrono>
#include <functional>
#include <string>
#include <utility>
#include <vector>

#include "gearloss/case/config.hpp"
#include "gearloss/map/output_metadata.hpp"
#include "gearloss/units/units.hpp"

namespace gearloss::app {

// Exit codes (README "Exit codes").
enum Exit : int {
    kOk = 0,
    kUsage = 1,
    kInput = 2,
    kOutput = 3,
    kInternal = 4,  // 128 + signal on SIGINT/SIGTERM/SIGHUP/SIGQUIT/SIGPIPE: io::interrupt_exit_code() (gearloss/io/interrupt.hpp)
};

// The case and the options every case command takes (add_common_options): config, --ratio,
// --oil-temp, --oil.
struct CommonOptions {
    std::string config;
    std::string ratio;
    std::string oil_temp;
    std::string oil;
};

// Every option given to the subcommand has a value that is not empty ("--shard ''" is not
// "no --shard") and is printable text; else an InputError naming the option.
void check_option_values(const CLI::App& sub);

// A CLI11 parse error on one line ("--threads: Value 0 not in range [1 - 1024]").
std::string usage_error_line(const CLI::Error& e);
// The --threads value: a whole number 1..1024 (CLI11's Range says only "not in range" of 1.5).
CLI::Validator threads_check();

// config, --ratio, --oil-temp and --oil with their help texts.
void add_common_options(CLI::App& sub, CommonOptions& c);

// --oil and --oil-temp applied to a loaded case (then map::validate_case without the grid).
void apply_case_options(io::Case& k, const CommonOptions& c);

// The case with --ratio, --oil and --oil-temp applied. `check` lists the plausibility warnings
// in its report (warn_on_stderr = false); every other command prints them on stderr.
io::Case load_with_options(const CommonOptions& c, bool warn_on_stderr = true);
// The same for a case already loaded (a sweep's variant).
io::Case with_options(io::Case k, const CommonOptions& c, bool warn_on_stderr = true);

// "-10degC", "263.15 K": an absolute temperature [K]; InputError naming `what` otherwise.
double absolute_temperature(const std::string& text, const char* what, const char* example = "-10degC");
// One value of dimension `d` ("800rpm"); InputError naming `what` otherwise.
double single_value(const std::string& text, const units::Dimension& d, const char* what, const char* example);
// "0.4K", "0.4 degC": a temperature difference (the unit's offset removed).
double temperature_difference(const std::string& text, const char* what);

// The command line as given (main sets it), for the sidecar metadata of outputs.
void set_command_line(int argc, char** argv);
const std::vector<std::string>& command_line();

// The sidecar FILE.meta.json of a CSV written to `csv` (map::write_sidecar; nothing for standard
// output or a device): the case as the command used it, the CSV's header line, and what else
// the request says (oils, text columns). Written atomically with the command's other outputs:
// a run that fails leaves neither.
void write_csv_sidecar(const std::string& csv, const io::Case& k, std::string_view header_line,
                       map::MetadataRequest r = {});
// `text` (a CSV, after any '#' lines its header) into `csv`, and its sidecar.
void write_csv_file(const std::string& csv, const std::string& text, const io::Case& k, map::MetadataRequest r = {});
// The sidecar a CSV output `csv` of option `option` adds, as an (option, path) pair for
// io::require_safe_outputs (path empty: none).
std::pair<std::string, std::string> sidecar_output(const std::string& option, const std::string& csv);

// The files a command reads for the case `config`: the case itself and every file it names as
// the loader resolves them (its oil file, a user bearing catalogue, sweep values:
// map::named_files), the bearing catalogue gearloss ships, then `more`; for
// io::require_safe_outputs, so that no output lands on any of them.
using NamedPaths = std::vector<std::pair<std::string, std::string>>;
NamedPaths case_inputs(const std::string& config, const NamedPaths& more = {});

// `text` into `file` (atomically; "-" = stdout).
void write_file(const std::string& file, const std::string& text);
// The same when a file was named (an optional --json FILE).
void write_optional_file(const std::string& file, const std::string& text);

// Progress on stderr for long runs: only on a terminal, only once a run has lasted
// GEARLOSS_PROGRESS_AFTER seconds (default 1), at most 5 updates a second.
class ProgressMeter {
public:
    ProgressMeter();
    ~ProgressMeter();
    ProgressMeter(const ProgressMeter&) = delete;
    ProgressMeter& operator=(const ProgressMeter&) = delete;
    std::function<void(size_t, size_t)> callback();

private:
    void update(size_t done, size_t total);
    bool enabled_, shown_ = false;
    std::chrono::steady_clock::time_point t0_;
    double after_ = 1.0, last_ = -1.0;
};

// Runs a parsed command inside an output transaction (its files appear together, or none)
// and translates what it throws into the exit code and the message on stderr:
// InputError -> 2, io::IoError -> 3, any other exception -> 4, an interrupt -> 128 + the signal (130 SIGINT, 143 SIGTERM, 129 SIGHUP, 131 SIGQUIT, 141 SIGPIPE or a closed output pipe).
int run_command(const std::function<int()>& body);

}  // namespace gearloss::app
