#pragma once
// Runs the model's plausibility checks (gearloss/solver/plausibility.hpp) on a loaded case and
// locates each finding at the YAML key it concerns: errors throw InputError, warnings
// and notes go to Case::warnings.
#include "gearloss/case/config.hpp"
#include "gearloss/case/yaml_reader.hpp"
#include "gearloss/solver/plausibility.hpp"

namespace gearloss::io {

void check_case_plausibility(const YamlNode& root, Case& c, solver::Lubrication lubrication);

// Sizes of parts against each other (case_sizes.cpp): a bearing position far beyond every gear
// of its shaft, a seal far from its shaft's bearing sizes, an oil volume far beyond the gears'
// swept space are errors at their key; a size that is only unusual is a warning.
void check_component_sizes(const YamlNode& root, Case& c);

// After the command-line overrides: a fixed oil temperature above the oil's permissible
// one is a warning (`option` names the override, or empty for the case file's value); bearings
// past SKF's starvation limit there, at the grid's largest speed, are a note.
void check_oil_temperature(Case& c, const std::string& option);

// Prints the case's warnings on stderr, each once per process (sweeps re-read the case).
void print_warnings(const Case& c);

}  // namespace gearloss::io
