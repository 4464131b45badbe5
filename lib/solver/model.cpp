#include "solver/model.hpp"

#include <cmath>

namespace gearloss::solver {

bool Calibration::neutral() const {
    return windage_W_at_1000rpm == 0 && churning_factor == 1 && bearing_drag_f0 == 0 && seal_factor == 1 &&
           mesh_friction_factor == 1 && viscosity_factor == 1 && heat_rejection_factor == 1 &&
           cooling_per_1000rpm == 0 && auxiliary_W == 0;
}

lubricant::OilState Model::oil_state(double T) const {
    lubricant::OilState s = oil.state(T);
    if (calibration.viscosity_factor != 1.0) {
        const double f = calibration.viscosity_factor;
        s.nu *= f;
        s.nu_cSt *= f;
        s.eta *= f;
        s.alpha_p = oil.pressure_viscosity(T, s.nu_cSt);
    }
    return s;
}

double Model::heat_flow(double T_oil, double T_amb, double omega_in) const {
    const double n_k = std::abs(omega_in) * 30.0 / 3.14159265358979323846 / 1000.0;
    return thermal.rejection.heat_flow(T_oil, T_amb, omega_in) * calibration.heat_rejection_factor *
           (1.0 + calibration.cooling_per_1000rpm * n_k);
}

void Model::finalise() {
    layout = gearbox::analyse(gearbox);
    mesh_E_prime.resize(gearbox.meshes.size());
    for (size_t i = 0; i < gearbox.meshes.size(); ++i) {
        const auto& m1 = gearbox.gears[gearbox.meshes[i].gear[0]].spec.material;
        const auto& m2 = gearbox.gears[gearbox.meshes[i].gear[1]].spec.material;
        mesh_E_prime[i] = 2.0 / ((1.0 - m1.poisson * m1.poisson) / m1.E + (1.0 - m2.poisson * m2.poisson) / m2.E);
    }
}

}  // namespace gearloss::solver
