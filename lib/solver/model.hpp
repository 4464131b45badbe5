#pragma once
// The complete description of one gearbox case: topology and its derived
// layout, the oil, the selected loss models and the thermal settings.
#include <string>
#include <vector>

#include "gearbox/gearbox.hpp"
#include "lubricant/oil.hpp"
#include "mesh/friction.hpp"
#include "mesh/loss_factor.hpp"
#include "thermal/equilibrium.hpp"
#include "thermal/heat_rejection.hpp"

namespace gearloss::solver {

enum class LambdaRoughness { average_Ra, composite_Rq };

struct LossOptions {
    bool mesh = true, churning = true, bearings = true, seals = true;
    mesh::LossFactorModel loss_factor = mesh::LossFactorModel::ohlendorf;
    mesh::FrictionModel friction = mesh::FrictionModel::schlenk;
    mesh::ThermalFilmCorrection film_correction = mesh::ThermalFilmCorrection::gupta;
    LambdaRoughness lambda_roughness = LambdaRoughness::average_Ra;
    double gear_mu_bl = 0.10, gear_mu_ehl = 0.02;  // boundary / full-film pair of the mixed model
};

enum class ThermalMode { stabilised, fixed };

struct ThermalSettings {
    ThermalMode mode = ThermalMode::stabilised;
    double oil_temperature = 353.15;  // K, fixed mode
    double ambient = 298.15;          // K
    thermal::HeatRejection rejection;
    thermal::EquilibriumOptions equilibrium;
};

struct Model {
    std::string name;
    gearbox::Gearbox gearbox;
    gearbox::Layout layout;
    lubricant::Oil oil;
    LossOptions options;
    ThermalSettings thermal;
    // Mean entrainment-independent data of each mesh computed once.
    std::vector<double> mesh_E_prime;  // Pa
    void finalise();  // derive layout and per-mesh constants; throws on bad topology
};

}  // namespace gearloss::solver
