#pragma once
// Library of candidate effects that a model may have left out. Each has an id,
// a one-line physical description, one physically bounded parameter and a
// signature (how it shows in the data) used to suggest a separating measurement.
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "gearloss/losses/loss_mechanism.hpp"
#include "gearloss/model/model.hpp"

namespace gearloss::diagnosis {

// Measurement artefacts: they change the recorded loss, not the oil temperature.
struct Artefacts {
    double torque_gain = 1.0;      // recorded input torque = gain * true + offset
    double torque_offset = 0.0;    // N m
};

// What a hypothesis sets: physics (inside the coupled solve) and artefacts.
struct Hypothesis {
    solver::Calibration cal;          // oil and heat-path terms
    losses::MechanismSet mechanisms;  // the loss mechanisms with their calibration parameters
    Artefacts art;
    std::vector<char> unstabilised;  // per point: its temperature is not an equilibrium value
    // The physics of `m` (its calibration and mechanisms) as described, as the starting point.
    static Hypothesis of(const solver::Model& m);
    void set(std::string_view mechanism, std::string_view parameter, double value);
    // Writes the physics of the hypothesis into a model.
    void apply_to(solver::Model& m) const;
};

struct Signature {
    bool heats_oil;          // a real loss: it raises the stabilised oil temperature
    bool thermal_path;       // acts on the heat rejection, not on the loss
    bool load_dependent;
    bool viscosity_dependent;
    double speed_exponent;   // approximate power of input speed in the loss (or in the cooling)
    bool pointwise;          // concerns single points, not a law
};

struct Effect {
    std::string id;
    std::string description;
    std::string parameter;   // name of the parameter
    std::string unit;        // as reported ("" = dimensionless)
    double lower, upper, neutral;
    Signature sig;
    // Sets the parameter (SI / dimensionless) on a hypothesis.
    void (*apply)(Hypothesis&, double);
};

const std::vector<Effect>& effect_library();

// The part of [lower, upper] in which the model stays physical at every input speed up to
// `max_speed_rpm`: speed_dependent_cooling multiplies the heat flow to ambient by
// (1 + a n/1000 rpm), so a >= -0.9 (1000 rpm / n_max) keeps at least a tenth of it (positive,
// the coupled solve well posed); the other parameters keep their bounds.
std::pair<double, double> valid_range(const Effect& e, double max_speed_rpm);
const Effect* find_effect(const std::string& id);

// Suggests the measurement that would tell two effects apart.
std::string separating_measurement(const Effect& a, const Effect& b);

}  // namespace gearloss::diagnosis
