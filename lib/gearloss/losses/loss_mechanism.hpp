#pragma once
// One interface for a loss mechanism (mesh friction, churning, bearings, seals, clutch drag,
// auxiliary, windage, ...), in the manner of Cantera's rate objects: each mechanism is a
// small object created by name from a registry (gearloss/losses/registry.cpp), sharing the
// per-temperature oil data of one evaluation (Evaluation) and keeping its own
// oil-independent terms of an operating point (MechanismPoint).
//
// The life of a mechanism in a solve:
//   prepare(model, input, point)   once per operating point, independent of the oil temperature;
//   power(model, point, eval, ...) the hot path: many times per point in the thermal solve.
// Everything that reports losses (CSV, --detail, point, JSON, cycle traces) loops over the
// mechanisms and takes its columns from them; the diagnosis reads their parameters and
// alternative forms without a hand-written list.
#include <memory>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "gearloss/core/issue.hpp"
#include "gearloss/lubricant/oil.hpp"

namespace gearloss::units {
struct Dimension;
}
namespace gearloss::solver {
struct Model;  // gearloss/model/model.hpp, a folder above this one (a model holds its mechanisms)
}

namespace gearloss::losses {

// The operating point as every mechanism sees it (SI: rad/s, N*m, W).
struct PointInput {
    double omega_in = 0, torque_in = 0, power_in = 0;
};

// Per-temperature data of one loss evaluation, computed once and shared by every
// mechanism (the oil state and the logarithm of its viscosity, from which the powers of
// nu of the empirical laws follow), and what the mechanisms report back about the films.
struct Evaluation {
    const lubricant::OilState& oil;
    double ln_nu_cSt = 0;     // ln(nu / (mm^2/s))
    bool want_film = false;   // compute the films (lambda_min) even when the loss does not need them
    double lambda_min = 0;    // smallest specific film thickness over loaded contacts
    bool has_lambda = false;
    void add_lambda(double lambda) {
        if (!has_lambda || lambda < lambda_min) lambda_min = lambda;
        has_lambda = true;
    }
};

// Oil-independent terms of one mechanism at one operating point (defined by the mechanism).
class MechanismPoint {
public:
    virtual ~MechanismPoint() = default;
    virtual std::unique_ptr<MechanismPoint> clone() const = 0;
};
template <class Derived>
class MechanismPointOf : public MechanismPoint {
public:
    std::unique_ptr<MechanismPoint> clone() const override {
        return std::make_unique<Derived>(static_cast<const Derived&>(*this));
    }
};

// A quantity reported per component with --detail: its CSV column ("{}" is replaced by the
// component's name) and the factor from SI to the column's unit. Quantities without a
// column are for the point report only (e.g. a churning regime as a number).
struct DetailQuantity {
    std::string column;   // "P_churn_{}_W", "h_min_{}_um"; empty: not in the CSV
    double csv_scale = 1.0;
};

// Per-component values of one evaluation: components x quantities, component-major;
// NaN means "no value" (an empty CSV cell).
struct MechanismDetail {
    std::vector<double> values;
    size_t quantities = 1;
    double at(size_t component, size_t quantity = 0) const { return values[component * quantities + quantity]; }
    double& at(size_t component, size_t quantity = 0) { return values[component * quantities + quantity]; }
    void reset(size_t components, size_t q);
};

// An adjustable number of a mechanism: a setting of the physics (an enclosure factor) or a
// calibration term (`calibration: {churning: {factor: 1.3}}`) that the diagnosis may fit.
struct Parameter {
    std::string name;            // key in the YAML block: "factor", "drag_f0", "power"
    std::string description;     // "scales every churning loss"
    const units::Dimension* dimension = nullptr;  // nullptr: a plain number
    std::string example;         // "20 W" (for error messages)
    double nominal = 0;          // the value that leaves the published model unchanged
    double lower = 0, upper = 0; // physical bounds (inclusive)
    bool calibration = true;     // read under `calibration:` (else under `mechanisms:`)
    // The diagnosis fits a calibration parameter that names an effect as a candidate: the
    // name it reports ("windage") and what a departure from nominal means physically. Its
    // bounds for a campaign are relative (an added loss up to a few times the recorded one),
    // within [lower, upper].
    std::string effect = {};     // empty: not a candidate
    std::string left_out = {};   // "air/oil-mist drag of the rotating gears, ..."
    // Whether the term may differ from oil to oil (a multi-oil campaign fits it per oil).
    bool oil_dependent = false;
    // The form that reads this setting ("fernandes_mixed"); empty: every form. A setting its
    // form reads and the case leaves at the nominal value is listed as assumed.
    std::string used_by = {};
    // A setting of an effect's shape (where mixed friction sets in) that the diagnosis cannot
    // scan as one more effect: it is profiled with that effect over these values and counts as
    // one more fitted parameter of it.
    std::string profiled_with = {};
    std::vector<double> profile_grid = {};
    // A refinement: not profiled when that effect is screened, moved over the grid only once it
    // is named (diagnosis: ShapeProfile::deferred).
    bool profile_deferred = false;
    // A factor on the mechanism's whole predicted loss (nominal 1): below nominal it says the
    // mechanism's own correlation over-predicts, which the diagnosis weighs by a prior
    // (diagnosis::Effect::prior_penalty).
    bool scales_loss = false;
};

// A choice between published forms of the same physics ("friction": schlenk, iso_6336_20, ...).
struct FormAxis {
    std::string axis;                 // "friction", "form"
    std::vector<std::string> forms;   // the names, the default first
};

// The names of a mechanism's components (gears, bearings, ...), for components().
template <class Items, class Name>
std::vector<std::string> names_of(const Items& items, Name name) {
    std::vector<std::string> v;
    v.reserve(items.size());
    for (const auto& x : items) v.push_back(name(x));
    return v;
}

class LossMechanism {
public:
    virtual ~LossMechanism() = default;
    virtual std::unique_ptr<LossMechanism> clone() const = 0;

    // Identity and output.
    virtual std::string_view name() const = 0;    // registry key, YAML key, JSON key ("churning")
    virtual std::string_view label() const = 0;   // for reports ("clutch drag")
    virtual std::string_view column() const = 0;  // CSV column of its total ("P_churn_W")
    // Whether its heat goes to the oil (else to the clutch-pack node of a thermal network).
    virtual bool heats_oil() const { return true; }

    // Components with a --detail column each (gears, bearings, ...), and their quantities.
    virtual std::vector<std::string> components(const solver::Model&) const { return {}; }
    virtual std::vector<DetailQuantity> quantities() const { return {}; }

    // Per operating point (oil independent).
    virtual std::unique_ptr<MechanismPoint> make_point() const = 0;
    // Fills `point` (made by make_point of this mechanism).
    virtual void prepare(const solver::Model&, const PointInput&, MechanismPoint& point) const = 0;
    // The first oil-independent term out of the model's range ("bearing B1 contact angle"), or empty.
    virtual std::string point_fault(const solver::Model&, const MechanismPoint&) const { return {}; }

    // Hot path: the loss [W] at the oil state of `eval`; `detail` (when not null) receives
    // the per-component values.
    virtual double power(const solver::Model&, const MechanismPoint&, Evaluation& eval,
                         MechanismDetail* detail) const = 0;
    // The first component whose loss is not a finite, non-negative number ("seal S1"), or empty.
    virtual std::string loss_fault(const solver::Model&, const MechanismPoint&, const MechanismDetail&) const;
    // The point report's section for this mechanism (a table of its components).
    virtual std::string report(const solver::Model&, const PointInput&, const MechanismPoint&,
                               const MechanismDetail&) const;

    // Parameters (with units and physical bounds) and their current values.
    virtual std::vector<Parameter> parameters() const { return {}; }
    double parameter(std::string_view name) const;
    void set_parameter(std::string_view name, double value);  // InputError for an unknown name
    bool parameters_nominal() const;
    // Whether set_parameter gave the parameter a value (the case wrote it), as opposed to
    // its nominal value.
    bool parameter_given(std::string_view name) const;
    // A value the oil gives for a setting of this mechanism (a measured lubricant property,
    // e.g. the boundary friction of the mesh); nullopt: the oil gives none.
    virtual std::optional<double> oil_value(const solver::Model&, std::string_view /*name*/) const {
        return std::nullopt;
    }
    // The value in force, and where it comes from: the case's setting, else the oil's, else
    // the nominal value.
    enum class Source { case_setting, oil, nominal };
    static const char* source_name(Source s);  // "case", "oil", "default" (for messages)
    double value_in(const solver::Model& m, std::string_view name) const;
    Source value_source(const solver::Model& m, std::string_view name) const;
    // Whether the selected forms read the parameter (Parameter::used_by empty or selected on an axis).
    bool reads(const solver::Model& m, const Parameter& p) const;
    // Alternative forms, selectable by name. Each mechanism keeps its own choice (a model
    // copy carries it with the mechanism set).
    virtual std::vector<FormAxis> forms(const solver::Model&) const { return {}; }
    virtual std::string form(const solver::Model&, std::string_view axis) const;
    // Selects a form (InputError for an unknown axis or name).
    virtual void set_form(solver::Model&, std::string_view axis, std::string_view form);

    // Whether the mechanism is switched on (`options: {losses: {bearings: false}}` switches
    // one off). A mechanism switched off contributes no loss: its prepare() leaves a point
    // without any, so the hot path needs no test of its own.
    bool enabled() const { return enabled_; }
    void set_enabled(bool on) { enabled_ = on; }

    // Issues of the mechanism's settings (parameters outside their bounds by default).
    virtual void validate(const solver::Model&, std::vector<solver::Issue>& out) const;

protected:
    // Value of parameter i of parameters() (the hot path reads these).
    double param(size_t i) const { return values_[i]; }
    bool given(size_t i) const { return given_[i]; }

public:
    // Every parameter at its nominal value (the registry calls this on creation).
    void reset_parameters();

private:
    std::vector<double> values_;  // per parameters(), in its order
    std::vector<bool> given_;     // per parameters(): set by set_parameter
    bool enabled_ = true;
};

}  // namespace gearloss::losses
