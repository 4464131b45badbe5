#pragma once
// Synthetic rig campaigns from the coupled model with concealed effects, so
// that anyone can reproduce the proof that `diagnose` finds them.
#include <string>
#include <utility>
#include <vector>

#include "gearloss/case/config.hpp"
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

// The effects `--effect` accepts, one per line with its unit and the value that leaves the model
// unchanged (its default), then the forms, and the default noise (`synth --help`): generated from
// candidate_effects() of a model with every registered mechanism, so that a mechanism added to
// the registry shows here without an edit. A case may offer fewer (mechanisms switched off) or
// other forms than the defaults (its own forms are the neutral ones).
std::string effects_help();

}  // namespace gearloss::diagnosis
