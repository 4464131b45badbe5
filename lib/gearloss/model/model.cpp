#include "gearloss/model/model.hpp"

#include "gearloss/losses/loss_mechanism.hpp"
#include "gearloss/model/validate.hpp"

#include <algorithm>
#include <boost/math/tools/toms748_solve.hpp>
#include <cmath>
#include <fmt/format.h>
#include <fmt/ranges.h>

#include "gearloss/core/errors.hpp"

namespace gearloss::solver {

bool Calibration::neutral() const {
    return viscosity_factor == 1 && heat_rejection_factor == 1 && cooling_per_1000rpm == 0 && heat_rejection_rise_slope == 0;
}

bool Model::calibration_neutral() const {
    if (!calibration.neutral()) return false;
    for (size_t i = 0; i < mechanisms.size(); ++i)
        if (!mechanisms[i].parameters_nominal()) return false;
    return true;
}

lubricant::OilState Model::oil_state(double T) const {
    return oil.state(T, calibration.viscosity_factor);
}

double Model::surface_heat_flow(double T_surface, double T_amb, double omega_in, double air_speed) const {
    const double n_k = std::abs(omega_in) * 30.0 / 3.14159265358979323846 / 1000.0;
    const double q = calibration.cooling_speed_exponent;
    const double forced = calibration.cooling_per_1000rpm == 0.0 ? 0.0
                          : calibration.cooling_per_1000rpm * (q == 1.0 ? n_k : std::pow(n_k, q));
    // |s| <= 0.2 (validate_calibration) keeps the heat flow growing with the rise up to 150 K.
    // Beyond 0 to 150 K the factor is held at its end, so that the heat flow stays positive and
    // growing at any temperature an equilibrium search brackets (a colder surface than the
    // ambient, a rise of several hundred kelvin).
    const double s = calibration.heat_rejection_rise_slope;
    const double rise = s == 0.0 ? 1.0 : 1.0 + s * (std::clamp(T_surface - T_amb, 0.0, 150.0) - 50.0) / 50.0;
    return thermal.rejection.heat_flow(T_surface, T_amb, omega_in, air_speed) * calibration.heat_rejection_factor *
           (1.0 + forced) * rise;
}

double Model::cooler_heat_flow(double T_oil) const {
    if (!thermal.cooler.present()) return 0.0;
    const lubricant::OilState s = oil.state(T_oil);
    return thermal.cooler.heat_flow(T_oil, s.rho * s.cp);
}

double Model::cooler_conductance(double T_oil) const {
    if (!thermal.cooler.present()) return 0.0;
    const lubricant::OilState s = oil.state(T_oil);
    return thermal.cooler.valve_share(T_oil) * thermal.cooler.conductance(s.rho * s.cp);
}

double Model::heat_flow(double T_oil, double T_amb, double omega_in) const {
    return housing_heat_flow(T_oil, T_amb, omega_in) + cooler_heat_flow(T_oil);
}

double Model::housing_heat_flow(double T_oil, double T_amb, double omega_in) const {
    const auto& net = thermal.network;
    if (!net.has_housing()) return surface_heat_flow(T_oil, T_amb, omega_in);
    // Steady state: G (T_oil - T_h) = Q_surface(T_h) for T_h between ambient and T_oil;
    // the left side falls and the right side rises with T_h.
    auto f = [&](double Th) { return net.G_oil_housing * (T_oil - Th) - surface_heat_flow(Th, T_amb, omega_in); };
    double lo = std::min(T_amb, T_oil), hi = std::max(T_amb, T_oil);
    if (hi - lo < 1e-9) return surface_heat_flow(T_oil, T_amb, omega_in);
    std::uintmax_t it = 60;
    const auto [a, b] = boost::math::tools::toms748_solve(
        f, lo, hi, [](double x, double y) { return std::abs(y - x) < 1e-7; }, it);
    const double Th = 0.5 * (a + b);
    return net.G_oil_housing * (T_oil - Th);
}

void Model::finalise() {
    // Indices that would make the analysis read out of bounds (a model built in code): a
    // topology error before anything else. The other checks are validate()'s (gearloss/model/validate.hpp).
    for (const Issue& is : validate(*this))
        if (is.structural) throw gearbox::TopologyError(is.text(), is.section, is.item, is.key);
    layout = gearbox::analyse(gearbox);
    mesh_E_prime.resize(gearbox.meshes.size());
    for (size_t i = 0; i < gearbox.meshes.size(); ++i) {
        const auto& m1 = gearbox.gears[gearbox.meshes[i].gear[0]].spec.material;
        const auto& m2 = gearbox.gears[gearbox.meshes[i].gear[1]].spec.material;
        mesh_E_prime[i] = 2.0 / ((1.0 - m1.poisson * m1.poisson) / m1.E + (1.0 - m2.poisson * m2.poisson) / m2.E);
    }
}

std::vector<std::string> Model::ratio_names() const {
    std::vector<std::string> v;
    for (const auto& r : gearbox.ratios) v.push_back(r.name);
    return v;
}

void Model::select_ratio(std::string_view name) {
    const auto it = std::find_if(gearbox.ratios.begin(), gearbox.ratios.end(), [&](const auto& r) { return r.name == name; });
    if (it == gearbox.ratios.end()) {
        const std::string defined = fmt::format("{}", fmt::join(ratio_names(), ", "));
        throw InputError("", 0, 0, "gearbox.ratio",
                         gearbox.ratios.empty() ? std::string("the case defines no 'gearbox.ratios'")
                                                : fmt::format("unknown ratio '{}'; defined: {}", name, defined));
    }
    gearbox.engaged = it->engaged;
    ratio = it->name;
    finalise();
}

Model Model::with_ratio(std::string_view name) const {
    Model m = *this;
    m.select_ratio(name);
    return m;
}

}  // namespace gearloss::solver
