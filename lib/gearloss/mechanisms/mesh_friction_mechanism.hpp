#pragma once
// Mesh friction as a loss mechanism: P_VZP = mu_mZ H_V |P_roll| per mesh (Niemann &
// Winter 1983; mu_mZ after Schlenk 1994 or ISO/TS 6336-20, or the mixed-film split of
// Fernandes et al. 2015, or local thermal EHL along the path of contact).
#include <memory>
#include <vector>

#include "gearloss/losses/loss_mechanism.hpp"
#include "gearloss/mesh/ehl_contact.hpp"
#include "gearloss/mesh/friction.hpp"
#include "gearloss/mesh/loss_factor.hpp"

namespace gearloss::mesh {

// The roughness sigma of the specific film thickness Lambda = h_c / sigma: the mean of the
// two flanks' Ra (Doleschel 2003, the ISO gear practice) or the composite sqrt(Rq1^2 + Rq2^2)
// (Rq = 1.25 Ra when not given, the Gaussian ratio).
enum class LambdaRoughness { average_Ra, composite_Rq };

// The model choices the mesh mechanism owns (set by the case's `options:` keys or its
// `mechanisms: {mesh: ...}` block). friction, loss_factor and film_correction are its form
// axes (`check`, `map --spread`). The roughness of Lambda is a setting outside the spread:
// only fernandes_mixed and the ehl_ forms read Lambda, so as an axis it would double the
// combinations (135 to 270 on every shipped case) while half of the added ones repeat a total.
struct MeshForms {
    FrictionModel friction = FrictionModel::schlenk;
    // Rigid load sharing over the contact lines (Wimmer 2006 H_VL): for spur pairs it equals
    // Ohlendorf (1958) within 0.2 %; for helical pairs Ohlendorf's closed form, which only
    // divides the spur form by cos beta_b, is 12-16 % low.
    LossFactorModel loss_factor = LossFactorModel::wimmer;
    ThermalFilmCorrection film_correction = ThermalFilmCorrection::gupta;
    LambdaRoughness lambda_roughness = LambdaRoughness::average_Ra;
};

// The traction law of a local-EHL friction form (Eyring for every other form).
inline TractionLaw traction_law(FrictionModel f) {
    return f == FrictionModel::ehl_maxwell ? TractionLaw::maxwell_eyring : TractionLaw::eyring;
}

// The choices of the model's mesh mechanism, by type (for code that names them: the case
// loader's `options:` keys, the reports, tests); generic code goes through form()/set_form().
const MeshForms& mesh_forms(const solver::Model& m);
MeshForms& mesh_forms(solver::Model& m);

// The boundary / full-film friction pair of the mixed-film model (Fernandes et al. 2015, the
// mesh mechanism's settings mu_bl and mu_ehl) holds 0 <= mu_ehl < mu_bl < 1.
bool mixed_friction_pair_valid(double mu_bl, double mu_ehl);

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
