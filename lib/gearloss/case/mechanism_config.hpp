#pragma once
// The loss mechanisms' blocks of a case: `calibration:` (each mechanism's calibration
// parameters, plus the oil and heat-path terms) and `mechanisms:` (each mechanism's
// settings and selected forms). Keys come from the mechanisms themselves
// (losses::LossMechanism::parameters, forms), so a new mechanism needs no edit here.
#include "gearloss/case/yaml_reader.hpp"
#include "gearloss/model/model.hpp"

namespace gearloss::io {

// calibration:
//   churning: {factor: 1.3}          a mechanism's calibration parameters
//   auxiliary: {power: 20 W}
//   viscosity_factor: 1.1            oil and heat path
//   heat_rejection_factor: 0.9
//   cooling_per_1000rpm: 0.1
// The flat keys of earlier versions (churning_factor, windage: 12 W, ...) are still read.
void load_calibration(const YamlNode& n, solver::Model& m);

// mechanisms:
//   mesh: {friction: schlenk}        a form axis of the mechanism, by name
//   windage: {form: free_disk}       a form, and settings (non-calibration parameters)
void load_mechanism_settings(const YamlNode& n, solver::Model& m);

// The calibration block of a model as YAML text lines ("churning:\n  factor: 1.3\n"): the
// terms that differ from neutral, each mechanism's in its own block (used when a calibrated
// case is written).
struct CalibrationEntry {
    std::string mechanism;  // empty: an oil or heat-path term
    std::string key;
    double value = 0;
    std::string unit;       // "W" or empty
};
std::vector<CalibrationEntry> calibration_entries(const losses::MechanismSet& mechanisms, const solver::Calibration& c);

}  // namespace gearloss::io
