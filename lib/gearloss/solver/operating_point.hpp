#pragma once
// Losses at one operating point and the coupled (stabilised) oil temperature.
#include <string>
#include <vector>

#include <boost/container/small_vector.hpp>
#include <memory>
#include <string_view>

#include "gearloss/losses/loss_mechanism.hpp"
#include "gearloss/losses/mechanism_set.hpp"
#include "gearloss/model/model.hpp"

namespace gearloss::solver {

// Everything about a point that does not depend on the oil temperature: the input and
// each loss mechanism's own terms (kinematics, mesh loads, bearing loads), computed once
// per point. Copies are deep.
struct PointState {
    double omega_in = 0, torque_in = 0, power_in = 0;
    std::vector<std::unique_ptr<losses::MechanismPoint>> data;  // per mechanism of the model
    unsigned long long mechanisms_id = 0;                        // the MechanismSet that made `data`
    // First component whose oil-independent terms are out of the model's range at this point
    // ("bearing B1_RMS11 contact angle", "churning gear w5", ...); empty when all are valid.
    std::string fault;

    PointState() = default;
    PointState(const PointState& o);
    PointState& operator=(const PointState& o);
    PointState(PointState&&) noexcept = default;
    PointState& operator=(PointState&&) noexcept = default;
    losses::PointInput input() const { return {omega_in, torque_in, power_in}; }
};

PointState prepare_point(const Model& m, double omega_in, double torque_in);
// Same, reusing the storage of `p` (no allocation once warm).
void prepare_point(const Model& m, double omega_in, double torque_in, PointState& p);

// The loss of every mechanism of the model, in the order of m.mechanisms.
struct LossBreakdown {
    boost::container::small_vector<double, 8> power;  // W, per mechanism
    std::vector<losses::MechanismDetail> detail;      // per mechanism (only when detail is requested)
    double lambda_min = 0;   // over loaded meshes; NaN-free: 0 when no loaded mesh
    bool has_lambda = false;
    double total() const {
        double t = 0.0;
        for (double P : power) t += P;
        return t;
    }
    // The loss of the mechanism `name` (0 when the model has none of that name).
    double of(const Model& m, std::string_view name) const;
    // The per-component detail of mechanism `name` (detail evaluations only).
    const losses::MechanismDetail& detail_of(const Model& m, std::string_view name) const;
    // The part of the loss whose heat goes straight into the oil (LossMechanism::heats_oil).
    double into_oil(const Model& m) const;
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
