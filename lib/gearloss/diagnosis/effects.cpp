#include "gearloss/diagnosis/effects.hpp"

#include <algorithm>
#include <cmath>

#include <fmt/format.h>

#include "gearloss/units/units.hpp"

namespace gearloss::diagnosis {

Hypothesis Hypothesis::of(const solver::Model& m) {
    Hypothesis h;
    h.cal = m.calibration;
    h.mechanisms = m.mechanisms;
    return h;
}

void Hypothesis::set(std::string_view mechanism, std::string_view parameter, double value) {
    mechanisms.at(mechanism).set_parameter(parameter, value);
}

void Hypothesis::select_form(const std::string& mechanism, const std::string& axis, const std::string& form) {
    for (auto& f : forms)
        if (f.mechanism == mechanism && f.axis == axis) {
            f.form = form;
            return;
        }
    forms.push_back({mechanism, axis, form});
}

void Hypothesis::set_oil_term(int oil, const std::string& effect, const std::function<void(Hypothesis&, double)>& apply,
                              double value) {
    for (auto& t : per_oil)
        if (t.oil == oil && t.effect == effect) {
            t.value = value;
            return;
        }
    per_oil.push_back({oil, effect, apply, value});
}

void Hypothesis::apply_to(solver::Model& m, int oil) const {
    if (std::none_of(per_oil.begin(), per_oil.end(), [&](const OilTerm& t) { return t.oil == oil; })) {
        apply_to(m);
        return;
    }
    Hypothesis h = *this;
    h.per_oil.clear();
    for (const auto& t : per_oil)
        if (t.oil == oil) t.apply(h, t.value);
    h.apply_to(m);
}

Effect for_oil(const Effect& e, int oil, const std::string& oil_name) {
    Effect x = e;
    x.base_id = e.id;
    x.id = e.id + "@" + oil_name;
    x.oil = oil;
    x.oil_name = oil_name;
    if (x.shape) x.shape->variants = nullptr;  // the shape stays the common effect's (no variants of one oil)
    x.apply = [oil, id = e.id, f = e.apply](Hypothesis& h, double v) { h.set_oil_term(oil, id, f, v); };
    return x;
}

void Hypothesis::apply_to(solver::Model& m) const {
    m.calibration = cal;
    m.mechanisms = mechanisms;
    for (const auto& f : forms) m.mechanisms.at(f.mechanism).set_form(m, f.axis, f.form);
}

double Effect::prior_penalty(double value) const {
    if (!scales_loss || !(value < nominal) || !(nominal > 0)) return 0.0;
    // A factor at (or below) a thousandth of nominal costs what a thousandth does (100): the
    // mechanism switched off is possible, only very unlikely.
    const double z = std::log(std::max(value / nominal, 1e-3)) / std::log(2.0);
    return z * z;
}

namespace {
// A candidate of the diagnosis itself (oil, heat path, artefacts), not of a mechanism.
Effect builtin(std::string id, std::string description, std::string parameter, std::string unit, double lower,
               double upper, double neutral, EffectKind kind, bool multiplicative,
               std::function<void(Hypothesis&, double)> apply) {
    Effect e;
    e.id = std::move(id);
    e.description = std::move(description);
    e.parameter = std::move(parameter);
    e.unit = std::move(unit);
    e.lower = lower;
    e.upper = upper;
    e.neutral = neutral;
    e.kind = kind;
    e.multiplicative = multiplicative;
    e.apply = std::move(apply);
    return e;
}

// Gives e a shape setting profiled with its parameter (the case's own value among the grid's).
void give_shape(Effect& e, std::string parameter, std::vector<double> grid, double own,
                std::function<void(Hypothesis&, double)> apply) {
    ShapeProfile s;
    s.parameter = std::move(parameter);
    s.grid = std::move(grid);
    s.own = own;
    if (std::find(s.grid.begin(), s.grid.end(), own) == s.grid.end()) s.grid.push_back(own);
    std::sort(s.grid.begin(), s.grid.end());
    s.apply = std::move(apply);
    s.effect_apply = e.apply;
    e.shape = std::move(s);
}
}  // namespace

std::vector<Effect> candidate_effects(const solver::Model& m) {
    std::vector<Effect> v;
    for (size_t k = 0; k < m.mechanisms.size(); ++k) {
        const auto& mech = m.mechanisms[k];
        if (!mech.enabled()) continue;
        for (const auto& p : mech.parameters()) {
            if (p.effect.empty() || !p.calibration) continue;
            Effect e;
            e.id = p.effect;
            e.description = p.left_out.empty() ? p.description : p.left_out;
            e.parameter = std::string(mech.name()) + "." + p.name;
            if (p.dimension == &units::dim::power) e.unit = "W";
            e.lower = p.lower;
            e.upper = p.upper;
            e.neutral = mech.parameter(p.name);
            e.kind = EffectKind::mechanism;
            e.mechanism = std::string(mech.name());
            e.oil_dependent = p.oil_dependent;
            e.group = e.id;
            e.scales_loss = p.scales_loss;
            e.nominal = p.nominal;
            e.apply = [mname = std::string(mech.name()), pname = p.name](Hypothesis& h, double x) { h.set(mname, pname, x); };
            v.push_back(std::move(e));
        }
        // Shape settings profiled with one of this mechanism's effects (the case's own value
        // among the grid's).
        for (const auto& p : mech.parameters()) {
            if (p.profiled_with.empty()) continue;
            for (auto& e : v)
                if (e.id == p.profiled_with && e.parameter.starts_with(std::string(mech.name()) + ".")) {
                    give_shape(e, std::string(mech.name()) + "." + p.name, p.profile_grid, mech.parameter(p.name),
                               [mname = std::string(mech.name()), pname = p.name](Hypothesis& h, double x) {
                                   h.set(mname, pname, x);
                               });
                    e.shape->deferred = p.profile_deferred;
                }
        }
    }
    const auto& c = m.calibration;
    v.push_back(builtin("oil_viscosity", "the oil's viscosity-temperature data are off (other oil, aged or diluted oil)",
                 "viscosity factor", "", 0.2, 5, c.viscosity_factor, EffectKind::oil, true,
                 [](Hypothesis& h, double x) { h.cal.viscosity_factor = x; }));
    v.back().oil_dependent = true;  // each oil has its own viscosity data
    v.push_back(builtin("thermal_resistance", "the heat path to ambient differs (housing area, mounting, heat conducted into the rig)",
                 "heat rejection factor", "", 0.2, 5, c.heat_rejection_factor, EffectKind::heat_path, true,
                 [](Hypothesis& h, double x) { h.cal.heat_rejection_factor = x; }));
    // Its change with the surface's rise over ambient, moved once the heat path is named (a
    // refinement): a rig's path is rarely linear in the rise (Model::surface_heat_flow).
    give_shape(v.back(), "heat_rejection_rise_slope", {-0.15, 0.0, 0.15}, c.heat_rejection_rise_slope,
               [](Hypothesis& h, double s) { h.cal.heat_rejection_rise_slope = s; });
    v.back().shape->deferred = true;
    v.push_back(builtin("speed_dependent_cooling", "forced convection grows with speed (air stirred by rotating parts or rig fans)",
                 "cooling increase per 1000 rpm", "", -0.9, 10, c.cooling_per_1000rpm, EffectKind::heat_path, false,
                 [](Hypothesis& h, double x) { h.cal.cooling_per_1000rpm = x; }));
    // Its power of speed fitted with it: forced convection grows as Re^0.5 to Re^0.8
    // (Incropera et al. 2007, ch. 7), the case's linear law is the upper end.
    give_shape(v.back(), "cooling_speed_exponent", {0.5, 0.65, 0.8, 1.0}, c.cooling_speed_exponent,
               [](Hypothesis& h, double q) { h.cal.cooling_speed_exponent = q; });
    v.push_back(builtin("torque_sensor_gain",
                 "input torque sensor gain error: the recorded loss carries (g - 1) P_in, the oil is not heated", "gain", "",
                 0.5, 2, 1, EffectKind::artefact, false, [](Hypothesis& h, double x) { h.art.torque_gain = x; }));
    v.push_back(builtin("torque_sensor_offset",
                 "input torque sensor offset: the recorded loss carries T_0 omega, the oil is not heated", "offset", "N*m",
                 -1e6, 1e6, 0, EffectKind::artefact, false, [](Hypothesis& h, double x) { h.art.torque_offset = x; }));
    v.push_back(builtin("unstabilised_test",
                 "some tests were recorded before thermal equilibrium: oil colder (warming) or hotter (cooling) than "
                 "the heat balance of the measured loss",
                 "points still warming", "", 0, 0, 0, EffectKind::pointwise, false, nullptr));
    for (auto& e : v) e.group = e.id;  // an effect and its per-oil copies exclude each other
    // Model form: each alternative of each form axis, as a discrete candidate. The axis is
    // named by itself ("friction", "loss_factor") or, for a mechanism's single "form" axis, by
    // the mechanism ("windage").
    for (size_t k = 0; k < m.mechanisms.size(); ++k) {
        const auto& mech = m.mechanisms[k];
        if (!mech.enabled()) continue;
        for (const auto& axis : mech.forms(m)) {
            const std::string current = mech.form(m, axis.axis);
            const std::string label = axis.axis == "form" ? std::string(mech.name()) : axis.axis;
            for (const auto& form : axis.forms) {
                if (form == current) continue;
                Effect e;
                e.id = label + ":" + form;
                e.description = fmt::format("model form: the {} {} follows {}, not the case's {} (another published form)",
                                            mech.label(), axis.axis == "form" ? "model" : axis.axis, form, current);
                e.parameter = std::string(mech.name()) + "." + axis.axis;
                e.lower = 0;
                e.upper = 1;
                e.neutral = 0;
                e.kind = EffectKind::form;
                e.mechanism = std::string(mech.name());
                e.group = e.parameter;
                e.form = form;
                e.case_form = current;
                e.apply = [mname = std::string(mech.name()), ax = axis.axis, form](Hypothesis& h, double x) {
                    if (x >= 0.5) h.select_form(mname, ax, form);
                };
                v.push_back(std::move(e));
            }
        }
    }
    return v;
}

Effect with_shape(const Effect& e, double value) {
    Effect x = e;
    if (!e.shape) return x;
    x.shape->chosen = value;
    x.apply = [inner = e.shape->effect_apply, set = e.shape->apply, value](Hypothesis& h, double v) {
        set(h, value);
        inner(h, v);
    };
    return x;
}

std::optional<Effect> find_effect(const solver::Model& m, const std::string& id) {
    for (auto& e : candidate_effects(m))
        if (e.id == id) return e;
    return std::nullopt;
}

std::string effect_names(const solver::Model& m) {
    std::string all;
    for (const auto& e : candidate_effects(m)) all += (all.empty() ? "" : ", ") + e.id;
    return all;
}

std::pair<double, double> valid_range(const Effect& e, double max_speed_rpm, bool cooling_may_fall) {
    double lo = e.lower;
    if (e.id != "speed_dependent_cooling") return {lo, e.upper};
    const double q = e.shape && std::isfinite(e.shape->chosen) ? e.shape->chosen : 1.0;  // its power of speed
    if (max_speed_rpm > 0 && std::isfinite(max_speed_rpm)) lo = std::max(lo, -0.9 / std::pow(max_speed_rpm / 1000.0, q));
    if (!cooling_may_fall) lo = std::max(lo, std::min(0.0, e.neutral));
    return {lo, e.upper};
}

std::string separating_measurement(const Signature& x, const Signature& y) {
    if (x.pointwise != y.pointwise)
        return "extend the suspect tests until (T_oil - T_room) varies < 0.5 K over 30 min and re-record them";
    if (x.form != y.form)
        return "extend the load range and repeat a few points at another oil temperature: a form changes how the "
               "loss follows load and film thickness, a scale factor does not";
    if (x.thermal_path != y.thermal_path)
        return "measure the loss at a fixed, controlled oil temperature: a heat-path error leaves the loss unchanged";
    if (x.heats_oil != y.heats_oil)
        return "record the stabilised oil temperature at every point: a real loss heats the oil, a torque-sensor error "
               "does not (or re-calibrate the torque sensors statically)";
    if (x.load_dependent != y.load_dependent)
        return "add points at no load and at the highest torque: only one of them depends on load";
    if (x.viscosity_dependent != y.viscosity_dependent)
        return "repeat a few points at another oil temperature (temperature-controlled run): only viscous losses change";
    if (std::abs(x.speed_exponent - y.speed_exponent) > 0.4)
        return "widen the speed range (at least 3:1): the two grow with different powers of speed";
    return "run the gearbox without the component in question (e.g. seals removed, gears out of the oil), or with "
           "another oil";
}

}  // namespace gearloss::diagnosis
