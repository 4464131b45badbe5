#include "gearloss/diagnosis/effects.hpp"

#include <algorithm>
#include <cmath>

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

void Hypothesis::apply_to(solver::Model& m) const {
    m.calibration = cal;
    m.mechanisms = mechanisms;
}

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
            e.apply = [mname = std::string(mech.name()), pname = p.name](Hypothesis& h, double x) { h.set(mname, pname, x); };
            v.push_back(std::move(e));
        }
    }
    const auto& c = m.calibration;
    v.push_back({"oil_viscosity", "the oil's viscosity-temperature data are off (other oil, aged or diluted oil)",
                 "viscosity factor", "", 0.2, 5, c.viscosity_factor, EffectKind::oil, true,
                 [](Hypothesis& h, double x) { h.cal.viscosity_factor = x; }});
    v.push_back({"thermal_resistance", "the heat path to ambient differs (housing area, mounting, heat conducted into the rig)",
                 "heat rejection factor", "", 0.2, 5, c.heat_rejection_factor, EffectKind::heat_path, true,
                 [](Hypothesis& h, double x) { h.cal.heat_rejection_factor = x; }});
    v.push_back({"speed_dependent_cooling", "forced convection grows with speed (air stirred by rotating parts or rig fans)",
                 "cooling increase per 1000 rpm", "", -0.9, 10, c.cooling_per_1000rpm, EffectKind::heat_path, false,
                 [](Hypothesis& h, double x) { h.cal.cooling_per_1000rpm = x; }});
    v.push_back({"torque_sensor_gain",
                 "input torque sensor gain error: the recorded loss carries (g - 1) P_in, the oil is not heated", "gain", "",
                 0.5, 2, 1, EffectKind::artefact, false, [](Hypothesis& h, double x) { h.art.torque_gain = x; }});
    v.push_back({"torque_sensor_offset",
                 "input torque sensor offset: the recorded loss carries T_0 omega, the oil is not heated", "offset", "N*m",
                 -1e6, 1e6, 0, EffectKind::artefact, false, [](Hypothesis& h, double x) { h.art.torque_offset = x; }});
    v.push_back({"unstabilised_test",
                 "some tests were recorded before thermal equilibrium: oil colder (warming) or hotter (cooling) than "
                 "the heat balance of the measured loss",
                 "points still warming", "", 0, 0, 0, EffectKind::pointwise, false, nullptr});
    return v;
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

std::pair<double, double> valid_range(const Effect& e, double max_speed_rpm) {
    double lo = e.lower;
    if (e.id == "speed_dependent_cooling" && max_speed_rpm > 0 && std::isfinite(max_speed_rpm))
        lo = std::max(lo, -0.9 * 1000.0 / max_speed_rpm);
    return {lo, e.upper};
}

std::string separating_measurement(const Signature& x, const Signature& y) {
    if (x.pointwise != y.pointwise)
        return "extend the suspect tests until (T_oil - T_room) varies < 0.5 K over 30 min and re-record them";
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
