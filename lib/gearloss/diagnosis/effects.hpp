#pragma once
// The candidate effects a model may have left out, built from the model itself: every
// calibration parameter of its loss mechanisms that names an effect (LossMechanism::
// parameters(), Parameter::effect), the oil and heat-path terms of the model's calibration,
// and the measurement artefacts of a rig (torque-sensor gain and offset, unstabilised tests).
// Each has one parameter with physical bounds; the diagnosis narrows them per campaign to
// sizes relative to the recorded losses (diagnose_internal.hpp, Engine::range).
#include <functional>
#include <optional>
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

// How an effect shows in recordings, measured on the model at the campaign's points
// (Engine::signature), so that a mechanism added to the registry needs no table here.
struct Signature {
    bool heats_oil = true;          // a real loss: it raises the stabilised oil temperature
    bool thermal_path = false;      // acts on the heat rejection, not on the loss
    bool load_dependent = false;
    bool viscosity_dependent = false;
    double speed_exponent = 0;      // power of input speed in the loss it adds (or in the cooling)
    bool pointwise = false;         // concerns single points, not a law
};

enum class EffectKind { mechanism, oil, heat_path, artefact, pointwise };

struct Effect {
    std::string id;
    std::string description;
    std::string parameter;   // name of the parameter
    std::string unit;        // as reported ("" = dimensionless)
    double lower = 0, upper = 0, neutral = 0;  // physical bounds and the value of the case as described
    EffectKind kind = EffectKind::mechanism;
    bool multiplicative = false;  // a factor on a property (scanned on a log scale)
    // Sets the parameter (SI / dimensionless) on a hypothesis.
    std::function<void(Hypothesis&, double)> apply;
};

// The candidates of a model: its mechanisms' effect parameters (mechanisms switched off
// excepted), then viscosity, heat path and artefacts.
std::vector<Effect> candidate_effects(const solver::Model& m);
std::optional<Effect> find_effect(const solver::Model& m, const std::string& id);
// Every candidate id of a model, comma-separated (for messages).
std::string effect_names(const solver::Model& m);

// The part of [lower, upper] in which the model stays physical at every input speed up to
// `max_speed_rpm`: speed_dependent_cooling multiplies the heat flow to ambient by
// (1 + a n/1000 rpm), so a >= -0.9 (1000 rpm / n_max) keeps at least a tenth of it (positive,
// the coupled solve well posed); the other parameters keep their bounds.
std::pair<double, double> valid_range(const Effect& e, double max_speed_rpm);

// Suggests the measurement that would tell two effects apart.
std::string separating_measurement(const Signature& a, const Signature& b);

}  // namespace gearloss::diagnosis
