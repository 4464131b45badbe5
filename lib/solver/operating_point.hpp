#pragma once
// Losses at one operating point and the coupled (stabilised) oil temperature.
#include <string>
#include <vector>

#include "bearings/skf_model.hpp"
#include "churning/changenet_velex.hpp"
#include "solver/model.hpp"

namespace gearloss::solver {

// Everything about a point that does not depend on the oil temperature:
// kinematics, mesh loads, bearing load terms (computed once per point).
struct PointState {
    double omega_in = 0, torque_in = 0, power_in = 0;
    struct MeshState {
        double power = 0;         // transmitted power magnitude [W]
        double mu_prefactor = 0;  // mu = mu_prefactor * eta_mPas^-0.05 (Schlenk / ISO forms)
        double H_V = 0;
        mesh::LineContact contact;
        double sigma = 0;         // roughness for Lambda [m]
        double F_bn = 0;          // normal force of one mesh [N] (local EHL model)
        double omega_rel = 0;     // speed of gear 0 relative to the carrier [rad/s]
        // Film temperature rises of the local EHL nodes at the last oil temperature tried:
        // the warm start of the next evaluation of this point's thermal solve.
        mutable std::vector<double> ehl_film_rise;
    };
    std::vector<MeshState> meshes;
    std::vector<churning::ChurningAtSpeed> churn;      // per gear
    std::vector<bearings::SkfAtPoint> bearings;        // per bearing
    std::vector<double> bearing_omega;
    std::vector<double> seal_power;                     // per seal, oil independent
    std::vector<double> clutch_slip;                    // per clutch pack [rad/s] (0 when engaged)
    double seal_total = 0;
    bool any_drag = false;
    // Calibration terms fixed by the point.
    double windage = 0;                       // W
    std::vector<double> bearing_drag_coef;    // W per (nu_cSt)^(2/3), per bearing
    // First component whose oil-independent terms are out of the model's range at this point
    // ("bearing B1_RMS11 contact angle", "churning gear w5", ...); empty when all are valid.
    std::string fault;
};

PointState prepare_point(const Model& m, double omega_in, double torque_in);
// Same, reusing the storage of `p` (no allocation once warm).
void prepare_point(const Model& m, double omega_in, double torque_in, PointState& p);

struct LossBreakdown {
    double mesh = 0, churning = 0, bearings = 0, seals = 0, auxiliary = 0;  // churning includes windage
    double clutches = 0;  // drag of open wet clutch packs
    double windage = 0;   // part of `churning` from the calibration's windage term
    double total() const { return mesh + churning + bearings + seals + clutches + auxiliary; }
    // Per component (filled only when detail is requested).
    std::vector<double> mesh_each, mesh_mu, mesh_lambda, mesh_hmin, mesh_hc;
    std::vector<double> churn_each, bearing_each, seal_each, clutch_each;
    std::vector<churning::Regime> churn_regime;
    double lambda_min = 0;   // over loaded meshes; NaN-free: 0 when no loaded mesh
    bool has_lambda = false;
};

// Losses at oil state s. `film` computes the pitch-point films and lambda_min;
// `detail` also fills the per-component vectors.
LossBreakdown evaluate_losses(const Model& m, const PointState& p, const lubricant::OilState& s, bool detail,
                              bool film = false);
// Total loss only (the hot path of the thermal solve).
double total_loss(const Model& m, const PointState& p, double T_oil);

// Stabilised oil temperature of a prepared point (the thermal solve alone).
thermal::Equilibrium solve_temperature(const Model& m, const PointState& p, double ambient_K);

// ok; above_oil_limit: a stabilised oil temperature above the oil's permissible
// temperature (the numbers are computed, the operating point is not admissible);
// no_equilibrium: no stable temperature up to max_oil_temperature (no numbers);
// out_of_range: an input or a component left the model's range, or a value that is not a
// finite number appeared (no numbers; PointResult::cause names it, e.g. "bearing B1_RMS11
// contact angle").
enum class PointStatus { ok, above_oil_limit, no_equilibrium, out_of_range };
const char* to_string(PointStatus s);
// Whether the result carries losses, temperatures and efficiency.
inline bool has_values(PointStatus s) { return s == PointStatus::ok || s == PointStatus::above_oil_limit; }

// What is out of the model's range in the losses at oil temperature T (the oil's validity,
// then each component's loss and the heat flow, first found); empty when every value is a
// finite, non-negative number.
std::string loss_fault(const Model& m, const PointState& p, double T_oil, double ambient_K);

struct PointResult {
    double speed_in = 0, torque_in = 0, power_in = 0;  // rad/s, N*m, W
    double ambient = 0, oil_temperature = 0;            // K
    double power_out = 0, torque_out = 0, omega_out = 0;
    double efficiency = 0;
    bool has_efficiency = false;
    PointStatus status = PointStatus::ok;
    std::string cause;             // out_of_range: what left the range ("input speed ...", "mesh m12 friction loss")
    double thermal_residual = 0;   // W, P - Q at the solution (stabilised)
    int evaluations = 0;
    LossBreakdown losses;
};

// The status cell of a result: "ok", "no_equilibrium", "out_of_range: <cause>" (a cause
// never contains a comma, a quote or a line break, so the cell needs no CSV quoting).
std::string status_text(const PointResult& r);

// Every input is checked here too (speed, torque, ambient, oil temperature within the oil's
// validity) and every component at the point: out of range, the result says out_of_range
// with its cause and carries no numbers.
PointResult solve_point(const Model& m, double omega_in, double torque_in, bool detail, double ambient_K);
inline PointResult solve_point(const Model& m, double omega_in, double torque_in, bool detail = false) {
    return solve_point(m, omega_in, torque_in, detail, m.thermal.ambient);
}

}  // namespace gearloss::solver
