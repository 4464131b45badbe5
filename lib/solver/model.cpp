#include "solver/model.hpp"

namespace gearloss::solver {

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
