#pragma once
// The candidate effects a model may have left out, built from the model itself: every
// calibration parameter of its loss mechanisms that names an effect (LossMechanism::
// parameters(), Parameter::effect), the oil and heat-path terms of the model's calibration,
// and the measurement artefacts of a rig (torque-sensor gain and offset, unstabilised tests).
// Each has one parameter with physical bounds; the diagnosis narrows them per campaign to
// sizes relative to the recorded losses (diagnose_internal.hpp, Engine::range).
#include <algorithm>
#include <cmath>
#include <functional>
#include <limits>
#include <memory>
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

// A published form selected on a mechanism's form axis (mesh friction law, H_V model, ...).
struct FormChoice {
    std::string mechanism, axis, form;
};

struct Hypothesis;

// A term that acts on the tests of one oil only (multi-oil campaigns): applied on top of the
// common terms when a point of that oil is evaluated.
struct OilTerm {
    int oil = 0;
    std::string effect;  // the effect's id (a refit replaces the value)
    std::function<void(Hypothesis&, double)> apply;
    double value = 0;
};

// What a hypothesis sets: physics (inside the coupled solve) and artefacts.
struct Hypothesis {
    solver::Calibration cal;          // oil and heat-path terms
    losses::MechanismSet mechanisms;  // the loss mechanisms with their calibration parameters
    std::vector<FormChoice> forms;    // forms other than the case's (applied after `mechanisms`)
    Artefacts art;
    std::vector<char> unstabilised;  // per point: its temperature is not an equilibrium value
    std::vector<OilTerm> per_oil;    // terms of one oil each (empty for a single-oil campaign)
    // The physics of `m` (its calibration and mechanisms) as described, as the starting point.
    static Hypothesis of(const solver::Model& m);
    void set(std::string_view mechanism, std::string_view parameter, double value);
    // Selects a form (replacing an earlier choice on the same axis).
    void select_form(const std::string& mechanism, const std::string& axis, const std::string& form);
    // Sets (or replaces) the value of a term of one oil.
    void set_oil_term(int oil, const std::string& effect, const std::function<void(Hypothesis&, double)>& apply,
                      double value);
    // Writes the physics of the hypothesis into a model (the common terms).
    void apply_to(solver::Model& m) const;
    // The same for the tests of oil `oil`: the common terms, then that oil's own.
    void apply_to(solver::Model& m, int oil) const;
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
    bool form = false;              // another published form (not a scale on today's)
};

// form: another published form of a mechanism (a discrete choice, no continuous parameter:
// its "parameter" is 0 for the case's form and 1 for the alternative).
enum class EffectKind { mechanism, oil, heat_path, artefact, pointwise, form };

struct Effect;

// A setting of an effect's shape that is fitted with it by profiling: the effect is fitted at
// each value of the grid and the best kept (mesh_friction_mixed: the film parameter below
// which the friction rises). `chosen` is NaN until the campaign's value is chosen.
struct ShapeProfile {
    std::string parameter;            // "mesh.mixed_friction_onset"
    std::vector<double> grid;         // ascending, with the case's own value
    double own = 0;                   // the case's value
    std::function<void(Hypothesis&, double)> apply;
    double chosen = std::numeric_limits<double>::quiet_NaN();
    // The effect's own parameter setter, before a value was chosen.
    std::function<void(Hypothesis&, double)> effect_apply;
    // The effect at every grid value (diagnose: profile_shapes), so that a joint refit can move
    // the shape with the other effects: owned by the chosen effect, pointed to by each variant.
    std::shared_ptr<const std::vector<Effect>> variants_owner;
    const std::vector<Effect>* variants = nullptr;
    // What the choice costs in the information criteria (units of ln-likelihood x 2): half the
    // prior weight on the case's own value, the other half shared by the other grid values, so
    // that keeping the case's value costs 2 ln 2 and moving costs 2 ln(2 (G - 1)) (about a
    // parameter's ln N when G = 5 and N = 50); a choice that is not made yet costs the move.
    // A refinement (deferred): not profiled when the effect is screened, moved only once it is
    // named, with the findings' joint refits; until it moves it is no parameter and costs
    // nothing, a move costs what a move from the case's value costs a profiled shape,
    // 2 ln(G - 1). (A friction factor confined to thin films would otherwise stand in for
    // mixed friction, a viscosity error or a drag before either is tried.)
    bool deferred = false;
    bool at_own() const { return !std::isfinite(chosen) || chosen == own; }
    double bic_penalty() const {
        const double others = static_cast<double>(std::max<size_t>(grid.size(), 2) - 1);
        if (deferred) return at_own() ? 0.0 : 2.0 * std::log(others);
        return chosen == own ? 2.0 * std::log(2.0) : 2.0 * std::log(2.0 * others);
    }
    // Whether the shape is a parameter fitted with the effect (a deferred one once it moved).
    bool fitted() const { return !deferred || !at_own(); }
};

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
    // Effects of one group exclude each other (the forms of one axis: "mesh.friction").
    std::string group;
    std::string form, case_form;  // a form effect: the alternative and the case's own form
    // The loss mechanism whose physics it changes ("mesh": its friction level, its mixed-film
    // rise and its friction law alike); empty for the oil, the heat path and the artefacts.
    std::string mechanism;
    // Multi-oil campaigns: an effect of one oil's tests (-1: of every test), its oil as
    // written in the recordings, and the id of the effect it restricts ("oil_viscosity").
    int oil = -1;
    std::string oil_name, base_id;
    // Whether the effect may differ from oil to oil (the oil's data, the lubricant's friction
    // level, its foaming): such effects are also offered per oil.
    bool oil_dependent = false;
    std::optional<ShapeProfile> shape;  // a setting profiled with the parameter (none: one parameter)
    // A factor on a mechanism's whole predicted loss (losses::Parameter::scales_loss), and the
    // value that leaves its published correlation unchanged. Above it, the factor is how the
    // diagnosis names a loss left out with that mechanism's signature (a second seal, parts
    // the model does not churn): whatever was left out sets its size. Below it, the factor
    // says the correlation itself over-predicts that mechanism's loss in this box, and that
    // error has a size: a log-normal prior, one standard deviation a factor 2 (an assumption
    // of this code, not a published scatter), so that churning at 7 % of its correlation
    // (cost 15 in BIC units) does not stand in for a thinner oil, which lowers churning,
    // bearing drag and seal friction together.
    bool scales_loss = false;
    double nominal = 1;
    // -2 ln of that prior (relative to the nominal value): ((ln(value / nominal)) / ln 2)^2
    // below nominal, 0 at or above it and for every other effect. Evaluated at the fitted
    // value and added to the effect's cost in every information criterion.
    double prior_penalty(double value) const;
    bool discrete() const { return kind == EffectKind::form; }
    // Its fitted parameters (the degrees of freedom the adequacy tests take off): a form none,
    // a profiled shape one more.
    int fitted_parameters() const { return discrete() ? 0 : shape && shape->fitted() ? 2 : 1; }
    // Its parameters whose cost is ln N each in the BIC: a form none, a law one (its shape is
    // paid for by shape->bic_penalty(), by its prior over the grid).
    int bic_parameters() const { return discrete() ? 0 : 1; }
    // What its shape's choice costs in the BIC (none without a shape).
    double shape_penalty() const { return shape ? shape->bic_penalty() : 0.0; }
    // What the effect costs in the BIC with n_obs observations (its parameters, its shape's
    // choice); at a fitted value also its prior.
    double bic_penalty(size_t n_obs) const {
        return bic_parameters() * std::log(static_cast<double>(n_obs)) + shape_penalty();
    }
    double bic_penalty(size_t n_obs, double value) const { return bic_penalty(n_obs) + prior_penalty(value); }
};

// The effect with its shape setting held at `value` (applied with the parameter): the
// profile's candidate at one grid value, and the campaign's choice.
Effect with_shape(const Effect& e, double value);

// The candidates of a model: its mechanisms' effect parameters (mechanisms switched off
// excepted), then viscosity, heat path and artefacts, then every alternative form of every
// form axis of its mechanisms ("friction:ehl_local": the case's mesh friction law replaced).
std::vector<Effect> candidate_effects(const solver::Model& m);
std::optional<Effect> find_effect(const solver::Model& m, const std::string& id);
// The per-oil copy of an oil-dependent effect: it acts on the tests of oil `oil` only.
Effect for_oil(const Effect& e, int oil, const std::string& oil_name);
// Every candidate id of a model, comma-separated (for messages).
std::string effect_names(const solver::Model& m);

// The part of [lower, upper] in which the model stays physical at every input speed up to
// `max_speed_rpm`: speed_dependent_cooling multiplies the heat flow to ambient by
// (1 + a (n/1000 rpm)^q), so a >= -0.9 (1000 rpm / n_max)^q keeps at least a tenth of it (positive,
// the coupled solve well posed); the other parameters keep their bounds. With
// `cooling_may_fall` false (a diagnosis of a case whose heat path has no speed dependence)
// a >= 0, or the case's calibrated value: air stirred by rotating parts or a rig fan adds
// cooling and cannot take any away; a negative value there would stand in for a heat path
// that changes with oil temperature (a thermal_resistance that is not constant).
std::pair<double, double> valid_range(const Effect& e, double max_speed_rpm, bool cooling_may_fall = true);

// Suggests the measurement that would tell two effects apart.
std::string separating_measurement(const Signature& a, const Signature& b);

}  // namespace gearloss::diagnosis
