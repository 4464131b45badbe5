#pragma once
// Mesh friction as a loss mechanism: P_VZP = mu_mZ H_V |P_roll| per mesh (Niemann &
// Winter 1983; mu_mZ after Schlenk 1994 or ISO/TS 6336-20, or the mixed-film split of
// Fernandes et al. 2015, or local thermal EHL along the path of contact).
#include <memory>
#include <vector>

#include "losses/loss_mechanism.hpp"
#include "mesh/friction.hpp"

namespace gearloss::mesh {

// Oil-independent terms of one mesh at an operating point.
struct MeshState {
    double power = 0;         // rolling power magnitude [W] (relative to the carrier)
    double mu_prefactor = 0;  // mu = mu_prefactor * eta_mPas^-0.05 (Schlenk / ISO forms)
    double H_V = 0;
    LineContact contact;
    double sigma = 0;         // roughness for Lambda [m]
    double F_bn = 0;          // normal force of one mesh [N] (local EHL model)
    double omega_rel = 0;     // speed of gear 0 relative to the carrier [rad/s]
    // Film temperature rises of the local EHL nodes at the last oil temperature tried:
    // the warm start of the next evaluation of this point's thermal solve.
    mutable std::vector<double> ehl_film_rise;
};

struct MeshFrictionPoint : losses::MechanismPointOf<MeshFrictionPoint> {
    std::vector<MeshState> meshes;
};

// Detail quantities of the mesh mechanism, per mesh (MechanismDetail::at(mesh, q)).
enum MeshQuantity : size_t { kMeshPower = 0, kMeshMu, kMeshLambda, kMeshHmin, kMeshHc, kMeshQuantities };

// The mesh terms of a prepared point, from its per-mechanism data (solver::PointState::data).
const MeshFrictionPoint& mesh_friction_point(const solver::Model& m,
                                             const std::vector<std::unique_ptr<losses::MechanismPoint>>& data);

}  // namespace gearloss::mesh
