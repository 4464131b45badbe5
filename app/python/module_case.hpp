#pragma once
// A loaded case as the Python module holds it (gearloss_module.cpp) and what every call on it
// shares with the others (module_commands.cpp): the checks the CLI applies after its options,
// the renaming of option names in errors, and the watch that turns Ctrl-C into KeyboardInterrupt.
#include <pybind11/pybind11.h>

#include <numbers>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "gearloss/core/errors.hpp"
#include "gearloss/case/config.hpp"
#include "gearloss/io/interrupt.hpp"

namespace gearloss::python {

constexpr double kRadSPerRpm = 2.0 * std::numbers::pi / 60.0;  // as the unit parser's "rpm"
constexpr double kZeroCelsius = 273.15;

// Where a case was read from: a file, or text (a YAML string, or a dict as its JSON text) with
// the name its messages show and the folder its relative paths resolve against.
struct CaseSource {
    std::string path;               // the file (empty for text)
    std::optional<std::string> text;
    std::string name, base_dir;     // text only
    std::optional<std::string> ratio;
    std::string folder() const;     // the case's own folder (its cycles/ beside it)
};

// A loaded case as the CLI holds it after its common options (common.cpp): checked, with its
// plausibility warnings collected (the package turns them into Python warnings).
struct PyCase {
    io::Case k;
    std::string oil_file;  // the oil replaced by with_oil (empty: the case's own)
    CaseSource source;
};

// The case read again from its source (io::load_case or io::load_case_text), unchecked.
io::Case read_case(const CaseSource& s);
// The checks that every CLI command applies after loading (app/commands/common.cpp
// apply_case_options and with_options), for the options the case has been given.
void check_loaded(io::Case& k, const std::string& oil_file, const std::string& oil_temp);
// The case at a fixed oil temperature (the CLI's --oil-temp), or unchanged.
io::Case at_oil_temperature(const PyCase& c, const std::optional<double>& oil_temp_C);
// The case's grid, or the speeds x torques given (as the CLI's --speed / --torque).
io::OperatingGrid grid_of(const io::Case& k, const std::optional<std::vector<double>>& speeds_rpm,
                          const std::optional<std::vector<double>>& torques_Nm);
// An empty list given for an axis: an InputError naming the argument.
void require_values(const std::optional<std::vector<double>>& speeds_rpm,
                    const std::optional<std::vector<double>>& torques_Nm);

// An InputError whose key names a CLI option is renamed to the Python argument that set the
// value ("--speed" -> "speed_rpm"); the message and location stay.
using KeyNames = std::vector<std::pair<std::string, std::string>>;
template <class F>
auto renaming_keys(const KeyNames& names, F&& f) -> decltype(f()) {
    try {
        return f();
    } catch (const InputError& e) {
        for (const auto& [option, argument] : names)
            if (e.key == option) throw InputError(e.file, e.line, e.column, argument, e.message);
        throw;
    }
}

// A KeyboardInterrupt raised by Python's SIGINT handler while the library computes: the
// library's progress callbacks (on the calling thread) poll Python's signals, and a pending
// one stops the computation through the library's own interrupt flag.
class SignalWatch {
public:
    // Called with the GIL released, on the thread that released it.
    void poll() {
        if (raised_) return;
        pybind11::gil_scoped_acquire gil;
        if (PyErr_CheckSignals() != 0) {
            raised_ = true;
            error_ = pybind11::error_already_set();  // taken out of the thread state: raised again by finish()
            io::g_interrupted.store(true);
        }
    }
    // With the GIL held, after the computation: the pending exception, if one was caught.
    void finish() {
        if (!raised_) return;
        io::g_interrupted.store(false);
        raised_ = false;
        throw std::move(*error_);
    }
    // The library's flag never outlives the computation it stopped (an error thrown past finish()).
    ~SignalWatch() {
        if (raised_) io::g_interrupted.store(false);
    }
    SignalWatch() = default;
    SignalWatch(const SignalWatch&) = delete;
    SignalWatch& operator=(const SignalWatch&) = delete;

private:
    bool raised_ = false;
    std::optional<pybind11::error_already_set> error_;
};

}  // namespace gearloss::python
