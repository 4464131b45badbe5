#pragma once
// The empirical terms of a calibration (mechanisms/empirical_mechanism.hpp) in a case file:
//
// calibration:
//   empirical:
//     terms:
//       - coefficient: 41 W                      a loss that switches on in hot oil
//         factors: [{variable: oil_temperature, shape: step, above: 80 degC}]
//       - coefficient: 2.5 W                     a power of speed, above 1050 rpm only
//         factors:
//           - {variable: speed, shape: power, reference: 1000 rpm, exponent: 2.9}
//           - {variable: speed, shape: step, above: 1050 rpm}
//       - coefficient: 3 W                       a window of torque, one oil only
//         factors: [{variable: torque, shape: window, lower: 100 N*m, upper: 200 N*m}]
//         oil: ISO VG 100
//
// variable: speed | torque | oil_temperature | viscosity; shape: power (reference,
// exponent), step (above), threshold (above, reference: (x - above)/reference above it),
// window (lower, upper). Values carry their units; temperatures are absolute.
#include <vector>

#include <yaml-cpp/yaml.h>

#include "gearloss/case/yaml_reader.hpp"
#include "gearloss/mechanisms/empirical_mechanism.hpp"

namespace gearloss::io {

// Reads the `terms:` list (fails naming file, line and key on bad input).
std::vector<losses::EmpiricalTerm> read_empirical_terms(const YamlNode& terms);

// The same terms as YAML, in the units an engineer reads (rpm, N*m, degC, cSt).
YAML::Node empirical_terms_yaml(const std::vector<losses::EmpiricalTerm>& terms);

}  // namespace gearloss::io
