#pragma once
// The CLI's other commands for the Python module (module_commands.cpp): check, compare, the
// form spread and sweeps of `map`, and cycle. Each returns the text the CLI writes (its report,
// JSON or CSV, made by the same library functions from the same results), which the package
// (app/python/gearloss/) turns into dicts and tables; so the numbers are the CLI's by
// construction, cell for cell.
#include <pybind11/pybind11.h>

#include <optional>
#include <string>
#include <vector>

#include "module_case.hpp"

namespace gearloss::python {

using OptionalAxis = std::optional<std::vector<double>>;

// `gearloss check` (--json): the case read again from its source with the oil of with_oil.
std::string check(const PyCase& c, bool json);

// `gearloss compare --oil A --oil B ...`: the CSV text.
std::string compare(const PyCase& c, const std::vector<std::string>& oils, const OptionalAxis& speeds_rpm,
                    const OptionalAxis& torques_Nm, const std::optional<double>& oil_temp_C,
                    const std::optional<int>& threads, bool detail);

// `gearloss map --spread [--spread-axes ...]`: {"csv": text, "note": the combinations left out}.
pybind11::dict spread(const PyCase& c, const std::optional<std::vector<std::string>>& axes, const OptionalAxis& speeds_rpm,
                      const OptionalAxis& torques_Nm, const std::optional<double>& oil_temp_C,
                      const std::optional<int>& threads, bool detail);

// `gearloss map` of a case with a `sweep:` block (every variant; the plain map without one):
// {"csv": text, "warnings": the variants' plausibility warnings}.
pybind11::dict sweeps(const PyCase& c, const OptionalAxis& speeds_rpm, const OptionalAxis& torques_Nm,
                      const std::optional<double>& oil_temp_C, const std::optional<int>& threads, bool detail);

// `gearloss cycle`: {"json": the --json summary, "text": the printed summary, "trace": the -o CSV
// (empty unless asked), "warning": the engine-map warning (empty when none)}.
pybind11::dict cycle(const PyCase& c, const std::string& cycle_name, double start_temp_C,
                     const std::optional<double>& ambient_C, const std::optional<double>& prewarm_C,
                     double heater_W, double warm_temp_C, bool trace);

}  // namespace gearloss::python
