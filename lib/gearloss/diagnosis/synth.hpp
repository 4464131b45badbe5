#pragma once
// Synthetic rig campaigns from the coupled model with concealed effects, so
// that anyone can reproduce the proof that `diagnose` finds them.
#include <string>
#include <utility>
#include <vector>

#include "gearloss/io/config.hpp"
#include "gearloss/model/model.hpp"

namespace gearloss::diagnosis {

struct SynthOptions {
    std::vector<std::pair<std::string, double>> effects;  // effect id -> parameter (SI or dimensionless)
    double noise_loss = 0.015;     // relative, one standard deviation per recorded point
    double noise_temp = 0.4;       // K
    unsigned seed = 1;
    bool raw_log = false;          // a 0.5 Hz rig log instead of steady points
    double test_minutes = 240;     // duration of a stabilised test (log)
    double short_test_minutes = 60;  // duration of an unstabilised test (log)
    // Ceres-style check of the options (synthesize calls it): throws InputError naming the option.
    void validate() const;
};

// Returns the CSV text. Throws InputError for an unknown effect or a value
// outside the effect's bounds.
std::string synthesize(const solver::Model& model, const io::OperatingGrid& grid, const SynthOptions& opt);

// Parses "NAME=VALUE[unit]" for --effect (NAME a candidate of the model: effects.hpp).
std::pair<std::string, double> parse_effect_assignment(const solver::Model& model, const std::string& text);

}  // namespace gearloss::diagnosis
