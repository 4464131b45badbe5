// gearloss check: validates a case and prints derived data (geometry, H_V, speeds, oil); with
// --oil-temp also the oil's properties at that temperature.
#include <stdexcept>
#include <string>

#include "commands/command.hpp"
#include "commands/common.hpp"
#include "gearloss/core/message_text.hpp"
#include "gearloss/io/atomic_file.hpp"
#include "gearloss/io/json_text.hpp"
#include "gearloss/results/reports.hpp"

namespace gearloss::app {
namespace {

// The oil of the case at its fixed temperature (--oil-temp), one line of the text report:
// "    at 70.0 degC (--oil-temp): nu = 25.4 cSt, rho = 850.1 kg/m^3, ...".
std::string oil_state_text(const io::Case& k) {
    const auto& oil = k.model.oil;
    const auto s = oil.state(k.model.thermal.oil_temperature);
    return fmt::format("    at {} (--oil-temp): nu = {} cSt, rho = {} kg/m^3, eta = {} mPa*s, alpha_p = {} 1/Pa, "
                       "beta_T = {} 1/K\n",
                       celsius_text(s.T), finite_number_text(s.nu_cSt), finite_number_text(s.rho),
                       finite_number_text(s.eta * 1e3), finite_number_text(s.alpha_p, 4), finite_number_text(s.beta_T, 4));
}

// The same as the JSON object of the key "oil_at_oil_temp".
nlohmann::ordered_json oil_state_json(const io::Case& k) {
    const auto s = k.model.oil.state(k.model.thermal.oil_temperature);
    return {{"temperature_C", s.T - 273.15}, {"nu_cSt", s.nu_cSt},          {"rho_kg_m3", s.rho},
            {"eta_mPa_s", s.eta * 1e3},      {"alpha_p_1_Pa", s.alpha_p}, {"beta_T_1_K", s.beta_T}};
}

// check_report with the oil line inserted after the oil block (before "operating points: N",
// the last line ahead of the assumed values and the plausibility warnings).
std::string report_with_oil_state(io::Case& k) {
    const std::string full = io::check_report(k);
    auto warnings = std::move(k.warnings);
    auto assumed = std::move(k.assumed);
    k.warnings.clear();
    k.assumed.clear();
    const std::string head = io::check_report(k);  // the report up to its assumed values
    k.warnings = std::move(warnings);
    k.assumed = std::move(assumed);
    if (head.empty() || head.back() != '\n' || full.compare(0, head.size(), head) != 0)
        throw std::logic_error("check report: unexpected layout");
    const size_t last_line = head.rfind('\n', head.size() - 2) + 1;  // npos + 1 = 0
    const size_t at = head.compare(last_line, 18, "operating points: ") == 0 ? last_line : head.size();
    return head.substr(0, at) + oil_state_text(k) + head.substr(at) + full.substr(head.size());
}

// check_json with the top-level key "oil_at_oil_temp" added last.
std::string json_with_oil_state(const io::Case& k) {
    nlohmann::ordered_json j = io::check_json_object(k);
    j["oil_at_oil_temp"] = oil_state_json(k);
    return io::json_line(j);
}

class CheckCommand final : public Command {
public:
    CLI::App* add_to(CLI::App& app) override {
        auto* s = app.add_subcommand("check", "validate a case and print derived data (geometry, H_V, speeds, oil)");
        add_common_options(*s, common_);
        s->add_flag("--json", json_, "print the derived data as JSON");
        s->footer("Example: gearloss check configs/fzg-c40-paor.yaml --json");
        return s;
    }

    int run() override {
        io::Case k = load_with_options(common_, false);  // first: its reader bounds what a hostile case can cost
        // No output file, but the report goes to standard output: not onto an input, and a
        // reader that goes away ends the run.
        io::require_safe_outputs({}, case_inputs(common_.config, {{"--oil", common_.oil}}), true);
        if (common_.oil_temp.empty()) io::write_stdout(json_ ? io::check_json(k) : io::check_report(k));
        else io::write_stdout(json_ ? json_with_oil_state(k) : report_with_oil_state(k));
        return kOk;
    }

private:
    CommonOptions common_;
    bool json_ = false;
};

}  // namespace

std::unique_ptr<Command> make_check_command() { return std::make_unique<CheckCommand>(); }

}  // namespace gearloss::app
