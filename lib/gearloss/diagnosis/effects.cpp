#include "gearloss/diagnosis/effects.hpp"

#include <algorithm>
#include <cmath>

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

const std::vector<Effect>& effect_library() {
    static const std::vector<Effect> lib = {
        {"windage", "air/oil-mist drag of the rotating gears, P = C (n/1000 rpm)^2.9, independent of oil viscosity and load",
         "C (loss at 1000 rpm)", "W", 0, 20000, 0, {true, false, false, false, 2.9, false},
         [](Hypothesis& h, double v) { h.set("windage", "empirical_W_at_1000rpm", v); }},
        {"churning", "churning level of the dipping gears (immersion or oil level) differs from the description",
         "churning factor", "", 0, 60, 1, {true, false, false, true, 1.6, false},
         [](Hypothesis& h, double v) { h.set("churning", "factor", v); }},
        {"bearing_drag", "load-independent viscous drag in the bearings (oil bath), Palmgren M0 = 1e-7 f0 (nu n)^(2/3) d_m^3",
         "f0", "", 0, 60, 0, {true, false, false, true, 1.67, false},
         [](Hypothesis& h, double v) { h.set("bearings", "drag_f0", v); }},
        {"seal_friction", "radial lip seal friction differs from the standard estimate (P ~ d^2 n)", "seal factor", "", 0,
         60, 1, {true, false, false, false, 1.0, false}, [](Hypothesis& h, double v) { h.set("seals", "factor", v); }},
        {"mesh_friction", "load-dependent mesh friction level differs (lubricant factor X_L, surface finish)",
         "mesh friction factor", "", 0.2, 5, 1, {true, false, true, false, 0.8, false},
         [](Hypothesis& h, double v) { h.set("mesh", "friction_factor", v); }},
        {"oil_viscosity", "the oil's viscosity-temperature data are off (other oil, aged or diluted oil)",
         "viscosity factor", "", 0.2, 5, 1, {true, false, false, true, 1.0, false},
         [](Hypothesis& h, double v) { h.cal.viscosity_factor = v; }},
        {"thermal_resistance", "the heat path to ambient differs (housing area, mounting, heat conducted into the rig)",
         "heat rejection factor", "", 0.2, 5, 1, {false, true, false, false, 0.0, false},
         [](Hypothesis& h, double v) { h.cal.heat_rejection_factor = v; }},
        {"speed_dependent_cooling", "forced convection grows with speed (air stirred by rotating parts or rig fans)",
         "cooling increase per 1000 rpm", "", -0.9, 10, 0, {false, true, false, false, 1.0, false},
         [](Hypothesis& h, double v) { h.cal.cooling_per_1000rpm = v; }},
        {"torque_sensor_gain", "input torque sensor gain error: the recorded loss carries (g - 1) P_in, the oil is not heated",
         "gain", "", 0.8, 1.2, 1, {false, false, true, false, 1.0, false},
         [](Hypothesis& h, double v) { h.art.torque_gain = v; }},
        {"torque_sensor_offset", "input torque sensor offset: the recorded loss carries T_0 omega, the oil is not heated",
         "offset", "N*m", -100, 100, 0, {false, false, false, false, 1.0, false},
         [](Hypothesis& h, double v) { h.art.torque_offset = v; }},
        {"unstabilised_test", "some tests were recorded before thermal equilibrium: oil colder (warming) or hotter (cooling) than its heat balance",
         "points still warming", "", 0, 0, 0, {false, false, false, false, 0.0, true}, nullptr},
        {"constant_parasitic", "a constant parasitic loss (oil pump, drag of an auxiliary part), heating the oil",
         "P_aux", "W", 0, 20000, 0, {true, false, false, false, 0.0, false},
         [](Hypothesis& h, double v) { h.set("auxiliary", "power", v); }},
    };
    return lib;
}

std::pair<double, double> valid_range(const Effect& e, double max_speed_rpm) {
    double lo = e.lower;
    if (e.id == "speed_dependent_cooling" && max_speed_rpm > 0 && std::isfinite(max_speed_rpm))
        lo = std::max(lo, -0.9 * 1000.0 / max_speed_rpm);
    return {lo, e.upper};
}

const Effect* find_effect(const std::string& id) {
    for (const auto& e : effect_library())
        if (e.id == id) return &e;
    return nullptr;
}

std::string separating_measurement(const Effect& a, const Effect& b) {
    const Signature &x = a.sig, &y = b.sig;
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
    return "run the gearbox without the component in question (e.g. seals removed, gears out of the oil)";
}

}  // namespace gearloss::diagnosis
